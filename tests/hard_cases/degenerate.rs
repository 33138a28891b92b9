//! Degenerate triangles: three equal vertices, collinear vertices, and
//! distinct vertices that snap onto a line or a point. Each draws nothing,
//! is counted as degenerate (its snapped area is zero) and leaves the
//! triangles around it exact. Debug builds trap integer division by zero,
//! so a run that returns at all has not divided by the zero area.

use crate::common::*;
use soft3d::math::{Mat4, Vec3};
use soft3d::mesh::Mesh;
use soft3d::tri::TriVertex;
use soft3d::Cull;

const W: usize = 40;
const H: usize = 32;

/// Twice the snapped area in i128, computed here (not by the renderer).
fn snapped_area2(p: &[(f64, f64); 3], bits: u32) -> i128 {
    let s: Vec<(i128, i128)> = p.iter().map(|&(x, y)| (snap(x, bits), snap(y, bits))).collect();
    (s[1].0 - s[0].0) * (s[2].1 - s[0].1) - (s[1].1 - s[0].1) * (s[2].0 - s[0].0)
}

/// Draws `tris` (all degenerate at `bits`) in one mode: nothing covered,
/// every one counted degenerate or off screen, none queued.
fn assert_draws_nothing(tris: &[[TriVertex; 3]], bits: u32, float: bool) {
    let mode = mode_name(bits, float);
    for t in tris {
        assert_eq!(snapped_area2(&points(t), bits), 0, "{mode}: test case {:?} is not degenerate", points(t));
    }
    for strip in [1, 7, H] {
        let (got, stats) = coverage_stats_mode(tris, W, H, strip, bits, float);
        assert!(got.iter().all(|&c| c == 0), "{mode} strip {strip}: {} pixels drawn", got.iter().filter(|&&c| c > 0).count());
        assert_eq!(stats.queued, 0, "{mode}: a degenerate triangle was queued");
        assert_eq!(stats.degenerate + stats.off_screen, tris.len() as u32, "{mode}: {stats:?}");
    }
}

#[test]
fn three_equal_vertices_draw_nothing() {
    for (bits, float) in MODES {
        let u = unit(bits);
        // On a pixel center, a pixel corner, off the grid, on the screen
        // border, and just off screen.
        let at = [(10.5, 7.5), (10.0, 7.0), (3.0 + 0.37 * u, 21.0 - 0.49 * u), (0.0, 0.0), (W as f64, H as f64), (-0.5, 5.5)];
        let tris: Vec<_> = at.iter().map(|&(x, y)| tri(&[(x, y), (x, y), (x, y)])).collect();
        assert_draws_nothing(&tris, bits, float);
    }
}

#[test]
fn collinear_vertices_draw_nothing() {
    for (bits, float) in MODES {
        let u = unit(bits);
        // Lines through pixel centers (where a fill-rule tie could draw),
        // along pixel edges, diagonals and odd slopes, with the middle
        // vertex between the others or beyond them; all on the grid.
        let cases = [
            [(2.5, 4.5), (30.5, 4.5), (12.5, 4.5)], // horizontal through centers
            [(7.5, 1.5), (7.5, 30.5), (7.5, 40.5)], // vertical through centers, one vertex off screen
            [(1.0, 1.0), (10.0, 10.0), (20.0, 20.0)],
            [(20.0, 20.0), (10.0, 10.0), (1.0, 1.0)],
            [(0.5, 0.5), (36.5, 12.5), (18.5, 6.5)],  // slope 1/3 through centers
            [(39.0, 2.0), (3.0, 29.0), (27.0, 11.0)], // slope -3/4
            [(5.0, 5.0), (5.0, 5.0), (25.0, 9.0)],    // two equal vertices
            // One sub-pixel steps along a slope of 1/2.
            [(8.0, 8.0), (8.0 + 2.0 * u, 8.0 + u), (8.0 + 200.0 * u, 8.0 + 100.0 * u)],
        ];
        let tris: Vec<_> = cases.iter().map(tri).collect();
        assert_draws_nothing(&tris, bits, float);
    }
}

#[test]
fn distinct_vertices_that_snap_to_a_point_or_a_line_draw_nothing() {
    for (bits, float) in MODES {
        let u = unit(bits);
        // Offsets below half a sub-pixel (half rounds up: -u/2 joins the
        // grid point, +u/2 would not).
        let e = [0.1 * u, -0.5 * u, 0.49 * u, -0.3 * u, 0.25 * u, -0.45 * u];
        // A pixel center where the grid has one, else a pixel corner.
        let c = if bits == 0 { 0.0 } else { 0.5 };
        let cases = [
            // Three points within one snapping cell.
            [(12.0 + c + e[0], 9.0 + c + e[1]), (12.0 + c + e[2], 9.0 + c + e[3]), (12.0 + c + e[4], 9.0 + c + e[5])],
            // Spread 30 pixels vertically, x within one cell: a vertical line.
            [(20.0 + e[0], 1.0), (20.0 + e[5], 31.0), (20.0 + e[2], 16.3)],
            // Horizontal, through a row of centers.
            [(1.0, 8.0 + c + e[2]), (35.0, 8.0 + c + e[1]), (18.0 + e[3], 8.0 + c + e[4])],
            // Near the diagonal y = x: each coordinate off by less than u/2.
            [(3.0 + e[0], 3.0 + e[2]), (30.0 + e[1], 30.0 + e[3]), (15.0 + e[4], 15.0 + e[5])],
        ];
        for c in &cases {
            let (a, b, d) = (c[0], c[1], c[2]);
            let area = (b.0 - a.0) * (d.1 - a.1) - (b.1 - a.1) * (d.0 - a.0);
            assert!(area != 0.0, "{c:?} is degenerate before snapping: not the case under test");
            assert!(oracle(c, W, H, bits).iter().all(|&v| v == 0));
        }
        let tris: Vec<_> = cases.iter().map(tri).collect();
        assert_draws_nothing(&tris, bits, float);
    }
}

#[test]
fn degenerate_triangles_among_others_leave_them_exact() {
    // A degenerate triangle between two halves of a quad: the quad is
    // still covered exactly once, as the oracle says.
    for (bits, float) in MODES {
        let u = unit(bits);
        let quad = [[(3.0, 3.0), (33.0, 4.0), (30.0, 27.0)], [(3.0, 3.0), (30.0, 27.0), (5.0, 25.0)]];
        let tris = vec![
            tri(&quad[0]),
            tri(&[(3.0, 3.0), (3.0, 3.0), (3.0, 3.0)]),
            tri(&[(3.0, 3.0), (30.0, 27.0), (3.0 + 0.4 * u, 3.0 + 0.3 * u)]), // along the diagonal
            tri(&quad[1]),
        ];
        assert_eq!(snapped_area2(&points(&tris[2]), bits), 0);
        let want = oracle_sum(&tris, W, H, bits);
        assert!(want.iter().all(|&c| c <= 1));
        let got = coverage_mode(&tris, W, H, 5, bits, float);
        assert_eq!(got, want, "{}: {}", mode_name(bits, float), diff(&got, &want, W));
    }
}

#[test]
fn degenerate_mesh_triangles_draw_nothing() {
    // Through the mesh path: repeated indices, collinear positions and a
    // triangle seen edge-on (its plane contains the eye). The projection
    // (clip = (x, y, z / 100, z)) puts these vertices exactly on pixel
    // corners, so they stay collinear after snapping in every mode.
    static P: [Vec3; 7] = [
        Vec3::new(-1.0, -1.0, 4.0), // window (15, 20)
        Vec3::new(1.0, 0.5, 4.0),   // (25, 14)
        Vec3::new(3.0, 2.0, 4.0),   // (35, 8): on the line through the first two
        Vec3::new(0.0, -1.0, 3.0),
        Vec3::new(0.0, 1.0, 5.0),
        Vec3::new(0.0, 0.0, 8.0), // x = 0: a plane through the eye
        Vec3::new(0.5, 0.5, 2.0),
    ];
    static N: [Vec3; 7] = [Vec3::ZERO; 7];
    static I: [u16; 12] = [0, 0, 1, 6, 6, 6, 0, 1, 2, 3, 4, 5];
    let mesh = Mesh::new(&P, &N, &I).unwrap();
    let view_proj = Mat4 { m: [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.01, 0.0], [0.0, 0.0, 1.0, 0.0]] };
    for (bits, float) in MODES {
        let (got, stats) = mesh_coverage_mode(&mesh, view_proj, Cull::None, W, H, bits, float);
        assert!(got.iter().all(|&c| c == 0), "{}: drawn", mode_name(bits, float));
        assert_eq!((stats.queued, stats.degenerate), (0, 4), "{}: {stats:?}", mode_name(bits, float));
    }
}
