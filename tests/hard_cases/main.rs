//! The catalogue of hard cases: one module per category, each test a named
//! case with a precise expectation, run in every numeric mode (fixed point
//! and `f32`, every sub-pixel setting) where the mode matters. Debug test
//! builds keep overflow checks on, so an overflow anywhere fails the case.
//!
//! The README's "Hard cases" section lists the categories and their tests.

#[path = "../common/mod.rs"]
mod common;

mod degenerate;
mod slivers;
mod shared_edges;
mod huge;
mod camera_plane;
mod subpixel_motion;
mod depth;
mod lighting;
mod texture;
mod bad_numbers;
mod capacity;
