//! Compile-time precision choices of a renderer.
//!
//! Every precision trade is a type, so its cost is paid only by the
//! firmware that picks it: see [`Settings`].

use crate::math::{Fixed, Interp};
use core::marker::PhantomData;

/// The numeric choices a [`Renderer`](crate::Renderer) is built with.
pub trait Settings: 'static {
    /// Scalar that attribute plane equations are stepped in.
    type Interp: Interp;
    /// Sub-pixel bits of the vertex grid: vertices snap to `1 / 2^bits`
    /// of a pixel before coverage is decided. At most 8.
    const SUBPIXEL_BITS: u32;
}

/// The standard [`Settings`]: interpolation scalar `I` (`f32` or
/// [`Fixed`]) and `SUBPIXEL_BITS` bits of sub-pixel precision (0 to 8).
pub struct Precision<I, const SUBPIXEL_BITS: u32>(PhantomData<I>);

impl<I: Interp, const B: u32> Settings for Precision<I, B> {
    type Interp = I;
    const SUBPIXEL_BITS: u32 = B;
}

/// Fixed-point interpolation, 6 sub-pixel bits: for FPU-less parts
/// (Cortex-M0+). Six bits, because the accuracy study (`docs/accuracy.md`)
/// measured them clearly closer to the exact image than four (edges follow
/// the reference), at no measurable cost in instructions; the guard band is
/// then 32,768 pixels.
pub type FixedPoint = Precision<Fixed, 6>;
/// `f32` interpolation, 6 sub-pixel bits: for parts with an FPU (Cortex-M4F,
/// M33F), where the study measured it both faster and more accurate than
/// fixed point.
pub type FloatingPoint = Precision<f32, 6>;
