//! Vectors, matrices and scalar types.
//!
//! Geometry (the vertex stage) works in `f32`, or mostly in integers for
//! fixed-point renderers ([`IntegerVertices`](crate::vertex::IntegerVertices)). Attribute
//! interpolation in the rasterizer is generic over [`Interp`], implemented
//! by `f32` and by the fixed-point [`Fixed`].
//!
//! Matrices use the column-vector convention: a point is transformed as
//! `M * p`, and `A * B` applies `B` first. Storage is row-major
//! (`m[row][col]`). Coordinate systems are left-handed as in Babylon.js:
//! x right, y up, z away from the viewer.

mod elementary;
mod fixed;
mod interp;
mod matrix;
mod soft_float;
mod vector;

pub use elementary::{cos, rsqrt, sin, sqrt, tan};
pub use fixed::Fixed;
pub use interp::{FixedBasis, FloatBasis, Interp};
pub use matrix::{Mat3, Mat4};
pub(crate) use soft_float::{greater, less, mul};
pub use vector::{Vec2, Vec3, Vec4};

/// Whether `f32` arithmetic runs on a hardware FPU: everywhere but on Arm
/// targets with the soft-float ABI (Cortex-M0+, M3), where every float
/// operation is a library call. A few spots pick a different but
/// equivalent formulation by it (a constant, so the other costs nothing).
pub(crate) const HARD_FLOAT: bool = !cfg!(target_arch = "arm") || cfg!(target_abi = "eabihf");

/// `a * b` as `i64`, exactly. Where the core has a 32×32→64-bit multiply
/// (every target but ARMv6-M) this is that one instruction. ARMv6-M has
/// only the low 32 bits of a product, and the compiler calls a 64×64-bit
/// library routine for it (some 40 instructions with the call); four
/// 16×16-bit products, about 20, are cheaper there. Used in the integer
/// vertex stage, triangle setup and the fixed-point span loops' products;
/// in the planes' range checks, inlined many times over, it measured
/// slower than the library call.
#[inline(always)]
pub(crate) fn mul_wide(a: i32, b: i32) -> i64 {
    if cfg!(soft3d_armv6m) {
        mul_wide_by_halves(a, b)
    } else {
        a as i64 * b as i64
    }
}

/// `a * b` as `i64`, exactly, for a 16-bit `b` (an `i16` mesh's steps):
/// on ARMv6-M two 16×16-bit products (`a`'s halves times `b`, each within
/// 32 bits), not the four of [`mul_wide`].
#[inline(always)]
pub(crate) fn mul_wide_short(a: i32, b: i16) -> i64 {
    if cfg!(soft3d_armv6m) {
        mul_wide_short_by_halves(a, b)
    } else {
        a as i64 * b as i64
    }
}

#[inline(always)]
fn mul_wide_short_by_halves(a: i32, b: i16) -> i64 {
    let (high, low) = halves_times_short(a, b as i32);
    (high << 16) + low
}

/// `a`'s 16-bit halves times a short `b` (in `[-2^15, 2^15)`): `a b =
/// high 2^16 + low`. With `a = ah 2^16 + al` (`|ah| <= 2^15`, `al <
/// 2^16`) each product fits 32 bits: two 16×16-bit products, not the four
/// of [`mul_wide_by_halves`].
#[inline(always)]
fn halves_times_short(a: i32, b: i32) -> (i64, i64) {
    (((a >> 16) * b) as i64, ((a & 0xFFFF) * b) as i64)
}

/// `a · b` exactly, for entries within `±2^30`. On ARMv6-M the three
/// products by 16-bit halves are summed part by part (the high parts'
/// sum fits 32 bits, as does each pair of middle parts), so that only the
/// middle and low sums and the end take 64-bit additions, not every
/// product (the integer vertex stage's rows).
#[inline(always)]
pub(crate) fn dot3_wide(a: &[i32; 3], b: &[i32; 3]) -> i64 {
    if cfg!(soft3d_armv6m) {
        dot3_by_halves(a, b)
    } else {
        a[0] as i64 * b[0] as i64 + a[1] as i64 * b[1] as i64 + a[2] as i64 * b[2] as i64
    }
}

#[inline(always)]
fn dot3_by_halves(a: &[i32; 3], b: &[i32; 3]) -> i64 {
    let (mut high, mut middle, mut low) = (0i32, 0i64, 0u64);
    for (&a, &b) in a.iter().zip(b) {
        // |ah|, |bh| <= 2^14 and al, bl < 2^16: ah bh within 2^28 (three
        // of them within 2^30), ah bl + al bh within 2^31, al bl below 2^32.
        let (ah, al, bh, bl) = (a >> 16, a & 0xFFFF, b >> 16, b & 0xFFFF);
        high += ah * bh;
        middle += (ah * bl + al * bh) as i64;
        low += (al as u32 * bl as u32) as u64;
    }
    ((high as i64) << 32) + (middle << 16) + low as i64
}

/// The high word of `(o << up) * r`, for `|o| < 2^(31 - up)` (so that the
/// shift loses nothing). Where `up >= 16` and the core has no long
/// multiply (ARMv6-M), `o << up` is a short value times `2^16` and the
/// word is two 32-bit products (`r`'s halves times it, see
/// [`halves_times_short`]), not four by halves and a 64-bit shift: the
/// same bits.
#[inline(always)]
pub(crate) fn high_word_of_shifted_product(o: i32, up: u32, r: i32) -> i32 {
    if cfg!(soft3d_armv6m) && up >= 16 {
        high_word_of_short_product(o << (up - 16), r)
    } else {
        (mul_wide(o << up, r) >> 32) as i32
    }
}

/// `((s 2^16) r) >> 32` for a short `s`: `s r = high 2^16 + low`, so the
/// word is `high + floor(low / 2^16)`, every step within 32 bits.
#[inline(always)]
fn high_word_of_short_product(s: i32, r: i32) -> i32 {
    let (high, low) = halves_times_short(r, s);
    (high + (low >> 16)) as i32
}

/// `a * b + c * d` exactly. On ARMv6-M one call of two products by halves
/// costs less than two calls of the library's 64×64-bit multiply and,
/// unlike products inlined at each of the triangle setup's many uses,
/// leaves the caller its registers (the planes' start values: torus.babylon
/// 2% fewer instructions; the gradients, though, measured 2% more).
#[inline(always)]
pub(crate) fn dot_wide(a: i32, b: i32, c: i32, d: i32) -> i64 {
    if cfg!(soft3d_armv6m) {
        dot_by_halves(a, b, c, d)
    } else {
        a as i64 * b as i64 + c as i64 * d as i64
    }
}

/// Whether every value is in `[-2^15, 2^15)` (see [`all_within`]).
#[inline(always)]
pub(crate) fn all_short<const N: usize>(values: [i32; N]) -> bool {
    all_within(values, 15)
}

/// Whether every value is in `[-2^k, 2^k)`, `k < 31`: one addition each
/// and one compare (cheaper than absolute values and their maximum).
#[inline(always)]
pub(crate) fn all_within<const N: usize>(values: [i32; N], k: u32) -> bool {
    values.iter().fold(0, |bits, &v| bits | v.wrapping_add(1 << k) as u32) < 2 << k
}

#[inline(never)]
fn dot_by_halves(a: i32, b: i32, c: i32, d: i32) -> i64 {
    if all_short([b, d]) {
        // Short second factors (a small triangle's offsets): the high
        // halves' products summed before their one shift.
        let ((ab_high, ab_low), (cd_high, cd_low)) = (halves_times_short(a, b), halves_times_short(c, d));
        return ((ab_high + cd_high) << 16) + ab_low + cd_low;
    }
    mul_wide_by_halves(a, b) + mul_wide_by_halves(c, d)
}

/// `v >> s` for `s < 64`. ARMv6-M calls a library routine for a 64-bit
/// shift by a variable amount; two 32-bit shifts and an or are cheaper.
#[inline(always)]
pub(crate) fn shr_wide(v: i64, s: u32) -> i64 {
    if cfg!(soft3d_armv6m) {
        shr_wide_by_words(v, s)
    } else {
        v >> s
    }
}

#[inline(always)]
fn shr_wide_by_words(v: i64, s: u32) -> i64 {
    let (low, high) = (v as u32, (v >> 32) as i32);
    if s >= 32 {
        (high >> (s - 32)) as i64
    } else if s == 0 {
        v
    } else {
        (((high >> s) as i64) << 32) | ((low >> s) | ((high as u32) << (32 - s))) as i64
    }
}

/// `v << s` for `s < 64` (bits shifted out are lost), by words on ARMv6-M
/// as [`shr_wide`].
#[inline(always)]
pub(crate) fn shl_wide(v: u64, s: u32) -> u64 {
    if cfg!(soft3d_armv6m) {
        shl_wide_by_words(v, s)
    } else {
        v << s
    }
}

#[inline(always)]
fn shl_wide_by_words(v: u64, s: u32) -> u64 {
    let (low, high) = (v as u32, (v >> 32) as u32);
    if s >= 32 {
        ((low << (s - 32)) as u64) << 32
    } else if s == 0 {
        v
    } else {
        (((high << s) | (low >> (32 - s))) as u64) << 32 | (low << s) as u64
    }
}

/// `v.leading_zeros()`, which ARMv6-M (no `CLZ` instruction) turns into a
/// library call of some 50 instructions; two or three compares and a
/// 256-byte table cost about 9 there. Elsewhere it is the instruction.
#[inline(always)]
pub(crate) fn leading_zeros(v: u32) -> u32 {
    if cfg!(soft3d_armv6m) {
        leading_zeros_by_table(v)
    } else {
        v.leading_zeros()
    }
}

/// Leading zeros of each byte value (8 for 0).
const BYTE_LEADING_ZEROS: [u8; 256] = {
    let mut t = [0u8; 256];
    let mut i = 0;
    while i < 256 {
        t[i] = (i as u8).leading_zeros() as u8;
        i += 1;
    }
    t
};

/// The leading zeros of the highest non-zero byte, plus 8 per zero byte
/// above it (a zero `v` counts 24 + 8).
#[inline(always)]
fn leading_zeros_by_table(v: u32) -> u32 {
    let (byte, above) = if v >> 16 != 0 {
        if v >> 24 != 0 {
            (v >> 24, 0)
        } else {
            (v >> 16, 8)
        }
    } else if v >> 8 != 0 {
        (v >> 8, 16)
    } else {
        (v, 24)
    };
    above + BYTE_LEADING_ZEROS[byte as usize] as u32
}

/// [`leading_zeros`] of a `u64`.
#[inline(always)]
pub(crate) fn leading_zeros_u64(v: u64) -> u32 {
    let high = (v >> 32) as u32;
    if high != 0 {
        leading_zeros(high)
    } else {
        32 + leading_zeros(v as u32)
    }
}

/// `(floor(n / d), n - d * floor(n / d))` for `d > 0`, by shifts and
/// subtractions in time proportional to the quotient's bits. ARMv6-M has
/// no divide instruction and its library division takes some 150
/// instructions whatever the quotient; the edge walker's quotients are
/// mostly a few pixels (about 25 instructions here).
#[inline]
pub(crate) fn div_floor_small(n: i32, d: i32) -> (i32, i32) {
    let (mut r, d) = (n.unsigned_abs(), d as u32);
    let mut q = 0;
    if r >= d {
        // The largest d 2^k at most r; doubling only while at most r / 2
        // cannot overflow.
        let (mut dk, mut bit) = (d, 1u32);
        while dk <= r >> 1 {
            dk <<= 1;
            bit <<= 1;
        }
        while bit != 0 {
            if r >= dk {
                r -= dk;
                q |= bit;
            }
            dk >>= 1;
            bit >>= 1;
        }
    }
    // |n| = q d + r; for negative n the floor is one lower where r > 0.
    match (n < 0, r) {
        (false, _) => (q as i32, r as i32),
        (true, 0) => ((q as i32).wrapping_neg(), 0),
        (true, _) => ((q as i32).wrapping_neg() - 1, (d - r) as i32),
    }
}

/// Reciprocal estimates: entry `i` is `2^25 / (513 + 2 i)` rounded, the
/// reciprocal of the middle of the `i`-th of 256 equal parts of `[1, 2)`,
/// in units of `2^-16` (512 bytes of flash).
const RECIPROCALS: [u16; 256] = {
    let mut table = [0; 256];
    let mut i = 0;
    while i < 256 {
        let d = 513 + 2 * i as u32;
        table[i] = (((1 << 25) + d / 2) / d) as u16;
        i += 1;
    }
    table
};

/// `2^61 / m` for a normalized `m` (in `[2^31, 2^32)`), within 2^-28 of
/// it relatively and in `[2^29, 2^30)`, without a division (a library
/// routine of some 200 instructions on ARMv6-M, and for 64 bits on every
/// Cortex-M): a table indexed by `m`'s top 9 bits estimates it within
/// 2^-9, and two Newton steps square that error twice.
#[inline(always)]
pub(crate) fn reciprocal_q61(m: u32) -> i32 {
    newton_q61(m, reciprocal_q61_coarse(m)).min((1 << 30) - 1) as i32
}

/// [`reciprocal_q61`] within about 2^-17 (one Newton step), at or below
/// it but for the step's truncations.
#[inline(always)]
pub(crate) fn reciprocal_q61_coarse(m: u32) -> u32 {
    let t = RECIPROCALS[(m >> 23) as usize & 0xFF] as u32;
    if cfg!(soft3d_armv6m) {
        newton_q61_from_table(m, t)
    } else {
        newton_q61(m, t << 14)
    }
}

/// [`newton_q61`] from `r = t 2^14` with `t` from the 16-bit table, in
/// 32-bit arithmetic (ARMv6-M has no long multiply): `m t` and `r e` are a
/// factor's halves times `t`, two multiplies each rather than four. The
/// same bits.
#[inline(always)]
fn newton_q61_from_table(m: u32, t: u32) -> u32 {
    // m t = high 2^16 + low, each part within 32 bits (t < 2^16).
    let (high, low) = ((m >> 16) * t, (m & 0xFFFF) * t);
    // e = 2^61 - m t 2^14 is below 2^52 in magnitude (the table is within
    // 2^-9), so e >> 22 = 2^39 - ceil(m t / 2^8) fits 32 bits, and those
    // are the low bits of -ceil(m t / 2^8) (low + 255 cannot overflow).
    let e = (high << 8).wrapping_add((low + 255) >> 8).wrapping_neg() as i32;
    // r e 2^-39 = t e 2^-25, with t e = high 2^16 + low again.
    let (high, low) = ((e >> 16) * t as i32, (e as u32 & 0xFFFF) * t);
    ((t << 14) as i32 + ((high + (low >> 16) as i32) >> 9)) as u32
}

/// One Newton step toward `2^61 / m` from `r` (below `2^30`, within 2^-8
/// of it): `r (2 - m r / 2^61)`. The error `2^61 - m r` is then below
/// 2^53, so its top bits fit 32 and the product is one [`mul_wide`]; the
/// step lands at or below the reciprocal but for its truncations.
#[inline(always)]
fn newton_q61(m: u32, r: u32) -> u32 {
    let e = (1i64 << 61) - mul_wide_unsigned(m, r) as i64;
    (r as i64 + (mul_wide(r as i32, (e >> 22) as i32) >> 39)) as u32
}

/// [`mul_wide`] of unsigned factors.
#[inline(always)]
pub(crate) fn mul_wide_unsigned(a: u32, b: u32) -> u64 {
    if cfg!(soft3d_armv6m) {
        mul_wide_unsigned_by_halves(a, b)
    } else {
        a as u64 * b as u64
    }
}

#[inline(always)]
fn mul_wide_unsigned_by_halves(a: u32, b: u32) -> u64 {
    let (ah, al, bh, bl) = (a >> 16, a & 0xFFFF, b >> 16, b & 0xFFFF);
    (((ah * bh) as u64) << 32) + (((ah * bl) as u64 + (al * bh) as u64) << 16) + (al * bl) as u64
}

/// [`mul_wide`] from 16×16-bit products, for cores without a long multiply.
#[inline(always)]
fn mul_wide_by_halves(a: i32, b: i32) -> i64 {
    // a = ah * 2^16 + al with ah signed and al in [0, 2^16); every partial
    // product then fits 32 bits: |ah * bh| <= 2^30, |ah * bl| < 2^31,
    // al * bl < 2^32.
    let (ah, al, bh, bl) = (a >> 16, a & 0xFFFF, b >> 16, b & 0xFFFF);
    let high = (ah * bh) as i64;
    let middle = (ah * bl) as i64 + (al * bh) as i64;
    let low = (al as u32 * bl as u32) as i64;
    (high << 32) + (middle << 16) + low
}

/// A xorshift generator for tests: the same numbers on every run.
#[cfg(test)]
pub(crate) fn xorshift(mut seed: u32) -> impl FnMut() -> u32 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        seed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalized_reciprocals_are_within_2_to_the_minus_28() {
        let mut next = xorshift(0x2545_F491);
        let ms = (0..200_000).map(|_| next() | 1 << 31);
        for m in ms.chain([1 << 31, (1 << 31) + 1, u32::MAX, 0xFFFF_0000, 0x8000_FFFF]) {
            let r = reciprocal_q61(m) as f64;
            let exact = 2f64.powi(61) / m as f64;
            assert!(((r - exact) / exact).abs() < 2f64.powi(-28), "2^61 / {m}: {r} against {exact}");
            assert!(r >= 2f64.powi(29) && r < 2f64.powi(30));
        }
    }

    #[test]
    fn products_by_halves_are_exact() {
        let edges = [0, 1, -1, 0xFFFF, 0x10000, -0x10000, 0x7FFF_FFFF, i32::MIN, i32::MIN + 1, 12345, -98765];
        for &a in &edges {
            for &b in &edges {
                assert_eq!(mul_wide_by_halves(a, b), a as i64 * b as i64, "{a} * {b}");
            }
        }
        let mut next = xorshift(0x9E37_79B9);
        for _ in 0..100_000 {
            let x = next();
            let (a, b) = (x as i32, x.rotate_left(11) as i32 >> (x % 31));
            assert_eq!(mul_wide_by_halves(a, b), a as i64 * b as i64, "{a} * {b}");
        }
        assert_eq!(mul_wide(-7, 6), -42);
        for _ in 0..100_000 {
            let (a, b) = (next(), next() >> (next() % 32));
            assert_eq!(mul_wide_unsigned_by_halves(a, b), a as u64 * b as u64, "{a} * {b}");
        }
        assert_eq!(mul_wide_unsigned_by_halves(u32::MAX, u32::MAX), u32::MAX as u64 * u32::MAX as u64);
        // By a 16-bit factor.
        for &a in &edges {
            for b in [i16::MIN, i16::MIN + 1, -1, 0, 1, i16::MAX, 12345] {
                assert_eq!(mul_wide_short_by_halves(a, b), a as i64 * b as i64, "{a} * {b}");
            }
        }
        for _ in 0..100_000 {
            let (a, b) = (next() as i32, next() as i16);
            assert_eq!(mul_wide_short_by_halves(a, b), a as i64 * b as i64, "{a} * {b}");
        }
        // Sums of two, with second factors short (below 2^15) or not.
        let extremes = [i32::MIN, i32::MAX, -(1 << 15), (1 << 15) - 1, 1 << 15, 0, -1];
        for &a in &extremes {
            for &b in &extremes {
                assert_eq!(dot_by_halves(a, b, 3, b), a as i64 * b as i64 + 3 * b as i64, "{a} * {b} + 3 * {b}");
            }
        }
        for _ in 0..100_000 {
            let (a, c) = (next() as i32, next() as i32);
            let (b, d) = (next() as i32 >> (next() % 32), next() as i32 >> (next() % 32));
            assert_eq!(dot_by_halves(a, b, c, d), a as i64 * b as i64 + c as i64 * d as i64, "{a} * {b} + {c} * {d}");
        }
    }

    #[test]
    fn short_values_are_those_of_16_bits() {
        for v in [i32::MIN, -(1 << 15) - 1, -(1 << 15), -1, 0, (1 << 15) - 1, 1 << 15, i32::MAX] {
            assert_eq!(all_short([v]), i16::try_from(v).is_ok(), "{v}");
            assert_eq!(all_short([0, v, 5]), i16::try_from(v).is_ok(), "{v}");
        }
        for k in [0, 12, 23, 30] {
            let (lo, hi) = (-(1i64 << k), 1i64 << k);
            for v in [i32::MIN as i64, lo - 1, lo, -1, 0, hi - 1, hi, i32::MAX as i64] {
                let inside = (lo..hi).contains(&v);
                assert_eq!(all_within([v as i32], k), inside, "{v} within 2^{k}");
                assert_eq!(all_within([-1, v as i32, 0], k), inside, "{v} within 2^{k}");
            }
        }
    }

    #[test]
    fn small_floor_division_is_exact() {
        let mut next = xorshift(0x7F4A_7C15);
        let edges = [0, 1, -1, 2, -2, 7, -7, i32::MAX, i32::MIN, i32::MIN + 1, 1 << 30, -(1 << 30)];
        let divisors = [1, 2, 3, 7, 64, 1 << 20, i32::MAX, (1 << 30) + 1];
        let randoms = (0..100_000).map(|_| (next() as i32 >> (next() % 31), (next() >> (1 + next() % 31)).max(1) as i32));
        let pairs = edges.iter().flat_map(|&n| divisors.iter().map(move |&d| (n, d)));
        for (n, d) in pairs.chain(randoms) {
            let want = (n.div_euclid(d), n.rem_euclid(d));
            assert_eq!(div_floor_small(n, d), want, "{n} / {d}");
        }
    }

    #[test]
    fn shifts_by_words_are_exact() {
        let mut next = xorshift(0x5851_F42D);
        let values = [0, 1, -1, i64::MAX, i64::MIN, 1 << 32, -(1 << 32), 0x1234_5678_9ABC_DEF0];
        let randoms = (0..100_000).map(|_| (((next() as u64) << 32 | next() as u64) as i64) >> (next() % 64));
        for v in values.into_iter().chain(randoms) {
            for s in 0..64 {
                assert_eq!(shr_wide_by_words(v, s), v >> s, "{v} >> {s}");
                assert_eq!(shl_wide_by_words(v as u64, s), (v as u64) << s, "{v} << {s}");
            }
        }
    }

    #[test]
    fn dots_of_three_by_halves_are_exact() {
        let mut next = xorshift(0x7A3D_91C5);
        let mut value = || match next() % 8 {
            0 => 1 << 30,
            1 => -(1 << 30),
            _ => (next() as i32) >> (1 + next() % 31),
        };
        for _ in 0..100_000 {
            let (a, b) = ([value(), value(), value()], [value(), value(), value()]);
            let exact: i64 = a.iter().zip(&b).map(|(&a, &b)| a as i64 * b as i64).sum();
            assert_eq!(dot3_by_halves(&a, &b), exact, "{a:?} · {b:?}");
        }
    }

    #[test]
    fn newton_steps_from_the_table_are_exact() {
        let mut next = xorshift(0x3C6E_F372);
        // Both ends of every table entry's interval (where its estimate is
        // furthest off), and random ones.
        let ends = (0..256u32).flat_map(|i| [(1 << 31) | i << 23, (1 << 31) | i << 23 | ((1 << 23) - 1)]);
        for m in ends.chain((0..100_000).map(|_| next() | (1 << 31))) {
            let t = RECIPROCALS[(m >> 23) as usize & 0xFF] as u32;
            assert_eq!(newton_q61_from_table(m, t), newton_q61(m, t << 14), "{m:#x}");
        }
    }

    #[test]
    fn high_words_of_short_products_are_exact() {
        let mut next = xorshift(0x2545_F491);
        let edges = [0, 1, -1, (1 << 15) - 1, -(1 << 15), i32::MAX, i32::MIN, 1 << 30, -(1 << 30)];
        let randoms: std::vec::Vec<(i32, i32)> = (0..100_000).map(|_| ((next() as i32) >> (next() % 32), (next() as i32) >> 16)).collect();
        for (r, s) in edges.map(|r| (r, 12_345)).into_iter().chain(randoms) {
            for s in [s, 0, 1, -1, (1 << 15) - 1, -(1 << 15)] {
                let exact = ((((s as i64) << 16) * r as i64) >> 32) as i32;
                assert_eq!(high_word_of_short_product(s, r), exact, "({s} << 16) * {r}");
            }
        }
    }

    #[test]
    fn leading_zeros_by_table_count_like_the_instruction() {
        let mut next = xorshift(0x1B87_3593);
        let singles = (0..32).flat_map(|b| [1u32 << b, (1u32 << b) - 1, u32::MAX >> b]);
        for v in singles.chain((0..100_000).map(|_| next() >> (next() % 32))) {
            assert_eq!(leading_zeros_by_table(v), v.leading_zeros(), "{v:#x}");
        }
        for v in [0u64, 1, u32::MAX as u64, 1 << 32, u64::MAX, 0x0000_1234_0000_0000] {
            assert_eq!(leading_zeros_u64(v), v.leading_zeros(), "{v:#x}");
        }
    }
}
