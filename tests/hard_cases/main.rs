//! The catalogue of hard cases: one module per category, each test a named
//! case with a precise expectation, run in every numeric mode (fixed point
//! and `f32`, every sub-pixel setting) where the mode matters. Debug test
//! builds keep overflow checks on, so an overflow anywhere fails the case.
//!
//! The README's "Hard cases" section lists the categories and their tests.

#[path = "../common/mod.rs"]
mod common;

mod bad_numbers;
mod camera_plane;
mod capacity;
mod degenerate;
mod depth;
mod huge;
mod lighting;
mod shared_edges;
mod slivers;
mod subpixel_motion;
mod texture;
