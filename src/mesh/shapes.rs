//! Procedural meshes generated at compile time: cube, UV sphere, torus.
//!
//! The generators are `const fn`s, so a shape can be a `static` that lives
//! in flash like a baked mesh:
//!
//! ```
//! use soft3d::mesh::{torus_index_count, torus_vertex_count, MeshData};
//! static TORUS: MeshData<{ torus_vertex_count(24, 12) }, { torus_index_count(24, 12) }> =
//!     MeshData::torus(24, 12, 1.0, 0.4);
//! let mesh = TORUS.mesh();
//! assert_eq!(mesh.triangle_count(), 24 * 12 * 2);
//! ```
//!
//! The array sizes are passed as const generics (stable Rust cannot derive
//! them from the segment counts); the `*_count` functions compute them and a
//! mismatch is a compile-time error.

use super::Mesh;
use crate::math::{Vec2, Vec3};

/// Owned arrays of a generated mesh; [`MeshData::mesh`] borrows them.
#[derive(Clone, Debug)]
pub struct MeshData<const V: usize, const I: usize> {
    /// Vertex positions.
    pub positions: [Vec3; V],
    /// Unit vertex normals.
    pub normals: [Vec3; V],
    /// Texture coordinates (u right, v down).
    pub uvs: [Vec2; V],
    /// Triangle indices.
    pub indices: [u16; I],
}

/// Vertices of [`MeshData::cube`].
pub const fn cube_vertex_count() -> usize {
    24
}
/// Indices of [`MeshData::cube`].
pub const fn cube_index_count() -> usize {
    36
}
/// Vertices of [`MeshData::uv_sphere`].
pub const fn sphere_vertex_count(segments: usize, rings: usize) -> usize {
    (segments + 1) * (rings + 1)
}
/// Indices of [`MeshData::uv_sphere`] (the pole rows are single triangles).
pub const fn sphere_index_count(segments: usize, rings: usize) -> usize {
    6 * segments * (rings - 1)
}
/// Vertices of [`MeshData::torus`].
pub const fn torus_vertex_count(major: usize, minor: usize) -> usize {
    (major + 1) * (minor + 1)
}
/// Indices of [`MeshData::torus`].
pub const fn torus_index_count(major: usize, minor: usize) -> usize {
    6 * major * minor
}

impl<const V: usize, const I: usize> MeshData<V, I> {
    const EMPTY: Self = Self { positions: [Vec3::ZERO; V], normals: [Vec3::ZERO; V], uvs: [Vec2::new(0.0, 0.0); V], indices: [0; I] };

    /// The mesh view of these arrays.
    pub const fn mesh(&self) -> Mesh<'_> {
        match Mesh::new(&self.positions, &self.normals, &self.indices) {
            Ok(m) => match m.with_uvs(&self.uvs) {
                Ok(m) => m,
                Err(_) => panic!("uv count mismatch"),
            },
            Err(_) => panic!("generated mesh is invalid"),
        }
    }

    /// An axis-aligned cube centered on the origin with edge length `size`,
    /// four vertices per face so that faces are flat-lit.
    pub const fn cube(size: f32) -> Self {
        assert!(V == cube_vertex_count() && I == cube_index_count(), "use cube_vertex_count() and cube_index_count()");
        let h = size * 0.5;
        let mut d = Self::EMPTY;
        // Each face: outward normal n and in-plane axes u and v = u × n (so
        // u × v = -n); triangles (c0, c2, c1) and (c0, c3, c2) over the
        // corners c = n ± u ± v then have outward normals.
        let faces: [[f32; 9]; 6] = [
            [0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0, -1.0, 0.0, 0.0, 0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0],
            [0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0],
            [0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -1.0],
        ];
        let corners: [[f32; 2]; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
        let mut f = 0;
        while f < 6 {
            let a = faces[f];
            let n = Vec3::new(a[0], a[1], a[2]);
            let mut k = 0;
            while k < 4 {
                let (cu, cv) = (corners[k][0], corners[k][1]);
                let i = f * 4 + k;
                d.positions[i] =
                    Vec3::new((a[0] + cu * a[3] + cv * a[6]) * h, (a[1] + cu * a[4] + cv * a[7]) * h, (a[2] + cu * a[5] + cv * a[8]) * h);
                d.normals[i] = n;
                d.uvs[i] = Vec2::new((cu + 1.0) * 0.5, (1.0 - cv) * 0.5);
                k += 1;
            }
            let b = (f * 4) as u16;
            let t = f * 6;
            d.indices[t] = b;
            d.indices[t + 1] = b + 2;
            d.indices[t + 2] = b + 1;
            d.indices[t + 3] = b;
            d.indices[t + 4] = b + 3;
            d.indices[t + 5] = b + 2;
            f += 1;
        }
        d
    }

    /// A UV sphere of the given radius: `segments` around the y axis,
    /// `rings` from pole to pole (at least 2).
    pub const fn uv_sphere(segments: usize, rings: usize, radius: f32) -> Self {
        assert!(segments >= 3 && rings >= 2, "a sphere needs 3 segments and 2 rings");
        assert!(
            V == sphere_vertex_count(segments, rings) && I == sphere_index_count(segments, rings),
            "use sphere_vertex_count() and sphere_index_count()"
        );
        assert!(V <= 1 << 16, "too many vertices for u16 indices");
        let mut d = Self::EMPTY;
        let mut r = 0;
        while r <= rings {
            // Polar angle from the top pole (+y).
            let (sp, cp) = sin_cos(core::f64::consts::PI * r as f64 / rings as f64);
            let mut s = 0;
            while s <= segments {
                let (sa, ca) = sin_cos(2.0 * core::f64::consts::PI * s as f64 / segments as f64);
                let n = [sp * ca, cp, sp * sa];
                let i = r * (segments + 1) + s;
                d.normals[i] = Vec3::new(n[0] as f32, n[1] as f32, n[2] as f32);
                d.positions[i] = Vec3::new(n[0] as f32 * radius, n[1] as f32 * radius, n[2] as f32 * radius);
                d.uvs[i] = Vec2::new(s as f32 / segments as f32, r as f32 / rings as f32);
                s += 1;
            }
            r += 1;
        }
        let mut t = 0;
        r = 0;
        while r < rings {
            let mut s = 0;
            while s < segments {
                let a = (r * (segments + 1) + s) as u16;
                let b = a + 1;
                let c = a + (segments + 1) as u16;
                let e = c + 1;
                // Quad a-b (this ring), c-e (next ring, further from +y).
                // At the top ring a and b are both the pole; at the bottom
                // ring c and e are: each pole row keeps one triangle.
                if r != rings - 1 {
                    d.indices[t] = a;
                    d.indices[t + 1] = e;
                    d.indices[t + 2] = c;
                    t += 3;
                }
                if r != 0 {
                    d.indices[t] = a;
                    d.indices[t + 1] = b;
                    d.indices[t + 2] = e;
                    t += 3;
                }
                s += 1;
            }
            r += 1;
        }
        d
    }

    /// A torus around the y axis: ring radius `major`, tube radius `minor`,
    /// `major_segments` around the ring and `minor_segments` around the tube.
    pub const fn torus(major_segments: usize, minor_segments: usize, major: f32, minor: f32) -> Self {
        assert!(major_segments >= 3 && minor_segments >= 3, "a torus needs 3 segments each way");
        assert!(
            V == torus_vertex_count(major_segments, minor_segments) && I == torus_index_count(major_segments, minor_segments),
            "use torus_vertex_count() and torus_index_count()"
        );
        assert!(V <= 1 << 16, "too many vertices for u16 indices");
        let mut d = Self::EMPTY;
        let mut i = 0;
        while i <= major_segments {
            let (sa, ca) = sin_cos(2.0 * core::f64::consts::PI * i as f64 / major_segments as f64);
            let mut j = 0;
            while j <= minor_segments {
                let (sb, cb) = sin_cos(2.0 * core::f64::consts::PI * j as f64 / minor_segments as f64);
                let n = [cb * ca, sb, cb * sa];
                let ring = major as f64 + minor as f64 * cb;
                let k = i * (minor_segments + 1) + j;
                d.normals[k] = Vec3::new(n[0] as f32, n[1] as f32, n[2] as f32);
                d.positions[k] = Vec3::new((ring * ca) as f32, (minor as f64 * sb) as f32, (ring * sa) as f32);
                d.uvs[k] = Vec2::new(i as f32 / major_segments as f32, j as f32 / minor_segments as f32);
                j += 1;
            }
            i += 1;
        }
        let mut t = 0;
        i = 0;
        while i < major_segments {
            let mut j = 0;
            while j < minor_segments {
                let a = (i * (minor_segments + 1) + j) as u16;
                let b = a + 1;
                let c = a + (minor_segments + 1) as u16;
                let e = c + 1;
                d.indices[t] = a;
                d.indices[t + 1] = b;
                d.indices[t + 2] = e;
                d.indices[t + 3] = a;
                d.indices[t + 4] = e;
                d.indices[t + 5] = c;
                t += 6;
                j += 1;
            }
            i += 1;
        }
        d
    }
}

/// Sine and cosine for compile-time generation (Taylor series in `f64`
/// after reduction to [-pi, pi]; accurate to ~1e-15).
pub(crate) const fn sin_cos(x: f64) -> (f64, f64) {
    let two_pi = 2.0 * core::f64::consts::PI;
    let mut r = x - two_pi * ((x / two_pi) as i64) as f64;
    if r > core::f64::consts::PI {
        r -= two_pi;
    } else if r < -core::f64::consts::PI {
        r += two_pi;
    }
    let (mut s, mut c) = (0.0, 0.0);
    let (mut ts, mut tc) = (r, 1.0);
    let mut n = 0;
    while n < 30 {
        s += ts;
        c += tc;
        let k = (2 * n + 2) as f64;
        ts = -ts * r * r / (k * (k + 1.0));
        tc = -tc * r * r / ((k - 1.0) * k);
        n += 1;
    }
    (s, c)
}

/// Square root for compile-time use (Newton's method in `f64`).
pub(crate) const fn const_sqrt(x: f64) -> f64 {
    if x <= 0.0 || x.is_nan() {
        return 0.0;
    }
    let mut g = if x > 1.0 { x } else { 1.0 };
    let mut n = 0;
    while n < 200 {
        let next = 0.5 * (g + x / g);
        if next >= g {
            break;
        }
        g = next;
        n += 1;
    }
    g
}

#[cfg(test)]
mod tests {
    use super::*;

    static CUBE: MeshData<24, 36> = MeshData::cube(2.0);
    static SPHERE: MeshData<{ sphere_vertex_count(12, 8) }, { sphere_index_count(12, 8) }> = MeshData::uv_sphere(12, 8, 1.5);
    static TORUS: MeshData<{ torus_vertex_count(16, 8) }, { torus_index_count(16, 8) }> = MeshData::torus(16, 8, 1.0, 0.3);

    /// Every triangle's winding normal points the way its vertex normals do
    /// (outward), and no triangle is degenerate.
    fn winding_is_outward(m: Mesh<'_>) {
        let (p, n) = (|i: u16| m.position(i as usize), |i: u16| m.normal(i as usize));
        for t in m.indices().chunks_exact(3) {
            let (a, b, c) = (p(t[0]), p(t[1]), p(t[2]));
            let face = (b - a).cross(c - a);
            assert!(face.length() > 1e-6, "degenerate triangle {t:?}");
            let avg = n(t[0]) + n(t[1]) + n(t[2]);
            assert!(face.dot(avg) > 0.0, "triangle {t:?} winds inward");
        }
    }

    #[test]
    fn generated_meshes_wind_outward() {
        winding_is_outward(CUBE.mesh());
        winding_is_outward(SPHERE.mesh());
        winding_is_outward(TORUS.mesh());
    }

    #[test]
    fn generated_normals_are_unit_and_positions_on_the_surface() {
        for v in SPHERE.mesh().positions().as_f32().unwrap() {
            assert!((v.length() - 1.5).abs() < 1e-5);
        }
        for (p, n) in TORUS.positions.iter().zip(TORUS.normals.iter()) {
            assert!((n.length() - 1.0).abs() < 1e-5);
            // The point minus tube radius along the normal lies on the ring.
            let c = *p - *n * 0.3;
            assert!((c.y).abs() < 1e-5 && ((c.x * c.x + c.z * c.z).sqrt() - 1.0).abs() < 1e-5);
        }
        assert!((CUBE.mesh().bounds().radius - 3f32.sqrt()).abs() < 1e-4);
    }

    #[test]
    fn const_math_matches_std() {
        for i in -40..40 {
            let x = i as f64 * 0.37;
            let (s, c) = sin_cos(x);
            assert!((s - x.sin()).abs() < 1e-12 && (c - x.cos()).abs() < 1e-12, "{x}");
        }
        assert!((const_sqrt(2.0) - 2f64.sqrt()).abs() < 1e-15);
        assert_eq!(const_sqrt(0.0), 0.0);
    }
}
