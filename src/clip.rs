//! Clipping and culling: whole-mesh rejection by bounding sphere,
//! back-face culling in model space from baked face planes
//! ([`BackFaceTest`]), homogeneous clipping against the near and far
//! planes, and guard-band clipping in window space for vertices the
//! fixed-point setup cannot hold.
//!
//! Only the near and far planes are clipped in homogeneous space: `w` at or
//! behind the eye never reaches the perspective divide, so nothing behind
//! the camera is drawn mirrored. The screen edges need no clipping, since
//! the rasterizer clamps spans to the strip; only vertices beyond the guard
//! band ([`guard`](crate::raster::guard), thousands to millions of pixels away) are
//! clipped, in `f64` window coordinates so the rounding is far below a
//! pixel.

use crate::math::{Mat3, Mat4, Vec3, Vec4};
use crate::mesh::{FacePlane, Sphere};
use heapless::Vec;

/// Most vertices a clipped triangle can have (3 + near + far + 4 guard planes).
pub const MAX_CLIPPED: usize = 9;

/// Where a bounding sphere lies relative to the view frustum.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SphereTest {
    /// Entirely outside one plane: the mesh can be skipped.
    Outside,
    /// Entirely inside all planes.
    Inside,
    /// Crosses at least one plane.
    Crossing,
}

/// Tests a world-space sphere against the frustum of a view-projection
/// matrix (planes extracted from its rows). Non-finite input is `Outside`.
pub fn sphere_in_frustum(view_proj: &Mat4, center: Vec3, radius: f32) -> SphereTest {
    if !center.is_finite() || !radius.is_finite() || !view_proj.is_finite() {
        return SphereTest::Outside;
    }
    let m = &view_proj.m;
    let row = |r: usize| [m[r][0], m[r][1], m[r][2], m[r][3]];
    let (r0, r1, r2, r3) = (row(0), row(1), row(2), row(3));
    let comb = |a: [f32; 4], b: [f32; 4], s: f32| [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2], a[3] + s * b[3]];
    // Inside means: -w <= x <= w, -w <= y <= w, 0 <= z <= w.
    let planes = [comb(r3, r0, 1.0), comb(r3, r0, -1.0), comb(r3, r1, 1.0), comb(r3, r1, -1.0), r2, comb(r3, r2, -1.0)];
    let mut result = SphereTest::Inside;
    for p in planes {
        let n = Vec3::new(p[0], p[1], p[2]);
        let len = n.length();
        if len.is_nan() || len <= 0.0 {
            continue;
        }
        let dist = (n.dot(center) + p[3]) / len;
        if dist < -radius {
            return SphereTest::Outside;
        }
        if dist < radius {
            result = SphereTest::Crossing;
        }
    }
    result
}

/// Back-face culling in model space, before the vertex stage, from a
/// mesh's baked [face planes](crate::mesh::Mesh::with_face_planes), in
/// integers.
///
/// A triangle's winding on screen is the side of its plane the eye is on.
/// With `A` the rows `x`, `y`, `w` of the model-view-projection matrix,
/// `det[A p̂a, A p̂b, A p̂c]` (`p̂ = (p, 1)`), whose sign is the winding for
/// vertices in front of the eye (`w > 0`), equals `-(n · g - gw n · a)` for
/// the triangle's normal `n`, where `(g, gw)` is the vector of `A`'s 3×3
/// minors: the eye in homogeneous form (`gw = 0` for an orthographic
/// camera; a mirroring model matrix flips its sign). So a face is
/// clockwise, front, where `n · g - gw n · a > 0`. With the planes' offsets
/// `δ = (n · a - n · c) / r` from the bounds' center `c` (radius `r`), that
/// is `n · h - k δ` for `h = g - gw c` and `k = gw r`: four products of
/// 15-bit numbers a face, `h` and `k` scaled once per draw call.
///
/// Only faces turned away by a margin are culled here: `n · h - k δ <
/// -T`, with `T` the margin times `|h| + |k|` (at least `|g - gw p|` for
/// any point `p` of the bounds) plus a bound of the rounding. That is,
/// faces seen at less than [`EDGE_ON`] from edge-on are left to the exact
/// test on snapped screen coordinates, where snapping decides their
/// winding.
#[derive(Clone, Copy, Debug)]
pub struct BackFaceTest {
    h: [i32; 3],
    k: i32,
    threshold: i32,
}

/// The sine of the angle from edge-on within which [`BackFaceTest`] leaves
/// a face to the screen-space test (about 1.8°).
pub const EDGE_ON: f32 = 1.0 / 32.0;

impl BackFaceTest {
    /// The test for a mesh of bounds `bounds` drawn with model-view-projection
    /// `mvp`; `None` if it is not finite or the eye is undefined.
    #[inline(always)]
    pub fn new(mvp: &Mat4, bounds: Sphere) -> Option<Self> {
        let m = &mvp.m;
        let a = [m[0], m[1], m[3]];
        // The 3×3 minor of `a` without column `skip`.
        let minor = |skip: usize| {
            let c: [usize; 3] = match skip {
                0 => [1, 2, 3],
                1 => [0, 2, 3],
                2 => [0, 1, 3],
                _ => [0, 1, 2],
            };
            Mat3 { m: a.map(|row| c.map(|k| row[k])) }.determinant()
        };
        let (g, gw) = ([-minor(0), minor(1), -minor(2)], minor(3));
        let c = bounds.center;
        let h = [g[0] - gw * c.x, g[1] - gw * c.y, g[2] - gw * c.z];
        let k = gw * bounds.radius;
        let big = h[0].abs().max(h[1].abs()).max(h[2].abs()).max(k.abs());
        // Not finite (NaN fails the test too), or no eye at all.
        if !(big > 0.0 && big <= f32::MAX) {
            return None;
        }
        // Scaled to at most 2^14 - 1: with plane steps of at most 2^14 (a
        // unit normal; |δ| <= 1 up to rounding, at most 2^15 clamped), each
        // product is below 2^29 and the sum of four below 2^31.
        let s = 16383.0 / big;
        // To nearest (`as` truncates; the values are within ±16383.5).
        let round = |v: f32| {
            let r = v * s;
            (if r < 0.0 { r - 0.5 } else { r + 0.5 }) as i32
        };
        let (hi, ki) = ([round(h[0]), round(h[1]), round(h[2])], round(k));
        // The exact `(n · h - k δ) 2^14 s` and the integer sum differ by the
        // rounding of the eight factors: at most 4 (2^13 + 2^13 + 1) < 2^16.
        let length = Vec3::new(h[0], h[1], h[2]).length() + k.abs();
        let threshold = EDGE_ON * length * s * crate::mesh::FACE_PLANE_ONE as f32 + 65536.0;
        Some(Self { h: hi, k: ki, threshold: threshold as i32 })
    }

    /// Whether the face of plane `p` is turned away from the eye by more
    /// than the margin. False for a zero plane.
    #[inline(always)]
    pub fn culls(&self, p: &FacePlane) -> bool {
        let t = p[0] as i32 * self.h[0] + p[1] as i32 * self.h[1] + p[2] as i32 * self.h[2] - p[3] as i32 * self.k;
        t < -self.threshold
    }
}

/// A vertex in clip space with its varyings.
#[derive(Clone, Copy, Debug)]
pub struct ClipVertex<const V: usize> {
    /// Homogeneous clip-space position.
    pub pos: Vec4,
    /// Varyings.
    pub attrs: [f32; V],
    /// Index of the frame vertex this is a copy of, or [`NO_SOURCE`].
    pub src: u16,
}

/// Marks a clipped vertex that is new (not a copy of an input vertex).
pub const NO_SOURCE: u16 = u16::MAX;

/// A vertex in window space (pixels, y down) before snapping.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindowVertex<const V: usize> {
    /// x in pixels.
    pub x: f64,
    /// y in pixels, down.
    pub y: f64,
    /// Depth in [0, 1].
    pub z: f32,
    /// `1 / w`.
    pub q: f32,
    /// Varyings.
    pub attrs: [f32; V],
    /// Index of the frame vertex this is a copy of, or [`NO_SOURCE`].
    pub src: u16,
}

/// A convex polygon being clipped.
pub type Polygon<T> = Vec<T, MAX_CLIPPED>;

/// Sutherland–Hodgman against one plane: keeps the part where
/// `dist(v) >= 0`, inserting `lerp(inside, outside, t)` where an edge
/// crosses. The new vertex is always interpolated from the inside end, so
/// two triangles sharing the edge compute the same bits (no crack). Never
/// grows past [`MAX_CLIPPED`] (a convex polygon gains at most one vertex per
/// plane, and callers clip against at most six planes).
pub fn clip_polygon<T: Copy>(poly: &mut Polygon<T>, dist: impl Fn(&T) -> f64, lerp: impl Fn(&T, &T, f64) -> T) {
    let input = core::mem::take(poly);
    let n = input.len();
    for i in 0..n {
        let (a, b) = (&input[i], &input[(i + 1) % n]);
        let (da, db) = (dist(a), dist(b));
        if da >= 0.0 {
            let _ = poly.push(*a);
        }
        if da >= 0.0 && db < 0.0 {
            let _ = poly.push(lerp(a, b, da / (da - db)));
        } else if da < 0.0 && db >= 0.0 {
            let _ = poly.push(lerp(b, a, db / (db - da)));
        }
    }
}

/// Clips a clip-space triangle to `0 <= z <= w`.
///
/// Crossings are computed in `f64` and placed exactly on the plane
/// (`z = 0`, or `z = w`). In `f32`, `a + (b - a)·t` from a far vertex
/// (say at 10^7) is off by about `|b|·2^-24` ≈ 0.6 in `w`: the crossing's
/// `w`, which is the near distance (0.1 for the default camera), could
/// land anywhere, even below zero, and the clipped edge moved or flipped
/// to the other side of the screen. Clipping is rare, so `f64` costs
/// nothing measurable.
pub fn clip_near_far<const V: usize>(poly: &mut Polygon<ClipVertex<V>>) {
    let lerp = |a: &ClipVertex<V>, b: &ClipVertex<V>, t: f64| {
        let tf = t as f32;
        let mut attrs = a.attrs;
        for (o, (x, y)) in attrs.iter_mut().zip(a.attrs.iter().zip(b.attrs.iter())) {
            *o = x + (y - x) * tf;
        }
        let at = |p: f32, q: f32| (p as f64 + (q as f64 - p as f64) * t) as f32;
        let (pa, pb) = (a.pos, b.pos);
        let pos = Vec4 { x: at(pa.x, pb.x), y: at(pa.y, pb.y), z: at(pa.z, pb.z), w: at(pa.w, pb.w) };
        ClipVertex { pos, attrs, src: NO_SOURCE }
    };
    clip_polygon(
        poly,
        |v| v.pos.z as f64,
        |a, b, t| {
            let mut v = lerp(a, b, t);
            v.pos.z = 0.0;
            v
        },
    );
    clip_polygon(
        poly,
        |v| v.pos.w as f64 - v.pos.z as f64,
        |a, b, t| {
            let mut v = lerp(a, b, t);
            v.pos.z = v.pos.w;
            v
        },
    );
}

/// Projects a clip-space vertex (with `w > 0`) to window coordinates of a
/// `width` × `height` viewport.
pub fn to_window<const V: usize>(v: &ClipVertex<V>, width: f32, height: f32) -> WindowVertex<V> {
    let q = 1.0 / v.pos.w;
    WindowVertex {
        x: ((v.pos.x * q + 1.0) * 0.5 * width) as f64,
        y: ((1.0 - v.pos.y * q) * 0.5 * height) as f64,
        z: v.pos.z * q,
        q,
        attrs: v.attrs,
        src: v.src,
    }
}

/// Clips a window-space polygon to the square `[-limit, limit]²` (pixels).
/// Depth and `1/w` are linear in window space; varyings are interpolated
/// as `value * q` when `perspective` is set, so the result is exact either way.
pub fn clip_guard<const V: usize>(poly: &mut Polygon<WindowVertex<V>>, limit: f64, perspective: bool) {
    let lerp = |a: &WindowVertex<V>, b: &WindowVertex<V>, t: f64| {
        let tf = t as f32;
        let q = a.q + (b.q - a.q) * tf;
        let mut attrs = a.attrs;
        for (o, (x, y)) in attrs.iter_mut().zip(a.attrs.iter().zip(b.attrs.iter())) {
            *o = if perspective && q > 0.0 { (x * a.q + (y * b.q - x * a.q) * tf) / q } else { x + (y - x) * tf };
        }
        WindowVertex { x: a.x + (b.x - a.x) * t, y: a.y + (b.y - a.y) * t, z: a.z + (b.z - a.z) * tf, q, attrs, src: NO_SOURCE }
    };
    // The crossing lies exactly on the band, and its other coordinate is
    // interpolated from the endpoint nearer the band: from the far end (say
    // at 1e300) `a + (b - a)·t` cancels catastrophically, the clipped
    // polygon folds, and its fan triangles overlap.
    let on = |bound: f64, along_x: bool| {
        move |a: &WindowVertex<V>, b: &WindowVertex<V>, t: f64| {
            let mut v = lerp(a, b, t);
            let (pa, pb) = if along_x { ((a.x, a.y), (b.x, b.y)) } else { ((a.y, a.x), (b.y, b.x)) };
            let (near, far) = if (bound - pa.0).abs() <= (bound - pb.0).abs() { (pa, pb) } else { (pb, pa) };
            let other = near.1 + (far.1 - near.1) * ((bound - near.0) / (far.0 - near.0));
            // Spans near f64::MAX overflow to inf · 0: keep the near end.
            let other = if other.is_finite() { other } else { near.1 };
            if along_x {
                (v.x, v.y) = (bound, other);
            } else {
                (v.x, v.y) = (other, bound);
            }
            v
        }
    };
    clip_polygon(poly, |v| v.x + limit, on(-limit, true));
    clip_polygon(poly, |v| limit - v.x, on(limit, true));
    clip_polygon(poly, |v| v.y + limit, on(-limit, false));
    clip_polygon(poly, |v| limit - v.y, on(limit, false));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Twice the signed window area (y down; positive is clockwise, a
    /// front face) of a model-space triangle, in `f64`, if all three
    /// vertices are in front of the eye.
    fn window_area2(mvp: &Mat4, p: [Vec3; 3]) -> Option<f64> {
        let mut s = [(0.0f64, 0.0f64); 3];
        for (k, v) in p.iter().enumerate() {
            let m = &mvp.m;
            let row = |r: usize| m[r][0] as f64 * v.x as f64 + m[r][1] as f64 * v.y as f64 + m[r][2] as f64 * v.z as f64 + m[r][3] as f64;
            let (x, y, w) = (row(0), row(1), row(3));
            if w <= 1e-9 {
                return None;
            }
            s[k] = (x / w, -y / w);
        }
        Some((s[1].0 - s[0].0) * (s[2].1 - s[0].1) - (s[1].1 - s[0].1) * (s[2].0 - s[0].0))
    }

    #[test]
    fn model_space_culling_culls_only_back_faces() {
        let mut next = crate::math::xorshift(0x9E37_79B9);
        let mut u = move |lo: f32, hi: f32| lo + (hi - lo) * (next() as f32 / u32::MAX as f32);
        // Perspective and orthographic cameras, models turned, scaled
        // unevenly and mirrored.
        let orthographic = Mat4 { m: [[0.1, 0.0, 0.0, 0.0], [0.0, 0.13, 0.0, 0.0], [0.0, 0.0, 0.01, 0.5], [0.0, 0.0, 0.0, 1.0]] };
        let (mut culled, mut back) = (0, 0);
        for case in 0..400 {
            let eye = Vec3::new(u(-20.0, 20.0), u(-20.0, 20.0), u(-20.0, 20.0));
            let view = Mat4::look_at_lh(eye, Vec3::ZERO, Vec3::new(0.0, 1.0, 0.0));
            let projection = if case % 4 == 3 { orthographic } else { Mat4::perspective_fov_lh(u(0.4, 1.5), 4.0 / 3.0, 0.1, 100.0) };
            let mirror = if case % 2 == 1 { -1.0 } else { 1.0 };
            let model = Mat4::rotation_y(u(0.0, 6.3))
                * Mat4::rotation_x(u(0.0, 6.3))
                * Mat4::scaling(Vec3::new(mirror * u(0.2, 3.0), u(0.2, 3.0), u(0.2, 3.0)));
            let mvp = projection * view * model;
            let bounds = Sphere { center: Vec3::new(0.5, -0.5, 0.25), radius: 2.0 };
            let test = BackFaceTest::new(&mvp, bounds).unwrap();
            for _ in 0..100 {
                let mut point = || {
                    let d = Vec3::new(u(-1.0, 1.0), u(-1.0, 1.0), u(-1.0, 1.0)) * 1.15;
                    bounds.center + d
                };
                let p = [point(), point(), point()];
                let Some(area) = window_area2(&mvp, p) else { continue };
                let plane = crate::mesh::face_plane(p[0], p[1], p[2], bounds);
                if test.culls(&plane) {
                    assert!(area < 0.0, "case {case}: a front face {p:?} (area {area}) was culled");
                    culled += 1;
                }
                back += usize::from(area < 0.0);
            }
        }
        // Most back faces are culled (the sign is not inverted, and the
        // margin is small).
        assert!(culled * 10 > back * 9, "{culled} of {back} back faces culled");
    }

    fn cv(x: f32, y: f32, z: f32, w: f32, a: f32) -> ClipVertex<1> {
        ClipVertex { pos: Vec4::new(x, y, z, w), attrs: [a], src: 0 }
    }

    #[test]
    fn near_clip_splits_into_at_most_two_triangles() {
        // One vertex behind: quad. Two behind: triangle.
        let mut p: Polygon<_> =
            [cv(0.0, 0.0, -1.0, 0.5, 0.0), cv(1.0, 0.0, 1.0, 2.0, 1.0), cv(0.0, 1.0, 1.0, 2.0, 1.0)].into_iter().collect();
        clip_near_far(&mut p);
        assert_eq!(p.len(), 4);
        assert!(p.iter().all(|v| v.pos.z >= -1e-6 && v.pos.w > 0.0));
        let mut p: Polygon<_> =
            [cv(0.0, 0.0, -1.0, 0.5, 0.0), cv(1.0, 0.0, -1.0, 0.5, 0.0), cv(0.0, 1.0, 1.0, 2.0, 1.0)].into_iter().collect();
        clip_near_far(&mut p);
        assert_eq!(p.len(), 3);
        // The attribute is interpolated at the crossing: z goes -1 -> 1, so t = 0.5.
        assert!(p.iter().any(|v| (v.attrs[0] - 0.5).abs() < 1e-6));
    }

    #[test]
    fn crossings_lie_exactly_inside_the_depth_range() {
        // From the `clip` fuzzer: a projection with z ≈ 1.001·w, so where
        // an edge crosses z = 0, w is ~1e-4 while the far vertex sits at
        // 4.5e6. In f32 the crossing's w came out -2.4e-5: the vertex
        // projected to the other side of the screen, and colors
        // interpolated toward it left their range.
        let (a, b, c) = (
            cv(23.042974, -13560.758, 1686.259, 1684.5729, 0.0),
            cv(-55144256.0, -3253765.0, -4533410.5, -4528877.0, 1.0),
            cv(-11020.453, -14209.659, 778.0358, 777.2578, 0.5),
        );
        let mut p: Polygon<_> = [a, b, c].into_iter().collect();
        clip_near_far(&mut p);
        assert!(!p.is_empty());
        for v in &p {
            assert!(v.pos.z >= 0.0 && v.pos.z <= v.pos.w && v.pos.w > 0.0, "{:?}", v.pos);
        }
        // A well-formed projection (z = w - 0.1): the near crossings have
        // w = 0.1, whatever the distance of the vertex behind the eye.
        let behind = -4.0e7 - 0.7;
        let mut p: Polygon<_> =
            [cv(0.0, 0.0, 0.9, 1.0, 0.0), cv(3.0, 0.0, 0.9, 1.0, 0.0), cv(behind, behind, behind - 0.1, behind, 1.0)].into_iter().collect();
        clip_near_far(&mut p);
        assert_eq!(p.len(), 4);
        for v in p.iter().filter(|v| v.src == NO_SOURCE) {
            assert_eq!(v.pos.z, 0.0);
            assert!((v.pos.w - 0.1).abs() < 1e-6, "w = {}", v.pos.w);
        }
    }

    #[test]
    fn all_behind_clips_to_nothing() {
        let mut p: Polygon<_> =
            [cv(0.0, 0.0, -1.0, 0.5, 0.0), cv(1.0, 0.0, -2.0, 0.5, 0.0), cv(0.0, 1.0, -0.1, 0.5, 0.0)].into_iter().collect();
        clip_near_far(&mut p);
        assert!(p.is_empty());
    }

    #[test]
    fn sphere_test_classifies() {
        let vp = Mat4::perspective_fov_lh(1.0, 1.0, 0.1, 100.0);
        assert_eq!(sphere_in_frustum(&vp, Vec3::new(0.0, 0.0, 10.0), 1.0), SphereTest::Inside);
        assert_eq!(sphere_in_frustum(&vp, Vec3::new(0.0, 0.0, -10.0), 1.0), SphereTest::Outside);
        assert_eq!(sphere_in_frustum(&vp, Vec3::new(0.0, 0.0, 0.0), 1.0), SphereTest::Crossing);
        assert_eq!(sphere_in_frustum(&vp, Vec3::new(100.0, 0.0, 10.0), 1.0), SphereTest::Outside);
        assert_eq!(sphere_in_frustum(&vp, Vec3::new(f32::NAN, 0.0, 10.0), 1.0), SphereTest::Outside);
    }

    #[test]
    fn guard_clip_keeps_depth_and_perspective_exact() {
        let w = |x: f64, q: f32, a: f32| WindowVertex { x, y: 0.0, z: 0.5, q, attrs: [a], src: NO_SOURCE };
        let mut p: Polygon<_> =
            [w(-3000.0, 1.0, 0.0), w(1000.0, 0.25, 4.0), WindowVertex { y: 10.0, ..w(0.0, 1.0, 0.0) }].into_iter().collect();
        clip_guard(&mut p, 2000.0, true);
        assert!(p.iter().all(|v| v.x >= -2000.0 && v.x <= 2000.0));
        // At x = -2000, t = 0.25 along the first edge: q = 0.8125 and the
        // perspective-correct value is (0 + 0.25 * (4 * 0.25)) / 0.8125.
        let v = p.iter().find(|v| v.x == -2000.0 && v.y == 0.0).unwrap();
        assert!((v.q - 0.8125).abs() < 1e-6);
        assert!((v.attrs[0] - 0.25 / 0.8125).abs() < 1e-6);
    }
}
