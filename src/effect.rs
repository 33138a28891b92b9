//! Effects: what color a pixel gets.
//!
//! An effect is a type. It says which per-vertex values (varyings) it needs
//! interpolated, computes them in the vertex stage, may compute one value
//! per triangle, and turns the interpolated values into a color in the span
//! loop. Each effect (with its material's other choices) is compiled into
//! its own span loop, so there is no per-pixel branch on a feature, and an
//! effect that no draw call uses is not in the binary.

use crate::math::{Interp, Vec2, Vec3};
use crate::scene::Lighting;
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

/// Most varyings any effect may ask for.
pub const MAX_VARYINGS: usize = 4;

/// Per-vertex input to an effect (world space).
#[derive(Clone, Copy, Debug)]
pub struct VertexInput {
    /// Position.
    pub position: Vec3,
    /// Unit normal (zero if the mesh's normal was zero or invalid).
    pub normal: Vec3,
    /// Vertex color, or the material color if the mesh has none.
    pub color: Rgb888,
    /// Texture coordinate (zero if the mesh has none).
    pub uv: Vec2,
}

/// Per-triangle input to an effect (world space).
#[derive(Clone, Copy, Debug)]
pub struct FaceInput {
    /// Centroid.
    pub position: Vec3,
    /// Unit geometric normal of the triangle as wound.
    pub normal: Vec3,
    /// Color of the first vertex (or the material color).
    pub color: Rgb888,
}

/// A way of coloring pixels. See the [module docs](self).
pub trait Effect: Copy + 'static {
    /// Number of interpolated values (at most [`MAX_VARYINGS`]).
    const VARYINGS: usize;
    /// Whether [`Effect::vertex`] uses the lights (and so the world-space
    /// position and normal), so unlit effects skip that work.
    const LIT_VERTICES: bool;
    /// Whether [`Effect::face`] is used, so other effects skip the face normal.
    const USES_FACE: bool;
    /// Name for reports.
    const NAME: &'static str;

    /// Varyings of one vertex.
    fn vertex(&self, v: &VertexInput, lights: &Lighting) -> [f32; MAX_VARYINGS];
    /// The per-triangle color.
    fn face(&self, f: &FaceInput, lights: &Lighting) -> Rgb888;
    /// The color of a pixel from the triangle's color (converted once per
    /// triangle), the interpolated varyings and the color already there
    /// (for effects that blend; the others ignore it and the load is
    /// optimized away).
    fn shade<C: From<Rgb888> + Into<Rgb888> + Copy, S: Interp>(face: C, v: &[S; MAX_VARYINGS], dst: C) -> C;
}

/// The first `V` varyings `effect` computes for one vertex (the renderer
/// stores `V` per vertex; `V >= E::VARYINGS` is checked at compile time).
#[inline]
pub(crate) fn vertex_varyings<E: Effect, const V: usize>(effect: &E, input: &VertexInput, lights: &Lighting) -> [f32; V] {
    let mut out = [0.0; V];
    if E::VARYINGS > 0 {
        let all = effect.vertex(input, lights);
        let n = V.min(all.len());
        out[..n].copy_from_slice(&all[..n]);
    }
    out
}

/// Light times color, per channel, clamped to [0, 255]. Varyings carry an
/// extra 0.5 so that the span loop's `floor` rounds to nearest.
#[inline]
fn lit(light: Vec3, c: Rgb888) -> [f32; 3] {
    let ch = |l: f32, v: u8| crate::scene::clamp01(l) * v as f32;
    [ch(light.x, c.r()), ch(light.y, c.g()), ch(light.z, c.b())]
}

#[inline]
fn rgb_varyings(c: [f32; 3]) -> [f32; MAX_VARYINGS] {
    [c[0] + 0.5, c[1] + 0.5, c[2] + 0.5, 0.0]
}

#[inline]
fn to_rgb888(c: [f32; 3]) -> Rgb888 {
    // `as` saturates; inputs are already in [0, 255].
    Rgb888::new((c[0] + 0.5) as u8, (c[1] + 0.5) as u8, (c[2] + 0.5) as u8)
}

#[inline]
fn shade_rgb<C: From<Rgb888>, S: Interp>(v: &[S; MAX_VARYINGS]) -> C {
    let ch = |s: S| s.quantize(0, 255) as u8;
    C::from(Rgb888::new(ch(v[0]), ch(v[1]), ch(v[2])))
}

/// Flat shading: one N·L per triangle from its geometric normal.
#[derive(Clone, Copy, Debug, Default)]
pub struct Flat;

impl Effect for Flat {
    const VARYINGS: usize = 0;
    const LIT_VERTICES: bool = false;
    const USES_FACE: bool = true;
    const NAME: &'static str = "flat";
    fn vertex(&self, _: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        [0.0; MAX_VARYINGS]
    }
    fn face(&self, f: &FaceInput, lights: &Lighting) -> Rgb888 {
        to_rgb888(lit(lights.diffuse(f.position, f.normal), f.color))
    }
    #[inline(always)]
    fn shade<C: From<Rgb888> + Into<Rgb888> + Copy, S: Interp>(face: C, _: &[S; MAX_VARYINGS], _: C) -> C {
        face
    }
}

/// Gouraud shading: N·L per vertex, the lit color interpolated.
#[derive(Clone, Copy, Debug, Default)]
pub struct Gouraud;

impl Effect for Gouraud {
    const VARYINGS: usize = 3;
    const LIT_VERTICES: bool = true;
    const USES_FACE: bool = false;
    const NAME: &'static str = "gouraud";
    fn vertex(&self, v: &VertexInput, lights: &Lighting) -> [f32; MAX_VARYINGS] {
        rgb_varyings(lit(lights.diffuse(v.position, v.normal), v.color))
    }
    fn face(&self, _: &FaceInput, _: &Lighting) -> Rgb888 {
        Rgb888::BLACK
    }
    #[inline(always)]
    fn shade<C: From<Rgb888> + Into<Rgb888> + Copy, S: Interp>(_: C, v: &[S; MAX_VARYINGS], _: C) -> C {
        shade_rgb(v)
    }
}

/// Unlit vertex colors, interpolated (the material color where the mesh
/// has no colors).
#[derive(Clone, Copy, Debug, Default)]
pub struct VertexColor;

impl Effect for VertexColor {
    const VARYINGS: usize = 3;
    const LIT_VERTICES: bool = false;
    const USES_FACE: bool = false;
    const NAME: &'static str = "unlit";
    fn vertex(&self, v: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        rgb_varyings([v.color.r() as f32, v.color.g() as f32, v.color.b() as f32])
    }
    fn face(&self, _: &FaceInput, _: &Lighting) -> Rgb888 {
        Rgb888::BLACK
    }
    #[inline(always)]
    fn shade<C: From<Rgb888> + Into<Rgb888> + Copy, S: Interp>(_: C, v: &[S; MAX_VARYINGS], _: C) -> C {
        shade_rgb(v)
    }
}

/// A diagnostic effect: adds one to every channel of the pixel per
/// fragment (saturating at 255), so that the image counts how many
/// fragments covered each pixel. Use it with [`DepthOff`](crate::material::DepthOff)
/// and an 8-bit-per-channel color type to count fragments before the depth
/// test, or to find overdraw.
#[derive(Clone, Copy, Debug, Default)]
pub struct FragmentCount;

impl Effect for FragmentCount {
    const VARYINGS: usize = 0;
    const LIT_VERTICES: bool = false;
    const USES_FACE: bool = false;
    const NAME: &'static str = "count";
    fn vertex(&self, _: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        [0.0; MAX_VARYINGS]
    }
    fn face(&self, _: &FaceInput, _: &Lighting) -> Rgb888 {
        Rgb888::BLACK
    }
    #[inline(always)]
    fn shade<C: From<Rgb888> + Into<Rgb888> + Copy, S: Interp>(_: C, _: &[S; MAX_VARYINGS], dst: C) -> C {
        let d: Rgb888 = dst.into();
        C::from(Rgb888::new(d.r().saturating_add(1), d.g().saturating_add(1), d.b().saturating_add(1)))
    }
}
