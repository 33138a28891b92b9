//! Built-in scenes, shared by the demo, the board firmware, the tests and
//! the benchmarks, so that none of them needs a file: meshes generated at
//! compile time, and a crate baked by the bake tool ([`crate_scene`]).

use crate::blend::Opaque;
#[cfg(doc)]
use crate::effect::GrayLight;
use crate::effect::{Color, Gouraud, LightModel, MonoGouraud, Textured};
use crate::material::{Material, PerSpan};
use crate::math::{Mat4, Vec3};
use crate::mesh::{sphere_index_count, sphere_vertex_count, torus_index_count, torus_vertex_count, Mesh, MeshData};
use crate::renderer::{DrawError, Frame};
use crate::scene::{Camera, DirectionalLight, Lights, PointLight};
use crate::settings::Settings;
use crate::texture::{Nearest, Repeat};
use crate::tri::TriVertex;
use embedded_graphics::pixelcolor::{IntoStorage, PixelColor, Rgb888};
use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Pixel, Size};
use embedded_graphics::primitives::Rectangle;

/// A textured wooden crate, baked by `tools/bake` (i16 geometry, RGB565
/// texture) from `assets/demo/crate.babylon`, which
/// `scripts/make-demo-scene.py` writes. CI checks that the file is current;
/// rebake from `tools/bake` with
/// `cargo run --release -- ../../assets/demo/crate.babylon -o ../../src/scenes/crate_scene.rs --quantize i16`.
#[rustfmt::skip]
#[allow(clippy::all, clippy::pedantic)]
pub mod crate_scene {
    include!("crate_scene.rs");
}

mod demo_loop;
pub mod study;
pub mod wall;

pub use demo_loop::{DemoFrameReport, DemoLoop};

static TORUS_DATA: MeshData<{ torus_vertex_count(32, 16) }, { torus_index_count(32, 16) }> = MeshData::torus(32, 16, 1.0, 0.4);
static SPHERE_DATA: MeshData<{ sphere_vertex_count(24, 16) }, { sphere_index_count(24, 16) }> = MeshData::uv_sphere(24, 16, 0.8);
static CUBE_DATA: MeshData<24, 36> = MeshData::cube(1.2);

// The meshes are validated and their bounds computed at compile time, so a
// draw call starts from a ready `Mesh`.
/// A torus, 32 × 16 segments (561 vertices, 1,024 triangles).
pub static TORUS: Mesh<'static> = TORUS_DATA.mesh();
/// A UV sphere, 24 × 16 segments (425 vertices, 720 triangles).
pub static SPHERE: Mesh<'static> = SPHERE_DATA.mesh();
/// A cube of edge 1.2 (24 vertices, 12 triangles).
pub static CUBE: Mesh<'static> = CUBE_DATA.mesh();

/// Gouraud-shaded orange.
pub static ORANGE: Material<Gouraud> = Material::new(Gouraud).with_color(Rgb888::new(255, 140, 40));
/// The baked crate's texture, lit per vertex, perspective-correct every 32 pixels (the
/// accuracy study: as close to exact as every pixel, for less).
pub static CRATE: Material<Textured<'static>, PerSpan<32>> =
    Material::new(Textured::new(crate_scene::CRATE_TEXTURE)).with_cull(crate_scene::CRATE_CULL).with_perspective::<PerSpan<32>>();
/// Gouraud-shaded green.
pub static GREEN: Material<Gouraud> = Material::new(Gouraud).with_color(Rgb888::new(90, 220, 110));

/// Varyings per vertex the demo scene needs (the textured crate's five).
pub const DEMO_VARYINGS: usize = 5;
/// Vertices the demo scene needs per frame (plus room for clipping).
pub const DEMO_VERTICES: usize = 1100;
/// Triangles the demo scene can queue per frame.
pub const DEMO_TRIANGLES: usize = 1800;

/// The demo's camera.
pub fn demo_camera() -> Camera {
    Camera::looking_at(Vec3::new(0.0, 2.2, -6.0), Vec3::new(0.0, 0.0, 0.0))
}

/// The demo's lights: ambient, a white directional light from the upper
/// left, and a warm point light to the right.
pub fn demo_lights() -> Lights {
    Lights {
        ambient: Vec3::new(0.12, 0.12, 0.15),
        point: Some(PointLight { position: Vec3::new(4.0, 3.0, -3.0), color: Vec3::new(0.6, 0.45, 0.3) }),
        directional: Some(DirectionalLight { direction: Vec3::new(0.6, -0.8, 0.7), color: Vec3::new(0.7, 0.7, 0.7) }),
    }
}

/// Draws the demo scene at time `t` (seconds): a spinning Gouraud torus
/// between the baked, textured crate and a Gouraud sphere. The renderer
/// must store [`DEMO_VARYINGS`] varyings per vertex.
pub fn draw_demo<C, const V: usize, S>(frame: &mut Frame<'_, '_, C, V, S>, t: f32) -> Result<(), DrawError>
where
    C: Color,
    S: Settings,
{
    let spin = Mat4::rotation_y(t * 0.9) * Mat4::rotation_x(0.6 + t * 0.5);
    frame.draw(&TORUS, &spin, &ORANGE)?;
    let cube = Mat4::translation(Vec3::new(-2.4, 0.0, 0.5)) * Mat4::rotation_y(-t * 1.3) * Mat4::rotation_x(0.5);
    frame.draw(&crate_scene::CRATE, &cube, &CRATE)?;
    let sphere = Mat4::translation(Vec3::new(2.4, 0.2 * crate::math::sin(t * 2.0), 0.5)) * Mat4::rotation_y(t);
    frame.draw(&SPHERE, &sphere, &GREEN)
}

/// The lighting of the comparison benchmarks: ambient 0.15 and a white
/// directional light of 0.85 shining along the view direction.
pub fn headlight(camera: &Camera) -> Lights {
    Lights {
        ambient: Vec3::new(0.15, 0.15, 0.15),
        point: None,
        directional: Some(DirectionalLight { direction: camera.target - camera.position, color: Vec3::new(0.85, 0.85, 0.85) }),
    }
}

/// White Gouraud shading, the material of the benchmark scenes drawn from
/// Blender exports.
pub static WHITE: Material<Gouraud> = Material::new(Gouraud);

/// The benchmark scenes drawn from the shared Blender exports (when
/// available), each with its file's camera, [`headlight`] and [`WHITE`].
pub const FILE_SCENES: [(&str, &str); 2] = [("torus.babylon", "torus.babylon"), ("monkey", "monkey.babylon")];

/// [`WHITE`] as one interpolated light level ([`MonoGouraud`]) instead of
/// three channels: the same lighting, each channel within one level.
pub static WHITE_MONO: Material<MonoGouraud> = Material::new(MonoGouraud);

/// Scenes of [`FILE_SCENES`] and [`QUANTIZED_SCENES`] (named second) drawn
/// with [`WHITE_MONO`]. The last, the `i16` torus with one light level,
/// is the two cheapest geometry and shading choices together, the setting
/// for a white-lit scene on a core without an FPU.
pub const MONO_SCENES: [(&str, &str); 3] =
    [("torus.babylon-mono", "torus.babylon"), ("monkey-mono", "monkey"), ("torus.babylon-i16-mono", "torus.babylon-i16")];

/// The place of scene `name` among [`FILE_SCENES`] then
/// [`QUANTIZED_SCENES`] (the order the benchmarks store them in), if it is
/// one of them.
pub fn file_scene_index(name: &str) -> Option<usize> {
    FILE_SCENES.iter().chain(&QUANTIZED_SCENES).position(|(n, _)| *n == name)
}

/// The torus of [`FILE_SCENES`] (the scene named second) from `i16`
/// positions and normals, as `soft3d-bake --quantize i16` stores them: what
/// quantized geometry costs or saves in time, and changes in the frame.
pub const QUANTIZED_SCENES: [(&str, &str); 1] = [("torus.babylon-i16", "torus.babylon")];

/// The textured benchmark scenes: the monkey of [`FILE_SCENES`] drawn with
/// its texture by [`textured`], its perspective corrected at every pixel
/// (`monkey-tex`) or every 32 pixels (`monkey-tex32`, the setting
/// `docs/accuracy.md` recommends), then the same two lit by one
/// interpolated level ([`GrayLight`]): the headlight is gray and the
/// material white, so their frames are those of the first two.
pub const TEXTURED_SCENES: [&str; 4] = ["monkey-tex", "monkey-tex32", "monkey-tex-gray", "monkey-tex32-gray"];

/// The material of the textured benchmark scenes: `texture` (nearest texel,
/// repeating) times Gouraud lighting interpolated as `L` says, perspective mode `P`.
pub const fn textured<P: crate::material::Perspective, L: LightModel>(
    texture: crate::texture::Texture<'_>,
) -> Material<Textured<'_, Nearest, Repeat, Opaque, L>, P> {
    Material::new(Textured::new(texture)).with_perspective::<P>()
}

/// Names of the benchmark scenes, in the order [`draw_bench`] takes them.
pub const BENCH_SCENES: [&str; 5] = ["empty", "fill", "torus", "demo-t0", "demo-t1.7"];

/// Vertex-colored, depth-tested material of the `fill` benchmark scene.
pub static FILL: Material<crate::effect::VertexColor> = Material::new(crate::effect::VertexColor);

/// Draws benchmark scene `index` (see [`BENCH_SCENES`]) with the demo's
/// camera and lights: nothing (the cost of clearing and sending strips),
/// two vertex-colored triangles covering a 320×240 screen (the cost per
/// pixel), the generated torus alone, or the demo scene at two moments.
/// Out-of-range indices draw nothing.
pub fn draw_bench<C, const V: usize, S>(frame: &mut Frame<'_, '_, C, V, S>, index: usize) -> Result<(), DrawError>
where
    C: Color,
    S: Settings,
{
    match index {
        1 => {
            let v = |x: f64, y: f64, z: f32, r: u8, g: u8, b: u8| TriVertex { x, y, z, w: 1.0, color: Rgb888::new(r, g, b) };
            let (tl, tr) = (v(0.0, 0.0, 0.2, 255, 0, 0), v(320.0, 0.0, 0.4, 0, 255, 0));
            let (bl, br) = (v(0.0, 240.0, 0.6, 0, 0, 255), v(320.0, 240.0, 0.8, 255, 255, 255));
            frame.draw_window_triangles([[tl, tr, br], [tl, br, bl]], &FILL)
        }
        2 => frame.draw(&TORUS, &(Mat4::rotation_y(0.4) * Mat4::rotation_x(0.6)), &ORANGE),
        3 => draw_demo(frame, 0.0),
        4 => draw_demo(frame, 1.7),
        _ => Ok(()),
    }
}

/// A `DrawTarget` that only folds every pixel it receives into a 32-bit
/// FNV-1a checksum of the raw color values, so host and target frames can
/// be compared without storing them. It also counts the pixels that differ
/// from the background, the "pixels drawn" of per-pixel costs.
pub struct FrameChecksum<C> {
    size: Size,
    background: C,
    /// The checksum so far.
    pub sum: u32,
    /// Pixels received that are not the background color.
    pub drawn: u32,
}

impl<C> FrameChecksum<C> {
    /// A checksum target of the given size for frames on `background`.
    pub const fn new(width: u32, height: u32, background: C) -> Self {
        Self { size: Size::new(width, height), background, sum: 0x811c_9dc5, drawn: 0 }
    }
}

impl<C: PixelColor> OriginDimensions for FrameChecksum<C> {
    fn size(&self) -> Size {
        self.size
    }
}

impl<C: PixelColor + IntoStorage> DrawTarget for FrameChecksum<C>
where
    C::Storage: Into<u32>,
{
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(_, c) in pixels {
            self.drawn += (c != self.background) as u32;
            self.sum = (self.sum ^ c.into_storage().into()).wrapping_mul(0x0100_0193);
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(&mut self, _: &Rectangle, colors: I) -> Result<(), Self::Error> {
        for c in colors {
            self.drawn += (c != self.background) as u32;
            self.sum = (self.sum ^ c.into_storage().into()).wrapping_mul(0x0100_0193);
        }
        Ok(())
    }
}
