//! Host side (feature `textures`): reading PNG and JPEG files into
//! [`OwnedTexture`]s. The simulator and the bake tool both load through
//! here, so the two decode every file to the same pixels.

use super::OwnedTexture;
use std::format;
use std::fs::File;
use std::io;
use std::path::Path;
use std::vec::Vec;

/// Reads an 8-bit RGB, RGBA, gray or gray-alpha PNG as RGBA pixels
/// (opaque when it has no alpha): width, height, pixels row-major.
pub fn read_png(path: &Path) -> io::Result<(u32, u32, Vec<[u8; 4]>)> {
    let mut reader = png::Decoder::new(File::open(path)?).read_info().map_err(io::Error::other)?;
    let mut buf = std::vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).map_err(io::Error::other)?;
    if info.bit_depth != png::BitDepth::Eight {
        return Err(io::Error::other("only 8-bit PNGs are supported"));
    }
    let n = info.color_type.samples();
    let pixels = buf[..info.buffer_size()]
        .chunks_exact(n)
        .map(|p| match n {
            1 => [p[0], p[0], p[0], 255],
            2 => [p[0], p[0], p[0], p[1]],
            3 => [p[0], p[1], p[2], 255],
            _ => [p[0], p[1], p[2], p[3]],
        })
        .collect();
    Ok((info.width, info.height, pixels))
}

/// Reads a baseline or progressive RGB or gray JPEG as opaque RGBA pixels.
pub fn read_jpeg(path: &Path) -> io::Result<(u32, u32, Vec<[u8; 4]>)> {
    let mut dec = jpeg_decoder::Decoder::new(io::BufReader::new(File::open(path)?));
    let data = dec.decode().map_err(io::Error::other)?;
    let info = dec.info().ok_or_else(|| io::Error::other("JPEG without a header"))?;
    let pixels = match info.pixel_format {
        jpeg_decoder::PixelFormat::RGB24 => data.chunks_exact(3).map(|p| [p[0], p[1], p[2], 255]).collect(),
        jpeg_decoder::PixelFormat::L8 => data.iter().map(|&v| [v, v, v, 255]).collect(),
        other => return Err(io::Error::other(format!("unsupported JPEG pixel format {other:?}"))),
    };
    Ok((info.width as u32, info.height as u32, pixels))
}

/// Reads a PNG or JPEG, by extension, as RGBA pixels.
pub fn read_image(path: &Path) -> io::Result<(u32, u32, Vec<[u8; 4]>)> {
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
    match ext.as_str() {
        "png" => read_png(path),
        "jpg" | "jpeg" => read_jpeg(path),
        _ => Err(io::Error::other("unsupported texture format (PNG or JPEG)")),
    }
}

impl OwnedTexture {
    /// Reads a PNG or JPEG (by extension) and converts it with
    /// [`OwnedTexture::from_rgba`]: RGB565 rounded to the nearest level, an
    /// alpha plane if any pixel is not opaque, sides that are not powers of
    /// two (or exceed `max_side`) averaged down.
    pub fn load(path: &Path, max_side: usize) -> io::Result<Self> {
        let (width, height, pixels) = read_image(path)?;
        if width == 0 || height == 0 {
            return Err(io::Error::other("empty image"));
        }
        Self::from_rgba(width as usize, height as usize, &pixels, max_side).map_err(io::Error::other)
    }
}
