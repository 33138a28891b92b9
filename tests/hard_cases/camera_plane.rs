//! Behind and across the camera, through the mesh path (clip space, near
//! plane clipping): a vertex behind the eye, two behind, one exactly on
//! the near plane, w = 0, w < 0, a triangle containing the eye, the eye
//! inside a closed mesh. Only what is in front of the near plane is drawn,
//! nothing mirrored.
//!
//! The oracle casts an f64 ray from the eye through each pixel center
//! and intersects it with the triangle (independent of the pipeline). The
//! eye is at the origin looking along +z (the view-projection matrix is a
//! plain perspective projection), so a hit at parameter t has view depth
//! t and is drawn when near <= t <= far. Pixels whose center is within
//! half a sub-pixel (plus 0.02 px for f32 projection and clipping) of the
//! visible region's boundary may go either way — vertices snap by up to
//! half a sub-pixel per axis — and are left out; every other pixel must
//! match.

use crate::common::*;
use soft3d::math::{Mat4, Vec3};
use soft3d::mesh::Mesh;
use soft3d::Cull;

const W: usize = 64;
const H: usize = 48;
const FOV: f64 = 1.2;
const NEAR: f32 = 0.1;
const FAR: f32 = 100.0;

fn view_proj() -> Mat4 {
    Mat4::perspective_fov_lh(FOV as f32, W as f32 / H as f32, NEAR, FAR)
}

/// Whether the ray from the eye through window point (sx, sy) meets
/// triangle `t` between the near and far planes.
fn ray_hits(t: &[P3; 3], sx: f64, sy: f64) -> bool {
    let ys = 1.0 / (FOV / 2.0).tan();
    let xs = ys / (W as f64 / H as f64);
    let d = [(2.0 * sx / W as f64 - 1.0) / xs, (1.0 - 2.0 * sy / H as f64) / ys, 1.0];
    // Möller–Trumbore with the ray origin at 0.
    let (e1, e2) = (sub(t[1], t[0]), sub(t[2], t[0]));
    let p = cross(d, e2);
    let det = dot(e1, p);
    if det.abs() < 1e-300 {
        return false; // the ray runs in the triangle's plane: nothing to see
    }
    let s = [-t[0][0], -t[0][1], -t[0][2]];
    let u = dot(s, p) / det;
    let q = cross(s, e1);
    let v = dot(d, q) / det;
    let depth = dot(e2, q) / det;
    u >= 0.0 && v >= 0.0 && u + v <= 1.0 && depth >= NEAR as f64 && depth <= FAR as f64
}

/// The oracle for one pixel: `Some(covered)` if every point within `r` of
/// its center (a 5 × 5 grid of samples) agrees, `None` if it is ambiguous.
fn ray_oracle(tris: &[[P3; 3]], x: usize, y: usize, r: f64) -> Option<bool> {
    let hit = |sx: f64, sy: f64| tris.iter().any(|t| ray_hits(t, sx, sy));
    let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
    let want = hit(cx, cy);
    for i in -2..=2 {
        for j in -2..=2 {
            if hit(cx + r * i as f64 / 2.0, cy + r * j as f64 / 2.0) != want {
                return None;
            }
        }
    }
    Some(want)
}

/// Draws `tris` (view space, model = view = identity) in every mode and
/// compares with the ray cast; each pixel is drawn at most once. Returns
/// the number of pixels the oracle is sure are covered.
fn assert_matches_ray_cast(tris: &[[P3; 3]], cull: Cull, what: &str) -> usize {
    let positions: Vec<Vec3> = tris.iter().flatten().map(|p| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32)).collect();
    let normals = vec![Vec3::ZERO; positions.len()];
    let indices: Vec<u16> = (0..positions.len() as u16).collect();
    let mesh = Mesh::new(&positions, &normals, &indices).unwrap();
    // The oracle sees the f32 positions the renderer gets.
    let tris: Vec<[P3; 3]> = positions.chunks(3).map(|c| [0, 1, 2].map(|k| [c[k].x as f64, c[k].y as f64, c[k].z as f64])).collect();
    let mut sure = 0;
    for (bits, float) in MODES {
        let mode = mode_name(bits, float);
        let (got, _) = mesh_coverage_mode(&mesh, view_proj(), cull, W, H, bits, float);
        let r = unit(bits) / 2.0 + 0.02;
        sure = 0;
        for y in 0..H {
            for x in 0..W {
                let g = got[y * W + x];
                assert!(g <= 1, "{mode}, {what}: ({x}, {y}) drawn {g} times");
                if let Some(want) = ray_oracle(&tris, x, y, r) {
                    assert_eq!(g == 1, want, "{mode}, {what}: pixel ({x}, {y}) against the ray cast");
                    sure += want as usize;
                }
            }
        }
    }
    sure
}

#[test]
fn one_vertex_behind_the_eye() {
    let sure = assert_matches_ray_cast(&[[[-0.5, -0.3, -1.0], [1.5, -0.4, 3.0], [-1.0, 0.8, 2.5]]], Cull::None, "one behind");
    assert!(sure > 300, "only {sure} pixels visible: not a test of clipping");
    // A steeper one, the vertex behind the eye twice as far back.
    assert_matches_ray_cast(&[[[0.4, 0.2, -2.0], [-0.3, -0.6, 1.0], [1.2, 0.3, 0.8]]], Cull::None, "one behind, steep");
}

#[test]
fn two_vertices_behind_the_eye() {
    let sure = assert_matches_ray_cast(&[[[-0.5, -0.3, -1.0], [1.2, 0.2, -0.5], [0.2, -0.1, 2.0]]], Cull::None, "two behind");
    assert!(sure > 100, "only {sure} pixels visible");
    assert_matches_ray_cast(&[[[-2.0, 0.5, -3.0], [2.0, 0.5, -3.0], [0.0, -0.2, 0.5]]], Cull::None, "two behind, tip just past near");
}

#[test]
fn a_vertex_exactly_on_the_near_plane() {
    // Clip z is exactly 0 there (not clipped, w = near). With the other
    // two in front, and with one in front and one behind.
    let n = NEAR as f64;
    let sure = assert_matches_ray_cast(&[[[0.02, -0.01, n], [1.0, 0.4, 2.0], [-0.6, 0.5, 1.5]]], Cull::None, "on near, two in front");
    assert!(sure > 100, "only {sure} pixels visible");
    assert_matches_ray_cast(&[[[0.03, 0.02, n], [0.8, -0.5, 2.0], [-0.6, 0.5, -1.5]]], Cull::None, "on near, one behind");
    // All three on the near plane: a tiny triangle right in front of the eye.
    assert_matches_ray_cast(&[[[-0.03, -0.02, n], [0.04, -0.02, n], [0.0, 0.03, n]]], Cull::None, "all on near");
}

#[test]
fn a_vertex_with_w_zero() {
    // A vertex in the eye plane (view z = 0, so w = 0), and one at the eye
    // itself (x = y = w = 0): never divided by, clipped away.
    let sure = assert_matches_ray_cast(&[[[0.3, -0.2, 0.0], [1.0, 0.5, 2.0], [-0.8, 0.3, 1.5]]], Cull::None, "w = 0");
    assert!(sure > 200, "only {sure} pixels visible");
    assert_matches_ray_cast(&[[[0.0, 0.0, 0.0], [1.0, -0.5, 2.0], [-0.7, -0.4, 2.5]]], Cull::None, "vertex at the eye");
    assert_matches_ray_cast(&[[[0.5, 0.5, 0.0], [-0.5, 0.5, 0.0], [0.0, -0.3, 1.0]]], Cull::None, "two with w = 0");
}

#[test]
fn vertices_with_w_negative_are_not_mirrored() {
    // Vertices behind the eye whose naive projection (x/w, y/w with w < 0)
    // lands on screen: the mirror image must not appear.
    let sure = assert_matches_ray_cast(&[[[-3.0, 2.0, -5.0], [2.0, -1.5, -4.0], [0.1, 0.1, 1.5]]], Cull::None, "two with w < 0");
    assert!(sure > 0);
    // Entirely behind: nothing at all, though the mirror fills the screen.
    for (bits, float) in MODES {
        static P: [Vec3; 3] = [Vec3::new(-3.0, -3.0, -2.0), Vec3::new(3.0, -3.0, -2.0), Vec3::new(0.0, 3.0, -2.0)];
        static N: [Vec3; 3] = [Vec3::ZERO; 3];
        static I: [u16; 3] = [0, 1, 2];
        let (got, stats) = mesh_coverage_mode(&Mesh::new(&P, &N, &I).unwrap(), view_proj(), Cull::None, W, H, bits, float);
        assert!(got.iter().all(|&c| c == 0), "{}: a triangle behind the eye was drawn", mode_name(bits, float));
        assert_eq!(stats.queued, 0);
    }
    assert_eq!(assert_matches_ray_cast(&[[[-3.0, -3.0, -2.0], [3.0, -3.0, -2.0], [0.0, 3.0, -0.01]]], Cull::None, "behind"), 0);
}

#[test]
fn random_triangles_across_the_camera_plane_match_the_ray_cast() {
    // Vertices around the eye, most triangles crossing z = 0 or the near
    // plane, in both windings (culling off).
    let mut rng = Rng(0xca3e7a);
    let tris: Vec<[P3; 3]> = (0..24).map(|_| [0; 3].map(|_| [rng.range(-3.0, 3.0), rng.range(-2.5, 2.5), rng.range(-2.0, 4.0)])).collect();
    for (i, t) in tris.iter().enumerate() {
        assert_matches_ray_cast(&[*t], Cull::None, &format!("random triangle {i}: {t:?}"));
    }
}

#[test]
fn a_triangle_containing_the_eye_draws_at_most_its_edge_on_line() {
    // Its plane passes through the eye, so it is seen edge-on: a line of
    // zero area. In the planes x = 0 and y = 0 the projected vertices are
    // exactly collinear (on screen column 32, row 24) and nothing is drawn.
    for t in [[[0.0, -1.0, -1.0], [0.0, 2.0, -1.0], [0.0, -1.0, 2.0]], [[-1.0, 0.0, -1.0], [-1.0, 0.0, 2.0], [2.0, 0.0, -1.0]]] {
        assert_eq!(assert_matches_ray_cast(&[t], Cull::None, &format!("edge-on {t:?}")), 0);
        let positions: Vec<Vec3> = t.iter().map(|p| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32)).collect();
        let mesh = Mesh::new(&positions, &[Vec3::ZERO; 3], &[0, 1, 2]).unwrap();
        for (bits, float) in MODES {
            let (got, _) = mesh_coverage_mode(&mesh, view_proj(), Cull::None, W, H, bits, float);
            assert!(got.iter().all(|&c| c == 0), "{}: {t:?} drew pixels", mode_name(bits, float));
        }
    }
    // In the tilted plane y = 0.5 z the projection is the row
    // y = H/2 · (1 − 0.5 · ys); rounding may leave a sliver of the snapped
    // triangles, but only within half a sub-pixel (+ rounding) of it.
    let t = [[-2.0f32, -0.5, -1.0], [2.0, -0.5, -1.0], [0.0, 1.5, 3.0]];
    let positions: Vec<Vec3> = t.iter().map(|p| Vec3::new(p[0], p[1], p[2])).collect();
    let mesh = Mesh::new(&positions, &[Vec3::ZERO; 3], &[0, 1, 2]).unwrap();
    let line = H as f64 / 2.0 * (1.0 - 0.5 / (FOV / 2.0).tan());
    for (bits, float) in MODES {
        let (got, _) = mesh_coverage_mode(&mesh, view_proj(), Cull::None, W, H, bits, float);
        for (i, &c) in got.iter().enumerate() {
            let cy = (i / W) as f64 + 0.5;
            assert!(
                c == 0 || (cy - line).abs() <= unit(bits) / 2.0 + 0.01,
                "{}: ({}, {}) drawn, the line is at y = {line}",
                mode_name(bits, float),
                i % W,
                i / W
            );
        }
    }
}

/// A cube of half-size `h` around the eye, turned by `rot` (f64 rotation
/// matrix rows), its faces wound to face outward (or inward).
fn cube_around_the_eye(h: f64, rot: [P3; 3], inward: bool) -> Vec<[P3; 3]> {
    let corner = |i: usize| {
        let p = [if i & 1 == 0 { -h } else { h }, if i & 2 == 0 { -h } else { h }, if i & 4 == 0 { -h } else { h }];
        [dot(rot[0], p), dot(rot[1], p), dot(rot[2], p)]
    };
    // Each face as a quad of corner indices, split along one diagonal.
    let faces = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]];
    let mut out = Vec::new();
    for f in faces {
        for t in [[f[0], f[1], f[2]], [f[0], f[2], f[3]]] {
            let mut t = t.map(corner);
            // Outward: (b − a) × (c − a) points away from the center.
            let centroid = [0, 1, 2].map(|k| (t[0][k] + t[1][k] + t[2][k]) / 3.0);
            if (dot(cross(sub(t[1], t[0]), sub(t[2], t[0])), centroid) > 0.0) == inward {
                t.swap(1, 2);
            }
            out.push(t);
        }
    }
    out
}

#[test]
fn the_eye_inside_a_closed_cube_sees_every_pixel_once() {
    // Every ray from inside a closed convex mesh leaves it exactly once:
    // with culling off every pixel is drawn exactly once, though most
    // triangles cross the eye plane and are clipped (shared edges clipped
    // to the same points). Its outward faces are back faces from inside.
    let (a, b) = (0.5f64, 0.3f64);
    let rot = [[a.cos(), 0.0, a.sin()], [a.sin() * b.sin(), b.cos(), -a.cos() * b.sin()], [-a.sin() * b.cos(), b.sin(), a.cos() * b.cos()]];
    for (h, inward) in [(1.0, false), (2.5, true), (0.4, false)] {
        let cube = cube_around_the_eye(h, rot, inward);
        let positions: Vec<Vec3> = cube.iter().flatten().map(|p| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32)).collect();
        let normals = vec![Vec3::ZERO; positions.len()];
        let indices: Vec<u16> = (0..positions.len() as u16).collect();
        let mesh = Mesh::new(&positions, &normals, &indices).unwrap();
        for (bits, float) in MODES {
            let mode = mode_name(bits, float);
            let (all, _) = mesh_coverage_mode(&mesh, view_proj(), Cull::None, W, H, bits, float);
            assert!(all.iter().all(|&c| c == 1), "{mode}, cube {h}: {}", diff(&all, &[1; W * H], W));
            let (front, _) = mesh_coverage_mode(&mesh, view_proj(), Cull::Back, W, H, bits, float);
            let want = if inward { 1 } else { 0 };
            assert!(front.iter().all(|&c| c == want), "{mode}, cube {h} inward {inward}: {}", diff(&front, &[want; W * H], W));
        }
    }
}
