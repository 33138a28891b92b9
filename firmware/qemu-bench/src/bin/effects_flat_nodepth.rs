//! "Flat, no depth": like `effects_flat`, but the scene's materials neither
//! test nor write depth (`DepthOff`; objects are drawn in order, so the
//! picture differs). Against `effects_flat` it shows what the depth test
//! costs a scene that uses it, in instructions and in flash.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use soft3d::effect::Flat;
use soft3d::material::{Affine, DepthOff};

#[path = "effects/common.rs"]
mod common;

#[entry]
fn main() -> ! {
    let mut timer = common::start_timer();
    let renderer = common::static_renderer!(0);
    common::report_renderer::<0>("flat-nodepth-only");
    let flat = common::materials::<Flat, Affine, DepthOff>(Flat);
    common::measure(&mut timer, renderer, "flat-nodepth-only", "flat-nodepth", |frame| common::draw_scene(frame, &flat));
    common::exit()
}
