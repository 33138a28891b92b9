//! Needles and slivers: triangles one sub-pixel wide and hundreds of
//! pixels long cover exactly the pixels whose centers the oracle puts
//! inside (top-left rule), and fans of slivers leave no gap and no overlap.

use crate::common::*;

const W: usize = 64;
const H: usize = 48;

/// Compares one set of triangles with the summed oracle in one mode, for
/// a few strip heights.
fn assert_matches_oracle(tris: &[[soft3d::tri::TriVertex; 3]], bits: u32, float: bool, what: &str) {
    let want = oracle_sum(tris, W, H, bits);
    for strip in [1, 5, H] {
        let got = coverage_mode(tris, W, H, strip, bits, float);
        assert_eq!(got, want, "{} strip {strip}, {what}: {}", mode_name(bits, float), diff(&got, &want, W));
    }
}

#[test]
fn needles_one_subpixel_wide_match_the_oracle() {
    for (bits, float) in MODES {
        let u = unit(bits);
        // A point on the grid that is a pixel center where the grid has one.
        let c = if bits == 0 { 0.0 } else { 0.5 };
        // Base one sub-pixel wide, apex 300 pixels away; lines through
        // pixel centers, shallow and steep slopes, both windings.
        let needles = [
            [(10.0 + c, -100.0), (10.0 + c + u, -100.0), (10.0 + c, 200.0)], // vertical, edge through centers
            [(10.0 + c, 200.0), (10.0 + c + u, -100.0), (10.0 + c, -100.0)],
            [(30.0 + c - u, 250.0), (30.0 + c, 250.0), (30.0 + c, -50.0)],
            [(-100.0, 20.0 + c), (-100.0, 20.0 + c + u), (200.0, 20.0 + c)], // horizontal
            [(-100.0, 20.0 + c - u), (200.0, 20.0 + c), (-100.0, 20.0 + c)],
            [(-80.0, -80.0), (-80.0 + u, -80.0), (220.0, 220.0)],          // diagonal
            [(-5.0, 60.0), (-5.0, 60.0 - u), (295.0, -40.0)],              // slope -1/3
            [(2.0 + c, -200.0), (2.0 + c + u, -200.0), (62.0 + c, 250.0)], // steep: 60 px across 450 rows
            [(-200.0, 3.0 + c), (-200.0, 3.0 + c + u), (250.0, 44.0 + c)], // shallow
            // A sliver whose widest point is one sub-pixel: the third
            // vertex one step off the midpoint of a long edge.
            [(-40.0, 2.0), (120.0 + u, 25.0), (280.0, 48.0)],
            [(5.0 + c, -60.0), (5.0 + c + 3.0 * u, 40.0), (5.0 + c + 6.0 * u, 140.0 - u)],
        ];
        for n in &needles {
            assert_matches_oracle(&[tri(n)], bits, float, &format!("{n:?}"));
        }
        // Random needles: an edge 100 to 400 pixels long through the
        // screen, and a third vertex one sub-pixel beside a point on it.
        let mut rng = Rng(0x51_1e5 + bits as u64);
        for _ in 0..40 {
            let (x0, y0) = (rng.grid(-150.0, 0.0, u), rng.grid(-150.0, H as f64 + 150.0, u));
            let (x1, y1) = (rng.grid(W as f64, W as f64 + 200.0, u), rng.grid(-150.0, H as f64 + 150.0, u));
            let s = rng.grid(0.1, 0.9, 1.0 / 64.0);
            let (mx, my) = ((x0 + (x1 - x0) * s) / u, (y0 + (y1 - y0) * s) / u);
            let side = if rng.next_u64() & 1 == 0 { u } else { -u };
            let p = [(x0, y0), (x1, y1), (mx.round() * u, my.round() * u + side)];
            assert_matches_oracle(&[tri(&p)], bits, float, &format!("{p:?}"));
        }
    }
}

#[test]
fn single_pixel_spans_and_needles_do_not_disappear() {
    // Seeds' bug 2: spans with sx == ex vanish. (Moved here from
    // tests/coverage.rs and run in every mode.)
    for (bits, float) in MODES {
        let u = unit(bits);
        let mode = mode_name(bits, float);
        // A needle one pixel wide covers exactly one pixel per row.
        let needle = [(10.0, 0.0), (11.0, 0.0), (10.5, 30.0)];
        let got = coverage_mode(&[tri(&needle)], 24, 32, 4, bits, float);
        assert_eq!(got, oracle(&needle, 24, 32, bits), "{mode}");
        for y in 0..30 {
            let row: u32 = got[y * 24..(y + 1) * 24].iter().map(|&c| c as u32).sum();
            assert!(row <= 1, "{mode}: row {y} has {row} pixels");
            // With the apex on the grid (not at 0 bits, where it snaps to
            // x = 11) the center x = 10.5 is inside on every row.
            if bits > 0 {
                assert_eq!(row, 1, "{mode}: row {y} lost its pixel");
            }
        }
        // A vertical sliver one sub-pixel wide along x = x0, and its
        // mirror: together they cover the centers on the line exactly once.
        let x0 = if bits == 0 { 6.0 } else { 5.5 };
        let a = [(x0, 0.0), (x0 + u, 0.0), (x0, 20.0)];
        let b = [(x0, 0.0), (x0, 20.0), (x0 - u, 20.0)];
        let ga = coverage_mode(&[tri(&a)], 12, 20, 20, bits, float);
        let gb = coverage_mode(&[tri(&b)], 12, 20, 20, bits, float);
        let both = coverage_mode(&[tri(&a), tri(&b)], 12, 20, 20, bits, float);
        assert_eq!(ga, oracle(&a, 12, 20, bits), "{mode}");
        assert_eq!(gb, oracle(&b, 12, 20, bits), "{mode}");
        assert!(both.iter().all(|&c| c <= 1), "{mode}");
        if bits > 0 {
            // Every row's center on x = 5.5 belongs to exactly one of the two.
            for y in 1..19 {
                assert_eq!(both[y * 12 + 5], 1, "{mode}: row {y}");
            }
        }
    }
}

#[test]
fn a_fan_of_slivers_covers_its_union_exactly_once() {
    // Many very thin triangles sharing an apex, their far vertices
    // consecutive points on one straight line: together they tile one big
    // triangle, so their coverage must equal that triangle's (computed by
    // the oracle) with every pixel drawn once.
    for (bits, float) in MODES {
        let u = unit(bits);
        let mode = mode_name(bits, float);
        let c = if bits == 0 { 0.0 } else { 0.5 };
        for (apex, rim, step, n) in [
            // 480 slivers, their far ends 1.25 px apart 400 to 800 px away
            // (5 px at 0 bits): about 1/300 px wide near the apex.
            ((20.0, 23.0), (420.0, -277.0), (3.0 * u.max(0.25), 4.0 * u.max(0.25)), 480usize),
            // 256 slivers whose far ends are one sub-pixel apart, 360 px away.
            ((63.0, 30.0), (-300.0, 10.0), (0.0, u), 256),
            // Apex on a pixel center (where the grid has one), 960 slivers
            // ending 5/16 px apart (5 sub-pixels below 4 bits).
            ((32.0 + c, 24.0 + c), (2.0, 47.0), (3.0 * u.max(1.0 / 16.0), -4.0 * u.max(1.0 / 16.0)), 960),
        ] {
            // Rim points are whole steps along a line, so on the grid and
            // exactly collinear.
            let rim_at = |k: usize| (rim.0 + k as f64 * step.0, rim.1 + k as f64 * step.1);
            let tris: Vec<_> = (0..n).map(|k| tri(&[apex, rim_at(k), rim_at(k + 1)])).collect();
            let big = [apex, rim_at(0), rim_at(n)];
            let want = oracle(&big, W, H, bits);
            assert_eq!(oracle_sum(&tris, W, H, bits), want, "{mode}: the oracle's fan differs from its union");
            for strip in [3, H] {
                let got = coverage_mode(&tris, W, H, strip, bits, float);
                assert_eq!(got, want, "{mode} strip {strip}, fan at {apex:?}: {}", diff(&got, &want, W));
            }
            assert!(want.contains(&1), "{mode}: the fan at {apex:?} covers nothing to test");
        }
    }
}
