//! Decoding and invariant checks shared by the fuzz targets
//! (`fuzz_targets/`) and the regression replay in the main crate
//! (`tests/fuzz_regressions.rs`, which includes these files with
//! `#[path]`, so each module names the others only as `crate::...`).

pub mod babylon;
pub mod check;
pub mod clip;
pub mod input;
pub mod raster;
