//! Meshes as borrowed, flash-resident data.
//!
//! A [`Mesh`] borrows slices, so it can be a `static` whose arrays stay in
//! flash; it is validated once when built (in a `const` context, a bad mesh
//! is a compile error) and carries its bounding sphere.
//!
//! Winding: a triangle `(a, b, c)` faces the side its normal
//! `(b - a) × (c - a)` points to. Seen from that side in the left-handed
//! frame it is clockwise on screen. (Babylon's files wind the other way;
//! the [`babylon`](crate::babylon) loader rewinds them.)

mod shapes;

pub use shapes::{
    cube_index_count, cube_vertex_count, sphere_index_count, sphere_vertex_count, torus_index_count, torus_vertex_count, MeshData,
};

use crate::math::{Vec2, Vec3};
use embedded_graphics::pixelcolor::Rgb888;

/// Why a mesh was rejected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshError {
    /// `normals` (or `uvs`, `colors`) is not as long as `positions`.
    AttributeLength {
        /// Which attribute.
        attribute: &'static str,
        /// Its length.
        len: usize,
        /// The number of positions.
        positions: usize,
    },
    /// The index count is not a multiple of three.
    IndexCount(usize),
    /// An index points past the last vertex.
    IndexOutOfRange {
        /// Position in the index array.
        at: usize,
        /// The index found there.
        index: u16,
        /// The number of vertices.
        vertices: usize,
    },
    /// More vertices than a `u16` index can address.
    TooManyVertices(usize),
}

impl core::fmt::Display for MeshError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self {
            MeshError::AttributeLength { attribute, len, positions } => {
                write!(f, "mesh has {len} {attribute} for {positions} positions")
            }
            MeshError::IndexCount(n) => write!(f, "mesh index count {n} is not a multiple of 3"),
            MeshError::IndexOutOfRange { at, index, vertices } => {
                write!(f, "mesh index {index} at position {at} is out of range (mesh has {vertices} vertices)")
            }
            MeshError::TooManyVertices(n) => write!(f, "mesh has {n} vertices; at most 65536 can be indexed"),
        }
    }
}

/// A bounding sphere in model space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Center.
    pub center: Vec3,
    /// Radius.
    pub radius: f32,
}

/// An indexed triangle mesh borrowing its arrays.
#[derive(Clone, Copy, Debug)]
pub struct Mesh<'a> {
    positions: &'a [Vec3],
    normals: &'a [Vec3],
    uvs: Option<&'a [Vec2]>,
    colors: Option<&'a [Rgb888]>,
    indices: &'a [u16],
    bounds: Sphere,
}

impl<'a> Mesh<'a> {
    /// Builds and validates a mesh: one normal per position, indices in
    /// range and a multiple of three. Usable in `const` items.
    pub const fn new(positions: &'a [Vec3], normals: &'a [Vec3], indices: &'a [u16]) -> Result<Self, MeshError> {
        if positions.len() > 1 << 16 {
            return Err(MeshError::TooManyVertices(positions.len()));
        }
        if normals.len() != positions.len() {
            return Err(MeshError::AttributeLength { attribute: "normals", len: normals.len(), positions: positions.len() });
        }
        if indices.len() % 3 != 0 {
            return Err(MeshError::IndexCount(indices.len()));
        }
        let mut i = 0;
        while i < indices.len() {
            if indices[i] as usize >= positions.len() {
                return Err(MeshError::IndexOutOfRange { at: i, index: indices[i], vertices: positions.len() });
            }
            i += 1;
        }
        Ok(Self { positions, normals, uvs: None, colors: None, indices, bounds: bounding_sphere(positions) })
    }

    /// Adds texture coordinates, one per position.
    pub const fn with_uvs(mut self, uvs: &'a [Vec2]) -> Result<Self, MeshError> {
        if uvs.len() != self.positions.len() {
            return Err(MeshError::AttributeLength { attribute: "uvs", len: uvs.len(), positions: self.positions.len() });
        }
        self.uvs = Some(uvs);
        Ok(self)
    }

    /// Adds vertex colors, one per position.
    pub const fn with_colors(mut self, colors: &'a [Rgb888]) -> Result<Self, MeshError> {
        if colors.len() != self.positions.len() {
            return Err(MeshError::AttributeLength { attribute: "colors", len: colors.len(), positions: self.positions.len() });
        }
        self.colors = Some(colors);
        Ok(self)
    }

    /// Vertex positions.
    pub const fn positions(&self) -> &'a [Vec3] {
        self.positions
    }
    /// Vertex normals.
    pub const fn normals(&self) -> &'a [Vec3] {
        self.normals
    }
    /// Texture coordinates, if any.
    pub const fn uvs(&self) -> Option<&'a [Vec2]> {
        self.uvs
    }
    /// Vertex colors, if any.
    pub const fn colors(&self) -> Option<&'a [Rgb888]> {
        self.colors
    }
    /// Triangle indices, three per triangle.
    pub const fn indices(&self) -> &'a [u16] {
        self.indices
    }
    /// Number of triangles.
    pub const fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }
    /// Number of vertices.
    pub const fn vertex_count(&self) -> usize {
        self.positions.len()
    }
    /// Bounding sphere in model space (non-finite positions are left out).
    pub const fn bounds(&self) -> Sphere {
        self.bounds
    }
}

/// Center of the bounding box, radius to the farthest finite vertex.
const fn bounding_sphere(p: &[Vec3]) -> Sphere {
    let (mut lo, mut hi) = ([f32::MAX; 3], [f32::MIN; 3]);
    let mut i = 0;
    while i < p.len() {
        let v = [p[i].x, p[i].y, p[i].z];
        if finite(v[0]) && finite(v[1]) && finite(v[2]) {
            let mut k = 0;
            while k < 3 {
                if v[k] < lo[k] {
                    lo[k] = v[k];
                }
                if v[k] > hi[k] {
                    hi[k] = v[k];
                }
                k += 1;
            }
        }
        i += 1;
    }
    if lo[0] > hi[0] {
        return Sphere { center: Vec3::ZERO, radius: 0.0 };
    }
    let c = [(lo[0] as f64 + hi[0] as f64) * 0.5, (lo[1] as f64 + hi[1] as f64) * 0.5, (lo[2] as f64 + hi[2] as f64) * 0.5];
    let mut r2 = 0.0f64;
    i = 0;
    while i < p.len() {
        let d = [p[i].x as f64 - c[0], p[i].y as f64 - c[1], p[i].z as f64 - c[2]];
        let l2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if l2 > r2 && l2 < f64::MAX {
            r2 = l2;
        }
        i += 1;
    }
    // Round the radius up a little so f32 rounding never cuts a vertex off.
    let r = shapes::const_sqrt(r2) * (1.0 + 1e-6) + 1e-6;
    Sphere { center: Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32), radius: r as f32 }
}

const fn finite(v: f32) -> bool {
    !v.is_nan() && v > f32::MIN && v < f32::MAX
}

#[cfg(test)]
mod tests {
    use super::*;

    static P: [Vec3; 3] = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 4.0, 0.0)];
    static N: [Vec3; 3] = [Vec3::new(0.0, 0.0, -1.0); 3];

    #[test]
    fn validation_reports_what_is_wrong() {
        assert_eq!(
            Mesh::new(&P, &N[..2], &[0, 1, 2]).unwrap_err(),
            MeshError::AttributeLength { attribute: "normals", len: 2, positions: 3 }
        );
        assert_eq!(Mesh::new(&P, &N, &[0, 1]).unwrap_err(), MeshError::IndexCount(2));
        assert_eq!(Mesh::new(&P, &N, &[0, 1, 3]).unwrap_err(), MeshError::IndexOutOfRange { at: 2, index: 3, vertices: 3 });
        assert!(Mesh::new(&P, &N, &[0, 1, 2]).unwrap().with_uvs(&[Vec2::new(0.0, 0.0)]).is_err());
    }

    #[test]
    fn bounding_sphere_contains_every_vertex() {
        const M: Mesh<'static> = match Mesh::new(&P, &N, &[0, 1, 2]) {
            Ok(m) => m,
            Err(_) => panic!(),
        };
        let b = M.bounds();
        assert_eq!(b.center, Vec3::new(1.0, 2.0, 0.0));
        for p in P {
            assert!((p - b.center).length() <= b.radius);
        }
    }
}
