//! # soft3d-bake
//!
//! Converts `.babylon` scenes and Wavefront OBJ files (with their JPEG/PNG
//! diffuse textures) into a Rust source file of `static` data that
//! [`soft3d`] renders straight from flash: per mesh the vertex and index
//! arrays and a compile-time validated [`soft3d::mesh::Mesh`], its model
//! matrix, its material's color and culling, the scene's camera and
//! lights, and each texture as RGB565 (or 8-bit palette) texels.
//!
//! ```no_run
//! use soft3d_bake::{bake_file, Options, Quantize};
//! use std::path::Path;
//!
//! // In a firmware crate's build.rs:
//! let out = std::path::PathBuf::from(std::env::var("OUT_DIR").unwrap()).join("scene.rs");
//! let options = Options { quantize: Quantize::I16, ..Options::default() };
//! let report = bake_file(Path::new("assets/monkey.babylon"), &out, &options).unwrap();
//! for input in &report.inputs {
//!     println!("cargo:rerun-if-changed={}", input.display());
//! }
//! // In the firmware: mod scene { include!(concat!(env!("OUT_DIR"), "/scene.rs")); }
//! ```
//!
//! Babylon files are read with the core's own loader, [`soft3d::babylon`],
//! so an `f32` bake is bit-identical to the same file parsed at run time.
//! `docs/bake.md` in the repository describes the generated items.

#![warn(missing_docs)]

mod babylon;
mod emit;
mod names;
mod obj;
mod quantize;
mod report;
mod texture;

use embedded_graphics::pixelcolor::Rgb888;
use soft3d::math::{Mat4, Vec2, Vec3};
use soft3d::{Camera, Cull, Lights};
use std::fmt;
use std::path::{Path, PathBuf};

pub use quantize::{dequantize, QuantizationError, QuantizedMesh, NORMAL_SCALE};
pub use report::{MeshReport, Report, TextureReport};
pub use texture::{rgb565, rgb565_to_rgb888};

/// How vertex data is stored.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Quantize {
    /// `f32` as read (bit-exact).
    #[default]
    F32,
    /// Positions and normals as `i16` triples with per-mesh scale and
    /// offset; the mesh is built from their dequantized values.
    I16,
}

/// How textures are stored.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TextureFormat {
    /// One RGB565 `u16` per texel.
    #[default]
    Rgb565,
    /// A 256-entry RGB565 palette and one `u8` index per texel.
    Palette8,
    /// Textures are not read; materials still name theirs.
    None,
}

/// What to bake and how.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// Vertex storage (default `f32`).
    pub quantize: Quantize,
    /// Where texture files are looked up. `None`: beside the input file
    /// for [`bake_file`]/[`bake`]/[`bake_obj`], the current directory for
    /// [`bake_babylon`].
    pub textures: Option<PathBuf>,
    /// Texture storage (default RGB565).
    pub texture_format: TextureFormat,
    /// Largest texture side in texels (rounded down to a power of two);
    /// larger textures are scaled down. `None`: no limit.
    pub max_texture_size: Option<u32>,
    /// Prepended (as `PREFIX_`) to every generated item, so that several
    /// scenes can share a module. Must be an identifier; it is upper-cased.
    pub prefix: String,
    /// Emit each mesh's face planes (8 bytes of flash a triangle), with
    /// which draw calls culling back faces do so before the vertex stage
    /// (see `soft3d::mesh::Mesh::with_face_planes`).
    pub face_planes: bool,
}

/// Why a bake failed. Every message names the file or item concerned.
#[derive(Debug)]
pub enum BakeError {
    /// A file could not be read or written.
    Io {
        /// The file.
        path: PathBuf,
        /// What happened.
        source: std::io::Error,
    },
    /// The `.babylon` file was refused by `soft3d::babylon`.
    Babylon(soft3d::babylon::Error),
    /// The scene is larger than the bake tool's loader holds.
    TooLarge {
        /// What the file needs.
        needed: soft3d::babylon::Requirements,
        /// What the tool holds.
        capacity: soft3d::babylon::Requirements,
    },
    /// The OBJ (or its MTL) file was refused by the parser.
    Obj {
        /// The file.
        path: PathBuf,
        /// The parser's message.
        problem: String,
    },
    /// A mesh cannot be baked (too many vertices, non-finite values for
    /// `i16` quantization, ...).
    Mesh {
        /// The mesh's name.
        name: String,
        /// What is wrong.
        problem: String,
    },
    /// A texture could not be read or decoded.
    Texture {
        /// The name the material uses.
        name: String,
        /// Where it was looked for.
        path: PathBuf,
        /// What is wrong.
        problem: String,
    },
    /// The input's format is neither `.babylon` nor `.obj`.
    UnknownFormat(PathBuf),
    /// The options are inconsistent (e.g. a prefix that is no identifier).
    Options(String),
    /// The host could not run the loader (no thread could be started).
    Internal(String),
}

impl fmt::Display for BakeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BakeError::Io { path, source } => write!(f, "{}: {source}", path.display()),
            BakeError::Babylon(e) => write!(f, "invalid .babylon scene: {e}"),
            BakeError::TooLarge { needed, capacity } => write!(
                f,
                "scene too large for the bake tool: it needs {} meshes, {} materials, {} lights, {} vertices, {} uvs, {} indices; \
                 the tool holds {} meshes, {} materials, {} lights, {} vertices, {} uvs, {} indices",
                needed.meshes,
                needed.materials,
                needed.lights,
                needed.vertices,
                needed.uvs,
                needed.indices,
                capacity.meshes,
                capacity.materials,
                capacity.lights,
                capacity.vertices,
                capacity.uvs,
                capacity.indices
            ),
            BakeError::Obj { path, problem } => write!(f, "{}: invalid OBJ/MTL: {problem}", path.display()),
            BakeError::Mesh { name, problem } => write!(f, "mesh '{name}': {problem}"),
            BakeError::Texture { name, path, problem } => write!(f, "texture '{name}' ({}): {problem}", path.display()),
            BakeError::UnknownFormat(path) => {
                write!(f, "{}: unknown scene format (expected a .babylon or .obj file)", path.display())
            }
            BakeError::Options(problem) => write!(f, "invalid options: {problem}"),
            BakeError::Internal(problem) => write!(f, "internal error: {problem}"),
        }
    }
}

impl std::error::Error for BakeError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            BakeError::Io { source, .. } => Some(source),
            BakeError::Babylon(e) => Some(e),
            _ => None,
        }
    }
}

/// A baked mesh: the arrays its `Mesh` static is built from.
#[derive(Clone, Debug)]
pub struct BakedMesh {
    /// The name in the file.
    pub name: String,
    /// The base identifier of its items (without the prefix).
    pub ident: String,
    /// Positions the mesh is built from (dequantized in `i16` mode).
    pub positions: Vec<Vec3>,
    /// Unit normals the mesh is built from (dequantized in `i16` mode).
    pub normals: Vec<Vec3>,
    /// Texture coordinates, if the mesh has them.
    pub uvs: Option<Vec<Vec2>>,
    /// Triangle indices.
    pub indices: Vec<u16>,
    /// The model matrix.
    pub model: Mat4,
    /// Index of its material in [`Baked::materials`].
    pub material: Option<usize>,
    /// The `i16` data and its error, in `i16` mode.
    pub quantized: Option<QuantizedMesh>,
}

/// A baked material.
#[derive(Clone, Debug, PartialEq)]
pub struct BakedMaterial {
    /// The name in the file.
    pub name: String,
    /// The base identifier of its items.
    pub ident: String,
    /// Diffuse color.
    pub color: Rgb888,
    /// Culling.
    pub cull: Cull,
    /// The diffuse texture's file name, as the file gives it.
    pub texture_name: Option<String>,
    /// Index of the baked texture in [`Baked::textures`] (`None` when
    /// textures are not baked).
    pub texture: Option<usize>,
}

/// Texel storage of a baked texture.
#[derive(Clone, Debug, PartialEq)]
pub enum Texels {
    /// RGB565, row-major, first row = top of the image.
    Rgb565(Vec<u16>),
    /// A palette of 256 RGB565 colors and one index per texel (row-major).
    Palette8 {
        /// The palette (unused entries are 0).
        palette: Vec<u16>,
        /// Palette indices.
        indices: Vec<u8>,
    },
}

/// A baked texture.
#[derive(Clone, Debug, PartialEq)]
pub struct BakedTexture {
    /// The name materials use (`diffuseTexture.name`, `map_Kd`).
    pub name: String,
    /// The base identifier of its items.
    pub ident: String,
    /// The file read.
    pub path: PathBuf,
    /// Size of the image file in pixels.
    pub source_size: (u32, u32),
    /// Size baked (powers of two).
    pub size: (u32, u32),
    /// The texels.
    pub texels: Texels,
    /// One alpha byte per texel (0 transparent, 255 opaque), if any pixel
    /// of the image is not opaque.
    pub alpha: Option<Vec<u8>>,
    /// PSNR in dB of the RGB565 texels against the (resized) 8-bit image.
    pub psnr_rgb565: f64,
    /// In `palette8` mode, PSNR in dB of the palette image against the
    /// RGB565 one (infinite when the image has at most 256 RGB565 colors).
    pub psnr_palette: Option<f64>,
}

/// A baked scene, ready to be written as Rust source.
#[derive(Clone, Debug)]
pub struct Baked {
    /// The input's file name (for the header comment).
    pub source: String,
    /// The options used.
    pub options: Options,
    /// The meshes, in file order.
    pub meshes: Vec<BakedMesh>,
    /// The materials, in file order.
    pub materials: Vec<BakedMaterial>,
    /// The textures, in order of first use.
    pub textures: Vec<BakedTexture>,
    /// The active camera, if the file has one.
    pub camera: Option<Camera>,
    /// The lights, if the format has any (`.babylon` always does).
    pub lights: Option<Lights>,
    /// The scene's background color, if given.
    pub clear_color: Option<Rgb888>,
    /// Things the user should know (resized textures, skipped items...).
    pub warnings: Vec<String>,
    /// Every file read (for `cargo:rerun-if-changed`).
    pub inputs: Vec<PathBuf>,
}

impl Baked {
    /// The generated Rust source.
    pub fn to_rust(&self) -> String {
        emit::to_rust(self)
    }

    /// Statistics: sizes, quantization error, texture quality, warnings.
    pub fn report(&self) -> Report {
        report::report(self)
    }
}

/// Bakes a `.babylon` scene given as bytes. Texture names resolve against
/// `options.textures`, or the current directory.
pub fn bake_babylon(json: &[u8], options: &Options) -> Result<Baked, BakeError> {
    let dir = options.textures.clone().unwrap_or_else(|| PathBuf::from("."));
    babylon::bake(json, "scene.babylon", &dir, options)
}

/// Bakes a Wavefront OBJ file (and the MTL files it names). Right-handed
/// OBJ data is mirrored into soft3d's left-handed frame (z negated,
/// winding reversed) and `v` is flipped so that `v = 0` is the top row of
/// the texture.
pub fn bake_obj(path: &Path, options: &Options) -> Result<Baked, BakeError> {
    let dir = texture_dir(path, options);
    obj::bake(path, &dir, options)
}

/// Bakes a file, choosing the format by extension (`.babylon`, `.obj`;
/// otherwise by content: JSON is taken as `.babylon`).
pub fn bake(input: &Path, options: &Options) -> Result<Baked, BakeError> {
    let ext = input.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("obj") => bake_obj(input, options),
        Some("babylon") => bake_babylon_file(input, options),
        _ => {
            let bytes = read(input)?;
            if bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{') {
                bake_babylon_bytes(&bytes, input, options)
            } else {
                Err(BakeError::UnknownFormat(input.to_path_buf()))
            }
        }
    }
}

/// Bakes `input` and writes the Rust source to `output`, leaving the file
/// untouched when its content would not change (so that cargo does not
/// rebuild needlessly). Meant for a firmware crate's `build.rs`.
pub fn bake_file(input: &Path, output: &Path, options: &Options) -> Result<Report, BakeError> {
    let baked = bake(input, options)?;
    let source = baked.to_rust();
    write_if_changed(output, source.as_bytes())?;
    let mut report = baked.report();
    report.output = Some(output.to_path_buf());
    report.source_bytes = source.len();
    Ok(report)
}

fn bake_babylon_file(input: &Path, options: &Options) -> Result<Baked, BakeError> {
    let bytes = read(input)?;
    bake_babylon_bytes(&bytes, input, options)
}

fn bake_babylon_bytes(bytes: &[u8], input: &Path, options: &Options) -> Result<Baked, BakeError> {
    let dir = texture_dir(input, options);
    let name = input.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let mut baked = babylon::bake(bytes, &name, &dir, options)?;
    baked.inputs.insert(0, input.to_path_buf());
    Ok(baked)
}

fn texture_dir(input: &Path, options: &Options) -> PathBuf {
    match &options.textures {
        Some(dir) => dir.clone(),
        None => match input.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        },
    }
}

pub(crate) fn read(path: &Path) -> Result<Vec<u8>, BakeError> {
    std::fs::read(path).map_err(|source| BakeError::Io { path: path.to_path_buf(), source })
}

/// Writes through a temporary file and a rename, so that an interrupted
/// build never leaves half a source file behind.
fn write_if_changed(path: &Path, bytes: &[u8]) -> Result<(), BakeError> {
    if std::fs::read(path).is_ok_and(|old| old == bytes) {
        return Ok(());
    }
    let io = |source| BakeError::Io { path: path.to_path_buf(), source };
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    std::fs::write(&tmp, bytes).map_err(io)?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io(e)
    })
}

/// Checks the prefix and returns it as `PREFIX_` (or empty).
pub(crate) fn normalized_prefix(prefix: &str) -> Result<String, BakeError> {
    if prefix.is_empty() {
        return Ok(String::new());
    }
    let valid = prefix.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && prefix.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !valid {
        return Err(BakeError::Options(format!(
            "prefix '{prefix}' is not an identifier (letters, digits, '_', not starting with a digit)"
        )));
    }
    let p = prefix.to_ascii_uppercase();
    Ok(if p.ends_with('_') { p } else { p + "_" })
}

/// What every format shares after parsing: drops meshes without
/// triangles, validates the rest as the core will, names the items,
/// quantizes and bakes the textures.
pub(crate) fn finish(mut baked: Baked, texture_dir: &Path) -> Result<Baked, BakeError> {
    normalized_prefix(&baked.options.prefix)?;
    let mut meshes = Vec::with_capacity(baked.meshes.len());
    for m in std::mem::take(&mut baked.meshes) {
        if m.indices.is_empty() {
            baked.warnings.push(format!("mesh '{}' has no triangles; skipped", m.name));
            continue;
        }
        // The generated static runs the same check at compile time; failing
        // here gives the reason instead of a const-evaluation panic.
        let mesh = soft3d::mesh::Mesh::new(&m.positions, &m.normals, &m.indices);
        let mesh = match (mesh, &m.uvs) {
            (Ok(mesh), Some(uvs)) => mesh.with_uvs(uvs).map(|_| ()),
            (mesh, _) => mesh.map(|_| ()),
        };
        mesh.map_err(|e| BakeError::Mesh { name: m.name.clone(), problem: e.to_string() })?;
        meshes.push(m);
    }
    baked.meshes = meshes;

    let mut names = names::Names::new();
    for (i, m) in baked.meshes.iter_mut().enumerate() {
        m.ident = names.claim(&m.name, "MESH", i, names::MESH);
    }
    for (i, m) in baked.materials.iter_mut().enumerate() {
        m.ident = names.claim(&m.name, "MATERIAL", i, names::MATERIAL);
    }

    if baked.options.quantize == Quantize::I16 {
        for m in &mut baked.meshes {
            let q = quantize::quantize(&m.name, &m.positions, &m.normals)?;
            m.positions = q.steps.dequantized_positions();
            m.normals = q.steps.dequantized_normals();
            m.quantized = Some(q);
        }
    }

    if baked.options.texture_format != TextureFormat::None {
        for i in 0..baked.materials.len() {
            let Some(name) = baked.materials[i].texture_name.clone() else { continue };
            if let Some(t) = baked.textures.iter().position(|t| t.name == name) {
                baked.materials[i].texture = Some(t);
                continue;
            }
            let path = texture_dir.join(&name);
            let stem = Path::new(&name).file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
            let ident = names.claim(&stem, "TEXTURE", baked.textures.len(), names::TEXTURE);
            let format = baked.options.texture_format;
            let texture = texture::bake(&name, ident, &path, format, baked.options.max_texture_size, &mut baked.warnings)?;
            baked.inputs.push(path);
            baked.materials[i].texture = Some(baked.textures.len());
            baked.textures.push(texture);
        }
    }
    Ok(baked)
}
