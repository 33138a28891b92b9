//! The `raster` case: a few window-space triangles drawn with
//! `FragmentCount` (no depth test, no culling) into a small frame, checked
//! against an exact coverage oracle written here, independently of the
//! rasterizer's edge walk.
//!
//! Input layout (missing bytes read as zero):
//!
//! ```text
//! byte 0        bit 0: f32 (else fixed point); (byte >> 1) % 5 picks 0, 2, 4, 6, 8 sub-pixel bits
//! bytes 1-3     width 1..=40, height 1..=32, strip 1..=height
//! then          up to 6 triangles of 3 vertices; a vertex is a selector
//!               byte (>= 0xC0: copy vertex `sel % 3` of the previous
//!               triangle) or x and y, each a tag byte and its payload
//! ```
//!
//! Invariants: no panic (overflow checks are on); every pixel written once
//! per frame and never outside it ([`CheckedTarget`]); the statistics add
//! up; and the fragment count of every pixel equals the oracle's, which
//! snaps each vertex half up to the 1/2^bits grid and applies the top-left
//! rule with `i128` edge functions at pixel centers.
//!
//! What is compared exactly, and why not everything:
//!
//! - A triangle whose vertices all snap inside the guard band (|snapped| <=
//!   2^(27 - 2·bits) pixels, `soft3d::raster::guard`) is documented exact:
//!   every pixel must match.
//! - A triangle with a vertex beyond it is clipped to the band in `f64`
//!   and the new vertices are snapped again, so its edges move by up to
//!   half a grid step plus the `f64` rounding of the clip. For those
//!   (coordinates up to 2^50 pixels) only pixel centers farther than
//!   `2^-bits + M·2^-44` pixels (M the largest coordinate) from every edge
//!   line of the unsnapped triangle are compared; nearer ones may be 0 or 1.
//! - Finite coordinates without an exact form here (1e300, f64::MAX, ...):
//!   `f64` cannot place every guard-band crossing of such edges within a
//!   pixel, so each pixel may get 0 or 1 fragment from the triangle, never
//!   2 (the clipper places crossings exactly on the band, from the nearer
//!   endpoint, so the clipped polygon does not fold: regression
//!   `a_triangle_at_1e300_covers_each_pixel_at_most_once`). A triangle with
//!   a NaN or infinite coordinate must draw nothing.

use crate::check::CheckedTarget;
use crate::input::Bytes;
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use soft3d::effect::FragmentCount;
use soft3d::material::DepthOff;
use soft3d::math::{Fixed, Mat4};
use soft3d::tri::TriVertex;
use soft3d::{Cull, FrameStats, HostRenderer, Lights, Material, Precision, Settings};

/// The sub-pixel settings fuzzed.
pub const BITS: [u32; 5] = [0, 2, 4, 6, 8];
/// Most triangles in one case.
pub const MAX_TRIANGLES: usize = 6;
/// Exact forms cover coordinates up to this many pixels.
const EXACT_LIMIT: f64 = (1u64 << 50) as f64;

/// A window coordinate and, if it is `m · 2^e` with `e >= -10` and at most
/// 2^50 in magnitude, that exact form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coord {
    pub value: f64,
    pub exact: Option<Dyadic>,
}

/// `(m, e)`: the exact value `m · 2^e`.
type Dyadic = (i64, i32);

fn dyadic(m: i64, e: i32) -> Coord {
    // |m| < 2^53 in every use, so the f64 is exact.
    let value = m as f64 * (e as f64).exp2();
    Coord { value, exact: (value.abs() <= EXACT_LIMIT && e >= -10).then_some((m, e)) }
}

fn inexact(value: f64) -> Coord {
    Coord { value, exact: None }
}

/// One coordinate: near the screen on several grids, far (through every
/// guard band), exactly at a guard band's edge, or extreme.
fn coord(b: &mut Bytes) -> Coord {
    let tag = b.u8();
    let sign = if tag & 8 != 0 { -1 } else { 1 };
    match tag % 8 {
        0 => dyadic(b.i16() as i64, -10), // ±32 px, off every grid: exercises half-up rounding
        1 => dyadic(b.i16() as i64, -8),
        2 => dyadic(b.i16() as i64, -4), // ±2,048 px
        3 => dyadic(b.u8() as i64, -2),  // on screen, quarter pixels
        4 => dyadic(b.i32() as i64, -8), // ±8 million px
        5 => {
            let m = b.i32() as i64;
            dyadic(m, (b.u8() % 19) as i32) // integers up to 2^49
        }
        6 => {
            // 2^(27-2k) px (the guard band at k bits) plus j/2^(k+2).
            let k = BITS[(b.u8() % 5) as usize] as i32;
            let j = (b.i8() % 8) as i64;
            dyadic(sign * ((1i64 << (29 - k)) + j), -(k + 2))
        }
        _ => match b.u8() % 16 {
            0 => inexact(f64::NAN),
            1 => inexact(f64::INFINITY),
            2 => inexact(f64::NEG_INFINITY),
            3 => inexact(f64::MAX),
            4 => inexact(f64::MIN),
            5 => inexact(1e300),
            6 => inexact(-1e300),
            7 => inexact(1e-300),
            8 => inexact(1e20),
            9 => inexact(-1e20),
            10 => inexact(f64::MIN_POSITIVE),
            11 => dyadic(sign, 50),
            12 => Coord { value: -0.0, exact: Some((0, 0)) },
            13 => dyadic(1, -1),
            14 => dyadic(sign * ((1i64 << 40) + 1), -10),
            _ => inexact(sign as f64 * 4503599627370495.5), // 2^52 - 0.5: the last f64 with a half
        },
    }
}

/// A decoded case.
#[derive(Clone, Debug)]
pub struct Case {
    pub float: bool,
    pub bits: u32,
    pub width: usize,
    pub height: usize,
    pub strip: usize,
    pub tris: Vec<[(Coord, Coord); 3]>,
}

pub fn decode(data: &[u8]) -> Case {
    let mut b = Bytes::new(data);
    let mode = b.u8();
    let (float, bits) = (mode & 1 == 1, BITS[((mode >> 1) % 5) as usize]);
    let width = 1 + (b.u8() % 40) as usize;
    let height = 1 + (b.u8() % 32) as usize;
    let strip = 1 + (b.u8() as usize % height);
    let mut tris: Vec<[(Coord, Coord); 3]> = Vec::new();
    while !b.is_empty() && tris.len() < MAX_TRIANGLES {
        let prev = tris.last().copied();
        let mut tri = [(inexact(0.0), inexact(0.0)); 3];
        for v in &mut tri {
            let sel = b.u8();
            *v = match prev {
                // Shared vertices make shared edges, where the top-left rule matters most.
                Some(p) if sel >= 0xC0 => p[(sel % 3) as usize],
                _ => (coord(&mut b), coord(&mut b)),
            };
        }
        tris.push(tri);
    }
    Case { float, bits, width, height, strip, tris }
}

/// What the oracle knows about one triangle at one pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Cover {
    Certain(u8),
    /// 0 or 1.
    Either,
}

/// How a triangle relates to the guard band, for the statistics.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Class {
    /// A NaN or infinite coordinate: skipped as invalid.
    NonFinite,
    /// Every vertex snaps inside the guard band: one outcome, exactly.
    Inside { degenerate: bool },
    /// Clipped to the guard band, or no exact form: 0 to 7 pieces.
    Clipped,
}

/// `floor(m·2^e·2^bits + 1/2)`: the vertex on the 1/2^bits grid, half up.
fn snap_grid((m, e): Dyadic, bits: u32) -> i128 {
    let s = e + bits as i32;
    if s >= 0 {
        (m as i128) << s
    } else {
        let sh = -s;
        // Arithmetic shift floors, for negative values too.
        (m as i128 + (1i128 << (sh - 1))) >> sh
    }
}

/// Whether `(x, y)`, in units of 2^-(bits+1) pixel, is covered by the
/// triangle `p` (same units), whose doubled area is `area2 != 0`.
fn covers(p: &[(i128, i128); 3], cx: i128, cy: i128) -> bool {
    (0..3).all(|i| {
        let (a, b) = (p[i], p[(i + 1) % 3]);
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        // Edge function, increasing toward the interior (the vertices are
        // ordered so that the area is positive).
        let e = dx * (cy - a.1) - dy * (cx - a.0);
        // Its gradient is (-dy, dx). A center on the edge belongs to the
        // triangle when the interior lies to the right of the edge (a left
        // edge) or straight below it (a top edge).
        let (gx, gy) = (-dy, dx);
        e > 0 || (e == 0 && (gx > 0 || (gx == 0 && gy > 0)))
    })
}

/// The oracle for one triangle over the whole frame, and its class.
fn oracle(tri: &[(Coord, Coord); 3], case: &Case) -> (Vec<Cover>, Class) {
    let (w, h, bits) = (case.width, case.height, case.bits);
    if tri.iter().any(|(x, y)| !x.value.is_finite() || !y.value.is_finite()) {
        return (vec![Cover::Certain(0); w * h], Class::NonFinite);
    }
    let exact: Option<Vec<(Dyadic, Dyadic)>> = tri.iter().map(|(x, y)| Some((x.exact?, y.exact?))).collect();
    let Some(exact) = exact else {
        return (vec![Cover::Either; w * h], Class::Clipped);
    };
    // Snapped, in units of 2^-(bits+1) pixel so that centers are integers.
    let mut p = [(0i128, 0i128); 3];
    let limit = 1i128 << (27 - bits);
    let mut inside = true;
    for (q, &(x, y)) in p.iter_mut().zip(&exact) {
        let (gx, gy) = (snap_grid(x, bits), snap_grid(y, bits));
        inside &= gx.abs() <= limit && gy.abs() <= limit;
        *q = (2 * gx, 2 * gy);
    }
    let area2 = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[1].1 - p[0].1) * (p[2].0 - p[0].0);
    if area2 < 0 {
        p.swap(1, 2);
    }
    let class = if inside { Class::Inside { degenerate: area2 == 0 } } else { Class::Clipped };
    // Unsnapped vertices in units of 2^-11 pixel (e >= -10, so exact), for
    // the distance of a center to the edges of a clipped triangle.
    let fine: Vec<(i128, i128)> =
        exact.iter().map(|&((mx, ex), (my, ey))| ((mx as i128) << (ex + 11), (my as i128) << (ey + 11))).collect();
    let biggest = tri.iter().map(|(x, y)| x.value.abs().max(y.value.abs())).fold(0.0, f64::max);
    let tol = (-(bits as f64)).exp2() + biggest * (-44f64).exp2();
    let near_edge = |cx: i128, cy: i128| {
        (0..3).any(|i| {
            let (a, b) = (fine[i], fine[(i + 1) % 3]);
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            let len = ((dx as f64).powi(2) + (dy as f64).powi(2)).sqrt();
            let dist = if len == 0.0 {
                ((cx - a.0) as f64).hypot((cy - a.1) as f64)
            } else {
                (dx * (cy - a.1) - dy * (cx - a.0)).abs() as f64 / len
            };
            dist / 2048.0 < tol
        })
    };
    let mut out = vec![Cover::Certain(0); w * h];
    for y in 0..h {
        for x in 0..w {
            let (cx, cy) = (((2 * x as i128 + 1) << bits), ((2 * y as i128 + 1) << bits));
            let value = (area2 != 0 && covers(&p, cx, cy)) as u8;
            out[y * w + x] = if inside || !near_edge((2 * x as i128 + 1) << 10, (2 * y as i128 + 1) << 10) {
                Cover::Certain(value)
            } else {
                Cover::Either
            };
        }
    }
    (out, class)
}

/// Draws the case; returns the fragment count of every pixel and the
/// frame's statistics.
fn render<S: Settings>(case: &Case) -> (Vec<u8>, FrameStats) {
    let tv = |(x, y): (Coord, Coord)| TriVertex { x: x.value, y: y.value, z: 0.5, w: 1.0, color: Rgb888::WHITE };
    let tris: Vec<[TriVertex; 3]> = case.tris.iter().map(|t| t.map(tv)).collect();
    let n = tris.len();
    // Worst case: every triangle clipped into 9 new vertices and 7 pieces.
    let mut r: HostRenderer<Rgb888, 3, S> =
        HostRenderer::new(case.width, case.height, case.strip, 9 * n + 1, 7 * n + 1, Rgb888::BLACK).expect("valid sizes");
    let material = Material::new(FragmentCount).with_cull(Cull::None).with_depth::<DepthOff>();
    let mut frame = r.begin_frame_with(Mat4::IDENTITY, &Lights::UNLIT, Rgb888::BLACK);
    frame.draw_window_triangles(tris, &material).expect("buffers sized for the worst case");
    let recorded = frame.stats();
    let mut target = CheckedTarget::new(case.width, case.height);
    let Ok(stats) = frame.finish(&mut target);
    assert_eq!(stats, recorded, "finish returns the recorded statistics");
    let counts = target
        .finished()
        .iter()
        .map(|c| {
            assert!(c.r() == c.g() && c.g() == c.b(), "FragmentCount adds to every channel: {c:?}");
            c.r()
        })
        .collect();
    (counts, stats)
}

pub fn render_mode(case: &Case) -> (Vec<u8>, FrameStats) {
    macro_rules! go {
        ($($b:literal)*) => {
            match (case.bits, case.float) {
                $(($b, false) => render::<Precision<Fixed, $b>>(case),
                  ($b, true) => render::<Precision<f32, $b>>(case),)*
                _ => unreachable!("bits are from BITS"),
            }
        };
    }
    go!(0 2 4 6 8)
}

/// Decodes `data`, draws it and checks every invariant (panics on a
/// violation).
pub fn run(data: &[u8]) {
    let case = decode(data);
    let (got, stats) = render_mode(&case);
    let (w, n) = (case.width, case.tris.len());
    let oracles: Vec<(Vec<Cover>, Class)> = case.tris.iter().map(|t| oracle(t, &case)).collect();

    for (i, &count) in got.iter().enumerate() {
        let (mut sure, mut either) = (0u32, 0u32);
        for (o, _) in &oracles {
            match o[i] {
                Cover::Certain(v) => sure += v as u32,
                Cover::Either => either = either.saturating_add(1),
            }
        }
        let ok = (sure..=sure.saturating_add(either)).contains(&(count as u32));
        assert!(ok, "pixel ({}, {}): {count} fragments, oracle says {sure} (+ up to {either} near clipped edges)\n{case:?}", i % w, i / w);
    }

    // Statistics: every triangle is counted once; non-finite ones are
    // invalid; one inside the guard band has exactly one outcome.
    let count = |f: &dyn Fn(Class) -> bool| oracles.iter().filter(|(_, c)| f(*c)).count() as u32;
    let non_finite = count(&|c| c == Class::NonFinite);
    let degenerate = count(&|c| c == Class::Inside { degenerate: true });
    let inside = count(&|c| matches!(c, Class::Inside { .. }));
    let clipped = count(&|c| c == Class::Clipped);
    let s = stats;
    assert_eq!((s.draw_calls, s.triangles, s.back_facing, s.clipped, s.vertices), (1, n as u32, 0, 0, 0), "{s:?}");
    assert_eq!((s.meshes_culled, s.meshes_invalid), (0, 0), "{s:?}");
    let outcomes = s.invalid + s.degenerate + s.off_screen + s.queued;
    assert!(s.invalid >= non_finite && s.degenerate >= degenerate, "{s:?} for {case:?}");
    assert!(outcomes >= non_finite + inside && outcomes <= non_finite + inside + 7 * clipped, "{s:?} for {case:?}");
    if clipped == 0 {
        assert_eq!((s.invalid, s.degenerate, s.off_screen + s.queued), (non_finite, degenerate, inside - degenerate), "{case:?}");
    }
    if s.queued == 0 {
        assert!(got.iter().all(|&c| c == 0), "nothing queued, yet something drawn: {case:?}");
    }
}
