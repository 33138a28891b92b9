//! Textures: decode (JPEG/PNG), fit to power-of-two sizes, convert to
//! RGB565, optionally reduce to a 256-color palette.

use crate::{BakeError, BakedTexture, Texels, TextureFormat};
use soft3d::texture::{read_image, resample, OwnedTexture};
use std::path::Path;

/// RGB888 to RGB565 with rounding to the nearest level: the core's
/// conversion, which the simulator's texture loader uses too.
pub use soft3d::texture::rgb565;

/// RGB565 back to RGB888, each level to the nearest 8-bit value.
pub fn rgb565_to_rgb888(c: u16) -> [u8; 3] {
    let e = |v: u16, max: u32| ((v as u32 * 255 + max / 2) / max) as u8;
    [e(c >> 11, 31), e((c >> 5) & 63, 63), e(c & 31, 31)]
}

/// The largest side `soft3d::texture::Texture` accepts.
const MAX_SIDE: u32 = 1 << 15;

/// Reads, decodes and converts one texture with the core's
/// `soft3d::texture::OwnedTexture::from_rgba`, exactly as the simulator's
/// loader does: sides that are not powers of two (or exceed `max_size`) are
/// averaged down per side to the largest power of two that fits; an alpha
/// plane is kept if any pixel is not opaque.
pub fn bake(
    name: &str,
    ident: String,
    path: &Path,
    format: TextureFormat,
    max_size: Option<u32>,
    warnings: &mut Vec<String>,
) -> Result<BakedTexture, BakeError> {
    let fail = |problem: String| BakeError::Texture { name: name.to_string(), path: path.to_path_buf(), problem };
    // The core's reader, as the simulator uses: the same pixels from the same file.
    if !path.is_file() {
        return Err(fail("cannot read it: no such file (use --textures DIR to say where textures are, or --texture-format none)".into()));
    }
    let (width, height, pixels) = read_image(path).map_err(|e| fail(format!("cannot decode it (JPEG and PNG are supported): {e}")))?;
    let source_size = (width, height);
    let limit = max_size.unwrap_or(MAX_SIDE).clamp(1, MAX_SIDE) as usize;
    let owned =
        OwnedTexture::from_rgba(width as usize, height as usize, &pixels, limit).map_err(|e| fail(format!("cannot decode it: {e}")))?;
    let size = (owned.width as u32, owned.height as u32);
    let resampled = if size == source_size {
        pixels
    } else {
        warnings.push(format!(
            "texture '{name}': {}×{} resized to {}×{} (power-of-two sides{}; box filter)",
            source_size.0,
            source_size.1,
            size.0,
            size.1,
            max_size.map_or(String::new(), |m| format!(", at most {m}"))
        ));
        resample(source_size.0 as usize, source_size.1 as usize, &pixels, owned.width, owned.height)
    };
    let source: Vec<[u8; 3]> = resampled.iter().map(|p| [p[0], p[1], p[2]]).collect();
    let expanded: Vec<[u8; 3]> = owned.texels.iter().map(|&c| rgb565_to_rgb888(c)).collect();
    let psnr_rgb565 = psnr(&source, &expanded);
    let alpha = owned.alpha;
    let (texels, psnr_palette) = match format {
        TextureFormat::Palette8 => {
            let (palette, indices) = palettize(&owned.texels);
            let mapped: Vec<[u8; 3]> = indices.iter().map(|&i| rgb565_to_rgb888(palette[i as usize])).collect();
            (Texels::Palette8 { palette, indices }, Some(psnr(&expanded, &mapped)))
        }
        _ => (Texels::Rgb565(owned.texels), None),
    };
    Ok(BakedTexture {
        name: name.to_string(),
        ident,
        path: path.to_path_buf(),
        source_size,
        size,
        texels,
        alpha,
        psnr_rgb565,
        psnr_palette,
    })
}

/// Peak signal-to-noise ratio in dB over the three channels (infinite for
/// identical images).
pub fn psnr(a: &[[u8; 3]], b: &[[u8; 3]]) -> f64 {
    let mut sum = 0.0;
    for (x, y) in a.iter().zip(b) {
        for k in 0..3 {
            let d = x[k] as f64 - y[k] as f64;
            sum += d * d;
        }
    }
    let n = (a.len().min(b.len()) * 3).max(1) as f64;
    let mse = sum / n;
    if mse == 0.0 {
        f64::INFINITY
    } else {
        10.0 * (255.0 * 255.0 / mse).log10()
    }
}

/// A distinct RGB565 color of the image, expanded to 8 bits, with its
/// pixel count.
#[derive(Clone, Copy)]
struct Entry {
    rgb: [f64; 3],
    count: f64,
}

/// Reduces RGB565 texels to a 256-entry palette: median cut over the
/// image's distinct colors (always splitting the box with the largest
/// squared error, at the weighted median of its widest-spread channel),
/// then a few k-means (Lloyd) passes to move the entries to their
/// clusters' means. Returns the palette (unused entries 0) and the indices.
pub fn palettize(texels: &[u16]) -> (Vec<u16>, Vec<u8>) {
    let mut counts = vec![0u32; 1 << 16];
    for &t in texels {
        counts[t as usize] += 1;
    }
    let colors: Vec<u16> = (0..=u16::MAX).filter(|&c| counts[c as usize] > 0).collect();
    let mut palette: Vec<u16> = if colors.len() <= 256 {
        colors.clone()
    } else {
        let entries: Vec<Entry> = colors
            .iter()
            .map(|&c| {
                let [r, g, b] = rgb565_to_rgb888(c);
                Entry { rgb: [r as f64, g as f64, b as f64], count: counts[c as usize] as f64 }
            })
            .collect();
        let centers = kmeans(&entries, median_cut(&entries, 256));
        centers.iter().map(|c| rgb565(channel(c[0]), channel(c[1]), channel(c[2]))).collect()
    };
    let lookup: Vec<[i32; 3]> = palette.iter().map(|&c| rgb565_to_rgb888(c).map(i32::from)).collect();
    // Each distinct color maps to its nearest palette entry, once.
    let mut index_of = vec![0u8; 1 << 16];
    for &c in &colors {
        let rgb = rgb565_to_rgb888(c).map(i32::from);
        let nearest = (0..lookup.len()).min_by_key(|&i| distance2(rgb, lookup[i])).unwrap_or(0);
        index_of[c as usize] = nearest as u8;
    }
    let indices = texels.iter().map(|&t| index_of[t as usize]).collect();
    palette.resize(256, 0);
    (palette, indices)
}

fn channel(v: f64) -> u8 {
    v.round().clamp(0.0, 255.0) as u8
}

fn distance2(a: [i32; 3], b: [i32; 3]) -> i32 {
    (0..3).map(|k| (a[k] - b[k]) * (a[k] - b[k])).sum()
}

/// Weighted mean and squared error of a set of entries.
fn stats(entries: &[Entry], set: &[usize]) -> ([f64; 3], f64) {
    let mut sum = [0.0; 3];
    let mut n = 0.0;
    for &i in set {
        for (s, c) in sum.iter_mut().zip(entries[i].rgb) {
            *s += c * entries[i].count;
        }
        n += entries[i].count;
    }
    let mean = sum.map(|s| s / n.max(1.0));
    let mut sse = 0.0;
    for &i in set {
        for (c, m) in entries[i].rgb.iter().zip(mean) {
            sse += (c - m) * (c - m) * entries[i].count;
        }
    }
    (mean, sse)
}

/// Splits the color set into at most `k` boxes; returns their means.
fn median_cut(entries: &[Entry], k: usize) -> Vec<[f64; 3]> {
    let mut boxes: Vec<(Vec<usize>, f64)> = vec![{
        let all: Vec<usize> = (0..entries.len()).collect();
        let sse = stats(entries, &all).1;
        (all, sse)
    }];
    while boxes.len() < k {
        // The box with the largest error that can still be split.
        let Some(pick) = (0..boxes.len()).filter(|&b| boxes[b].0.len() > 1).max_by(|&a, &b| boxes[a].1.total_cmp(&boxes[b].1)) else {
            break;
        };
        let (mut set, _) = boxes.swap_remove(pick);
        // Split along the channel with the largest weighted variance.
        let mean = stats(entries, &set).0;
        let spread = |k: usize| set.iter().map(|&i| (entries[i].rgb[k] - mean[k]).powi(2) * entries[i].count).sum::<f64>();
        let axis = (0..3).max_by(|&a, &b| spread(a).total_cmp(&spread(b))).unwrap_or(0);
        set.sort_by(|&a, &b| entries[a].rgb[axis].total_cmp(&entries[b].rgb[axis]).then(a.cmp(&b)));
        let total: f64 = set.iter().map(|&i| entries[i].count).sum();
        let mut acc = 0.0;
        let mut cut = 1;
        for (j, &i) in set.iter().enumerate() {
            acc += entries[i].count;
            if acc >= total / 2.0 {
                cut = j + 1;
                break;
            }
        }
        let cut = cut.clamp(1, set.len() - 1);
        let upper = set.split_off(cut);
        for part in [set, upper] {
            let sse = stats(entries, &part).1;
            boxes.push((part, sse));
        }
    }
    boxes.iter().map(|(set, _)| stats(entries, set).0).collect()
}

/// Lloyd iterations: assign every color to its nearest center, move each
/// center to its cluster's weighted mean; stops when nothing moves.
fn kmeans(entries: &[Entry], mut centers: Vec<[f64; 3]>) -> Vec<[f64; 3]> {
    let mut assignment = vec![usize::MAX; entries.len()];
    for _ in 0..8 {
        let mut changed = false;
        let mut sums = vec![[0.0f64; 4]; centers.len()];
        for (e, slot) in entries.iter().zip(assignment.iter_mut()) {
            let mut best = (0, f64::INFINITY);
            for (c, center) in centers.iter().enumerate() {
                let d = (0..3).map(|k| (e.rgb[k] - center[k]).powi(2)).sum::<f64>();
                if d < best.1 {
                    best = (c, d);
                }
            }
            changed |= *slot != best.0;
            *slot = best.0;
            let s = &mut sums[best.0];
            for (s, c) in s.iter_mut().zip(e.rgb) {
                *s += c * e.count;
            }
            s[3] += e.count;
        }
        for (center, s) in centers.iter_mut().zip(&sums) {
            if s[3] > 0.0 {
                *center = [s[0] / s[3], s[1] / s[3], s[2] / s[3]];
            }
        }
        if !changed {
            break;
        }
    }
    centers
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rgb565_rounds_and_expands_to_the_extremes() {
        assert_eq!(rgb565(255, 255, 255), 0xFFFF);
        assert_eq!(rgb565(0, 0, 0), 0);
        assert_eq!(rgb565(255, 0, 0), 0xF800);
        assert_eq!(rgb565(4, 2, 4), 0x0000); // 4·31/255 = 0.49 rounds down
        assert_eq!(rgb565(5, 3, 5), 0x0821); // 0.61 rounds up
        assert_eq!(rgb565_to_rgb888(0xFFFF), [255, 255, 255]);
        for c in 0..=255u8 {
            // Expanding a level and reducing it again gives the level back.
            let v = rgb565(c, c, c);
            let [r, g, b] = rgb565_to_rgb888(v);
            assert_eq!(rgb565(r, g, b), v);
        }
    }

    #[test]
    fn small_images_keep_their_colors() {
        let texels = [0xF800, 0x07E0, 0x001F, 0xF800];
        let (palette, indices) = palettize(&texels);
        assert_eq!(palette.len(), 256);
        for (t, i) in texels.iter().zip(&indices) {
            assert_eq!(palette[*i as usize], *t);
        }
    }

    #[test]
    fn a_gradient_palettizes_well() {
        let texels: Vec<u16> =
            (0..64 * 64).map(|i| rgb565((i % 64 * 4) as u8, (i / 64 * 4) as u8, ((i % 64 + i / 64) * 2) as u8)).collect();
        let (palette, indices) = palettize(&texels);
        let a: Vec<[u8; 3]> = texels.iter().map(|&c| rgb565_to_rgb888(c)).collect();
        let b: Vec<[u8; 3]> = indices.iter().map(|&i| rgb565_to_rgb888(palette[i as usize])).collect();
        let p = psnr(&a, &b);
        assert!(p > 30.0, "{p}");
    }
}
