//! Tells the crate whether it is built for ARMv6-M (Cortex-M0/M0+, e.g.
//! the RP2040), which lacks three instructions the compiler otherwise
//! uses and replaces with library calls: the 32×32→64-bit multiply
//! (`math::mul_wide` uses four 16-bit multiplies instead), `CLZ`
//! (`math::leading_zeros`) and division (the edge walker's small
//! quotients, `math::div_floor_small`). Stable Rust exposes no target
//! feature that says so.
fn main() {
    println!("cargo::rustc-check-cfg=cfg(soft3d_armv6m)");
    println!("cargo::rerun-if-changed=build.rs");
    let target = std::env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumbv6m") || target.starts_with("armv6m") {
        println!("cargo::rustc-cfg=soft3d_armv6m");
    }
}
