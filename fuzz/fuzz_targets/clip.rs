//! Fuzzes the mesh path: arbitrary positions, normals, colors, model and
//! view-projection matrices and lights (NaN, infinities, w = 0, w < 0,
//! the near plane), clipped and drawn with `Flat`, `Gouraud`,
//! `VertexColor` and `Phong`, depth test on. Invariants (see `src/clip.rs`
//! for the input layout): no panic; no pixel written outside the frame or
//! twice; statistics that add up, and refused draw calls that change
//! nothing; every pixel the background or a color the inputs can make.
//!
//! Run from this directory (nightly and `cargo install cargo-fuzz`):
//!
//! ```sh
//! mkdir -p corpus/clip && cp ../tests/data/fuzz/clip/* corpus/clip/
//! cargo +nightly fuzz run clip corpus/clip -- -max_len=512 -max_total_time=300
//! ```
//!
//! A crash is saved in `artifacts/clip/`; keep it as a regression (see
//! `README.md`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| soft3d_fuzz::clip::run(data));
