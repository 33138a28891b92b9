//! Test helpers: an independent coverage oracle and wrappers that run the
//! renderer on window-space triangles.
#![allow(dead_code)]

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use soft3d::effect::FragmentCount;
use soft3d::host::Image;
use soft3d::material::DepthOff;
use soft3d::math::{Fixed, Mat4};
use soft3d::tri::TriVertex;
use soft3d::{Cull, HostRenderer, Lights, Material, Precision, Settings};

/// Snaps a coordinate to the 1/2^bits grid, in units of 1/2^bits pixel,
/// rounding half up (the documented convention).
pub fn snap(v: f64, bits: u32) -> i128 {
    (v * (1u64 << bits) as f64 + 0.5).floor() as i128
}

/// The reference coverage of one triangle: pixel centers inside, or on a
/// top or left edge, decided with edge functions in i128 on the snapped
/// vertices. Independent of the rasterizer's scanline walk.
pub fn oracle(tri: &[(f64, f64); 3], width: usize, height: usize, bits: u32) -> Vec<u8> {
    let mut out = vec![0u8; width * height];
    // Work in units of 1/2^(bits+1) so centers are integers.
    let mut p: Vec<(i128, i128)> = tri.iter().map(|&(x, y)| (2 * snap(x, bits), 2 * snap(y, bits))).collect();
    let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[1].1 - p[0].1) * (p[2].0 - p[0].0);
    if area == 0 {
        return out;
    }
    if area < 0 {
        p.swap(1, 2);
    }
    let half = 1i128 << bits;
    for y in 0..height {
        for x in 0..width {
            let (cx, cy) = (((x as i128) << (bits + 1)) + half, ((y as i128) << (bits + 1)) + half);
            let inside = (0..3).all(|i| {
                let (a, b) = (p[i], p[(i + 1) % 3]);
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let e = dx * (cy - a.1) - dy * (cx - a.0);
                // y down: a top edge is horizontal going right (interior
                // below); a left edge goes up (interior to its right).
                let top_left = (dy == 0 && dx > 0) || dy < 0;
                e > 0 || (e == 0 && top_left)
            });
            if inside {
                out[y * width + x] = 1;
            }
        }
    }
    out
}

/// A window-space triangle vertex with w = 1 and a white color.
pub fn tv(x: f64, y: f64) -> TriVertex {
    TriVertex { x, y, z: 0.5, w: 1.0, color: Rgb888::WHITE }
}

/// Fragment counts (before any depth test) of `tris` drawn in one frame.
pub fn coverage_with<S: Settings>(tris: &[[TriVertex; 3]], width: usize, height: usize, strip: usize, cull: Cull) -> Vec<u8> {
    let verts = tris.len() * 9 + 3;
    let mut r: HostRenderer<Rgb888, 3, S> = HostRenderer::new(width, height, strip, verts, tris.len() * 7 + 1, Rgb888::BLACK).unwrap();
    let material = Material::new(FragmentCount).with_cull(cull).with_depth::<DepthOff>();
    let mut frame = r.begin_frame_with(Mat4::IDENTITY, &Lights::UNLIT, Rgb888::BLACK);
    frame.draw_window_triangles(tris.iter().copied(), &material).unwrap();
    let mut img = Image::new(width as u32, height as u32, Rgb888::BLACK);
    let Ok(_) = frame.finish(&mut img);
    img.pixels.iter().map(|c| c.r()).collect()
}

/// [`coverage_with`] for a run-time sub-pixel setting (fixed point).
pub fn coverage(tris: &[[TriVertex; 3]], width: usize, height: usize, strip: usize, bits: u32) -> Vec<u8> {
    coverage_mode(tris, width, height, strip, bits, false)
}

/// [`coverage_with`] for a run-time sub-pixel setting and scalar.
pub fn coverage_mode(tris: &[[TriVertex; 3]], width: usize, height: usize, strip: usize, bits: u32, float: bool) -> Vec<u8> {
    macro_rules! go {
        ($($b:literal)*) => {
            match (bits, float) {
                $(($b, false) => coverage_with::<Precision<Fixed, $b>>(tris, width, height, strip, Cull::None),
                  ($b, true) => coverage_with::<Precision<f32, $b>>(tris, width, height, strip, Cull::None),)*
                _ => panic!("bits"),
            }
        };
    }
    go!(0 1 2 3 4 5 6 7 8)
}

/// A small deterministic PRNG (xorshift64*), so tests need no seed files.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi), rounded to a multiple of `step`.
    pub fn grid(&mut self, lo: f64, hi: f64, step: f64) -> f64 {
        (self.range(lo, hi) / step).round() * step
    }
}

/// Describes where two coverage images differ.
pub fn diff(a: &[u8], b: &[u8], width: usize) -> String {
    let bad: Vec<String> = a
        .iter()
        .zip(b)
        .enumerate()
        .filter(|(_, (x, y))| x != y)
        .take(10)
        .map(|(i, (x, y))| format!("({}, {}): {x} vs {y}", i % width, i / width))
        .collect();
    format!("{} pixels differ, first: {}", a.iter().zip(b).filter(|(x, y)| x != y).count(), bad.join("; "))
}

/// Compares with `tests/golden/NAME.png`; `SOFT3D_BLESS=1` rewrites it.
pub fn golden(name: &str, img: &Image<embedded_graphics::pixelcolor::Rgb565>) {
    let path = format!("{}/tests/golden/{name}.png", env!("CARGO_MANIFEST_DIR"));
    if std::env::var_os("SOFT3D_BLESS").is_some() {
        img.save_png(&path).unwrap();
        eprintln!("blessed {path}");
        return;
    }
    let want = soft3d::host::load_png(&path).unwrap_or_else(|e| panic!("{path}: {e} (run with SOFT3D_BLESS=1 to create it)"));
    let got: Vec<Rgb888> = img.pixels.iter().map(|&c| c.into()).collect();
    assert_eq!((want.width, want.height), (img.width, img.height));
    let differ = got.iter().zip(&want.pixels).filter(|(a, b)| a != b).count();
    if differ != 0 {
        let out = std::env::temp_dir().join(format!("{name}-actual.png"));
        img.save_png(&out).unwrap();
        let ch = |a: u8, b: u8| a.abs_diff(b);
        let worst = got.iter().zip(&want.pixels).map(|(a, b)| ch(a.r(), b.r()).max(ch(a.g(), b.g())).max(ch(a.b(), b.b()))).max();
        panic!(
            "{name}: {differ} pixels differ from {path} (largest channel difference {worst:?} of 255); actual image written to {}",
            out.display()
        );
    }
}
