//! Host time per frame of the accuracy study's configurations
//! (`tools/accuracy`, `docs/accuracy.md`): the work the emulated firmware
//! (`firmware/qemu-bench/src/bin/study.rs`) times, on this machine.
//!
//! One benchmark per configuration key of `tools/accuracy/configs.rs` and
//! study scene, named `study/<key>/<scene>`: a 320×240 RGB565 frame in
//! 16-row strips with six varyings, `begin_frame`, the scene's draws
//! (textured objects with `Textured<F, Repeat>`, the others `Gouraud` or,
//! for per-pixel configurations, `Phong`), and `finish` into a sink that
//! does next to nothing. The scenes are the study tool's own
//! (`tools/accuracy/src/scenes.rs`); the Blender exports are read from
//! `../shared/assets` (or the directory in `SOFT3D_ASSETS`) and skipped
//! with a message when absent.
//!
//! ```sh
//! cargo bench --features simulator --bench study              # every configuration and scene
//! cargo bench --features simulator --bench study -- 'study/f32-6-span16-nearest-gouraud/'
//! ```
//!
//! Criterion writes each mean to
//! `target/criterion/study/<key>/<scene>/new/estimates.json`.

use criterion::measurement::WallTime;
use criterion::{criterion_group, criterion_main, BenchmarkGroup, BenchmarkId, Criterion};
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use soft3d::effect::{Gouraud, Phong, Textured};
use soft3d::material::{Affine, PerPixel, PerSpan, Perspective};
use soft3d::math::Fixed;
use soft3d::mesh::Mesh;
use soft3d::scenes::{DEMO_TRIANGLES, DEMO_VERTICES};
use soft3d::texture::{Bilinear, Filter, Nearest, Repeat, Texture};
use soft3d::{Depth16, Depth32, DepthF32, DrawError, HostRenderer, Material, Precision, Settings};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

/// The study tool's exact reference, needed by its scene module (a host
/// tool without the crate's minimum Rust version).
#[allow(dead_code, clippy::incompatible_msrv)]
#[path = "../tools/accuracy/src/reference.rs"]
mod reference;

/// The study tool's scenes.
#[allow(dead_code)]
#[path = "../tools/accuracy/src/scenes.rs"]
mod scenes;

use scenes::{Scene, HEIGHT, WIDTH};

/// The firmware's renderer: 16-row strips, six varyings (Phong needs six),
/// the demo's vertex and triangle capacities.
type StudyRenderer<S> = HostRenderer<Rgb565, 6, S>;

/// Rows per strip.
const STRIP: usize = 16;

/// The display: folds every pixel it receives into an XOR of the raw
/// values, so the strips are consumed but cost next to nothing (the
/// firmware subtracts its sink's time; `FrameChecksum`'s serial FNV-1a
/// would add a multiply chain per pixel here).
struct XorSink(u16);

impl OriginDimensions for XorSink {
    fn size(&self) -> Size {
        Size::new(WIDTH as u32, HEIGHT as u32)
    }
}

impl DrawTarget for XorSink {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        self.0 = pixels.into_iter().fold(self.0, |a, Pixel(_, c)| a ^ c.into_storage());
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(&mut self, _: &Rectangle, colors: I) -> Result<(), Self::Error> {
        self.0 = colors.into_iter().fold(self.0, |a, c| a ^ c.into_storage());
        Ok(())
    }
}

/// Registers the benchmarks of one configuration, one per scene: renders
/// with settings `S`, perspective mode `P` and texture filter `F`, the
/// untextured objects per pixel when `phong` is set.
fn config<S: Settings, P: Perspective, F: Filter>(group: &mut BenchmarkGroup<'_, WallTime>, key: &str, phong: bool, all: &[Scene]) {
    for scene in all {
        let textures: Result<Vec<Texture<'_>>, _> = scene.textures.iter().map(|t| t.texture()).collect();
        let textures = match textures {
            Ok(t) => t,
            Err(e) => {
                println!("skipped: study/{key}/{}: texture: {e:?}", scene.name);
                continue;
            }
        };
        let meshes: Result<Vec<Mesh<'_>>, String> = scene
            .objects
            .iter()
            .map(|o| {
                let m = Mesh::new(&o.positions, &o.normals, &o.indices).map_err(|e| format!("{e:?}"))?;
                match &o.uvs {
                    Some(uv) => m.with_uvs(uv).map_err(|e| format!("{e:?}")),
                    None => Ok(m),
                }
            })
            .collect();
        let meshes = match meshes {
            Ok(m) => m,
            Err(e) => {
                println!("skipped: study/{key}/{}: mesh: {e}", scene.name);
                continue;
            }
        };
        // Materials outlive the frames that borrow them.
        let textured: Vec<Option<Material<Textured<'_, F, Repeat>, P>>> = scene
            .objects
            .iter()
            .map(|o| o.texture.map(|t| Material::new(Textured::<F, Repeat>::new(textures[t])).with_color(o.color).with_perspective::<P>()))
            .collect();
        let gouraud: Vec<Material<Gouraud, P>> =
            scene.objects.iter().map(|o| Material::new(Gouraud).with_color(o.color).with_perspective::<P>()).collect();
        let per_pixel: Vec<Material<Phong, P>> =
            scene.objects.iter().map(|o| Material::new(Phong::new()).with_color(o.color).with_perspective::<P>()).collect();
        let mut renderer: StudyRenderer<S> = match HostRenderer::new(WIDTH, HEIGHT, STRIP, DEMO_VERTICES, DEMO_TRIANGLES, Rgb565::BLACK) {
            Ok(r) => r,
            Err(e) => {
                println!("skipped: study/{key}/{}: {e}", scene.name);
                continue;
            }
        };

        // The timed work: one color frame, as the firmware times it.
        let frame_once = |renderer: &mut StudyRenderer<S>| -> (u16, Result<(), DrawError>) {
            let mut sink = XorSink(0);
            let mut frame = renderer.begin_frame(&scene.camera, &scene.lights, Rgb565::BLACK);
            let mut drawn = Ok(());
            for (k, o) in scene.objects.iter().enumerate() {
                let res = match &textured[k] {
                    Some(t) => frame.draw(&meshes[k], &o.model, t),
                    None if phong => frame.draw(&meshes[k], &o.model, &per_pixel[k]),
                    None => frame.draw(&meshes[k], &o.model, &gouraud[k]),
                };
                drawn = drawn.and(res);
            }
            let Ok(_) = frame.finish(&mut sink);
            (sink.0, drawn)
        };

        // A refused draw is timed all the same (the firmware ignores it
        // too), but said.
        if let (_, Err(e)) = frame_once(&mut renderer) {
            println!("warning: study/{key}/{}: a draw was refused: {e:?}", scene.name);
        }
        group.bench_function(BenchmarkId::new(key, scene.name), |b| b.iter(|| black_box(frame_once(&mut renderer).0)));
    }
}

/// Expands the study's shared list (`tools/accuracy/configs.rs`) into
/// [`run_all`].
macro_rules! study_configs {
    ($(($key:literal, $interp:literal, $scalar:ty, $bits:literal, $persp:literal, $p:ty, $f:ty, $phong:literal, $z:ident)),* $(,)?) => {
        /// Registers every configuration of the study on every scene.
        fn run_all(group: &mut BenchmarkGroup<'_, WallTime>, all: &[Scene]) {
            $(config::<Precision<$scalar, $bits, $z>, $p, $f>(group, $key, $phong, all);)*
        }
    };
}

include!("../tools/accuracy/configs.rs");

/// Where the shared Blender exports are: `SOFT3D_ASSETS`, or
/// `../shared/assets` beside the repository.
fn assets() -> PathBuf {
    match std::env::var_os("SOFT3D_ASSETS") {
        Some(dir) => PathBuf::from(dir),
        None => PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/assets")),
    }
}

/// The `study` group: every configuration on every scene.
fn study(c: &mut Criterion) {
    let mut notes = Vec::new();
    let all = scenes::all(&assets(), &mut notes);
    for note in &notes {
        println!("{note}");
    }
    let mut group = c.benchmark_group("study");
    run_all(&mut group, &all);
    group.finish();
}

/// Short by default (a noisy 2-core machine, inside a regeneration
/// script); the command line can ask for more.
fn short() -> Criterion {
    Criterion::default().sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(1))
}

criterion_group! {
    name = benches;
    config = short();
    targets = study
}
criterion_main!(benches);
