//! Names two facts about the target that the crate's code paths depend on.
//!
//! - `soft3d_armv6m`: built for ARMv6-M (Cortex-M0/M0+, e.g. the RP2040),
//!   which lacks three instructions the compiler otherwise uses and
//!   replaces with library calls: the 32×32→64-bit multiply
//!   (`math::mul_wide` uses four 16-bit multiplies instead), `CLZ`
//!   (`math::leading_zeros`) and division (the edge walker's small
//!   quotients, `math::div_floor_small`). Stable Rust exposes no target
//!   feature that says so.
//! - `soft3d_fpu_sqrt`: the `libm` backend on an Arm core with an FPU
//!   (`eabihf`: Cortex-M4F, M7, M33), where `math::sqrt` is the FPU's
//!   `vsqrt.f32` rather than libm's integer code.
fn main() {
    println!("cargo::rustc-check-cfg=cfg(soft3d_armv6m)");
    println!("cargo::rustc-check-cfg=cfg(soft3d_fpu_sqrt)");
    println!("cargo::rerun-if-changed=build.rs");
    let target = std::env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumbv6m") || target.starts_with("armv6m") {
        println!("cargo::rustc-cfg=soft3d_armv6m");
    }
    let cfg = |name: &str| std::env::var(name).unwrap_or_default();
    let libm = std::env::var_os("CARGO_FEATURE_LIBM").is_some();
    if libm && cfg("CARGO_CFG_TARGET_ARCH") == "arm" && cfg("CARGO_CFG_TARGET_ABI") == "eabihf" {
        println!("cargo::rustc-cfg=soft3d_fpu_sqrt");
    }
}
