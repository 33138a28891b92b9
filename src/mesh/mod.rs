//! Meshes as borrowed, flash-resident data.
//!
//! A [`Mesh`] borrows slices, so it can be a `static` whose arrays stay in
//! flash; it is validated once when built (in a `const` context, a bad mesh
//! is a compile error) and carries its bounding sphere.
//!
//! Positions and normals are stored as `f32` triples, or quantized to `i16`
//! steps ([`Vectors::I16`], half the flash): each vertex is dequantized as
//! `q as f32 * scale + offset` when the vertex stage reads it, the same
//! `f32` arithmetic on every target, so an `i16` mesh renders exactly like
//! the `f32` mesh of its dequantized values. With the `std` feature,
//! `QuantizedMesh` quantizes a mesh at run time as the bake tool does.
//!
//! Winding: a triangle `(a, b, c)` faces the side its normal
//! `(b - a) × (c - a)` points to. Seen from that side in the left-handed
//! frame it is clockwise on screen. (Babylon's files wind the other way;
//! the `babylon` loader rewinds them.)

#[cfg(feature = "std")]
mod quantize;
mod shapes;

#[cfg(feature = "std")]
pub use quantize::{QuantizeError, QuantizedMesh};

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
    /// Face planes were given, but not one per triangle.
    FacePlaneCount {
        /// The number of planes.
        planes: usize,
        /// The number of triangles.
        triangles: usize,
    },
    /// A face plane is not [`face_plane`] of its triangle (planes baked
    /// from other positions).
    FacePlane(usize),
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
            MeshError::FacePlaneCount { planes, triangles } => write!(f, "mesh has {planes} face planes for {triangles} triangles"),
            MeshError::FacePlane(t) => write!(f, "face plane {t} is not the plane of triangle {t}"),
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

/// Model units per step of a quantized normal component (1/32767).
pub const NORMAL_SCALE: f32 = 1.0 / 32767.0;

/// Per-vertex 3-vectors (positions or normals), as `f32` or as `i16` steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Vectors<'a> {
    /// `f32` triples.
    F32(&'a [Vec3]),
    /// `i16` steps, component `k` meaning `q[k] as f32 * scale[k] + offset[k]`.
    I16 {
        /// The steps.
        steps: &'a [[i16; 3]],
        /// Model units per step, per axis.
        scale: [f32; 3],
        /// The value of step 0, per axis.
        offset: [f32; 3],
    },
}

impl<'a> Vectors<'a> {
    /// Number of vectors.
    pub const fn len(&self) -> usize {
        match self {
            Vectors::F32(v) => v.len(),
            Vectors::I16 { steps, .. } => steps.len(),
        }
    }

    /// Whether there are none.
    pub const fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Vector `i` (zero past the end), dequantized if stored as `i16`.
    /// Always inlined: a call is not removed where the vector goes unused
    /// (the normal and position of a vertex lit in integers).
    #[inline(always)]
    pub const fn get(&self, i: usize) -> Vec3 {
        match self {
            Vectors::F32(v) => {
                if i < v.len() {
                    v[i]
                } else {
                    Vec3::ZERO
                }
            }
            Vectors::I16 { steps, scale, offset } => {
                if i < steps.len() {
                    let q = steps[i];
                    Vec3::new(q[0] as f32 * scale[0] + offset[0], q[1] as f32 * scale[1] + offset[1], q[2] as f32 * scale[2] + offset[2])
                } else {
                    Vec3::ZERO
                }
            }
        }
    }

    /// The vectors in order, dequantized if stored as `i16`.
    pub fn iter(&self) -> impl Iterator<Item = Vec3> + '_ {
        (0..self.len()).map(|i| self.get(i))
    }

    /// The `f32` slice, if stored as `f32`.
    pub const fn as_f32(&self) -> Option<&'a [Vec3]> {
        match *self {
            Vectors::F32(v) => Some(v),
            Vectors::I16 { .. } => None,
        }
    }
}

/// An indexed triangle mesh borrowing its arrays.
#[derive(Clone, Copy, Debug)]
pub struct Mesh<'a> {
    positions: Vectors<'a>,
    normals: Vectors<'a>,
    uvs: Option<&'a [Vec2]>,
    colors: Option<&'a [Rgb888]>,
    indices: &'a [u16],
    bounds: Sphere,
    unit_normals: bool,
    planes: Option<&'a [FacePlane]>,
}

/// A triangle's plane in model space, in `i16` steps of 2^-14: its unit
/// normal `n` (`[0..3]`) and `(n · a - n · c) / r` (`[3]`), the plane's
/// signed distance from the center `c` of the mesh's bounding sphere in
/// units of its radius `r` (within ±1). From [`face_plane`]. Baked with a
/// mesh ([`Mesh::with_face_planes`]), they let a draw call cull back faces
/// before the vertex stage and skip the vertices only back faces use, in
/// integer arithmetic (no FPU needed).
pub type FacePlane = [i16; 4];

/// Steps of a [`FacePlane`] component per unit.
pub const FACE_PLANE_ONE: f64 = 16384.0;

/// The plane of triangle `(a, b, c)` of a mesh bounded by `bounds`: the
/// unit normal of `(b - a) × (c - a)` and its offset from the bounds'
/// center, computed in `f64` and rounded once to steps of 2^-14. Zero for a
/// degenerate triangle or empty bounds (which no test then culls).
pub const fn face_plane(a: Vec3, b: Vec3, c: Vec3, bounds: Sphere) -> FacePlane {
    let (a, b, c) = ([a.x as f64, a.y as f64, a.z as f64], [b.x as f64, b.y as f64, b.z as f64], [c.x as f64, c.y as f64, c.z as f64]);
    let (u, v) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
    let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    let len = shapes::const_sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    let r = bounds.radius as f64;
    // Not finite or too small to normalize: no plane (never culled).
    if !(len > 1e-300 && len < f64::MAX && r > 0.0 && r < f64::MAX) {
        return [0; 4];
    }
    let n = [n[0] / len, n[1] / len, n[2] / len];
    let o = [bounds.center.x as f64, bounds.center.y as f64, bounds.center.z as f64];
    let offset = (n[0] * (a[0] - o[0]) + n[1] * (a[1] - o[1]) + n[2] * (a[2] - o[2])) / r;
    [step(n[0]), step(n[1]), step(n[2]), step(offset)]
}

/// `v` in steps of 2^-14, rounded to nearest and clamped to `i16` (NaN: 0).
const fn step(v: f64) -> i16 {
    let s = v * FACE_PLANE_ONE;
    if s.is_nan() {
        return 0;
    }
    if s <= -32768.0 {
        return i16::MIN;
    }
    if s >= 32767.0 {
        return i16::MAX;
    }
    // Round half away from zero (`as` truncates toward zero).
    (if s < 0.0 { s - 0.5 } else { s + 0.5 }) as i16
}

impl<'a> Mesh<'a> {
    /// Builds and validates a mesh: one normal per position, indices in
    /// range and a multiple of three. Usable in `const` items.
    pub const fn new(positions: &'a [Vec3], normals: &'a [Vec3], indices: &'a [u16]) -> Result<Self, MeshError> {
        Self::from_vectors(Vectors::F32(positions), Vectors::F32(normals), indices)
    }

    /// A mesh of `i16` positions (component `k` is `q[k] as f32 *
    /// position_scale[k] + position_offset[k]`) and `i16` normals (steps of
    /// [`NORMAL_SCALE`]), validated like [`Mesh::new`]. Usable in `const`
    /// items; the bake tool's `--quantize i16` emits these.
    pub const fn new_i16(
        positions: &'a [[i16; 3]],
        position_scale: [f32; 3],
        position_offset: [f32; 3],
        normals: &'a [[i16; 3]],
        indices: &'a [u16],
    ) -> Result<Self, MeshError> {
        Self::from_vectors(
            Vectors::I16 { steps: positions, scale: position_scale, offset: position_offset },
            Vectors::I16 { steps: normals, scale: [NORMAL_SCALE; 3], offset: [0.0; 3] },
            indices,
        )
    }

    /// Builds and validates a mesh from positions and normals in either
    /// storage.
    pub const fn from_vectors(positions: Vectors<'a>, normals: Vectors<'a>, indices: &'a [u16]) -> Result<Self, MeshError> {
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
        let bounds = bounding_sphere(&positions);
        let unit_normals = all_unit_or_zero(&normals);
        Ok(Self { positions, normals, uvs: None, colors: None, indices, bounds, unit_normals, planes: None })
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

    /// Adds face planes, one per triangle, each checked to be exactly
    /// [`face_plane`] of its triangle (in a `const` item, at compile time).
    /// The bake tool emits them. A draw call with back-face culling then
    /// culls in model space first (see [`BackFaceTest`](crate::clip::BackFaceTest)).
    pub const fn with_face_planes(mut self, planes: &'a [FacePlane]) -> Result<Self, MeshError> {
        let triangles = self.triangle_count();
        if planes.len() != triangles {
            return Err(MeshError::FacePlaneCount { planes: planes.len(), triangles });
        }
        let mut t = 0;
        while t < triangles {
            let i = &self.indices;
            let (a, b, c) = (self.position(i[3 * t] as usize), self.position(i[3 * t + 1] as usize), self.position(i[3 * t + 2] as usize));
            let expect = face_plane(a, b, c, self.bounds);
            let (p, mut k) = (&planes[t], 0);
            while k < 4 {
                if p[k] != expect[k] {
                    return Err(MeshError::FacePlane(t));
                }
                k += 1;
            }
            t += 1;
        }
        self.planes = Some(planes);
        Ok(self)
    }

    /// The face planes, if baked.
    pub const fn face_planes(&self) -> Option<&'a [FacePlane]> {
        self.planes
    }

    /// Vertex positions.
    pub const fn positions(&self) -> Vectors<'a> {
        self.positions
    }
    /// Vertex normals.
    pub const fn normals(&self) -> Vectors<'a> {
        self.normals
    }
    /// Position of vertex `i` (zero past the end).
    #[inline]
    pub const fn position(&self, i: usize) -> Vec3 {
        self.positions.get(i)
    }
    /// Normal of vertex `i` (zero past the end).
    #[inline]
    pub const fn normal(&self, i: usize) -> Vec3 {
        self.normals.get(i)
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
    /// Whether every normal is unit length (within 1e-4 of 1 squared) or
    /// zero, checked once when the mesh is built (at compile time for a
    /// `static`), so lighting normalizes per vertex only when it must.
    pub const fn unit_normals(&self) -> bool {
        self.unit_normals
    }
    /// Bounding sphere in model space (non-finite positions are left out).
    pub const fn bounds(&self) -> Sphere {
        self.bounds
    }
}

/// Whether every vector is zero or of unit length (squared length within
/// 1e-4 of 1); false for any non-finite one.
const fn all_unit_or_zero(v: &Vectors<'_>) -> bool {
    let mut i = 0;
    while i < v.len() {
        let n = v.get(i);
        let l2 = n.x * n.x + n.y * n.y + n.z * n.z;
        let unit = l2 > 1.0 - 1e-4 && l2 < 1.0 + 1e-4;
        if !(unit || l2 == 0.0) {
            return false;
        }
        i += 1;
    }
    true
}

/// The bounding sphere a mesh of these positions carries
/// ([`Mesh::bounds`]): center of the bounding box, radius to the farthest
/// finite vertex (rounded up).
pub const fn bounding_sphere(p: &Vectors<'_>) -> Sphere {
    let (mut lo, mut hi) = ([f32::MAX; 3], [f32::MIN; 3]);
    let mut i = 0;
    while i < p.len() {
        let pi = p.get(i);
        let v = [pi.x, pi.y, pi.z];
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
        let pi = p.get(i);
        let d = [pi.x as f64 - c[0], pi.y as f64 - c[1], pi.z as f64 - c[2]];
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
    fn face_planes_are_unit_normals_and_offsets_in_steps() {
        let bounds = Sphere { center: Vec3::ZERO, radius: 2.0 };
        let (a, b, c) = (Vec3::new(0.0, 0.0, 1.0), Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 1.0, 1.0));
        // Normal +z (one is 2^14 steps), the plane half a radius from the center.
        assert_eq!(face_plane(a, b, c, bounds), [0, 0, 16384, 8192]);
        // Wound the other way round: the other side.
        assert_eq!(face_plane(a, c, b, bounds), [0, 0, -16384, -8192]);
        // At 45°: 16384 / √2 = 11585.24 rounds to 11585.
        let d = Vec3::new(0.0, 1.0, 2.0);
        assert_eq!(face_plane(a, b, d, bounds), [0, -11585, 11585, 5793]);
        // Degenerate or not finite: no plane.
        assert_eq!(face_plane(a, b, Vec3::new(2.0, 0.0, 1.0), bounds), [0; 4]);
        assert_eq!(face_plane(a, b, Vec3::new(f32::NAN, 0.0, 0.0), bounds), [0; 4]);
        assert_eq!(face_plane(a, b, c, Sphere { center: Vec3::ZERO, radius: 0.0 }), [0; 4]);
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
