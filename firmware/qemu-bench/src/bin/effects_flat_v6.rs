//! Diagnostic twin of `effects_flat`: only the flat effect exists, but the
//! renderer stores six varyings per vertex (`V = 6`) like the general
//! firmware's. Between `effects_flat` and it, the cost of the wider vertex
//! buffer alone; between it and `effects_all`, the cost of the other
//! effects' code being linked in.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use soft3d::effect::Flat;
use soft3d::material::{Affine, DepthLess};

#[path = "effects/common.rs"]
mod common;

#[entry]
fn main() -> ! {
    let mut timer = common::start_timer();
    let renderer = common::static_renderer!(6);
    common::report_renderer::<6>("flat-only-v6");
    let flat = common::materials::<Flat, Affine, DepthLess>(Flat);
    common::measure(&mut timer, renderer, "flat-only-v6", "flat", |frame| common::draw_scene(frame, &flat));
    common::exit()
}
