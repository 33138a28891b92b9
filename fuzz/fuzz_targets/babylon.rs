//! Fuzzes the `.babylon` loader: any bytes must load or give an error,
//! never panic, and a scene that loads must give valid meshes (the checks
//! are in `src/babylon.rs`, shared with `tests/fuzz_regressions.rs`).
//!
//! Run from this directory (needs a nightly toolchain and cargo-fuzz,
//! `cargo install cargo-fuzz`), seeded with the test scenes and guided by
//! the dictionary of Babylon's keys:
//!
//! ```sh
//! mkdir -p corpus/babylon && cp ../tests/data/babylon/*.babylon corpus/babylon/
//! cargo +nightly fuzz run babylon corpus/babylon -- -dict=babylon.dict -max_len=8192
//! ```
//!
//! The real Blender exports in `../../shared/assets` make good seeds too;
//! copy them into `corpus/babylon` (which is not committed), never into the
//! repository.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| soft3d_fuzz::babylon::run(data));
