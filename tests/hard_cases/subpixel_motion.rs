//! Sub-pixel motion: triangles moved in 1/64 px steps never flicker, their
//! pixel count stays near their area, and interpolated colors and depth
//! never leave the range of the vertex values (no overshoot at span ends).

use crate::common::*;
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use soft3d::effect::VertexColor;
use soft3d::host::Image;
use soft3d::material::{Affine, PerPixel, Perspective};
use soft3d::math::Mat4;
use soft3d::tri::TriVertex;
use soft3d::{Cull, HostRenderer, Lights, Material, Settings};
use std::marker::PhantomData;

const W: usize = 64;
const H: usize = 48;

/// A general triangle, a sliver about a pixel wide, and a flat-topped
/// triangle whose edges pass through pixel centers.
const SHAPES: [[(f64, f64); 3]; 3] =
    [[(10.3, 8.1), (40.7, 15.2), (18.4, 39.9)], [(5.0, 20.0), (58.0, 24.3), (30.0, 22.6)], [(8.5, 10.5), (50.5, 10.5), (29.5, 40.5)]];

/// Steps of 1/64 px: 0 to 2 pixels.
const STEPS: usize = 129;

fn moved(p: &[(f64, f64); 3], dx: f64, dy: f64) -> [(f64, f64); 3] {
    p.map(|(x, y)| (x + dx, y + dy))
}

/// Area and perimeter (pixels) of the triangle as snapped at `bits`.
fn snapped_area_perimeter(p: &[(f64, f64); 3], bits: u32) -> (f64, f64) {
    let u = unit(bits);
    let s = p.map(|(x, y)| (snap(x, bits) as f64 * u, snap(y, bits) as f64 * u));
    let area = ((s[1].0 - s[0].0) * (s[2].1 - s[0].1) - (s[1].1 - s[0].1) * (s[2].0 - s[0].0)).abs() / 2.0;
    let len = |a: (f64, f64), b: (f64, f64)| ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt();
    (area, len(s[0], s[1]) + len(s[1], s[2]) + len(s[2], s[0]))
}

#[test]
fn coverage_changes_monotonically_as_a_triangle_moves() {
    // Moving right (or down), every snapped vertex moves right (down) or
    // stays, so each row's span ends only move right: a pixel's coverage
    // over time is 0…0 1…1 0…0 — once covered by the leading edge it stays
    // covered until the trailing edge passes, and once uncovered it stays
    // uncovered. Any other pattern is flicker. Every frame also equals
    // the oracle, and its pixel count N satisfies |N − A| <= P/2 + 1 for
    // the snapped area A and perimeter P (the lattice-point bound for a
    // convex region, Nosarzewska).
    for (bits, float) in MODES {
        let mode = mode_name(bits, float);
        for shape in &SHAPES {
            for (dir_x, dir_y) in [(1.0, 0.0), (0.0, 1.0)] {
                let mut history: Vec<Vec<u8>> = Vec::with_capacity(STEPS);
                for k in 0..STEPS {
                    let t = k as f64 / 64.0;
                    let p = moved(shape, t * dir_x, t * dir_y);
                    let got = coverage_mode(&[tri(&p)], W, H, 7, bits, float);
                    let want = oracle(&p, W, H, bits);
                    assert_eq!(got, want, "{mode}, {p:?}: {}", diff(&got, &want, W));
                    let n = got.iter().filter(|&&c| c > 0).count() as f64;
                    let (a, per) = snapped_area_perimeter(&p, bits);
                    assert!((n - a).abs() <= per / 2.0 + 1.0, "{mode}, {p:?}: {n} pixels for area {a}, perimeter {per}");
                    history.push(got);
                }
                for i in 0..W * H {
                    let seq: Vec<u8> = history.iter().map(|h| h[i]).collect();
                    let changes = seq.windows(2).filter(|w| w[0] != w[1]).count();
                    let starts_on = seq[0] == 1;
                    // 0*1*0*: at most two changes, and if it starts covered, one.
                    assert!(
                        changes <= 2 - starts_on as usize,
                        "{mode}, {shape:?} moving ({dir_x}, {dir_y}): pixel ({}, {}) flickers: {seq:?}",
                        i % W,
                        i / W
                    );
                }
            }
        }
    }
}

/// Renders `tris` with vertex colors and the depth test in settings `S`
/// and interpolation `P`, on a background no vertex color uses.
struct Colors<'a, P>(&'a [[TriVertex; 3]], PhantomData<P>);

const BACKGROUND: Rgb888 = Rgb888::new(1, 2, 3);

impl<P: Perspective> ModeFn for Colors<'_, P> {
    type Out = Image<Rgb888>;
    fn run<S: Settings>(self) -> Image<Rgb888> {
        let n = self.0.len();
        let mut r: HostRenderer<Rgb888, 3, S> = HostRenderer::new(W, H, 5, n * 9 + 3, n * 7 + 1, BACKGROUND).unwrap();
        let material = Material::new(VertexColor).with_cull(Cull::None).with_perspective::<P>();
        let mut frame = r.begin_frame_with(Mat4::IDENTITY, &Lights::UNLIT, BACKGROUND);
        frame.draw_window_triangles(self.0.iter().copied(), &material).unwrap();
        let mut img = Image::new(W as u32, H as u32, BACKGROUND);
        let Ok(_) = frame.finish(&mut img);
        img
    }
}

/// The exact color channels at window point (x, y) of triangle `t`: f64
/// barycentrics on its snapped vertices, perspective-correct with the
/// vertices' w if `perspective`.
fn exact_channels(t: &[TriVertex; 3], bits: u32, x: f64, y: f64, perspective: bool) -> [f64; 3] {
    let u = unit(bits);
    let s = t.map(|v| (snap(v.x, bits) as f64 * u, snap(v.y, bits) as f64 * u));
    let area = (s[1].0 - s[0].0) * (s[2].1 - s[0].1) - (s[1].1 - s[0].1) * (s[2].0 - s[0].0);
    let edge = |a: (f64, f64), b: (f64, f64)| ((b.0 - a.0) * (y - a.1) - (b.1 - a.1) * (x - a.0)) / area;
    let mut l = [edge(s[1], s[2]), edge(s[2], s[0]), edge(s[0], s[1])];
    if perspective {
        for (li, v) in l.iter_mut().zip(t) {
            *li /= v.w as f64;
        }
        let sum: f64 = l.iter().sum();
        l.iter_mut().for_each(|li| *li /= sum);
    }
    let ch = |f: fn(Rgb888) -> u8| (0..3).map(|k| l[k] * f(t[k].color) as f64).sum::<f64>();
    [ch(|c| c.r()), ch(|c| c.g()), ch(|c| c.b())]
}

/// Vertex colors: 0 and 255 in every combination a channel can take across
/// the triangle (constant 0, constant 255, 0 to 255), plus 1 and 254.
const COLORS: [[Rgb888; 3]; 3] = [
    [Rgb888::new(255, 0, 255), Rgb888::new(255, 255, 0), Rgb888::new(255, 0, 0)],
    [Rgb888::new(0, 255, 1), Rgb888::new(0, 0, 254), Rgb888::new(0, 255, 254)],
    [Rgb888::new(1, 254, 0), Rgb888::new(254, 1, 255), Rgb888::new(128, 254, 255)],
];

fn check_colors<P: Perspective>(bits: u32, float: bool, t: &[TriVertex; 3], tolerance: f64) {
    let mode = format!("{} {}", mode_name(bits, float), P::NAME);
    let img = with_mode(bits, float, Colors::<P>(std::slice::from_ref(t), PhantomData));
    let cover = oracle(&points(t), W, H, bits);
    let channels = |c: Rgb888| [c.r(), c.g(), c.b()];
    for (i, (&px, &covered)) in img.pixels.iter().zip(&cover).enumerate() {
        let (x, y) = (i % W, i / W);
        if covered == 0 {
            assert_eq!(px, BACKGROUND, "{mode}: ({x}, {y}) drawn outside the triangle");
            continue;
        }
        let exact = exact_channels(t, bits, x as f64 + 0.5, y as f64 + 0.5, P::CORRECT);
        for (k, exact) in exact.iter().enumerate() {
            let vs = t.map(|v| channels(v.color)[k]);
            let (lo, hi) = (*vs.iter().min().unwrap(), *vs.iter().max().unwrap());
            let got = channels(px)[k];
            assert!((lo..=hi).contains(&got), "{mode}, {t:?}: ({x}, {y}) channel {k} is {got}, outside the vertices' {lo}..={hi}");
            assert!(
                (got as f64 - exact).abs() <= tolerance,
                "{mode}, {t:?}: ({x}, {y}) channel {k} is {got}, exactly {exact:.3} (tolerance {tolerance})"
            );
        }
    }
}

#[test]
fn vertex_colors_stay_within_the_vertex_range_as_a_triangle_moves() {
    // Extreme vertex colors, affine and perspective-correct (vertex w of
    // 1, 4 and 0.5), moved in 1/64 px steps along a diagonal: every pixel
    // within each channel's vertex range (a constant channel exactly), and
    // within 1.5 levels of the exact value (rounding to nearest is half a
    // level; the rest is interpolation error) — so no wrap-around either.
    for (bits, float) in MODES {
        for (shape, colors) in SHAPES.iter().zip(&COLORS) {
            for k in (0..64).step_by(5) {
                let t = k as f64 / 64.0;
                let p = moved(shape, t, t * 0.75);
                let ws = [1.0, 4.0, 0.5];
                let tv3 = |i: usize, w: f32| TriVertex { x: p[i].0, y: p[i].1, z: 0.5, w, color: colors[i] };
                check_colors::<Affine>(bits, float, &[tv3(0, 1.0), tv3(1, 1.0), tv3(2, 1.0)], 1.5);
                check_colors::<PerPixel>(bits, float, &[tv3(0, ws[0]), tv3(1, ws[1]), tv3(2, ws[2])], 1.5);
            }
        }
    }
}

#[test]
fn vertex_colors_of_slivers_do_not_overshoot_at_span_ends() {
    // Slivers one sub-pixel wide with 0 and 255 on opposite sides: the
    // gradient across a span is up to 255 levels per sub-pixel, so any
    // rounding at a span end would overshoot. Every pixel must stay in
    // the vertex range; constant channels exact.
    for (bits, float) in MODES {
        let u = unit(bits);
        for k in 0..8 {
            let o = k as f64 / 64.0;
            for p in [
                [(3.0 + o, 2.0), (3.0 + o + u, 2.0), (60.0 + o, 45.0)],
                [(2.0, 40.0 + o), (62.0, 5.0 + o), (2.0, 40.0 + o + u)],
                [(30.0 + o, 0.0), (31.0 + o, 0.0), (30.5 + o, 48.0)],
            ] {
                let c = COLORS[k % 3];
                let t = [0, 1, 2].map(|i| TriVertex { x: p[i].0, y: p[i].1, z: 0.5, w: [1.0, 2.0, 0.7][i], color: c[i] });
                // Across a sliver the exact value changes by up to 255 per
                // sub-pixel, so only the range is checked (tolerance 256).
                check_colors::<Affine>(bits, float, &t, 256.0);
                check_colors::<PerPixel>(bits, float, &t, 256.0);
            }
        }
    }
}

/// Draws `t` (white) and a screen-covering plane of constant depth
/// `plane_z` (color PLANE), the plane first or second, depth test on;
/// returns which of the oracle's pixels of `t` show the plane.
struct DepthProbe<'a>(&'a [TriVertex; 3], f32, bool);

const PLANE: Rgb888 = Rgb888::new(7, 77, 177);

impl ModeFn for DepthProbe<'_> {
    type Out = Image<Rgb888>;
    fn run<S: Settings>(self) -> Image<Rgb888> {
        let DepthProbe(t, plane_z, plane_first) = self;
        let v = |x: f64, y: f64| TriVertex { x, y, z: plane_z, w: 1.0, color: PLANE };
        let (w, h) = (W as f64, H as f64);
        let plane = [[v(-1.0, -1.0), v(w + 1.0, -1.0), v(w + 1.0, h + 1.0)], [v(-1.0, -1.0), v(w + 1.0, h + 1.0), v(-1.0, h + 1.0)]];
        let order: Vec<[TriVertex; 3]> = if plane_first { vec![plane[0], plane[1], *t] } else { vec![*t, plane[0], plane[1]] };
        let mut r: HostRenderer<Rgb888, 3, S> = HostRenderer::new(W, H, 9, 40, 40, BACKGROUND).unwrap();
        let material = Material::new(VertexColor).with_cull(Cull::None);
        let mut frame = r.begin_frame_with(Mat4::IDENTITY, &Lights::UNLIT, BACKGROUND);
        frame.draw_window_triangles(order, &material).unwrap();
        let mut img = Image::new(W as u32, H as u32, BACKGROUND);
        let Ok(_) = frame.finish(&mut img);
        img
    }
}

#[test]
fn depth_stays_within_the_vertex_range_as_a_triangle_moves() {
    // Depth is stored in 16 bits as floor((1 − z) · 65534 + 1.5). A plane
    // one unit nearer than the nearest vertex, drawn first, must hide the
    // whole triangle; one unit farther than the farthest vertex, drawn
    // after, must not show through anywhere. So no pixel's depth lies more
    // than one unit (1/65534) outside the vertices' range, extremes 0 and
    // 1 included (there a wrap-around would show).
    let unit_z = 1.0 / 65534.0;
    let mut failures = Vec::new();
    for (bits, float) in MODES {
        let mode = mode_name(bits, float);
        for (shape, zs) in SHAPES.iter().zip([[0.0f32, 1.0, 0.5], [0.25, 0.75, 0.3], [1.0, 0.0, 0.999]]) {
            for k in (0..64).step_by(9) {
                let t = k as f64 / 64.0;
                let p = moved(shape, t * 0.6, t);
                let tr: [TriVertex; 3] = [0, 1, 2].map(|i| TriVertex { x: p[i].0, y: p[i].1, z: zs[i], w: 1.0, color: Rgb888::WHITE });
                let cover = oracle(&p, W, H, bits);
                let (lo, hi) = (zs.iter().cloned().fold(1.0, f32::min), zs.iter().cloned().fold(0.0, f32::max));
                let near = with_mode(bits, float, DepthProbe(&tr, (lo - unit_z).max(0.0), true));
                let far = with_mode(bits, float, DepthProbe(&tr, (hi + unit_z).min(1.0), false));
                let pixels = |img: &Image<Rgb888>, want: Rgb888| {
                    (0..W * H).filter(|&i| cover[i] == 1 && img.pixels[i] != want).map(|i| (i % W, i / W)).collect::<Vec<_>>()
                };
                let (nearer, farther) = (pixels(&near, PLANE), pixels(&far, Rgb888::WHITE));
                if !nearer.is_empty() || !farther.is_empty() {
                    failures.push(format!(
                        "{mode} {p:?} z {zs:?}: nearer than the nearest vertex at {nearer:?}, farther than the farthest at {farther:?}"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{} cases leave the vertex depth range:\n{}", failures.len(), failures.join("\n"));
}
