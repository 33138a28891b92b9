//! Category 7, depth: coplanar duplicates, interpenetrating triangles and
//! a near/far ratio of a million, against `f64` references.
//!
//! The depth format (src/raster.rs): window depth z in [0, 1] is stored as
//! `s = floor((1 - z) * 65534 + 1.5)` (1 to 65535, larger nearer) and a
//! fragment passes when its `s` is larger than the stored one. With the
//! projection's `z = f/(f-n) * (1 - n/d)` at view depth `d`, one stored
//! unit spans `Δd ≈ d² (f - n) / (f n 65534)`. Surfaces whose window depths
//! differ by 2 units or more are always ordered; by less than 1 unit they
//! may tie, and a tie keeps the first drawn. For near 0.01 and far 10,000
//! the unit is `d² / 655` (1.5 mm at d = 1, 15 cm at 10, 15 at 100): beyond
//! d ≈ 650 a unit is longer than the distance itself.

use crate::common::{oracle, tv};
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use soft3d::effect::VertexColor;
use soft3d::host::Image;
use soft3d::math::{Mat4, Vec3};
use soft3d::mesh::Mesh;
use soft3d::tri::TriVertex;
use soft3d::{Camera, Cull, FrameStats, HostRenderer, Lights, Material, Settings};

/// Calls `$f::<S>()` for fixed point and `f32` at 0, 2, 4, 6 and 8
/// sub-pixel bits.
macro_rules! all_modes {
    ($f:ident) => {{
        use soft3d::math::Fixed;
        use soft3d::Precision;
        $f::<Precision<Fixed, 0>>();
        $f::<Precision<Fixed, 2>>();
        $f::<Precision<Fixed, 4>>();
        $f::<Precision<Fixed, 6>>();
        $f::<Precision<Fixed, 8>>();
        $f::<Precision<f32, 0>>();
        $f::<Precision<f32, 2>>();
        $f::<Precision<f32, 4>>();
        $f::<Precision<f32, 6>>();
        $f::<Precision<f32, 8>>();
    }};
}
pub(crate) use all_modes;

/// "fixed/4", "f32/8": the mode, for failure messages.
pub fn mode<S: Settings>() -> String {
    let scalar = std::any::type_name::<S::Interp>().rsplit("::").next().unwrap_or("?").to_lowercase();
    format!("{scalar}/{}", S::SUBPIXEL_BITS)
}

const BG: Rgb888 = Rgb888::new(0, 0, 80);

/// Window-space triangles drawn in order with the depth test on.
fn window<S: Settings>(tris: &[[TriVertex; 3]], w: usize, h: usize, strip: usize) -> Image<Rgb888> {
    let mut r: HostRenderer<Rgb888, 3, S> = HostRenderer::new(w, h, strip, 64, 64, BG).unwrap();
    let m = Material::new(VertexColor).with_cull(Cull::None);
    let mut frame = r.begin_frame_with(Mat4::IDENTITY, &Lights::UNLIT, BG);
    frame.draw_window_triangles(tris.iter().copied(), &m).unwrap();
    let mut img = Image::new(w as u32, h as u32, BG);
    let Ok(_) = frame.finish(&mut img);
    img
}

fn colored(t: [(f64, f64, f32); 3], c: Rgb888) -> [TriVertex; 3] {
    t.map(|(x, y, z)| TriVertex { z, color: c, ..tv(x, y) })
}

#[test]
fn coplanar_triangles_at_equal_depth_keep_the_first_drawn() {
    // Two different overlapping triangles at the same depth: every pixel
    // both cover shows the first drawn, whichever it is.
    fn case<S: Settings>() {
        let (w, h) = (40, 32);
        let a = [(1.3, 2.0, 0.5), (38.0, 5.7, 0.5), (9.0, 30.2, 0.5)];
        let b = [(4.0, 28.0, 0.5), (20.5, 0.4, 0.5), (39.0, 26.0, 0.5)];
        let bits = S::SUBPIXEL_BITS;
        let cov = |t: [(f64, f64, f32); 3]| oracle(&t.map(|(x, y, _)| (x, y)), w, h, bits);
        let (ca, cb) = (cov(a), cov(b));
        for (first, second) in
            [((a, ca.clone(), Rgb888::RED), (b, cb.clone(), Rgb888::GREEN)), ((b, cb, Rgb888::GREEN), (a, ca, Rgb888::RED))]
        {
            let tris = [colored(first.0, first.2), colored(second.0, second.2)];
            let full = window::<S>(&tris, w, h, h);
            for strip in [1, 3, 7, 16] {
                assert_eq!(window::<S>(&tris, w, h, strip).pixels, full.pixels, "{} strip {strip}", mode::<S>());
            }
            let mut both = 0;
            for i in 0..w * h {
                let want = if first.1[i] == 1 {
                    first.2
                } else if second.1[i] == 1 {
                    second.2
                } else {
                    BG
                };
                both += (first.1[i] & second.1[i]) as usize;
                assert_eq!(full.pixels[i], want, "{} pixel ({}, {})", mode::<S>(), i % w, i / w);
            }
            assert!(both > 200, "the triangles should overlap");
        }
    }
    all_modes!(case);
}

/// A quad tilted away from the camera (depth varies across it), as a mesh.
fn tilted_quad() -> (Vec<Vec3>, Vec<Vec3>, Vec<u16>) {
    let p = vec![Vec3::new(-1.0, 1.0, 0.8), Vec3::new(1.0, 1.0, -0.3), Vec3::new(1.0, -1.0, -0.5), Vec3::new(-1.0, -1.0, 0.6)];
    (p, vec![Vec3::new(0.0, 0.0, -1.0); 4], vec![0, 1, 2, 0, 2, 3])
}

#[test]
fn a_mesh_drawn_twice_shows_the_first_draw_stably() {
    // The same tilted quad drawn red then green: identical depths at every
    // pixel, so the image is the red quad alone, in every strip height and
    // again when the renderer draws the next frame.
    fn case<S: Settings>() {
        let (w, h) = (40, 30);
        let (p, n, i) = tilted_quad();
        let mesh = Mesh::new(&p, &n, &i).unwrap();
        let camera = Camera::looking_at(Vec3::new(0.2, 0.3, -3.0), Vec3::ZERO);
        let red = Material::new(VertexColor).with_color(Rgb888::RED).with_cull(Cull::None);
        let green = Material::new(VertexColor).with_color(Rgb888::GREEN).with_cull(Cull::None);
        let render = |r: &mut HostRenderer<Rgb888, 3, S>, twice: bool| {
            let mut frame = r.begin_frame(&camera, &Lights::UNLIT, BG);
            frame.draw(&mesh, &Mat4::IDENTITY, &red).unwrap();
            if twice {
                frame.draw(&mesh, &Mat4::IDENTITY, &green).unwrap();
            }
            let mut img = Image::new(w as u32, h as u32, BG);
            let Ok(_) = frame.finish(&mut img);
            img
        };
        let mut full: HostRenderer<Rgb888, 3, S> = HostRenderer::new(w, h, h, 16, 16, BG).unwrap();
        let alone = render(&mut full, false);
        assert!(alone.pixels.iter().filter(|&&c| c == Rgb888::RED).count() > 300, "{}", mode::<S>());
        for strip in [1, 4, 7, 16, 30] {
            let mut r: HostRenderer<Rgb888, 3, S> = HostRenderer::new(w, h, strip, 16, 16, BG).unwrap();
            for frame in 0..2 {
                let img = render(&mut r, true);
                assert_eq!(img.pixels, alone.pixels, "{} strip {strip} frame {frame}", mode::<S>());
            }
        }
    }
    all_modes!(case);
}

#[test]
fn interpenetrating_triangles_cross_where_the_f64_planes_do() {
    // Two triangles covering the whole frame, their depth planes crossing
    // along a slanted line. Integer vertices snap exactly at every setting.
    // A pixel may differ from the f64 reference only within one pixel of
    // the line.
    fn case<S: Settings>() {
        let (w, h) = (48, 40);
        let corners = [(-2.0, -2.0), (100.0, -2.0), (-2.0, 100.0)];
        let za = [0.2f32, 0.8, 0.5];
        let zb = [0.7f32, 0.3, 0.45];
        let tri = |z: [f32; 3], c| colored([0, 1, 2].map(|k| (corners[k].0, corners[k].1, z[k])), c);
        // Depth planes in f64 from the same vertices.
        let plane = |z: [f32; 3], x: f64, y: f64| {
            let (x0, y0) = corners[0];
            let (ax, ay, bx, by) = (corners[1].0 - x0, corners[1].1 - y0, corners[2].0 - x0, corners[2].1 - y0);
            let det = ax * by - ay * bx;
            let (s, t) = (((x - x0) * by - (y - y0) * bx) / det, (ax * (y - y0) - ay * (x - x0)) / det);
            z[0] as f64 + s * (z[1] - z[0]) as f64 + t * (z[2] - z[0]) as f64
        };
        // Gradient of za - zb in depth per pixel, for the distance to the line.
        let d = |x: f64, y: f64| plane(za, x, y) - plane(zb, x, y);
        let grad = ((d(1.0, 0.0) - d(0.0, 0.0)).powi(2) + (d(0.0, 1.0) - d(0.0, 0.0)).powi(2)).sqrt();
        for (first, second, fc, sc) in [(za, zb, Rgb888::RED, Rgb888::GREEN), (zb, za, Rgb888::GREEN, Rgb888::RED)] {
            let img = window::<S>(&[tri(first, fc), tri(second, sc)], w, h, 8);
            let (mut near_line, mut counts) = (0, [0, 0]);
            for y in 0..h {
                for x in 0..w {
                    let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                    let (zf, zs) = (plane(first, cx, cy), plane(second, cx, cy));
                    let want = if zs < zf { sc } else { fc };
                    let got = img.get(x as u32, y as u32);
                    counts[(want == Rgb888::GREEN) as usize] += 1;
                    if got != want {
                        let dist = (zf - zs).abs() / grad;
                        assert!(dist <= 1.0, "{} ({x}, {y}) is {dist:.2} px from the intersection line", mode::<S>());
                        assert!(got == sc || got == fc, "{} ({x}, {y}): {got:?}", mode::<S>());
                        near_line += 1;
                    }
                }
            }
            assert!(counts[0] > 300 && counts[1] > 300, "the line should cross the frame: {counts:?}");
            assert!(near_line <= h, "{}: {near_line} pixels off the reference", mode::<S>());
        }
    }
    all_modes!(case);
}

/// The stored depth of view depth `d` (before the floor), in f64.
fn stored(d: f64, near: f64, far: f64) -> f64 {
    let z = far / (far - near) * (1.0 - near / d);
    (1.0 - z) * 65534.0 + 1.5
}

/// The view depth whose stored depth (before the floor) is `s`.
fn depth_at(s: f64, near: f64, far: f64) -> f64 {
    let z = 1.0 - (s - 1.5) / 65534.0;
    near / (1.0 - z * (far - near) / far)
}

/// Two frame-filling quads facing `camera` (at the origin, looking down
/// +z) at view depths `quads[k].0`, drawn in order with the depth test on
/// into a 16×12 frame.
fn two_quads<S: Settings>(camera: &Camera, quads: [(f64, Rgb888); 2]) -> (Image<Rgb888>, FrameStats) {
    let mut r: HostRenderer<Rgb888, 3, S> = HostRenderer::new(16, 12, 4, 16, 16, BG).unwrap();
    let n = vec![Vec3::new(0.0, 0.0, -1.0); 4];
    let i = vec![0u16, 1, 2, 0, 2, 3];
    let ps: Vec<Vec<Vec3>> = quads
        .iter()
        .map(|&(d, _)| {
            let (d, e) = (d as f32, d as f32 * 0.7);
            vec![Vec3::new(-e, e, d), Vec3::new(e, e, d), Vec3::new(e, -e, d), Vec3::new(-e, -e, d)]
        })
        .collect();
    let meshes: Vec<Mesh<'_>> = ps.iter().map(|p| Mesh::new(p, &n, &i).unwrap()).collect();
    let ms = quads.map(|(_, c)| Material::new(VertexColor).with_color(c).with_cull(Cull::None));
    let mut frame = r.begin_frame(camera, &Lights::UNLIT, BG);
    for (mesh, m) in meshes.iter().zip(&ms) {
        frame.draw(mesh, &Mat4::IDENTITY, m).unwrap();
    }
    let mut img = Image::new(16, 12, BG);
    let Ok(stats) = frame.finish(&mut img);
    (img, stats)
}

#[test]
fn depth_with_near_a_millionth_of_far_orders_surfaces_two_units_apart() {
    // Camera at the origin looking down +z, near 0.01, far 10,000; two
    // quads facing it, each filling the frame. Separated by two stored
    // units they are ordered whichever is drawn first; inside one unit they
    // tie and the first drawn stays.
    fn case<S: Settings>() {
        let (near, far) = (0.01, 10_000.0);
        let camera = Camera { near: near as f32, far: far as f32, ..Camera::looking_at(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)) };
        let draw = |quads: [(f64, Rgb888); 2]| {
            let (img, stats) = two_quads::<S>(&camera, quads);
            assert_eq!(stats.queued, 4, "{}", mode::<S>());
            img
        };
        let all = |img: &Image<Rgb888>, c: Rgb888| img.pixels.iter().all(|&p| p == c);
        for d in [0.02, 0.2, 2.0, 20.0, 200.0] {
            // Two units farther.
            let behind = depth_at(stored(d, near, far) - 2.0, near, far);
            assert!(behind > d && behind < far);
            for (a, b) in [((d, Rgb888::RED), (behind, Rgb888::GREEN)), ((behind, Rgb888::GREEN), (d, Rgb888::RED))] {
                assert!(all(&draw([a, b]), Rgb888::RED), "{} d {d} vs {behind}: the nearer must win", mode::<S>());
            }
            // A tie: both in the same unit, a quarter unit from its ends.
            let unit = stored(d, near, far).floor();
            let (d0, d1) = (depth_at(unit + 0.75, near, far), depth_at(unit + 0.25, near, far));
            assert!(all(&draw([(d0, Rgb888::RED), (d1, Rgb888::GREEN)]), Rgb888::RED), "{} tie at {d0}", mode::<S>());
            assert!(all(&draw([(d1, Rgb888::GREEN), (d0, Rgb888::RED)]), Rgb888::GREEN), "{} tie at {d0}", mode::<S>());
        }
        // The documented unit: d² (f - n) / (f n 65534), about d² / 655.
        let unit = |d: f64| d * d * (far - near) / (far * near * 65534.0);
        for d in [1.0, 10.0, 100.0] {
            let exact = depth_at(stored(d, near, far) - 1.0, near, far) - d;
            assert!((exact / unit(d) - 1.0).abs() < 0.2, "d {d}: one unit is {exact}, formula {}", unit(d));
        }
    }
    all_modes!(case);
}

#[test]
fn wide_depth_formats_order_surfaces_a_tenth_of_a_16_bit_unit_apart() {
    // The setup above, with the two quads inside one 16-bit unit, a tenth
    // of it apart: `Depth16` ties them (the first drawn stays), `Depth32`
    // and `DepthF32` put the nearer in front in both orders, with either
    // interpolation scalar. (Their limit is the `f32` window depth, whose
    // step near z = 1 is 2^-24, about 0.004 of a 16-bit unit.)
    fn case<S: Settings>(wide: bool) {
        let (near, far) = (0.01, 10_000.0);
        let camera = Camera { near: near as f32, far: far as f32, ..Camera::looking_at(Vec3::ZERO, Vec3::new(0.0, 0.0, 1.0)) };
        let draw = |quads: [(f64, Rgb888); 2]| two_quads::<S>(&camera, quads).0;
        let all = |img: &Image<Rgb888>, c: Rgb888| img.pixels.iter().all(|&p| p == c);
        let name = format!("{} {}", mode::<S>(), std::any::type_name::<S>());
        for d in [0.02, 0.2, 2.0, 20.0, 200.0] {
            let unit = stored(d, near, far).floor();
            // Red is nearer (a larger stored value), a tenth of a unit.
            let (red, green) = (depth_at(unit + 0.7, near, far), depth_at(unit + 0.6, near, far));
            assert!(red < green);
            let first_green = draw([(green, Rgb888::GREEN), (red, Rgb888::RED)]);
            let first_red = draw([(red, Rgb888::RED), (green, Rgb888::GREEN)]);
            assert!(all(&first_red, Rgb888::RED), "{name} d {d}");
            let want = if wide { Rgb888::RED } else { Rgb888::GREEN };
            assert!(all(&first_green, want), "{name} d {d}: {:?}", first_green.pixels[0]);
        }
    }
    use soft3d::math::Fixed;
    use soft3d::{Depth16, Depth32, DepthF32, Precision};
    case::<Precision<Fixed, 6, Depth16>>(false);
    case::<Precision<f32, 6, Depth16>>(false);
    case::<Precision<Fixed, 6, Depth32>>(true);
    case::<Precision<f32, 6, Depth32>>(true);
    case::<Precision<Fixed, 6, DepthF32>>(true);
    case::<Precision<f32, 6, DepthF32>>(true);
    case::<Precision<Fixed, 0, Depth32>>(true);
    case::<Precision<f32, 8, DepthF32>>(true);
}
