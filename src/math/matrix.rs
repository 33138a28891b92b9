//! 3×3 and 4×4 `f32` matrices (column-vector convention, row-major storage).

use super::{Vec3, Vec4};
use core::ops::Mul;

/// A 3×3 matrix, `m[row][col]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mat3 {
    /// Rows of the matrix.
    pub m: [[f32; 3]; 3],
}

/// A 4×4 matrix, `m[row][col]`; points transform as `M * p`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mat4 {
    /// Rows of the matrix.
    pub m: [[f32; 4]; 4],
}

impl Mat3 {
    /// The identity.
    pub const IDENTITY: Self = Self { m: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] };
    /// All zeros.
    pub const ZERO: Self = Self { m: [[0.0; 3]; 3] };

    /// Transforms a vector.
    #[inline]
    pub fn transform(&self, v: Vec3) -> Vec3 {
        let m = &self.m;
        Vec3::new(
            m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z,
        )
    }

    /// Determinant.
    pub fn determinant(&self) -> f32 {
        let m = &self.m;
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    }

    /// Transpose of the inverse (the matrix that transforms normals).
    ///
    /// A singular (or non-finite) matrix gives [`Mat3::ZERO`], so normals of
    /// a flattened mesh become zero and are lit by the ambient term only,
    /// never by NaN.
    pub fn inverse_transpose(&self) -> Self {
        let m = &self.m;
        let det = self.determinant();
        if !det.is_finite() || det.abs() < 1e-30 {
            return Self::ZERO;
        }
        let inv = 1.0 / det;
        // Cofactor matrix divided by the determinant is the inverse
        // transposed, so no explicit transpose is needed.
        let c = |r0: usize, r1: usize, c0: usize, c1: usize| (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) * inv;
        Self {
            m: [
                [c(1, 2, 1, 2), -c(1, 2, 0, 2), c(1, 2, 0, 1)],
                [-c(0, 2, 1, 2), c(0, 2, 0, 2), -c(0, 2, 0, 1)],
                [c(0, 1, 1, 2), -c(0, 1, 0, 2), c(0, 1, 0, 1)],
            ],
        }
    }
}

impl Mat4 {
    /// The identity.
    pub const IDENTITY: Self = Self { m: [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]] };

    /// Translation by `t`.
    pub const fn translation(t: Vec3) -> Self {
        Self { m: [[1.0, 0.0, 0.0, t.x], [0.0, 1.0, 0.0, t.y], [0.0, 0.0, 1.0, t.z], [0.0, 0.0, 0.0, 1.0]] }
    }

    /// Non-uniform scaling.
    pub const fn scaling(s: Vec3) -> Self {
        Self { m: [[s.x, 0.0, 0.0, 0.0], [0.0, s.y, 0.0, 0.0], [0.0, 0.0, s.z, 0.0], [0.0, 0.0, 0.0, 1.0]] }
    }

    /// Rotation about the x axis by `a` radians (y turns toward z).
    pub fn rotation_x(a: f32) -> Self {
        let (s, c) = (super::sin(a), super::cos(a));
        Self { m: [[1.0, 0.0, 0.0, 0.0], [0.0, c, -s, 0.0], [0.0, s, c, 0.0], [0.0, 0.0, 0.0, 1.0]] }
    }

    /// Rotation about the y axis by `a` radians (z turns toward x).
    pub fn rotation_y(a: f32) -> Self {
        let (s, c) = (super::sin(a), super::cos(a));
        Self { m: [[c, 0.0, s, 0.0], [0.0, 1.0, 0.0, 0.0], [-s, 0.0, c, 0.0], [0.0, 0.0, 0.0, 1.0]] }
    }

    /// Rotation about the z axis by `a` radians (x turns toward y).
    pub fn rotation_z(a: f32) -> Self {
        let (s, c) = (super::sin(a), super::cos(a));
        Self { m: [[c, -s, 0.0, 0.0], [s, c, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]] }
    }

    /// Left-handed view matrix looking from `eye` toward `target`
    /// (Babylon's `LookAtLH`): the camera looks down +z, x right, y up.
    ///
    /// A degenerate frame (eye on target, or `up` parallel to the view
    /// direction) falls back to a valid orthonormal frame instead of NaN.
    pub fn look_at_lh(eye: Vec3, target: Vec3, up: Vec3) -> Self {
        let mut z = (target - eye).normalize_or_zero();
        if z == Vec3::ZERO {
            z = Vec3::new(0.0, 0.0, 1.0);
        }
        let mut x = up.cross(z).normalize_or_zero();
        if x == Vec3::ZERO {
            // `up` is parallel to the view direction: pick any perpendicular.
            let alt = if z.x.abs() < 0.9 { Vec3::new(1.0, 0.0, 0.0) } else { Vec3::new(0.0, 1.0, 0.0) };
            x = alt.cross(z).normalize_or_zero();
        }
        let y = z.cross(x);
        Self { m: [[x.x, x.y, x.z, -x.dot(eye)], [y.x, y.y, y.z, -y.dot(eye)], [z.x, z.y, z.z, -z.dot(eye)], [0.0, 0.0, 0.0, 1.0]] }
    }

    /// Left-handed perspective projection (Babylon's `PerspectiveFovLH`):
    /// `fov_y` is the vertical field of view in radians, `aspect` is
    /// width / height. Clip-space depth runs from 0 at `near` to `w` at
    /// `far`, so window depth is in [0, 1], smaller nearer; `w` is the view
    /// depth.
    pub fn perspective_fov_lh(fov_y: f32, aspect: f32, near: f32, far: f32) -> Self {
        let ys = 1.0 / super::tan(fov_y * 0.5);
        let xs = ys / aspect;
        let q = far / (far - near);
        Self { m: [[xs, 0.0, 0.0, 0.0], [0.0, ys, 0.0, 0.0], [0.0, 0.0, q, -near * q], [0.0, 0.0, 1.0, 0.0]] }
    }

    /// Transforms a homogeneous vector.
    #[inline]
    pub fn transform(&self, v: Vec4) -> Vec4 {
        let m = &self.m;
        let row = |r: usize| m[r][0] * v.x + m[r][1] * v.y + m[r][2] * v.z + m[r][3] * v.w;
        Vec4::new(row(0), row(1), row(2), row(3))
    }

    /// Transforms a point (w = 1), returning the homogeneous result.
    #[inline]
    pub fn transform_point(&self, p: Vec3) -> Vec4 {
        let m = &self.m;
        let row = |r: usize| m[r][0] * p.x + m[r][1] * p.y + m[r][2] * p.z + m[r][3];
        Vec4::new(row(0), row(1), row(2), row(3))
    }

    /// Transforms a point by an affine matrix (ignores the last row).
    #[inline]
    pub fn transform_point3(&self, p: Vec3) -> Vec3 {
        let m = &self.m;
        let row = |r: usize| m[r][0] * p.x + m[r][1] * p.y + m[r][2] * p.z + m[r][3];
        Vec3::new(row(0), row(1), row(2))
    }

    /// The upper-left 3×3 part (rotation and scale).
    pub fn upper3(&self) -> Mat3 {
        let m = &self.m;
        Mat3 { m: [[m[0][0], m[0][1], m[0][2]], [m[1][0], m[1][1], m[1][2]], [m[2][0], m[2][1], m[2][2]]] }
    }

    /// The matrix that transforms normals of a mesh placed by this model
    /// matrix: the inverse transpose of its 3×3 part. Translation never
    /// reaches normals (one of the seeds' lighting bugs).
    pub fn normal_matrix(&self) -> Mat3 {
        self.upper3().inverse_transpose()
    }

    /// The largest factor by which this matrix can stretch a length
    /// (an upper bound from the column lengths), for bounding spheres.
    pub fn max_scale(&self) -> f32 {
        let m = &self.m;
        let col = |c: usize| m[0][c] * m[0][c] + m[1][c] * m[1][c] + m[2][c] * m[2][c];
        super::sqrt(col(0).max(col(1)).max(col(2)))
    }

    /// If this is a similarity (rotation, uniform scale `s > 0` and
    /// translation, within a relative tolerance of 1e-4), its scale.
    /// Lighting can then be done in model space: angles are preserved.
    pub fn similarity_scale(&self) -> Option<f32> {
        let m = &self.m;
        let col = |c: usize| Vec3::new(m[0][c], m[1][c], m[2][c]);
        let (x, y, z) = (col(0), col(1), col(2));
        let s2 = x.length_squared();
        let tol = s2 * 1e-4;
        let ok = s2 > 0.0
            && (y.length_squared() - s2).abs() <= tol
            && (z.length_squared() - s2).abs() <= tol
            && x.dot(y).abs() <= tol
            && y.dot(z).abs() <= tol
            && z.dot(x).abs() <= tol
            && x.cross(y).dot(z) > 0.0
            && m[3] == [0.0, 0.0, 0.0, 1.0];
        ok.then(|| super::sqrt(s2))
    }

    /// The inverse of a similarity with scale `s` (see
    /// [`Mat4::similarity_scale`]): `(1/s²) Mᵀ` on the 3×3 part.
    pub fn similarity_inverse(&self, s: f32) -> Mat4 {
        let m = &self.m;
        let k = 1.0 / (s * s);
        let mut r = [[0.0f32; 4]; 4];
        for (i, row) in r.iter_mut().take(3).enumerate() {
            for (j, cell) in row.iter_mut().take(3).enumerate() {
                *cell = m[j][i] * k;
            }
            row[3] = -(row[0] * m[0][3] + row[1] * m[1][3] + row[2] * m[2][3]);
        }
        r[3][3] = 1.0;
        Mat4 { m: r }
    }

    /// The eye of a perspective view-projection matrix: the point that
    /// projects to `x = y = w = 0`. `None` for an orthographic or singular
    /// matrix.
    pub fn eye(&self) -> Option<Vec3> {
        // Rows 0, 1 and 3 of M · (e, 1) = 0: a 3×3 system, by Cramer's rule.
        let m = &self.m;
        let r = [m[0], m[1], m[3]];
        let a = Mat3 { m: [[r[0][0], r[0][1], r[0][2]], [r[1][0], r[1][1], r[1][2]], [r[2][0], r[2][1], r[2][2]]] };
        let b = [-r[0][3], -r[1][3], -r[2][3]];
        let det = a.determinant();
        if det.is_nan() || det.abs() <= 1e-20 {
            return None;
        }
        let solve = |col: usize| {
            let mut c = a;
            for (row, v) in c.m.iter_mut().zip(b) {
                row[col] = v;
            }
            c.determinant() / det
        };
        let e = Vec3::new(solve(0), solve(1), solve(2));
        e.is_finite().then_some(e)
    }

    /// True if every entry is finite.
    pub fn is_finite(&self) -> bool {
        self.m.iter().flatten().all(|v| v.is_finite())
    }
}

impl Mul for Mat4 {
    type Output = Mat4;
    fn mul(self, o: Mat4) -> Mat4 {
        let mut r = [[0.0f32; 4]; 4];
        for (i, row) in r.iter_mut().enumerate() {
            for (j, cell) in row.iter_mut().enumerate() {
                *cell = (0..4).map(|k| self.m[i][k] * o.m[k][j]).sum();
            }
        }
        Mat4 { m: r }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-5
    }

    #[test]
    fn look_at_puts_the_target_straight_ahead() {
        let v = Mat4::look_at_lh(Vec3::new(1.0, 2.0, -5.0), Vec3::new(1.0, 2.0, 0.0), Vec3::new(0.0, 1.0, 0.0));
        let t = v.transform_point3(Vec3::new(1.0, 2.0, 0.0));
        assert!(close(t, Vec3::new(0.0, 0.0, 5.0)), "{t:?}");
        // Left-handed: +x world stays +x (right) when looking down +z.
        let r = v.transform_point3(Vec3::new(2.0, 2.0, 0.0));
        assert!(r.x > 0.9, "{r:?}");
    }

    #[test]
    fn perspective_maps_near_to_zero_and_far_to_one() {
        let p = Mat4::perspective_fov_lh(0.8, 1.5, 0.5, 100.0);
        let n = p.transform_point(Vec3::new(0.0, 0.0, 0.5));
        let f = p.transform_point(Vec3::new(0.0, 0.0, 100.0));
        assert!((n.z / n.w).abs() < 1e-6);
        assert!((f.z / f.w - 1.0).abs() < 1e-6);
    }

    #[test]
    fn normal_matrix_ignores_translation_and_undoes_scale() {
        let m = Mat4::translation(Vec3::new(10.0, -3.0, 7.0)) * Mat4::scaling(Vec3::new(2.0, 1.0, 1.0));
        let n = m.normal_matrix().transform(Vec3::new(1.0, 1.0, 0.0));
        // A plane x + y = c scaled by 2 in x becomes x/2 + y = c: normal (0.5, 1, 0).
        assert!(close(n, Vec3::new(0.5, 1.0, 0.0)), "{n:?}");
    }

    #[test]
    fn singular_normal_matrix_is_zero_not_nan() {
        let m = Mat4::scaling(Vec3::new(1.0, 0.0, 1.0));
        assert_eq!(m.normal_matrix(), Mat3::ZERO);
    }

    #[test]
    fn the_eye_is_recovered_from_a_view_projection() {
        let eye = Vec3::new(1.5, -2.0, -7.0);
        let vp = Mat4::perspective_fov_lh(0.8, 1.3, 0.1, 50.0) * Mat4::look_at_lh(eye, Vec3::new(0.2, 0.1, 3.0), Vec3::new(0.0, 1.0, 0.0));
        assert!((vp.eye().unwrap() - eye).length() < 1e-3);
        assert_eq!(Mat4::IDENTITY.eye(), None);
    }

    #[test]
    fn similarities_are_recognized_and_inverted() {
        let m =
            Mat4::translation(Vec3::new(1.0, -2.0, 3.0)) * Mat4::rotation_y(0.7) * Mat4::rotation_x(-0.3) * Mat4::scaling(Vec3::ONE * 2.5);
        let s = m.similarity_scale().unwrap();
        assert!((s - 2.5).abs() < 1e-5);
        let p = Vec3::new(0.3, 0.9, -1.7);
        assert!(close(m.similarity_inverse(s).transform_point3(m.transform_point3(p)), p));
        assert_eq!(Mat4::scaling(Vec3::new(1.0, 2.0, 1.0)).similarity_scale(), None);
        assert_eq!(Mat4::scaling(Vec3::new(-1.0, 1.0, 1.0)).similarity_scale(), None); // mirror
        assert_eq!(Mat4::scaling(Vec3::ZERO).similarity_scale(), None);
    }

    #[test]
    fn rotation_matches_babylon_handedness() {
        // Babylon's RotationY(pi/2) maps +z to +x.
        let r = Mat4::rotation_y(core::f32::consts::FRAC_PI_2).transform_point3(Vec3::new(0.0, 0.0, 1.0));
        assert!(close(r, Vec3::new(1.0, 0.0, 0.0)), "{r:?}");
    }
}
