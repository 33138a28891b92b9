//! The demo's frame loop for board firmware: draw, finish, time, report.

use super::draw_demo;
use crate::effect::Color;
use crate::renderer::{DrawError, Frame, FrameStats};
use crate::settings::Settings;
use core::fmt;
use embedded_graphics::prelude::DrawTarget;

/// Draws [`draw_demo`] frame after frame, timing each with the board's
/// clock.
///
/// The animation's time is the sum of the frames' measured durations, so
/// the scene turns at the same speed whatever the frame rate, and the same
/// clock readings always give the same frames.
///
/// Every board runs this same loop and differs only in its clock, so a
/// board's `main` is its clocks, bus and display setup around it. Here a
/// mock display stands for the board's, and a clock that advances 5 ms at
/// each reading (three a frame) for its timer:
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::Rgb565, prelude::*};
/// use soft3d::scenes::{demo_camera, demo_lights, DemoLoop, DEMO_TRIANGLES, DEMO_VARYINGS, DEMO_VERTICES};
/// use soft3d::{FixedPoint, Renderer};
///
/// let mut renderer: Renderer<Rgb565, 64, 48, 16, DEMO_VERTICES, DEMO_TRIANGLES, DEMO_VARYINGS, FixedPoint> =
///     Renderer::new(Rgb565::BLACK);
/// let (camera, lights) = (demo_camera(), demo_lights());
/// let mut microseconds = 0u32; // a board reads its timer here
/// let mut demo = DemoLoop::new(1_000_000);
/// for _ in 0..2 {
///     let mut display = MockDisplay::new();
///     let frame = renderer.begin_frame(&camera, &lights, Rgb565::BLACK);
///     let report = demo.render(frame, &mut display, || {
///         microseconds += 5_000;
///         microseconds
///     });
///     match report {
///         Ok(report) => println!("{report}"), // rprintln! over RTT on a board
///         Err(e) => println!("display: {e:?}"),
///     }
/// }
/// assert_eq!(demo.seconds(), 0.02); // two frames of 10 ms
/// ```
#[derive(Clone, Debug)]
pub struct DemoLoop {
    ticks_per_second: u32,
    /// Clock ticks the frames so far took.
    elapsed: u64,
    /// Frames finished so far.
    frames: u32,
}

/// What one frame of [`DemoLoop::render`] took and drew.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DemoFrameReport {
    /// The frame's number, from 0.
    pub index: u32,
    /// Clock ticks spent in the draw calls: culling, vertices, clipping,
    /// triangle setup and queuing.
    pub geometry_ticks: u32,
    /// Clock ticks for the whole frame: the draw calls, then rasterizing
    /// every strip and sending it to the display.
    pub total_ticks: u32,
    /// The clock's rate, as given to [`DemoLoop::new`].
    pub ticks_per_second: u32,
    /// The renderer's counts for the frame.
    pub stats: FrameStats,
    /// A draw call's error, if one failed: the frame was still finished
    /// and sent, without the meshes from that draw call on (`draw_demo`
    /// stops at the first error).
    pub draw_error: Option<DrawError>,
}

impl DemoLoop {
    /// A loop timed by a clock that counts `ticks_per_second` ticks a
    /// second (0 is taken as 1).
    pub const fn new(ticks_per_second: u32) -> Self {
        let ticks_per_second = if ticks_per_second == 0 { 1 } else { ticks_per_second };
        Self { ticks_per_second, elapsed: 0, frames: 0 }
    }

    /// The animation time (seconds) the next frame is drawn at.
    pub fn seconds(&self) -> f32 {
        // Whole seconds and the rest apart: exact integers, one rounding.
        let tps = u64::from(self.ticks_per_second);
        (self.elapsed / tps) as f32 + (self.elapsed % tps) as f32 / tps as f32
    }

    /// Draws the demo into `frame`, finishes it into `display` and reports
    /// the time it took. `now` reads the board's clock, a counter of ticks
    /// that may wrap around. Only the display's error stops a frame; it
    /// then does not count towards the animation time or the frame numbers.
    pub fn render<C, const V: usize, S, D>(
        &mut self,
        mut frame: Frame<'_, '_, C, V, S>,
        display: &mut D,
        mut now: impl FnMut() -> u32,
    ) -> Result<DemoFrameReport, D::Error>
    where
        C: Color,
        S: Settings,
        D: DrawTarget<Color = C>,
    {
        let start = now();
        let draw_error = draw_demo(&mut frame, self.seconds()).err();
        let drawn = now();
        let stats = frame.finish(display)?;
        let end = now();
        let total_ticks = end.wrapping_sub(start);
        let report = DemoFrameReport {
            index: self.frames,
            geometry_ticks: drawn.wrapping_sub(start),
            total_ticks,
            ticks_per_second: self.ticks_per_second,
            stats,
            draw_error,
        };
        self.elapsed += u64::from(total_ticks);
        self.frames = self.frames.wrapping_add(1);
        Ok(report)
    }
}

impl DemoFrameReport {
    /// `ticks` in whole microseconds.
    pub fn micros(&self, ticks: u32) -> u64 {
        u64::from(ticks) * 1_000_000 / u64::from(self.ticks_per_second.max(1))
    }

    /// Frames per second in tenths, at this frame's duration.
    pub fn tenths_fps(&self) -> u64 {
        10 * u64::from(self.ticks_per_second) / u64::from(self.total_ticks.max(1))
    }
}

/// One line: `frame 7: 41250 us (geometry 9800 us, raster + display 31450
/// us), 24.2 fps, 1148 triangles`. A clock other than 1 MHz (a cycle
/// counter) adds its ticks after the total, a draw call's error goes at
/// the end.
impl fmt::Display for DemoFrameReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (total, geometry) = (self.micros(self.total_ticks), self.micros(self.geometry_ticks));
        write!(f, "frame {}: {} us", self.index, total)?;
        if self.ticks_per_second != 1_000_000 {
            write!(f, " = {} ticks", self.total_ticks)?;
        }
        let fps = self.tenths_fps();
        write!(
            f,
            " (geometry {} us, raster + display {} us), {}.{} fps, {} triangles",
            geometry,
            total.saturating_sub(geometry),
            fps / 10,
            fps % 10,
            self.stats.queued
        )?;
        match &self.draw_error {
            Some(e) => write!(f, "; draw_demo: {e}"),
            None => Ok(()),
        }
    }
}
