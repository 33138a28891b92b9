//! Vertex lighting in integers, for fixed-point settings: the lit color
//! ([`VertexInput::lit`](crate::effect::VertexInput)) of Gouraud and
//! textured effects from the ambient and directional lights, in 30-bit
//! fractions (within a thousandth of a level of the `f32` result). Without
//! an FPU the `f32` version (a dot product, clamps, three products by the
//! color) is some twenty library calls a vertex.
//!
//! It covers the common case, a draw call lit in model space (a
//! similarity model matrix) by ambient and directional light of less than
//! 2 per channel, on a mesh of unit normals; any other (a point light,
//! whose direction needs a normalization per vertex) is lit in `f32`:
//! [`IntegerLighting::new`] returns `None`.

use super::integer::{f32_from_parts, scaled_rounded};
use crate::math::{mul_wide, mul_wide_short};
use crate::mesh::Vectors;
use crate::scene::Lighting;
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

/// One in 30-bit fractions.
const ONE: i32 = 1 << 30;

/// The lights of one draw call in 30-bit fractions.
#[derive(Clone, Copy, Debug)]
pub struct IntegerLighting<'a> {
    normals: Vectors<'a>,
    /// The lights' colors are times the effect's scale per channel
    /// ([`Effect::lit_scale`](crate::effect::Effect::lit_scale)), and so
    /// is `cap`, the most light a channel takes.
    ambient: [i32; 3],
    /// Unit direction toward the light, and its color (zero if none).
    sun: ([i32; 3], [i32; 3]),
    cap: [u32; 3],
}

/// `v` in 30-bit fractions (truncated: within 2^-30), if it is in `[0, 2)`.
fn fraction(v: f32) -> Option<i32> {
    // Scaling by a power of two is exact; `as` saturates at 2^31 - 1.
    (0.0..2.0).contains(&v).then_some((v * ONE as f32) as i32)
}

impl<'a> IntegerLighting<'a> {
    /// The integer form of `lights` (in model space) for a mesh with
    /// `normals` (all of unit length or zero if `unit_normals`), lighting
    /// for an effect whose [`lit_scale`](crate::effect::Effect::lit_scale)
    /// is `scale`, or `None` where it does not apply.
    pub fn new(lights: &Lighting, normals: Vectors<'a>, unit_normals: bool, scale: [f32; 3]) -> Option<Self> {
        if lights.point.is_some() || !unit_normals {
            return None;
        }
        let color = |c: crate::math::Vec3| Some([fraction(c.x * scale[0])?, fraction(c.y * scale[1])?, fraction(c.z * scale[2])?]);
        let ambient = color(lights.ambient)?;
        let sun = match lights.sun {
            // A unit vector: each component in [-1, 1], rounded.
            Some((d, c)) => ([d.x, d.y, d.z].map(|v| scaled_rounded(v, 30, ONE).unwrap_or(0)), color(c)?),
            None => ([0; 3], [0; 3]),
        };
        let cap = color(crate::math::Vec3::ONE)?.map(|c| c as u32);
        Some(Self { normals, ambient, sun, cap })
    }

    /// The dot product of vertex `i`'s normal, in 30-bit fractions, with
    /// `d` (30-bit fractions too).
    #[inline(always)]
    fn dot_normal(&self, i: usize, d: [i32; 3]) -> i64 {
        let n = match self.normals {
            // Steps of 1/32767: 2^30 / 32767 is 32769 within 2^-30. The
            // steps times `d` first (products by 16-bit factors), then
            // times 32769 = 2^15 + 1.
            Vectors::I16 { steps, .. } => {
                let s = steps.get(i).copied().unwrap_or([0; 3]);
                let sum = mul_wide_short(d[0], s[0]) + mul_wide_short(d[1], s[1]) + mul_wide_short(d[2], s[2]);
                // Where a 64-bit product is a library call (ARMv6-M), LLVM
                // folded the shift and the sum back into one (about 40
                // instructions a vertex): the shifted sum is taken opaque.
                let shifted = if cfg!(soft3d_armv6m) { core::hint::black_box(sum << 15) } else { sum << 15 };
                return shifted + sum;
            }
            // Unit normals (checked when the mesh was built): finite, and
            // each component within [-1, 1] but for rounding.
            // (Not by `array::map`: a firmware with two lit effects called
            // its closure out of line, per vertex.)
            Vectors::F32(n) => n.get(i).map_or([0; 3], |n| {
                let fraction = |v: f32| scaled_rounded(v, 30, ONE).unwrap_or(0);
                [fraction(n.x), fraction(n.y), fraction(n.z)]
            }),
        };
        mul_wide(n[0], d[0]) + mul_wide(n[1], d[1]) + mul_wide(n[2], d[2])
    }

    /// [`VertexInput::lit`](crate::effect::VertexInput::lit) of vertex
    /// `i` of color `color`: computed in units of 2^-23 (below 2^31),
    /// truncated to `f32`, in the `channels` flagged (the others zero).
    #[inline(always)]
    pub fn lit(&self, i: usize, color: Rgb888, channels: [bool; 3]) -> [f32; 3] {
        let (direction, sun) = self.sun;
        // Each product at most 2^60, and so is the sum (both vectors unit).
        let dot = self.dot_normal(i, direction);
        let facing = ((dot.clamp(0, 1 << 60) + (1 << 29)) >> 30) as i32;
        let channel = |k: usize, c: u8| {
            if !channels[k] {
                return 0.0;
            }
            // Both terms below 2^31: their sum fits 32 bits unsigned.
            let term = ((mul_wide(sun[k], facing) + (1 << 29)) >> 30) as u32;
            let light = (self.ambient[k] as u32 + term).min(self.cap[k]);
            // At most 2^23 times 255, plus one half: below 2^31.
            f32_from_parts((light >> 7) * c as u32 + (1 << 22), -23)
        };
        [channel(0, color.r()), channel(1, color.g()), channel(2, color.b())]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effect::{lit_input, Effect, Gouraud};
    use crate::math::{xorshift, Vec3};
    use crate::scene::{DirectionalLight, Lights};
    use embedded_graphics::pixelcolor::Rgb565;

    #[test]
    fn integer_lighting_matches_f32_within_a_thousandth_of_a_level() {
        let mut next = xorshift(0xC0FF_EE11);
        let mut u = move |lo: f32, hi: f32| lo + (hi - lo) * (next() as f32 / u32::MAX as f32);
        let mut worst = 0.0f32;
        for case in 0..2000 {
            let direction = Vec3::new(u(-1.0, 1.0), u(-1.0, 1.0), u(-1.0, 1.0));
            let lights = Lights {
                ambient: Vec3::new(u(0.0, 0.5), u(0.0, 0.5), u(0.0, 0.5)),
                point: None,
                directional: (case % 10 != 0)
                    .then(|| DirectionalLight { direction, color: Vec3::new(u(0.0, 1.9), u(0.0, 1.9), u(0.0, 1.9)) }),
            };
            let lighting = Lighting::new(&lights, Vec3::ZERO);
            let normals: std::vec::Vec<Vec3> = (0..16)
                .map(|k| if k == 0 { Vec3::ZERO } else { Vec3::new(u(-1.0, 1.0), u(-1.0, 1.0), u(-1.0, 1.0)).normalize_or_zero() })
                .collect();
            // Levels of 0 to 255 (textures), and Rgb565's channels (Gouraud).
            let rgb565 = case % 2 == 0;
            let scale = if rgb565 { Gouraud::lit_scale::<Rgb565>() } else { [1.0; 3] };
            // Every third case with the normals as `i16` steps of 1/32767
            // (what the mesh gives for them is the reference then).
            let steps: std::vec::Vec<[i16; 3]> = normals.iter().map(|n| [n.x, n.y, n.z].map(|v| (v * 32767.0).round() as i16)).collect();
            let vectors = if case % 3 == 0 {
                Vectors::I16 { steps: &steps, scale: [1.0 / 32767.0; 3], offset: [0.0; 3] }
            } else {
                Vectors::F32(&normals)
            };
            let normals: std::vec::Vec<Vec3> = (0..normals.len()).map(|i| vectors.get(i)).collect();
            let integer = IntegerLighting::new(&lighting, vectors, true, scale).expect("ambient and directional light");
            for (i, n) in normals.iter().enumerate() {
                let color = Rgb888::new((u(0.0, 255.9)) as u8, (u(0.0, 255.9)) as u8, (u(0.0, 255.9)) as u8);
                let want = if rgb565 {
                    lit_input::<Rgb565, Gouraud>(&lighting, Vec3::ZERO, *n, color)
                } else {
                    lit_input::<Rgb565, crate::effect::Flat>(&lighting, Vec3::ZERO, *n, color)
                };
                for (g, w) in integer.lit(i, color, [true; 3]).iter().zip(want) {
                    worst = worst.max((g - w).abs());
                }
            }
        }
        // Rounding to 2^-30 of the lights, normal, N·L and their product,
        // and the f32 result's own rounding.
        assert!(worst < 0.001, "worst difference {worst} of a level");
        assert!(worst > 0.0);
    }

    #[test]
    fn lights_it_does_not_cover_are_declined() {
        let lit_by = |lights: Lights| Lighting::new(&lights, Vec3::ZERO);
        let n = [Vec3::new(0.0, 0.0, 1.0)];
        let mut lights = Lights::default();
        assert!(IntegerLighting::new(&lit_by(lights), Vectors::F32(&n), true, [1.0; 3]).is_some());
        assert!(IntegerLighting::new(&lit_by(lights), Vectors::F32(&n), false, [1.0; 3]).is_none());
        lights.ambient = Vec3::new(2.5, 0.0, 0.0);
        assert!(IntegerLighting::new(&lit_by(lights), Vectors::F32(&n), true, [1.0; 3]).is_none());
        lights.ambient = Vec3::new(f32::NAN, 0.0, 0.0);
        assert!(IntegerLighting::new(&lit_by(lights), Vectors::F32(&n), true, [1.0; 3]).is_none());
        let point = crate::scene::PointLight { position: Vec3::ZERO, color: Vec3::ONE };
        assert!(
            IntegerLighting::new(&lit_by(Lights { point: Some(point), ..Lights::default() }), Vectors::F32(&n), true, [1.0; 3]).is_none()
        );
    }
}
