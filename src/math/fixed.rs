//! A 16.16 fixed-point number for attribute interpolation.

use core::fmt;

/// A signed fixed-point number with 16 integer and 16 fractional bits.
///
/// Arithmetic wraps (it never panics): interpolation adds gradients to a
/// start value, and linear functions evaluated modulo 2^32 give the right
/// result wherever the true value is in range, even if an intermediate
/// extrapolation is not. Conversions from `f32` saturate, and NaN maps to 0.
#[derive(Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Fixed(i32);

impl Fixed {
    /// Number of fractional bits.
    pub const FRAC_BITS: u32 = 16;
    /// The value 1.0.
    pub const ONE: Self = Self(1 << Self::FRAC_BITS);
    /// The value 0.0.
    pub const ZERO: Self = Self(0);

    /// Builds a value from its raw bits.
    pub const fn from_bits(bits: i32) -> Self {
        Self(bits)
    }

    /// The raw bits.
    pub const fn to_bits(self) -> i32 {
        self.0
    }

    /// Nearest representable value; saturates, NaN gives zero.
    #[inline]
    pub fn from_f32(v: f32) -> Self {
        // `as` saturates and maps NaN to 0.
        let scaled = v * (1u32 << Self::FRAC_BITS) as f32;
        Self((scaled + if scaled < 0.0 { -0.5 } else { 0.5 }) as i32)
    }

    /// The value as `f32`.
    #[inline]
    pub fn to_f32(self) -> f32 {
        self.0 as f32 * (1.0 / (1u32 << Self::FRAC_BITS) as f32)
    }

    /// Wrapping sum.
    #[inline]
    pub const fn wrapping_add(self, o: Self) -> Self {
        Self(self.0.wrapping_add(o.0))
    }

    /// Product, rounded toward negative infinity, saturating.
    #[inline]
    pub fn saturating_mul(self, o: Self) -> Self {
        let p = (self.0 as i64 * o.0 as i64) >> Self::FRAC_BITS;
        Self(p.clamp(i32::MIN as i64, i32::MAX as i64) as i32)
    }

    /// `1 / self`, saturating; zero maps to the largest value.
    #[inline]
    pub fn saturating_recip(self) -> Self {
        if self.0 > 0 {
            // 2^32 / r in 32-bit unsigned division (one instruction on a
            // Cortex-M3/M4, where the 64-bit one is a library call of a
            // hundred or more): (2^32 - 1) / r is the same floor unless r
            // divides 2^32, which the check catches.
            let r = self.0 as u32;
            let q = u32::MAX / r;
            let q = if q.wrapping_add(1).wrapping_mul(r) == 0 { q as u64 + 1 } else { q as u64 };
            return Self(q.min(i32::MAX as u64) as i32);
        }
        if self.0 == 0 {
            return Self(i32::MAX);
        }
        let r = (1i64 << (2 * Self::FRAC_BITS)) / self.0 as i64;
        Self(r.clamp(i32::MIN as i64, i32::MAX as i64) as i32)
    }
}

impl fmt::Debug for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Fixed({})", self.to_f32())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reciprocals_equal_the_64_bit_division() {
        for r in (1..=70_000i32).chain([1 << 16, 1 << 20, 3 << 20, i32::MAX, -1, -7, -(1 << 16), i32::MIN, 0]) {
            let expect = if r == 0 { i32::MAX as i64 } else { ((1i64 << 32) / r as i64).clamp(i32::MIN as i64, i32::MAX as i64) };
            assert_eq!(Fixed::from_bits(r).saturating_recip().to_bits() as i64, expect, "1 / {r}");
        }
    }

    #[test]
    fn conversions_round_and_saturate() {
        assert_eq!(Fixed::from_f32(1.0), Fixed::ONE);
        assert_eq!(Fixed::from_f32(-1.5).to_f32(), -1.5);
        assert_eq!(Fixed::from_f32(f32::NAN), Fixed::ZERO);
        assert_eq!(Fixed::from_f32(1e12).to_bits(), i32::MAX);
        assert_eq!(Fixed::from_f32(-1e12).to_bits(), i32::MIN);
        assert_eq!(Fixed::from_f32(0.75).saturating_mul(Fixed::from_f32(2.0)).to_f32(), 1.5);
        assert_eq!(Fixed::from_f32(0.25).saturating_recip().to_f32(), 4.0);
        assert_eq!(Fixed::ZERO.saturating_recip().to_bits(), i32::MAX);
    }
}
