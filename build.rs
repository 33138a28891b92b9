//! Tells the crate whether its target lacks a 32×32→64-bit multiply
//! (ARMv6-M: Cortex-M0/M0+, e.g. the RP2040), where `math::mul_wide`
//! replaces the compiler's 64×64-bit library call with four 16-bit
//! multiplies. (Stable Rust exposes no target feature that says so.)
fn main() {
    println!("cargo::rustc-check-cfg=cfg(soft3d_no_long_multiply)");
    println!("cargo::rerun-if-changed=build.rs");
    let target = std::env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumbv6m") || target.starts_with("armv6m") {
        println!("cargo::rustc-cfg=soft3d_no_long_multiply");
    }
}
