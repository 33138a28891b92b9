//! Host side of the target benchmark: renders the benchmark scenes exactly
//! as `firmware/qemu-bench` does and prints `scene,mode,checksum,drawn`
//! lines for `scripts/target-bench.sh` to compare with the emulated
//! Cortex-M. The scenes from `../shared/assets` are parsed here at run time
//! and baked into the firmware: equal checksums also show that baking
//! changes nothing.

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::RgbColor;
use soft3d::effect::{ColorLight, Effect, GrayLight};
use soft3d::host::scene::HostScene;
use soft3d::material::{Material, PerPixel, PerSpan, Perspective};
use soft3d::scenes::wall::{draw_wall, WALL_CAMERA, WALL_LIGHTS, WALL_SCENES, WALL_VARYINGS};
use soft3d::scenes::{
    demo_camera, demo_lights, draw_bench, headlight, textured, FrameChecksum, BENCH_SCENES, DEMO_TRIANGLES, DEMO_VARYINGS, DEMO_VERTICES,
    FILE_SCENES, MONO_SCENES, QUANTIZED_SCENES, TEXTURED_SCENES, WHITE, WHITE_MONO,
};
use soft3d::{HostRenderer, Settings};

const ASSETS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/assets");

fn run<S: Settings>(mode: &str, files: &[(&str, HostScene)]) {
    let mut r: HostRenderer<Rgb565, DEMO_VARYINGS, S> =
        HostRenderer::new(320, 240, 16, DEMO_VERTICES, DEMO_TRIANGLES, Rgb565::BLACK).expect("valid sizes");
    for (i, name) in BENCH_SCENES.iter().enumerate() {
        let mut frame = r.begin_frame(&demo_camera(), &demo_lights(), Rgb565::BLACK);
        draw_bench(&mut frame, i).expect("the scene fits its buffers");
        print_frame(name, mode, frame);
    }
    let mut wall: HostRenderer<Rgb565, WALL_VARYINGS, S> = HostRenderer::new(320, 240, 16, 8, 8, Rgb565::BLACK).expect("valid sizes");
    for (i, name) in WALL_SCENES.iter().enumerate() {
        let mut frame = wall.begin_frame(&WALL_CAMERA, &WALL_LIGHTS, Rgb565::BLACK);
        draw_wall(&mut frame, i).expect("the scene fits its buffers");
        print_frame(name, mode, frame);
    }
    for (name, scene) in files {
        file_scene(&mut r, name, mode, scene, &WHITE);
    }
    // Scenes quantized to i16, as the firmware bakes them.
    for (name, file) in QUANTIZED_SCENES {
        if let Some((_, scene)) = files.iter().find(|(n, _)| *n == file) {
            quantized_scene(&mut r, name, mode, scene, &WHITE);
        }
    }
    for (name, file) in MONO_SCENES {
        // A quantized scene is drawn from the file it quantizes.
        let source = QUANTIZED_SCENES.iter().find(|(n, _)| *n == file).map_or(file, |(_, f)| *f);
        let Some((_, scene)) = files.iter().find(|(n, _)| *n == source) else { continue };
        if source == file {
            file_scene(&mut r, name, mode, scene, &WHITE_MONO);
        } else {
            quantized_scene(&mut r, name, mode, scene, &WHITE_MONO);
        }
    }
    // The monkey with its texture, as the firmware bakes it.
    if let Some((_, monkey)) = files.iter().find(|(name, _)| *name == "monkey") {
        let texture = monkey.textures.first().expect("monkey.babylon names Suzanne.jpg").texture();
        file_scene(&mut r, TEXTURED_SCENES[0], mode, monkey, &textured::<PerPixel, ColorLight>(texture));
        file_scene(&mut r, TEXTURED_SCENES[1], mode, monkey, &textured::<PerSpan<32>, ColorLight>(texture));
        file_scene(&mut r, TEXTURED_SCENES[2], mode, monkey, &textured::<PerPixel, GrayLight>(texture));
        file_scene(&mut r, TEXTURED_SCENES[3], mode, monkey, &textured::<PerSpan<32>, GrayLight>(texture));
    }
}

/// Renders a file scene quantized to `i16` with its camera and `material`
/// and prints its line.
fn quantized_scene<S: Settings, E: Effect>(
    r: &mut HostRenderer<Rgb565, DEMO_VARYINGS, S>,
    name: &str,
    mode: &str,
    scene: &HostScene,
    material: &Material<E>,
) {
    let camera = scene.camera_or_default();
    let meshes: Vec<_> = scene.meshes.iter().map(|m| (m.quantized().expect("the file's vectors are finite"), m.model)).collect();
    let mut frame = r.begin_frame(&camera, &headlight(&camera), Rgb565::BLACK);
    for (m, model) in &meshes {
        frame.draw(&m.mesh(), model, material).expect("the scene fits its buffers");
    }
    print_frame(name, mode, frame);
}

/// Renders a file scene with its camera and `material` and prints its line.
fn file_scene<S: Settings, E: Effect, P: Perspective>(
    r: &mut HostRenderer<Rgb565, DEMO_VARYINGS, S>,
    name: &str,
    mode: &str,
    scene: &HostScene,
    material: &Material<E, P>,
) {
    let camera = scene.camera_or_default();
    let mut frame = r.begin_frame(&camera, &headlight(&camera), Rgb565::BLACK);
    for m in &scene.meshes {
        frame.draw(&m.mesh(), &m.model, material).expect("the scene fits its buffers");
    }
    print_frame(name, mode, frame);
}

/// Finishes a frame into the checksum sink and prints its line.
fn print_frame<S: Settings, const V: usize>(name: &str, mode: &str, frame: soft3d::Frame<'_, '_, Rgb565, V, S>) {
    let mut sink = FrameChecksum::new(320, 240, Rgb565::BLACK);
    let Ok(_) = frame.finish(&mut sink);
    println!("{name},{mode},{:08x},{}", sink.sum, sink.drawn);
}

fn main() {
    let files: Vec<(&str, HostScene)> = FILE_SCENES
        .iter()
        .filter_map(|(name, file)| {
            let path = format!("{ASSETS}/{file}");
            match HostScene::load(&path) {
                Ok(s) => Some((*name, s)),
                Err(e) => {
                    eprintln!("bench_host: skipped {name}: {e}");
                    None
                }
            }
        })
        .collect();
    run::<soft3d::FixedPoint>("fixed", &files);
    run::<soft3d::FloatingPoint>("f32", &files);
}
