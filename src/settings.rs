//! Compile-time precision choices of a renderer.
//!
//! Every precision trade is a type, so its cost is paid only by the
//! firmware that picks it: see [`Settings`].

use crate::math::{Fixed, Interp};
use core::marker::PhantomData;

/// The numeric choices a [`Renderer`](crate::Renderer) is built with.
pub trait Settings: 'static {
    /// Scalar that attribute plane equations are stepped in.
    type Interp: Interp;
    /// Sub-pixel bits of the vertex grid: vertices snap to `1 / 2^bits`
    /// of a pixel before coverage is decided. At most 8.
    const SUBPIXEL_BITS: u32;
    /// How each pixel's depth is stored.
    type Depth: DepthFormat;
}

/// The stored depth value of settings `S` (the depth buffer's element).
pub type DepthValue<S> = <<S as Settings>::Depth as DepthFormat>::Value;

/// A depth buffer format: what one pixel's depth is stored as.
///
/// Depth is interpolated in the settings' scalar as a value in `[1, 65536)`
/// (larger nearer, linear in screen space); the format decides how much of
/// that value survives in the buffer, and so how close two surfaces can be
/// before the depth test cannot order them, at the price of its bytes per
/// pixel in the strip's depth buffer.
pub trait DepthFormat: 'static {
    /// One pixel's stored depth. Larger is nearer. Plain bytes, so that
    /// a strip's depths are cleared by words.
    type Value: bytemuck::Pod + PartialOrd + core::fmt::Debug;
    /// The cleared value: farther than anything drawable.
    const CLEAR: Self::Value;
    /// A short name for reports.
    const NAME: &'static str;
    /// The stored form of an interpolated depth.
    fn store<I: Interp>(depth: I) -> Self::Value;
    /// Whether an interpolated depth is nearer than a stored one:
    /// `store(depth) > stored`.
    #[inline(always)]
    fn nearer<I: Interp>(depth: I, stored: Self::Value) -> bool {
        Self::store(depth) > stored
    }
}

/// 16-bit depth (2 bytes per pixel): the integer part of the depth value.
/// Surfaces closer than one part in 65,534 of the window depth range
/// (which is far from uniform in distance: see `docs/accuracy.md`) tie.
pub struct Depth16;

impl DepthFormat for Depth16 {
    type Value = u16;
    const CLEAR: u16 = 0;
    const NAME: &'static str = "16-bit";
    #[inline(always)]
    fn store<I: Interp>(depth: I) -> u16 {
        depth.depth16() as u16
    }
    #[inline(always)]
    fn nearer<I: Interp>(depth: I, stored: u16) -> bool {
        depth.depth16() > stored as u32
    }
}

/// 32-bit fixed-point depth (4 bytes per pixel): the depth value with 16
/// fractional bits (15 of them carry information with [`Fixed`]
/// interpolation, whose plane holds depth halved).
pub struct Depth32;

impl DepthFormat for Depth32 {
    type Value = u32;
    const CLEAR: u32 = 0;
    const NAME: &'static str = "32-bit fixed";
    #[inline(always)]
    fn store<I: Interp>(depth: I) -> u32 {
        depth.depth32()
    }
}

/// `f32` depth (4 bytes per pixel): the interpolated value as it is. With
/// `f32` interpolation nothing is lost; with [`Fixed`] it holds the same
/// bits as [`Depth32`], converted.
pub struct DepthF32;

impl DepthFormat for DepthF32 {
    type Value = f32;
    const CLEAR: f32 = 0.0;
    const NAME: &'static str = "f32";
    #[inline(always)]
    fn store<I: Interp>(depth: I) -> f32 {
        depth.depth_f32()
    }
}

/// The standard [`Settings`]: interpolation scalar `I` (`f32` or
/// [`Fixed`]), `SUBPIXEL_BITS` bits of sub-pixel precision (0 to 8) and
/// depth format `Z` ([`Depth16`] unless given).
pub struct Precision<I, const SUBPIXEL_BITS: u32, Z = Depth16>(PhantomData<(I, Z)>);

impl<I: Interp, const B: u32, Z: DepthFormat> Settings for Precision<I, B, Z> {
    type Interp = I;
    const SUBPIXEL_BITS: u32 = B;
    type Depth = Z;
}

/// Fixed-point interpolation, 6 sub-pixel bits: for FPU-less parts
/// (Cortex-M0+), where its triangle setup runs in integers only (see
/// [`FixedBasis`](crate::math::FixedBasis)), and so does the vertex stage
/// but for uncommon lights (see
/// [`IntegerVertices`](crate::vertex::IntegerVertices)). Six bits, because the accuracy study (`docs/accuracy.md`)
/// measured them clearly closer to the exact image than four (edges follow
/// the reference), at no measurable cost in instructions; the guard band is
/// then 32,768 pixels.
pub type FixedPoint = Precision<Fixed, 6>;
/// `f32` interpolation, 6 sub-pixel bits: for parts with an FPU (Cortex-M4F,
/// M33F), where the study measured it both faster and more accurate than
/// fixed point.
pub type FloatingPoint = Precision<f32, 6>;

#[cfg(test)]
mod tests {
    use super::*;

    /// `Depth16::nearer` compares without narrowing: it must agree with
    /// the stored value's comparison over the depths the contract allows
    /// (`[0, 65536)` stored units).
    fn nearer_is_the_stored_comparison<S: Interp>(depth: impl Fn(u32) -> S) {
        // Each stored unit at 0, 1/4 and 1/2 of a unit past it, against
        // the stored values next to it and at both ends.
        for unit in 0..65536u32 {
            for part in [0, 1, 2] {
                let d = depth(unit * 4 + part);
                for stored in [0, unit.saturating_sub(1), unit, unit + 1, 65535].map(|s| s.min(65535) as u16) {
                    assert_eq!(Depth16::nearer(d, stored), Depth16::store(d) > stored, "unit {unit}.{part}, stored {stored}");
                }
            }
        }
    }

    #[test]
    fn the_16_bit_depth_test_compares_what_it_stores() {
        // Fixed holds depth halved with 16 fractional bits: a stored unit
        // is 2^15, the quarter steps 2^13; its largest value sits just
        // below the contract's end.
        nearer_is_the_stored_comparison(|q| Fixed::from_bits((q << 13) as i32));
        assert!(Depth16::nearer(Fixed::from_bits(i32::MAX), 65534));
        nearer_is_the_stored_comparison(|q| q as f32 / 4.0);
    }
}
