//! The scene, renderer and timing shared by the "pay only for the effects
//! you use" firmwares (`effects_flat`, `effects_flat_nodepth`,
//! `effects_flat_v6`, `effects_all`; `scripts/effects-bench.sh` builds,
//! runs and compares them). Included by each with `#[path]`, so every firmware links only
//! the effects its own `main` names: this module is generic and draws
//! nothing by itself.
//!
//! Each timed frame prints
//! `effects,build,scene,core,instructions,geometry,checksum,queued`
//! (instructions as in the main benchmark: `begin_frame` to `finish`, the
//! checksum sink's own work excluded; geometry: the part spent in the draw
//! calls, before `finish` rasterizes), and each firmware one
//! `renderer,build,core,bytes` line (`size_of` of its renderer, a `static`).

use cortex_m_semihosting::hprintln;
use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use soft3d::effect::Effect;
use soft3d::material::{DepthMode, Perspective};
use soft3d::math::{Mat4, Vec3};
use soft3d::mesh::Mesh;
use soft3d::scenes::{demo_camera, demo_lights, FrameChecksum, CUBE, SPHERE, TORUS};
use soft3d::{Frame, Material, Renderer};
pub use soft3d_qemu_bench::{exit, start_timer};
use soft3d_qemu_bench::{TimedSink, Timer, INSTRUCTIONS_PER_TICK, TARGET};

/// The numeric settings each core would ship with (the accuracy study's
/// recommendation): `f32` interpolation where there is an FPU, fixed point
/// on the M0+ code. One per firmware, so that no build carries both.
#[cfg(target_abi = "eabihf")]
pub type Mode = soft3d::FloatingPoint;
/// See the `eabihf` definition.
#[cfg(not(target_abi = "eabihf"))]
pub type Mode = soft3d::FixedPoint;

/// Vertices per frame: the scene's 1,034 plus room for clipped triangles.
pub const VERTICES: usize = 1100;
/// Triangles per frame: all 1,768 of the scene could be queued.
pub const TRIANGLES: usize = 1800;

/// The renderer of a firmware storing `V` varyings per vertex: 320×240
/// RGB565 in 16-row strips. `V` is the only thing that differs between
/// the builds' renderers (0 for flat only, 6 for the general one, which
/// Phong needs).
pub type EffectsRenderer<const V: usize> = Renderer<Rgb565, 320, 240, 16, VERTICES, TRIANGLES, V, Mode>;

/// A frame of [`EffectsRenderer`] drawing materials that live for `'m`.
pub type EffectsFrame<'r, 'm, const V: usize> = Frame<'r, 'm, Rgb565, V, Mode>;

/// The renderer as a `static` (on a board it would be one, and so it counts
/// in the ELF's static RAM that the script reports), borrowed once. Black,
/// so it is zero-initialized (`.bss`, no flash). Expects this module as
/// `common` at the crate root.
macro_rules! static_renderer {
    ($v:literal) => {{
        static mut RENDERER: $crate::common::EffectsRenderer<$v> = $crate::common::EffectsRenderer::new($crate::common::BACKGROUND);
        // SAFETY: the macro is expanded once, in `main`, which runs once
        // and never returns: this is the only reference ever made.
        unsafe { &mut *core::ptr::addr_of_mut!(RENDERER) }
    }};
}
pub(crate) use static_renderer;

/// The whole `main` of a firmware in which the flat effect is the only one
/// that exists: a renderer storing `$v` varyings, the scene drawn with
/// `Material<Flat, Affine, $depth>`, one timed frame printed as build
/// `$build`, frame `$scene`. Expects this module as `common` at the crate
/// root. (Unused by `effects_all`, which includes this module too.)
#[allow(unused_macros)]
macro_rules! flat_only_firmware {
    ($v:literal, $depth:ty, $build:literal, $scene:literal) => {
        #[cortex_m_rt::entry]
        fn main() -> ! {
            use $crate::common;
            let mut timer = common::start_timer();
            let renderer = common::static_renderer!($v);
            common::report_renderer::<$v>($build);
            let flat = common::materials::<soft3d::effect::Flat, soft3d::material::Affine, $depth>(soft3d::effect::Flat);
            common::measure(&mut timer, renderer, $build, $scene, |frame| common::draw_scene(frame, &flat));
            common::exit()
        }
    };
}
#[allow(unused_imports)]
pub(crate) use flat_only_firmware;

/// The background of every frame (and the renderer's fill).
pub const BACKGROUND: Rgb565 = Rgb565::BLACK;

/// Objects of the scene.
pub const OBJECTS: usize = 4;

/// The scene: the benchmark's torus in the middle, a sphere on the right,
/// a cube on the left and a second cube behind the torus, overlapping it
/// on screen (so the depth test decides pixels), each with its color.
pub fn objects() -> [(&'static Mesh<'static>, Mat4, Rgb888); OBJECTS] {
    [
        (&TORUS, Mat4::rotation_y(0.4) * Mat4::rotation_x(0.6), Rgb888::new(255, 140, 40)),
        (&SPHERE, Mat4::translation(Vec3::new(2.4, 0.2, 0.5)), Rgb888::new(90, 220, 110)),
        (&CUBE, Mat4::translation(Vec3::new(-2.4, 0.0, 0.5)) * Mat4::rotation_y(-0.7) * Mat4::rotation_x(0.5), Rgb888::new(80, 140, 255)),
        (&CUBE, Mat4::translation(Vec3::new(0.6, 0.5, 1.8)) * Mat4::rotation_y(0.3), Rgb888::new(230, 230, 230)),
    ]
}

/// One material per object: `effect` in the object's color, interpolated
/// by `P`, using depth as `D` says.
pub fn materials<E: Effect, P: Perspective, D: DepthMode>(effect: E) -> [Material<E, P, D>; OBJECTS] {
    let objects = objects();
    core::array::from_fn(|k| Material::new(effect).with_color(objects[k].2).with_perspective::<P>().with_depth::<D>())
}

/// Draws every object of the scene, object `k` with `materials[k]`.
pub fn draw_scene<'m, E, P, D, const V: usize>(frame: &mut EffectsFrame<'_, 'm, V>, materials: &'m [Material<E, P, D>; OBJECTS])
where
    E: Effect,
    P: Perspective,
    D: DepthMode,
{
    for ((mesh, model, _), material) in objects().iter().zip(materials) {
        // Capacities hold the whole scene; a refused draw would show as a
        // different checksum.
        let _ = frame.draw(mesh, model, material);
    }
}

/// Prints the renderer's size, what the `static` holds.
pub fn report_renderer<const V: usize>(build: &str) {
    hprintln!("renderer,{},{},{}", build, TARGET, core::mem::size_of::<EffectsRenderer<V>>());
}

/// Renders one frame (the demo's camera and lights) with `draw`, timed,
/// into the checksum sink, and prints its `effects,...` line.
pub fn measure<'m, const V: usize>(
    timer: &mut Timer,
    renderer: &mut EffectsRenderer<V>,
    build: &str,
    scene: &str,
    draw: impl FnOnce(&mut EffectsFrame<'_, 'm, V>),
) {
    let (camera, lights) = (demo_camera(), demo_lights());
    let mut out = TimedSink { inner: FrameChecksum::new(320, 240, BACKGROUND), ticks: 0 };
    timer.start();
    let mut frame = renderer.begin_frame(&camera, &lights, BACKGROUND);
    draw(&mut frame);
    let geometry = timer.instructions();
    let Ok(stats) = frame.finish(&mut out);
    let total = timer.instructions();
    let sink = out.ticks * INSTRUCTIONS_PER_TICK;
    match (total, geometry) {
        (Some(n), Some(g)) => hprintln!("effects,{},{},{},{},{},{:08x},{}", build, scene, TARGET, n - sink, g, out.inner.sum, stats.queued),
        _ => hprintln!("effects,{},{},{},overflow,overflow,{:08x},{}", build, scene, TARGET, out.inner.sum, stats.queued),
    }
}
