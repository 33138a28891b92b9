//! Textures: RGB565 texels in flash, sampled nearest or bilinear, wrapped
//! or clamped, every choice a type so each combination is its own span loop.
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
    /// The texel slice does not hold `width * height` texels.
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
/// at v = 0). Validated once when built, in `const` context if wanted.
#[derive(Clone, Copy, Debug)]
pub struct Texture<'a> {
    texels: &'a [u16],
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
        Ok(Self { texels, width_log2, height_log2 })
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

    /// Texel at integer coordinates, wrapped or clamped by `W`.
    #[inline(always)]
    pub fn texel<W: Wrap>(&self, x: i32, y: i32) -> u16 {
        let x = W::apply(x, self.width_log2) as usize;
        let y = W::apply(y, self.height_log2) as usize;
        // Both are within the texture after `apply`; the mask keeps the
        // index provably in bounds without a panic path.
        let i = (y << self.width_log2 | x) & (self.texels.len() - 1);
        self.texels.get(i).copied().unwrap_or(0)
    }

    /// The texel channels `(r, g, b)` (5, 6 and 5 bits) at a point given
    /// in texel units with 16 fractional bits.
    #[inline(always)]
    pub fn sample<F: Filter, W: Wrap>(&self, u: i32, v: i32) -> (u32, u32, u32) {
        F::sample::<W>(self, u, v)
    }
}

/// What happens outside `[0, size)`.
pub trait Wrap: 'static {
    /// Name for reports.
    const NAME: &'static str;
    /// Whether coordinates repeat with the texture's size as period.
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
        t.clamp(0, (1 << size_log2) - 1)
    }
}

/// How a texel color is made from the texture around a point.
pub trait Filter: 'static {
    /// Name for reports.
    const NAME: &'static str;
    /// Channels (5, 6, 5 bits) at `(u, v)` in texel units with 16
    /// fractional bits.
    fn sample<W: Wrap>(texture: &Texture<'_>, u: i32, v: i32) -> (u32, u32, u32);
}

#[inline(always)]
fn channels(t: u16) -> (u32, u32, u32) {
    let t = t as u32;
    (t >> 11, (t >> 5) & 0x3F, t & 0x1F)
}

/// The texel containing the point.
#[derive(Clone, Copy, Debug, Default)]
pub struct Nearest;
impl Filter for Nearest {
    const NAME: &'static str = "nearest";
    #[inline(always)]
    fn sample<W: Wrap>(texture: &Texture<'_>, u: i32, v: i32) -> (u32, u32, u32) {
        channels(texture.texel::<W>(u >> 16, v >> 16))
    }
}

/// The four texels around the point, weighted by distance to their
/// centers (8-bit weights), wrapped or clamped like single texels.
#[derive(Clone, Copy, Debug, Default)]
pub struct Bilinear;
impl Filter for Bilinear {
    const NAME: &'static str = "bilinear";
    #[inline(always)]
    fn sample<W: Wrap>(texture: &Texture<'_>, u: i32, v: i32) -> (u32, u32, u32) {
        // Texel centers are at half units.
        let (u, v) = (u.wrapping_sub(1 << 15), v.wrapping_sub(1 << 15));
        let (x, y) = (u >> 16, v >> 16);
        let (fx, fy) = (((u >> 8) & 0xFF) as u32, ((v >> 8) & 0xFF) as u32);
        let w = [(256 - fx) * (256 - fy), fx * (256 - fy), (256 - fx) * fy, fx * fy];
        let t = [texture.texel::<W>(x, y), texture.texel::<W>(x + 1, y), texture.texel::<W>(x, y + 1), texture.texel::<W>(x + 1, y + 1)];
        // Weights sum to 2^16; start at one half for rounding.
        let (mut r, mut g, mut b) = (1u32 << 15, 1u32 << 15, 1u32 << 15);
        for k in 0..4 {
            let (tr, tg, tb) = channels(t[k]);
            r += tr * w[k];
            g += tg * w[k];
            b += tb * w[k];
        }
        (r >> 16, g >> 16, b >> 16)
    }
}
