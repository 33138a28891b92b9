//! Exact coverage: the rasterizer against an independent oracle, the fill
//! rule on shared edges, and the cases the seeds' readers reported.

mod common;
use common::*;
use soft3d::tri::TriVertex;

const W: usize = 48;
const H: usize = 40;

#[test]
fn random_triangles_match_the_oracle_at_every_subpixel_setting() {
    let mut rng = Rng(0x5eed_1234_abcd_0001);
    for bits in [0u32, 1, 2, 4, 6, 8] {
        for n in 0..700 {
            // Coarse grids put many pixel centers exactly on edges.
            let step = [1.0, 0.5, 0.25, 1.0 / 16.0, 1.0 / (1u32 << bits) as f64][n % 5].max(1.0 / (1u32 << bits) as f64);
            let pts = [0; 3].map(|_| (rng.grid(-10.0, W as f64 + 10.0, step), rng.grid(-10.0, H as f64 + 10.0, step)));
            let tri = [tv(pts[0].0, pts[0].1), tv(pts[1].0, pts[1].1), tv(pts[2].0, pts[2].1)];
            let strip = [1, 3, 16, H][n % 4];
            let got = coverage_mode(&[tri], W, H, strip, bits, n % 2 == 1);
            let want = oracle(&pts, W, H, bits);
            assert_eq!(got, want, "bits {bits}, triangle {pts:?}, strip {strip}: {}", diff(&got, &want, W));
        }
    }
}

#[test]
fn off_grid_vertices_are_snapped_half_up() {
    // Vertices off the 1/16 grid: the oracle snaps the same way.
    let mut rng = Rng(77);
    for _ in 0..500 {
        let pts = [0; 3].map(|_| (rng.range(-5.0, W as f64 + 5.0), rng.range(-5.0, H as f64 + 5.0)));
        let tri = [tv(pts[0].0, pts[0].1), tv(pts[1].0, pts[1].1), tv(pts[2].0, pts[2].1)];
        let got = coverage(&[tri], W, H, 7, 4);
        assert_eq!(got, oracle(&pts, W, H, 4), "{pts:?}");
    }
}

/// Every pixel covered by the union of `tris` is covered exactly once.
fn assert_exactly_once(tris: &[[TriVertex; 3]], w: usize, h: usize, bits: u32) {
    let got = coverage(tris, w, h, 5, bits);
    let mut want = vec![0u8; w * h];
    for t in tris {
        let o = oracle(&[(t[0].x, t[0].y), (t[1].x, t[1].y), (t[2].x, t[2].y)], w, h, bits);
        for (a, b) in want.iter_mut().zip(o) {
            *a += b;
        }
    }
    assert!(want.iter().all(|&c| c <= 1), "the oracle itself double-covers");
    assert_eq!(got, want, "{}", diff(&got, &want, w));
}

#[test]
fn triangle_fans_cover_every_pixel_exactly_once() {
    for n in [3usize, 7, 16, 100, 1000] {
        let (cx, cy, r) = (31.3, 27.7, 40.0);
        let tris: Vec<_> = (0..n)
            .map(|i| {
                let a0 = i as f64 / n as f64 * std::f64::consts::TAU;
                let a1 = (i + 1) as f64 / n as f64 * std::f64::consts::TAU;
                [tv(cx, cy), tv(cx + r * a0.cos(), cy + r * a0.sin()), tv(cx + r * a1.cos(), cy + r * a1.sin())]
            })
            .collect();
        let got = coverage(&tris, 64, 56, 5, 4);
        assert!(got.iter().all(|&c| c <= 1), "fan of {n}: a pixel was drawn twice");
        assert_exactly_once(&tris, 64, 56, 4);
        // The fan around an interior point leaves no hole: the polygon's
        // interior pixels near the center are all covered.
        for y in 20..36 {
            for x in 24..40 {
                assert_eq!(got[y * 64 + x], 1, "fan of {n}: hole at ({x}, {y})");
            }
        }
    }
}

#[test]
fn grids_of_quads_split_both_ways_cover_once() {
    let mut rng = Rng(99);
    for flip in [false, true] {
        let (nx, ny) = (7, 6);
        // A jittered grid: shared vertices, irregular quads.
        let pts: Vec<Vec<(f64, f64)>> = (0..=ny)
            .map(|j| {
                (0..=nx)
                    .map(|i| (i as f64 * 8.0 + rng.grid(-2.0, 2.0, 0.0625) - 3.0, j as f64 * 8.0 + rng.grid(-2.0, 2.0, 0.0625) - 3.0))
                    .collect()
            })
            .collect();
        let mut tris = Vec::new();
        for j in 0..ny {
            for i in 0..nx {
                let (a, b, c, d) = (pts[j][i], pts[j][i + 1], pts[j + 1][i + 1], pts[j + 1][i]);
                let v = |p: (f64, f64)| tv(p.0, p.1);
                if flip ^ ((i + j) % 2 == 0) {
                    tris.push([v(a), v(b), v(c)]);
                    tris.push([v(a), v(c), v(d)]);
                } else {
                    tris.push([v(a), v(b), v(d)]);
                    tris.push([v(b), v(c), v(d)]);
                }
            }
        }
        assert_exactly_once(&tris, 56, 48, 4);
        let got = coverage(&tris, 56, 48, 5, 4);
        // Interior of the grid fully covered.
        for y in 6..40 {
            for x in 6..48 {
                assert_eq!(got[y * 56 + x], 1, "hole at ({x}, {y})");
            }
        }
    }
}

#[test]
fn flat_top_and_flat_bottom_triangles_draw_the_right_side() {
    // Seeds' bug 1: P1.y == P2.y handled with the wrong side.
    let cases = [
        [(2.0, 2.0), (20.0, 2.0), (11.0, 18.0)],  // flat top
        [(11.0, 2.0), (2.0, 18.0), (20.0, 18.0)], // flat bottom
        [(20.0, 2.0), (2.0, 2.0), (11.0, 18.0)],  // flat top, other winding
        [(2.0, 18.0), (11.0, 2.0), (20.0, 18.0)], // flat bottom, other winding
        [(2.0, 2.0), (2.0, 18.0), (20.0, 10.0)],  // vertical left edge
        [(20.0, 2.0), (20.0, 18.0), (2.0, 10.0)], // vertical right edge
    ];
    for pts in cases {
        let tri = [tv(pts[0].0, pts[0].1), tv(pts[1].0, pts[1].1), tv(pts[2].0, pts[2].1)];
        let got = coverage(&[tri], 24, 20, 4, 4);
        assert_eq!(got, oracle(&pts, 24, 20, 4), "{pts:?}");
        // Area check: a triangle of area 144 covers about 144 pixels.
        let n: u32 = got.iter().map(|&c| c as u32).sum();
        assert!((130..=160).contains(&n), "{pts:?} covers {n} pixels");
    }
}

#[test]
fn single_pixel_spans_and_needles_do_not_disappear() {
    // Seeds' bug 2: sx == ex spans vanish. A needle one pixel wide covers
    // exactly one pixel per row.
    let needle = [(10.0, 0.0), (11.0, 0.0), (10.5, 30.0)];
    let got = coverage(&[[tv(10.0, 0.0), tv(11.0, 0.0), tv(10.5, 30.0)]], 24, 32, 4, 4);
    assert_eq!(got, oracle(&needle, 24, 32, 4));
    for y in 0..30 {
        let row: u32 = got[y * 24..(y + 1) * 24].iter().map(|&c| c as u32).sum();
        assert!(row <= 1, "row {y} has {row} pixels");
    }
    // A vertical sliver one sub-pixel wide through pixel centers, and its
    // mirror: together they cover the centers on the line exactly once.
    let a = [tv(5.5, 0.0), tv(5.5625, 0.0), tv(5.5, 20.0)];
    let b = [tv(5.5, 0.0), tv(5.5, 20.0), tv(5.4375, 20.0)];
    let ga = coverage(&[a], 12, 20, 20, 4);
    let gb = coverage(&[b], 12, 20, 20, 4);
    let both = coverage(&[a, b], 12, 20, 20, 4);
    assert_eq!(ga, oracle(&[(5.5, 0.0), (5.5625, 0.0), (5.5, 20.0)], 12, 20, 4));
    assert_eq!(gb, oracle(&[(5.5, 0.0), (5.5, 20.0), (5.4375, 20.0)], 12, 20, 4));
    assert!(both.iter().all(|&c| c <= 1));
    // Every row's center at x = 5.5 belongs to exactly one of the two.
    for y in 1..19 {
        assert_eq!(both[y * 12 + 5], 1, "row {y}");
    }
}

#[test]
fn degenerate_triangles_draw_nothing() {
    for pts in [
        [(5.0, 5.0), (5.0, 5.0), (5.0, 5.0)],
        [(1.0, 1.0), (10.0, 10.0), (20.0, 20.0)],
        [(1.0, 1.0), (10.01, 1.0), (20.0, 1.0)], // collinear after snapping
    ] {
        let got = coverage(&[[tv(pts[0].0, pts[0].1), tv(pts[1].0, pts[1].1), tv(pts[2].0, pts[2].1)]], 24, 24, 4, 4);
        assert!(got.iter().all(|&c| c == 0), "{pts:?}");
    }
}

#[test]
fn huge_triangles_match_the_oracle_on_screen() {
    // Vertices up to half a million pixels away (inside the guard band at
    // 4 sub-pixel bits, 2^19 px) must give exactly the oracle's coverage.
    let mut rng = Rng(4242);
    for n in 0..300 {
        let far = [1e3, 1e5, 3e5, 5.2e5][n % 4];
        let pts = [0; 3].map(|_| (rng.grid(-far, far, 0.0625), rng.grid(-far, far, 0.0625)));
        let tri = [tv(pts[0].0, pts[0].1), tv(pts[1].0, pts[1].1), tv(pts[2].0, pts[2].1)];
        let got = coverage(&[tri], 32, 24, 8, 4);
        assert_eq!(got, oracle(&pts, 32, 24, 4), "{pts:?}: {}", diff(&got, &oracle(&pts, 32, 24, 4), 32));
    }
    // A screen-filling triangle whose vertices are far outside.
    // Inside the guard band, and far beyond it (clipped first).
    for far in [5e5, 5e6, 5e9] {
        let pts = [(-far, -far), (far, -0.8 * far), (0.0, far)];
        let got = coverage(&[[tv(pts[0].0, pts[0].1), tv(pts[1].0, pts[1].1), tv(pts[2].0, pts[2].1)]], 32, 24, 8, 4);
        assert!(got.iter().all(|&c| c == 1), "{far}");
    }
}

#[test]
fn triangles_beyond_the_guard_band_are_clipped_without_visible_change() {
    // Beyond the guard band (2^19 px at 4 bits; 2^11 at 8) triangles are
    // clipped in f64; the visible pixels still match the oracle.
    let mut rng = Rng(31337);
    for bits in [4, 8] {
        for _ in 0..100 {
            let pts = [
                (rng.grid(-1e9, 1e9, 1.0), rng.grid(-1e9, 1e9, 1.0)),
                (rng.grid(0.0, 32.0, 0.0625), rng.grid(0.0, 24.0, 0.0625)),
                (rng.grid(-1e8, 1e8, 1.0), rng.grid(-1e8, 1e8, 1.0)),
            ];
            let tri = [tv(pts[0].0, pts[0].1), tv(pts[1].0, pts[1].1), tv(pts[2].0, pts[2].1)];
            let got = coverage(&[tri], 32, 24, 8, bits);
            let want = oracle(&pts, 32, 24, bits);
            let differ = got.iter().zip(&want).filter(|(a, b)| a != b).count();
            assert!(differ <= 1, "bits {bits} {pts:?}: {}", diff(&got, &want, 32));
        }
    }
}

#[test]
fn coordinates_at_and_past_every_limit_never_panic() {
    // Exactly at the guard band, just past it, and at the ends of f64:
    // overflow checks are on in tests, so any overflow would panic here.
    let g4 = (1u64 << 19) as f64; // guard band at 4 sub-pixel bits, in pixels
    let values = [0.0, 16.5, g4, -g4, g4 - 0.0625, g4 + 0.0625, 1e12, -1e12, 1e300, -1e300, f64::MAX, f64::MIN, 1e-300];
    for &a in &values {
        for &b in &values {
            for bits in [0, 4, 8] {
                let tri = [tv(a, b), tv(b, 20.0), tv(10.0, a)];
                let got = coverage(&[tri], 24, 24, 8, bits);
                assert!(got.iter().all(|&c| c <= 1));
            }
        }
    }
    // Inside the guard band the result is still exact.
    let pts = [(-g4 + 1.0, -3.0), (g4 - 1.0, 5.5), (7.25, g4 - 1.0)];
    let got = coverage(&[[tv(pts[0].0, pts[0].1), tv(pts[1].0, pts[1].1), tv(pts[2].0, pts[2].1)]], 24, 24, 8, 4);
    assert_eq!(got, oracle(&pts, 24, 24, 4));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(400))]
    /// Property form of the oracle comparison: shrinks a failure to a
    /// minimal triangle. Coordinates are on the 1/16 grid.
    #[test]
    fn any_grid_triangle_matches_the_oracle(
        c in proptest::array::uniform6(-320i32..1100),
        strip in 1usize..41,
        float in proptest::bool::ANY,
    ) {
        let pts = [0, 1, 2].map(|i| (c[2 * i] as f64 / 16.0, c[2 * i + 1] as f64 / 16.0));
        let tri = [tv(pts[0].0, pts[0].1), tv(pts[1].0, pts[1].1), tv(pts[2].0, pts[2].1)];
        let got = coverage_mode(&[tri], W, H, strip, 4, float);
        let want = oracle(&pts, W, H, 4);
        proptest::prop_assert_eq!(&got, &want, "{:?}: {}", pts, diff(&got, &want, W));
    }
}
