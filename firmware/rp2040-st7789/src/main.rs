//! soft3d's demo scene on a Raspberry Pi Pico (RP2040, Cortex-M0+ at
//! 125 MHz, no FPU) driving an ST7789 320×240 display over SPI, in fixed
//! point.
//!
//! The firmware only sets up the clocks, the SPI bus and the display; the
//! frame loop is `soft3d::scenes::DemoLoop`, tested on the host. Each frame
//! is rendered in 16-row strips, each strip sent with one `fill_contiguous`,
//! and the frame time, measured with the RP2040's 1 MHz timer, is printed
//! over RTT. Wiring, building and flashing: `docs/boards.md`.
#![no_std]
#![no_main]
#![deny(unsafe_code)]

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_hal::digital::{OutputPin, PinState};
use embedded_hal::spi::MODE_0;
use embedded_hal_bus::spi::ExclusiveDevice;
use mipidsi::interface::SpiInterface;
use mipidsi::models::ST7789;
use mipidsi::options::{ColorInversion, Orientation, Rotation};
use rp2040_hal::fugit::RateExtU32;
use rp2040_hal::gpio::{FunctionSpi, Pins};
use rp2040_hal::{self as hal, pac, Clock};
use rtt_target::{rprintln, rtt_init_print};
use soft3d::scenes::{demo_camera, demo_lights, DemoLoop, DEMO_TRIANGLES, DEMO_VARYINGS, DEMO_VERTICES};
use soft3d::{FixedPoint, Renderer};
use static_cell::ConstStaticCell;

/// The second-stage bootloader for the Pico's W25Q080 flash. The boot ROM
/// runs the first 256 bytes of flash, so they must be placed there under
/// this exact name (memory.x keeps `.boot2` and names `BOOT2_FIRMWARE`).
// The `unsafe_code` lint covers `link_section` and `no_mangle`; there is no
// other way to put the bootloader where the ROM looks for it.
#[allow(unsafe_code)]
#[link_section = ".boot2"]
#[no_mangle]
#[used]
pub static BOOT2_FIRMWARE: [u8; 256] = rp2040_boot2::BOOT_LOADER_W25Q080;

/// The Pico's crystal.
const XOSC_HZ: u32 = 12_000_000;
/// SPI clock: the peripheral clock (125 MHz) / 2, the RP2040's maximum.
/// Lower it (e.g. to 31.25 MHz) if long wires garble the picture.
const SPI_HZ: u32 = 62_500_000;

/// Display size in landscape, and rows rendered at a time.
const W: usize = 320;
const H: usize = 240;
const STRIP: usize = 16;

type DemoRenderer = Renderer<Rgb565, W, H, STRIP, DEMO_VERTICES, DEMO_TRIANGLES, DEMO_VARYINGS, FixedPoint>;

/// The renderer's buffers (73 KB), built at compile time (`Renderer::new`
/// is a `const fn`) so that they never pass through the stack. A renderer
/// with a black fill is all zeros, so it sits in `.bss`: no flash image,
/// nothing copied at startup.
static RENDERER: ConstStaticCell<DemoRenderer> = ConstStaticCell::new(Renderer::new(Rgb565::BLACK));

#[hal::entry]
fn main() -> ! {
    rtt_init_print!();
    let mut pac = pac::Peripherals::take().unwrap();
    let mut watchdog = hal::Watchdog::new(pac.WATCHDOG);
    let clocks =
        hal::clocks::init_clocks_and_plls(XOSC_HZ, pac.XOSC, pac.CLOCKS, pac.PLL_SYS, pac.PLL_USB, &mut pac.RESETS, &mut watchdog).unwrap();
    let mut timer = hal::Timer::new(pac.TIMER, &mut pac.RESETS, &clocks);
    let sio = hal::Sio::new(pac.SIO);
    let pins = Pins::new(pac.IO_BANK0, pac.PADS_BANK0, sio.gpio_bank0, &mut pac.RESETS);

    // SPI1 on GP10 (SCK) and GP11 (MOSI); CS, DC, RST and the backlight on
    // plain outputs (the pinout of Waveshare's Pico-LCD-2 plug-in board).
    let sck = pins.gpio10.into_function::<FunctionSpi>();
    let mosi = pins.gpio11.into_function::<FunctionSpi>();
    let cs = pins.gpio9.into_push_pull_output_in_state(PinState::High);
    let dc = pins.gpio8.into_push_pull_output();
    let rst = pins.gpio12.into_push_pull_output_in_state(PinState::High);
    let mut backlight = pins.gpio13.into_push_pull_output_in_state(PinState::Low);
    let spi = hal::Spi::<_, _, _, 8>::new(pac.SPI1, (mosi, sck)).init(&mut pac.RESETS, clocks.peripheral_clock.freq(), SPI_HZ.Hz(), MODE_0);
    let spi = ExclusiveDevice::new_no_delay(spi, cs).unwrap();
    let mut spi_buffer = [0u8; 1024];
    let interface = SpiInterface::new(spi, dc, &mut spi_buffer);
    let mut display = mipidsi::Builder::new(ST7789, interface)
        .reset_pin(rst)
        // IPS ST7789 panels show inverted colors without this.
        .invert_colors(ColorInversion::Inverted)
        .orientation(Orientation::new().rotate(Rotation::Deg90))
        .init(&mut timer)
        .unwrap();
    display.clear(Rgb565::BLACK).unwrap();
    backlight.set_high().unwrap();

    let renderer = RENDERER.take();
    let (camera, lights) = (demo_camera(), demo_lights());
    rprintln!("soft3d demo: RP2040 + ST7789 {}x{}, {}-row strips, fixed point", W, H, STRIP);
    // The timer counts microseconds; its low 32 bits wrap after 71 minutes,
    // which the loop's differences allow for.
    let mut demo = DemoLoop::new(1_000_000);
    loop {
        let frame = renderer.begin_frame(&camera, &lights, Rgb565::BLACK);
        match demo.render(frame, &mut display, || timer.get_counter().ticks() as u32) {
            Ok(report) => rprintln!("{}", report),
            Err(e) => rprintln!("display: {:?}", e),
        }
    }
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    rprintln!("panic: {}", info);
    loop {
        cortex_m::asm::wfi();
    }
}
