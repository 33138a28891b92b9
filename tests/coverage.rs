//! Exact coverage: the rasterizer against an independent oracle (random
//! and property-based triangles, off-grid vertices) and the seeds'
//! flat-top/flat-bottom case. Fans, grids, needles, degenerate and huge
//! triangles are in the hard-case catalogue (tests/hard_cases).

mod common;
use common::*;

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
