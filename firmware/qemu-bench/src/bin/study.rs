//! Times the accuracy study's configurations (`tools/accuracy`,
//! `docs/accuracy.md`) on an emulated Cortex-M: every configuration key of
//! the study, every study scene, one frame each, printed as
//! `study,key,scene,core,instructions,checksum` (instructions as in the
//! benchmark: the whole frame, strip clears included, the checksum sink
//! excluded). `scripts/accuracy.sh` runs it on both cores.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::hprintln;
use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use soft3d::effect::{Effect, Gouraud, Phong, Textured};
use soft3d::material::{Affine, PerPixel, PerSpan, Perspective};
use soft3d::math::{Fixed, Mat4};
use soft3d::mesh::Mesh;
use soft3d::scenes::study::*;
use soft3d::scenes::{headlight, FrameChecksum, DEMO_TRIANGLES, DEMO_VERTICES};
use soft3d::texture::{Bilinear, Filter, Nearest, Repeat, Texture};
use soft3d::{Camera, Depth16, Depth32, DepthF32, Lights, Material, Precision, Renderer, Settings};
use soft3d_qemu_bench::*;

/// Phong needs six varyings.
type StudyRenderer<S> = Renderer<Rgb565, 320, 240, 16, DEMO_VERTICES, DEMO_TRIANGLES, 6, S>;

/// One object of a study scene: mesh, model, color, texture.
type Object = (&'static Mesh<'static>, Mat4, Rgb888, Option<&'static Texture<'static>>);

/// Most objects a study scene has.
const MAX_OBJECTS: usize = 2;

/// Renders `objects` in one timed frame: textured ones with `Textured<F>`,
/// the others Gouraud or (with `phong`) per-pixel lit, all with
/// perspective mode `P`, and prints the line.
fn measure<S: Settings, P: Perspective, F: Filter>(
    timer: &mut Timer,
    renderer: &mut StudyRenderer<S>,
    key: &str,
    scene: &str,
    (camera, lights): (Camera, Lights),
    objects: &[Object],
    phong: bool,
) {
    // Materials outlive the frame that borrows them.
    let color = |k: usize| objects.get(k).map_or(Rgb888::WHITE, |o| o.2);
    let textured: [Option<Material<Textured<'static, F, Repeat>, P>>; MAX_OBJECTS] = core::array::from_fn(|k| {
        objects.get(k).and_then(|o| o.3).map(|t| Material::new(Textured::new(*t)).with_color(color(k)).with_perspective::<P>())
    });
    let gouraud: [Material<Gouraud, P>; MAX_OBJECTS] =
        core::array::from_fn(|k| Material::new(Gouraud).with_color(color(k)).with_perspective::<P>());
    let per_pixel: [Material<Phong, P>; MAX_OBJECTS] =
        core::array::from_fn(|k| Material::new(Phong::new()).with_color(color(k)).with_perspective::<P>());
    let mut out = TimedSink { inner: FrameChecksum::new(320, 240, Rgb565::BLACK), ticks: 0 };
    timer.start();
    let mut frame = renderer.begin_frame(&camera, &lights, Rgb565::BLACK);
    for (k, &(mesh, model, _, _)) in objects.iter().enumerate().take(MAX_OBJECTS) {
        let _ = match &textured[k] {
            Some(t) => frame.draw(mesh, &model, t),
            None if phong => frame.draw(mesh, &model, &per_pixel[k]),
            None => frame.draw(mesh, &model, &gouraud[k]),
        };
    }
    let Ok(_) = frame.finish(&mut out);
    let total = timer.instructions();
    let sink = out.ticks * INSTRUCTIONS_PER_TICK;
    match total {
        Some(n) => hprintln!("study,{}{},{},{},{},{:08x}", key, BACKEND, scene, TARGET, n - sink, out.inner.sum),
        None => hprintln!("study,{}{},{},{},overflow,{:08x}", key, BACKEND, scene, TARGET, out.inner.sum),
    }
}

/// Renders every study scene with one configuration.
fn config<S: Settings, P: Perspective, F: Filter>(timer: &mut Timer, key: &str, phong: bool)
where
    Textured<'static, F, Repeat>: Effect,
{
    let mut renderer: StudyRenderer<S> = Renderer::new(Rgb565::BLACK);
    #[cfg(soft3d_assets)]
    {
        let (camera, meshes) = file_scene(0);
        let torus: [Object; 1] = [(meshes[0].0, meshes[0].1, Rgb888::WHITE, None)];
        measure::<S, P, F>(timer, &mut renderer, key, "torus", (camera, headlight(&camera)), &torus, phong);
        let camera = monkey_file::CAMERA;
        let monkey: [Object; 1] = [(&monkey_file::SUZANNE, monkey_file::SUZANNE_MODEL, Rgb888::WHITE, Some(&monkey_file::SUZANNE_TEXTURE))];
        measure::<S, P, F>(timer, &mut renderer, key, "monkey", (camera, headlight(&camera)), &monkey, phong);
    }
    let floor: [Object; 1] = [(&FLOOR, Mat4::IDENTITY, Rgb888::WHITE, Some(&CHECKER))];
    measure::<S, P, F>(timer, &mut renderer, key, "floor", (FLOOR_CAMERA, FLOOR_LIGHTS), &floor, phong);
    let planes: [Object; 2] = [(&ZFIGHT_A, Mat4::IDENTITY, ZFIGHT_A_COLOR, None), (&ZFIGHT_B, Mat4::IDENTITY, ZFIGHT_B_COLOR, None)];
    measure::<S, P, F>(timer, &mut renderer, key, "zfight", (ZFIGHT_CAMERA, ZFIGHT_LIGHTS), &planes, phong);
}

/// Built with `SOFT3D_STUDY_ONLY=key1,key2` in the environment, only those
/// configurations run (`scripts/qemu-profile.py`, and the micromath build).
const ONLY: Option<&str> = option_env!("SOFT3D_STUDY_ONLY");

/// Appended to the keys of a build with soft3d's `micromath` backend
/// (`--no-default-features --features micromath`), as the study names them.
const BACKEND: &str = if cfg!(feature = "libm") { "" } else { "+micromath" };

/// Expands the study's shared list into `run_all`.
macro_rules! study_configs {
    ($(($key:literal, $interp:literal, $scalar:ty, $bits:literal, $persp:literal, $p:ty, $f:ty, $phong:literal, $z:ident)),* $(,)?) => {
        /// Times every configuration of the study.
        fn run_all(timer: &mut Timer) {
            $(
                if ONLY.is_none_or(|only| only.split(',').any(|k| k == $key)) {
                    config::<Precision<$scalar, $bits, $z>, $p, $f>(timer, $key, $phong);
                }
            )*
        }
    };
}

include!(concat!(env!("CARGO_MANIFEST_DIR"), "/../../tools/accuracy/configs.rs"));

#[entry]
fn main() -> ! {
    let mut timer = start_timer();
    run_all(&mut timer);
    exit()
}
