//! Test helpers: an independent coverage oracle and wrappers that run the
//! renderer on window-space triangles.
#![allow(dead_code)]

use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use soft3d::effect::{FragmentCount, Textured};
use soft3d::host::Image;
use soft3d::material::DepthOff;
use soft3d::math::{Fixed, Mat4, Vec2, Vec3};
use soft3d::mesh::Mesh;
use soft3d::texture::{Filter, Texture, Wrap};
use soft3d::tri::TriVertex;
use soft3d::{Cull, FrameStats, HostRenderer, Lights, Material, Precision, Settings};

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
    // Only the bounding box can be covered (pixel n's center is at
    // (2n + 1) * 2^bits in these units); this keeps sums over many
    // triangles fast.
    let pixel = |v: i128| (v >> (bits + 1)).clamp(-1, 1 << 40);
    let (lo_x, hi_x) = (p.iter().map(|v| v.0).min().unwrap(), p.iter().map(|v| v.0).max().unwrap());
    let (lo_y, hi_y) = (p.iter().map(|v| v.1).min().unwrap(), p.iter().map(|v| v.1).max().unwrap());
    let xs = pixel(lo_x).max(0) as usize..(pixel(hi_x) + 1).clamp(0, width as i128) as usize;
    let ys = pixel(lo_y).max(0) as usize..(pixel(hi_y) + 1).clamp(0, height as i128) as usize;
    for y in ys {
        for x in xs.clone() {
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
    coverage_stats_with::<S>(tris, width, height, strip, cull).0
}

/// [`coverage_with`] and the frame's statistics.
pub fn coverage_stats_with<S: Settings>(
    tris: &[[TriVertex; 3]],
    width: usize,
    height: usize,
    strip: usize,
    cull: Cull,
) -> (Vec<u8>, FrameStats) {
    let verts = tris.len() * 9 + 3;
    let mut r: HostRenderer<Rgb888, 3, S> = HostRenderer::new(width, height, strip, verts, tris.len() * 7 + 1, Rgb888::BLACK).unwrap();
    let material = Material::new(FragmentCount).with_cull(cull).with_depth::<DepthOff>();
    let mut frame = r.begin_frame_with(Mat4::IDENTITY, &Lights::UNLIT, Rgb888::BLACK);
    frame.draw_window_triangles(tris.iter().copied(), &material).unwrap();
    let mut img = Image::new(width as u32, height as u32, Rgb888::BLACK);
    let Ok(stats) = frame.finish(&mut img);
    (img.pixels.iter().map(|c| c.r()).collect(), stats)
}

/// [`coverage_stats_with`] for a run-time sub-pixel setting and scalar
/// (no culling).
pub fn coverage_stats_mode(
    tris: &[[TriVertex; 3]],
    width: usize,
    height: usize,
    strip: usize,
    bits: u32,
    float: bool,
) -> (Vec<u8>, FrameStats) {
    struct Go<'a>(&'a [[TriVertex; 3]], usize, usize, usize);
    impl ModeFn for Go<'_> {
        type Out = (Vec<u8>, FrameStats);
        fn run<S: Settings>(self) -> Self::Out {
            coverage_stats_with::<S>(self.0, self.1, self.2, self.3, Cull::None)
        }
    }
    with_mode(bits, float, Go(tris, width, height, strip))
}

/// Work generic over the renderer's [`Settings`], run for a mode chosen at
/// run time by [`with_mode`].
pub trait ModeFn {
    /// What the work returns.
    type Out;
    /// Runs it with settings `S`.
    fn run<S: Settings>(self) -> Self::Out;
}

/// Runs `f` with `Precision<Fixed or f32, bits>` (bits 0 to 8).
pub fn with_mode<F: ModeFn>(bits: u32, float: bool, f: F) -> F::Out {
    macro_rules! go {
        ($($b:literal)*) => {
            match (bits, float) {
                $(($b, false) => f.run::<Precision<Fixed, $b>>(),
                  ($b, true) => f.run::<Precision<f32, $b>>(),)*
                _ => panic!("bits {bits}"),
            }
        };
    }
    go!(0 1 2 3 4 5 6 7 8)
}

/// The numeric modes every hard case runs in: sub-pixel bits 0, 2, 4, 6, 8,
/// each with fixed-point and `f32` interpolation.
pub const MODES: [(u32, bool); 10] =
    [(0, false), (0, true), (2, false), (2, true), (4, false), (4, true), (6, false), (6, true), (8, false), (8, true)];

/// A mode for messages: "fixed/4", "f32/8".
pub fn mode_name(bits: u32, float: bool) -> String {
    format!("{}/{bits}", if float { "f32" } else { "fixed" })
}

/// One sub-pixel at `bits`, in pixels.
pub fn unit(bits: u32) -> f64 {
    1.0 / (1u64 << bits) as f64
}

/// A white window-space triangle from three points.
pub fn tri(p: &[(f64, f64); 3]) -> [TriVertex; 3] {
    [tv(p[0].0, p[0].1), tv(p[1].0, p[1].1), tv(p[2].0, p[2].1)]
}

/// The corners of a window-space triangle.
pub fn points(t: &[TriVertex; 3]) -> [(f64, f64); 3] {
    [(t[0].x, t[0].y), (t[1].x, t[1].y), (t[2].x, t[2].y)]
}

/// The oracle's coverage of several triangles, summed per pixel.
pub fn oracle_sum(tris: &[[TriVertex; 3]], width: usize, height: usize, bits: u32) -> Vec<u8> {
    let mut sum = vec![0u8; width * height];
    for t in tris {
        for (s, o) in sum.iter_mut().zip(oracle(&points(t), width, height, bits)) {
            *s += o;
        }
    }
    sum
}

/// [`coverage_with`] for a run-time sub-pixel setting (fixed point).
pub fn coverage(tris: &[[TriVertex; 3]], width: usize, height: usize, strip: usize, bits: u32) -> Vec<u8> {
    coverage_mode(tris, width, height, strip, bits, false)
}

/// [`coverage_with`] for a run-time sub-pixel setting and scalar.
pub fn coverage_mode(tris: &[[TriVertex; 3]], width: usize, height: usize, strip: usize, bits: u32, float: bool) -> Vec<u8> {
    coverage_stats_mode(tris, width, height, strip, bits, float).0
}

/// Fragment counts and statistics of `mesh` drawn with the clip-space
/// matrix `view_proj` (model = identity) in a `width` × `height` frame of
/// 16-row strips.
pub fn mesh_coverage_with<S: Settings>(mesh: &Mesh<'_>, view_proj: Mat4, cull: Cull, width: usize, height: usize) -> (Vec<u8>, FrameStats) {
    let tris = mesh.triangle_count();
    let mut r: HostRenderer<Rgb888, 3, S> =
        HostRenderer::new(width, height, 16, mesh.vertex_count() + tris * 8, tris * 8 + 1, Rgb888::BLACK).unwrap();
    let material = Material::new(FragmentCount).with_cull(cull).with_depth::<DepthOff>();
    let mut frame = r.begin_frame_with(view_proj, &Lights::UNLIT, Rgb888::BLACK);
    frame.draw(mesh, &Mat4::IDENTITY, &material).unwrap();
    let mut img = Image::new(width as u32, height as u32, Rgb888::BLACK);
    let Ok(stats) = frame.finish(&mut img);
    (img.pixels.iter().map(|c| c.r()).collect(), stats)
}

/// [`mesh_coverage_with`] for a run-time sub-pixel setting and scalar.
pub fn mesh_coverage_mode(
    mesh: &Mesh<'_>,
    view_proj: Mat4,
    cull: Cull,
    width: usize,
    height: usize,
    bits: u32,
    float: bool,
) -> (Vec<u8>, FrameStats) {
    struct Go<'a, 'b>(&'a Mesh<'b>, Mat4, Cull, usize, usize);
    impl ModeFn for Go<'_, '_> {
        type Out = (Vec<u8>, FrameStats);
        fn run<S: Settings>(self) -> Self::Out {
            mesh_coverage_with::<S>(self.0, self.1, self.2, self.3, self.4)
        }
    }
    with_mode(bits, float, Go(mesh, view_proj, cull, width, height))
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

/// A point or vector in `f64`, for ray-cast references.
pub type P3 = [f64; 3];

/// `a - b`.
pub fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a × b`.
pub fn cross(a: P3, b: P3) -> P3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// `a · b`.
pub fn dot(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// A quad in the plane z = 0 covering `[-1, 1]²`, facing -z (the camera),
/// with texture coordinates `uv0` at the top left to `uv1` at the bottom right.
pub fn textured_quad(uv0: (f32, f32), uv1: (f32, f32)) -> (Vec<Vec3>, Vec<Vec3>, Vec<Vec2>, Vec<u16>) {
    let p = vec![Vec3::new(-1.0, 1.0, 0.0), Vec3::new(1.0, 1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(-1.0, -1.0, 0.0)];
    let n = vec![Vec3::new(0.0, 0.0, -1.0); 4];
    let uv = vec![Vec2::new(uv0.0, uv0.1), Vec2::new(uv1.0, uv0.1), Vec2::new(uv1.0, uv1.1), Vec2::new(uv0.0, uv1.1)];
    (p, n, uv, vec![0, 1, 2, 0, 2, 3])
}

/// Renders the quad filling a `size`×`size` image: an explicit
/// view-projection maps its corners to the image corners with w = 1, so
/// texel boundaries fall on known pixels.
pub fn render_textured_quad<S: Settings, F: Filter, W: Wrap>(
    texture: Texture<'_>,
    uv0: (f32, f32),
    uv1: (f32, f32),
    size: usize,
) -> Image<Rgb565> {
    let (p, n, uv, idx) = textured_quad(uv0, uv1);
    let mesh = Mesh::new(&p, &n, &idx).unwrap().with_uvs(&uv).unwrap();
    let material = Material::new(Textured::<F, W>::new(texture)).with_cull(Cull::None);
    let mut r: HostRenderer<Rgb565, 5, S> = HostRenderer::new(size, size, 8, 16, 16, Rgb565::BLACK).unwrap();
    // Clip space: x, y as they are, z = 0.5, w = 1.
    let view_proj = Mat4 { m: [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.5], [0.0, 0.0, 0.0, 1.0]] };
    let mut frame = r.begin_frame_with(view_proj, &Lights::UNLIT, Rgb565::BLACK);
    frame.draw(&mesh, &Mat4::IDENTITY, &material).unwrap();
    let mut img = Image::new(size as u32, size as u32, Rgb565::BLACK);
    let Ok(_) = frame.finish(&mut img);
    img
}
