//! The accuracy study's built-in scenes (`docs/accuracy.md`): a textured
//! floor at a grazing angle and two planes crossing far away. Shared by the
//! study tool (`tools/accuracy`, host) and the emulated benchmark
//! (`firmware/qemu-bench`), so that both render the very same data.

use crate::math::{Vec2, Vec3};
use crate::mesh::Mesh;
use crate::scene::{Camera, DirectionalLight, Lights};
use crate::texture::Texture;
use embedded_graphics::pixelcolor::Rgb888;

const fn camera(position: Vec3, target: Vec3) -> Camera {
    Camera::looking_at(position, target)
}

/// Unwraps a mesh built at compile time (a bad one is a build error).
pub(super) const fn valid(m: Result<Mesh<'static>, crate::mesh::MeshError>) -> Mesh<'static> {
    match m {
        Ok(m) => m,
        Err(_) => panic!("invalid built-in mesh"),
    }
}

/// RGB565 from 8-bit channels, rounded.
const fn rgb565(r: u32, g: u32, b: u32) -> u16 {
    (((r * 31 + 127) / 255) << 11 | ((g * 63 + 127) / 255) << 5 | ((b * 31 + 127) / 255)) as u16
}

/// Side of the checkerboard texture.
pub const CHECKER_SIDE: usize = 64;

/// A 64×64 checkerboard of 8-texel squares, cream and blue (RGB565).
pub static CHECKER_TEXELS: [u16; CHECKER_SIDE * CHECKER_SIDE] = {
    let mut t = [0u16; CHECKER_SIDE * CHECKER_SIDE];
    let mut i = 0;
    while i < t.len() {
        let (x, y) = (i % CHECKER_SIDE, i / CHECKER_SIDE);
        t[i] = if (x / 8 + y / 8) % 2 == 0 { rgb565(240, 230, 200) } else { rgb565(40, 90, 160) };
        i += 1;
    }
    t
};

/// The checkerboard as a texture.
pub static CHECKER: Texture<'static> = match Texture::new(&CHECKER_TEXELS, CHECKER_SIDE, CHECKER_SIDE) {
    Ok(t) => t,
    Err(_) => panic!("a power-of-two texture"),
};

/// Height of the floor.
const FLOOR_Y: f32 = -0.4;
static FLOOR_POSITIONS: [Vec3; 4] =
    [Vec3::new(-6.0, FLOOR_Y, 0.0), Vec3::new(-6.0, FLOOR_Y, 30.0), Vec3::new(6.0, FLOOR_Y, 30.0), Vec3::new(6.0, FLOOR_Y, 0.0)];
static FLOOR_NORMALS: [Vec3; 4] = [Vec3::new(0.0, 1.0, 0.0); 4];
/// The texture repeats 8 times each way (512 texels across the floor).
static FLOOR_UVS: [Vec2; 4] = [Vec2::new(0.0, 0.0), Vec2::new(0.0, 8.0), Vec2::new(8.0, 8.0), Vec2::new(8.0, 0.0)];
pub(super) static QUAD_INDICES: [u16; 6] = [0, 1, 2, 0, 2, 3];

/// A 12 × 30 floor, two triangles, checkerboard UVs (draw it textured with
/// [`CHECKER`]).
pub static FLOOR: Mesh<'static> = match valid(Mesh::new(&FLOOR_POSITIONS, &FLOOR_NORMALS, &QUAD_INDICES)).with_uvs(&FLOOR_UVS) {
    Ok(m) => m,
    Err(_) => panic!("one UV per vertex"),
};
/// The floor's camera: one unit above it, looking down its length.
pub const FLOOR_CAMERA: Camera =
    Camera { position: Vec3::new(0.0, 0.6, -1.0), target: Vec3::new(0.0, 0.0, 8.0), ..camera(Vec3::ZERO, Vec3::ONE) };
/// Full ambient light: the texture as it is.
pub const FLOOR_LIGHTS: Lights = Lights { ambient: Vec3::ONE, point: None, directional: None };

// Two planes spanning x in [-12, 12], y in [-9, 9], 40 m away; one is 4 cm
// deeper on the right, the other on the left, so they cross at x = 0 at an
// angle of 0.0017 rad. Normals: (∓0.04, 0, -24) normalized.
static ZFIGHT_A_POSITIONS: [Vec3; 4] =
    [Vec3::new(-12.0, -9.0, 40.0), Vec3::new(-12.0, 9.0, 40.0), Vec3::new(12.0, 9.0, 40.04), Vec3::new(12.0, -9.0, 40.04)];
static ZFIGHT_A_NORMALS: [Vec3; 4] = [Vec3::new(0.0016666644, 0.0, -0.9999986); 4];
static ZFIGHT_B_POSITIONS: [Vec3; 4] =
    [Vec3::new(-12.0, -9.0, 40.04), Vec3::new(-12.0, 9.0, 40.04), Vec3::new(12.0, 9.0, 40.0), Vec3::new(12.0, -9.0, 40.0)];
static ZFIGHT_B_NORMALS: [Vec3; 4] = [Vec3::new(-0.0016666644, 0.0, -0.9999986); 4];

/// The first plane (nearer on the left), drawn first, in [`ZFIGHT_A_COLOR`].
pub static ZFIGHT_A: Mesh<'static> = valid(Mesh::new(&ZFIGHT_A_POSITIONS, &ZFIGHT_A_NORMALS, &QUAD_INDICES));
/// The second plane (nearer on the right), in [`ZFIGHT_B_COLOR`].
pub static ZFIGHT_B: Mesh<'static> = valid(Mesh::new(&ZFIGHT_B_POSITIONS, &ZFIGHT_B_NORMALS, &QUAD_INDICES));
/// Red.
pub const ZFIGHT_A_COLOR: Rgb888 = Rgb888::new(220, 60, 50);
/// Blue.
pub const ZFIGHT_B_COLOR: Rgb888 = Rgb888::new(50, 110, 220);
/// One meter behind the origin, 41 m from the planes (near 0.1, far 1000).
pub const ZFIGHT_CAMERA: Camera = camera(Vec3::new(0.0, 0.0, -1.0), Vec3::new(0.0, 0.0, 40.0));
/// Ambient 0.3 and a directional light from the upper left.
pub const ZFIGHT_LIGHTS: Lights = Lights {
    ambient: Vec3::new(0.3, 0.3, 0.3),
    point: None,
    directional: Some(DirectionalLight { direction: Vec3::new(0.3, -0.5, 1.0), color: Vec3::new(0.7, 0.7, 0.7) }),
};
