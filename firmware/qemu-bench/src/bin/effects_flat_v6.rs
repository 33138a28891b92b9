//! Diagnostic twin of `effects_flat`: only the flat effect exists, but the
//! renderer stores six varyings per vertex (`V = 6`) like the general
//! firmware's. Between `effects_flat` and it, the cost of the wider vertex
//! buffer alone; between it and `effects_all`, the cost of the other
//! effects' code being linked in.
#![no_std]
#![no_main]

#[path = "effects/common.rs"]
mod common;

common::flat_only_firmware!(6, soft3d::material::DepthLess, "flat-only-v6", "flat");
