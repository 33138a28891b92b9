//! "Flat only": a firmware in which the flat effect is the only one that
//! exists. It renders the effects scene (`effects/common.rs`) with
//! `Material<Flat>` (depth-tested, like any scene of solid objects) through
//! a renderer that stores no varyings (`V = 0`, all `Flat` needs), and
//! prints instructions per frame and the frame's checksum. The baseline
//! `scripts/effects-bench.sh` compares the general firmware (`effects_all`)
//! with.
#![no_std]
#![no_main]

#[path = "effects/common.rs"]
mod common;

common::flat_only_firmware!(0, soft3d::material::DepthLess, "flat-only", "flat");
