//! Triangle setup and rasterization of one triangle into one strip.
//!
//! Coverage is exact integer arithmetic on snapped vertices. Window
//! coordinates are stored with `F = SUBPIXEL_BITS + 1` fractional bits;
//! vertices sit on even values (the `SUBPIXEL_BITS` grid) and pixel centers
//! on odd ones (`x * 2^F + 2^(F-1)`), so "is this center left of that edge"
//! is an exact integer question for every sub-pixel setting, 0 included.
//!
//! A pixel is covered when its center is inside the triangle, or on a left
//! or top edge (the top-left rule). Rows run from the topmost to the
//! bottommost vertex, a triangle is split at its middle vertex, and each
//! edge is walked down the rows with an exact integer DDA that yields the
//! first covered (left edge) or first uncovered (right edge) pixel:
//! `ceil((x_a - 2^(F-1)) * dy + dx * (y_c - y_a)) / (dy * 2^F))`. The same
//! formula serves both sides, which is what makes shared edges exact: a
//! pixel left of an edge is never also right of it.
//!
//! Attributes (depth and the effect's varyings) are plane equations set up
//! once per triangle in `f32`, then stepped with one addition per pixel in
//! the renderer's [`Interp`] scalar.

use crate::effect::{Effect, MAX_VARYINGS};
use crate::material::{DepthMode, Perspective};
use crate::math::Interp;
use embedded_graphics::pixelcolor::Rgb888;

/// Largest magnitude of a snapped coordinate, in units of `2^-F` pixels.
///
/// Differences then fit in 31 bits and every product in setup in 61, so
/// setup never overflows `i64`. Vertices beyond it are clipped to it first
/// (see [`crate::clip`]). In pixels this is `2^(29 - F)`: 16.7 million
/// pixels at 4 sub-pixel bits, 1 million at 8.
pub const GUARD: i32 = 1 << 29;

/// Depth values are stepped as `z * 2^DEPTH_PRESHIFT` so that the
/// fixed-point scalar keeps 24 bits of depth below the point; the stored
/// 16-bit depth is `floor(z * 65536)`.
const DEPTH_PRESHIFT: f32 = 256.0;

/// Cleared depth value (farther than anything drawable).
pub const DEPTH_CLEAR: u16 = u16::MAX;

/// A vertex in window space, ready for setup.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScreenVertex<const V: usize> {
    /// Snapped x in units of `2^-F` pixels.
    pub x: i32,
    /// Snapped y (down) in units of `2^-F` pixels.
    pub y: i32,
    /// Window depth in [0, 1], smaller nearer.
    pub z: f32,
    /// `1 / w` (clip-space w), for perspective-correct interpolation.
    pub q: f32,
    /// Varyings.
    pub attrs: [f32; V],
}

impl<const V: usize> ScreenVertex<V> {
    /// A placeholder vertex.
    pub const ZERO: Self = Self { x: 0, y: 0, z: 0.0, q: 1.0, attrs: [0.0; V] };
}

/// Snaps a window coordinate (pixels) to the sub-pixel grid, in units of
/// `2^-F` pixels, rounding half up. `None` if it is not finite or lies
/// beyond [`GUARD`]. Gives exactly what [`snap_f64`] gives for the same value.
#[inline]
pub fn snap(v: f32, subpixel_bits: u32) -> Option<i32> {
    // Scaling by a power of two is exact. Below 2^23 adding 0.5 is exact
    // too; above, every f32 is already an integer.
    let s = v * (1u32 << subpixel_bits) as f32;
    let r = if s.abs() < 8_388_608.0 { floor_f32(s + 0.5) } else { s };
    let limit = (GUARD >> 1) as f32;
    if r >= -limit && r <= limit {
        Some((r as i32) << 1)
    } else {
        None
    }
}

/// [`snap`] for `f64` input (window-space input files keep full precision).
#[inline]
pub fn snap_f64(v: f64, subpixel_bits: u32) -> Option<i32> {
    let s = v * (1u32 << subpixel_bits) as f64;
    let t = s + 0.5;
    let mut r = t as i64 as f64;
    if r > t {
        r -= 1.0;
    }
    let limit = (GUARD >> 1) as f64;
    if r >= -limit && r <= limit {
        Some((r as i32) << 1)
    } else {
        None
    }
}

#[inline]
fn floor_f32(v: f32) -> f32 {
    // Callers pass |v| < 2^23 + 1, where the i32 round trip is exact.
    let t = v as i32 as f32;
    if t > v {
        t - 1.0
    } else {
        t
    }
}

/// Twice the signed area of a snapped triangle, in `2^-2F` square pixels.
/// Positive when the triangle is clockwise on screen (y down), which is a
/// front face.
#[inline]
pub fn signed_area2<const V: usize>(a: &ScreenVertex<V>, b: &ScreenVertex<V>, c: &ScreenVertex<V>) -> i64 {
    let (bx, by) = (b.x as i64 - a.x as i64, b.y as i64 - a.y as i64);
    let (cx, cy) = (c.x as i64 - a.x as i64, c.y as i64 - a.y as i64);
    bx * cy - by * cx
}

/// First pixel row whose center is at or below snapped y.
#[inline]
pub fn first_row_at_or_below(y: i32, subpixel_bits: u32) -> i32 {
    let f = subpixel_bits + 1;
    // ceil((y - half) / 2^F) as an arithmetic shift.
    ((y as i64 - (1i64 << subpixel_bits) + (1i64 << f) - 1) >> f) as i32
}

/// `ceil(n / d)` and `d * ceil(n / d) - n` for `d > 0`, fast when both fit
/// in 32 bits (divisions of 64-bit values are library calls on Cortex-M).
#[inline]
fn div_ceil_rem(n: i64, d: i64) -> (i64, i64) {
    let neg = -n;
    if let (Ok(n32), Ok(d32)) = (i32::try_from(neg), i32::try_from(d)) {
        (-(n32.div_euclid(d32)) as i64, n32.rem_euclid(d32) as i64)
    } else {
        (-neg.div_euclid(d), neg.rem_euclid(d))
    }
}

/// `floor(n / d)` and the remainder for `d > 0`.
#[inline]
fn div_floor_rem(n: i64, d: i64) -> (i64, i64) {
    if let (Ok(n32), Ok(d32)) = (i32::try_from(n), i32::try_from(d)) {
        (n32.div_euclid(d32) as i64, n32.rem_euclid(d32) as i64)
    } else {
        (n.div_euclid(d), n.rem_euclid(d))
    }
}

/// Walks one edge down the rows, yielding the pixel bound at each row
/// center exactly: `bound = ceil(m / d)` with `m` growing by a constant per
/// row, tracked as quotient `bound` and remainder `err = bound * d - m`.
struct EdgeWalker {
    bound: i64,
    err: i64,
    step_q: i64,
    step_r: i64,
    d: i64,
}

impl EdgeWalker {
    /// Edge from `a` down to `b` (`b.y > a.y`), positioned at pixel row `row`.
    #[inline]
    fn new(ax: i32, ay: i32, bx: i32, by: i32, row: i32, f: u32) -> Self {
        let half = 1i64 << (f - 1);
        let (dx, dy) = (bx as i64 - ax as i64, by as i64 - ay as i64);
        let d = dy << f;
        let yc = ((row as i64) << f) + half;
        let m = (ax as i64 - half) * dy + dx * (yc - ay as i64);
        let (bound, err) = div_ceil_rem(m, d);
        // One row adds dx * 2^F to m: dx / dy pixels.
        let (q, r) = div_floor_rem(dx, dy);
        Self { bound, err, step_q: q, step_r: r << f, d }
    }

    #[inline]
    fn step(&mut self) {
        self.bound += self.step_q;
        self.err -= self.step_r;
        if self.err < 0 {
            self.err += self.d;
            self.bound += 1;
        }
    }
}

/// The part of a frame one strip covers.
pub struct StripTarget<'a, C> {
    /// Colors, `width` per row.
    pub color: &'a mut [C],
    /// Depths, `width` per row.
    pub depth: &'a mut [u16],
    /// Row length in pixels.
    pub width: usize,
    /// First frame row of the strip.
    pub y0: i32,
    /// Rows in the strip.
    pub rows: i32,
}

/// Rasterizes one triangle into a strip with effect `E`, interpolation
/// `P` and depth mode `D`, stepping attributes in `S`.
///
/// `face` is the triangle's color (already converted) for effects that
/// use one. Degenerate triangles (zero snapped area) draw nothing.
#[allow(clippy::too_many_arguments)]
#[inline(never)]
pub fn rasterize<C, S, E, P, D, const V: usize>(target: &mut StripTarget<'_, C>, tri: [&ScreenVertex<V>; 3], face: C, subpixel_bits: u32)
where
    C: From<Rgb888> + Into<Rgb888> + Copy,
    S: Interp,
    E: Effect,
    P: Perspective,
    D: DepthMode,
{
    let f = subpixel_bits + 1;
    // Sort by y: a top, b middle, c bottom.
    let [mut a, mut b, mut c] = tri;
    if a.y > b.y {
        core::mem::swap(&mut a, &mut b);
    }
    if b.y > c.y {
        core::mem::swap(&mut b, &mut c);
    }
    if a.y > b.y {
        core::mem::swap(&mut a, &mut b);
    }
    let area = signed_area2(a, b, c);
    if area == 0 {
        return;
    }
    // With y down, a negative area puts the middle vertex left of the long edge.
    let mid_left = area < 0;

    let y_top = first_row_at_or_below(a.y, subpixel_bits);
    let y_mid = first_row_at_or_below(b.y, subpixel_bits);
    let y_bot = first_row_at_or_below(c.y, subpixel_bits);
    let y_start = y_top.max(target.y0);
    let y_end = y_bot.min(target.y0 + target.rows);
    if y_start >= y_end {
        return;
    }
    let width = target.width as i64;

    // Plane equations, relative to vertex a, in pixels.
    let inv_f = 1.0 / (1u32 << f) as f32;
    let (x1, y1) = ((b.x as i64 - a.x as i64) as f32 * inv_f, (b.y as i64 - a.y as i64) as f32 * inv_f);
    let (x2, y2) = ((c.x as i64 - a.x as i64) as f32 * inv_f, (c.y as i64 - a.y as i64) as f32 * inv_f);
    let inv_det = 1.0 / (area as f32 * inv_f * inv_f);
    // Base point: center of the leftmost on-screen pixel of the bounding box
    // on the first row, so offsets stay small.
    let min_x = a.x.min(b.x).min(c.x);
    let x_base = ((min_x as i64) >> f).clamp(0, width - 1) as i32;
    let ox = (x_base as f32 + 0.5) - a.x as f32 * inv_f;
    let oy = (y_start as f32 + 0.5) - a.y as f32 * inv_f;
    let plane = |v0: f32, v1: f32, v2: f32| -> (S, S, S) {
        let (d1, d2) = (v1 - v0, v2 - v0);
        let gx = (d1 * y2 - d2 * y1) * inv_det;
        let gy = (d2 * x1 - d1 * x2) * inv_det;
        (S::from_f32(v0 + gx * ox + gy * oy), S::from_f32(gx), S::from_f32(gy))
    };

    let (mut z_row, z_dx, z_dy) = plane(a.z * DEPTH_PRESHIFT, b.z * DEPTH_PRESHIFT, c.z * DEPTH_PRESHIFT);
    // Perspective-correct varyings are interpolated as value * q', with
    // q' = q / max(q) in (0, 1] (normalized so fixed point keeps precision).
    let (qa, qb, qc) = if P::CORRECT {
        let qmax = a.q.max(b.q).max(c.q);
        let k = if qmax > 0.0 { 1.0 / qmax } else { 1.0 };
        (a.q * k, b.q * k, c.q * k)
    } else {
        (1.0, 1.0, 1.0)
    };
    let (mut q_row, q_dx, q_dy) = if P::CORRECT { plane(qa, qb, qc) } else { (S::default(), S::default(), S::default()) };
    let mut v_row = [S::default(); MAX_VARYINGS];
    let mut v_dx = [S::default(); MAX_VARYINGS];
    let mut v_dy = [S::default(); MAX_VARYINGS];
    for i in 0..E::VARYINGS.min(V) {
        (v_row[i], v_dx[i], v_dy[i]) = plane(a.attrs[i] * qa, b.attrs[i] * qb, c.attrs[i] * qc);
    }

    let mut long = EdgeWalker::new(a.x, a.y, c.x, c.y, y_start, f);
    let mut short =
        if y_start < y_mid { EdgeWalker::new(a.x, a.y, b.x, b.y, y_start, f) } else { EdgeWalker::new(b.x, b.y, c.x, c.y, y_start, f) };

    for y in y_start..y_end {
        if y == y_mid && y_mid > y_start {
            short = EdgeWalker::new(b.x, b.y, c.x, c.y, y, f);
        }
        let (left, right) = if mid_left { (&short, &long) } else { (&long, &short) };
        let x0 = left.bound.clamp(0, width) as usize;
        let x1 = right.bound.clamp(0, width) as usize;
        if x0 < x1 {
            let row = (y - target.y0) as usize * target.width;
            let n = (x0 as i32) - x_base;
            let mut vals = v_row;
            for i in 0..E::VARYINGS.min(V) {
                vals[i] = v_row[i].add_mul(v_dx[i], n);
            }
            span::<C, S, E, P, D>(
                &mut target.color[row + x0..row + x1],
                &mut target.depth[row + x0..row + x1],
                z_row.add_mul(z_dx, n),
                z_dx,
                vals,
                &v_dx,
                q_row.add_mul(q_dx, n),
                q_dx,
                face,
            );
        }
        long.step();
        short.step();
        z_row = z_row.add(z_dy);
        if P::CORRECT {
            q_row = q_row.add(q_dy);
        }
        for i in 0..E::VARYINGS.min(V) {
            v_row[i] = v_row[i].add(v_dy[i]);
        }
    }
}

/// The inner loop: one row of one triangle. No branch depends on a feature
/// at run time; `P` and `D` are constants here.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn span<C, S, E, P, D>(
    color: &mut [C],
    depth: &mut [u16],
    mut z: S,
    z_dx: S,
    mut vals: [S; MAX_VARYINGS],
    v_dx: &[S; MAX_VARYINGS],
    mut q: S,
    q_dx: S,
    face: C,
) where
    C: From<Rgb888> + Into<Rgb888> + Copy,
    S: Interp,
    E: Effect,
    P: Perspective,
    D: DepthMode,
{
    for (px, zb) in color.iter_mut().zip(depth.iter_mut()) {
        let zq = z.quantize(8, u16::MAX as u32) as u16;
        if !D::TEST || zq < *zb {
            if D::WRITE {
                *zb = zq;
            }
            *px = if P::CORRECT {
                let w = q.recip();
                let mut v = vals;
                for x in v.iter_mut().take(E::VARYINGS) {
                    *x = x.mul(w);
                }
                E::shade(face, &v, *px)
            } else {
                E::shade(face, &vals, *px)
            };
        }
        z = z.add(z_dx);
        if P::CORRECT {
            q = q.add(q_dx);
        }
        for i in 0..E::VARYINGS {
            vals[i] = vals[i].add(v_dx[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snapping_rounds_to_the_grid_and_rejects_the_far() {
        assert_eq!(snap(1.0, 4), Some(32));
        assert_eq!(snap(1.03125, 4), Some(34)); // 1 + 1/32 rounds up to 1 + 1/16
        assert_eq!(snap(-0.5, 0), Some(0)); // half rounds up
        assert_eq!(snap(f32::NAN, 4), None);
        assert_eq!(snap(1e9, 4), None);
        assert_eq!(snap_f64(1234567.0625, 4), Some(1234567 * 32 + 2));
        assert_eq!(snap_f64(-2.5, 0), Some(-4));
        assert_eq!(snap_f64(f64::INFINITY, 4), None);
    }

    #[test]
    fn rows_start_at_the_first_center_at_or_below() {
        // 4 sub-pixel bits: F = 5, a pixel is 32 units, centers at 16 + 32k.
        assert_eq!(first_row_at_or_below(16, 4), 0);
        assert_eq!(first_row_at_or_below(17, 4), 1);
        assert_eq!(first_row_at_or_below(-15, 4), 0);
        assert_eq!(first_row_at_or_below(-16, 4), -1);
        assert_eq!(first_row_at_or_below(-48, 4), -2);
        assert_eq!(first_row_at_or_below(-47, 4), -1);
    }

    #[test]
    fn edge_walker_is_exact() {
        // Compare against direct evaluation for many edges and rows.
        let f = 5;
        let half = 16i64;
        for (ax, ay, bx, by) in [(0, 0, 100, 7), (37, -5, -400, 900), (1000, 3, 1000, 64), (-5, 10, 6000, 11)] {
            let start = first_row_at_or_below(ay, 4);
            let mut w = EdgeWalker::new(ax, ay, bx, by, start, f);
            for row in start..start + 40 {
                let yc = ((row as i64) << f) + half;
                let m = (ax as i64 - half) * (by - ay) as i64 + (bx - ax) as i64 * (yc - ay as i64);
                let d = ((by - ay) as i64) << f;
                let expect = (m as f64 / d as f64).ceil() as i64;
                assert_eq!(w.bound, expect, "edge {ax},{ay}->{bx},{by} row {row}");
                w.step();
            }
        }
    }
}
