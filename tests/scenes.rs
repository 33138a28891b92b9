//! The shared Blender exports rendered end to end (loader, textures,
//! camera and lights from the file): golden images of the textured,
//! perspective-correct monkey and of the torus, and agreement between the
//! fixed-point and `f32` modes. Skipped, with a message, when
//! `../shared/assets` is absent.

use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use soft3d::host::scene::{EffectChoice, HostScene};
use soft3d::host::Image;
use soft3d::material::PerPixel;
use soft3d::math::Mat4;
use soft3d::texture::{Nearest, Repeat};
use soft3d::{FixedPoint, FloatingPoint, HostRenderer, Settings};

mod common;
use common::golden;

const ASSETS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/assets");

fn load(name: &str) -> Option<HostScene> {
    let path = format!("{ASSETS}/{name}");
    if !std::path::Path::new(&path).exists() {
        println!("skipped: {path} is not available");
        return None;
    }
    let scene = HostScene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    Some(scene)
}

fn render<S: Settings>(scene: &HostScene, w: usize, h: usize) -> Image<Rgb565> {
    let materials = scene.materials::<Nearest, Repeat, PerPixel>(EffectChoice::Auto);
    let mut r: HostRenderer<Rgb565, 6, S> = HostRenderer::new(w, h, 16, 4096, 4096, Rgb565::BLACK).unwrap();
    let mut frame = r.begin_frame(&scene.camera_or_default(), &scene.lights, Rgb565::new(2, 4, 6));
    scene.draw(&mut frame, &materials, &Mat4::IDENTITY).unwrap();
    let mut img = Image::new(w as u32, h as u32, Rgb565::BLACK);
    let Ok(_) = frame.finish(&mut img);
    img
}

/// Pixels that differ between two images, and the largest channel step.
fn compare(a: &Image<Rgb565>, b: &Image<Rgb565>) -> (usize, u8) {
    let step = |x: Rgb565, y: Rgb565| x.r().abs_diff(y.r()).max(x.g().abs_diff(y.g())).max(x.b().abs_diff(y.b()));
    let differ = a.pixels.iter().zip(&b.pixels).filter(|(x, y)| x != y).count();
    (differ, a.pixels.iter().zip(&b.pixels).map(|(&x, &y)| step(x, y)).max().unwrap_or(0))
}

#[test]
fn textured_monkey_and_torus_golden_images() {
    if let Some(monkey) = load("monkey.babylon") {
        assert_eq!(monkey.textures.len(), 1);
        assert_eq!((monkey.textures[0].width, monkey.textures[0].height), (512, 512));
        golden("monkey-textured", &render::<FixedPoint>(&monkey, 160, 120));
    }
    if let Some(torus) = load("torus.babylon") {
        golden("torus-babylon", &render::<FixedPoint>(&torus, 160, 120));
    }
}

#[test]
fn fixed_and_f32_agree_on_the_shared_scenes() {
    for name in ["monkey.babylon", "torus.babylon", "cube.babylon"] {
        let Some(scene) = load(name) else { continue };
        let (fixed, float) = (render::<FixedPoint>(&scene, 160, 120), render::<FloatingPoint>(&scene, 160, 120));
        let (differ, step) = compare(&fixed, &float);
        let drawn = fixed.pixels.iter().filter(|&&p| p != Rgb565::new(2, 4, 6)).count();
        eprintln!("{name}: {differ} of {drawn} drawn pixels differ, by at most {step} steps");
        assert!(drawn > 200, "{name}: {drawn} pixels drawn");
        // Coverage is identical; colors may round differently by a step,
        // and a texel boundary may fall on the other side of a pixel center.
        assert!(differ * 10 <= drawn, "{name}: {differ} of {drawn} differ");
    }
}
