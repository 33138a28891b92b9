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
        assert_eq!((monkey.textures[0].image.width, monkey.textures[0].image.height), (512, 512));
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

/// A scene of two quads facing the camera, lit by a directional light along
/// the view (so each quad is evenly lit): first in the file a textured quad
/// whose 4×1 PNG is green with alphas `alphas`, in front of an untextured
/// red quad twice its size. Material opacity `opacity`.
fn translucent_scene(dir: &std::path::Path, alphas: [u8; 4], opacity: f32) -> HostScene {
    let png: Vec<u8> = alphas.iter().flat_map(|&a| [0, 255, 0, a]).collect();
    soft3d::host::write_png(&dir.join("glass.png"), 4, 1, png::ColorType::Rgba, &png).unwrap();
    let quad = |s: f32, z: f32, uv: bool| {
        let v = [(-s, -s, 0.0, 0.0), (s, -s, 1.0, 0.0), (s, s, 1.0, 1.0), (-s, s, 0.0, 1.0)];
        v.iter()
            .map(|&(x, y, u, w)| if uv { format!("{x},{y},{z},0,0,-1,{u},{w}") } else { format!("{x},{y},{z},0,0,-1") })
            .collect::<Vec<_>>()
            .join(",")
    };
    let json = format!(
        r#"{{"cameras":[{{"name":"C","id":"C","position":[0,0,-4],"target":[0,0,0],"fov":0.9,"minZ":0.5,"maxZ":50}}],"activeCamera":"C",
"lights":[{{"name":"Sun","id":"Sun","type":1,"direction":[0,0,1],"intensity":1,"diffuse":[1,1,1]}}],
"materials":[{{"name":"Glass","id":"Glass","diffuse":[1,1,1],"alpha":{opacity},"backFaceCulling":false,"diffuseTexture":{{"name":"glass.png","hasAlpha":1}}}},
 {{"name":"Red","id":"Red","diffuse":[1,0,0],"alpha":1,"backFaceCulling":false}}],
"meshes":[{{"name":"Front","id":"Front","materialId":"Glass","uvCount":1,"vertices":[{}],"indices":[0,2,1,0,3,2]}},
 {{"name":"Back","id":"Back","materialId":"Red","uvCount":0,"vertices":[{}],"indices":[0,2,1,0,3,2]}}]}}"#,
        quad(1.0, 0.0, true),
        quad(2.0, 1.0, false)
    );
    std::fs::write(dir.join("glass.babylon"), json).unwrap();
    let scene = HostScene::load(dir.join("glass.babylon")).unwrap_or_else(|e| panic!("{e}"));
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    scene
}

/// Alpha survives lighting: the texel's alpha times the material's opacity
/// mixes the lit texel over what is behind, whatever the file order; alpha
/// 0 leaves the red quad visible, 255 hides it.
#[test]
fn translucent_textures_blend_over_what_is_behind() {
    let dir = std::env::temp_dir().join(format!("soft3d-alpha-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (alphas, opacity) in [([255, 128, 0, 255], 1.0), ([255, 255, 255, 255], 0.5)] {
        let scene = translucent_scene(&dir, alphas, opacity);
        let (w, h) = (160, 120);
        for img in [render::<FixedPoint>(&scene, w, h), render::<FloatingPoint>(&scene, w, h)] {
            // The front quad spans about x 52..108 at this distance; sample
            // the middle of each texel's quarter, and the red quad beside it.
            let at = |x: usize| img.get(x as u32, 60);
            let red = at(40);
            assert!(red.r() > 20 && red.g() == 0 && red.b() == 0, "red quad: {red:?}");
            let green = Rgb565::new(0, 63, 0);
            let expect = |a: f64| {
                let a = a * opacity as f64;
                let mix = |s: u8, d: u8| s as f64 * a + d as f64 * (1.0 - a);
                (mix(green.r(), red.r()), mix(green.g(), red.g()), mix(green.b(), red.b()))
            };
            for (quarter, &alpha) in alphas.iter().enumerate() {
                let c = at(59 + quarter * 14);
                let (r, g, b) = expect(alpha as f64 / 255.0);
                let close = |got: u8, want: f64| (got as f64 - want).abs() <= 1.0;
                assert!(
                    close(c.r(), r) && close(c.g(), g) && close(c.b(), b),
                    "quarter {quarter} alpha {alpha} opacity {opacity}: {c:?}, want ({r:.1}, {g:.1}, {b:.1})"
                );
            }
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}
