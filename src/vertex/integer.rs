//! The vertex stage's positions in integers, for fixed-point settings
//! ([`Interp::INTEGER_VERTICES`](crate::math::Interp)): on a core without
//! an FPU each `f32` operation is a library call of 50 to 100 instructions,
//! and transforming, projecting and snapping a vertex took about 40 of them.
//!
//! Once per draw call the model-view-projection matrix is scaled into four
//! integer rows (in `f32`, a few dozen operations). Per vertex:
//!
//! - the position is an integer vector of magnitude at most `2^30`: an
//!   `f32` mesh's coordinates rounded to the power-of-two step that puts
//!   its bounding box within `±2^30` (finer than `f32` itself but for
//!   coordinates far below the box's size), or an `i16` mesh's steps times
//!   `2^15` (its scale and offset are folded into the rows);
//! - each clip coordinate is three exact 32×32→64-bit products and a
//!   constant, summed in 64 bits and kept to 30 bits: the rows are scaled
//!   by a power of two each so that nothing the mesh's bounds allow
//!   overflows. The x and y rows are premultiplied by the viewport, so the
//!   quotient by `w` is directly in sub-pixel units;
//! - the near/far tests compare z with 0 and with w (one scale for both);
//! - one reciprocal of `w` ([`reciprocal_q61`]: a table and two Newton
//!   steps) gives x, y, depth and `1 / w` by multiplies and shifts.
//!
//! A draw call whose numbers the scheme cannot hold (a bounding box or a
//! matrix row beyond the exponents it allows, x or y rows out of all
//! proportion to the w row, a zero w row) goes through the `f32` stage
//! instead: [`IntegerProjection::new`] returns `None`.
//!
//! Triangles that need clipping are clipped in `f32` from the same integer
//! clip coordinates ([`IntegerProjection::clip_position`]), so a vertex the
//! integer tests put inside the near and far planes is inside for the
//! clipper too.

use super::{all_finite, BEHIND_NEAR, BEYOND_FAR, NOT_FINITE, OUTSIDE_GUARD};
use crate::math::{dot3_wide, mul_wide, mul_wide_short, reciprocal_q61, shr_wide, Mat4, Vec4};
use crate::mesh::{Sphere, Vectors};
use crate::raster::{guard, ScreenVertex};

/// Positions as integer vectors of magnitude at most [`INPUT_MAX`].
#[derive(Clone, Copy, Debug)]
enum Input<'a> {
    /// `f32` coordinates times `2^k`, rounded.
    F32(&'a [crate::math::Vec3], i32),
    /// Steps of an `i16` mesh, times `2^15`.
    I16(&'a [[i16; 3]]),
}

/// Bits of the input coordinates: their magnitude is at most `2^INPUT_BITS`.
const INPUT_BITS: u32 = 30;
const INPUT_MAX: i32 = 1 << INPUT_BITS;

/// Fractional bits of the quotients `x / w` and `y / w` before snapping.
const QUOTIENT_BITS: u32 = 8;

/// The integer form of one draw call's transform and viewport.
#[derive(Clone, Copy, Debug)]
pub struct IntegerProjection<'a> {
    input: Input<'a>,
    /// Rows x·W·2^f, -y·H·2^f, z and w of the clip transform per input
    /// unit, times `2^(s + INPUT_BITS)`.
    rows: [[i32; 3]; 4],
    /// The rows' constant terms, times `2^(s + INPUT_BITS)`.
    constant: [i64; 4],
    /// Each row's scale exponent `s` (z and w share one).
    scale: [i32; 4],
    /// `x / w` in units of `2^-QUOTIENT_BITS` is `(x r) >> (base - n)`
    /// for `w = m 2^-n`, `r = 2^61 / m` (x and y).
    base: [u32; 2],
    /// `(W 2^f + 1) 2^QUOTIENT_BITS` and the same for the height: the
    /// quotients' offset to window coordinates, plus the rounding half.
    offset: [i64; 2],
    /// Largest snapped coordinate magnitude (the guard band).
    limit: i64,
    /// Viewport size in sub-pixel units, for [`IntegerProjection::clip_position`].
    viewport: [f32; 2],
}

/// `2^e` as `f32`, for `-126 <= e <= 127`.
#[inline]
fn pow2(e: i32) -> f32 {
    f32::from_bits(((e + 127) as u32) << 23)
}

/// `floor(log2(v))` of a positive normal `f32`.
#[inline]
fn exponent(v: f32) -> i32 {
    ((v.to_bits() >> 23) & 0xFF) as i32 - 127
}

/// `v 2^e` as `f32`, truncated toward zero (flushed to zero below the
/// normal range, saturated above it), from the bits: no float operation.
#[inline(always)]
pub(super) fn f32_from_parts(v: u32, e: i32) -> f32 {
    if v == 0 {
        return 0.0;
    }
    // v = m 2^(31 - n) with m in [1, 2): the exponent field is 127 + 31 - n + e.
    let n = crate::math::leading_zeros(v);
    let field = 158 - n as i32 + e;
    if field <= 0 {
        0.0
    } else if field >= 255 {
        f32::MAX
    } else {
        f32::from_bits(((field as u32) << 23) | (((v << n) >> 8) & 0x7F_FFFF))
    }
}

/// `v` truncated to its 24 leading bits, the precision of an `f32` (what
/// [`f32_from_parts`] keeps), as an integer. The integer window depth is
/// kept so: its last bits carry the integer transform's and the
/// reciprocal's rounding, and with all 30 of them `Depth32` showed the
/// wrong plane of `zfight` (docs/accuracy.md) at 62 pixels, against none
/// when cut to 24 bits like the `f32` vertex stage's depth.
#[inline(always)]
pub(super) fn f32_precision(v: u32) -> u32 {
    // Most depths are from 1/2 up (2^29 units): their low 6 bits go, with
    // no count of leading zeros (a table lookup on ARMv6-M).
    if v >= 1 << 29 {
        return v & !0x3F;
    }
    let n = crate::math::leading_zeros(v);
    if n >= 8 {
        v
    } else {
        v & (u32::MAX << (8 - n))
    }
}

/// `round(v 2^k)` of a finite `f32` from its bits, clamped to `±max`
/// (at most `2^30`), or `None` if `v` is not finite.
#[inline(always)]
pub(super) fn scaled_rounded(v: f32, k: i32, max: i32) -> Option<i32> {
    let bits = v.to_bits();
    let field = ((bits >> 23) & 0xFF) as i32;
    if field == 0xFF {
        return None;
    }
    if field == 0 {
        // Zero or subnormal: below any step the setup allows.
        return Some(0);
    }
    // |v| = m 2^(field - 150) with m in [2^23, 2^24).
    let m = (bits & 0x7F_FFFF) | 0x80_0000;
    let shift = 150 - field - k;
    let magnitude = if shift <= 0 {
        // m < 2^24: up to six places left it stays below 2^30.
        if shift < -6 {
            max
        } else {
            (m << -shift).min(max as u32) as i32
        }
    } else if shift > 24 {
        0
    } else {
        (((m >> (shift - 1)) + 1) >> 1).min(max as u32) as i32
    };
    Some(if bits >> 31 != 0 { -magnitude } else { magnitude })
}

impl<'a> IntegerProjection<'a> {
    /// The integer form of `mvp` for `positions` (whose finite entries lie
    /// in `bounds`) on a `width`×`height` viewport with `subpixel_bits`,
    /// or `None` if the matrix or the bounds do not fit it.
    pub fn new(mvp: &Mat4, positions: Vectors<'a>, bounds: Sphere, width: f32, height: f32, subpixel_bits: u32) -> Option<Self> {
        // Input unit per axis (`a`), value of input zero (`b`).
        let (input, a, b) = match positions {
            Vectors::I16 { steps, scale, offset } => (Input::I16(steps), scale, offset),
            Vectors::F32(p) => {
                let c = bounds.center;
                let extent = c.x.abs().max(c.y.abs()).max(c.z.abs()) + bounds.radius;
                // extent < 2^(e + 1), so extent 2^(29 - e) < 2^30.
                let k = if extent > 0.0 { INPUT_BITS as i32 - 1 - exponent(extent) } else { 0 };
                if !extent.is_finite() || !(-100..=100).contains(&k) {
                    return None;
                }
                (Input::F32(p, k), [pow2(-k); 3], [0.0; 3])
            }
        };
        // Per input unit.
        let a = match input {
            Input::I16(_) => a.map(|v| v * pow2(-15)),
            Input::F32(..) => a,
        };
        let unit = (1u32 << subpixel_bits) as f32;
        let factor = [width * unit, -height * unit, 1.0, 1.0];
        let mut real = [[0.0f32; 4]; 4];
        let mut bound = [0.0f32; 4];
        for (r, (row, f)) in mvp.m.iter().zip(factor).enumerate() {
            let t = (row[0] * b[0] + row[1] * b[1] + row[2] * b[2] + row[3]) * f;
            real[r] = [row[0] * a[0] * f, row[1] * a[1] * f, row[2] * a[2] * f, t];
            bound[r] = (real[r][0].abs() + real[r][1].abs() + real[r][2].abs()) * INPUT_MAX as f32 + t.abs();
            if !bound[r].is_finite() {
                return None;
            }
        }
        if bound[3] == 0.0 {
            return None;
        }
        // The largest s with bound 2^s < 2^30 (any for a zero row).
        let fit = |b: f32| if b > 0.0 { 29 - exponent(b) } else { 0 };
        let zw = fit(bound[2]).min(fit(bound[3]));
        let scale = [fit(bound[0]), fit(bound[1]), zw, zw];
        if scale.iter().any(|s| !(-100..=90).contains(s)) {
            return None;
        }
        // x / w = (x r) 2^(n - 61 + s_zw - s_x) for w = m 2^-n, r = 2^61 / m:
        // the shift base - n must stay in [0, 63] for n in [1, 31].
        let base = |s: i32| 61 - QUOTIENT_BITS as i32 - zw + s;
        let bases = [base(scale[0]), base(scale[1])];
        if bases.iter().any(|b| !(31..=64).contains(b)) {
            return None;
        }
        let mut rows = [[0; 3]; 4];
        let mut constant = [0; 4];
        for r in 0..4 {
            // In range by the choice of s: each |value| 2^-INPUT_BITS < 2^30.
            let unit = pow2(scale[r] + INPUT_BITS as i32);
            rows[r] = [0, 1, 2].map(|j| (real[r][j] * unit) as i32);
            constant[r] = (real[r][3] * unit) as i64;
        }
        let offset = |size: f32| ((size * unit) as i64 + 1) << QUOTIENT_BITS;
        Some(Self {
            input,
            rows,
            constant,
            scale,
            base: bases.map(|b| b as u32),
            offset: [offset(width), offset(height)],
            limit: (guard(subpixel_bits) >> 1) as i64,
            viewport: [width * unit, height * unit],
        })
    }

    /// Clip coordinates of vertex `i` in integers (the rows' units),
    /// `None` if its input is not finite (or past the end).
    #[inline(always)]
    fn clip(&self, i: usize) -> Option<[i32; 4]> {
        match self.input {
            Input::F32(p, k) => {
                let v = p.get(i)?;
                let p = [scaled_rounded(v.x, k, INPUT_MAX)?, scaled_rounded(v.y, k, INPUT_MAX)?, scaled_rounded(v.z, k, INPUT_MAX)?];
                Some(self.rows_dot(|l| dot3_wide(l, &p)))
            }
            // The input is `q 2^15`: a row times the 16-bit steps, then
            // shifted (two 16×16-bit multiplies a product on ARMv6-M, not four).
            Input::I16(s) => {
                let q = s.get(i)?;
                Some(self.rows_dot(|l| (mul_wide_short(l[0], q[0]) + mul_wide_short(l[1], q[1]) + mul_wide_short(l[2], q[2])) << 15))
            }
        }
    }

    /// The four rows from `dot(row)`, a row's products with the input.
    #[inline(always)]
    fn rows_dot(&self, dot: impl Fn(&[i32; 3]) -> i64) -> [i32; 4] {
        // The sum is below 2^60 in magnitude (the bound the scales were
        // chosen for), so the row is below 2^30.
        let row = |r: usize| ((dot(&self.rows[r]) + self.constant[r]) >> INPUT_BITS) as i32;
        [row(0), row(1), row(2), row(3)]
    }

    /// Clip-space position of vertex `i` as `f32` (for the clipper): the
    /// integer coordinates scaled back, so their signs and the order of
    /// z and w are those the vertex was flagged by. Zero if not finite.
    pub fn clip_position(&self, i: usize) -> Vec4 {
        let Some(c) = self.clip(i) else { return Vec4::new(0.0, 0.0, 0.0, 0.0) };
        let back = |r: usize| c[r] as f32 * pow2(-self.scale[r]);
        Vec4::new(back(0) / self.viewport[0], -back(1) / self.viewport[1], back(2), back(3))
    }

    /// Snapped window coordinate from a clip coordinate premultiplied by
    /// the viewport, the reciprocal `r` of w and w's normalization `n`.
    #[inline(always)]
    fn snap(&self, axis: usize, v: i32, r: i32, n: u32) -> Option<i32> {
        // v / w in units of 2^-QUOTIENT_BITS half sub-pixels (below 2^61).
        let quotient = shr_wide(mul_wide(v, r), self.base[axis] - n);
        // floor((v / w + W 2^f + 1) / 2): snap's rounding to nearest.
        let s = (quotient + self.offset[axis]) >> (QUOTIENT_BITS + 1);
        if s >= -self.limit && s <= self.limit {
            Some((s as i32) << 1)
        } else {
            None
        }
    }

    /// Transforms, projects and snaps vertex `i` with varyings `attrs`, or
    /// flags it like [`project`](super::project).
    #[inline(always)]
    pub fn project<const V: usize>(&self, i: usize, attrs: [f32; V]) -> ScreenVertex<V> {
        let mut out = ScreenVertex::ZERO;
        self.project_into(i, attrs, true, V, &mut out);
        out
    }

    /// [`IntegerProjection::project`] into `out`, where the vertex is
    /// stored (see [`project_into`](super::project_into)).
    #[inline(always)]
    ///
    /// Without `perspective` (a material that does not correct for it and
    /// so never reads `q`), `q` is stored as 1, not converted to `f32`.
    /// Only the first `varyings` attributes are stored (see
    /// [`store_projected`](super::store_projected)).
    pub(super) fn project_into<const V: usize>(
        &self,
        i: usize,
        attrs: [f32; V],
        perspective: bool,
        varyings: usize,
        out: &mut ScreenVertex<V>,
    ) {
        let flags = match self.clip(i) {
            Some([x, y, z, w]) if all_finite(&attrs) => {
                let mut flags = 0;
                if z < 0 {
                    flags |= BEHIND_NEAR;
                }
                if z > w {
                    flags |= BEYOND_FAR;
                }
                // 0 <= z <= w, so w > 0 unless both are zero.
                if flags == 0 && w > 0 {
                    let n = crate::math::leading_zeros(w as u32);
                    let r = reciprocal_q61((w as u32) << n);
                    if let (Some(sx), Some(sy)) = (self.snap(0, x, r, n), self.snap(1, y, r, n)) {
                        // 1 / w = r 2^(n - 61 + s), and z / w = (z r) 2^(n - 61),
                        // in [0, 1] but for the reciprocal's error: the
                        // window depth in units of 2^-30, to `f32` precision.
                        let depth = f32_precision((shr_wide(mul_wide(z, r), 31 - n) as u32).min(crate::raster::DEPTH_ONE));
                        let q = if perspective { f32_from_parts(r as u32, n as i32 - 61 + self.scale[3]) } else { 1.0 };
                        super::store_projected(out, (sx, sy, depth, q), &attrs, varyings);
                        return;
                    }
                }
                if flags == 0 {
                    OUTSIDE_GUARD
                } else {
                    flags
                }
            }
            _ => NOT_FINITE,
        };
        super::store_unprojected(out, flags)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{xorshift, Vec3};
    use crate::mesh::Mesh;
    use std::{vec, vec::Vec};

    const W: f32 = 320.0;
    const H: f32 = 240.0;

    /// A random camera looking at a random model placement, and the
    /// model's scale.
    fn random_mvp(next: &mut impl FnMut() -> u32) -> (Mat4, f32) {
        let mut u = |lo: f32, hi: f32| lo + (hi - lo) * (next() as f32 / u32::MAX as f32);
        let eye = Vec3::new(u(-30.0, 30.0), u(-30.0, 30.0), u(-30.0, 30.0));
        let target = Vec3::new(u(-3.0, 3.0), u(-3.0, 3.0), u(-3.0, 3.0));
        let projection = Mat4::perspective_fov_lh(u(0.3, 1.6), W / H, u(0.01, 1.0), u(50.0, 1000.0));
        let view_proj = projection * Mat4::look_at_lh(eye, target, Vec3::new(0.0, 1.0, 0.0));
        let scale = 2f32.powf(u(-6.0, 6.0));
        let model = Mat4::translation(Vec3::new(u(-5.0, 5.0), u(-5.0, 5.0), u(-5.0, 5.0)))
            * Mat4::rotation_y(u(0.0, 6.3))
            * Mat4::rotation_x(u(0.0, 6.3))
            * Mat4::scaling(Vec3::new(scale, scale, scale));
        (view_proj * model, scale)
    }

    /// Checks every vertex of `mesh` (whose model-space positions are
    /// `exact`) against the projection in `f64` of the same matrix:
    /// flags, snapped coordinates (equal to the exact rounding wherever
    /// that is not within the `f32` matrix's error of a rounding boundary,
    /// else within one step), depth and `1 / w`. Returns how many
    /// coordinates were checked for equality.
    fn check(mvp: &Mat4, mesh: &Mesh<'_>, exact: &[[f64; 3]], bits: u32) -> usize {
        let projection = IntegerProjection::new(mvp, mesh.positions(), mesh.bounds(), W, H, bits).expect("an ordinary draw call fits");
        let unit = (1u32 << bits) as f64;
        let mut equal = 0;
        for (i, p) in exact.iter().enumerate() {
            let v = projection.project::<1>(i, [0.5]);
            let flags = super::super::flags(&v);
            // Clip coordinates and a bound on their f32 coefficients' error.
            let row = |r: usize| {
                let m = mvp.m[r].map(|c| c as f64);
                let terms = [m[0] * p[0], m[1] * p[1], m[2] * p[2], m[3]];
                (terms.iter().sum::<f64>(), terms.iter().map(|t| t.abs()).sum::<f64>() * 1e-6)
            };
            let ((x, ex), (y, ey), (z, ez), (w, ew)) = (row(0), row(1), row(2), row(3));
            let c = projection.clip_position(i);
            assert_eq!(c.z < 0.0, flags & BEHIND_NEAR != 0, "vertex {i}: the clipper's near test");
            assert_eq!(c.z > c.w, flags & BEYOND_FAR != 0, "vertex {i}: the clipper's far test");
            if z < -ez {
                assert_ne!(flags & BEHIND_NEAR, 0, "vertex {i}: z = {z} is behind the near plane");
            }
            if z > w + ez + ew {
                assert_ne!(flags & BEYOND_FAR, 0, "vertex {i}: z = {z} is beyond w = {w}");
            }
            let inside = z > ez && z < w - ez - ew;
            if !inside {
                continue;
            }
            // Error of the quotient: the rows' and w's, relative, and the
            // reciprocal's 2^-28; in sub-pixel units.
            let rel = ew / w + 2f64.powi(-27);
            let err_x = (ex / w + (x / w).abs() * rel) * 0.5 * W as f64 * unit + 1e-3;
            let err_y = (ey / w + (y / w).abs() * rel) * 0.5 * H as f64 * unit + 1e-3;
            let (sx, sy) = ((x / w + 1.0) * 0.5 * W as f64 * unit, (1.0 - y / w) * 0.5 * H as f64 * unit);
            let limit = (guard(bits) >> 1) as f64;
            if flags != 0 {
                assert_eq!(flags, OUTSIDE_GUARD, "vertex {i}");
                let beyond = (sx.abs() + err_x + 0.5).max(sy.abs() + err_y + 0.5);
                assert!(beyond >= limit, "vertex {i}: ({sx}, {sy}) is inside the guard band but was flagged");
                continue;
            }
            let mut compare = |s: f64, err: f64, got: i32| {
                let (lo, hi) = ((s - err + 0.5).floor(), (s + err + 0.5).floor());
                let g = (got >> 1) as f64;
                assert!(g >= lo - 1.0 && g <= hi + 1.0, "vertex {i}: snapped {g}, exact {s}");
                if lo == hi {
                    assert_eq!(g, lo, "vertex {i}: snapped {g}, exact {s} ± {err}");
                    equal += 1;
                }
            };
            compare(sx, err_x, v.x);
            compare(sy, err_y, v.y);
            // (The depth is kept in units of 2^-30, truncated to 24 bits.)
            let depth_err = (ez + ew) / w + (z / w) * rel + 2f64.powi(-23);
            let depth = v.z as f64 / (1u64 << 30) as f64;
            assert!((depth - z / w).abs() <= depth_err, "vertex {i}: depth {depth} against {}", z / w);
            assert!((v.q as f64 * w - 1.0).abs() <= rel + 2f64.powi(-22), "vertex {i}: 1/w {} against {}", v.q, 1.0 / w);
        }
        equal
    }

    #[test]
    fn integer_projection_matches_the_exact_one() {
        let mut next = xorshift(0x1357_9BDF);
        let mut equal = 0;
        for case in 0..600 {
            let bits = case % 9;
            let (mvp, _) = random_mvp(&mut next);
            let mut u = |lo: f32, hi: f32| lo + (hi - lo) * (next() as f32 / u32::MAX as f32);
            let extent = 2f32.powf(u(-4.0, 4.0));
            let center = Vec3::new(u(-1.0, 1.0), u(-1.0, 1.0), u(-1.0, 1.0)) * extent * u(0.0, 4.0);
            let positions: Vec<Vec3> = (0..64)
                .map(|k| if k == 0 { Vec3::ZERO } else { center + Vec3::new(u(-1.0, 1.0), u(-1.0, 1.0), u(-1.0, 1.0)) * extent })
                .collect();
            let normals = vec![Vec3::ZERO; positions.len()];
            if case % 2 == 0 {
                let mesh = Mesh::new(&positions, &normals, &[]).unwrap();
                let exact: Vec<[f64; 3]> = positions.iter().map(|p| [p.x as f64, p.y as f64, p.z as f64]).collect();
                equal += check(&mvp, &mesh, &exact, bits);
            } else {
                let (scale, offset) = ([extent / 16000.0; 3], [center.x, center.y, center.z]);
                let steps: Vec<[i16; 3]> =
                    positions.iter().map(|p| [p.x, p.y, p.z].map(|_| (next() % 65535) as i32 - 32767).map(|s| s as i16)).collect();
                let qn = vec![[0i16; 3]; steps.len()];
                let mesh = Mesh::new_i16(&steps, scale, offset, &qn, &[]).unwrap();
                let exact: Vec<[f64; 3]> =
                    steps.iter().map(|s| [0, 1, 2].map(|k| s[k] as f64 * scale[k] as f64 + offset[k] as f64)).collect();
                equal += check(&mvp, &mesh, &exact, bits);
            }
        }
        // Most coordinates are checked for equality (the rest lie within
        // the f32 matrix's error of a rounding boundary, or off screen).
        assert!(equal > 60_000, "only {equal} coordinates checked exactly");
    }

    #[test]
    fn non_finite_positions_are_flagged() {
        let (mvp, _) = random_mvp(&mut xorshift(7));
        let positions = [Vec3::new(f32::NAN, 0.0, 0.0), Vec3::new(0.0, f32::INFINITY, 0.0), Vec3::new(0.0, 0.0, 1.0)];
        let mesh = Mesh::new(&positions, &[Vec3::ZERO; 3], &[]).unwrap();
        let projection = IntegerProjection::new(&mvp, mesh.positions(), mesh.bounds(), W, H, 4).unwrap();
        for i in 0..2 {
            assert_eq!(super::super::flags(&projection.project::<1>(i, [0.0])), NOT_FINITE);
        }
        assert_eq!(super::super::flags(&projection.project::<1>(2, [f32::NAN])), NOT_FINITE);
        assert_ne!(super::super::flags(&projection.project::<1>(2, [0.0])), NOT_FINITE);
    }

    #[test]
    fn draw_calls_beyond_the_scheme_are_declined() {
        let (mvp, _) = random_mvp(&mut xorshift(9));
        let positions = [Vec3::new(1e38, 0.0, 0.0), Vec3::new(-1e38, 0.0, 0.0)];
        let mesh = Mesh::new(&positions, &[Vec3::ZERO; 2], &[]).unwrap();
        assert!(IntegerProjection::new(&mvp, mesh.positions(), mesh.bounds(), W, H, 4).is_none());
        let small = Mesh::new(&positions[..0], &[], &[]).unwrap();
        assert!(IntegerProjection::new(&Mat4 { m: [[0.0; 4]; 4] }, small.positions(), small.bounds(), W, H, 4).is_none());
    }

    #[test]
    fn conversions_by_the_bits() {
        for (v, k, want) in
            [(1.5f32, 1, 3), (-1.25, 2, -5), (0.5, 0, 1), (-0.5, 0, -1), (0.49, 0, 0), (3.0, 40, INPUT_MAX), (1e-30, 10, 0), (-0.0, 5, 0)]
        {
            assert_eq!(scaled_rounded(v, k, INPUT_MAX), Some(want), "{v} * 2^{k}");
        }
        assert_eq!(scaled_rounded(3.0, 40, 7), Some(7));
        assert_eq!(scaled_rounded(f32::NAN, 0, INPUT_MAX), None);
        for (v, e, want) in [(1u32, 0, 1.0f32), (3, -1, 1.5), (1 << 30, -30, 1.0), (0, 5, 0.0), (1, -200, 0.0), (1, 200, f32::MAX)] {
            assert_eq!(f32_from_parts(v, e), want, "{v} * 2^{e}");
        }
    }

    #[test]
    fn depth_to_f32_precision_is_the_round_trip_through_f32() {
        // What the depth was when stored as `f32_from_parts(depth, -30)`
        // and converted back: the same integer, with no `f32` stored.
        let mut next = xorshift(0x0DE9_7A30);
        let edges = [0, 1, (1 << 24) - 1, 1 << 24, (1 << 24) + 1, (1 << 30) - 1, 1 << 30];
        for v in edges.into_iter().chain((0..100_000).map(|_| next() >> (2 + next() % 24))) {
            let v = v.min(1 << 30);
            let round_trip = (f32_from_parts(v, -30) as f64 * (1u64 << 30) as f64) as u32;
            assert_eq!(f32_precision(v), round_trip, "{v}");
        }
    }
}
