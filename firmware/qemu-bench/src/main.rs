//! Renders the built-in scenes on an emulated Cortex-M and prints the
//! instructions each frame takes.
//!
//! Under `qemu-system-arm -icount shift=0` every instruction advances the
//! virtual clock by 1 ns; the board's SysTick runs at 25 MHz, so one tick is
//! 40 instructions. Counts are deterministic: the same binary prints the
//! same numbers. The factor is calibrated at start-up on a loop of exactly
//! known length and printed as a `calibration` line.
//!
//! Per scene and mode it prints instructions per frame (the checksum sink
//! timed separately), the frame's checksum, the peak stack the frame used
//! (stack painting) and the renderer's RAM (`size_of`, what a `static`
//! renderer occupies on a board).
#![no_std]
#![no_main]

use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use soft3d::scenes::{demo_camera, demo_lights, draw_bench, FrameChecksum, BENCH_SCENES, DEMO_TRIANGLES, DEMO_VARYINGS, DEMO_VERTICES};
use soft3d::{Renderer, Settings};

/// The shared Blender exports, baked by `build.rs` (see `tools/bake`).
#[cfg(soft3d_assets)]
#[allow(missing_docs, dead_code)]
mod torus_file {
    include!(concat!(env!("OUT_DIR"), "/torus_file.rs"));
}
#[cfg(soft3d_assets)]
#[allow(missing_docs, dead_code)]
mod monkey_file {
    include!(concat!(env!("OUT_DIR"), "/monkey_file.rs"));
}

/// The baked scenes, in the order of `FILE_SCENES`: camera and meshes.
#[cfg(soft3d_assets)]
fn file_scene(i: usize) -> (soft3d::Camera, &'static [(&'static soft3d::mesh::Mesh<'static>, soft3d::math::Mat4, Rgb888, soft3d::Cull)]) {
    match i {
        0 => (torus_file::CAMERA, &torus_file::MESHES),
        _ => (monkey_file::CAMERA, &monkey_file::MESHES),
    }
}

/// Instructions per SysTick tick under `-icount shift=0` at 25 MHz.
const INSTRUCTIONS_PER_TICK: u32 = 40;

struct Timer(cortex_m::peripheral::SYST);

impl Timer {
    fn start(&mut self) {
        self.0.clear_current();
        let _ = self.0.has_wrapped();
    }
    /// Instructions since `start`, or None if the 24-bit counter wrapped
    /// (more than 671 million instructions).
    fn instructions(&mut self) -> Option<u32> {
        let now = cortex_m::peripheral::SYST::get_current();
        if self.0.has_wrapped() {
            return None;
        }
        Some((0x00FF_FFFF - now) * INSTRUCTIONS_PER_TICK)
    }
}

/// Built with `SOFT3D_BENCH_ONLY=scene,mode` in the environment, the
/// benchmark runs only that scene and mode (for `scripts/qemu-profile.py`).
const ONLY: Option<&str> = option_env!("SOFT3D_BENCH_ONLY");

fn selected(scene: &str, mode: &str) -> bool {
    match ONLY {
        None => true,
        Some(only) => only.split_once(',').is_some_and(|(s, m)| s == scene && m == mode),
    }
}

const TARGET: &str = if cfg!(target_abi = "eabihf") { "m4f" } else { "m0" };

/// Stack painting: the pattern written below the stack pointer before a
/// frame, and how far below it is checked.
const PAINT: u32 = 0x5AFE_57AC;
const PAINT_BYTES: usize = 64 * 1024;
/// Room left for `paint`'s and `stack_used`'s own frames.
const PAINT_MARGIN: usize = 512;

/// Fills `[top - PAINT_BYTES, top - PAINT_MARGIN)` with the pattern.
#[inline(never)]
fn paint(top: usize) {
    let mut a = top - PAINT_BYTES;
    while a < top - PAINT_MARGIN {
        // SAFETY: the region is RAM below the live stack frames (the
        // emulated boards have 4 MB of RAM and the stack starts at its top),
        // not used by anything else; written before the frame runs.
        unsafe { (a as *mut u32).write_volatile(PAINT) };
        a += 4;
    }
}

/// Bytes below `top` that no longer hold the pattern: the deepest the
/// stack went since `paint(top)`.
#[inline(never)]
fn stack_used(top: usize) -> usize {
    let mut a = top - PAINT_BYTES;
    while a < top - PAINT_MARGIN {
        // SAFETY: the same region `paint` wrote; only read here.
        if unsafe { (a as *const u32).read_volatile() } != PAINT {
            return top - a;
        }
        a += 4;
    }
    PAINT_MARGIN
}

/// Instructions per tick, measured: a loop of `subs` and `bne` run
/// `LOOPS` times is `2 * LOOPS` instructions (plus a handful around it).
fn calibrate(timer: &mut Timer) -> Option<u32> {
    const LOOPS: u32 = 2_000_000;
    timer.start();
    // SAFETY: a register-only countdown loop; touches no memory.
    unsafe {
        core::arch::asm!("2:", "subs {n}, #1", "bne 2b", n = inout(reg) LOOPS => _, options(nomem, nostack));
    }
    let ticks = timer.instructions()? / INSTRUCTIONS_PER_TICK;
    Some(((2 * LOOPS as u64 + ticks as u64 / 2) / ticks.max(1) as u64) as u32)
}

/// Wraps the checksum sink and accumulates the instructions spent inside
/// it, so that the frame's own cost can exclude them.
struct TimedSink {
    inner: FrameChecksum<Rgb565>,
    ticks: u32,
}

impl OriginDimensions for TimedSink {
    fn size(&self) -> Size {
        self.inner.size()
    }
}

impl DrawTarget for TimedSink {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    #[inline(never)]
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        let t0 = cortex_m::peripheral::SYST::get_current();
        let r = self.inner.draw_iter(pixels);
        self.ticks += t0.wrapping_sub(cortex_m::peripheral::SYST::get_current()) & 0x00FF_FFFF;
        r
    }

    #[inline(never)]
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error> {
        let t0 = cortex_m::peripheral::SYST::get_current();
        let r = self.inner.fill_contiguous(area, colors);
        self.ticks += t0.wrapping_sub(cortex_m::peripheral::SYST::get_current()) & 0x00FF_FFFF;
        r
    }
}

type BenchRenderer<S> = Renderer<Rgb565, 320, 240, 16, DEMO_VERTICES, DEMO_TRIANGLES, DEMO_VARYINGS, S>;

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
    #[cfg(soft3d_assets)]
    for (i, (name, _)) in soft3d::scenes::FILE_SCENES.iter().enumerate() {
        if selected(name, mode) {
            let (camera, meshes) = file_scene(i);
            measure_with(timer, &mut renderer, &camera, &soft3d::scenes::headlight(&camera), name, mode, ram, |frame| {
                for (mesh, model, _, _) in meshes {
                    let _ = frame.draw(mesh, model, &soft3d::scenes::WHITE);
                }
            });
        }
    }
}

type BenchFrame<'r, S> = soft3d::Frame<'r, 'static, Rgb565, DEMO_VARYINGS, S>;

fn measure<S: Settings>(
    timer: &mut Timer,
    renderer: &mut BenchRenderer<S>,
    name: &str,
    mode: &str,
    ram: usize,
    draw: impl FnOnce(&mut BenchFrame<'_, S>),
) {
    let (camera, lights) = (demo_camera(), demo_lights());
    measure_with(timer, renderer, &camera, &lights, name, mode, ram, draw)
}

/// Renders one frame, timed, into the checksum sink and prints its line.
#[allow(clippy::too_many_arguments)]
fn measure_with<S: Settings>(
    timer: &mut Timer,
    renderer: &mut BenchRenderer<S>,
    camera: &soft3d::Camera,
    lights: &soft3d::Lights,
    name: &str,
    mode: &str,
    ram: usize,
    draw: impl FnOnce(&mut BenchFrame<'_, S>),
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
    let p = cortex_m::Peripherals::take().unwrap();
    let mut syst = p.SYST;
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(0x00FF_FFFF);
    syst.enable_counter();
    let mut timer = Timer(syst);
    match calibrate(&mut timer) {
        Some(f) => hprintln!("calibration,instructions_per_tick,{},assumed,{}", f, INSTRUCTIONS_PER_TICK),
        None => hprintln!("calibration,failed"),
    }
    hprintln!("scene,mode,target,instructions,sink_instructions,queued,checksum,geometry_instructions,stack,renderer_ram");
    run::<soft3d::FixedPoint>(&mut timer, "fixed");
    run::<soft3d::FloatingPoint>(&mut timer, "f32");
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    hprintln!("panic: {}", info);
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::wfi();
    }
}
