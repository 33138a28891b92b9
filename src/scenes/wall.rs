//! The full-screen benchmark: one wall (two triangles) filling the whole
//! 320×240 view, drawn once with each effect. Nearly all of such a frame
//! is the span loop, so its instructions per pixel are the effect's cost
//! per pixel; `scripts/target-bench.sh` reports them per effect (the
//! frame minus the `empty` frame, over the 76,800 pixels). Shared by the
//! emulated benchmark and its host twin, which must give equal frames.

use super::study::{valid, CHECKER, QUAD_INDICES};
use crate::effect::{BlinnPhong, Color, Flat, Gouraud, Phong, Textured};
use crate::material::{Material, PerPixel, PerSpan};
use crate::math::{Mat4, Vec2, Vec3};
use crate::mesh::Mesh;
use crate::renderer::{DrawError, Frame};
use crate::scene::{Camera, DirectionalLight, Lights, PointLight};
use crate::settings::Settings;
use crate::texture::{Bilinear, Repeat};
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

/// Varyings the wall's renderer stores per vertex (Phong's six).
pub const WALL_VARYINGS: usize = 6;

// 24 × 18 units, turned so that its right side is 4 units deeper than its
// left (the plane z = 6 + x / 6): depth and 1/w vary across every row.
static POSITIONS: [Vec3; 4] =
    [Vec3::new(-12.0, -9.0, 4.0), Vec3::new(-12.0, 9.0, 4.0), Vec3::new(12.0, 9.0, 8.0), Vec3::new(12.0, -9.0, 8.0)];
// (1/6, 0, -1) normalized: facing the camera.
static NORMALS: [Vec3; 4] = [Vec3::new(0.164_398_99, 0.0, -0.986_393_9); 4];
/// The checkerboard repeats 8 times across and 6 times down.
static UVS: [Vec2; 4] = [Vec2::new(0.0, 6.0), Vec2::new(0.0, 0.0), Vec2::new(8.0, 0.0), Vec2::new(8.0, 6.0)];

/// The wall: two triangles, normals and checkerboard UVs.
pub static WALL: Mesh<'static> = valid(match Mesh::new(&POSITIONS, &NORMALS, &QUAD_INDICES) {
    Ok(m) => m.with_uvs(&UVS),
    Err(e) => Err(e),
});

/// One unit behind the origin, looking along +z: the wall overfills the
/// view on every side (its corners are off screen, within the guard band).
pub const WALL_CAMERA: Camera = Camera::looking_at(Vec3::new(0.0, 0.0, -1.0), Vec3::new(0.0, 0.0, 5.0));

/// Ambient, a directional light from the upper left and a point light
/// in front of the wall, so per-pixel lighting does all its work.
pub const WALL_LIGHTS: Lights = Lights {
    ambient: Vec3::new(0.15, 0.15, 0.15),
    point: Some(PointLight { position: Vec3::new(1.0, 1.0, 2.0), color: Vec3::new(0.6, 0.5, 0.4) }),
    directional: Some(DirectionalLight { direction: Vec3::new(0.3, -0.5, 1.0), color: Vec3::new(0.6, 0.6, 0.6) }),
};

const COLOR: Rgb888 = Rgb888::new(200, 180, 140);

static FLAT: Material<Flat> = Material::new(Flat).with_color(COLOR);
static GOURAUD: Material<Gouraud> = Material::new(Gouraud).with_color(COLOR);
static PHONG: Material<Phong> = Material::new(Phong::new()).with_color(COLOR);
static BLINN: Material<BlinnPhong> = Material::new(BlinnPhong::with_specular(Rgb888::WHITE, 24.0)).with_color(COLOR);
static TEX_AFFINE: Material<Textured<'static>> = Material::new(Textured::new(CHECKER));
static TEX: Material<Textured<'static>, PerPixel> = Material::new(Textured::new(CHECKER)).with_perspective::<PerPixel>();
static TEX32: Material<Textured<'static>, PerSpan<32>> = Material::new(Textured::new(CHECKER)).with_perspective::<PerSpan<32>>();
static BILINEAR32: Material<Textured<'static, Bilinear, Repeat>, PerSpan<32>> =
    Material::new(Textured::new(CHECKER)).with_perspective::<PerSpan<32>>();

/// Names of the wall scenes, in the order [`draw_wall`] takes them: the
/// effect, and for textures the perspective correction (`tex`: every
/// pixel, `tex32`: every 32 pixels, `tex-affine`: none) and the filter.
pub const WALL_SCENES: [&str; 8] =
    ["wall-flat", "wall-gouraud", "wall-phong", "wall-blinn", "wall-tex-affine", "wall-tex", "wall-tex32", "wall-bilinear32"];

/// Draws wall scene `index` (see [`WALL_SCENES`]); out-of-range indices
/// draw nothing. Every material is depth-tested and back-face culled; the
/// textured ones are lit per vertex, as [`Textured`] is.
pub fn draw_wall<C, S>(frame: &mut Frame<'_, '_, C, WALL_VARYINGS, S>, index: usize) -> Result<(), DrawError>
where
    C: Color,
    S: Settings,
{
    let model = &Mat4::IDENTITY;
    match index {
        0 => frame.draw(&WALL, model, &FLAT),
        1 => frame.draw(&WALL, model, &GOURAUD),
        2 => frame.draw(&WALL, model, &PHONG),
        3 => frame.draw(&WALL, model, &BLINN),
        4 => frame.draw(&WALL, model, &TEX_AFFINE),
        5 => frame.draw(&WALL, model, &TEX),
        6 => frame.draw(&WALL, model, &TEX32),
        7 => frame.draw(&WALL, model, &BILINEAR32),
        _ => Ok(()),
    }
}
