//! How far a core render is from the reference.
//!
//! Colors are compared in 8-bit units after both go through the display's
//! format: the reference's exact color is rounded to RGB565 (what a perfect
//! renderer would show), then both are widened to 8 bits the way
//! `embedded-graphics` converts them. A perfect render scores zero error.

use crate::reference::RefImage;
use crate::render::CoreImages;
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};

/// Errors of one render.
#[derive(Clone, Copy, Debug, Default)]
pub struct Errors {
    /// Peak signal-to-noise ratio over the whole image, dB (`f64::INFINITY`
    /// when identical).
    pub psnr: f64,
    /// Largest channel error (8-bit units) where the same triangle is visible.
    pub max: u8,
    /// 99th percentile of the channel error there.
    pub p99: u8,
    /// Mean channel error there.
    pub mean: f64,
    /// Pixels covered in one image and not the other.
    pub coverage: usize,
    /// Pixels covered in both where a different object is visible (the
    /// depth test decided otherwise).
    pub depth: usize,
    /// Largest texture-coordinate error in texels where the same textured
    /// triangle is visible (`None` without textures).
    pub uv_max: Option<f64>,
    /// 99th percentile of it.
    pub uv_p99: Option<f64>,
    /// Pixels compared for color.
    pub pixels: usize,
}

impl Errors {
    /// Comma-separated fields, exact (`{:?}` round-trips every `f64`).
    pub fn to_fields(self) -> String {
        let opt = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:?}"));
        format!(
            "{:?},{},{},{:?},{},{},{},{},{}",
            self.psnr,
            self.max,
            self.p99,
            self.mean,
            self.coverage,
            self.depth,
            opt(self.uv_max),
            opt(self.uv_p99),
            self.pixels
        )
    }

    /// Parses what [`Errors::to_fields`] wrote (`FIELDS` values).
    pub fn from_fields(f: &[&str]) -> Option<Self> {
        if f.len() != Self::FIELDS {
            return None;
        }
        let opt = |s: &str| if s.is_empty() { Ok(None) } else { s.parse().map(Some) };
        Some(Errors {
            psnr: f[0].parse().ok()?,
            max: f[1].parse().ok()?,
            p99: f[2].parse().ok()?,
            mean: f[3].parse().ok()?,
            coverage: f[4].parse().ok()?,
            depth: f[5].parse().ok()?,
            uv_max: opt(f[6]).ok()?,
            uv_p99: opt(f[7]).ok()?,
            pixels: f[8].parse().ok()?,
        })
    }

    /// Fields [`Errors::to_fields`] writes.
    pub const FIELDS: usize = 9;
}

/// The exact color as the display shows it.
fn quantized(c: [f64; 3]) -> Rgb888 {
    let q = |v: f64, max: f64| (v.clamp(0.0, 1.0) * max).round() as u8;
    Rgb888::from(Rgb565::new(q(c[0], 31.0), q(c[1], 63.0), q(c[2], 31.0)))
}

fn percentile<T: Copy + PartialOrd>(v: &mut [T], p: f64) -> Option<T> {
    if v.is_empty() {
        return None;
    }
    v.sort_by(|a, b| a.partial_cmp(b).expect("no NaN"));
    let i = ((v.len() as f64 * p).ceil() as usize).clamp(1, v.len()) - 1;
    Some(v[i])
}

/// Compares `core` with `reference`; `sizes` are the textures' sides for
/// wrapping texture-coordinate differences.
pub fn compare(core: &CoreImages, reference: &RefImage, wrap: Option<(f64, f64)>) -> Errors {
    let mut sq = 0.0;
    let mut channel = Vec::new();
    let mut uv = Vec::new();
    let (mut coverage, mut depth) = (0, 0);
    for i in 0..core.color.len() {
        let (a, b) = (Rgb888::from(core.color[i]), quantized(reference.color[i]));
        let d = [a.r().abs_diff(b.r()), a.g().abs_diff(b.g()), a.b().abs_diff(b.b())];
        sq += d.iter().map(|&e| (e as f64).powi(2)).sum::<f64>();
        match (core.object[i], reference.object[i]) {
            (Some(x), Some(y)) if x == y => {
                // Shading is compared where the same triangle is visible (a
                // moved edge between two triangles is coverage, not shading).
                if core.triangle[i] != reference.triangle[i] {
                    continue;
                }
                channel.extend(d);
                if let (Some(p), Some(q), Some((w, h))) = (core.uv[i], reference.uv[i], wrap) {
                    // Differences modulo the texture (both are wrapped the
                    // same way when sampled).
                    let m = |d: f64, s: f64| (d + s / 2.0).rem_euclid(s) - s / 2.0;
                    uv.push(m(p[0] - q[0], w).abs().max(m(p[1] - q[1], h).abs()));
                }
            }
            (Some(_), Some(_)) => depth += 1,
            (None, None) => {}
            _ => coverage += 1,
        }
    }
    let mse = sq / (core.color.len() * 3) as f64;
    let psnr = if mse == 0.0 { f64::INFINITY } else { 10.0 * (255.0f64 * 255.0 / mse).log10() };
    let pixels = channel.len() / 3;
    let mean = if channel.is_empty() { 0.0 } else { channel.iter().map(|&e| e as f64).sum::<f64>() / channel.len() as f64 };
    let max = channel.iter().copied().max().unwrap_or(0);
    let p99 = percentile(&mut channel, 0.99).unwrap_or(0);
    let uv_max = uv.iter().copied().fold(None, |m: Option<f64>, e| Some(m.map_or(e, |m| m.max(e))));
    let uv_p99 = percentile(&mut uv, 0.99);
    Errors { psnr, max, p99, mean, coverage, depth, uv_max, uv_p99, pixels }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_render_equal_to_the_quantized_reference_has_no_error() {
        let reference = RefImage {
            width: 2,
            height: 1,
            color: vec![[0.5, 0.25, 1.0], [0.0; 3]],
            object: vec![Some(0), None],
            triangle: vec![Some(0), None],
            uv: vec![Some([1.0, 2.0]), None],
            depth: vec![0.5, f64::INFINITY],
        };
        let exact = Rgb565::new(16, 16, 31);
        let core = CoreImages {
            color: vec![exact, Rgb565::BLACK],
            object: vec![Some(0), None],
            triangle: vec![Some(0), None],
            uv: vec![Some([1.0, 2.0]), None],
        };
        let e = compare(&core, &reference, Some((8.0, 8.0)));
        assert_eq!((e.psnr, e.max, e.coverage, e.depth, e.uv_max), (f64::INFINITY, 0, 0, 0, Some(0.0)));
        // One level of green off, a coordinate a period and 1/8 texel off, the
        // background pixel covered by another object.
        let core = CoreImages {
            color: vec![Rgb565::new(16, 17, 31), Rgb565::WHITE],
            object: vec![Some(0), Some(1)],
            triangle: vec![Some(0), Some(5)],
            uv: vec![Some([9.125, 2.0]), None],
        };
        let e = compare(&core, &reference, Some((8.0, 8.0)));
        assert_eq!((e.max, e.coverage, e.depth), (4, 1, 0));
        assert!((e.uv_max.unwrap() - 0.125).abs() < 1e-12, "{:?}", e.uv_max);
        // Written and read back exactly.
        let line = e.to_fields();
        let back = Errors::from_fields(&line.split(',').collect::<Vec<_>>()).unwrap();
        assert_eq!(back.to_fields(), line);
        assert_eq!((back.psnr.to_bits(), back.uv_p99), (e.psnr.to_bits(), e.uv_p99));
        assert!(Errors::from_fields(&["1"; 8]).is_none());
    }
}
