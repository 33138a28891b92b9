//! Host side (`std`): images to textures. The run-time loader
//! (`soft3d::host`) and the bake tool both convert through here, so a
//! texture baked into flash has the very texels the simulator samples.

use super::{Texture, TextureError};
use std::vec::Vec;

/// Largest side a [`Texture`] takes.
const MAX_SIDE: usize = 1 << 15;

/// An 8-bit RGB color to RGB565, each channel rounded to the nearest level.
pub fn rgb565(r: u8, g: u8, b: u8) -> u16 {
    let q = |c: u8, max: u32| (c as u32 * max + 127) / 255;
    ((q(r, 31) << 11) | (q(g, 63) << 5) | q(b, 31)) as u16
}

/// Resizes RGBA pixels (row-major, `width`×`height`) to `to_width`×`to_height`
/// by averaging, for each output pixel, the input pixels whose centers fall
/// in its footprint (so every input pixel counts once when shrinking; when
/// enlarging, the nearest input pixel). Colors are weighted by alpha, so
/// transparent pixels do not darken the edges of opaque ones.
pub fn resample(width: usize, height: usize, rgba: &[[u8; 4]], to_width: usize, to_height: usize) -> Vec<[u8; 4]> {
    // Footprint of output index `i` along a side of `n` in, `m` out: the
    // inputs whose centers (k + 0.5) lie in [i·n/m, (i+1)·n/m), at least one.
    let span = |i: usize, n: usize, m: usize| {
        let lo = (2 * i * n + m - 1) / (2 * m);
        let hi = ((2 * (i + 1) * n + m - 1) / (2 * m)).max(lo + 1).min(n);
        lo.min(n - 1)..hi
    };
    let mut out = Vec::with_capacity(to_width * to_height);
    for y in 0..to_height {
        for x in 0..to_width {
            let (mut sum, mut alpha, mut count) = ([0u64; 3], 0u64, 0u64);
            let mut plain = [0u64; 3];
            for sy in span(y, height, to_height) {
                for sx in span(x, width, to_width) {
                    let p = rgba.get(sy * width + sx).copied().unwrap_or([0; 4]);
                    for c in 0..3 {
                        sum[c] += p[c] as u64 * p[3] as u64;
                        plain[c] += p[c] as u64;
                    }
                    alpha += p[3] as u64;
                    count += 1;
                }
            }
            let count = count.max(1);
            // Weighted by alpha, unless the footprint is fully transparent.
            let channel = |c: usize| match (sum[c] + alpha / 2).checked_div(alpha) {
                Some(v) => v as u8,
                None => ((plain[c] + count / 2) / count) as u8,
            };
            out.push([channel(0), channel(1), channel(2), ((alpha + count / 2) / count) as u8]);
        }
    }
    out
}

/// A texture that owns its texels: RGB565, and an alpha plane if any pixel
/// of the image it came from was not opaque.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OwnedTexture {
    /// RGB565 texels, row-major, first row at v = 0.
    pub texels: Vec<u16>,
    /// One alpha byte per texel, or `None` for an opaque texture.
    pub alpha: Option<Vec<u8>>,
    /// Width, a power of two.
    pub width: usize,
    /// Height, a power of two.
    pub height: usize,
}

impl OwnedTexture {
    /// Converts a `width`×`height` RGBA image. Sides that are not powers of
    /// two, or exceed `max_side` (at most 32768), are reduced per side to the
    /// largest power of two that fits, with [`resample`].
    pub fn from_rgba(width: usize, height: usize, rgba: &[[u8; 4]], max_side: usize) -> Result<Self, TextureError> {
        if width == 0 || height == 0 || rgba.len() != width * height {
            return Err(TextureError::Length { expected: width * height, found: rgba.len() });
        }
        let limit = max_side.clamp(1, MAX_SIDE);
        let fit = |n: usize| 1usize << (usize::BITS - 1 - n.min(limit).leading_zeros());
        let (w, h) = (fit(width), fit(height));
        let pixels = if (w, h) == (width, height) { rgba.to_vec() } else { resample(width, height, rgba, w, h) };
        let texels = pixels.iter().map(|p| rgb565(p[0], p[1], p[2])).collect();
        let alpha = pixels.iter().any(|p| p[3] < 255).then(|| pixels.iter().map(|p| p[3]).collect());
        Ok(Self { texels, alpha, width: w, height: h })
    }

    /// The texture view (with its alpha plane, if any).
    pub fn texture(&self) -> Result<Texture<'_>, TextureError> {
        let t = Texture::new(&self.texels, self.width, self.height)?;
        match &self.alpha {
            Some(a) => t.with_alpha(a),
            None => Ok(t),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rgb565_rounds_to_the_nearest_level() {
        assert_eq!(rgb565(0, 0, 0), 0);
        assert_eq!(rgb565(255, 255, 255), 0xFFFF);
        // 4 / 255 · 31 = 0.49 rounds down, 5 / 255 · 31 = 0.61 up.
        assert_eq!(rgb565(4, 0, 0) >> 11, 0);
        assert_eq!(rgb565(5, 0, 0) >> 11, 1);
    }

    #[test]
    fn halving_averages_each_two_by_two_block() {
        let px = |v: u8| [v, v, v, 255];
        let img = [px(0), px(100), px(10), px(10), px(200), px(50), px(10), px(10)];
        let out = resample(4, 2, &img, 2, 1);
        assert_eq!(out, std::vec![px(88), px(10)]);
    }

    #[test]
    fn transparent_pixels_do_not_darken_opaque_ones() {
        let img = [[255, 0, 0, 255], [0, 0, 0, 0]];
        assert_eq!(resample(2, 1, &img, 1, 1), std::vec![[255, 0, 0, 128]]);
    }

    #[test]
    fn odd_sizes_fit_the_largest_power_of_two_and_keep_alpha_only_when_used() {
        let opaque = std::vec![[1, 2, 3, 255]; 5 * 3];
        let t = OwnedTexture::from_rgba(5, 3, &opaque, 4096).unwrap();
        assert_eq!((t.width, t.height, t.alpha.is_none()), (4, 2, true));
        let mut clear = opaque.clone();
        clear[0][3] = 0;
        let t = OwnedTexture::from_rgba(5, 3, &clear, 2).unwrap();
        assert_eq!((t.width, t.height), (2, 2));
        assert!(t.alpha.as_ref().is_some_and(|a| a.len() == 4 && a[0] < 255));
        assert!(t.texture().is_ok());
        assert!(OwnedTexture::from_rgba(2, 2, &opaque[..3], 8).is_err());
    }
}
