//! Host-side helpers (feature `simulator`): an in-memory `DrawTarget`,
//! PNG and animated GIF output, PNG and JPEG input, and `.babylon` scenes
//! with their textures ([`scene`]).

pub mod scene;

use crate::texture::OwnedTexture;
use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::pixelcolor::{PixelColor, Rgb888, RgbColor};
use embedded_graphics::prelude::{OriginDimensions, Pixel, Point, Size};
use embedded_graphics::primitives::Rectangle;
use std::fs::File;
use std::io::{self, BufWriter};
use std::path::Path;
use std::vec::Vec;

/// A `width`×`height` image in memory that is also a `DrawTarget`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image<C> {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Pixels, row by row.
    pub pixels: Vec<C>,
    /// Number of `fill_contiguous` calls received (one per strip).
    pub fills: u32,
}

impl<C: PixelColor> Image<C> {
    /// An image filled with `fill`.
    pub fn new(width: u32, height: u32, fill: C) -> Self {
        Self { width, height, pixels: std::vec![fill; width as usize * height as usize], fills: 0 }
    }

    /// The pixel at (x, y). Panics if out of bounds (test helper).
    pub fn get(&self, x: u32, y: u32) -> C {
        self.pixels[(y * self.width + x) as usize]
    }

    fn index(&self, p: Point) -> Option<usize> {
        (p.x >= 0 && p.y >= 0 && (p.x as u32) < self.width && (p.y as u32) < self.height)
            .then(|| p.y as usize * self.width as usize + p.x as usize)
    }
}

impl<C: PixelColor> OriginDimensions for Image<C> {
    fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }
}

impl<C: PixelColor> DrawTarget for Image<C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            if let Some(i) = self.index(p) {
                self.pixels[i] = c;
            }
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error> {
        self.fills += 1;
        let mut it = colors.into_iter();
        for y in 0..area.size.height as i32 {
            for x in 0..area.size.width as i32 {
                let Some(c) = it.next() else { return Ok(()) };
                if let Some(i) = self.index(area.top_left + Point::new(x, y)) {
                    self.pixels[i] = c;
                }
            }
        }
        Ok(())
    }
}

impl<C: PixelColor + Into<Rgb888>> Image<C> {
    /// RGB bytes, 3 per pixel.
    pub fn to_rgb_bytes(&self) -> Vec<u8> {
        self.pixels
            .iter()
            .flat_map(|&c| {
                let c: Rgb888 = c.into();
                [c.r(), c.g(), c.b()]
            })
            .collect()
    }

    /// Writes an 8-bit RGB PNG.
    pub fn save_png(&self, path: impl AsRef<Path>) -> io::Result<()> {
        write_png(path.as_ref(), self.width, self.height, png::ColorType::Rgb, &self.to_rgb_bytes())
    }
}

/// Writes an 8-bit PNG of the given color type.
pub fn write_png(path: &Path, width: u32, height: u32, color: png::ColorType, data: &[u8]) -> io::Result<()> {
    let w = BufWriter::new(File::create(path)?);
    let mut enc = png::Encoder::new(w, width, height);
    enc.set_color(color);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().map_err(io::Error::other)?;
    writer.write_image_data(data).map_err(io::Error::other)?;
    writer.finish().map_err(io::Error::other)
}

/// Reads an 8-bit RGB, RGBA, gray or gray-alpha PNG as RGB pixels (alpha
/// dropped).
pub fn load_png(path: impl AsRef<Path>) -> io::Result<Image<Rgb888>> {
    let (width, height, rgba) = crate::texture::read_png(path.as_ref())?;
    let pixels = rgba.iter().map(|p| Rgb888::new(p[0], p[1], p[2])).collect();
    Ok(Image { width, height, pixels, fills: 0 })
}

/// Reads a PNG or JPEG (by extension) as a texture: see
/// [`OwnedTexture::load`] (the bake tool's loader too).
pub fn load_texture(path: impl AsRef<Path>) -> io::Result<OwnedTexture> {
    OwnedTexture::load(path.as_ref(), 1 << 15)
}

/// Collects frames into an animated GIF.
pub struct GifRecorder {
    width: u16,
    height: u16,
    frames: Vec<Vec<u8>>,
    delay_cs: u16,
}

impl GifRecorder {
    /// A recorder for frames of the given size, shown `delay_cs`
    /// hundredths of a second each.
    pub fn new(width: u32, height: u32, delay_cs: u16) -> Self {
        Self { width: width as u16, height: height as u16, frames: Vec::new(), delay_cs }
    }

    /// Adds a frame.
    pub fn push<C: PixelColor + Into<Rgb888>>(&mut self, image: &Image<C>) {
        self.frames.push(image.to_rgb_bytes());
    }

    /// Writes the GIF (looping forever).
    pub fn save(&self, path: impl AsRef<Path>) -> io::Result<()> {
        let mut enc = gif::Encoder::new(BufWriter::new(File::create(path)?), self.width, self.height, &[]).map_err(io::Error::other)?;
        enc.set_repeat(gif::Repeat::Infinite).map_err(io::Error::other)?;
        for rgb in &self.frames {
            let mut f = gif::Frame::from_rgb_speed(self.width, self.height, rgb, 10);
            f.delay = self.delay_cs;
            enc.write_frame(&f).map_err(io::Error::other)?;
        }
        Ok(())
    }
}
