//! A `DrawTarget` that checks how the renderer writes to it: every pixel
//! inside the frame, no pixel twice in one flush (one `fill_contiguous`
//! or `draw_iter` call), and, over a whole frame, every pixel exactly once
//! (the strips partition the frame). A violation panics, which is what a
//! fuzzer reports as a crash.

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{OriginDimensions, Size};
use embedded_graphics::pixelcolor::PixelColor;
use embedded_graphics::primitives::{PointsIter, Rectangle};
use embedded_graphics::Pixel;

/// A `width`×`height` frame that records what it receives.
pub struct CheckedTarget<C> {
    pub width: usize,
    pub height: usize,
    /// The last color written to each pixel (row-major), `None` if never.
    pub pixels: Vec<Option<C>>,
    /// The flush that last wrote each pixel (0: none).
    written_in: Vec<u32>,
    flushes: u32,
}

impl<C: PixelColor> CheckedTarget<C> {
    pub fn new(width: usize, height: usize) -> Self {
        Self { width, height, pixels: vec![None; width * height], written_in: vec![0; width * height], flushes: 0 }
    }

    fn put(&mut self, x: i32, y: i32, c: C) {
        let inside = x >= 0 && y >= 0 && (x as usize) < self.width && (y as usize) < self.height;
        assert!(inside, "pixel ({x}, {y}) written outside the {}x{} frame", self.width, self.height);
        let i = y as usize * self.width + x as usize;
        assert!(self.written_in[i] != self.flushes, "pixel ({x}, {y}) written twice in flush {}", self.flushes);
        // Strips do not overlap, so a pixel written by an earlier flush is
        // a second write in the same frame.
        assert!(self.written_in[i] == 0, "pixel ({x}, {y}) written by flush {} and again by {}", self.written_in[i], self.flushes);
        self.written_in[i] = self.flushes;
        self.pixels[i] = Some(c);
    }

    /// The frame's colors, once every pixel was written exactly once.
    pub fn finished(&self) -> Vec<C> {
        let missing = self.pixels.iter().position(Option::is_none);
        if let Some(i) = missing {
            panic!("pixel ({}, {}) never written ({} flushes)", i % self.width, i / self.width, self.flushes);
        }
        self.pixels.iter().map(|p| p.unwrap()).collect()
    }
}

impl<C: PixelColor> OriginDimensions for CheckedTarget<C> {
    fn size(&self) -> Size {
        Size::new(self.width as u32, self.height as u32)
    }
}

impl<C: PixelColor> DrawTarget for CheckedTarget<C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        self.flushes += 1;
        for Pixel(p, c) in pixels {
            self.put(p.x, p.y, c);
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error> {
        self.flushes += 1;
        let mut colors = colors.into_iter();
        for (n, p) in area.points().enumerate() {
            let c = colors.next().unwrap_or_else(|| panic!("{area:?}: the color iterator ended after {n} pixels"));
            self.put(p.x, p.y, c);
        }
        // The renderer hands over exactly one color per pixel of the area.
        assert!(colors.next().is_none(), "{area:?}: more colors than pixels");
        Ok(())
    }
}
