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
mod vector;

pub use elementary::{cos, rsqrt, sin, sqrt, tan};
pub use fixed::Fixed;
pub use interp::{FixedBasis, FloatBasis, Interp};
pub use matrix::{Mat3, Mat4};
pub use vector::{Vec2, Vec3, Vec4};

/// Whether `f32` arithmetic runs on a hardware FPU: everywhere but on Arm
/// targets with the soft-float ABI (Cortex-M0+, M3), where every float
/// operation is a library call. A few spots pick a different but
/// equivalent formulation by it (a constant, so the other costs nothing).
pub(crate) const HARD_FLOAT: bool = !cfg!(target_arch = "arm") || cfg!(target_abi = "eabihf");

/// `a * b` as `i64`, exactly. Where the core has a 32×32→64-bit multiply
/// (every target but ARMv6-M) this is that one instruction. ARMv6-M has
/// only the low 32 bits of a product, and the compiler calls a 64×64-bit
/// library routine for it; four 16×16-bit products are cheaper there.
/// Used where it measured faster on the M0+ (edge setup and the triangle's
/// area: 0.8% of `torus.babylon`); in the planes' range checks, inlined
/// many times over, it was slower than the library call.
#[inline(always)]
pub(crate) fn mul_wide(a: i32, b: i32) -> i64 {
    if cfg!(soft3d_no_long_multiply) {
        mul_wide_by_halves(a, b)
    } else {
        a as i64 * b as i64
    }
}

/// `2^61 / m` for a normalized `m` (in `[2^31, 2^32)`), within 2^-28 of
/// it relatively and in `[2^29, 2^30)`, without a 64-bit division (a long
/// library routine on every Cortex-M): a 32-bit division of `m`'s top 16
/// bits estimates it (relative error below 2^-14) and one Newton step
/// squares that error.
#[inline(always)]
pub(crate) fn reciprocal_q61(m: u32) -> i32 {
    let r0 = (u32::MAX / (m >> 16)) << 13;
    let e = (1i64 << 61) - (m as u64 * r0 as u64) as i64;
    (r0 as i64 + (mul_wide(r0 as i32, (e >> 16) as i32) >> 45)).min((1 << 30) - 1) as i32
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
    }
}
