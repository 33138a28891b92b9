//! soft3d's demo scene on an STM32F411 "Black Pill" (Cortex-M4F at
//! 100 MHz) driving an ILI9341 320×240 display over SPI, in `f32`.
//!
//! The firmware only sets up the clocks, the SPI bus and the display; the
//! frame loop is `soft3d::scenes::DemoLoop`, tested on the host. Each frame
//! is rendered in 16-row strips, each strip sent with one `fill_contiguous`,
//! and the frame time, measured with the core's cycle counter (DWT CYCCNT),
//! is printed over RTT. Wiring, building and flashing: `docs/boards.md`.
#![no_std]
#![no_main]
#![deny(unsafe_code)]

use cortex_m::peripheral::DWT;
use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_hal::spi::MODE_0;
use embedded_hal_bus::spi::ExclusiveDevice;
use mipidsi::interface::SpiInterface;
use mipidsi::models::ILI9341Rgb565;
use mipidsi::options::{ColorOrder, Orientation, Rotation};
use rtt_target::{rprintln, rtt_init_print};
use soft3d::scenes::{demo_camera, demo_lights, DemoLoop, DEMO_TRIANGLES, DEMO_VARYINGS, DEMO_VERTICES};
use soft3d::{FloatingPoint, Renderer};
use static_cell::ConstStaticCell;
use stm32f4xx_hal::dwt::MonoTimer;
use stm32f4xx_hal::gpio::PinState;
use stm32f4xx_hal::pac;
use stm32f4xx_hal::prelude::*;
use stm32f4xx_hal::rcc::Config;

/// The Black Pill's crystal.
const HSE_MHZ: u32 = 25;
/// Core clock: the STM32F411's maximum.
const SYSCLK_MHZ: u32 = 100;
/// SPI clock: APB2 (100 MHz) / 4. The ILI9341's datasheet asks for at most
/// 10 MHz, but modules commonly work at 25 MHz; with short wires 50 MHz
/// (APB2 / 2) often does too.
const SPI_MHZ: u32 = 25;

/// Display size in landscape, and rows rendered at a time.
const W: usize = 320;
const H: usize = 240;
const STRIP: usize = 16;

type DemoRenderer = Renderer<Rgb565, W, H, STRIP, DEMO_VERTICES, DEMO_TRIANGLES, DEMO_VARYINGS, FloatingPoint>;

/// The renderer's buffers (73 KB), built at compile time (`Renderer::new`
/// is a `const fn`) so that they never pass through the stack. A renderer
/// with a black fill is all zeros, so it sits in `.bss`: no flash image,
/// nothing copied at startup.
static RENDERER: ConstStaticCell<DemoRenderer> = ConstStaticCell::new(Renderer::new(Rgb565::BLACK));

#[entry]
fn main() -> ! {
    rtt_init_print!();
    let dp = pac::Peripherals::take().unwrap();
    let cp = cortex_m::Peripherals::take().unwrap();
    let mut rcc = dp.RCC.freeze(Config::hse(HSE_MHZ.MHz()).sysclk(SYSCLK_MHZ.MHz()));
    let clocks = rcc.clocks;
    let mut delay = cp.SYST.delay(&clocks);
    // Starts the DWT cycle counter, which times the frames.
    let _cycle_counter = MonoTimer::new(cp.DWT, cp.DCB, &clocks);

    // SPI1 on PA5 (SCK) and PA7 (MOSI); CS, DC and RST on plain outputs.
    // The display's backlight (LED) is wired to 3V3.
    let gpioa = dp.GPIOA.split(&mut rcc);
    let gpiob = dp.GPIOB.split(&mut rcc);
    let cs = gpioa.pa4.into_push_pull_output_in_state(PinState::High);
    let dc = gpiob.pb0.into_push_pull_output();
    let rst = gpiob.pb1.into_push_pull_output_in_state(PinState::High);
    let spi = dp.SPI1.spi((Some(gpioa.pa5), pac::SPI1::NoMiso, Some(gpioa.pa7)), MODE_0, SPI_MHZ.MHz(), &mut rcc);
    let spi = ExclusiveDevice::new_no_delay(spi, cs).unwrap();
    let mut spi_buffer = [0u8; 1024];
    let interface = SpiInterface::new(spi, dc, &mut spi_buffer);
    let mut display = mipidsi::Builder::new(ILI9341Rgb565, interface)
        .reset_pin(rst)
        // Most ILI9341 modules have BGR subpixels.
        .color_order(ColorOrder::Bgr)
        .orientation(Orientation::new().rotate(Rotation::Deg90))
        .init(&mut delay)
        .unwrap();
    display.clear(Rgb565::BLACK).unwrap();

    let renderer = RENDERER.take();
    let (camera, lights) = (demo_camera(), demo_lights());
    rprintln!("soft3d demo: STM32F411 + ILI9341 {}x{}, {}-row strips, f32, {} MHz", W, H, STRIP, SYSCLK_MHZ);
    // Frames are timed in core cycles (the 32-bit counter wraps after 42 s
    // at 100 MHz, far beyond a frame), so the report gives cycles as well.
    let mut demo = DemoLoop::new(clocks.hclk().raw());
    loop {
        let frame = renderer.begin_frame(&camera, &lights, Rgb565::BLACK);
        match demo.render(frame, &mut display, DWT::cycle_count) {
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
