//! `i16` quantization of positions and normals, by the core's
//! `soft3d::mesh::QuantizedMesh` (so a mesh quantized at run time holds the
//! same steps), and the error it introduces.
//!
//! Positions: per mesh and per axis, `offset` is the middle of the bounding
//! box and `scale` the model units per step, chosen so that the box fits in
//! ±32767 steps. Normals: `scale` 1/32767, no offset. Both dequantize as
//! `q as f32 * scale + offset` in `f32` ([`dequantize`]), the arithmetic
//! `soft3d::mesh::Mesh::new_i16` meshes use when the vertex stage reads
//! them, so bake and target agree bit for bit.

use crate::BakeError;
use soft3d::math::Vec3;

pub use soft3d::mesh::NORMAL_SCALE;

/// `q as f32 * scale + offset`, in `f32`: the dequantization the renderer
/// performs on an `i16` mesh.
pub fn dequantize(q: i16, scale: f32, offset: f32) -> f32 {
    q as f32 * scale + offset
}

/// The error quantization introduced into one mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct QuantizationError {
    /// Largest distance between a position and its dequantized value, in
    /// model units.
    pub max_position: f64,
    /// Root mean square of that distance over the vertices.
    pub rms_position: f64,
    /// The mesh's bounding radius (as `soft3d::mesh::Mesh::bounds`).
    pub radius: f64,
    /// Largest error along one axis, in quantization steps of that axis
    /// (at most 0.5 plus `f32` rounding).
    pub max_axis_steps: f64,
    /// Largest angle between a normal and its dequantized value, in
    /// degrees (zero normals are left out).
    pub max_normal_degrees: f64,
}

impl QuantizationError {
    /// `max_position` relative to the bounding radius.
    pub fn max_relative(&self) -> f64 {
        relative(self.max_position, self.radius)
    }
    /// `rms_position` relative to the bounding radius.
    pub fn rms_relative(&self) -> f64 {
        relative(self.rms_position, self.radius)
    }
}

fn relative(e: f64, r: f64) -> f64 {
    if r > 0.0 {
        e / r
    } else {
        0.0
    }
}

/// A mesh's `i16` data, quantized by the core, and the error it introduced.
#[derive(Clone, Debug, PartialEq)]
pub struct QuantizedMesh {
    /// The steps, scales and offsets (`soft3d::mesh::QuantizedMesh`).
    pub steps: soft3d::mesh::QuantizedMesh,
    /// The error introduced.
    pub error: QuantizationError,
}

/// Quantizes a mesh's positions and normals and measures the error.
pub fn quantize(name: &str, positions: &[Vec3], normals: &[Vec3]) -> Result<QuantizedMesh, BakeError> {
    let steps = soft3d::mesh::QuantizedMesh::new(positions, normals)
        .map_err(|e| BakeError::Mesh { name: name.to_string(), problem: format!("{e} (bake with f32)") })?;
    let scale = steps.position_scale;
    let radius = soft3d::mesh::Mesh::new(positions, normals, &[]).map(|m| m.bounds().radius as f64).unwrap_or(0.0);
    let mut e = QuantizationError { radius, ..Default::default() };
    let mut sum2 = 0.0;
    for (p, d) in positions.iter().zip(steps.dequantized_positions()) {
        let mut d2 = 0.0;
        for (k, s) in scale.iter().enumerate() {
            let diff = (component(d, k) as f64 - component(*p, k) as f64).abs();
            d2 += diff * diff;
            if *s > 0.0 {
                e.max_axis_steps = e.max_axis_steps.max(diff / *s as f64);
            }
        }
        sum2 += d2;
        e.max_position = e.max_position.max(d2.sqrt());
    }
    if !positions.is_empty() {
        e.rms_position = (sum2 / positions.len() as f64).sqrt();
    }
    for (n, d) in normals.iter().zip(steps.dequantized_normals()) {
        e.max_normal_degrees = e.max_normal_degrees.max(angle_degrees(*n, d));
    }
    Ok(QuantizedMesh { steps, error: e })
}

fn component(v: Vec3, k: usize) -> f32 {
    v.to_array()[k]
}

/// The angle between two vectors in degrees (0 if either is zero), from
/// atan2(|a × b|, a · b), which stays accurate for tiny angles.
fn angle_degrees(a: Vec3, b: Vec3) -> f64 {
    let a = [a.x as f64, a.y as f64, a.z as f64];
    let b = [b.x as f64, b.y as f64, b.z as f64];
    let dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let c = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let cross = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    let zero = |v: [f64; 3]| v.iter().all(|c| *c == 0.0);
    if zero(a) || zero(b) {
        0.0
    } else {
        cross.atan2(dot).to_degrees()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extremes_stay_in_range_and_errors_are_half_a_step() {
        let p = [Vec3::new(-1.0, 0.0, 5.0), Vec3::new(3.0, 0.0, 5.0), Vec3::new(0.123, 0.0, 5.0)];
        let n = [Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, -1.0, 0.0), Vec3::new(0.6, 0.8, 0.0)];
        let q = quantize("t", &p, &n).unwrap();
        assert_eq!(q.steps.positions[0][0], -32767);
        assert_eq!(q.steps.positions[1][0], 32767);
        assert_eq!(q.steps.position_offset, [1.0, 0.0, 5.0]);
        assert_eq!(q.steps.position_scale[1], 0.0); // flat axes dequantize to the offset exactly
        let d = q.steps.dequantized_positions();
        assert_eq!((d[0].y, d[0].z), (0.0, 5.0));
        assert!((d[0].x + 1.0).abs() < 1e-6, "{:?}", d[0]);
        assert!(q.error.max_axis_steps <= 0.5 + 1e-3, "{:?}", q.error);
        assert_eq!(q.steps.normals[0], [32767, 0, 0]);
        assert!(q.error.max_normal_degrees < 0.01);
    }

    #[test]
    fn non_finite_is_an_error() {
        let p = [Vec3::new(f32::INFINITY, 0.0, 0.0)];
        assert!(quantize("t", &p, &[Vec3::ZERO]).is_err());
    }

    #[test]
    fn angles() {
        assert!((angle_degrees(Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)) - 90.0).abs() < 1e-9);
        assert_eq!(angle_degrees(Vec3::ZERO, Vec3::new(0.0, 1.0, 0.0)), 0.0);
    }
}
