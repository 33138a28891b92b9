//! The scalar that attribute interpolation runs in: `f32` or [`Fixed`].
//!
//! The rasterizer is written once, generic over this trait; each
//! implementation is a compile-time choice with its own cost and accuracy.
//!
//! A plane equation is kept as its value at the triangle's first vertex
//! and its two gradients (per pixel). Everything else (the value at the
//! first pixel of a strip, the check that no pixel can leave its range) is
//! derived from those three numbers with [`Interp::plane_at`] and
//! [`Interp::plane_within`], so stepping and checking agree exactly.

use super::{dot_wide, high_word_of_shifted_product, mul_wide, reciprocal_q61, shl_wide, shr_wide, Fixed};

/// A number type that plane equations are stepped in.
///
/// All operations are total: they saturate or wrap, never panic.
pub trait Interp: Copy + Default + PartialEq + PartialOrd + core::fmt::Debug + 'static {
    /// A short name for reports ("f32", "fixed16").
    const NAME: &'static str;
    /// Depth values are interpolated as `depth * DEPTH_SCALE`, where
    /// `depth` is in stored 16-bit units (`0..=65535`).
    const DEPTH_SCALE: f32;
    /// Normalized `1 / w` (in `(0, 2]`) is interpolated as `q * Q_SCALE`:
    /// fixed point gives it 13 more fractional bits, or the rounding of its
    /// gradient (2^-17 per pixel), stepped over hundreds of pixels and
    /// divided by `q`, moves the texture coordinates of a large triangle by
    /// texels. See [`Interp::q_recip`].
    const Q_SCALE: f32;
    /// Whether stepping can wrap around, so that a triangle's planes must
    /// be checked against their ranges ([`Interp::plane_within`]). `f32`
    /// saturates when converted instead.
    const WRAPS: bool;
    /// Whether a span loop masks each [`Interp::channel`] to its bits when
    /// it builds a pixel ([`Color::from_channels`] rather than
    /// [`Color::from_channels_in_range`]). Fixed point takes a channel's
    /// bits with a shift, and with the masks LLVM packs RGB565 in the
    /// fewest registers (without: `wall-gouraud` on the M4F 1,898,000
    /// instructions against 2,438,000). `f32` converts, and a mask is then
    /// one more instruction a channel (with: `wall-gouraud` 2,401,200
    /// against 2,247,600).
    ///
    /// [`Color::from_channels`]: crate::effect::Color::from_channels
    /// [`Color::from_channels_in_range`]: crate::effect::Color::from_channels_in_range
    const FREE_CHANNEL_MASK: bool;
    /// How perspective-correct varyings are divided. `true` (`f32`): each
    /// is interpolated relative to its least value at the triangle's
    /// vertices, as `(v - lo) * q`, and `lo` is added back after the
    /// division. A constant varying then stays exact, and rounding moves a
    /// value by a fraction of its spread across the triangle, not of its
    /// size, so the span loop divides without clamping; a triangle whose
    /// `q` varies more than [`MAX_Q_RATIO`](crate::raster::MAX_Q_RATIO) to
    /// one, where the division amplifies rounding, takes the careful path,
    /// which clamps. `false` (fixed point, whose rounding is too coarse
    /// for that): `v * q` is interpolated and every division is clamped to
    /// the vertex values' range.
    const RELATIVE_DIVISION: bool;
    /// Whether the vertex stage works in integers
    /// ([`IntegerVertices`](crate::vertex::IntegerVertices)) rather than in
    /// `f32`: where there is no FPU, that is the bulk of a small-triangle
    /// frame.
    const INTEGER_VERTICES: bool;
    /// From `f32` (saturating; NaN gives zero).
    fn from_f32(v: f32) -> Self;
    /// A vertex value for plane setup: like [`Interp::from_f32`], but
    /// truncated toward zero in fixed point (one conversion instruction
    /// where rounding takes a sequence; the difference, under 2^-16, stays
    /// far below a color or depth step), and `f32` as it is (a NaN would
    /// give NaN gradients, which [`Interp::gradients`] makes zero, and
    /// pixels converted from NaN are zero: no test is worth its cost, a
    /// library call per value without an FPU).
    fn from_f32_truncated(v: f32) -> Self;
    /// A triangle's shape prepared once for the gradients of all its
    /// planes ([`Interp::basis`]).
    type Basis: Copy + core::fmt::Debug;
    /// The basis of a triangle whose second and third vertices lie at
    /// `o = [ox1, oy1, ox2, oy2]` units of `2^-f` pixels from its first,
    /// `area2 = ox1 * oy2 - oy1 * ox2` being nonzero.
    fn basis(o: [i32; 4], area2: i64, f: u32) -> Self::Basis;
    /// The gradients per pixel `(dx, dy)` of the plane through the values
    /// `a`, `b`, `c` at the triangle's three vertices. Fixed point
    /// saturates gradients it cannot represent (so that
    /// [`Interp::is_wide`] holds for them).
    fn gradients(basis: &Self::Basis, a: Self, b: Self, c: Self) -> (Self, Self);
    /// Whether a gradient is too steep to step precisely (fixed point:
    /// beyond ±32,000 per pixel, near where 16.16 saturates); `f32` never is.
    fn is_wide(self) -> bool;
    /// The interpolated depth of a vertex's window depth `z` in units of
    /// 2^-30 (see [`ScreenVertex::z`](crate::raster::ScreenVertex::z), at
    /// most 2^30): `((1 - z) * 65534 + 1.5) * DEPTH_SCALE`, stored units
    /// from 1 (far) to 65535.5 (near) scaled (see [`Interp::DEPTH_SCALE`]).
    fn depth(z: u32) -> Self;
    /// To `f32`.
    fn to_f32(self) -> f32;
    /// `self + d`.
    fn add(self, d: Self) -> Self;
    /// `self - d`.
    fn sub(self, d: Self) -> Self;
    /// `self + d * n`.
    fn add_mul(self, d: Self, n: i32) -> Self;
    /// `self / n` for `n > 0`.
    fn div_int(self, n: i32) -> Self;
    /// `self / 2^k`, exactly as [`Interp::div_int`] by `2^k` (`k < 31`),
    /// without a division.
    fn div_pow2(self, k: u32) -> Self;
    /// `self * o`.
    fn mul(self, o: Self) -> Self;
    /// `self * o` clamped to `[lo, hi]`: [`Interp::mul`] then
    /// [`Interp::clamp_between`], in one clamp (a perspective division).
    fn mul_clamped(self, o: Self, lo: Self, hi: Self) -> Self;
    /// The perspective division's factor `1 / q` from an interpolated
    /// `self = q * Q_SCALE`, which the rasterizer keeps positive (a
    /// triangle whose `q` could come near zero takes the careful path,
    /// which clamps `q` into range). Zero or less gives the largest value
    /// in fixed point. `f32` divides without testing `q` first, which
    /// saves a compare and a select at every pixel. No value makes either
    /// panic.
    fn q_recip(self) -> Self;
    /// `min(max(self, lo), hi)`.
    fn clamp_between(self, lo: Self, hi: Self) -> Self;
    /// `1 / sqrt(self)` for a positive value; zero or less gives zero.
    fn rsqrt(self) -> Self;
    /// The integer part as a color channel. The caller keeps the value in
    /// `[0, 256)`; outside it the result is unspecified (but no panic).
    /// A `u32`, not a `u8`: a channel then goes into its pixel with no
    /// mask to 8 bits.
    fn channel(self) -> u32;
    /// The value times 2^16 as an integer (saturating for `f32`): texture
    /// coordinates with 16 fractional bits.
    fn to_bits16(self) -> i32;
    /// A depth value (see [`Interp::DEPTH_SCALE`]) as 16-bit stored depth,
    /// under the same contract as [`Interp::channel`] for `[0, 65536)`.
    /// In a `u32`, so that the depth test compares in 32 bits: fixed point
    /// then needs no mask to 16 bits and `f32` no zero-extension after
    /// its saturation (one instruction a pixel less each on the M4F;
    /// `wall-gouraud` in fixed point on the M0+ three less).
    fn depth16(self) -> u32;
    /// A depth value as stored depth with 16 fractional bits (`f32`:
    /// saturating).
    fn depth32(self) -> u32;
    /// A depth value in stored units as `f32`.
    fn depth_f32(self) -> f32;
    /// The value of the plane `(value0, dx, dy)` at an offset of
    /// `(ox, oy)` units of `2^-f` pixels from its origin (wrapping in
    /// fixed point: exactly what stepping from the origin would give).
    fn plane_at(value0: Self, dx: Self, dy: Self, ox: i32, oy: i32, f: u32) -> Self;
    /// Whether the plane through `a`, `b`, `c` (a triangle's vertex values)
    /// with the gradients [`Interp::gradients`] gives stays within
    /// `[lo, hi]` at the three vertices when stepped, decided from the
    /// values alone: they lie far enough inside the range for any error
    /// the gradients can have (or the plane is constant). A sufficient
    /// condition, cheaper than [`Interp::plane_within`], which decides the
    /// rest. Always true where stepping cannot wrap (`f32`).
    fn clear_of_bounds(basis: &Self::Basis, a: Self, b: Self, c: Self, lo: Self, hi: Self) -> bool;
    /// Whether the plane's exact values at its origin and at the two
    /// offsets `b` and `c` (a triangle's other vertices) are all in
    /// `[lo, hi]`.
    #[allow(clippy::too_many_arguments)]
    fn plane_within(value0: Self, dx: Self, dy: Self, b: (i32, i32), c: (i32, i32), f: u32, lo: Self, hi: Self) -> bool;
    /// The plane's exact value at that offset, clamped to `[lo, hi]`.
    #[allow(clippy::too_many_arguments)]
    fn plane_clamped(value0: Self, dx: Self, dy: Self, ox: i32, oy: i32, f: u32, lo: Self, hi: Self) -> Self;
}

/// [`Interp::Basis`] of `f32`: the edge vectors in pixels and the
/// reciprocal of the area they span.
#[derive(Clone, Copy, Debug)]
pub struct FloatBasis {
    x1: f32,
    y1: f32,
    x2: f32,
    y2: f32,
    inv_area: f32,
}

/// [`Interp::Basis`] of [`Fixed`]: plane gradients in integers only, so
/// that a core without an FPU sets up a triangle without a float
/// operation (each one a library call of about a hundred instructions
/// there) and every core gets the same bits.
///
/// A gradient is a combination of the value differences `d1 = b - a` and
/// `d2 = c - a` at the other two vertices, `dx = (d1 oy2 - d2 oy1) 2^f /
/// area2` and `dy = (d2 ox1 - d1 ox2) 2^f / area2`. The four coefficients
/// are computed once per triangle, scaled by a common power of two to
/// about 30 significant bits: `dx = (d1 k[0] + d2 k[1]) / 2^shift`, `dy =
/// (d1 k[2] + d2 k[3]) / 2^shift`, rounded. Their relative error, about
/// 2^-28, is below that of `f32` (2^-24, and worse for slivers, whose area
/// cancels in `f32`: it is exact here).
#[derive(Clone, Copy, Debug)]
pub struct FixedBasis {
    k: [i32; 4],
    /// In `1..=62`, or 0 for gradients too steep for 32 bits whatever the
    /// values (a sliver far thinner than a pixel): [`Interp::gradients`]
    /// saturates them. (Not a flag of its own: a `bool` after the other
    /// fields left padding that ARMv6-M copied with a library call per
    /// triangle.)
    shift: u32,
    /// `2^(shift - 1)`, for rounding.
    half: i64,
    /// A bound on how far stepping from the first vertex can land from
    /// the value at another vertex (in units of 2^-16, from the
    /// coefficients' error: see [`Interp::clear_of_bounds`]), or a large
    /// value where it is not small.
    margin: i32,
}

impl FixedBasis {
    #[inline(always)]
    fn new([ox1, oy1, ox2, oy2]: [i32; 4], area2: i64, f: u32) -> Self {
        const STEEP: FixedBasis = FixedBasis { k: [0; 4], shift: 0, half: 0, margin: i32::MAX };
        let area = area2.unsigned_abs();
        if area == 0 {
            return STEEP;
        }
        // 1 / area = r * 2^(n - 93), r in (2^29, 2^30), from the area's
        // top 32 bits `m`.
        let n = super::leading_zeros_u64(area);
        let r = reciprocal_q61((shl_wide(area, n) >> 32) as u32);
        let r2 = if area2 < 0 { -(r << 1) } else { r << 1 };
        // Offsets below 2^t, t <= 30: each coefficient o r 2^-t is the high
        // word of (o 2^(31 - t)) (2 r), below 2^30 (one multiply-high).
        let span = ox1.unsigned_abs() | oy1.unsigned_abs() | ox2.unsigned_abs() | oy2.unsigned_abs();
        let t = 32 - super::leading_zeros(span);
        let up = 31 - t;
        let k = |o: i32| high_word_of_shifted_product(o, up, r2);
        // dx = (d1 oy2 - d2 oy1) r 2^(f + n - 93) = (d1 k0 + d2 k1) 2^(t + f + n - 93).
        let shift = 93 - (t + f + n) as i32;
        if shift < 1 {
            return STEEP;
        }
        // Each gradient is within 1/2 + 4 (|d1| + |d2|) / 2^shift of the
        // exact one (its rounding; each coefficient within 4 units: its
        // floor and the reciprocal's 2^-28), and |d1| + |d2| < 2^33 for
        // values in any range. Over offsets |ox| + |oy| < 2^(t + 1), in
        // units of 2^-f pixels, stepping then lands within 2^(t - f) +
        // 2^(36 + t - f - shift) of the exact plane, plus 1 for the floor.
        let (t, f) = (t as i32, f as i32);
        let rounding = if t > f { 1 << (t - f) } else { 1 };
        let exponent = 36 + t - f - shift;
        // (Beyond 2^28, no plane is clear of its bounds.)
        let margin = if exponent > 28 { i32::MAX } else { rounding + (1 << exponent.max(0)) + 2 };
        // Never above 62: t + n >= 63 - t (the area is below 2^(2t + 1)),
        // so shift <= 59.
        let shift = shift.min(62) as u32;
        Self { k: [k(oy2), k(-oy1), k(-ox2), k(ox1)], shift, half: shl_wide(1, shift - 1) as i64, margin }
    }

    /// Whether the gradients are too steep for 32 bits (see `shift`).
    #[inline(always)]
    fn is_steep(&self) -> bool {
        self.shift == 0
    }

    #[inline(always)]
    fn gradients(&self, a: Fixed, b: Fixed, c: Fixed) -> (Fixed, Fixed) {
        if self.is_steep() {
            return (Fixed::from_bits(i32::MAX), Fixed::from_bits(i32::MAX));
        }
        // Values outside every range saturate here; the range check then
        // rejects the plane (its far vertex lands far off).
        let (d1, d2) = (b.to_bits().saturating_sub(a.to_bits()), c.to_bits().saturating_sub(a.to_bits()));
        let gradient = |k1: i32, k2: i32| {
            // Each product is below 2^61, so the sum fits.
            let g = shr_wide(mul_wide(d1, k1) + mul_wide(d2, k2) + self.half, self.shift);
            // It fits 32 bits when the high word is the low word's sign
            // (one compare); beyond, it is far past what `is_wide` allows.
            let (low, high) = (g as i32, (g >> 32) as i32);
            Fixed::from_bits(if high == low >> 31 { low } else { i32::MAX })
        };
        (gradient(self.k[0], self.k[1]), gradient(self.k[2], self.k[3]))
    }
}

impl Interp for f32 {
    const NAME: &'static str = "f32";
    const DEPTH_SCALE: f32 = 1.0;
    const Q_SCALE: f32 = 1.0;
    const WRAPS: bool = false;
    const FREE_CHANNEL_MASK: bool = false;
    const RELATIVE_DIVISION: bool = true;
    const INTEGER_VERTICES: bool = false;
    #[inline]
    fn from_f32(v: f32) -> Self {
        if v.is_nan() {
            0.0
        } else {
            v
        }
    }
    #[inline(always)]
    fn from_f32_truncated(v: f32) -> Self {
        v
    }
    type Basis = FloatBasis;
    #[inline(always)]
    fn basis(o: [i32; 4], area2: i64, f: u32) -> FloatBasis {
        let unit = 1.0 / (1u32 << f) as f32;
        let [x1, y1, x2, y2] = o.map(|v| v as f32 * unit);
        // In f32 the area is exact enough on screen; for long slivers
        // reaching toward the guard band it cancels catastrophically, and
        // those take the f64 path (see `raster::Plane::far`). A sliver's
        // products can also round to the same value: then the exact
        // area's sign and smallest magnitude, so that `inv_area` is always
        // finite (that sliver covers a pixel or two at most). Taking the
        // exact area there instead measured 1.2% slower on torus.babylon
        // (M4F): the rare branch cost the setup its registers.
        let area = x1 * y2 - y1 * x2;
        let tiny = if area2 < 0 { -(unit * unit) } else { unit * unit };
        let area = if area != 0.0 { area } else { tiny };
        FloatBasis { x1, y1, x2, y2, inv_area: 1.0 / area }
    }
    #[inline(always)]
    fn gradients(basis: &FloatBasis, a: Self, b: Self, c: Self) -> (Self, Self) {
        let FloatBasis { x1, y1, x2, y2, inv_area } = *basis;
        let (d1, d2) = (b - a, c - a);
        // Finite: `inv_area` is, and so are the values (the vertex stage
        // flags non-finite ones). No NaN test per gradient (8 of them a
        // Gouraud triangle: 2.7% of torus.babylon on the M4F); values so
        // far apart that a product overflows would give an infinite or NaN
        // plane, which the span loop's saturating conversions still draw
        // without fault.
        ((d1 * y2 - d2 * y1) * inv_area, (d2 * x1 - d1 * x2) * inv_area)
    }
    #[inline(always)]
    fn clear_of_bounds(_: &FloatBasis, _: Self, _: Self, _: Self, _: Self, _: Self) -> bool {
        true
    }
    #[inline(always)]
    fn is_wide(self) -> bool {
        false
    }
    #[inline(always)]
    fn depth(z: u32) -> Self {
        // `1 - z` in units of 2^-30 is exact as an integer; its conversion
        // rounds as `1.0 - z` in `f32` does (the same value scaled by 2^30),
        // and so does the product by `DEPTH_RANGE` scaled by 2^-30 (a
        // power of two apart).
        ((crate::raster::DEPTH_ONE - z) as f32) * (crate::raster::DEPTH_RANGE / (1u32 << 30) as f32) + 1.5
    }
    #[inline]
    fn to_f32(self) -> f32 {
        self
    }
    #[inline(always)]
    fn add(self, d: Self) -> Self {
        self + d
    }
    #[inline(always)]
    fn sub(self, d: Self) -> Self {
        self - d
    }
    #[inline(always)]
    fn add_mul(self, d: Self, n: i32) -> Self {
        self + d * n as f32
    }
    #[inline]
    fn div_int(self, n: i32) -> Self {
        self / n as f32
    }
    #[inline(always)]
    fn div_pow2(self, k: u32) -> Self {
        // A power of two: the quotient is the product by its reciprocal.
        self * (1.0 / (1u32 << k) as f32)
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self * o
    }
    #[inline(always)]
    fn mul_clamped(self, o: Self, lo: Self, hi: Self) -> Self {
        (self * o).clamp_between(lo, hi)
    }
    #[inline(always)]
    fn q_recip(self) -> Self {
        1.0 / self
    }
    #[inline]
    fn rsqrt(self) -> Self {
        if self > 1e-30 {
            super::elementary::rsqrt_inline(self)
        } else {
            0.0
        }
    }
    #[inline]
    fn clamp_between(self, lo: Self, hi: Self) -> Self {
        if self > lo {
            if self < hi {
                self
            } else {
                hi
            }
        } else {
            lo
        }
    }
    #[inline(always)]
    fn channel(self) -> u32 {
        // `as` saturates and maps NaN to 0, and so does the Arm FPU's
        // conversion to u32: one instruction, where LLVM tests the bounds
        // of a direct `as u8` with two float compares (ten instructions a
        // channel).
        self as u32
    }
    #[inline(always)]
    fn to_bits16(self) -> i32 {
        (self * 65536.0) as i32
    }
    #[inline(always)]
    fn depth16(self) -> u32 {
        // With an FPU through i32 (one instruction, saturating, NaN to 0),
        // then clamped: with DSP instructions (Cortex-M4F) one `usat`,
        // where `min` on a u32 needed a compare and the constant's
        // register. Without, through u32: in software the conversion to
        // i32 tests more bounds (wall-flat f32 on the M0+ 15% slower).
        if super::HARD_FLOAT {
            (self as i32).clamp(0, 65535) as u32
        } else {
            (self as u32).min(65535)
        }
    }
    #[inline(always)]
    fn depth32(self) -> u32 {
        (self * 65536.0) as u32
    }
    #[inline(always)]
    fn depth_f32(self) -> f32 {
        self
    }
    #[inline]
    fn plane_at(value0: Self, dx: Self, dy: Self, ox: i32, oy: i32, f: u32) -> Self {
        let unit = 1.0 / (1u32 << f) as f32;
        value0 + dx * (ox as f32 * unit) + dy * (oy as f32 * unit)
    }
    #[inline]
    #[allow(clippy::too_many_arguments)]
    fn plane_within(value0: Self, dx: Self, dy: Self, b: (i32, i32), c: (i32, i32), f: u32, lo: Self, hi: Self) -> bool {
        let within = |v: f32| v >= lo && v <= hi;
        within(value0) & within(Self::plane_at(value0, dx, dy, b.0, b.1, f)) & within(Self::plane_at(value0, dx, dy, c.0, c.1, f))
    }
    #[inline]
    #[allow(clippy::too_many_arguments)]
    fn plane_clamped(value0: Self, dx: Self, dy: Self, ox: i32, oy: i32, f: u32, lo: Self, hi: Self) -> Self {
        Self::plane_at(value0, dx, dy, ox, oy, f).clamp_between(lo, hi)
    }
}

impl Fixed {
    /// `value0 + (dx * ox + dy * oy) / 2^f` exactly, in raw units.
    #[inline]
    fn plane_exact(value0: Self, dx: Self, dy: Self, ox: i32, oy: i32, f: u32) -> i64 {
        // |d| < 2^31 and |o| <= 2^30: each product below 2^61, no overflow.
        let sum = dot_wide(dx.to_bits(), ox, dy.to_bits(), oy);
        value0.to_bits() as i64 + shr_wide(sum, f)
    }
}

/// `(u32::MAX / d, u32::MAX % d)` for `d` in `[2^16, 2^17)`, exactly,
/// without a division (on ARMv6-M a library call of some 180
/// instructions, once per pixel in a perspective-correct span): one
/// Newton step from the reciprocal table gives the quotient within one,
/// and the remainder's sign and size correct it.
#[inline(always)]
fn max_by_17_bits(d: u32) -> (u32, u32) {
    // 2^61 / (d 2^15) = 2^46 / d within about 2^-17: the quotient 2^32 / d
    // (at most 2^16) within a half, truncated.
    let t = super::reciprocal_q61_coarse(d << 15) >> 14;
    // The remainder u32::MAX - t d is in (-2d, 2d): in i32 arithmetic
    // (d < 2^17), wrapping, it comes out exact.
    let rest = (u32::MAX.wrapping_sub(t.wrapping_mul(d))) as i32;
    let d = d as i32;
    // The step lands at or below the quotient for every d (the exhaustive
    // test never takes the first branch), but without that branch the
    // compiler's code for the span loop is longer: wall-tex fixed on the
    // M0+ measured +2.2%.
    let (t, rest) = if rest < 0 {
        (t - 1, rest + d)
    } else if rest >= d {
        (t + 1, rest - d)
    } else {
        (t, rest)
    };
    (t, rest as u32)
}

impl Interp for Fixed {
    const NAME: &'static str = "fixed16";
    // Depth up to 65535 does not fit 16.16 signed; it is kept halved (17.15).
    const DEPTH_SCALE: f32 = 0.5;
    const Q_SCALE: f32 = 8192.0;
    const WRAPS: bool = true;
    const FREE_CHANNEL_MASK: bool = true;
    const RELATIVE_DIVISION: bool = false;
    const INTEGER_VERTICES: bool = true;
    #[inline]
    fn from_f32(v: f32) -> Self {
        Fixed::from_f32(v)
    }
    #[inline(always)]
    fn from_f32_truncated(v: f32) -> Self {
        Fixed::truncate_f32(v)
    }
    type Basis = FixedBasis;
    #[inline(always)]
    fn basis(o: [i32; 4], area2: i64, f: u32) -> FixedBasis {
        FixedBasis::new(o, area2, f)
    }
    #[inline(always)]
    fn gradients(basis: &FixedBasis, a: Self, b: Self, c: Self) -> (Self, Self) {
        basis.gradients(a, b, c)
    }
    #[inline(always)]
    fn clear_of_bounds(basis: &FixedBasis, a: Self, b: Self, c: Self, lo: Self, hi: Self) -> bool {
        // Stepping from `a` reaches `b` within `margin - 1` below and
        // `margin - 2` above it (the gradients' error over the triangle,
        // and the floor of the last step); a constant plane is exact.
        // In 32-bit unsigned arithmetic: `v` is in `[lo + margin, hi -
        // margin]` when `v - lo - margin` (wrapping) is at most `width - 2
        // margin`, and ranges are narrower than 2^32.
        let (a, b, c, lo) = (a.to_bits() as u32, b.to_bits() as u32, c.to_bits() as u32, lo.to_bits() as u32);
        let width = (hi.to_bits() as u32).wrapping_sub(lo);
        let margin = basis.margin as u32;
        let inner_width = width.wrapping_sub(2 * margin);
        let inner = |v: u32| v.wrapping_sub(lo).wrapping_sub(margin) <= inner_width;
        // `&&`, not `&`: only ARMv6-M calls this, which has no conditional
        // execution, and a boolean made of a compare takes a branch there
        // anyway (`torus.babylon` on the M0+ 1.2% fewer instructions).
        let constant = b == a && c == a;
        a.wrapping_sub(lo) <= width && (constant || (width >= 2 * margin && inner(b) && inner(c)))
    }
    #[inline(always)]
    fn is_wide(self) -> bool {
        // `|g| >= LIMIT` as one add and one unsigned compare.
        const LIMIT: u32 = 32_000 << Fixed::FRAC_BITS;
        (self.to_bits() as u32).wrapping_add(LIMIT - 1) > 2 * LIMIT - 2
    }
    #[inline(always)]
    fn depth(z: u32) -> Self {
        // (1 - z) * 65534 + 1.5 halved, in units of 2^-16: the product is
        // below 2^46 and the result below 2^31. (An integer already: no
        // conversion per triangle.)
        Fixed::from_bits(halved_depth_bits(crate::raster::DEPTH_ONE - z))
    }
    #[inline]
    fn to_f32(self) -> f32 {
        Fixed::to_f32(self)
    }
    #[inline(always)]
    fn add(self, d: Self) -> Self {
        self.wrapping_add(d)
    }
    #[inline(always)]
    fn sub(self, d: Self) -> Self {
        Fixed::from_bits(self.to_bits().wrapping_sub(d.to_bits()))
    }
    #[inline(always)]
    fn add_mul(self, d: Self, n: i32) -> Self {
        Fixed::from_bits(self.to_bits().wrapping_add(d.to_bits().wrapping_mul(n)))
    }
    #[inline]
    fn div_int(self, n: i32) -> Self {
        Fixed::from_bits(self.to_bits().checked_div(n).unwrap_or(0))
    }
    #[inline(always)]
    fn div_pow2(self, k: u32) -> Self {
        // Truncating toward zero like the division: negative values are
        // raised by 2^k - 1 before the (flooring) shift.
        let b = self.to_bits();
        Fixed::from_bits(b.wrapping_add((b >> 31) & ((1 << k) - 1)) >> k)
    }
    #[inline]
    fn mul(self, o: Self) -> Self {
        self.saturating_mul(o)
    }
    #[inline(always)]
    fn mul_clamped(self, o: Self, lo: Self, hi: Self) -> Self {
        // The product clamped once, in 64 bits: saturating it to 32 bits
        // first would change nothing, `[lo, hi]` being inside.
        let p = mul_wide(self.to_bits(), o.to_bits()) >> Fixed::FRAC_BITS;
        Fixed::from_bits(p.max(lo.to_bits() as i64).min(hi.to_bits() as i64) as i32)
    }
    #[inline(always)]
    fn q_recip(self) -> Self {
        // The bits are q * 2^29 (q in (0, 2], at most 2^30); the result's
        // are 2^16 / q = 2^45 / bits.
        let bits = self.to_bits();
        if bits <= 0 {
            return Fixed::from_bits(i32::MAX);
        }
        // The top 17 bits of the divisor, `d` in [2^16, 2^17), in one
        // 32-bit division, or on ARMv6-M, which has none, by
        // `max_by_17_bits` (the same quotient; a 64-bit division is a
        // library call of a hundred instructions or more on Cortex-M; and
        // no float, so that every core gets the same bits): bits ~ d *
        // 2^(15 - n), so 2^45 / bits ~ (2^32 / d) * 2^(n - 2), within 3e-5
        // relative.
        let n = super::leading_zeros(bits as u32);
        let d = ((bits as u32) << n) >> 15;
        // 2^32 / d rounded: 2^32 = t * d + rest + 1.
        let (t, rest) = if cfg!(soft3d_armv6m) { max_by_17_bits(d) } else { (u32::MAX / d, u32::MAX % d) };
        let t = if 2 * (rest + 1) >= d { t + 1 } else { t };
        // t is in [2^15, 2^16]: shifted 15 it still fits 32 bits, and
        // shifted further it saturates (a 64-bit shift is a library call
        // on ARMv6-M).
        let r = match n {
            0 | 1 => t >> 1,
            2..=17 => (t << (n - 2)).min(i32::MAX as u32),
            _ => i32::MAX as u32,
        };
        Fixed::from_bits(r as i32)
    }
    #[inline]
    fn rsqrt(self) -> Self {
        Fixed::rsqrt(self)
    }
    #[inline]
    fn clamp_between(self, lo: Self, hi: Self) -> Self {
        // Not `clamp`, which asserts `lo <= hi` at every call (callers
        // keep them ordered).
        self.max(lo).min(hi)
    }
    #[inline(always)]
    fn channel(self) -> u32 {
        let bits = self.to_bits() >> Fixed::FRAC_BITS;
        // Masked to a byte where that is free (`ubfx`): without, the
        // textured span loops measured slower on the M4F (wall-tex32
        // +1.4%), and with it, on ARMv6-M (+6.9% wall-tex-affine).
        if cfg!(soft3d_armv6m) {
            bits as u32
        } else {
            bits as u8 as u32
        }
    }
    #[inline(always)]
    fn to_bits16(self) -> i32 {
        self.to_bits()
    }
    #[inline(always)]
    fn depth16(self) -> u32 {
        // Within the contract the top bit is clear: a logical shift is
        // the value.
        self.to_bits() as u32 >> (Fixed::FRAC_BITS - 1)
    }
    #[inline(always)]
    fn depth32(self) -> u32 {
        // Halved depth in 17.15 is the full depth in 16.16, one bit up.
        (self.to_bits() as u32) << 1
    }
    #[inline(always)]
    fn depth_f32(self) -> f32 {
        self.to_f32() * 2.0
    }
    #[inline]
    fn plane_at(value0: Self, dx: Self, dy: Self, ox: i32, oy: i32, f: u32) -> Self {
        Fixed::from_bits(Self::plane_exact(value0, dx, dy, ox, oy, f) as i32)
    }
    #[inline]
    #[allow(clippy::too_many_arguments)]
    fn plane_within(value0: Self, dx: Self, dy: Self, b: (i32, i32), c: (i32, i32), f: u32, lo: Self, hi: Self) -> bool {
        // `lo <= value0 + floor(sum / 2^f) <= hi` is `low <= sum < high`
        // with `low = (lo - value0) * 2^f`, `high = (hi - value0 + 1) * 2^f`:
        // per offset two multiplies and one unsigned compare, no shift.
        let (v0, lo, hi) = (value0.to_bits() as i64, lo.to_bits() as i64, hi.to_bits() as i64);
        let low = (lo - v0) << f;
        let width = (((hi - lo + 1) << f) - 1) as u64;
        let within = |(ox, oy): (i32, i32)| {
            let sum = dx.to_bits() as i64 * ox as i64 + dy.to_bits() as i64 * oy as i64;
            (sum.wrapping_sub(low) as u64) <= width
        };
        (((v0 - lo) as u64) <= (hi - lo) as u64) & within(b) & within(c)
    }
    #[inline]
    #[allow(clippy::too_many_arguments)]
    fn plane_clamped(value0: Self, dx: Self, dy: Self, ox: i32, oy: i32, f: u32, lo: Self, hi: Self) -> Self {
        Fixed::from_bits(Self::plane_exact(value0, dx, dy, ox, oy, f).max(lo.to_bits() as i64).min(hi.to_bits() as i64) as i32)
    }
}

/// `floor(x 65534 / 2^15) + 1.5 2^15` for `x = (1 - z) 2^30` in `[0,
/// 2^30]`: the fixed-point depth's bits. As `2x - ceil(x / 2^14)`, with
/// no product (a 64-bit one is four multiplies by halves on ARMv6-M, three
/// per triangle); the result is below 2^31.
#[inline(always)]
fn halved_depth_bits(x: u32) -> i32 {
    (2 * x - ((x + (1 << 14) - 1) >> 14) + (3 << 14)) as i32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::xorshift;

    #[test]
    fn window_depth_in_units_gives_the_f32_formula_and_the_fixed_depth() {
        use crate::raster::{window_depth, DEPTH_ONE, DEPTH_RANGE};
        // The ends, and rounding's overshoots, are clamped; NaN is 0.
        assert_eq!(window_depth(0.0), 0);
        assert_eq!(window_depth(-0.0), 0);
        assert_eq!(window_depth(-f32::EPSILON), 0);
        assert_eq!(window_depth(1.0), DEPTH_ONE);
        assert_eq!(window_depth(1.0 + f32::EPSILON), DEPTH_ONE);
        assert_eq!(window_depth(f32::NAN), 0);
        let mut next = xorshift(0x5EED_D397);
        let mut checked = 0;
        for _ in 0..200_000 {
            // Uniform bits in [0, 1]: every exponent, down to subnormals.
            let z = f32::from_bits(next() % (1.0f32.to_bits() + 1));
            let units = window_depth(z);
            assert_eq!(units as f64, (z as f64 * (1u64 << 30) as f64).floor(), "{z}");
            // Fixed point: what it took from the `f32` depth before.
            let old = Fixed::scaled_truncated(z, 30).clamp(0, 1 << 30);
            assert_eq!(<Fixed as Interp>::depth(units), Fixed::from_bits(halved_depth_bits(((1 << 30) - old) as u32)));
            // `f32`: the same bits as the formula on `z` itself, wherever
            // `z * 2^30` is whole (from 2^-7 up); below, within an ulp.
            let formula = (1.0 - z) * DEPTH_RANGE + 1.5;
            let from_units = <f32 as Interp>::depth(units);
            if z >= 1.0 / 128.0 {
                assert_eq!(from_units.to_bits(), formula.to_bits(), "{z}");
                checked += 1;
            } else {
                assert!((from_units - formula).abs() <= formula * f32::EPSILON, "{z}: {from_units} against {formula}");
            }
        }
        assert!(checked > 1000, "{checked} values from 2^-7 up");
    }

    #[test]
    fn halved_depth_needs_no_product() {
        let mut next = xorshift(0x68E3_1DA4);
        let edges = [0, 1, (1 << 14) - 1, 1 << 14, (1 << 14) + 1, (1 << 30) - 1, 1 << 30];
        for x in edges.into_iter().chain((0..100_000).map(|_| next() >> 2)) {
            let product = ((x as i64 * 65534) >> 15) + (3 << 14);
            assert_eq!(halved_depth_bits(x) as i64, product, "{x}");
        }
    }

    #[test]
    fn f32_gradients_stay_finite_where_the_area_cancels() {
        // 4097^2 and 4096 * 4098 round to the same f32: the f32 area is 0,
        // the exact one 1 unit.
        for (o, area2) in [([4097, 4096, 4098, 4097], 1i64), ([4098, 4097, 4097, 4096], -1)] {
            let unit = 1.0 / 128.0f32;
            let [x1, y1, x2, y2] = o.map(|v| v as f32 * unit);
            assert_eq!(x1 * y2 - y1 * x2, 0.0);
            let basis = <f32 as Interp>::basis(o, area2, 7);
            assert!(basis.inv_area.is_finite() && (basis.inv_area > 0.0) == (area2 > 0), "{}", basis.inv_area);
            for (a, b, c) in [(1.0, 1.0, 1.0), (0.0, 1.0, 2.0), (31.0, 0.0, 17.5)] {
                let (dx, dy) = f32::gradients(&basis, a, b, c);
                assert!(dx.is_finite() && dy.is_finite(), "{dx} {dy}");
            }
            assert_eq!(f32::gradients(&basis, 3.0, 3.0, 3.0), (0.0, 0.0));
        }
    }

    #[test]
    fn perspective_reciprocals_are_2_to_the_45_over_the_top_17_bits() {
        // The definition: 2^32 over the divisor's top 17 bits, rounded,
        // scaled back by the normalization, saturated.
        let reference = |bits: i32| {
            let n = bits.leading_zeros();
            let d = ((bits as u32) << n) >> 15;
            let t = ((1u64 << 33) + d as u64) / (2 * d as u64);
            let r = if n >= 2 { t << (n - 2) } else { t >> 1 };
            r.min(i32::MAX as u64) as i32
        };
        let mut next = xorshift(0x6A09_E667);
        let edges = [1, 2, 3, 0x7FFF, 0x8000, 0x1_0000, 0x2000_0000, 0x3FFF_FFFF, 0x4000_0000, i32::MAX];
        for bits in edges.into_iter().chain((0..1_000_000).map(|_| (next() >> (1 + next() % 31)).max(1) as i32)) {
            assert_eq!(Fixed::from_bits(bits).q_recip().to_bits(), reference(bits), "bits {bits:#x}");
        }
        assert_eq!(Fixed::from_bits(0).q_recip().to_bits(), i32::MAX);
        assert_eq!(Fixed::from_bits(-5).q_recip().to_bits(), i32::MAX);
    }

    #[test]
    fn quotients_of_17_bits_without_division_are_exact() {
        for d in 1 << 16..1 << 17 {
            assert_eq!(max_by_17_bits(d), (u32::MAX / d, u32::MAX % d), "d = {d}");
        }
    }

    /// Offsets `[ox1, oy1, ox2, oy2]` of a random triangle, its `area2` and
    /// `f` (1 to 9): from a unit to the guard band in size, slivers
    /// included; `None` if it came out degenerate.
    fn random_triangle(next: &mut impl FnMut() -> u32) -> Option<([i32; 4], i64, u32)> {
        let f = 1 + next() % 9;
        let reach = 1i64 << (next() % (30 - f));
        let mut offset = || ((next() as i64 % (2 * reach + 1)) - reach) as i32;
        let o = [offset(), offset(), offset(), offset()];
        let area2 = o[0] as i64 * o[3] as i64 - o[1] as i64 * o[2] as i64;
        (area2 != 0).then_some((o, area2, f))
    }

    fn stepping<S: Interp>() {
        let mut v = S::from_f32(10.5);
        let d = S::from_f32(0.25);
        for _ in 0..4 {
            v = v.add(d);
        }
        assert_eq!(v.channel(), 11);
        assert_eq!(S::from_f32(10.5).add_mul(d, 4), v);
        assert_eq!(v.sub(d), S::from_f32(11.25));
        assert_eq!(S::from_f32(3.0).div_int(4), S::from_f32(0.75));
        let mut next = xorshift(0xBB67_AE85);
        for _ in 0..20_000 {
            let v = S::from_f32((next() as i32 >> (next() % 31)) as f32 / 65536.0);
            let k = next() % 9;
            assert_eq!(v.div_pow2(k), v.div_int(1 << k), "{} / 2^{k}", v.to_f32());
        }
        assert_eq!(S::from_f32(300.0).clamp_between(S::from_f32(0.0), S::from_f32(255.0)), S::from_f32(255.0));
        assert_eq!(S::from_f32(40000.5 * S::DEPTH_SCALE).depth16(), 40000);
        assert_eq!(S::from_f32(40000.5 * S::DEPTH_SCALE).depth32(), 40000 * 65536 + 32768);
        assert_eq!(S::from_f32(40000.5 * S::DEPTH_SCALE).depth_f32(), 40000.5);
        assert_eq!(S::from_f32(0.5 * S::Q_SCALE).q_recip().to_f32(), 2.0);
        assert_eq!(S::from_f32(2.0 * S::Q_SCALE).q_recip().to_f32(), 0.5);
        let third = S::from_f32(3.0 * S::Q_SCALE / 4.0).q_recip().to_f32();
        assert!((third - 4.0 / 3.0).abs() < 1e-4, "{third}");
        let (lo, hi) = (S::from_f32(-2.0), S::from_f32(3.0));
        for (a, b) in [(1.5, 1.5), (-4.0, 1.0), (100.0, 200.0), (-0.25, 0.5), (30000.0, -30000.0)] {
            let (a, b) = (S::from_f32(a), S::from_f32(b));
            assert_eq!(a.mul_clamped(b, lo, hi), a.mul(b).clamp_between(lo, hi));
        }
        assert_eq!(S::from_f32(4.0).rsqrt().to_f32(), 0.5);
        assert!((S::from_f32(2.0).rsqrt().to_f32() - core::f32::consts::FRAC_1_SQRT_2).abs() < 1e-4);
        assert_eq!(S::from_f32(-1.0).rsqrt().to_f32(), 0.0);
        // Plane 10 + 2x - y at (3.5, 1.25) pixels with 4 sub-pixel bits (f = 5).
        let (v0, dx, dy) = (S::from_f32(10.0), S::from_f32(2.0), S::from_f32(-1.0));
        assert_eq!(S::plane_at(v0, dx, dy, 112, 40, 5), S::from_f32(15.75));
        let (lo, hi) = (S::from_f32(10.0), S::from_f32(15.75));
        assert!(S::plane_within(v0, dx, dy, (112, 40), (32, 0), 5, lo, hi));
        assert!(!S::plane_within(v0, dx, dy, (112, 40), (32, 0), 5, lo, S::from_f32(15.5)));
        assert!(!S::plane_within(v0, dx, dy, (32, 0), (112, 40), 5, lo, S::from_f32(15.5)));
        // The plane is 9 at (0, 1) pixels, below 9.5.
        assert!(!S::plane_within(v0, dx, dy, (0, 32), (32, 0), 5, S::from_f32(9.5), hi));
        // The origin (10) is below the range.
        assert!(!S::plane_within(v0, dx, dy, (32, 0), (32, 0), 5, S::from_f32(10.5), hi));
    }

    #[test]
    fn f32_channels_and_depths_convert_like_as() {
        // Every float class: NaN, infinities, zeros, subnormals, values
        // around each bound, and a sweep of bit patterns.
        let specials = [
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            0.0,
            -0.0,
            f32::MIN_POSITIVE,
            1e-45,
            -1e-45,
            254.99,
            255.0,
            255.5,
            256.0,
            65534.9,
            65535.0,
            65535.9,
            65536.0,
            4.3e9,
            -1.0,
            -0.5,
            0.5,
        ];
        let sweep = (0..=u32::MAX).step_by(65_521).map(f32::from_bits);
        for v in specials.into_iter().chain(sweep) {
            // Channels: as `as u8` below 256 (NaN and negatives give 0);
            // callers keep them there.
            if v.is_nan() || v < 256.0 {
                assert_eq!(Interp::channel(v), (v as u8).into(), "{v:e}");
            }
            assert_eq!(Interp::depth16(v), v as u16 as u32, "{v:e}");
        }
    }

    #[test]
    fn both_scalars_step_alike() {
        stepping::<f32>();
        stepping::<Fixed>();
    }

    #[test]
    fn fixed_plane_checks_are_exact_far_away() {
        // A steep plane evaluated 2^29 units away: the exact value is far
        // outside i32 even though stepping wraps; the check must say so.
        let (v0, dx) = (Fixed::from_f32(100.0), Fixed::from_f32(1000.0));
        assert!(!Fixed::plane_within(v0, dx, Fixed::ZERO, (1 << 29, 0), (0, 0), 5, Fixed::ZERO, Fixed::from_f32(255.0)));
    }

    #[test]
    fn fixed_range_check_equals_evaluating_the_plane() {
        // The shift-free check against the plain one, on values that
        // straddle the bounds (floor of negative sums included).
        let mut next = xorshift(12345u32);
        for _ in 0..20_000 {
            let v0 = Fixed::from_bits((next() % 4000) as i32 - 2000);
            let (dx, dy) = (Fixed::from_bits((next() % 600) as i32 - 300), Fixed::from_bits((next() % 600) as i32 - 300));
            let (ox, oy) = ((next() % 200) as i32 - 100, (next() % 200) as i32 - 100);
            let (lo, hi) = (Fixed::from_bits(-1000 + (next() % 50) as i32), Fixed::from_bits(1000 - (next() % 50) as i32));
            let f = next() % 9;
            let v = Fixed::plane_exact(v0, dx, dy, ox, oy, f);
            let plain = (lo.to_bits() as i64..=hi.to_bits() as i64).contains(&v) && (lo..=hi).contains(&v0);
            assert_eq!(Fixed::plane_within(v0, dx, dy, (ox, oy), (0, 0), f, lo, hi), plain, "{v0:?} {dx:?} {dy:?} {ox} {oy} {f}");
        }
    }

    #[test]
    fn integer_gradients_match_the_exact_quotient() {
        // Triangles from a pixel to the guard band, slivers included,
        // with values from flat to spanning the whole 32-bit range; the
        // gradients against the exact quotient in f64: off by the rounding
        // plus what the coefficients' last places weigh (about 2^-28 of
        // the terms `d1 oy2` and `d2 oy1`, so of the gradient unless they
        // cancel; f32 setup is off by 2^-24 of them).
        let mut next = xorshift(0x2545_F491u32);
        let mut checked = 0;
        for _ in 0..200_000 {
            let Some((o, area2, f)) = random_triangle(&mut next) else {
                continue;
            };
            // Below 2^30, so that differences fit (beyond, they saturate
            // and the range check rejects the plane).
            let scale = 1 + next() % 31;
            let mut value = || Fixed::from_bits((next() as i32) >> scale);
            let (a, b, c) = (value(), value(), value());
            let basis = Fixed::basis(o, area2, f);
            let (gx, gy) = Fixed::gradients(&basis, a, b, c);
            let (d1, d2) = ((b.to_bits() - a.to_bits()) as f64, (c.to_bits() - a.to_bits()) as f64);
            let per_pixel = (1u64 << f) as f64 / area2 as f64;
            let exact_x = (d1 * o[3] as f64 - d2 * o[1] as f64) * per_pixel;
            let exact_y = (d2 * o[0] as f64 - d1 * o[2] as f64) * per_pixel;
            for (got, exact) in [(gx, exact_x), (gy, exact_y)] {
                if exact.abs() >= 2_147_483_648.0 {
                    assert!(got.is_wide(), "{o:?} {area2} f={f}: {got:?} for {exact}");
                    continue;
                }
                if got.to_bits() == i32::MAX {
                    // Saturated: only where the basis itself is too steep.
                    assert!(basis.is_steep(), "{o:?} {area2} f={f}: saturated at {exact}");
                    continue;
                }
                // Rounding, and each coefficient within 4 units of its
                // last place (its floor and the reciprocal's 2^-28), the
                // bound `FixedBasis::new` derives its margin from.
                let off = (got.to_bits() as f64 - exact).abs();
                let bound = 0.5 + 4.0 * (d1.abs() + d2.abs()) / (1u64 << basis.shift) as f64;
                assert!(
                    off <= bound,
                    "{o:?} {area2} f={f} ({} {} {}): {} against {exact}, off {off}",
                    a.to_bits(),
                    b.to_bits(),
                    c.to_bits(),
                    got.to_bits()
                );
                checked += 1;
            }
        }
        assert!(checked > 300_000, "{checked}");
    }

    #[test]
    fn planes_cleared_by_their_values_pass_the_exact_check() {
        // `clear_of_bounds` must imply `plane_within`: triangles of every
        // size and shape, values anywhere in ranges as narrow as a color
        // channel's and as wide as depth's or texture coordinates', many
        // of them next to a bound.
        let mut next = xorshift(0x9E37_79B9u32);
        let ranges = [(0, 256 << 16), (1 << 15, 65535 << 15), (-30_000 << 16, 30_000 << 16), (-66_191, 66_191)];
        let (mut cleared, mut exact_only) = (0, 0);
        for _ in 0..300_000 {
            let Some((o, area2, f)) = random_triangle(&mut next) else {
                continue;
            };
            let (lo, hi) = ranges[next() as usize % ranges.len()];
            let width = (hi as i64 - lo as i64) as u64;
            let mut value = || {
                let near = next() % (1 << (next() % 24)) as u32;
                let v = match next() % 3 {
                    0 => lo as i64 + near as i64,
                    1 => hi as i64 - near as i64,
                    _ => lo as i64 + ((next() as u64 * width) >> 32) as i64,
                };
                Fixed::from_bits(v.clamp(lo as i64, hi as i64) as i32)
            };
            let (a, b, c) = (value(), value(), value());
            let basis = Fixed::basis(o, area2, f);
            let (gx, gy) = Fixed::gradients(&basis, a, b, c);
            let (lo, hi) = (Fixed::from_bits(lo), Fixed::from_bits(hi));
            let exact = !gx.is_wide() && !gy.is_wide() && Fixed::plane_within(a, gx, gy, (o[0], o[1]), (o[2], o[3]), f, lo, hi);
            if Fixed::clear_of_bounds(&basis, a, b, c, lo, hi) && !gx.is_wide() && !gy.is_wide() {
                assert!(exact, "{o:?} {area2} f={f} {basis:?}: {a:?} {b:?} {c:?} in {lo:?}..{hi:?}");
                cleared += 1;
            } else if exact {
                exact_only += 1;
            }
        }
        // Both outcomes occur often: the test is not vacuous.
        assert!(cleared > 50_000 && exact_only > 10_000, "{cleared} {exact_only}");
    }

    #[test]
    fn wide_gradients_are_those_of_32000_or_more() {
        let wide = |bits: i32| Fixed::from_bits(bits).is_wide();
        let limit = 32_000 << 16;
        assert!(!wide(0) && !wide(limit - 1) && !wide(-(limit - 1)));
        assert!(wide(limit) && wide(-limit) && wide(i32::MAX) && wide(i32::MIN));
    }
}
