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
        if super::HARD_FLOAT {
            // `as` saturates and maps NaN to 0.
            let scaled = v * (1u32 << Self::FRAC_BITS) as f32;
            Self((scaled + if scaled < 0.0 { -0.5 } else { 0.5 }) as i32)
        } else {
            Self(rounded_from_bits(v, Self::FRAC_BITS as i32))
        }
    }

    /// `v` times 2^16 truncated toward zero, saturating, NaN giving zero
    /// (a vertex value for plane setup).
    #[inline]
    pub fn truncate_f32(v: f32) -> Self {
        Self(Self::scaled_truncated(v, Self::FRAC_BITS as i32))
    }

    /// `v * 2^k` truncated toward zero to an integer, saturating, NaN
    /// giving zero, for `0 <= k <= 32` (no float operation without an FPU).
    #[inline]
    pub(crate) fn scaled_truncated(v: f32, k: i32) -> i32 {
        if super::HARD_FLOAT {
            (v * (1u64 << k) as f32) as i32
        } else {
            truncated_from_bits(v, k)
        }
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
        let p = super::mul_wide(self.0, o.0);
        let r = (p >> Self::FRAC_BITS) as i32;
        // It fits when the bits above it are all copies of its sign: one
        // compare, not a clamp in 64 bits (two branches per bound).
        if (p >> (31 + Self::FRAC_BITS)) as i32 == r >> 31 {
            Self(r)
        } else if p < 0 {
            Self(i32::MIN)
        } else {
            Self(i32::MAX)
        }
    }

    /// `1 / sqrt(self)` for a positive value, rounded to within one unit
    /// of the last place; zero or less gives zero. Integer only (the same
    /// bits on every core): a table and two Newton steps in 32×32→64-bit
    /// products, where an exact integer square root and a 64-bit division
    /// took five hundred instructions (per-pixel lighting normalizes two to
    /// five vectors per pixel).
    #[inline]
    pub fn rsqrt(self) -> Self {
        if self.0 <= 0 {
            return Self::ZERO;
        }
        let bits = self.0 as u32;
        // Shift by an even amount to m = M * 2^30, M in [1, 4):
        // 1 / sqrt(x) = 2^(9 + s/2) / sqrt(M) in units of 2^-16.
        let s = super::leading_zeros(bits) & !1;
        let m = bits << s;
        // g = 1 / sqrt(M) in units of 2^-30, from the table by the top
        // seven bits of m (`m >> 25` in 32..128), then Newton's
        // g' = g * (3 - M g^2) / 2: the relative error 0.8% becomes 1e-4,
        // then 1.5e-8 (results reach 2^24 units).
        // Every factor fits 32 bits (M g < 2, M g^2 near 1, g <= 1 + 1e-4),
        // so each product is one 32×32→64 multiply.
        let mut g = RSQRT_TABLE[(m >> 25) as usize - 32];
        for _ in 0..2 {
            let mg = (super::mul_wide_unsigned(m, g) >> 30) as u32;
            let mgg = (super::mul_wide_unsigned(mg, g) >> 30) as u32;
            g = (super::mul_wide_unsigned(g, (3u32 << 30) - mgg) >> 31) as u32;
        }
        // Rounded to units of 2^-16.
        let shift = 21 - s / 2;
        Self((((g >> (shift - 1)) + 1) >> 1) as i32)
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

/// `1 / sqrt(M)` in units of 2^-30 at the middle of each of the 96
/// intervals `[k, k + 1) * 2^25` of `m = M * 2^30` (`k` from 32 to 127),
/// for [`Fixed::rsqrt`]: `2^30 / sqrt(M) = 2^45 / sqrt(m)`.
const RSQRT_TABLE: [u32; 96] = {
    let mut t = [0u32; 96];
    let mut i = 0;
    while i < 96 {
        let mid = (((32 + i as u64) << 1) + 1) << 24;
        t[i] = ((1u64 << 45) / mid.isqrt()) as u32;
        i += 1;
    }
    t
};

/// `(v * 2^k) as i32` from the bits of `v`, with no float operation:
/// for a core without an FPU, where the multiply and the saturating
/// conversion are a library call each (the conversion four: three
/// comparisons and the conversion). Truncated toward zero, saturating,
/// NaN giving zero, for `0 <= k <= 32`. The common case (a value within
/// the range) takes one branch and no test for NaN.
#[inline]
fn truncated_from_bits(v: f32, k: i32) -> i32 {
    let bits = v.to_bits();
    // First, in one unsigned compare, a positive `v * 2^k` in `[1, 2^24)`
    // (a color or depth in 16.16): the mantissa shifted right by `right`
    // in `[0, 24)`. The sign bit takes a negative value's `right` below
    // zero, out of that range.
    let right = 150 - k - (bits >> 23) as i32;
    if (right as u32) < 24 {
        return (((bits & 0x7F_FFFF) | 0x80_0000) >> right) as i32;
    }
    // |v * 2^k| = mantissa * 2^shift. Zero and subnormals give a shift
    // far below -24 (they convert to 0), infinity and NaN one above 8.
    let shift = (bits << 1 >> 24) as i32 - 150 + k;
    let mantissa = (bits & 0x7F_FFFF) | 0x80_0000;
    let magnitude = if shift < 0 {
        if shift >= -24 {
            mantissa >> -shift
        } else {
            0
        }
    } else if shift < 8 {
        mantissa << shift
    } else if bits << 1 > 0xFF00_0000 {
        return 0;
    } else {
        // 2^31 or more (infinity included): saturated.
        return if (bits as i32) < 0 { i32::MIN } else { i32::MAX };
    };
    if (bits as i32) < 0 {
        (magnitude as i32).wrapping_neg()
    } else {
        magnitude as i32
    }
}

/// `(v * 2^k ± 0.5) as i32` from the bits of `v` (see
/// [`truncated_from_bits`]): rounded half away from zero through an `f32`
/// addition, which rounds ties to even once the product reaches 2^23.
/// Saturating; NaN gives zero. For `0 <= k <= 32`.
#[inline]
fn rounded_from_bits(v: f32, k: i32) -> i32 {
    let bits = v.to_bits();
    let negative = bits >> 31 != 0;
    let exponent = ((bits >> 23) & 0xFF) as i32;
    let fraction = bits & 0x7F_FFFF;
    if exponent == 0xFF && fraction != 0 {
        return 0;
    }
    // |v * 2^k| = mantissa * 2^shift (zero and subnormals give a shift far
    // below -24: they convert to 0).
    let mantissa = fraction | 0x80_0000;
    let shift = exponent - 150 + k;
    let magnitude = if exponent == 0 {
        0
    } else if shift >= 8 {
        // 2^31 or more (infinity included): saturated.
        return if negative { i32::MIN } else { i32::MAX };
    } else if shift > 0 {
        // An integer whose ulp is 2 or more: adding 0.5 rounds back to it.
        mantissa << shift
    } else if shift >= -25 {
        // `x + 0.5` in units of 2^shift is `mantissa + 2^(s-1)` (below
        // 2^26), which the addition rounds to 24 significant bits, ties to
        // even, before the conversion truncates it.
        let s = (-shift + 1) as u32;
        let (mantissa, s) = (mantissa << 1, s); // one more bit: s >= 1 even at shift 0
        let sum = mantissa + (1 << (s - 1));
        let dropped = if sum >= 1 << 26 {
            3
        } else if sum >= 1 << 25 {
            2
        } else if sum >= 1 << 24 {
            1
        } else {
            0
        };
        let sum = if dropped > 0 {
            let (kept, rest, half) = (sum >> dropped, sum & ((1 << dropped) - 1), 1 << (dropped - 1));
            let up = rest > half || (rest == half && kept & 1 == 1);
            (kept + up as u32) << dropped
        } else {
            sum
        };
        sum >> s
    } else {
        // Below a quarter: `x + 0.5` stays below 1.
        0
    };
    if negative {
        (magnitude as i32).wrapping_neg()
    } else {
        magnitude as i32
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
    fn reciprocal_square_roots_are_within_one_unit() {
        // Every power of two, both ends of each table interval, and a
        // sweep with an odd stride across the whole positive range.
        let powers = (0..31).map(|k| 1i32 << k);
        let edges = (0..31).flat_map(|k| [(3i64 << k) - 1, 3i64 << k]).filter(|&v| v <= i32::MAX as i64).map(|v| v as i32);
        let sweep = (1..=i32::MAX).step_by(104_729);
        let mut worst = 0.0f64;
        for r in powers.chain(edges).chain(sweep).chain([1, 2, 3, 65_535, 65_536, 65_537, i32::MAX]) {
            let exact = 65536.0 / (r as f64 / 65536.0).sqrt();
            let got = Fixed::from_bits(r).rsqrt().to_bits() as f64;
            let off = (got - exact).abs();
            worst = worst.max(off);
            assert!(off <= 1.0, "rsqrt({r} / 2^16): {got} against {exact}");
        }
        // Exact where the result is: 1 / sqrt(4) and 1 / sqrt(1/4).
        assert_eq!(Fixed::from_bits(4 << 16).rsqrt(), Fixed::from_bits(1 << 15));
        assert_eq!(Fixed::from_bits(1 << 14).rsqrt(), Fixed::from_bits(2 << 16));
        assert!(worst > 0.0);
        for r in [0, -1, i32::MIN] {
            assert_eq!(Fixed::from_bits(r).rsqrt(), Fixed::ZERO);
        }
    }

    #[test]
    fn products_saturate_exactly_like_a_64_bit_clamp() {
        let edges = [
            0,
            1,
            -1,
            2,
            -2,
            1 << 15,
            1 << 16,
            -(1 << 16),
            1 << 17,
            (1 << 23) - 1,
            1 << 23,
            1 << 24,
            -(1 << 24),
            i32::MAX,
            i32::MIN,
            i32::MIN + 1,
        ];
        // A multiplicative sequence through the whole range, both signs.
        let mut x = 0x9E37_79B9u32;
        let spread = (0..4000).map(|_| {
            x = x.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (x as i32) >> (x % 24)
        });
        let values: std::vec::Vec<i32> = edges.into_iter().chain(spread).collect();
        for &a in &values {
            for &b in values.iter().step_by(7) {
                let expect = ((a as i64 * b as i64) >> 16).clamp(i32::MIN as i64, i32::MAX as i64) as i32;
                assert_eq!(Fixed::from_bits(a).saturating_mul(Fixed::from_bits(b)).to_bits(), expect, "{a} * {b}");
            }
        }
    }

    #[test]
    fn reciprocals_equal_the_64_bit_division() {
        for r in (1..=70_000i32).chain([1 << 16, 1 << 20, 3 << 20, i32::MAX, -1, -7, -(1 << 16), i32::MIN, 0]) {
            let expect = if r == 0 { i32::MAX as i64 } else { ((1i64 << 32) / r as i64).clamp(i32::MIN as i64, i32::MAX as i64) };
            assert_eq!(Fixed::from_bits(r).saturating_recip().to_bits() as i64, expect, "1 / {r}");
        }
    }

    #[test]
    fn conversions_from_the_bits_equal_the_float_formulas() {
        let float_round = |v: f32| {
            let scaled = v * 65536.0;
            (scaled + if scaled < 0.0 { -0.5 } else { 0.5 }) as i32
        };
        let float_trunc = |v: f32| (v * 65536.0) as i32;
        let check = |bits: u32| {
            let v = f32::from_bits(bits);
            assert_eq!(rounded_from_bits(v, 16), float_round(v), "round {v:e} ({bits:#x})");
            assert_eq!(truncated_from_bits(v, 16), float_trunc(v), "truncate {v:e} ({bits:#x})");
            // Truncation serves other scales too (lighting's 2^30).
            for k in [0, 1, 15, 17, 30, 31, 32] {
                assert_eq!(truncated_from_bits(v, k), (v * (1u64 << k) as f32) as i32, "truncate {v:e} ({bits:#x}) at 2^{k}");
            }
        };
        // Every exponent with a spread of mantissas (the low bits odd and
        // even), both signs, and the values around each rounding boundary.
        for sign in [0u32, 1 << 31] {
            for exponent in 0..=255u32 {
                for fraction in (0..0x80_0000u32).step_by(4099).chain([0, 1, 2, 3, 0x40_0000, 0x40_0001, 0x7F_FFFE, 0x7F_FFFF]) {
                    check(sign | exponent << 23 | fraction);
                }
            }
        }
        for v in [0.5f32 / 65536.0, 1.5 / 65536.0, 2.5 / 65536.0, 128.0, 128.00002, 255.99998, 32767.5, 32768.0, -32768.0, 8388607.5] {
            for b in v.to_bits() - 2..=v.to_bits() + 2 {
                check(b);
            }
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
