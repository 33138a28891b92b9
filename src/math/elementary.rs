//! Elementary functions from the chosen backend.
//!
//! `libm` (feature `libm`, the default) is accurate to within an ulp or so;
//! `micromath` (feature `micromath`, used only when `libm` is off) trades
//! accuracy for speed. Both are plain Rust, so host and target compute the
//! same bits for the same backend.

#[cfg(not(any(feature = "libm", feature = "micromath")))]
compile_error!("soft3d needs a math backend: enable the `libm` (default) or `micromath` feature");

/// Square root. Negative inputs give NaN (callers clamp first).
#[inline]
pub fn sqrt(x: f32) -> f32 {
    #[cfg(feature = "libm")]
    {
        libm::sqrtf(x)
    }
    #[cfg(all(not(feature = "libm"), feature = "micromath"))]
    {
        micromath::F32Ext::sqrt(x)
    }
}

/// Inverse square root, `1 / sqrt(x)`: normalizing vectors. With
/// `micromath`, its one-step bit trick (a few percent off, no division).
#[inline]
pub fn rsqrt(x: f32) -> f32 {
    #[cfg(feature = "libm")]
    {
        1.0 / libm::sqrtf(x)
    }
    #[cfg(all(not(feature = "libm"), feature = "micromath"))]
    {
        micromath::F32Ext::invsqrt(x)
    }
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
