//! `f32` operations for cores without an FPU (ARMv6-M), where each float
//! operation is a library call: the general routines handle every class
//! of value, while the triangle setup's operands are finite. These give
//! the same results as the hardware (and as the host), by integer
//! arithmetic on the bits for the common case; elsewhere they are the
//! plain operators.

use super::HARD_FLOAT;

/// `a < b` for `f32` values that are not NaN. Without an FPU by their
/// bits, which order finite values and infinities as integers once a
/// negative value's magnitude bits are flipped; there `-0.0 < 0.0` (equal
/// in IEEE 754), a difference no conversion to an integer or fixed point
/// sees.
#[inline(always)]
pub(crate) fn less(a: f32, b: f32) -> bool {
    if HARD_FLOAT {
        a < b
    } else {
        ordered_bits(a) < ordered_bits(b)
    }
}

/// `a > b` for `f32` values that are not NaN (see [`less`]).
#[inline(always)]
pub(crate) fn greater(a: f32, b: f32) -> bool {
    if HARD_FLOAT {
        a > b
    } else {
        ordered_bits(a) > ordered_bits(b)
    }
}

/// The bits of `v` as an `i32` that orders like `v` (see [`less`]).
#[inline(always)]
fn ordered_bits(v: f32) -> i32 {
    let b = v.to_bits() as i32;
    b ^ (((b >> 31) as u32) >> 1) as i32
}

/// `a * b`, rounded to nearest even as IEEE 754 does. Without an FPU, two
/// normal operands with a normal product take integer arithmetic on their
/// significands (the library's general multiply also calls a 64-bit
/// multiply), as does a zero times a finite value; any other goes to the
/// library.
#[inline(always)]
pub(crate) fn mul(a: f32, b: f32) -> f32 {
    if HARD_FLOAT {
        a * b
    } else {
        // (A `match`: `unwrap_or` would call the library every time.)
        match mul_normal(a, b) {
            Some(product) => product,
            None => a * b,
        }
    }
}

/// `a * b` if both and the rounded product are normal numbers, or if one
/// is zero and the other finite.
#[inline]
fn mul_normal(a: f32, b: f32) -> Option<f32> {
    let (x, y) = (a.to_bits(), b.to_bits());
    let (ea, eb) = ((x >> 23) & 0xFF, (y >> 23) & 0xFF);
    // Exponent fields 1 to 254: normal (not zero, subnormal, infinite or NaN).
    if ea.wrapping_sub(1) >= 254 || eb.wrapping_sub(1) >= 254 {
        // Zero times a finite value (a texture coordinate's whole periods
        // are often none) is a zero of the signs' product.
        let zero = (x << 1 == 0 && eb != 255) || (y << 1 == 0 && ea != 255);
        return zero.then(|| f32::from_bits((x ^ y) & 0x8000_0000));
    }
    let (ma, mb) = ((x & 0x7F_FFFF) | 0x80_0000, (y & 0x7F_FFFF) | 0x80_0000);
    // The product of two 24-bit significands, in [2^46, 2^48), as a high
    // word (bits 32 up) and a low word, from 16×8-bit pieces: ma = ah 2^16
    // + al with ah below 2^8.
    let (ah, al, bh, bl) = (ma >> 16, ma & 0xFFFF, mb >> 16, mb & 0xFFFF);
    let cross = ah * bl + al * bh; // below 2^25
    let low = al * bl; // below 2^32
    let (low, carry) = low.overflowing_add(cross << 16);
    let high = ah * bh + (cross >> 16) + carry as u32; // below 2^16
                                                       // Keep 24 bits: shift 24 if the product reached 2^47, else 23. The
                                                       // kept bits are `high:low >> shift`, the rest decides the rounding.
    let top = high >> 15; // 1 if the product is at least 2^47
    let shift = 23 + top;
    let kept = (high << (32 - shift)) | (low >> shift);
    let rest = low << (32 - shift); // the dropped bits, left-aligned
                                    // Round half to even: up if the rest is above a half, or exactly a
                                    // half and the kept value odd.
    let up = (rest > 0x8000_0000) | ((rest == 0x8000_0000) & (kept & 1 == 1));
    let m = kept + up as u32; // at most 2^24: a carry into the next binade
    let exponent = (ea + eb + top + (m >> 24)) as i32 - 127;
    if !(1..=254).contains(&exponent) {
        return None;
    }
    // `m` is 2^24 only after a carry, whose fraction bits are zero.
    Some(f32::from_bits(((x ^ y) & 0x8000_0000) | ((exponent as u32) << 23) | (m & 0x7F_FFFF)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::xorshift;

    #[test]
    fn float_bits_order_like_floats() {
        let mut values = std::vec![0.0f32, -0.0, 1.0, -1.0, f32::MIN_POSITIVE, -f32::MIN_POSITIVE, 1e-45, -1e-45, f32::MAX, f32::MIN];
        values.extend([f32::INFINITY, f32::NEG_INFINITY, 0.5, 255.99, -3.25e7, 8192.0]);
        let mut next = xorshift(0x0BAD_F00D);
        values.extend((0..2000).map(|_| f32::from_bits(next())).filter(|v| !v.is_nan()));
        for &a in &values {
            for &b in &values {
                let zeros = a == 0.0 && b == 0.0;
                let want = if zeros { a.is_sign_negative() && b.is_sign_positive() } else { a < b };
                assert_eq!(ordered_bits(a) < ordered_bits(b), want, "{a:e} < {b:e}");
                assert_eq!(ordered_bits(b) > ordered_bits(a), want, "{b:e} > {a:e}");
            }
        }
    }

    #[test]
    fn products_of_normals_are_those_of_the_hardware() {
        let check = |a: f32, b: f32| {
            let want = a * b;
            match mul_normal(a, b) {
                Some(got) => assert_eq!(got.to_bits(), want.to_bits(), "{a:e} * {b:e} = {want:e}, got {got:e}"),
                // Declined: an operand or the product is not normal (or
                // only rounding made it the smallest normal), and not a
                // zero times a finite value.
                None => {
                    let normal = a.is_normal() && b.is_normal() && want.is_normal() && want.abs() != f32::MIN_POSITIVE;
                    let zero = (a == 0.0 && b.is_finite()) || (b == 0.0 && a.is_finite());
                    assert!(!normal && !zero, "{a:e} * {b:e} = {want:e} declined");
                }
            }
        };
        let mut next = xorshift(0x51F1_5EED);
        for _ in 0..2_000_000 {
            check(f32::from_bits(next()), f32::from_bits(next()));
        }
        // Exponents near each other (products near 1, the common case),
        // and significands of few bits, whose products are exact or ties.
        for _ in 0..2_000_000 {
            let (x, y) = (next(), next());
            let (ea, eb) = (100 + (x >> 24) % 56, 100 + (y >> 24) % 56);
            let keep = |v: u32, r: u32| v & (0x7F_FFFF << (r % 24)) & 0x7F_FFFF;
            let a = f32::from_bits((x & 0x8000_0000) | (ea << 23) | keep(x, y));
            let b = f32::from_bits((y & 0x8000_0000) | (eb << 23) | keep(y, x));
            check(a, b);
        }
        // The edges: the largest and smallest normals, zeros, subnormals,
        // infinities and NaN, and products that round up into the next
        // binade or over the largest finite value.
        let edges = [
            0.0f32,
            -0.0,
            -2.5,
            -f32::INFINITY,
            1.0,
            -1.0,
            1.5,
            f32::MIN_POSITIVE,
            f32::MAX,
            f32::MIN,
            1e-45,
            f32::INFINITY,
            f32::NAN,
            f32::from_bits(0x3F7F_FFFF),
            f32::from_bits(0x3F80_0001),
            f32::from_bits(0x4B7F_FFFF),
            1.0 / 3.0,
            1.0e19,
            1.0e-19,
        ];
        for &a in &edges {
            for &b in &edges {
                check(a, b);
            }
        }
        assert_eq!(mul(3.0, 0.5), 1.5);
    }
}
