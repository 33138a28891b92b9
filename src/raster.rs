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
//! once per triangle in the renderer's [`Interp`] scalar (`f32` in `f32`;
//! integers only in fixed point, from the exact snapped offsets: see
//! [`crate::math::FixedBasis`]), then stepped with one addition per pixel.

use crate::effect::{Color, Effect, MAX_VARYINGS};
use crate::material::{DepthMode, Perspective};
use crate::math::{all_short, all_within, div_floor_small, greater, less, mul, mul_wide, Interp};
use crate::settings::DepthFormat;

/// Largest magnitude of a snapped coordinate with `subpixel_bits` bits of
/// sub-pixel precision, in units of `2^-F` pixels (`F = subpixel_bits + 1`):
/// `2^(29 - F)`.
///
/// Edge heights in units times `2^F` then stay below `2^31`, so the edge
/// walkers work in 32 bits, and every product in setup fits `i64`.
/// Vertices beyond it are clipped to it first (see [`crate::clip`]). In
/// pixels this is `2^(27 - 2 * subpixel_bits)`: 134 million pixels at 0
/// sub-pixel bits, 524,288 at 4 and 2,048 at 8.
pub const fn guard(subpixel_bits: u32) -> i32 {
    1 << (28 - subpixel_bits)
}

/// Depth z in [0, 1] (smaller nearer) is stored inverted, as
/// `floor((1 - z) * DEPTH_RANGE + 1.5)`: 1 to 65535, larger nearer, so that
/// a cleared buffer is all zeros (a renderer made with a black fill is
/// zero-initialized and costs no flash in a `static`), nothing drawn ever
/// equals [`DEPTH_CLEAR`], and the half unit of margin absorbs
/// interpolation rounding at the vertices. "Nearer than stored" is then
/// `new > stored`; ties keep the first fragment, like a "less" test on z.
pub(crate) const DEPTH_RANGE: f32 = 65534.0;

/// Window depth 1 (the far plane) in [`ScreenVertex::z`]'s units of 2^-30.
pub const DEPTH_ONE: u32 = 1 << 30;

/// Window depth `z` (in `[0, 1]`, which rounding can leave by an ulp) in
/// [`ScreenVertex::z`]'s units: times 2^30, truncated and clamped to
/// `0..=DEPTH_ONE` (NaN gives 0). Exact for `z` from 2^-7 up: below, the
/// bits lost are finer than any depth format stores.
#[inline]
pub fn window_depth(z: f32) -> u32 {
    if crate::math::HARD_FLOAT {
        // The conversion to `u32` saturates (NaN and negatives to 0): one
        // instruction with an FPU, and one compare for the upper end.
        ((z * (1u32 << 30) as f32) as u32).min(DEPTH_ONE)
    } else {
        crate::math::Fixed::scaled_truncated(z, 30).clamp(0, DEPTH_ONE as i32) as u32
    }
}

/// A vertex in window space, ready for setup.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScreenVertex<const V: usize> {
    /// Snapped x in units of `2^-F` pixels.
    pub x: i32,
    /// Snapped y (down) in units of `2^-F` pixels.
    pub y: i32,
    /// Window depth in [0, 1], smaller nearer, in units of 2^-30 (at most
    /// [`DEPTH_ONE`]; see [`window_depth`]): an integer, so that the vertex
    /// stage converts it once and fixed point sets up depth planes with no
    /// conversion per triangle.
    pub z: u32,
    /// `1 / w` (clip-space w), for perspective-correct interpolation.
    pub q: f32,
    /// Varyings.
    pub attrs: [f32; V],
}

impl<const V: usize> ScreenVertex<V> {
    /// A placeholder vertex.
    pub const ZERO: Self = Self { x: 0, y: 0, z: 0, q: 0.0, attrs: [0.0; V] };
}

/// Snaps a window coordinate (pixels) to the sub-pixel grid, in units of
/// `2^-F` pixels, rounding half up. `None` if it is not finite or lies
/// beyond the [`guard`] band. Gives exactly what [`snap_f64`] gives for the same value.
#[inline]
pub fn snap(v: f32, subpixel_bits: u32) -> Option<i32> {
    // Rounding half up is `floor(s + 0.5) = floor((floor(2 s) + 1) / 2)`
    // for the scaled value `s`, and `2 s` is exact (a power of two times
    // `v`): no rounded sum (in `f32`, `s + 0.5` rounds up for `s` just
    // below a half).
    let u = v * (2u32 << subpixel_bits) as f32;
    let limit = guard(subpixel_bits) >> 1;
    // The band is `floor(u)` in `[-2 limit - 1, 2 limit]`, i.e. `u` in
    // `[-2 limit - 1, 2 limit + 1)`; NaN is outside.
    let (lo, hi) = (-2 * limit - 1, 2 * limit + 1);
    let inside = if hi <= 1 << 24 {
        // Bounds exact in f32 (5 sub-pixel bits or more, the usual; known
        // once this is inlined): one range test.
        u >= lo as f32 && u < hi as f32
    } else {
        // Below that |u| < 2^29 keeps `floor(u)` in i32 (where |u| >= 2^24
        // it is an integer), and the band is tested on it.
        u > -536_870_912.0 && u < 536_870_912.0 && {
            let i = floor_to_i32(u);
            i >= lo && i < hi
        }
    };
    if !inside {
        return None;
    }
    // (floor(u) + 1) >> 1, times two.
    Some((floor_to_i32(u) + 1) & !1)
}

/// `floor(u)` for `|u| < 2^29`.
#[inline(always)]
fn floor_to_i32(u: f32) -> i32 {
    let i = u as i32;
    if i as f32 > u {
        i - 1
    } else {
        i
    }
}

/// [`snap`] for `f64` input (window-space input files keep full precision).
#[inline]
pub fn snap_f64(v: f64, subpixel_bits: u32) -> Option<i32> {
    // As in `snap`: `floor(s + 0.5)` from the exact `2 s`; every bound
    // is exact in f64, and NaN fails the test.
    let u = v * (2u32 << subpixel_bits) as f64;
    let limit = guard(subpixel_bits) >> 1;
    if !(u >= (-2 * limit - 1) as f64 && u < (2 * limit + 1) as f64) {
        return None;
    }
    let i = u as i32;
    Some((if i as f64 > u { i - 1 } else { i } + 1) & !1)
}

#[inline]
fn floor_f32(v: f32) -> f32 {
    // Callers pass |v| < 2^23 + 1, where the i32 round trip is exact.
    let t = v as i32 as f32;
    if greater(t, v) {
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
    // Snapped coordinates are within ±2^28, so differences fit i32 and
    // each product is one 32×32→64 multiply.
    cross(b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y, cfg!(soft3d_armv6m))
}

/// `bx cy - by cx`. With `short` (where there is no long multiply:
/// ARMv6-M), offsets in `[-2^15, 2^15)` units (below 256 pixels at the
/// default 6 sub-pixel bits) take two 32-bit products: each at most 2^30
/// in magnitude, and of opposite signs at most 2^30 - 2^15, so that their
/// difference fits.
#[inline(always)]
fn cross(bx: i32, by: i32, cx: i32, cy: i32, short: bool) -> i64 {
    if short && all_short([bx, by, cx, cy]) {
        return (bx * cy - by * cx) as i64;
    }
    mul_wide(bx, cy) - mul_wide(by, cx)
}

/// First pixel row whose center is at or below snapped y.
#[inline]
pub fn first_row_at_or_below(y: i32, subpixel_bits: u32) -> i32 {
    let f = subpixel_bits + 1;
    // ceil((y - half) / 2^F) as an arithmetic shift; |y| <= 2^28 (the
    // guard band), so the sum fits i32.
    (y - (1 << subpixel_bits) + (1 << f) - 1) >> f
}

/// The center of pixel row `row` in snapped units of `2^-F` pixels
/// (`F = subpixel_bits + 1`): a snapped `y` lies below it exactly when
/// [`first_row_at_or_below`]`(y)` is past `row`. For `|row|` below
/// `2^(30 - F)`.
#[inline]
pub fn row_center(row: i32, subpixel_bits: u32) -> i32 {
    (row << (subpixel_bits + 1)) + (1 << subpixel_bits)
}

/// `m` as `i32` if it fits. On the M4F, as "its high word is its low
/// word's sign", one compare with a shifted operand: `i32::try_from` took
/// five instructions there (`torus.babylon` `f32` 0.9% and `monkey` 1.2%
/// fewer with this). ARMv6-M has no shifted operands, and there the
/// same test measured 0.8% more on `torus.babylon`.
#[inline(always)]
fn narrow(m: i64) -> Option<i32> {
    if cfg!(soft3d_armv6m) {
        return i32::try_from(m).ok();
    }
    let (low, high) = (m as i32, (m >> 32) as i32);
    (high == low >> 31).then_some(low)
}

/// `ceil(m / d)` and `d * ceil(m / d) - m` (in `[0, d)`) for `d > 0`;
/// 32-bit division when `m` fits (64-bit division is a library call on
/// Cortex-M), and on ARMv6-M, which has no divide instruction at all, the
/// division by steps that is quick for small quotients.
#[inline]
fn div_ceil_rem(m: i64, d: i32) -> (i32, i32) {
    let (q, r) = match narrow(m) {
        Some(m) if cfg!(soft3d_armv6m) => {
            // Floor division, r in [0, d). Its own return measured 0.15%
            // quicker on torus.babylon (M0+) than joining the tail below.
            let (q, r) = div_floor_small(m, d);
            return if r > 0 { (q + 1, d - r) } else { (q, 0) };
        }
        Some(m) => (m / d, m % d),
        // |m| < 2^61 and d >= 2^F, so the quotient is a pixel coordinate
        // within the guard band and the remainder is below d.
        None => ((m / d as i64) as i32, (m % d as i64) as i32),
    };
    // Truncating division: r has the sign of m.
    if r > 0 {
        (q + 1, d - r)
    } else {
        (q, -r)
    }
}

/// An edge's bound at its first row, `ceil(m / d)`, and the remainder
/// `bound d - m`, for `m = from dy + dx t` and `d = dy 2^f` (see
/// [`EdgeWalker`]). With `split` (where there is no divide instruction)
/// the whole pixels of `from` are taken out first, exactly: what is left
/// to divide by steps is mostly the edge's run over part of a row, a
/// small quotient (and the fraction times `dy` is below `d < 2^31`). With
/// a divide instruction, that costs more than it saves (+1.4% on
/// torus.babylon, M4F).
#[inline(always)]
fn edge_start(from: i32, dx: i32, dy: i32, t: i32, f: u32, split: bool) -> (i32, i32) {
    let d = dy << f;
    if split {
        // A small triangle's run is a single multiply (t >= 0: the row is
        // at or below the vertex), not a product by halves.
        let run = if all_short([dx, t]) { (dx * t) as i64 } else { mul_wide(dx, t) };
        let (run, err) = div_ceil_rem(((from & ((1 << f) - 1)) * dy) as i64 + run, d);
        ((from >> f) + run, err)
    } else {
        div_ceil_rem(mul_wide(from, dy) + mul_wide(dx, t), d)
    }
}

/// Walks one edge down the rows, yielding the pixel bound at each row
/// center exactly: `bound = ceil(m / d)` with `m` growing by a constant per
/// row, tracked as quotient `bound` and remainder `err = bound * d - m`.
/// Within the guard band every field fits 32 bits.
struct EdgeWalker {
    bound: i32,
    err: i32,
    step_q: i32,
    step_r: i32,
    d: i32,
}

impl EdgeWalker {
    /// A walker whose steps mean nothing: where [`Rows`] divides per row,
    /// and for an edge that spans no row.
    const IDLE: Self = Self { bound: 0, err: 0, step_q: 0, step_r: 0, d: 1 };

    /// Edge from `a` down to `b` (`b.y > a.y`), positioned at pixel row
    /// `row`, to be walked to row `end` (exclusive). Its steps are set up
    /// only if it walks more than one row: on `torus.babylon` 709 of the
    /// 1,466 walkers a frame serve one row, and skipping their division
    /// took `EdgeWalker::new` from 159 k to 149 k instructions (M0+).
    /// Not inlined: its six copies (three per rasterizer) cost the RP2040
    /// firmware 10 KB of flash for 0.2% of `torus.babylon` on the M0+.
    /// (Where there is a divide instruction, [`Rows`] divides per row
    /// instead; the walker is checked against that in the tests.)
    #[inline(never)]
    fn new(ax: i32, ay: i32, bx: i32, by: i32, row: i32, end: i32, f: u32) -> Self {
        let half = 1i32 << (f - 1);
        // Coordinates are within ±2^(29-F), so dy << F < 2^31.
        let (dx, dy) = (bx - ax, by - ay);
        // Only descending edges are walked (a row center lies between
        // their ends). Tested all the same where there is a divide
        // instruction: the divisions then need no test for zero or
        // overflow (ARMv6-M divides by steps, without such tests, and
        // the test measured 0.4% slower there).
        if !cfg!(soft3d_armv6m) && dy <= 0 {
            return Self::IDLE;
        }
        let d = dy << f;
        let yc = (row << f) + half;
        let (bound, err) = edge_start(ax - half, dx, dy, yc - ay, f, cfg!(soft3d_armv6m));
        // One row adds dx * 2^F to m: dx / dy pixels, floored. (A walker
        // of one row is stepped once, past its end: its steps are zero.)
        let (step_q, step_r) = if end - row < 2 {
            (0, 0)
        } else if cfg!(soft3d_armv6m) {
            div_floor_small(dx, dy)
        } else {
            let (q, r) = (dx / dy, dx % dy);
            if r < 0 {
                (q - 1, r + dy)
            } else {
                (q, r)
            }
        };
        Self { bound, err, step_q, step_r: step_r << f, d }
    }

    #[inline(always)]
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
pub struct StripTarget<'a, C, Z> {
    /// Colors, `width` per row.
    pub color: &'a mut [C],
    /// Depths in a [`DepthFormat`]'s values, `width` per row.
    pub depth: &'a mut [Z],
    /// Row length in pixels.
    pub width: usize,
    /// First frame row of the strip.
    pub y0: i32,
    /// Rows in the strip.
    pub rows: i32,
    /// Columns written so far, `dirty.0..dirty.1` (empty if `0 >= 1`), so
    /// that only they need clearing for the next strip.
    pub dirty: (usize, usize),
}

/// One interpolated quantity of a triangle: its value at the top vertex,
/// its gradients per pixel, and the range it must stay in.
#[derive(Clone, Copy)]
struct Plane<S> {
    at_a: S,
    dx: S,
    dy: S,
    lo: S,
    hi: S,
}

/// A plane `(value at the top vertex, dx, dy)` in `f32` for where stepping
/// in `S` cannot be trusted: a gradient that does not fit 16.16 (a
/// sliver's depth), or a triangle reaching far toward the guard band,
/// whose gradients' rounding, times millions of pixels from its top
/// vertex, would be far off on screen. Only the careful path uses it: it
/// evaluates span ends from it in `f64` (the gradients, rounded to `f32`
/// from their `f64` values, are then off by less than 0.4 of a level at
/// 2^27 pixels).
type WidePlane = (f32, f32, f32);

impl<S: Interp> Plane<S> {
    /// The plane through the values `a`, `b`, `c` at the vertices of a
    /// triangle of shape `shape` (see [`Shape`]). A plane too steep to
    /// step (see [`Interp::is_wide`]) sets `steep`: the careful path then
    /// sets it up again by [`Plane::far`]. `clear` is cleared unless the
    /// vertex values alone show the stepped plane in range (see
    /// [`Interp::clear_of_bounds`]).
    #[inline(always)]
    fn new(shape: &Shape<S>, (a, b, c): (S, S, S), (lo, hi): (S, S), clear: &mut bool, steep: &mut bool) -> Self {
        let (gx, gy) = S::gradients(&shape.basis, a, b, c);
        // Fixed point saturates gradients beyond ±32768 (a sliver's
        // depth): checked on the integers, two compares that cost no float
        // operation (in software on an M0+).
        if gx.is_wide() | gy.is_wide() {
            (*clear, *steep) = (false, true);
        }
        // Only where the exact check's 64-bit products are library calls
        // (ARMv6-M): with a long multiply the check measured cheaper than
        // this test (torus.babylon on the M4F: 1.17 M instructions a frame
        // against 1.29 M; on the M0+ 7.64 M against 7.30 M).
        // (Not tested again once a plane has failed it.)
        *clear = *clear && cfg!(soft3d_armv6m) && S::clear_of_bounds(&shape.basis, a, b, c, lo, hi);
        Self { at_a: a, dx: gx, dy: gy, lo, hi }
    }

    /// [`Plane::new`] from values in `f32`.
    #[inline(always)]
    fn from_f32(shape: &Shape<S>, (va, vb, vc): (f32, f32, f32), range: (S, S), clear: &mut bool, steep: &mut bool) -> Self {
        let convert = S::from_f32_truncated;
        Self::new(shape, (convert(va), convert(vb), convert(vc)), range, clear, steep)
    }

    /// Whether the plane's gradients are too steep to step (see
    /// [`Interp::is_wide`]).
    fn is_steep(&self) -> bool {
        self.dx.is_wide() | self.dy.is_wide()
    }

    /// [`Plane::new`] for a triangle reaching toward the guard band, in
    /// `f64` from the exact integer offsets (in `f32` the products cancel
    /// to noise and the offsets themselves lose bits). Rare, so the cost
    /// of `f64` does not matter.
    #[cold]
    #[inline(never)]
    fn far(shape: &Shape<S>, (va, vb, vc): (f32, f32, f32), (lo, hi): (S, S)) -> (Self, WidePlane) {
        let (d1, d2) = (vb - va, vc - va);
        let (x1, y1, x2, y2) = (shape.ox1 as f64, shape.oy1 as f64, shape.ox2 as f64, shape.oy2 as f64);
        let area = x1 * y2 - y1 * x2;
        let (d1, d2) = (d1 as f64, d2 as f64);
        // Offsets are in 2^-f pixels: gradients per pixel scale by 2^f.
        let per_pixel = shape.per_pixel as f64;
        let dx = (d1 * y2 - d2 * y1) / area * per_pixel;
        let dy = (d2 * x1 - d1 * x2) / area * per_pixel;
        let plane = Self { at_a: S::from_f32(va), dx: S::from_f32(dx as f32), dy: S::from_f32(dy as f32), lo, hi };
        (plane, (va, dx as f32, dy as f32))
    }

    /// Value at an offset from the top vertex, in units of `2^-f` pixels.
    #[inline(always)]
    fn at(&self, ox: i32, oy: i32, f: u32) -> S {
        S::plane_at(self.at_a, self.dx, self.dy, ox, oy, f)
    }

    /// Whether every pixel of the triangle gets a value within range when
    /// stepped: the plane is linear, so it suffices that its values at the
    /// three vertices are.
    #[inline(always)]
    fn safe(&self, shape: &Shape<S>, f: u32) -> bool {
        S::plane_within(self.at_a, self.dx, self.dy, (shape.ox1, shape.oy1), (shape.ox2, shape.oy2), f, self.lo, self.hi)
    }

    /// Start value and step of a span of `len` pixels whose first pixel
    /// center is at offset `(ox, oy)`: both ends clamped into range, the
    /// values in between interpolated (the careful path), from `wide` in
    /// `f64` where it is set up.
    #[inline(always)]
    fn clamped_span(&self, wide: Option<WidePlane>, ox: i32, oy: i32, len: i32, f: u32) -> (S, S) {
        let at = |ox: i32| match wide {
            Some((v, dx, dy)) => {
                let unit = 1.0 / (1u32 << f) as f64;
                S::from_f32((v as f64 + dx as f64 * (ox as f64 * unit) + dy as f64 * (oy as f64 * unit)) as f32)
                    .clamp_between(self.lo, self.hi)
            }
            None => S::plane_clamped(self.at_a, self.dx, self.dy, ox, oy, f, self.lo, self.hi),
        };
        let start = at(ox);
        if len < 2 {
            return (start, self.dx);
        }
        let end = at(ox + ((len - 1) << f));
        (start, end.sub(start).div_int(len - 1))
    }
}

/// A triangle's edge vectors from its top vertex, for plane setup.
struct Shape<S: Interp> {
    /// `b - a` and `c - a` in units of `2^-f` pixels.
    ox1: i32,
    oy1: i32,
    ox2: i32,
    oy2: i32,
    /// What turns value differences into gradients.
    basis: S::Basis,
    /// Whether an offset reaches 2^16 pixels: then gradients are computed
    /// in `f64` (see [`Plane::far`]).
    far: bool,
    /// Units per pixel, `2^f`.
    per_pixel: u32,
}

impl<S: Interp> Shape<S> {
    /// The shape of a sorted triangle relative to its top vertex `a`.
    #[inline(always)]
    fn new<const V: usize>(t: &Sorted<'_, V>, f: u32) -> Self {
        let (a, b, c) = (t.a, t.b, t.c);
        // Snapped coordinates are within ±2^29, so their differences fit i32.
        let (ox1, oy1, ox2, oy2) = (b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y);
        let far = !all_within([ox1, oy1, ox2, oy2], 16 + f);
        let basis = S::basis([ox1, oy1, ox2, oy2], t.area2, f);
        Shape { ox1, oy1, ox2, oy2, basis, far, per_pixel: 1 << f }
    }
}

/// The three vertices of a triangle sorted by y (`a` top, `b` middle, `c`
/// bottom) and the rows it covers.
struct Sorted<'v, const V: usize> {
    a: &'v ScreenVertex<V>,
    b: &'v ScreenVertex<V>,
    c: &'v ScreenVertex<V>,
    /// Twice the signed area (see [`signed_area2`]), nonzero.
    area2: i64,
    /// Whether the middle vertex is left of the long edge `a`–`c`.
    mid_left: bool,
    /// First rows at or below each vertex.
    y_top: i32,
    y_mid: i32,
    y_bot: i32,
}

impl<const V: usize> Sorted<'_, V> {
    /// The depth values at the vertices in `f32`, times `S`'s depth scale
    /// (see [`Interp::depth`]): for the `f64` setup of far planes.
    fn depths<S: Interp>(&self) -> (f32, f32, f32) {
        let depth = |v: &ScreenVertex<V>| <f32 as Interp>::depth(v.z) * S::DEPTH_SCALE;
        (depth(self.a), depth(self.b), depth(self.c))
    }
}

/// Orders a triangle's corners by `y`, top first, as [`rasterize`] walks
/// them. Equal `y`s keep their order.
#[inline(always)]
pub fn sort_by_y<T: Copy>(mut t: [T; 3], y: impl Fn(T) -> i32) -> [T; 3] {
    if y(t[0]) > y(t[1]) {
        t.swap(0, 1);
    }
    if y(t[1]) > y(t[2]) {
        t.swap(1, 2);
    }
    if y(t[0]) > y(t[1]) {
        t.swap(0, 1);
    }
    t
}

/// A triangle's corners sorted by `y`, top first, as [`rasterize`] takes
/// them.
#[derive(Clone, Copy)]
pub struct SortedCorners<'v, const V: usize>([&'v ScreenVertex<V>; 3]);

impl<'v, const V: usize> SortedCorners<'v, V> {
    /// `corners` in any order, sorted (equal `y`s keep their order).
    #[inline]
    pub fn new(corners: [&'v ScreenVertex<V>; 3]) -> Self {
        Self(sort_by_y(corners, |v| v.y))
    }

    /// Corners already sorted (the renderer sorts them once, when it
    /// queues the triangle).
    #[inline(always)]
    pub(crate) fn presorted(corners: [&'v ScreenVertex<V>; 3]) -> Self {
        Self(corners)
    }
}

/// Rasterizes one triangle into a strip with effect `E`, interpolation
/// `P` and depth mode `D`, stepping attributes in `S`.
///
/// `face` is the triangle's color (already converted) for effects that
/// use one. Degenerate triangles (zero snapped area) draw nothing.
///
/// The corners come sorted ([`SortedCorners`]): the renderer sorts them
/// once, when it queues the triangle, rather than at every strip the
/// triangle is drawn in (`torus.babylon` `f32` on the M4F 541,160
/// instructions against 553,960, `monkey` 986,720 against 1,002,640; on
/// the M0+ `torus.babylon` in fixed point 2,161,120 against 2,277,840).
///
/// Most triangles take the lean path here: vertex values converted to `S`
/// once, planes set up in `S` and stepped with additions. A triangle whose stepped
/// values could leave their ranges (a wrapping scalar's rounding, or a
/// triangle reaching toward the guard band) takes `rasterize_careful`.
///
/// Not inlined into the material's dispatched program, although that
/// would save a forwarding jump per triangle (0.5% of `torus.babylon`):
/// the flat span loop then took 18.3 instructions a pixel instead of
/// 17.3 (fixed point, M4F).
#[inline(never)]
pub fn rasterize<C, S, E, P, D, Z, const V: usize>(
    target: &mut StripTarget<'_, C, Z::Value>,
    effect: &E,
    uniforms: &E::Uniforms<S>,
    SortedCorners(tri): SortedCorners<'_, V>,
    face: C,
    subpixel_bits: u32,
) where
    C: Color,
    S: Interp,
    E: Effect,
    P: Perspective,
    D: DepthMode,
    Z: DepthFormat,
{
    let f = subpixel_bits + 1;
    // a top, b middle, c bottom.
    let [a, b, c] = tri;
    let area = signed_area2(a, b, c);
    if area == 0 {
        return;
    }
    let y_top = first_row_at_or_below(a.y, subpixel_bits);
    let y_bot = first_row_at_or_below(c.y, subpixel_bits);
    // (A triangle whose rows miss the strip's finds no span below.)
    // With y down, a negative area puts the middle vertex left of the long edge.
    let t = Sorted { a, b, c, area2: area, mid_left: area < 0, y_top, y_mid: first_row_at_or_below(b.y, subpixel_bits), y_bot };
    let width = target.width as i32;
    // Coverage first: a small triangle often covers no pixel center at all,
    // and then needs no planes.
    let mut rows = Rows::new(&t, target.y0, target.rows, width, f);
    let Some(mut span_at) = rows.next_span() else {
        return;
    };
    let shape = Shape::<S>::new(&t, f);
    let planes = Planes::<S, V>::new::<C, E, P>(&shape, &t, effect, false);
    // With a wrapping scalar, a plane whose rounded gradients leave its
    // range at a vertex takes the careful path (clamped span ends), and so
    // does a plane too steep to step, and a triangle whose unclamped
    // perspective division could stray (see `Interp::RELATIVE_DIVISION`); a
    // triangle reaching far toward the guard band is evaluated in f64 per
    // span whatever the scalar (see `Plane::far`).
    let careful = shape.far || planes.steep || (S::WRAPS && !planes.safe::<E, P, D>(&shape, f));
    if careful {
        // The planes are set up again there, with their `f32` copies where
        // they need them: not kept here, on the hot path, for the rare case.
        return rasterize_careful::<C, S, E, P, D, Z, V>(target, effect, uniforms, &t, face, f);
    }
    let n = E::VARYINGS.min(V);
    let Planes { z, q, vary, bounds, .. } = planes;

    // Stepping origin: the center of the triangle's first row at the
    // leftmost on-screen column of the bounding box. A span's start values
    // are the origin's plus whole steps right and down (exactly what
    // stepping gives). Rows count from the triangle's first row, not the
    // strip's, so `f32` rounding is the same whatever the strip height.
    let min_x = a.x.min(b.x).min(c.x);
    let x_base = (min_x >> f).max(0).min(width - 1);
    let (ox, oy) = ((x_base << f) + (1 << (f - 1)) - a.x, (y_top << f) + (1 << (f - 1)) - a.y);
    let z0 = z.at(ox, oy, f);
    let q0 = q.at(ox, oy, f);
    let mut v0 = [S::default(); MAX_VARYINGS];
    let mut v_dx = [S::default(); MAX_VARYINGS];
    let mut v_dy = [S::default(); MAX_VARYINGS];
    for i in 0..n {
        v0[i] = vary[i].at(ox, oy, f);
        v_dx[i] = vary[i].dx;
        v_dy[i] = vary[i].dy;
    }
    loop {
        let (y, x0, x1) = span_at;
        let (color, depths) = target.span(y, x0, x1);
        let (k, j) = (x0 - x_base, y - y_top);
        let mut vals = [S::default(); MAX_VARYINGS];
        for i in 0..n {
            vals[i] = v0[i].add_mul(v_dy[i], j).add_mul(v_dx[i], k);
        }
        let zs = z0.add_mul(z.dy, j).add_mul(z.dx, k);
        let qs = if P::CORRECT { q0.add_mul(q.dy, j).add_mul(q.dx, k) } else { q0 };
        span::<C, S, E, P, D, Z, false>(color, depths, effect, uniforms, zs, z.dx, vals, &v_dx, qs, q.dx, face, &bounds);
        match rows.next_span() {
            Some(next) => span_at = next,
            None => return,
        }
    }
}

/// [`rasterize`] for a triangle whose stepped values could leave their
/// ranges: each span's ends are evaluated exactly (in `f64` for wide
/// planes and far triangles), clamped into range, and interpolated
/// between. Rare, so kept out of line.
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn rasterize_careful<C, S, E, P, D, Z, const V: usize>(
    target: &mut StripTarget<'_, C, Z::Value>,
    effect: &E,
    uniforms: &E::Uniforms<S>,
    t: &Sorted<'_, V>,
    face: C,
    f: u32,
) where
    C: Color,
    S: Interp,
    E: Effect,
    P: Perspective,
    D: DepthMode,
    Z: DepthFormat,
{
    let n = E::VARYINGS.min(V);
    let shape = &Shape::<S>::new(t, f);
    let Planes { mut z, mut q, mut vary, bounds, .. } = Planes::<S, V>::new::<C, E, P>(shape, t, effect, true);
    // Planes too steep to step, and every plane of a triangle reaching
    // toward the guard band, are set up again in f64 (see `Plane::far`).
    let far = |p: &Plane<S>| shape.far || p.is_steep();
    let (mut wide_z, mut wide_q, mut wide) = (None, None, [None; V]);
    if far(&z) || (P::CORRECT && far(&q)) || vary[..n].iter().any(far) {
        let values = VertexValues::<V>::new::<C, E, P, S>(t, effect, true);
        if far(&z) {
            (z, wide_z) = wide_plane(shape, t.depths::<S>(), (z.lo, z.hi));
        }
        if P::CORRECT && far(&q) {
            (q, wide_q) = wide_plane(shape, values.q, (q.lo, q.hi));
        }
        for (i, p) in vary.iter_mut().enumerate().take(n) {
            if far(p) {
                // (A steep plane keeps its range; those of a far triangle
                // are the varyings' own.)
                let range = if shape.far { range_in(values.ranges[i]) } else { (p.lo, p.hi) };
                (*p, wide[i]) = wide_plane(shape, values.vary[i], range);
            }
        }
    }
    let a = t.a;
    let mut rows = Rows::new(t, target.y0, target.rows, target.width as i32, f);
    while let Some((y, x0, x1)) = rows.next_span() {
        let (color, depths) = target.span(y, x0, x1);
        let (px, py) = ((x0 << f) + (1 << (f - 1)) - a.x, (y << f) + (1 << (f - 1)) - a.y);
        let len = x1 - x0;
        let (zs, zd) = z.clamped_span(wide_z, px, py, len, f);
        let (qs, qd) = q.clamped_span(wide_q, px, py, len, f);
        let mut vals = [S::default(); MAX_VARYINGS];
        let mut steps = [S::default(); MAX_VARYINGS];
        for i in 0..n {
            (vals[i], steps[i]) = vary[i].clamped_span(wide[i], px, py, len, f);
        }
        span::<C, S, E, P, D, Z, true>(color, depths, effect, uniforms, zs, zd, vals, &steps, qs, qd, face, &bounds);
    }
}

/// [`Plane::far`], with its `f32` plane as the careful path keeps it.
fn wide_plane<S: Interp>(shape: &Shape<S>, values: (f32, f32, f32), range: (S, S)) -> (Plane<S>, Option<WidePlane>) {
    let (plane, wide) = Plane::far(shape, values, range);
    (plane, Some(wide))
}

/// A sorted triangle's rows within a strip, yielding each non-empty span of
/// pixels `x0..x1` (clipped to the strip's width) as `(y, x0, x1)`.
///
/// Each row's bounds are the exact `ceil` of [`edge_start`]. Where there
/// is a divide instruction they are computed row by row, two divisions a
/// row: the triangles of a mesh on a small screen cover a row or two
/// each, and setting up two [`EdgeWalker`]s (two divisions each, and a
/// third for the middle vertex) cost more than that. ARMv6-M divides by
/// steps and walks the edges (dividing per row measured `monkey` 3.5%
/// slower there).
struct Rows<'t, const V: usize> {
    t: &'t Sorted<'t, V>,
    long: EdgeWalker,
    short: EdgeWalker,
    y: i32,
    y_end: i32,
    /// The row where the short side turns the corner at the middle vertex
    /// (`i32::MIN` if the walk starts below it).
    y_switch: i32,
    width: i32,
    f: u32,
}

/// Whether [`Rows`] walks edges rather than dividing per row.
const WALK_EDGES: bool = cfg!(soft3d_armv6m);

impl<'t, const V: usize> Rows<'t, V> {
    #[inline(always)]
    fn new(t: &'t Sorted<'t, V>, y0: i32, rows: i32, width: i32, f: u32) -> Self {
        let (a, b, c) = (t.a, t.b, t.c);
        let y = t.y_top.max(y0);
        let y_end = t.y_bot.min(y0 + rows);
        let (long, short) = if WALK_EDGES {
            let long = EdgeWalker::new(a.x, a.y, c.x, c.y, y, y_end, f);
            let short = if y < t.y_mid {
                EdgeWalker::new(a.x, a.y, b.x, b.y, y, t.y_mid.min(y_end), f)
            } else {
                EdgeWalker::new(b.x, b.y, c.x, c.y, y, y_end, f)
            };
            (long, short)
        } else {
            (EdgeWalker::IDLE, EdgeWalker::IDLE)
        };
        let y_switch = if y < t.y_mid { t.y_mid } else { i32::MIN };
        Self { t, long, short, y, y_end, y_switch, width, f }
    }

    /// The next non-empty span.
    #[inline(always)]
    fn next_span(&mut self) -> Option<(i32, i32, i32)> {
        while self.y < self.y_end {
            let y = self.y;
            let (long, short) = if WALK_EDGES {
                if y == self.y_switch {
                    // Below the middle vertex the short side is its lower edge.
                    let (b, c) = (self.t.b, self.t.c);
                    self.short = EdgeWalker::new(b.x, b.y, c.x, c.y, y, self.y_end, self.f);
                }
                let bounds = (self.long.bound, self.short.bound);
                self.long.step();
                self.short.step();
                bounds
            } else {
                let (a, b, c) = (self.t.a, self.t.b, self.t.c);
                let (top, bottom) = if y < self.t.y_mid { (a, b) } else { (b, c) };
                (bound_at(a, c, y, self.f), bound_at(top, bottom, y, self.f))
            };
            let (left, right) = if self.t.mid_left { (short, long) } else { (long, short) };
            // Each bound clamped on its own side only: a span off either
            // side of the strip is then empty as it is.
            let x0 = left.max(0);
            let x1 = right.min(self.width);
            self.y += 1;
            if x0 < x1 {
                return Some((y, x0, x1));
            }
        }
        None
    }
}

/// The bound at pixel row `row` of the edge from `a` down to `b` (whose
/// row centers it spans): what an [`EdgeWalker`] gives there.
///
/// The edge's differences are taken again each row: set up once per
/// triangle visit (the three edges in `Rows`), they took `torus.babylon`
/// in `f32` on the M4F from 620,960 instructions to 637,920 and
/// `wall-flat` in fixed point from 1,369,760 to 1,450,880 (most visits
/// use two edges for a row or two; the third and the stored values cost
/// more than the subtractions).
#[inline(always)]
fn bound_at<const V: usize>(a: &ScreenVertex<V>, b: &ScreenVertex<V>, row: i32, f: u32) -> i32 {
    let half = 1i32 << (f - 1);
    let (from, dx, dy, t) = (a.x - half, b.x - a.x, b.y - a.y, (row << f) + half - a.y);
    let m = mul_wide(from, dy) + mul_wide(dx, t);
    match narrow(m) {
        Some(m) => div_ceil_rem(m as i64, dy << f).0,
        None => wide_bound(from, dx, dy, t, f),
    }
}

/// [`bound_at`] for an edge too long for its 32-bit numerator: the whole
/// pixels of `from` are taken out first, and what is left fits 32 bits
/// for any triangle on screen (a 64-bit division is a library call).
#[cold]
#[inline(never)]
fn wide_bound(from: i32, dx: i32, dy: i32, t: i32, f: u32) -> i32 {
    edge_start(from, dx, dy, t, f, true).0
}

impl<C, Z> StripTarget<'_, C, Z> {
    /// The colors and depths of pixels `x0..x1` of frame row `y` (within
    /// the strip), marked dirty.
    #[inline(always)]
    fn span(&mut self, y: i32, x0: i32, x1: i32) -> (&mut [C], &mut [Z]) {
        let row = (y - self.y0) as usize * self.width;
        let (s0, s1) = (row + x0 as usize, row + x1 as usize);
        self.dirty = (self.dirty.0.min(x0 as usize), self.dirty.1.max(x1 as usize));
        (&mut self.color[s0..s1], &mut self.depth[s0..s1])
    }
}

/// A triangle's values at its three sorted vertices, as planes are set up
/// from them, with the ranges they must stay in.
struct VertexValues<const V: usize> {
    z_range: (f32, f32),
    /// Normalized `1 / w` times [`Interp::Q_SCALE`] (`(1, 1, 1)` without
    /// perspective correction).
    q: (f32, f32, f32),
    q_range: (f32, f32),
    /// Varyings, times `q` when perspective-correct (less their lower
    /// bound with [`Interp::RELATIVE_DIVISION`]).
    vary: [(f32, f32, f32); V],
    ranges: [(f32, f32); MAX_VARYINGS],
    /// The range `(lo, hi)` of each varying's vertex values (within its
    /// own range), for the perspective division: it clamps to it where it
    /// clamps, and a relative division adds `lo` back (the only bound set
    /// where it does not clamp).
    bounds: [(f32, f32); V],
}

/// Perspective-correct values whose `1 / w` (`q`) varies across a triangle
/// by more than this ratio take the careful path with a relative division
/// (see [`Interp::RELATIVE_DIVISION`]). The division multiplies the
/// rounding of the interpolated values by up to the ratio. Measured with
/// no careful path at all: property 3 of `tests/properties.rs` (`w` from
/// 1/16 to 16 per vertex, ratios up to 256) kept every channel within its
/// vertices' range over 300,000 triangles; with `w` from 2^-12 to 2^12 a
/// channel strayed to the end of its range (in three runs, after 71, 7,543
/// and 10,522 triangles).
pub const MAX_Q_RATIO: f32 = 16.0;

impl<const V: usize> VertexValues<V> {
    /// With `clamp`, the upper bounds are set up even where the lean path
    /// does not clamp (for the careful path).
    #[inline(always)]
    fn new<C: Color, E: Effect, P: Perspective, S: Interp>(t: &Sorted<'_, V>, effect: &E, clamp: bool) -> Self {
        let (a, b, c) = (t.a, t.b, t.c);
        // Depth in stored units, times the scalar's depth scale.
        // Perspective-correct varyings are interpolated as value * q', with
        // q' = q / max(q) in (0, 1] (normalized so fixed point keeps precision).
        let q = if P::CORRECT {
            // Compares, not `f32::max` (a library call on the M4F); without
            // an FPU, on the bits (`greater`), and the products too (`mul`).
            let qmax = if greater(b.q, a.q) { b.q } else { a.q };
            let qmax = if greater(c.q, qmax) { c.q } else { qmax };
            let k = if greater(qmax, 0.0) { 1.0 / qmax } else { 1.0 };
            (mul(a.q, k), mul(b.q, k), mul(c.q, k))
        } else {
            (1.0, 1.0, 1.0)
        };
        // The q plane itself is kept times `Q_SCALE` (see there).
        let scale = if P::CORRECT { S::Q_SCALE } else { 1.0 };
        let relative = P::CORRECT && S::RELATIVE_DIVISION;
        let ranges = E::ranges::<C>();
        let periods = effect.periods();
        let mut vary = [(0.0, 0.0, 0.0); V];
        let mut bounds = [(0.0, 0.0); V];
        // Compares, not `f32::min`: a library call without an FPU min
        // instruction (Cortex-M4F).
        let (min, max) = (|a: f32, b: f32| if less(b, a) { b } else { a }, |a: f32, b: f32| if greater(b, a) { b } else { a });
        for i in 0..E::VARYINGS.min(V) {
            let (mut va, mut vb, mut vc) = (a.attrs[i], b.attrs[i], c.attrs[i]);
            let periodic = greater(periods[i], 0.0);
            // The least vertex value: a periodic value's period, and a
            // perspective division's lower bound.
            let mut least = if periodic || P::CORRECT { min(min(va, vb), vc) } else { 0.0 };
            // Periodic values (texture coordinates) are shifted by whole
            // periods to start near zero, so large coordinates keep their
            // precision.
            if periodic {
                // Most triangles start in the first period: without an FPU
                // the shift by none (a zero, tested on its bits) is skipped.
                let whole = floor(least / periods[i]);
                if crate::math::HARD_FLOAT || whole.to_bits() << 1 != 0 {
                    let shift = whole * periods[i];
                    (va, vb, vc, least) = (va - shift, vb - shift, vc - shift, least - shift);
                }
            }
            if P::CORRECT && (clamp || !relative) {
                // Rounding of the two planes must not push a constant
                // channel off its value.
                let lo = max(least, ranges[i].0);
                let hi = max(min(max(max(va, vb), vc), ranges[i].1), lo);
                bounds[i] = (lo, hi);
            } else if relative {
                bounds[i].0 = least;
            }
            // (`q` is 1 without perspective correction.)
            vary[i] = if relative {
                // A constant varying's differences are zero: it is exactly
                // `lo` after the division.
                let lo = bounds[i].0;
                (mul(va - lo, q.0), mul(vb - lo, q.1), mul(vc - lo, q.2))
            } else if P::CORRECT {
                (mul(va, q.0), mul(vb, q.1), mul(vc, q.2))
            } else {
                (va, vb, vc)
            };
        }
        Self {
            z_range: (1.0 * S::DEPTH_SCALE, (DEPTH_RANGE + 1.999) * S::DEPTH_SCALE),
            q: if P::CORRECT { (mul(q.0, scale), mul(q.1, scale), mul(q.2, scale)) } else { q },
            // Normalized q is at most 1 at the vertices; the margin above
            // lets its rounded plane overshoot there (it only needs to
            // stay positive).
            q_range: (scale / 65536.0, 2.0 * scale),
            vary,
            ranges,
            bounds,
        }
    }
}

/// A range `(lo, hi)` in the stepping scalar.
#[inline(always)]
fn range_in<S: Interp>((lo, hi): (f32, f32)) -> (S, S) {
    (S::from_f32(lo), S::from_f32(hi))
}

/// Range `i` of an effect's `ranges` in the stepping scalar. The ranges
/// are the effect's constants, and by a match on `i` the first three
/// arms (a color's channels) each convert a constant, which folds away:
/// indexed by `i`, every plane of every triangle converted its range (in
/// software on an M0+, 5% of `torus.babylon` in fixed point).
#[inline(always)]
fn range_at<S: Interp>(ranges: &[(f32, f32); MAX_VARYINGS], i: usize) -> (S, S) {
    match i {
        0 => range_in(ranges[0]),
        1 => range_in(ranges[1]),
        2 => range_in(ranges[2]),
        _ => range_in(ranges[i]),
    }
}

/// A triangle's planes in the stepping scalar.
struct Planes<S, const V: usize> {
    z: Plane<S>,
    q: Plane<S>,
    vary: [Plane<S>; V],
    /// Per varying, the bounds of its perspective division (see
    /// [`VertexValues::bounds`]).
    bounds: [(S, S); MAX_VARYINGS],
    /// Whether a plane's gradients are too steep to step (see
    /// [`Interp::is_wide`]), or `q` varies over the triangle by more than
    /// [`MAX_Q_RATIO`] to one (only tested where
    /// [`Interp::RELATIVE_DIVISION`] holds): then the careful path draws it.
    steep: bool,
    /// Whether the vertex values alone show every plane in range (see
    /// [`Interp::clear_of_bounds`]); if not, [`Planes::safe`] decides.
    clear: bool,
}

impl<S: Interp, const V: usize> Planes<S, V> {
    #[inline(always)]
    fn new<C: Color, E: Effect, P: Perspective>(shape: &Shape<S>, t: &Sorted<'_, V>, effect: &E, clamp: bool) -> Self {
        let values = VertexValues::<V>::new::<C, E, P, S>(t, effect, clamp);
        // `q` is normalized to at most `Q_SCALE`, so its ratio shows in its
        // least.
        let least_q = S::Q_SCALE / MAX_Q_RATIO;
        let (qa, qb, qc) = values.q;
        let mut steep = P::CORRECT && S::RELATIVE_DIVISION && (less(qa, least_q) || less(qb, least_q) || less(qc, least_q));
        // Depth from window z in the scalar itself (integers only in fixed
        // point), not through f32.
        let (a, b, c) = (S::depth(t.a.z), S::depth(t.b.z), S::depth(t.c.z));
        let mut clear = true;
        let z = Plane::new(shape, (a, b, c), range_in(values.z_range), &mut clear, &mut steep);
        let q = if P::CORRECT {
            Plane::from_f32(shape, values.q, range_in(values.q_range), &mut clear, &mut steep)
        } else {
            let (one, zero) = (S::from_f32(1.0), S::default());
            Plane { at_a: one, dx: zero, dy: zero, lo: one, hi: one }
        };
        let mut vary = [q; V];
        let mut bounds = [(S::default(), S::default()); MAX_VARYINGS];
        for i in 0..E::VARYINGS.min(V) {
            // (With perspective, converting them by a match measured slower:
            // monkey-tex fixed on the M0+ +1.4%.)
            let range = if P::CORRECT && S::RELATIVE_DIVISION {
                // A difference of two values in the range, times q <= 1.
                let (lo, hi) = values.ranges[i];
                range_in((lo - hi, hi - lo))
            } else if P::CORRECT {
                range_in(values.ranges[i])
            } else {
                range_at(&values.ranges, i)
            };
            vary[i] = Plane::from_f32(shape, values.vary[i], range, &mut clear, &mut steep);
            if P::CORRECT {
                // (A relative division without a clamp uses `lo` alone.)
                let hi = if clamp || !S::RELATIVE_DIVISION { S::from_f32(values.bounds[i].1) } else { S::default() };
                bounds[i] = (S::from_f32(values.bounds[i].0), hi);
            }
        }
        Self { z, q, vary, bounds, steep, clear }
    }

    /// Whether every plane the material uses stays within its range at
    /// every pixel when stepped.
    #[inline(always)]
    fn safe<E: Effect, P: Perspective, D: DepthMode>(&self, shape: &Shape<S>, f: u32) -> bool {
        if self.clear {
            return true;
        }
        // Early returns: each plane's evaluations are done when tested, not
        // all first and kept (spilled) for a combined test.
        if (D::TEST || D::WRITE) && !self.z.safe(shape, f) {
            return false;
        }
        if P::CORRECT && !self.q.safe(shape, f) {
            return false;
        }
        for p in &self.vary[..E::VARYINGS.min(V)] {
            if !p.safe(shape, f) {
                return false;
            }
        }
        true
    }
}

/// Keeps LLVM from unrolling a span loop on Arm. For M-class cores it
/// unrolls small loops 4 times by default, which gives every interpolated
/// value four copies, more than the 13 registers hold: the spills cost more
/// than the loop overhead saved. `black_box` is an empty inline `asm!` to
/// LLVM, which counts as a call, and its Arm unroller leaves loops with
/// calls alone; it emits no instruction.
#[inline(always)]
pub(crate) fn no_unroll() {
    #[cfg(target_arch = "arm")]
    core::hint::black_box(());
}

/// `v`, as a value the compiler cannot trace back to where it came from
/// (`black_box`: on Arm it emits no instruction, but `v` passes through
/// the stack once). A span loop's steps so obtained start new live ranges
/// at the span: LLVM's register allocator then gives them registers in
/// the pixel loop rather than to values of the row loop around it
/// (M4F, fixed point: `wall-gouraud` 27.1 instructions a pixel against
/// 31.0 without, `fill` 2,063,080 instructions against 2,358,760; on
/// ARMv6-M it measured slower: `torus.babylon` 2,177,400 against
/// 2,161,120).
#[inline(always)]
fn opaque<T>(v: T) -> T {
    core::hint::black_box(v)
}

/// `floor` for any finite `f32` (values from 2^23 up are integers).
#[inline]
fn floor(v: f32) -> f32 {
    if less(v.abs(), 8_388_608.0) {
        floor_f32(v)
    } else {
        v
    }
}

/// Varyings divided by the interpolated `q` (see
/// [`Interp::RELATIVE_DIVISION`]): relative ones plus their lower bound,
/// clamped to their bounds if `CLAMP`; the others always clamped. A
/// function, not a closure, so that it is inlined into the span loop.
#[inline(always)]
fn divide<S: Interp, E: Effect, const CLAMP: bool>(v: &[S; MAX_VARYINGS], q: S, bounds: &[(S, S); MAX_VARYINGS]) -> [S; MAX_VARYINGS] {
    let w = q.q_recip();
    let mut out = *v;
    for i in 0..E::VARYINGS {
        let (lo, hi) = bounds[i];
        out[i] = if !S::RELATIVE_DIVISION {
            v[i].mul_clamped(w, lo, hi)
        } else if CLAMP {
            lo.add(v[i].mul(w)).clamp_between(lo, hi)
        } else {
            lo.add(v[i].mul(w))
        };
    }
    out
}

/// The inner loop: one row of one triangle. No branch depends on a feature
/// at run time; `P` and `D` are constants here, and every value is known
/// to be in range, so nothing is clamped per pixel (except after a
/// perspective division, whose rounding the planes cannot bound: see
/// `divide`, and `CLAMP` on the careful path).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn span<C, S, E, P, D, Z, const CLAMP: bool>(
    color: &mut [C],
    depth: &mut [Z::Value],
    effect: &E,
    uniforms: &E::Uniforms<S>,
    mut z: S,
    z_dx: S,
    mut vals: [S; MAX_VARYINGS],
    v_dx: &[S; MAX_VARYINGS],
    mut q: S,
    q_dx: S,
    face: C,
    bounds: &[(S, S); MAX_VARYINGS],
) where
    C: Color,
    S: Interp,
    E: Effect,
    P: Perspective,
    D: DepthMode,
    Z: DepthFormat,
{
    // (Per span, not per triangle: at the top of `rasterize` the test did
    // not reach the pixel loop, and `wall-tex` fixed M4F took 7% more.)
    if !effect.samples() {
        return;
    }
    if P::CORRECT && P::SPAN > 1 {
        // Exact at the start of every segment of SPAN pixels (and at the
        // span's end), linear in between.
        let mut cur = divide::<S, E, CLAMP>(&vals, q, bounds);
        let len = color.len();
        let mut start = 0;
        while start < len {
            let seg = (len - start).min(P::SPAN as usize);
            // The last segment ends at the span's last pixel: one pixel
            // further is outside the triangle, where 1/w may be near zero.
            let reach = if start + seg == len { seg - 1 } else { seg } as i32;
            let q_end = q.add_mul(q_dx, reach);
            let mut v_end = vals;
            for i in 0..E::VARYINGS {
                v_end[i] = vals[i].add_mul(v_dx[i], reach);
            }
            let end = divide::<S, E, CLAMP>(&v_end, q_end, bounds);
            let mut step = [S::default(); MAX_VARYINGS];
            // A whole segment divides by SPAN, a power of two: on ARMv6-M a
            // shift instead of a library division. (With a divide
            // instruction the second loop cost the M4F's span loop
            // registers: wall-tex32 fixed +7%.)
            if cfg!(soft3d_armv6m) && reach == P::SPAN as i32 {
                for i in 0..E::VARYINGS {
                    step[i] = end[i].sub(cur[i]).div_pow2(P::SPAN.trailing_zeros());
                }
            } else if reach > 0 {
                for i in 0..E::VARYINGS {
                    step[i] = end[i].sub(cur[i]).div_int(reach);
                }
            }
            let pixels = color[start..start + seg].iter_mut().zip(depth[start..start + seg].iter_mut());
            for (px, zb) in pixels {
                no_unroll();
                if !D::TEST || Z::nearer(z, *zb) {
                    if D::WRITE {
                        *zb = Z::store(z);
                    }
                    *px = effect.shade(uniforms, face, &cur, *px);
                }
                z = z.add(z_dx);
                for i in 0..E::VARYINGS {
                    cur[i] = cur[i].add(step[i]);
                }
            }
            (vals, q, cur) = (v_end, q_end, end);
            start += seg;
        }
        return;
    }
    // In fixed point, where there are shifted operands (not ARMv6-M), the
    // steps are taken as new values at each span: its pixel loop then
    // keeps them in registers instead of reloading them at every pixel
    // (see `opaque`).
    let (z_dx, v_dx) = if S::WRAPS && !cfg!(soft3d_armv6m) { opaque((z_dx, *v_dx)) } else { (z_dx, *v_dx) };
    for (px, zb) in color.iter_mut().zip(depth.iter_mut()) {
        no_unroll();
        if !D::TEST || Z::nearer(z, *zb) {
            if D::WRITE {
                *zb = Z::store(z);
            }
            *px = if P::CORRECT {
                effect.shade(uniforms, face, &divide::<S, E, CLAMP>(&vals, q, bounds), *px)
            } else {
                effect.shade(uniforms, face, &vals, *px)
            };
        }
        if D::TEST || D::WRITE {
            z = z.add(z_dx);
        }
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
    fn a_row_center_splits_the_rows_at_and_below() {
        for bits in 0..=8 {
            let unit = 1 << (bits + 1);
            for row in [-3, 0, 1, 15, 16, 239, 240] {
                let center = row_center(row, bits);
                // Every snapped y within two rows of the center.
                for y in (center - 2 * unit..=center + 2 * unit).filter(|y| y % 2 == 0) {
                    assert_eq!(y > center, first_row_at_or_below(y, bits) > row, "bits {bits}, row {row}, y {y}");
                }
            }
        }
    }

    #[test]
    fn corners_sort_by_y_keeping_ties_in_order() {
        // Every order of three values with and without ties.
        for ys in [[0, 1, 2], [0, 0, 1], [0, 1, 1], [5, 5, 5]] {
            for p in [[0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]] {
                let corners = p.map(|i| (ys[i], i));
                let sorted = sort_by_y(corners, |(y, _)| y);
                assert_eq!(sorted.map(|(y, _)| y), ys, "{corners:?}");
                // Equal ys keep the order they came in.
                for k in 0..2 {
                    if sorted[k].0 == sorted[k + 1].0 {
                        let at = |c: (i32, usize)| corners.iter().position(|&x| x == c);
                        assert!(at(sorted[k]) < at(sorted[k + 1]), "{corners:?} -> {sorted:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn snapping_rounds_to_the_grid_and_rejects_the_far() {
        assert_eq!(snap(1.0, 4), Some(32));
        assert_eq!(snap(1.03125, 4), Some(34)); // 1 + 1/32 rounds up to 1 + 1/16
        assert_eq!(snap(-0.5, 0), Some(0)); // half rounds up
        assert_eq!(snap(f32::NAN, 4), None);
        assert_eq!(snap(1e9, 4), None);
        assert_eq!(snap_f64(123456.0625, 4), Some(123456 * 32 + 2));
        assert_eq!(snap_f64(600_000.0, 4), None); // beyond the guard band at 4 bits
        assert_eq!(snap_f64(-2.5, 0), Some(-4));
        assert_eq!(snap_f64(f64::INFINITY, 4), None);
        assert_eq!(snap_f64(f64::NAN, 4), None);
        // Just below a half rounds down, however close (a rounded
        // `s + 0.5` would give 1), and a half rounds up, also negative.
        assert_eq!(snap_f64(0.49999999999999994, 0), Some(0));
        assert_eq!(snap(0.49999997, 0), Some(0));
        assert_eq!(snap_f64(0.5, 0), Some(2));
        assert_eq!(snap_f64(-0.5, 0), Some(0));
        assert_eq!(snap_f64(-0.5000000000000001, 0), Some(-2));
    }

    #[test]
    fn snapping_in_f32_gives_what_f64_gives() {
        // Around the band's ends, half-units, 2^22 and 2^23 (where f32
        // steps are a half and one unit), and random bit patterns, for
        // every sub-pixel setting (both of `snap`'s paths).
        let mut next = crate::math::xorshift(0x5EED_0F32);
        for bits in 0..=8 {
            let unit = (1u32 << bits) as f32;
            let limit = (guard(bits) >> 1) as f32;
            let mut values = std::vec![f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 0.0, -0.0, f32::MAX, f32::MIN_POSITIVE];
            for edge in [limit, 4_194_304.0, 8_388_608.0, 0.5, 1.5] {
                for sign in [1.0f32, -1.0] {
                    let s = sign * edge;
                    for k in -8..=8 {
                        // Scaled values a few f32 steps and half-units around the edge.
                        let nudged = f32::from_bits((s.to_bits() as i32 + k) as u32);
                        values.extend([nudged / unit, (s + k as f32 * 0.25) / unit, (s + 0.5) / unit, (s - 0.5) / unit]);
                    }
                }
            }
            for _ in 0..20_000 {
                let v = f32::from_bits(next());
                // Mostly magnitudes near the band, some of every size.
                let v = if v.is_finite() && next() % 4 != 0 { v % (limit * 2.0 / unit) } else { v };
                values.push(v);
            }
            for v in values {
                assert_eq!(snap(v, bits), snap_f64(v as f64, bits), "{v} at {bits} sub-pixel bits");
            }
        }
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
            let mut w = EdgeWalker::new(ax, ay, bx, by, start, start + 40, f);
            // A walker for one row skips its steps, and has the same bound.
            let one = EdgeWalker::new(ax, ay, bx, by, start, start + 1, f);
            assert_eq!((one.bound, one.err, one.step_q, one.step_r), (w.bound, w.err, 0, 0));
            for row in start..start + 40 {
                let yc = ((row as i64) << f) + half;
                let m = (ax as i64 - half) * (by - ay) as i64 + (bx - ax) as i64 * (yc - ay as i64);
                let d = ((by - ay) as i64) << f;
                let expect = (m as f64 / d as f64).ceil() as i64;
                assert_eq!(w.bound as i64, expect, "edge {ax},{ay}->{bx},{by} row {row}");
                w.step();
            }
        }
        // A level or rising edge (never walked) is no fault either.
        for (ay, by) in [(5, 5), (9, 2)] {
            let mut w = EdgeWalker::new(3, ay, 40, by, 0, 2, f);
            w.step();
        }
    }

    #[test]
    fn rows_divided_give_what_walkers_give() {
        // Edges from a pixel long to the guard band's reach (whose
        // numerators leave 32 bits: `wide_bound`), at the default
        // sub-pixel bits, each walked over its first rows and a later run.
        let (bits, f) = (6, 7);
        let mut next = crate::math::xorshift(0x1F83_D9AB);
        let vertex = |x: i32, y: i32| ScreenVertex::<0> { x, y, z: 0, q: 1.0, attrs: [] };
        let half = 1i64 << (f - 1);
        let mut wide = 0;
        let limit = guard(bits);
        for case in 0..20_000u32 {
            let reach = 1i32 << (8 + case % 15);
            let mut coordinate = || (next() % (2 * reach as u32)) as i32 - reach;
            let (ax, ay, bx) = (coordinate(), coordinate(), coordinate());
            let by = (ay + 1 + (next() % reach as u32) as i32).min(limit);
            let (a, b) = (vertex(ax, ay), vertex(bx, by));
            let (first, end) = (first_row_at_or_below(ay, bits), first_row_at_or_below(by, bits));
            for start in [first, first + (end - first) / 2] {
                let mut walker = EdgeWalker::new(ax, ay, bx, by, start, end.min(start + 8), f);
                for row in start..end.min(start + 8) {
                    assert_eq!(bound_at(&a, &b, row, f), walker.bound, "{ax},{ay} -> {bx},{by} row {row}");
                    walker.step();
                    let m = (ax as i64 - half) * (by - ay) as i64 + (bx - ax) as i64 * (((row as i64) << f) + half - ay as i64);
                    wide += i32::try_from(m).is_err() as u32;
                }
            }
        }
        assert!(wide > 10_000, "only {wide} rows took the wide path");
    }

    #[test]
    fn narrowing_keeps_exactly_the_values_that_fit() {
        let mut next = crate::math::xorshift(0x51A7_0C3D);
        let edges =
            [i32::MIN as i64 - 1, i32::MIN as i64, -1, 0, 1, i32::MAX as i64, i32::MAX as i64 + 1, 1 << 32, -(1 << 32), i64::MIN, i64::MAX];
        let random = (0..100_000).map(|_| (((next() as u64) << 32 | next() as u64) as i64) >> (next() % 64));
        for m in edges.into_iter().chain(random) {
            assert_eq!(narrow(m), i32::try_from(m).ok(), "{m}");
        }
    }

    #[test]
    fn areas_short_or_wide_are_exact() {
        // Offsets around the short products' limit and up to the guard
        // band, against i128.
        let mut next = crate::math::xorshift(0x2545_F491);
        for case in 0..200_000u32 {
            let reach = 1u32 << (1 + case % 29);
            let mut offset = || (next() % (2 * reach)) as i32 - reach as i32;
            let (bx, by, cx, cy) = (offset(), offset(), offset(), offset());
            let want = bx as i128 * cy as i128 - by as i128 * cx as i128;
            for short in [false, true] {
                assert_eq!(cross(bx, by, cx, cy, short) as i128, want, "{bx} {by} {cx} {cy} short {short}");
            }
        }
        // The largest difference of short products: 2^31 - 2^15.
        let (lo, hi) = (-(1 << 15), (1 << 15) - 1);
        assert_eq!(cross(lo, lo, hi, lo, true), (1i64 << 31) - (1 << 15));
        assert_eq!(cross(lo, lo, lo, hi, true), -(1i64 << 31) + (1 << 15));
    }

    #[test]
    fn edge_starts_split_or_not_are_exact() {
        // Both formulations (ARMv6-M's and the others'), against the
        // definition in i128, for edges from tiny to the guard band.
        let mut next = crate::math::xorshift(0x3C6E_F372);
        for case in 0..200_000 {
            let f = 1 + case % 9;
            let limit = guard(f - 1) as u32;
            let mut coordinate = || (next() % ((2 * limit) >> (next() % 24)).max(1)) as i32 - (limit >> (next() % 24)) as i32;
            let (ax, ay, bx) = (coordinate(), coordinate(), coordinate());
            let by = (ay + 1 + (next() % (limit >> (next() % 28)).max(1)) as i32).min(limit as i32);
            if by <= ay {
                continue;
            }
            let (dx, dy) = (bx - ax, by - ay);
            let t = (next() % dy as u32) as i32;
            let from = ax - (1 << (f - 1));
            let (m, d) = (from as i128 * dy as i128 + dx as i128 * t as i128, (dy as i128) << f);
            let bound = m.div_euclid(d) + (m.rem_euclid(d) != 0) as i128;
            let want = (bound as i32, (bound * d - m) as i32);
            for split in [false, true] {
                assert_eq!(edge_start(from, dx, dy, t, f, split), want, "from {from} dx {dx} dy {dy} t {t} f {f} split {split}");
            }
        }
    }
}
