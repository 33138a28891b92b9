//! `render`: renders a file to PNG through the same pipeline as the firmware.
//!
//! ```text
//! render INPUT -o OUT.png [--size WxH] [--strip N] [--subpixel-bits N]
//!        [--interp fixed|f32] [--effect ...] [--cull none|back]
//!        [--coverage COV.png]                              (.tri input)
//!        [--yaw DEG] [--pitch DEG] [--distance D] [--fov DEG]
//!        [--persp exact|span16|affine] [--filter nearest|bilinear]
//!        [--light file|head] [--frames N] [--spin]         (.babylon input)
//! ```
//! A `.babylon` scene is drawn from its own camera and lights; `--yaw`,
//! `--pitch` and `--distance` orbit the camera around the point it looks
//! at instead (yaw 0 looks along +z, pitch up positive), `--fov` sets the
//! vertical field of view, `--light head` replaces the file's lights by a
//! headlight (ambient 0.15, diffuse 0.85 along the view). Textures named
//! by the materials are read from beside the scene file (PNG or JPEG).
//! `--effect auto` (default) textures the meshes that have a texture and
//! texture coordinates and Gouraud-shades the rest; `gouraud`, `flat` and
//! `phong` (per-pixel Blinn-Phong with the materials' specular color and
//! power) force one effect. `--frames N --spin` renders a turntable of N frames
//! around the vertical axis: into an animated GIF if OUT ends in `.gif`,
//! else into OUT-000.png, OUT-001.png, …
//!
//! A `.tri` file (see `soft3d::tri`) holds triangles in window
//! coordinates that enter the pipeline at triangle assembly. Vertex colors
//! are interpolated perspective-correctly (using `w`) for `unlit` and
//! `gouraud`; `flat` uses each triangle's first color. `--coverage` writes
//! an 8-bit grayscale PNG counting, per pixel, the fragments that covered
//! it before the depth test (saturating at 255).
//!
//! Exit status: 0 on success, 1 for an input error (nothing is written),
//! 2 for a usage error.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::RgbColor;
use soft3d::effect::{Effect, Flat, FragmentCount, VertexColor};
use soft3d::host::{write_png, Image};
use soft3d::material::{DepthOff, PerPixel};
use soft3d::math::Mat4;
use soft3d::math::{Fixed, Interp};
use soft3d::tri::TriVertex;
use soft3d::{Cull, HostRenderer, Lights, Material, Precision, Settings};

mod scene;

struct Options {
    input: String,
    output: String,
    width: usize,
    height: usize,
    strip: Option<usize>,
    subpixel_bits: u32,
    effect: String,
    cull: Cull,
    float: bool,
    coverage: Option<String>,
    scene: scene::SceneOptions,
}

fn main() {
    let opts = parse_args().unwrap_or_else(|e| {
        eprintln!("render: {e}\nusage: render INPUT -o OUT.png [--size WxH] [--strip N] [--subpixel-bits 0..8] [--interp fixed|f32] [--effect unlit|flat|gouraud|auto|phong] [--cull none|back] [--coverage COV.png] [--yaw DEG] [--pitch DEG] [--distance D] [--fov DEG] [--persp exact|span16|affine] [--filter nearest|bilinear] [--light file|head] [--frames N] [--spin]");
        std::process::exit(2)
    });
    if let Err(e) = run(&opts) {
        eprintln!("render: {e}");
        std::process::exit(1)
    }
}

fn parse_args() -> Result<Options, String> {
    let mut o = Options {
        input: String::new(),
        output: String::new(),
        width: 320,
        height: 240,
        strip: None,
        subpixel_bits: <soft3d::FixedPoint as soft3d::Settings>::SUBPIXEL_BITS,
        effect: "unlit".into(),
        cull: Cull::None,
        float: false,
        coverage: None,
        scene: scene::SceneOptions::default(),
    };
    let mut effect_given = false;
    let mut args = std::env::args().skip(1);
    let value = |args: &mut dyn Iterator<Item = String>, flag: &str| args.next().ok_or(format!("{flag} needs a value"));
    while let Some(a) = args.next() {
        match a.as_str() {
            "-o" | "--output" => o.output = value(&mut args, &a)?,
            "--size" => {
                let v = value(&mut args, &a)?;
                let (w, h) = v.split_once(['x', 'X']).ok_or(format!("--size {v}: expected WxH"))?;
                o.width = w.parse().map_err(|_| format!("--size {v}: bad width"))?;
                o.height = h.parse().map_err(|_| format!("--size {v}: bad height"))?;
            }
            "--strip" => o.strip = Some(value(&mut args, &a)?.parse().map_err(|_| "--strip: expected a number of rows")?),
            "--subpixel-bits" => o.subpixel_bits = value(&mut args, &a)?.parse().map_err(|_| "--subpixel-bits: expected 0 to 8")?,
            "--effect" => {
                o.effect = value(&mut args, &a)?;
                effect_given = true;
            }
            "--cull" => {
                o.cull = match value(&mut args, &a)?.as_str() {
                    "none" => Cull::None,
                    "back" => Cull::Back,
                    v => return Err(format!("--cull {v}: expected none or back")),
                }
            }
            "--interp" => {
                o.float = match value(&mut args, &a)?.as_str() {
                    "fixed" => false,
                    "f32" => true,
                    v => return Err(format!("--interp {v}: expected fixed or f32")),
                }
            }
            "--coverage" => o.coverage = Some(value(&mut args, &a)?),
            "--yaw" | "--pitch" | "--distance" | "--fov" | "--persp" | "--filter" | "--light" | "--frames" => {
                let v = value(&mut args, &a)?;
                o.scene.set(&a, &v)?;
            }
            "--spin" => o.scene.spin = true,
            s if s.starts_with('-') => return Err(format!("unknown option {s}")),
            s if o.input.is_empty() => o.input = s.to_string(),
            s => return Err(format!("unexpected argument {s}")),
        }
    }
    if o.input.is_empty() || o.output.is_empty() {
        return Err("need INPUT and -o OUT.png".into());
    }
    if o.subpixel_bits > 8 {
        return Err("--subpixel-bits must be 0 to 8".into());
    }
    if o.input.ends_with(".babylon") {
        if !effect_given {
            o.effect = "auto".into();
        }
        if !["auto", "flat", "gouraud", "phong"].contains(&o.effect.as_str()) {
            return Err(format!("--effect {}: expected auto, flat, gouraud or phong for a scene", o.effect));
        }
        if o.coverage.is_some() {
            return Err("--coverage is only for .tri input".into());
        }
    } else if !["unlit", "flat", "gouraud"].contains(&o.effect.as_str()) {
        return Err(format!("--effect {}: expected unlit, flat or gouraud", o.effect));
    }
    if o.width == 0 || o.height == 0 || o.width > 16384 || o.height > 16384 {
        return Err("--size must be between 1x1 and 16384x16384".into());
    }
    if o.strip.is_some_and(|s| s == 0) {
        return Err("--strip must be at least 1".into());
    }
    Ok(o)
}

fn run(o: &Options) -> Result<(), String> {
    if o.input.ends_with(".babylon") {
        return scene::run(o);
    }
    if !o.input.ends_with(".tri") {
        return Err(format!("{}: unsupported input (expected a .tri or .babylon file)", o.input));
    }
    let text = std::fs::read_to_string(&o.input).map_err(|e| format!("{}: {e}", o.input))?;
    let tris: Vec<[TriVertex; 3]> = soft3d::tri::parse(&text).collect::<Result<_, _>>().map_err(|e| format!("{}: {e}", o.input))?;
    // One generic renderer per sub-pixel setting and scalar: both are
    // compile-time choices in the library.
    macro_rules! dispatch {
        ($($b:literal)*) => {
            match (o.subpixel_bits, o.float) {
                $(($b, false) => render::<Precision<Fixed, $b>>(o, &tris),
                  ($b, true) => render::<Precision<f32, $b>>(o, &tris),)*
                _ => unreachable!("checked in parse_args"),
            }
        };
    }
    dispatch!(0 1 2 3 4 5 6 7 8)
}

/// Renders `tris` with one effect, in one frame.
fn draw<S: Settings, E: Effect, P: soft3d::material::Perspective, D: soft3d::material::DepthMode>(
    o: &Options,
    tris: &[[TriVertex; 3]],
    material: &Material<E, P, D>,
) -> Result<Image<Rgb888>, String> {
    let strip = o.strip.unwrap_or(16).min(o.height);
    // Guard-band clipping can turn one triangle into a fan of up to seven.
    let verts = (tris.len() * 9 + 3).min(65534);
    let queued = (tris.len() * 7 + 1).min(65534);
    let mut renderer: HostRenderer<Rgb888, 3, S> =
        HostRenderer::new(o.width, o.height, strip, verts, queued, Rgb888::BLACK).map_err(|e| e.to_string())?;
    let mut frame = renderer.begin_frame_with(Mat4::IDENTITY, &Lights::UNLIT, Rgb888::BLACK);
    frame.draw_window_triangles(tris.iter().copied(), material).map_err(|e| format!("{}: {e}", o.input))?;
    let mut image = Image::new(o.width as u32, o.height as u32, Rgb888::BLACK);
    let Ok(_) = frame.finish(&mut image);
    Ok(image)
}

fn render<S: Settings>(o: &Options, tris: &[[TriVertex; 3]]) -> Result<(), String>
where
    S::Interp: Interp,
{
    let image = match o.effect.as_str() {
        "flat" => draw::<S, _, _, _>(o, tris, &Material::new(Flat).with_cull(o.cull))?,
        _ => draw::<S, _, _, _>(o, tris, &Material::new(VertexColor).with_cull(o.cull).with_perspective::<PerPixel>())?,
    };
    let coverage = match &o.coverage {
        Some(_) => Some(draw::<S, _, _, _>(o, tris, &Material::new(FragmentCount).with_cull(o.cull).with_depth::<DepthOff>())?),
        None => None,
    };
    image.save_png(&o.output).map_err(|e| format!("{}: {e}", o.output))?;
    if let (Some(path), Some(cov)) = (&o.coverage, coverage) {
        let gray: Vec<u8> = cov.pixels.iter().map(|c| c.r()).collect();
        write_png(path.as_ref(), cov.width, cov.height, png::ColorType::Grayscale, &gray).map_err(|e| format!("{path}: {e}"))?;
    }
    Ok(())
}
