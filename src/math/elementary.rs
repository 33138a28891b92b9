//! Elementary functions from the chosen backend.
//!
//! `libm` (feature `libm`, the default) is accurate to within an ulp or so;
//! `micromath` (feature `micromath`, used only when `libm` is off) trades
//! accuracy for speed. Both are plain Rust, so host and target compute the
//! same bits for the same backend. One exception, with the same bits: on
//! Arm cores with an FPU (`eabihf` targets) libm's square root is the FPU's
//! own instruction, where libm would run about 50 instructions of integer
//! code (it has no Arm path; `core` has no stable `f32::sqrt`).

#[cfg(not(any(feature = "libm", feature = "micromath")))]
compile_error!("soft3d needs a math backend: enable the `libm` (default) or `micromath` feature");

/// Square root. Negative inputs give NaN (callers clamp first).
///
/// Out of line where it is the FPU's instruction: its callers run per draw
/// call or per vertex, and inlined there `draw_mesh` took more instructions
/// than the call saved (`torus.babylon` `f32` M4F +0.3%; its blocks came
/// out reshuffled, not traced further).
#[cfg_attr(soft3d_fpu_sqrt, inline(never))]
#[cfg_attr(not(soft3d_fpu_sqrt), inline)]
pub fn sqrt(x: f32) -> f32 {
    root(x)
}

/// Inverse square root, `1 / sqrt(x)`: normalizing vectors. With
/// `micromath`, its one-step bit trick (a few percent off, no division).
#[inline]
pub fn rsqrt(x: f32) -> f32 {
    // With libm, through `sqrt`: out of line where that is the FPU's root.
    if cfg!(feature = "libm") {
        1.0 / sqrt(x)
    } else {
        rsqrt_inline(x)
    }
}

/// [`rsqrt`] with the root always inlined: the per-pixel normalizations of
/// `f32` Phong, where a call would cost as much as the FPU's root itself.
#[inline(always)]
pub(crate) fn rsqrt_inline(x: f32) -> f32 {
    #[cfg(feature = "libm")]
    {
        1.0 / root(x)
    }
    #[cfg(all(not(feature = "libm"), feature = "micromath"))]
    {
        micromath::F32Ext::invsqrt(x)
    }
}

/// The backend's square root.
#[inline(always)]
fn root(x: f32) -> f32 {
    #[cfg(soft3d_fpu_sqrt)]
    {
        fpu_sqrt(x)
    }
    #[cfg(all(feature = "libm", not(soft3d_fpu_sqrt)))]
    {
        libm::sqrtf(x)
    }
    #[cfg(all(not(feature = "libm"), feature = "micromath"))]
    {
        micromath::F32Ext::sqrt(x)
    }
}

/// The FPU's square root, `vsqrt.f32`: correctly rounded, as IEEE 754 and
/// libm's `sqrtf` are, so the bits equal the host's (the emulated benchmark's
/// Phong frames and `firmware/qemu-bench/src/bin/mathfns.rs` check it).
///
/// The operand goes through `s0`, saved in a core register and restored: the
/// single-precision register class needs the `vfp2` target feature, which
/// Rust ties to double precision, so `asm!` cannot allocate an `s` register
/// on a Cortex-M4F or M33.
#[cfg(soft3d_fpu_sqrt)]
#[allow(unsafe_code)]
#[inline(always)]
fn fpu_sqrt(x: f32) -> f32 {
    let root: f32;
    // SAFETY: every `eabihf` target has a VFP unit with `vsqrt.f32`. The
    // block writes only its three core registers and `s0`, which it puts
    // back; no memory, no stack, and not the flags (`vsqrt` sets only the
    // FPU's cumulative exception bits).
    unsafe {
        core::arch::asm!(
            "vmov {saved}, s0",
            "vmov s0, {x}",
            "vsqrt.f32 s0, s0",
            "vmov {root}, s0",
            "vmov s0, {saved}",
            x = in(reg) x,
            root = lateout(reg) root,
            saved = out(reg) _,
            options(pure, nomem, nostack, preserves_flags),
        );
    }
    root
}

/// Sine of an angle in radians.
#[inline]
pub fn sin(x: f32) -> f32 {
    #[cfg(feature = "libm")]
    {
        libm::sinf(x)
    }
    #[cfg(all(not(feature = "libm"), feature = "micromath"))]
    {
        micromath::F32Ext::sin(x)
    }
}

/// Cosine of an angle in radians.
#[inline]
pub fn cos(x: f32) -> f32 {
    #[cfg(feature = "libm")]
    {
        libm::cosf(x)
    }
    #[cfg(all(not(feature = "libm"), feature = "micromath"))]
    {
        micromath::F32Ext::cos(x)
    }
}

/// Tangent of an angle in radians.
#[inline]
pub fn tan(x: f32) -> f32 {
    #[cfg(feature = "libm")]
    {
        libm::tanf(x)
    }
    #[cfg(all(not(feature = "libm"), feature = "micromath"))]
    {
        micromath::F32Ext::tan(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn backend_is_close_to_std() {
        // libm is exact to an ulp or two; micromath's roots are bit tricks
        // (up to about 6% off) and its sin/cos about 0.1%.
        let (trig, root) = if cfg!(feature = "libm") { (1e-6, 4e-7) } else { (2e-3, 0.07) };
        for i in -50..50 {
            let x = i as f32 * 0.173;
            assert!((sin(x) - x.sin()).abs() < trig, "sin({x})");
            assert!((cos(x) - x.cos()).abs() < trig, "cos({x})");
            let s = x.abs();
            assert!((sqrt(s) - s.sqrt()).abs() <= root * s.sqrt().max(1.0), "sqrt({s})");
            if s > 0.0 {
                assert!((rsqrt(s) * s.sqrt() - 1.0).abs() <= root, "rsqrt({s})");
            }
        }
    }
}
