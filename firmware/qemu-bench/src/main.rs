//! Renders the built-in scenes on an emulated Cortex-M and prints the
//! instructions each frame takes.
//!
//! Under `qemu-system-arm -icount shift=0` every instruction advances the
//! virtual clock by 1 ns; the board's SysTick runs at 25 MHz (mps2-an385,
//! mps2-an386) or 20 MHz (mps2-an505), so one tick is 40 or 50
//! instructions. Counts are deterministic: the same binary prints the same
//! numbers. The factor is calibrated at start-up on a loop of exactly known
//! length and printed as a `calibration` line.
//!
//! Per scene and mode it prints instructions per frame (the checksum sink
//! timed separately), the frame's checksum, the peak stack the frame used
//! (stack painting) and the renderer's RAM (`size_of`, what a `static`
//! renderer occupies on a board).
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::hprintln;
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use soft3d::scenes::wall::{draw_wall, WALL_CAMERA, WALL_LIGHTS, WALL_SCENES, WALL_VARYINGS};
use soft3d::scenes::{demo_camera, demo_lights, draw_bench, FrameChecksum, BENCH_SCENES, DEMO_TRIANGLES, DEMO_VARYINGS, DEMO_VERTICES};
use soft3d::{Renderer, Settings};
use soft3d_qemu_bench::*;

/// Built with `SOFT3D_BENCH_ONLY=scene,mode` in the environment, the
/// benchmark runs only that scene and mode (for `scripts/qemu-profile.py`).
const ONLY: Option<&str> = option_env!("SOFT3D_BENCH_ONLY");

fn selected(scene: &str, mode: &str) -> bool {
    match ONLY {
        None => true,
        Some(only) => only.split_once(',').is_some_and(|(s, m)| s == scene && m == mode),
    }
}

type BenchRenderer<S> = Renderer<Rgb565, 320, 240, 16, DEMO_VERTICES, DEMO_TRIANGLES, DEMO_VARYINGS, S>;

/// The wall scenes' renderer: two triangles, Phong's six varyings.
type WallRenderer<S> = Renderer<Rgb565, 320, 240, 16, 8, 8, WALL_VARYINGS, S>;

fn run<S: Settings>(timer: &mut Timer, mode: &str) {
    let mut renderer: BenchRenderer<S> = Renderer::new(Rgb565::BLACK);
    let ram = core::mem::size_of::<BenchRenderer<S>>();
    for (i, name) in BENCH_SCENES.iter().enumerate() {
        if selected(name, mode) {
            measure(timer, &mut renderer, name, mode, ram, |frame| {
                let _ = draw_bench(frame, i);
            });
        }
    }
    // The full-screen wall with each effect, in a renderer sized for it.
    let mut wall: WallRenderer<S> = Renderer::new(Rgb565::BLACK);
    let wall_ram = core::mem::size_of::<WallRenderer<S>>();
    for (i, name) in WALL_SCENES.iter().enumerate() {
        if selected(name, mode) {
            measure_with(timer, &mut wall, &WALL_CAMERA, &WALL_LIGHTS, name, mode, wall_ram, |frame| {
                let _ = draw_wall(frame, i);
            });
        }
    }
    #[cfg(soft3d_assets)]
    {
        use soft3d::effect::{ColorLight, GrayLight};
        use soft3d::material::{PerPixel, PerSpan};
        use soft3d::scenes::{file_scene_index, textured, FILE_SCENES, MONO_SCENES, QUANTIZED_SCENES, TEXTURED_SCENES, WHITE, WHITE_MONO};
        for (i, (name, _)) in FILE_SCENES.iter().chain(&QUANTIZED_SCENES).enumerate() {
            baked_scene(timer, &mut renderer, name, mode, ram, i, &WHITE);
        }
        // The same files with one interpolated light level.
        for (name, file) in MONO_SCENES {
            if let Some(i) = file_scene_index(file) {
                baked_scene(timer, &mut renderer, name, mode, ram, i, &WHITE_MONO);
            }
        }
        // The monkey (the second file) with its texture.
        let texture = monkey_file::SUZANNE_TEXTURE;
        baked_scene(timer, &mut renderer, TEXTURED_SCENES[0], mode, ram, 1, &textured::<PerPixel, ColorLight>(texture));
        baked_scene(timer, &mut renderer, TEXTURED_SCENES[1], mode, ram, 1, &textured::<PerSpan<32>, ColorLight>(texture));
        // The same with one interpolated light level.
        baked_scene(timer, &mut renderer, TEXTURED_SCENES[2], mode, ram, 1, &textured::<PerPixel, GrayLight>(texture));
        baked_scene(timer, &mut renderer, TEXTURED_SCENES[3], mode, ram, 1, &textured::<PerSpan<32>, GrayLight>(texture));
    }
}

/// Baked scene `scene` (see [`file_scene`]) drawn with `material`, from
/// its camera with the headlight, measured as scene `name`.
#[cfg(soft3d_assets)]
fn baked_scene<S: Settings, E: soft3d::effect::Effect, P: soft3d::material::Perspective, D: soft3d::material::DepthMode>(
    timer: &mut Timer,
    renderer: &mut BenchRenderer<S>,
    name: &str,
    mode: &str,
    ram: usize,
    scene: usize,
    material: &soft3d::Material<E, P, D>,
) {
    if selected(name, mode) {
        let (camera, meshes) = file_scene(scene);
        measure_with(timer, renderer, &camera, &soft3d::scenes::headlight(&camera), name, mode, ram, |frame| {
            for (mesh, model, _, _) in meshes {
                let _ = frame.draw(mesh, model, material);
            }
        });
    }
}

type BenchFrame<'r, 'm, S, const V: usize = DEMO_VARYINGS> = soft3d::Frame<'r, 'm, Rgb565, V, S>;

fn measure<S: Settings>(
    timer: &mut Timer,
    renderer: &mut BenchRenderer<S>,
    name: &str,
    mode: &str,
    ram: usize,
    draw: impl FnOnce(&mut BenchFrame<'_, 'static, S>),
) {
    let (camera, lights) = (demo_camera(), demo_lights());
    measure_with(timer, renderer, &camera, &lights, name, mode, ram, draw)
}

/// Renders one frame, timed, into the checksum sink and prints its line.
#[allow(clippy::too_many_arguments)]
fn measure_with<'m, S: Settings, const NV: usize, const NT: usize, const V: usize>(
    timer: &mut Timer,
    renderer: &mut Renderer<Rgb565, 320, 240, 16, NV, NT, V, S>,
    camera: &soft3d::Camera,
    lights: &soft3d::Lights,
    name: &str,
    mode: &str,
    ram: usize,
    draw: impl FnOnce(&mut BenchFrame<'_, 'm, S, V>),
) {
    let mut out = TimedSink { inner: FrameChecksum::new(320, 240, Rgb565::BLACK), ticks: 0 };
    let top = cortex_m::register::msp::read() as usize;
    paint(top);
    timer.start();
    let mut frame = renderer.begin_frame(camera, lights, Rgb565::BLACK);
    draw(&mut frame);
    let geometry = timer.instructions();
    let Ok(stats) = frame.finish(&mut out);
    let total = timer.instructions();
    let stack = stack_used(top);
    let sink = out.ticks * INSTRUCTIONS_PER_TICK;
    let (sum, queued) = (out.inner.sum, stats.queued);
    match (total, geometry) {
        (Some(n), Some(g)) => hprintln!("{},{},{},{},{},{},{:08x},{},{},{}", name, mode, TARGET, n, sink, queued, sum, g, stack, ram),
        _ => hprintln!("{},{},{},overflow,{},{},{:08x},0,{},{}", name, mode, TARGET, sink, queued, sum, stack, ram),
    }
}

#[entry]
fn main() -> ! {
    let mut timer = start_timer();
    hprintln!("scene,mode,target,instructions,sink_instructions,queued,checksum,geometry_instructions,stack,renderer_ram");
    run::<soft3d::FixedPoint>(&mut timer, "fixed");
    run::<soft3d::FloatingPoint>(&mut timer, "f32");
    exit()
}
