//! Replays the committed fuzz corpus through the fuzz targets' own checks,
//! so every `cargo test --features simulator` runs them without a nightly
//! toolchain:
//!
//! - `tests/data/fuzz/raster/*`: coverage against the exact oracle
//!   (`fuzz/src/raster.rs`);
//! - `tests/data/fuzz/clip/*`: the mesh path with clipping, every
//!   untextured effect, depth on (`fuzz/src/clip.rs`);
//! - `tests/data/babylon/*` and `tests/data/fuzz/babylon/*`: the loader
//!   (`fuzz/src/babylon.rs`).
//!
//! The decoding and invariants are the fuzz crate's files, included here
//! with `#[path]` (the fuzz crate is a separate package). A crash the
//! fuzzer finds becomes a named test below; see `fuzz/README.md`.
#![cfg(all(feature = "std", feature = "babylon"))]

#[path = "../fuzz/src/babylon.rs"]
mod babylon;
#[path = "../fuzz/src/check.rs"]
mod check;
#[path = "../fuzz/src/clip.rs"]
mod clip;
#[path = "../fuzz/src/input.rs"]
mod input;
#[path = "../fuzz/src/raster.rs"]
mod raster;

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use std::path::{Path, PathBuf};

/// The files of `tests/data/<dir>`, sorted (none if it does not exist).
fn corpus(dir: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(dir);
    let mut files: Vec<PathBuf> = match std::fs::read_dir(&dir) {
        Ok(entries) => entries.map(|e| e.unwrap().path()).filter(|p| p.is_file()).collect(),
        Err(_) => Vec::new(),
    };
    files.sort();
    files
}

/// Runs `check` on every file, reporting all failures at once.
fn replay(files: &[PathBuf], check: fn(&[u8])) {
    let failed: Vec<String> = files
        .iter()
        .filter(|path| {
            let data = std::fs::read(path).unwrap();
            std::panic::catch_unwind(|| check(&data)).is_err()
        })
        .map(|path| path.display().to_string())
        .collect();
    assert!(failed.is_empty(), "{} of {} inputs fail (messages above): {failed:#?}", failed.len(), files.len());
}

#[test]
fn raster_corpus_replays() {
    let files = corpus("fuzz/raster");
    assert!(files.len() >= 10, "tests/data/fuzz/raster holds the minimized corpus");
    replay(&files, raster::run);
}

#[test]
fn clip_corpus_replays() {
    let files = corpus("fuzz/clip");
    assert!(files.len() >= 10, "tests/data/fuzz/clip holds the minimized corpus");
    replay(&files, clip::run);
}

#[test]
fn babylon_corpus_replays() {
    let mut files = corpus("babylon");
    files.extend(corpus("fuzz/babylon"));
    assert!(!files.is_empty());
    replay(&files, babylon::run);
}

// The harness itself: the checks must be able to fail.

/// Header bytes of a raster case: fixed point, 4 sub-pixel bits (mode
/// 2·2), a 16×12 frame in 5-row strips.
const RASTER_HEADER: [u8; 4] = [4, 15, 11, 4];

/// A vertex of a raster case on the quarter-pixel grid (tag 3).
fn quarter(x: u8, y: u8) -> [u8; 5] {
    [0, 3, x, 3, y]
}

#[test]
fn the_raster_oracle_covers_what_it_should() {
    // Two triangles sharing an edge, as a square from (1, 1) to (9, 9):
    // the oracle must see 64 covered pixels, each exactly once.
    let mut data = RASTER_HEADER.to_vec();
    for v in [quarter(4, 4), quarter(36, 4), quarter(4, 36), quarter(36, 4), quarter(36, 36), quarter(4, 36)] {
        data.extend(v);
    }
    let case = raster::decode(&data);
    assert_eq!((case.width, case.height, case.strip, case.bits, case.tris.len()), (16, 12, 5, 4, 2));
    assert_eq!(case.tris[1][0].0.value, 9.0);
    raster::run(&data);
}

#[test]
#[should_panic(expected = "outside the 4x3 frame")]
fn the_target_rejects_a_pixel_outside_the_frame() {
    let mut t = check::CheckedTarget::<Rgb888>::new(4, 3);
    let Ok(()) = t.fill_contiguous(&Rectangle::new(Point::new(0, 2), Size::new(4, 2)), std::iter::repeat_n(Rgb888::BLACK, 8));
}

#[test]
#[should_panic(expected = "written by flush 1 and again by 2")]
fn the_target_rejects_a_pixel_written_twice_in_a_frame() {
    let mut t = check::CheckedTarget::<Rgb888>::new(4, 3);
    let area = Rectangle::new(Point::new(0, 0), Size::new(4, 2));
    let Ok(()) = t.fill_contiguous(&area, std::iter::repeat_n(Rgb888::BLACK, 8));
    let Ok(()) = t.fill_contiguous(&area, std::iter::repeat_n(Rgb888::BLACK, 8));
}

#[test]
#[should_panic(expected = "never written")]
fn the_target_rejects_a_frame_with_a_hole() {
    let mut t = check::CheckedTarget::<Rgb888>::new(4, 3);
    let Ok(()) = t.fill_contiguous(&Rectangle::new(Point::new(0, 0), Size::new(4, 2)), std::iter::repeat_n(Rgb888::BLACK, 8));
    t.finished();
}

// Crashes the fuzzers found, minimized by hand.

/// A triangle with a vertex at (1e300, 1e300), one near the origin and one
/// at x = -2^30: fixed point, 0 sub-pixel bits, a 1×32 frame.
const TRIANGLE_AT_1E300: [u8; 22] = [
    0, 0, 31, 31, // fixed, 0 bits, 1×32, one strip
    0, 7, 5, 7, 5, // (1e300, 1e300)
    0, 0, 0xe8, 0xe8, 0, 0xe8, 0xff, // (-5912/1024, -24/1024)
    0, 15, 14, 0, 0x30, 0x30, // (-(2^40 + 1)/1024, 12336/1024)
];

#[test]
fn a_triangle_at_1e300_draws_within_the_frame() {
    let case = raster::decode(&TRIANGLE_AT_1E300);
    assert_eq!(case.tris.len(), 1);
    assert_eq!((case.tris[0][0].0.value, case.tris[0][2].0.value), (1e300, -1073741824.0009766));
    // No panic, every pixel written once, statistics consistent.
    raster::run(&TRIANGLE_AT_1E300);
}

/// Found by the `raster` fuzzer. Beyond the guard band a triangle is
/// clipped to it in `f64` (`clip::clip_guard`). Each crossing was
/// interpolated from the edge's inside end; with that end at 1e300 the
/// crossing was off by about 1e300·2^-52 pixels, the clipped polygon folded
/// over itself and its fan covered rows 7 to 31 twice. Fixed: crossings are
/// placed exactly on the band, their other coordinate interpolated from the
/// endpoint nearer it.
#[test]
fn a_triangle_at_1e300_covers_each_pixel_at_most_once() {
    let case = raster::decode(&TRIANGLE_AT_1E300);
    let (counts, _) = raster::render_mode(&case);
    assert!(counts.iter().all(|&c| c <= 1), "fragments per pixel: {counts:?}");
}

/// Found by the `clip` fuzzer: near-plane clipping of a triangle in fixed
/// point, 0 sub-pixel bits, made a sliver reaching 2^27 pixels off screen.
/// Its gradients came from `f32` products that cancel (and offsets that
/// lose bits in `f32`), and their 16.16 rounding times that distance put
/// colors far off on screen: green 63 where the vertices allow at most 43.
/// Fixed: such triangles get `f64` gradients and `f64` span ends.
#[test]
fn a_sliver_from_the_guard_band_keeps_colors_within_its_vertices() {
    let input = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fuzz/clip/sliver-from-guard-band");
    clip::run(&std::fs::read(input).expect("committed corpus file"));
}

/// Found by the `clip` fuzzer in CI: a degenerate projection gave a vertex
/// with a tiny `w`, its window position overflowed to infinity, and the
/// guard-band clip interpolated NaN colors from it, drawn as black. Fixed:
/// such triangles are skipped and counted invalid.
#[test]
fn a_projection_that_overflows_skips_the_triangle() {
    let input = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fuzz/clip/projection-overflow");
    clip::run(&std::fs::read(input).expect("committed corpus file"));
}

/// Found by the `clip` fuzzer in CI: a projection with z ≈ 1.001·w put the
/// near plane within 1e-4 of the eye. The near-plane crossing of an edge
/// to a vertex 4.5e6 away was interpolated in `f32`, its `w` came out
/// negative (-2.4e-5), it projected to the far side of the screen, and
/// the guard-band clip interpolated colors toward it out of range: green
/// 23 where the vertices allow at most 3. Fixed: near and far crossings
/// are computed in `f64` and placed exactly on their plane, and a clipped
/// polygon with a vertex at `w <= 0` is skipped and counted invalid.
#[test]
fn a_near_plane_through_the_eye_keeps_colors_within_its_vertices() {
    let input = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/fuzz/clip/near-plane-through-eye");
    clip::run(&std::fs::read(input).expect("committed corpus file"));
}
