//! The scalar that attribute interpolation runs in: `f32` or [`Fixed`].
//!
//! The rasterizer is written once, generic over this trait; each
//! implementation is a compile-time choice with its own cost and accuracy.

use super::Fixed;

/// A number type that plane equations are stepped in.
///
/// All operations are total: they saturate or wrap, never panic, and
/// quantization clamps, so no garbage reaches a buffer.
pub trait Interp: Copy + Default + PartialEq + core::fmt::Debug + 'static {
    /// A short name for reports ("f32", "fixed16").
    const NAME: &'static str;
    /// From `f32` (saturating; NaN gives zero).
    fn from_f32(v: f32) -> Self;
    /// To `f32`.
    fn to_f32(self) -> f32;
    /// `self + d`.
    fn add(self, d: Self) -> Self;
    /// `self + d * n`.
    fn add_mul(self, d: Self, n: i32) -> Self;
    /// `self * o`.
    fn mul(self, o: Self) -> Self;
    /// `1 / self` for a positive value (zero or less gives a large value).
    fn recip(self) -> Self;
    /// `floor(self * 2^frac_bits)`, clamped to `[0, max]`.
    fn quantize(self, frac_bits: u32, max: u32) -> u32;
}

impl Interp for f32 {
    const NAME: &'static str = "f32";
    #[inline]
    fn from_f32(v: f32) -> Self {
        if v.is_nan() {
            0.0
        } else {
            v
        }
    }
    #[inline]
    fn to_f32(self) -> f32 {
        self
    }
    #[inline]
    fn add(self, d: Self) -> Self {
        self + d
    }
    #[inline]
    fn add_mul(self, d: Self, n: i32) -> Self {
        self + d * n as f32
    }
    #[inline]
    fn mul(self, o: Self) -> Self {
        self * o
    }
    #[inline]
    fn recip(self) -> Self {
        if self > 1e-30 {
            1.0 / self
        } else {
            1e30
        }
    }
    #[inline]
    fn quantize(self, frac_bits: u32, max: u32) -> u32 {
        // `as` saturates at 0 and u32::MAX and maps NaN to 0.
        ((self * (1u32 << frac_bits) as f32) as u32).min(max)
    }
}

impl Interp for Fixed {
    const NAME: &'static str = "fixed16";
    #[inline]
    fn from_f32(v: f32) -> Self {
        Fixed::from_f32(v)
    }
    #[inline]
    fn to_f32(self) -> f32 {
        Fixed::to_f32(self)
    }
    #[inline]
    fn add(self, d: Self) -> Self {
        self.wrapping_add(d)
    }
    #[inline]
    fn add_mul(self, d: Self, n: i32) -> Self {
        Fixed::from_bits(self.to_bits().wrapping_add(d.to_bits().wrapping_mul(n)))
    }
    #[inline]
    fn mul(self, o: Self) -> Self {
        self.saturating_mul(o)
    }
    #[inline]
    fn recip(self) -> Self {
        if self.to_bits() <= 0 {
            Fixed::from_bits(i32::MAX)
        } else {
            self.saturating_recip()
        }
    }
    #[inline]
    fn quantize(self, frac_bits: u32, max: u32) -> u32 {
        let v = self.to_bits() >> (Fixed::FRAC_BITS - frac_bits);
        v.clamp(0, max as i32) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stepping<S: Interp>() {
        let mut v = S::from_f32(10.5);
        let d = S::from_f32(0.25);
        for _ in 0..4 {
            v = v.add(d);
        }
        assert_eq!(v.quantize(0, 255), 11);
        assert_eq!(S::from_f32(10.5).add_mul(d, 4), v);
        assert_eq!(S::from_f32(-3.0).quantize(0, 255), 0);
        assert_eq!(S::from_f32(300.0).quantize(0, 255), 255);
        assert_eq!(S::from_f32(1.5).quantize(8, 65535), 384);
        assert_eq!(S::from_f32(0.5).recip().to_f32(), 2.0);
    }

    #[test]
    fn both_scalars_step_and_quantize_alike() {
        stepping::<f32>();
        stepping::<Fixed>();
    }
}
