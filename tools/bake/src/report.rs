//! Statistics of a bake, for the CLI and for build scripts.

use crate::{Baked, QuantizationError, Quantize, Texels, TextureFormat};
use std::fmt;
use std::path::PathBuf;

/// What a bake produced.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Report {
    /// The input's file name.
    pub source: String,
    /// The file written ([`bake_file`](crate::bake_file) only).
    pub output: Option<PathBuf>,
    /// Vertex storage.
    pub quantize: Quantize,
    /// Texture storage.
    pub texture_format: TextureFormat,
    /// Per mesh.
    pub meshes: Vec<MeshReport>,
    /// Per texture.
    pub textures: Vec<TextureReport>,
    /// Number of materials.
    pub materials: usize,
    /// Whether `CAMERA` was emitted.
    pub camera: bool,
    /// Whether `LIGHTS` was emitted, and with which lights.
    pub lights: Option<(bool, bool)>,
    /// Bytes of mesh and texture data the firmware keeps in flash if it
    /// uses every item (the `i16` arrays are not counted: nothing reads
    /// them yet).
    pub flash_bytes: usize,
    /// Size of the generated source ([`bake_file`](crate::bake_file) only).
    pub source_bytes: usize,
    /// Warnings (resized textures, skipped meshes and lights, ...).
    pub warnings: Vec<String>,
    /// Every file read, for `cargo:rerun-if-changed`.
    pub inputs: Vec<PathBuf>,
}

/// One mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshReport {
    /// Name in the file.
    pub name: String,
    /// Base identifier of its items.
    pub ident: String,
    /// Vertices.
    pub vertices: usize,
    /// Triangles.
    pub triangles: usize,
    /// Whether it has texture coordinates.
    pub uvs: bool,
    /// Bytes of its `f32` arrays and indices.
    pub flash_bytes: usize,
    /// Bytes it would take with `i16` positions and normals.
    pub i16_flash_bytes: usize,
    /// The quantization error, in `i16` mode.
    pub quantization: Option<QuantizationError>,
}

/// One texture.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TextureReport {
    /// The name materials use.
    pub name: String,
    /// Base identifier of its items.
    pub ident: String,
    /// Size of the image file.
    pub source_size: (u32, u32),
    /// Size baked.
    pub size: (u32, u32),
    /// Storage.
    pub format: TextureFormat,
    /// Bytes of texels (and palette).
    pub flash_bytes: usize,
    /// PSNR (dB) of RGB565 against the 8-bit image.
    pub psnr_rgb565: f64,
    /// PSNR (dB) of the palette image against RGB565, in `palette8` mode.
    pub psnr_palette: Option<f64>,
}

pub(crate) fn report(b: &Baked) -> Report {
    let meshes: Vec<MeshReport> = b
        .meshes
        .iter()
        .map(|m| {
            let (v, i) = (m.positions.len(), m.indices.len());
            let uv_bytes = if m.uvs.is_some() { 8 * v } else { 0 };
            MeshReport {
                name: m.name.clone(),
                ident: m.ident.clone(),
                vertices: v,
                triangles: i / 3,
                uvs: m.uvs.is_some(),
                flash_bytes: 24 * v + uv_bytes + 2 * i,
                i16_flash_bytes: 12 * v + uv_bytes + 2 * i,
                quantization: m.quantized.as_ref().map(|q| q.error),
            }
        })
        .collect();
    let textures: Vec<TextureReport> = b
        .textures
        .iter()
        .map(|t| {
            let n = t.size.0 as usize * t.size.1 as usize;
            let (format, flash_bytes) = match t.texels {
                Texels::Rgb565(_) => (TextureFormat::Rgb565, 2 * n),
                Texels::Palette8 { .. } => (TextureFormat::Palette8, n + 512),
            };
            TextureReport {
                name: t.name.clone(),
                ident: t.ident.clone(),
                source_size: t.source_size,
                size: t.size,
                format,
                flash_bytes,
                psnr_rgb565: t.psnr_rgb565,
                psnr_palette: t.psnr_palette,
            }
        })
        .collect();
    let flash_bytes = meshes.iter().map(|m| m.flash_bytes).sum::<usize>() + textures.iter().map(|t| t.flash_bytes).sum::<usize>();
    Report {
        source: b.source.clone(),
        output: None,
        quantize: b.options.quantize,
        texture_format: b.options.texture_format,
        meshes,
        textures,
        materials: b.materials.len(),
        camera: b.camera.is_some(),
        lights: b.lights.map(|l| (l.point.is_some(), l.directional.is_some())),
        flash_bytes,
        source_bytes: 0,
        warnings: b.warnings.clone(),
        inputs: b.inputs.clone(),
    }
}

/// `1234567` → `1,234,567`.
fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let groups: Vec<&str> = digits.as_bytes().rchunks(3).rev().map(|g| std::str::from_utf8(g).unwrap_or("")).collect();
    groups.join(",")
}

fn db(v: f64) -> String {
    if v.is_infinite() {
        "lossless".to_string()
    } else {
        format!("PSNR {v:.1} dB")
    }
}

impl fmt::Display for Report {
    /// A human-readable summary (warnings not included).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let q = match self.quantize {
            Quantize::F32 => "f32",
            Quantize::I16 => "i16",
        };
        write!(f, "{} ({q} vertices", self.source)?;
        if !self.textures.is_empty() {
            write!(f, ", {} textures", format_name(self.texture_format))?;
        }
        write!(f, ")")?;
        if let Some(out) = &self.output {
            write!(f, " -> {}, {} bytes of source", out.display(), thousands(self.source_bytes))?;
        }
        writeln!(f)?;
        for m in &self.meshes {
            writeln!(
                f,
                "mesh '{}' ({}): {} vertices, {} triangles{}, {} bytes",
                m.name,
                m.ident,
                thousands(m.vertices),
                thousands(m.triangles),
                if m.uvs { ", uvs" } else { "" },
                thousands(m.flash_bytes)
            )?;
            if let Some(e) = m.quantization {
                writeln!(
                    f,
                    "  i16 positions: error max {:.3e} ({:.2e} of the bounding radius {:.4}), rms {:.3e} ({:.2e}), \
                     ≤ {:.3} steps per axis; normals: max {:.4}°; {} bytes",
                    e.max_position,
                    e.max_relative(),
                    e.radius,
                    e.rms_position,
                    e.rms_relative(),
                    e.max_axis_steps,
                    e.max_normal_degrees,
                    thousands(m.i16_flash_bytes)
                )?;
            }
        }
        for t in &self.textures {
            write!(f, "texture '{}' ({}): {}×{}", t.name, t.ident, t.size.0, t.size.1)?;
            if t.size != t.source_size {
                write!(f, " (from {}×{})", t.source_size.0, t.source_size.1)?;
            }
            write!(
                f,
                " {}, {} bytes; RGB565 {} against the 8-bit image",
                format_name(t.format),
                thousands(t.flash_bytes),
                db(t.psnr_rgb565)
            )?;
            if let Some(p) = t.psnr_palette {
                write!(f, "; palette {} against RGB565", db(p))?;
            }
            writeln!(f)?;
        }
        write!(f, "{} material(s); camera: {}; lights: ", self.materials, if self.camera { "yes" } else { "none" })?;
        match self.lights {
            None => write!(f, "none")?,
            Some((p, d)) => {
                write!(f, "ambient")?;
                if p {
                    write!(f, ", point")?;
                }
                if d {
                    write!(f, ", directional")?;
                }
            }
        }
        writeln!(f)?;
        write!(f, "flash: {} bytes of mesh and texture data", thousands(self.flash_bytes))
    }
}

fn format_name(t: TextureFormat) -> &'static str {
    match t {
        TextureFormat::Rgb565 => "rgb565",
        TextureFormat::Palette8 => "palette8",
        TextureFormat::None => "none",
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn thousands() {
        assert_eq!(super::thousands(0), "0");
        assert_eq!(super::thousands(999), "999");
        assert_eq!(super::thousands(1000), "1,000");
        assert_eq!(super::thousands(1234567), "1,234,567");
    }
}
