//! "Flat, no depth": like `effects_flat`, but the scene's materials neither
//! test nor write depth (`DepthOff`; objects are drawn in order, so the
//! picture differs). Against `effects_flat` it shows what the depth test
//! costs a scene that uses it, in instructions and in flash.
#![no_std]
#![no_main]

#[path = "effects/common.rs"]
mod common;

common::flat_only_firmware!(0, soft3d::material::DepthOff, "flat-nodepth-only", "flat-nodepth");
