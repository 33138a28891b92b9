//! Textures: RGB565 texels in flash, optionally with an 8-bit alpha plane,
//! sampled nearest or bilinear, wrapped or clamped, every choice a type so
//! each combination is its own span loop.
//!
//! Texture coordinates follow Babylon's exported UVs: u to the right, v
//! down the image as stored (row 0 at v = 0). Effects interpolate them in
//! texel units (`u * width`, `v * height`), so the texel under a pixel
//! center is `floor(u)`, and sampling only needs integer operations.

/// Why a texture was rejected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureError {
    /// Width or height is not a power of two between 1 and 32768.
    Size {
        /// The width given.
        width: usize,
        /// The height given.
        height: usize,
    },
    /// The texel (or alpha) slice does not hold `width * height` values.
    Length {
        /// Texels expected.
        expected: usize,
        /// Texels given.
        found: usize,
    },
}

impl core::fmt::Display for TextureError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self {
            TextureError::Size { width, height } => {
                write!(f, "texture is {width}×{height}; both sides must be powers of two from 1 to 32768")
            }
            TextureError::Length { expected, found } => write!(f, "texture needs {expected} texels, got {found}"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for TextureError {}

/// A power-of-two RGB565 texture borrowing its texels (row-major, first row
/// at v = 0), and optionally an alpha plane of one byte per texel (same
/// order; 0 transparent, 255 opaque). Validated once when built, in
/// `const` context if wanted. Only materials that blend read the alpha
/// plane (see [`AlphaBlend`](crate::blend::AlphaBlend)); a texture without
/// one is opaque.
#[derive(Clone, Copy, Debug)]
pub struct Texture<'a> {
    texels: &'a [u16],
    alpha: &'a [u8],
    width_log2: u32,
    height_log2: u32,
}

const fn log2_pow2(v: usize) -> Option<u32> {
    if v == 0 || v > 1 << 15 || !v.is_power_of_two() {
        None
    } else {
        Some(v.trailing_zeros())
    }
}

impl<'a> Texture<'a> {
    /// A `width`×`height` texture over `texels` (RGB565 raw values).
    pub const fn new(texels: &'a [u16], width: usize, height: usize) -> Result<Self, TextureError> {
        let (Some(width_log2), Some(height_log2)) = (log2_pow2(width), log2_pow2(height)) else {
            return Err(TextureError::Size { width, height });
        };
        if texels.len() != width * height {
            return Err(TextureError::Length { expected: width * height, found: texels.len() });
        }
        Ok(Self { texels, alpha: &[], width_log2, height_log2 })
    }

    /// The texture with an alpha plane: one byte per texel, in the order of
    /// the texels.
    pub const fn with_alpha(self, alpha: &'a [u8]) -> Result<Self, TextureError> {
        if alpha.len() != self.texels.len() {
            return Err(TextureError::Length { expected: self.texels.len(), found: alpha.len() });
        }
        Ok(Self { alpha, ..self })
    }

    /// The alpha plane (empty if the texture is opaque).
    pub const fn alpha(&self) -> &'a [u8] {
        self.alpha
    }

    /// Width in texels.
    pub const fn width(&self) -> usize {
        1 << self.width_log2
    }

    /// Height in texels.
    pub const fn height(&self) -> usize {
        1 << self.height_log2
    }

    /// The texels.
    pub const fn texels(&self) -> &'a [u16] {
        self.texels
    }

    /// Index of the texel at integer coordinates, wrapped or clamped by `W`.
    #[inline(always)]
    fn index<W: Wrap>(&self, x: i32, y: i32) -> usize {
        let x = W::apply(x, self.width_log2) as usize;
        // The mask below keeps the index provably in bounds without a
        // panic path, and wraps a repeating `y` by itself.
        let y = if W::PERIODIC { y } else { W::apply(y, self.height_log2) } as usize;
        (y << self.width_log2 | x) & (self.texels.len() - 1)
    }

    /// Texel at integer coordinates, wrapped or clamped by `W`.
    #[inline(always)]
    pub fn texel<W: Wrap>(&self, x: i32, y: i32) -> u16 {
        self.texels.get(self.index::<W>(x, y)).copied().unwrap_or(0)
    }

    /// Texel and alpha (255 without an alpha plane) at integer coordinates.
    #[inline(always)]
    fn texel_alpha<W: Wrap>(&self, x: i32, y: i32, alpha: bool) -> (u16, u32) {
        let i = self.index::<W>(x, y);
        let a = if alpha { self.alpha.get(i).map_or(255, |&a| a as u32) } else { 255 };
        (self.texels.get(i).copied().unwrap_or(0), a)
    }

    /// The texel channels (5, 6 and 5 bits, and alpha 0–255 if `alpha`,
    /// else 255) at a point given in texel units with 16 fractional bits.
    /// Inlined, so a constant `alpha` costs nothing when false.
    #[inline(always)]
    pub fn sample<F: Filter, W: Wrap>(&self, u: i32, v: i32, alpha: bool) -> Texel {
        F::sample::<W>(self, u, v, alpha)
    }
}

/// What happens outside `[0, size)`.
pub trait Wrap: 'static {
    /// Name for reports.
    const NAME: &'static str;
    /// Whether coordinates repeat with the texture's size as period. A
    /// periodic wrap's [`Wrap::apply`] must then be `t mod 2^size_log2`
    /// (as [`Repeat`]'s is): a texel's row is wrapped by the index's own
    /// mask, without `apply`.
    const PERIODIC: bool;
    /// Maps an integer texel coordinate into `[0, 2^size_log2)`.
    fn apply(t: i32, size_log2: u32) -> i32;
}

/// Repeat: a true modulo, negative coordinates included.
#[derive(Clone, Copy, Debug, Default)]
pub struct Repeat;
impl Wrap for Repeat {
    const NAME: &'static str = "repeat";
    const PERIODIC: bool = true;
    #[inline(always)]
    fn apply(t: i32, size_log2: u32) -> i32 {
        // Two's complement: masking is the floor modulo for powers of two.
        t & ((1 << size_log2) - 1)
    }
}

/// Clamp to the edge texels.
#[derive(Clone, Copy, Debug, Default)]
pub struct Clamp;
impl Wrap for Clamp {
    const NAME: &'static str = "clamp";
    const PERIODIC: bool = false;
    #[inline(always)]
    fn apply(t: i32, size_log2: u32) -> i32 {
        t.max(0).min((1 << size_log2) - 1)
    }
}

/// A sampled texture color: red and blue in 5 bits, green in 6, alpha in 8.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Texel {
    /// Red, 0–31.
    pub r: u32,
    /// Green, 0–63.
    pub g: u32,
    /// Blue, 0–31.
    pub b: u32,
    /// Alpha, 0 (transparent) to 255 (opaque).
    pub a: u32,
}

impl Texel {
    #[inline(always)]
    fn new(t: u16, a: u32) -> Self {
        let t = t as u32;
        Self { r: t >> 11, g: (t >> 5) & 0x3F, b: t & 0x1F, a }
    }
}

/// How a texel color is made from the texture around a point.
pub trait Filter: 'static {
    /// Name for reports.
    const NAME: &'static str;
    /// The color at `(u, v)` in texel units with 16 fractional bits; the
    /// alpha plane is read only if `alpha`.
    fn sample<W: Wrap>(texture: &Texture<'_>, u: i32, v: i32, alpha: bool) -> Texel;
}

/// The texel containing the point.
#[derive(Clone, Copy, Debug, Default)]
pub struct Nearest;
impl Filter for Nearest {
    const NAME: &'static str = "nearest";
    #[inline(always)]
    fn sample<W: Wrap>(texture: &Texture<'_>, u: i32, v: i32, alpha: bool) -> Texel {
        let (t, a) = texture.texel_alpha::<W>(u >> 16, v >> 16, alpha);
        Texel::new(t, a)
    }
}

/// The four texels around the point, weighted by distance to their
/// centers (8-bit weights), wrapped or clamped like single texels.
#[derive(Clone, Copy, Debug, Default)]
pub struct Bilinear;
impl Filter for Bilinear {
    const NAME: &'static str = "bilinear";
    #[inline(always)]
    fn sample<W: Wrap>(texture: &Texture<'_>, u: i32, v: i32, alpha: bool) -> Texel {
        // Texel centers are at half units. Saturating: a coordinate already
        // clamped to i32::MIN must not wrap to the opposite edge.
        let (u, v) = (u.saturating_sub(1 << 15), v.saturating_sub(1 << 15));
        let (x, y) = (u >> 16, v >> 16);
        let (fx, fy) = (((u >> 8) & 0xFF) as u32, ((v >> 8) & 0xFF) as u32);
        let w = [(256 - fx) * (256 - fy), fx * (256 - fy), (256 - fx) * fy, fx * fy];
        let corners = [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)];
        // Weights sum to 2^16; start at one half for rounding.
        let mut sum = Texel { r: 1 << 15, g: 1 << 15, b: 1 << 15, a: 1 << 15 };
        for (k, &(cx, cy)) in corners.iter().enumerate() {
            let (t, a) = texture.texel_alpha::<W>(cx, cy, alpha);
            let t = Texel::new(t, a);
            sum.r += t.r * w[k];
            sum.g += t.g * w[k];
            sum.b += t.b * w[k];
            if alpha {
                sum.a += t.a * w[k];
            }
        }
        Texel { r: sum.r >> 16, g: sum.g >> 16, b: sum.b >> 16, a: if alpha { sum.a >> 16 } else { 255 } }
    }
}

#[cfg(feature = "std")]
mod convert;
#[cfg(feature = "std")]
pub use convert::{resample, rgb565, OwnedTexture};
#[cfg(feature = "textures")]
mod load;
#[cfg(feature = "textures")]
pub use load::{read_image, read_jpeg, read_png};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texel_wraps_and_clamps_any_coordinate() {
        // A rectangular texture (8 by 4) whose every texel is its own index.
        let texels: [u16; 32] = core::array::from_fn(|i| i as u16);
        let t = Texture::new(&texels, 8, 4).unwrap();
        for y in -70i32..70 {
            for x in -70i32..70 {
                let repeat = (y.rem_euclid(4) * 8 + x.rem_euclid(8)) as u16;
                assert_eq!(t.texel::<Repeat>(x, y), repeat, "repeat {x},{y}");
                let clamp = (y.clamp(0, 3) * 8 + x.clamp(0, 7)) as u16;
                assert_eq!(t.texel::<Clamp>(x, y), clamp, "clamp {x},{y}");
            }
        }
        for (x, y) in [(i32::MIN, i32::MAX), (i32::MAX, i32::MIN), (i32::MIN, i32::MIN)] {
            assert_eq!(t.texel::<Repeat>(x, y), (y.rem_euclid(4) * 8 + x.rem_euclid(8)) as u16);
        }
    }
}
