//! What the emulated benchmarks share: the instruction timer, the timed
//! checksum sink, stack painting, the baked Blender exports and the panic
//! handler. `src/main.rs` is the benchmark of the README's table;
//! `src/bin/study.rs` times the accuracy study's configurations.
#![no_std]

use core::sync::atomic::{AtomicU32, Ordering};
use cortex_m_semihosting::{debug, hprintln};
use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use soft3d::scenes::FrameChecksum;

/// The shared Blender exports, baked by `build.rs` (see `tools/bake`).
#[cfg(soft3d_assets)]
#[allow(missing_docs, dead_code)]
pub mod torus_file {
    include!(concat!(env!("OUT_DIR"), "/torus_file.rs"));
}
#[cfg(soft3d_assets)]
#[allow(missing_docs, dead_code)]
pub mod monkey_file {
    include!(concat!(env!("OUT_DIR"), "/monkey_file.rs"));
}

#[cfg(soft3d_assets)]
#[allow(missing_docs, dead_code)]
pub mod torus_i16_file {
    include!(concat!(env!("OUT_DIR"), "/torus_i16_file.rs"));
}

/// The baked scenes, in the order of `FILE_SCENES` then
/// `QUANTIZED_SCENES`: camera and meshes.
#[cfg(soft3d_assets)]
pub fn file_scene(
    i: usize,
) -> (soft3d::Camera, &'static [(&'static soft3d::mesh::Mesh<'static>, soft3d::math::Mat4, Rgb888, soft3d::Cull)]) {
    match i {
        0 => (torus_file::CAMERA, &torus_file::MESHES),
        1 => (monkey_file::CAMERA, &monkey_file::MESHES),
        _ => (torus_i16_file::CAMERA, &torus_i16_file::MESHES),
    }
}

/// Instructions per SysTick tick under `-icount shift=0` (1 ns an
/// instruction): SysTick runs at 25 MHz on mps2-an385 and mps2-an386, at
/// 20 MHz on mps2-an505.
pub const INSTRUCTIONS_PER_TICK: u32 = if cfg!(soft3d_an505) { 50 } else { 40 };

pub struct Timer(pub cortex_m::peripheral::SYST);

/// Times the 24-bit SysTick counter wrapped since [`Timer::start`] (every
/// 671 million instructions), counted by its exception: per-pixel lighting
/// in software float fills a frame with billions.
static WRAPS: AtomicU32 = AtomicU32::new(0);

#[cortex_m_rt::exception]
fn SysTick() {
    // Only this handler writes: a load and a store suffice (ARMv6-M has no
    // atomic read-modify-write).
    WRAPS.store(WRAPS.load(Ordering::Relaxed) + 1, Ordering::Relaxed);
}

impl Timer {
    /// Restarts the count.
    pub fn start(&mut self) {
        self.0.clear_current();
        let _ = self.0.has_wrapped();
        WRAPS.store(0, Ordering::Relaxed);
    }
    /// Instructions since `start`, or None beyond `u32::MAX`.
    pub fn instructions(&mut self) -> Option<u32> {
        loop {
            let wraps = WRAPS.load(Ordering::Relaxed);
            let now = cortex_m::peripheral::SYST::get_current();
            // A wrap between the two reads: read both again.
            if WRAPS.load(Ordering::Relaxed) == wraps {
                let ticks = wraps as u64 * 0x0100_0000 + (0x00FF_FFFF - now) as u64;
                return u32::try_from(ticks * INSTRUCTIONS_PER_TICK as u64).ok();
            }
        }
    }
}

pub const TARGET: &str = if cfg!(soft3d_an505) {
    "m33"
} else if cfg!(target_abi = "eabihf") {
    "m4f"
} else {
    "m0"
};

/// Stack painting: the pattern written below the stack pointer before a
/// frame, and how far below it is checked.
pub const PAINT: u32 = 0x5AFE_57AC;
pub const PAINT_BYTES: usize = 64 * 1024;
/// Room left for `paint`'s and `stack_used`'s own frames.
pub const PAINT_MARGIN: usize = 512;

/// Fills `[top - PAINT_BYTES, top - PAINT_MARGIN)` with the pattern.
#[inline(never)]
pub fn paint(top: usize) {
    let mut a = top - PAINT_BYTES;
    while a < top - PAINT_MARGIN {
        // SAFETY: the region is RAM below the live stack frames (the
        // emulated boards have 4 MB of RAM and the stack starts at its top),
        // not used by anything else; written before the frame runs.
        unsafe { (a as *mut u32).write_volatile(PAINT) };
        a += 4;
    }
}

/// Bytes below `top` that no longer hold the pattern: the deepest the
/// stack went since `paint(top)`.
#[inline(never)]
pub fn stack_used(top: usize) -> usize {
    let mut a = top - PAINT_BYTES;
    while a < top - PAINT_MARGIN {
        // SAFETY: the same region `paint` wrote; only read here.
        if unsafe { (a as *const u32).read_volatile() } != PAINT {
            return top - a;
        }
        a += 4;
    }
    PAINT_MARGIN
}

/// Instructions per tick, measured: a loop of `subs` and `bne` run
/// `LOOPS` times is `2 * LOOPS` instructions (plus a handful around it).
pub fn calibrate(timer: &mut Timer) -> Option<u32> {
    const LOOPS: u32 = 2_000_000;
    timer.start();
    // SAFETY: a register-only countdown loop; touches no memory.
    unsafe {
        core::arch::asm!("2:", "subs {n}, #1", "bne 2b", n = inout(reg) LOOPS => _, options(nomem, nostack));
    }
    let ticks = timer.instructions()? / INSTRUCTIONS_PER_TICK;
    Some(((2 * LOOPS as u64 + ticks as u64 / 2) / ticks.max(1) as u64) as u32)
}

/// Starts SysTick as the instruction counter (core clock, free-running over
/// 24 bits, its wraps counted by its exception), calibrates it and prints the
/// `calibration,instructions_per_tick,N,assumed,40` line the scripts check.
pub fn start_timer() -> Timer {
    let Some(p) = cortex_m::Peripherals::take() else {
        hprintln!("calibration,failed");
        exit()
    };
    let mut syst = p.SYST;
    syst.set_clock_source(cortex_m::peripheral::syst::SystClkSource::Core);
    syst.set_reload(0x00FF_FFFF);
    syst.enable_interrupt();
    syst.enable_counter();
    let mut timer = Timer(syst);
    match calibrate(&mut timer) {
        Some(f) => hprintln!("calibration,instructions_per_tick,{},assumed,{}", f, INSTRUCTIONS_PER_TICK),
        None => hprintln!("calibration,failed"),
    }
    timer
}

/// Ends the emulation successfully.
pub fn exit() -> ! {
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

/// Wraps the checksum sink and accumulates the instructions spent inside
/// it, so that the frame's own cost can exclude them.
pub struct TimedSink {
    /// The checksum.
    pub inner: FrameChecksum<Rgb565>,
    /// Ticks spent inside it.
    pub ticks: u32,
}

impl OriginDimensions for TimedSink {
    fn size(&self) -> Size {
        self.inner.size()
    }
}

impl DrawTarget for TimedSink {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    #[inline(never)]
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        let t0 = cortex_m::peripheral::SYST::get_current();
        let r = self.inner.draw_iter(pixels);
        self.ticks += t0.wrapping_sub(cortex_m::peripheral::SYST::get_current()) & 0x00FF_FFFF;
        r
    }

    #[inline(never)]
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error> {
        let t0 = cortex_m::peripheral::SYST::get_current();
        let r = self.inner.fill_contiguous(area, colors);
        self.ticks += t0.wrapping_sub(cortex_m::peripheral::SYST::get_current()) & 0x00FF_FFFF;
        r
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
