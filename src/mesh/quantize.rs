//! `i16` quantization of positions and normals (feature `std`): the one
//! implementation the bake tool and run-time users share, so a baked `i16`
//! mesh and the same mesh quantized at run time hold the same steps.
//!
//! Positions: per axis, `offset` is the middle of the bounding box and
//! `scale` the model units per step, the smallest `f32` that fits the box
//! in ±32767 steps; each position takes the step whose `f32`
//! dequantization lands nearest. Normals: steps of [`NORMAL_SCALE`].

use super::{Mesh, MeshError, Vectors, NORMAL_SCALE};
use crate::math::Vec3;
use std::vec::Vec;

/// Largest quantized magnitude (symmetric range; -32768 is unused).
const Q_MAX: i32 = 32767;

/// Why a mesh cannot be quantized.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QuantizeError {
    /// Position `n` is not finite.
    Position(usize),
    /// Normal `n` is not finite.
    Normal(usize),
    /// `normals` is not as long as `positions`.
    Length,
}

impl core::fmt::Display for QuantizeError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            QuantizeError::Position(i) => write!(f, "position {i} is not finite and cannot be quantized to i16"),
            QuantizeError::Normal(i) => write!(f, "normal {i} is not finite and cannot be quantized to i16"),
            QuantizeError::Length => write!(f, "positions and normals differ in number"),
        }
    }
}

impl std::error::Error for QuantizeError {}

/// A mesh's positions and normals as `i16` steps.
#[derive(Clone, Debug, PartialEq)]
pub struct QuantizedMesh {
    /// Positions in steps.
    pub positions: Vec<[i16; 3]>,
    /// Model units per position step, per axis (0 for an axis of no extent).
    pub position_scale: [f32; 3],
    /// The middle of the bounding box, per axis.
    pub position_offset: [f32; 3],
    /// Normals in steps of [`NORMAL_SCALE`].
    pub normals: Vec<[i16; 3]>,
}

impl QuantizedMesh {
    /// Quantizes `positions` and `normals` (same length, all finite).
    pub fn new(positions: &[Vec3], normals: &[Vec3]) -> Result<Self, QuantizeError> {
        if positions.len() != normals.len() {
            return Err(QuantizeError::Length);
        }
        if let Some(i) = positions.iter().position(|p| !p.is_finite()) {
            return Err(QuantizeError::Position(i));
        }
        if let Some(i) = normals.iter().position(|n| !n.is_finite()) {
            return Err(QuantizeError::Normal(i));
        }
        let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for p in positions {
            for (k, v) in p.to_array().into_iter().enumerate() {
                lo[k] = lo[k].min(v);
                hi[k] = hi[k].max(v);
            }
        }
        // An empty mesh has no box: scale and offset 0.
        let axes = [0, 1, 2].map(|k| if lo[k] <= hi[k] { fit(lo[k], hi[k]) } else { (0.0, 0.0) });
        let (scale, offset) = (axes.map(|a| a.0), axes.map(|a| a.1));
        let positions = positions.iter().map(|p| [0, 1, 2].map(|k| nearest_step(p.to_array()[k], scale[k], offset[k]))).collect();
        let normals = normals.iter().map(|n| n.to_array().map(unit_step)).collect();
        Ok(Self { positions, position_scale: scale, position_offset: offset, normals })
    }

    /// The mesh over these steps and `indices`.
    pub fn mesh<'a>(&'a self, indices: &'a [u16]) -> Result<Mesh<'a>, MeshError> {
        Mesh::new_i16(&self.positions, self.position_scale, self.position_offset, &self.normals, indices)
    }

    /// The positions as the renderer reads them.
    pub fn dequantized_positions(&self) -> Vec<Vec3> {
        let v = Vectors::I16 { steps: &self.positions, scale: self.position_scale, offset: self.position_offset };
        (0..v.len()).map(|i| v.get(i)).collect()
    }

    /// The normals as the renderer reads them.
    pub fn dequantized_normals(&self) -> Vec<Vec3> {
        let v = Vectors::I16 { steps: &self.normals, scale: [NORMAL_SCALE; 3], offset: [0.0; 3] };
        (0..v.len()).map(|i| v.get(i)).collect()
    }
}

/// Scale and offset fitting `[lo, hi]` into ±32767 steps; the scale is
/// rounded up to the next `f32` if needed, so the extremes stay in range.
fn fit(lo: f32, hi: f32) -> (f32, f32) {
    let offset = ((lo as f64 + hi as f64) * 0.5) as f32;
    let half = (hi as f64 - offset as f64).max(offset as f64 - lo as f64);
    if half <= 0.0 {
        return (0.0, offset);
    }
    let mut scale = (half / Q_MAX as f64) as f32;
    while (scale as f64) * (Q_MAX as f64) < half {
        scale = f32::from_bits(scale.to_bits() + 1);
    }
    (scale, offset)
}

/// The step whose `f32` dequantization lands nearest to `v`: the rounded
/// quotient, or a neighbor where `f32` rounding favors it.
fn nearest_step(v: f32, scale: f32, offset: f32) -> i16 {
    if scale == 0.0 {
        return 0;
    }
    let q0 = ((v as f64 - offset as f64) / scale as f64).round().clamp(-(Q_MAX as f64), Q_MAX as f64) as i32;
    let dequantized = |q: i32| q as f32 * scale + offset;
    let best = [q0, q0 - 1, q0 + 1]
        .into_iter()
        .filter(|q| q.abs() <= Q_MAX)
        .min_by(|&a, &b| (dequantized(a) as f64 - v as f64).abs().total_cmp(&(dequantized(b) as f64 - v as f64).abs()))
        .unwrap_or(q0);
    best as i16
}

/// A component in [-1, 1] in steps of 1/32767.
fn unit_step(v: f32) -> i16 {
    (v as f64 * Q_MAX as f64).round().clamp(-(Q_MAX as f64), Q_MAX as f64) as i16
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_land_within_half_a_step_and_extremes_fit() {
        let p = [Vec3::new(-3.0, 0.5, 7.0), Vec3::new(1.0, 0.5, -2.0), Vec3::new(0.123, 0.5, 1e-3)];
        let n = [Vec3::new(0.0, 0.0, -1.0), Vec3::new(0.6, 0.8, 0.0), Vec3::ZERO];
        let q = QuantizedMesh::new(&p, &n).unwrap();
        assert_eq!(q.position_scale[1], 0.0); // a flat axis dequantizes to the offset exactly
        for (a, b) in p.iter().zip(q.dequantized_positions()) {
            for k in 0..3 {
                let step = q.position_scale[k].max(f32::EPSILON) as f64;
                assert!((a.to_array()[k] as f64 - b.to_array()[k] as f64).abs() <= 0.5 * step * 1.001, "{a:?} {b:?}");
            }
        }
        assert_eq!(q.normals[1], [19660, 26214, 0]);
        let mesh = q.mesh(&[0, 1, 2]).unwrap();
        assert_eq!(mesh.position(1), q.dequantized_positions()[1]);
        assert!((mesh.normal(0).z + 1.0).abs() < 1e-6);
    }

    #[test]
    fn non_finite_input_is_refused() {
        let p = [Vec3::new(f32::NAN, 0.0, 0.0)];
        assert_eq!(QuantizedMesh::new(&p, &[Vec3::ZERO]), Err(QuantizeError::Position(0)));
        assert_eq!(QuantizedMesh::new(&[Vec3::ZERO], &[Vec3::new(0.0, f32::INFINITY, 0.0)]), Err(QuantizeError::Normal(0)));
        assert_eq!(QuantizedMesh::new(&[Vec3::ZERO], &[]), Err(QuantizeError::Length));
    }
}
