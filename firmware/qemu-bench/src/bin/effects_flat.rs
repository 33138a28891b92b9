//! "Flat only": a firmware in which the flat effect is the only one that
//! exists. It renders the effects scene (`effects/common.rs`) with
//! `Material<Flat>` (depth-tested, like any scene of solid objects) through
//! a renderer that stores no varyings (`V = 0`, all `Flat` needs), and
//! prints instructions per frame and the frame's checksum. The baseline
//! `scripts/effects-bench.sh` compares the general firmware (`effects_all`)
//! with.
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
    let renderer = common::static_renderer!(0);
    common::report_renderer::<0>("flat-only");
    let flat = common::materials::<Flat, Affine, DepthLess>(Flat);
    common::measure(&mut timer, renderer, "flat-only", "flat", |frame| common::draw_scene(frame, &flat));
    common::exit()
}
