//! Fuzzes coverage: a few window-space triangles (coordinates from a
//! sixteenth of a pixel to `f64::MAX`, NaN, degenerate and shared
//! vertices) in fixed point or `f32` at 0, 2, 4, 6 or 8 sub-pixel bits,
//! through strips of any height, drawn with `FragmentCount` and no depth
//! test. Invariants (see `src/raster.rs` for the input layout and the
//! exact rule): no panic; no pixel written outside the frame or twice;
//! statistics that add up; and fragment counts equal to an independent
//! `i128` oracle (top-left rule, vertices snapped half up), exactly for
//! triangles inside the guard band and away from the edges of clipped ones.
//!
//! Run from this directory (nightly and `cargo install cargo-fuzz`):
//!
//! ```sh
//! mkdir -p corpus/raster && cp ../tests/data/fuzz/raster/* corpus/raster/
//! cargo +nightly fuzz run raster corpus/raster -- -max_len=128 -max_total_time=300
//! ```
//!
//! A crash is saved in `artifacts/raster/`; replay it with
//! `cargo +nightly fuzz run raster artifacts/raster/crash-...`, and keep it
//! as a regression (see `README.md`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| soft3d_fuzz::raster::run(data));
