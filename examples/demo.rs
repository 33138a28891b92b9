//! The demo: a rotating, lit scene of the built-in meshes, rendered through
//! 16-row strips exactly as on a microcontroller.
//!
//! ```text
//! cargo run --release --example demo --features simulator [-- --frames N --out demo.png --gif demo.gif]
//! cargo run --release --example demo --features simulator -- --scene ../shared/assets/monkey.babylon
//! ```
//! Writes the last frame as a PNG and all frames as an animated GIF, and
//! prints the time per frame. `--scene` shows a `.babylon` file instead (its
//! textures read from beside it) turning on a turntable, seen from the
//! file's camera with a headlight. Built with `--features window` and run where
//! a display is available, it shows the animation in a window instead.

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::RgbColor;
use soft3d::host::{GifRecorder, Image};
use soft3d::scenes::{demo_camera, demo_lights, draw_demo, DEMO_TRIANGLES, DEMO_VARYINGS, DEMO_VERTICES};
use soft3d::{FixedPoint, Renderer};
use std::time::Instant;

const W: usize = 320;
const H: usize = 240;
const STRIP: usize = 16;
type DemoRenderer = Renderer<Rgb565, W, H, STRIP, DEMO_VERTICES, DEMO_TRIANGLES, DEMO_VARYINGS, FixedPoint>;

fn main() {
    let mut frames = 72usize;
    let mut out = String::from("demo.png");
    let mut gif = Some(String::from("demo.gif"));
    let mut scene = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--frames" => frames = args.next().and_then(|v| v.parse().ok()).filter(|&n| n > 0).unwrap_or_else(|| usage()),
            "--out" => out = args.next().unwrap_or_else(|| usage()),
            "--gif" => gif = Some(args.next().unwrap_or_else(|| usage())),
            "--no-gif" => gif = None,
            "--scene" => scene = Some(args.next().unwrap_or_else(|| usage())),
            _ => usage(),
        }
    }
    if let Some(path) = scene {
        return turntable(&path, frames, &out, gif.as_deref());
    }
    // The renderer is 180 KB; keep it off the stack as firmware keeps it in a static.
    let mut renderer = Box::new(DemoRenderer::new(Rgb565::BLACK));

    #[cfg(feature = "window")]
    if std::env::var_os("DISPLAY").is_some() || std::env::var_os("WAYLAND_DISPLAY").is_some() {
        window::run(&mut renderer);
        return;
    }

    let mut image = Image::new(W as u32, H as u32, Rgb565::BLACK);
    let mut recorder = GifRecorder::new(W as u32, H as u32, 4);
    let (camera, lights) = (demo_camera(), demo_lights());
    let mut busy = std::time::Duration::ZERO;
    let mut last = Default::default();
    for i in 0..frames {
        let t = i as f32 / 24.0;
        let start = Instant::now();
        let mut frame = renderer.begin_frame(&camera, &lights, Rgb565::new(2, 4, 6));
        draw_demo(&mut frame, t).expect("the demo scene fits its buffers");
        last = frame.finish(&mut image).expect("an in-memory image cannot fail");
        busy += start.elapsed();
        if gif.is_some() {
            recorder.push(&image);
        }
    }
    image.save_png(&out).unwrap_or_else(|e| fail(&format!("cannot write {out}: {e}")));
    if let Some(path) = &gif {
        recorder.save(path).unwrap_or_else(|e| fail(&format!("cannot write {path}: {e}")));
    }
    println!("rendered {frames} frames of {W}x{H} in {STRIP}-row strips (fixed-point)");
    println!("time per frame: {:.3} ms (host wall clock)", busy.as_secs_f64() * 1e3 / frames as f64);
    println!(
        "last frame: {} draw calls, {} vertices, {} triangles submitted, {} drawn, {} back-facing",
        last.draw_calls, last.vertices, last.triangles, last.queued, last.back_facing
    );
    println!("wrote {out}{}", gif.map(|g| format!(" and {g}")).unwrap_or_default());
}

/// A `.babylon` scene turning once around the vertical axis.
fn turntable(path: &str, frames: usize, out: &str, gif: Option<&str>) {
    use soft3d::host::scene::{EffectChoice, HostScene};
    use soft3d::material::PerSpan;
    use soft3d::math::Mat4;
    use soft3d::texture::{Bilinear, Repeat};
    let scene = HostScene::load(path).unwrap_or_else(|e| fail(&e.to_string()));
    for w in &scene.warnings {
        eprintln!("warning: {w}");
    }
    let materials = scene.materials::<Bilinear, Repeat, PerSpan<32>>(EffectChoice::Auto);
    let camera = scene.camera_or_default();
    let lights = HostScene::headlight(&camera);
    let mut renderer: soft3d::HostRenderer<Rgb565, 6, FixedPoint> =
        soft3d::HostRenderer::new(W, H, STRIP, 8192, 8192, Rgb565::BLACK).unwrap_or_else(|e| fail(&e.to_string()));
    let mut image = Image::new(W as u32, H as u32, Rgb565::BLACK);
    let mut recorder = GifRecorder::new(W as u32, H as u32, 4);
    let center = scene.bounds().center;
    let mut busy = std::time::Duration::ZERO;
    for i in 0..frames {
        let angle = i as f32 / frames as f32 * std::f32::consts::TAU;
        let spin = Mat4::translation(center) * Mat4::rotation_y(angle) * Mat4::translation(-center);
        let start = Instant::now();
        let mut frame = renderer.begin_frame(&camera, &lights, Rgb565::new(2, 4, 6));
        scene.draw(&mut frame, &materials, &spin).unwrap_or_else(|e| fail(&format!("{path}: {e}")));
        let Ok(_) = frame.finish(&mut image);
        busy += start.elapsed();
        if gif.is_some() {
            recorder.push(&image);
        }
    }
    image.save_png(out).unwrap_or_else(|e| fail(&format!("cannot write {out}: {e}")));
    if let Some(g) = gif {
        recorder.save(g).unwrap_or_else(|e| fail(&format!("cannot write {g}: {e}")));
    }
    println!(
        "rendered {frames} frames of {path} at {W}x{H} in {STRIP}-row strips (fixed-point, textures bilinear, perspective every 16 px)"
    );
    println!("time per frame: {:.3} ms (host wall clock)", busy.as_secs_f64() * 1e3 / frames as f64);
    println!("wrote {out}{}", gif.map(|g| format!(" and {g}")).unwrap_or_default());
}

fn usage() -> ! {
    fail("usage: demo [--frames N] [--out FILE.png] [--gif FILE.gif | --no-gif] [--scene FILE.babylon]")
}

fn fail(msg: &str) -> ! {
    eprintln!("{msg}");
    std::process::exit(2)
}

#[cfg(feature = "window")]
mod window {
    use super::*;
    use embedded_graphics::prelude::Size;
    use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay, SimulatorEvent, Window};

    pub fn run(renderer: &mut DemoRenderer) {
        let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(W as u32, H as u32));
        let mut window = Window::new("soft3d demo", &OutputSettingsBuilder::new().scale(2).build());
        let (camera, lights) = (demo_camera(), demo_lights());
        let start = Instant::now();
        loop {
            let mut frame = renderer.begin_frame(&camera, &lights, Rgb565::new(2, 4, 6));
            draw_demo(&mut frame, start.elapsed().as_secs_f32()).expect("the demo scene fits its buffers");
            frame.finish(&mut display).expect("the simulator display cannot fail");
            window.update(&display);
            if window.events().any(|e| e == SimulatorEvent::Quit) {
                break;
            }
        }
    }
}
