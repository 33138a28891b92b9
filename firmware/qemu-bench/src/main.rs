//! Renders the built-in scenes on an emulated Cortex-M and prints the
//! instructions each frame takes.
//!
//! Under `qemu-system-arm -icount shift=0` every instruction advances the
//! virtual clock by 1 ns; the board's SysTick runs at 25 MHz, so one tick is
//! 40 instructions. Counts are deterministic: the same binary prints the
//! same numbers.
#![no_std]
#![no_main]

use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use soft3d::scenes::{demo_camera, demo_lights, draw_bench, FrameChecksum, BENCH_SCENES, DEMO_TRIANGLES, DEMO_VERTICES};
use soft3d::{Renderer, Settings};

/// Instructions per SysTick tick under `-icount shift=0` at 25 MHz.
const INSTRUCTIONS_PER_TICK: u32 = 40;

struct Timer(cortex_m::peripheral::SYST);

impl Timer {
    fn start(&mut self) {
        self.0.clear_current();
        let _ = self.0.has_wrapped();
    }
    /// Instructions since `start`, or None if the 24-bit counter wrapped
    /// (more than 671 million instructions).
    fn instructions(&mut self) -> Option<u32> {
        let now = cortex_m::peripheral::SYST::get_current();
        if self.0.has_wrapped() {
            return None;
        }
        Some((0x00FF_FFFF - now) * INSTRUCTIONS_PER_TICK)
    }
}

/// Built with `SOFT3D_BENCH_ONLY=scene,mode` in the environment, the
/// benchmark runs only that scene and mode (for `scripts/qemu-profile.py`).
const ONLY: Option<&str> = option_env!("SOFT3D_BENCH_ONLY");

fn selected(scene: &str, mode: &str) -> bool {
    match ONLY {
        None => true,
        Some(only) => only.split_once(',').is_some_and(|(s, m)| s == scene && m == mode),
    }
}

const TARGET: &str = if cfg!(target_abi = "eabihf") { "m4f" } else { "m0" };

/// The cost of the sink alone: the same 15 strips of 320×16 pixels
/// through `FrameChecksum`, which the frame measurement includes.
fn sink_cost(timer: &mut Timer) -> Option<u32> {
    let strip = [Rgb565::BLACK; 320 * 16];
    let mut sink = FrameChecksum::<Rgb565>::new(320, 240);
    timer.start();
    for s in 0..15 {
        let area = Rectangle::new(Point::new(0, s * 16), Size::new(320, 16));
        let Ok(()) = sink.fill_contiguous(&area, strip.iter().copied());
    }
    let n = timer.instructions();
    core::hint::black_box(sink.sum);
    n
}

fn run<S: Settings>(timer: &mut Timer, mode: &str, sink: u32) {
    let mut renderer: Renderer<Rgb565, 320, 240, 16, DEMO_VERTICES, DEMO_TRIANGLES, 3, S> = Renderer::new(Rgb565::BLACK);
    let (camera, lights) = (demo_camera(), demo_lights());
    for (i, name) in BENCH_SCENES.iter().enumerate() {
        if !selected(name, mode) {
            continue;
        }
        let mut out = FrameChecksum::new(320, 240);
        timer.start();
        let mut frame = renderer.begin_frame(&camera, &lights, Rgb565::BLACK);
        let _ = draw_bench(&mut frame, i);
        let geometry = timer.instructions();
        let Ok(stats) = frame.finish(&mut out);
        match (timer.instructions(), geometry) {
            (Some(n), Some(g)) => hprintln!("{},{},{},{},{},{},{:08x},{}", name, mode, TARGET, n, sink, stats.queued, out.sum, g),
            _ => hprintln!("{},{},{},overflow,{},{},{:08x},0", name, mode, TARGET, sink, stats.queued, out.sum),
        }
    }
}

#[entry]
fn main() -> ! {
    let p = cortex_m::Peripherals::take().unwrap();
    let mut syst = p.SYST;
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(0x00FF_FFFF);
    syst.enable_counter();
    let mut timer = Timer(syst);
    let sink = sink_cost(&mut timer).unwrap_or(0);
    hprintln!("scene,mode,target,instructions,sink_instructions,queued,checksum,geometry_instructions");
    run::<soft3d::FixedPoint>(&mut timer, "fixed", sink);
    run::<soft3d::FloatingPoint>(&mut timer, "f32", sink);
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    hprintln!("panic: {}", info);
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::wfi();
    }
}
