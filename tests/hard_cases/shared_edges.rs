//! Shared edges and vertices: fans, quad grids split both ways and many
//! triangles meeting at one vertex cover every pixel of their union
//! exactly once. The union is the sum of the oracle's coverage of each
//! triangle, which must itself never exceed one.

use crate::common::*;
use soft3d::tri::TriVertex;
use std::f64::consts::TAU;

/// Every pixel covered by the union of `tris` is covered exactly once, in
/// one mode, through several strip heights; returns the coverage.
fn assert_exactly_once(tris: &[[TriVertex; 3]], w: usize, h: usize, bits: u32, float: bool, what: &str) -> Vec<u8> {
    let mode = mode_name(bits, float);
    let want = oracle_sum(tris, w, h, bits);
    assert!(want.iter().all(|&c| c <= 1), "{mode}, {what}: the oracle itself double-covers");
    let mut last = Vec::new();
    for strip in [1, 5, h] {
        let got = coverage_mode(tris, w, h, strip, bits, float);
        assert!(got.iter().all(|&c| c <= 1), "{mode} strip {strip}, {what}: a pixel was drawn twice");
        assert_eq!(got, want, "{mode} strip {strip}, {what}: {}", diff(&got, &want, w));
        last = got;
    }
    last
}

/// Rounds a point to the sub-pixel grid, so that shared vertices are
/// shared exactly after snapping too.
fn on_grid((x, y): (f64, f64), bits: u32) -> (f64, f64) {
    let u = unit(bits);
    ((x / u).round() * u, (y / u).round() * u)
}

/// A fan of `n` triangles around `center`, rim on a circle of radius `r`.
fn fan(center: (f64, f64), r: f64, n: usize, clockwise: bool, bits: u32) -> Vec<[TriVertex; 3]> {
    let rim =
        |i: usize| on_grid((center.0 + r * (i as f64 / n as f64 * TAU).cos(), center.1 + r * (i as f64 / n as f64 * TAU).sin()), bits);
    (0..n)
        .map(|i| {
            let (a, b) = if clockwise { (rim(i), rim(i + 1)) } else { (rim(i + 1), rim(i)) };
            tri(&[center, a, b])
        })
        .collect()
}

#[test]
fn fans_of_3_to_1000_triangles_cover_every_pixel_once() {
    // (Moved from tests/coverage.rs and run in every mode.)
    for (bits, float) in MODES {
        let c = if bits == 0 { 0.0 } else { 0.5 };
        for n in [3usize, 7, 16, 100, 1000] {
            // Center off the grid points, on a pixel center, on a corner.
            for (center, clockwise) in [(on_grid((31.3, 27.7), bits), true), ((32.0 + c, 28.0 + c), false), ((30.0, 26.0), true)] {
                let tris = fan(center, 40.0, n, clockwise, bits);
                let got = assert_exactly_once(&tris, 64, 56, bits, float, &format!("fan of {n} at {center:?}"));
                // The fan around an interior point leaves no hole: the
                // polygon's interior pixels near the center are all covered.
                if n >= 7 {
                    for y in 20..36 {
                        for x in 24..40 {
                            assert_eq!(got[y * 64 + x], 1, "{}: fan of {n}: hole at ({x}, {y})", mode_name(bits, float));
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn fans_with_edges_through_pixel_centers_cover_once() {
    // Center on a pixel center and rim vertices at whole-pixel offsets from
    // it: every edge passes through a row of pixel centers, so every edge
    // is decided by the fill rule's tie-break. At 0 bits the same shape
    // sits on pixel corners (no center on the grid).
    for (bits, float) in MODES {
        let c = if bits == 0 { 0.0 } else { 0.5 };
        let center = (30.0 + c, 22.0 + c);
        let offsets =
            [(13, 0), (12, 5), (9, 9), (5, 12), (0, 13), (-4, 12), (-8, 8), (-13, 1), (-12, -5), (-7, -7), (-1, -13), (6, -11), (11, -4)];
        let rim: Vec<(f64, f64)> = offsets.iter().map(|&(dx, dy)| (center.0 + dx as f64 * 2.0, center.1 + dy as f64 * 1.5)).collect();
        let tris: Vec<_> = (0..rim.len()).map(|i| tri(&[center, rim[i], rim[(i + 1) % rim.len()]])).collect();
        let got = assert_exactly_once(&tris, 64, 48, bits, float, "lattice fan");
        assert_eq!(got[22 * 64 + 30], 1, "{}: the center pixel", mode_name(bits, float));
    }
}

#[test]
fn grids_of_quads_split_both_ways_cover_once() {
    // (Moved from tests/coverage.rs and run in every mode.) A jittered
    // grid: shared vertices, irregular quads, each split along one
    // diagonal or the other in a checkerboard, then the other way round.
    for (bits, float) in MODES {
        let mut rng = Rng(99 + bits as u64);
        for flip in [false, true] {
            let (nx, ny) = (7, 6);
            let pts: Vec<Vec<(f64, f64)>> = (0..=ny)
                .map(|j| {
                    (0..=nx)
                        .map(|i| on_grid((i as f64 * 8.0 + rng.range(-2.0, 2.0) - 3.0, j as f64 * 8.0 + rng.range(-2.0, 2.0) - 3.0), bits))
                        .collect()
                })
                .collect();
            let mut tris = Vec::new();
            for j in 0..ny {
                for i in 0..nx {
                    let (a, b, c, d) = (pts[j][i], pts[j][i + 1], pts[j + 1][i + 1], pts[j + 1][i]);
                    if flip ^ ((i + j) % 2 == 0) {
                        tris.push(tri(&[a, b, c]));
                        tris.push(tri(&[a, c, d]));
                    } else {
                        tris.push(tri(&[a, b, d]));
                        tris.push(tri(&[b, c, d]));
                    }
                }
            }
            let got = assert_exactly_once(&tris, 56, 48, bits, float, &format!("grid, flip {flip}"));
            // Interior of the grid fully covered.
            for y in 6..40 {
                for x in 6..48 {
                    assert_eq!(got[y * 56 + x], 1, "{}: hole at ({x}, {y})", mode_name(bits, float));
                }
            }
        }
    }
}

#[test]
fn axis_aligned_grids_on_pixel_centers_cover_once() {
    // Quads whose every edge runs through pixel centers (horizontal and
    // vertical edges at .5, diagonals through centers): each pixel of the
    // 40 × 30 block is drawn once, nothing outside it.
    for (bits, float) in MODES {
        let c = if bits == 0 { 0.0 } else { 0.5 };
        let mut tris = Vec::new();
        for j in 0..6 {
            for i in 0..8 {
                let (x0, y0) = (4.0 + c + i as f64 * 5.0, 3.0 + c + j as f64 * 5.0);
                let (a, b, cc, d) = ((x0, y0), (x0 + 5.0, y0), (x0 + 5.0, y0 + 5.0), (x0, y0 + 5.0));
                if (i + j) % 2 == 0 {
                    tris.extend([tri(&[a, b, cc]), tri(&[a, cc, d])]);
                } else {
                    tris.extend([tri(&[a, b, d]), tri(&[b, cc, d])]);
                }
            }
        }
        let got = assert_exactly_once(&tris, 52, 40, bits, float, "aligned grid");
        // The block's pixels: centers in [x0, x0 + 40) × [y0, y0 + 30), the
        // top and left borders included (top-left rule).
        for y in 0..40 {
            for x in 0..52 {
                let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                let inside = (4.0 + c..44.0 + c).contains(&cx) && (3.0 + c..33.0 + c).contains(&cy);
                assert_eq!(got[y * 52 + x], inside as u8, "{}: ({x}, {y})", mode_name(bits, float));
            }
        }
    }
}

#[test]
fn many_triangles_meeting_at_one_vertex_cover_once() {
    // Irregular stars: 12 to 400 triangles of random angular widths around
    // one vertex (on a pixel center where the grid has one, so the vertex
    // itself is a sample that exactly one triangle must own), closed and
    // open (a wedge missing).
    for (bits, float) in MODES {
        let mut rng = Rng(0xfa2 + bits as u64);
        let c = if bits == 0 { 0.0 } else { 0.5 };
        let hub = (25.0 + c, 20.0 + c);
        for n in [12usize, 50, 400] {
            // Snapped first, then sorted by angle, so that snapping cannot
            // reorder neighbours and make wedges overlap.
            let mut rim: Vec<(f64, f64)> = (0..n)
                .map(|_| {
                    let (a, r) = (rng.range(0.0, TAU), rng.range(8.0, 60.0));
                    on_grid((hub.0 + r * a.cos(), hub.1 + r * a.sin()), bits)
                })
                .collect();
            let angle = |p: &(f64, f64)| (p.1 - hub.1).atan2(p.0 - hub.0);
            rim.sort_by(|p, q| angle(p).total_cmp(&angle(q)));
            let angles: Vec<f64> = rim.iter().map(angle).collect();
            for open in [false, true] {
                let count = if open { n - 1 } else { n };
                let tris: Vec<_> = (0..count).map(|i| tri(&[hub, rim[i], rim[(i + 1) % n]])).collect();
                // Skip wedges wider than half a turn (not a valid star).
                let wedge = |i: usize| (angles[(i + 1) % n] - angles[i]).rem_euclid(TAU);
                if (0..count).any(|i| wedge(i) >= TAU / 2.0) {
                    continue;
                }
                let got = assert_exactly_once(&tris, 52, 40, bits, float, &format!("star of {count}"));
                if !open {
                    assert_eq!(got[20 * 52 + 25], 1, "{}: the hub pixel", mode_name(bits, float));
                }
            }
        }
    }
}
