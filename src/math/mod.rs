//! Vectors, matrices and scalar types.
//!
//! Geometry (the vertex stage) works in `f32`. Attribute interpolation in the
//! rasterizer is generic over [`Interp`], implemented by `f32` and by the
//! fixed-point [`Fixed`].
//!
//! Matrices use the column-vector convention: a point is transformed as
//! `M * p`, and `A * B` applies `B` first. Storage is row-major
//! (`m[row][col]`). Coordinate systems are left-handed as in Babylon.js:
//! x right, y up, z away from the viewer.

mod elementary;
mod fixed;
mod interp;
mod matrix;
mod vector;

pub use elementary::{cos, rsqrt, sin, sqrt, tan};
pub use fixed::Fixed;
pub use interp::Interp;
pub use matrix::{Mat3, Mat4};
pub use vector::{Vec2, Vec3, Vec4};

/// Whether `f32` arithmetic runs on a hardware FPU: everywhere but on Arm
/// targets with the soft-float ABI (Cortex-M0+, M3), where every float
/// operation is a library call. A few spots pick a different but
/// equivalent formulation by it (a constant, so the other costs nothing).
pub(crate) const HARD_FLOAT: bool = !cfg!(target_arch = "arm") || cfg!(target_abi = "eabihf");
