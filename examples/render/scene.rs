//! The `.babylon` half of `render`: camera and light overrides, effect,
//! perspective and filter choices, turntables.

use super::Options;
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::RgbColor;
use soft3d::host::scene::{EffectChoice, HostScene};
use soft3d::host::{GifRecorder, Image};
use soft3d::material::{Affine, PerPixel, PerSpan, Perspective};
use soft3d::math::{Fixed, Mat4, Vec3};
use soft3d::texture::{Bilinear, Filter, Nearest, Repeat};
use soft3d::{Camera, HostRenderer, Precision, Settings};

/// Options that only apply to scenes.
#[derive(Default)]
pub struct SceneOptions {
    yaw: Option<f32>,
    pitch: Option<f32>,
    distance: Option<f32>,
    fov: Option<f32>,
    persp: Persp,
    bilinear: bool,
    headlight: bool,
    frames: Option<usize>,
    pub spin: bool,
}

#[derive(Default, Clone, Copy)]
enum Persp {
    #[default]
    Exact,
    Span16,
    Affine,
}

impl SceneOptions {
    /// Sets one option from its flag and value.
    pub fn set(&mut self, flag: &str, v: &str) -> Result<(), String> {
        let num = |what: &str| v.parse::<f32>().ok().filter(|x| x.is_finite()).ok_or(format!("{flag} {v}: expected {what}"));
        match flag {
            "--yaw" => self.yaw = Some(num("degrees")?),
            "--pitch" => self.pitch = Some(num("degrees")?.clamp(-89.0, 89.0)),
            "--distance" => {
                self.distance = Some(num("a distance").and_then(|d| if d > 0.0 { Ok(d) } else { Err("--distance must be > 0".into()) })?)
            }
            "--fov" => {
                self.fov =
                    Some(
                        num("degrees")
                            .and_then(|d| if d > 0.5 && d < 179.0 { Ok(d) } else { Err("--fov must be in (0.5, 179)".into()) })?,
                    )
            }
            "--persp" => {
                self.persp = match v {
                    "exact" => Persp::Exact,
                    "span16" => Persp::Span16,
                    "affine" => Persp::Affine,
                    _ => return Err(format!("--persp {v}: expected exact, span16 or affine")),
                }
            }
            "--filter" => {
                self.bilinear = match v {
                    "nearest" => false,
                    "bilinear" => true,
                    _ => return Err(format!("--filter {v}: expected nearest or bilinear")),
                }
            }
            "--light" => {
                self.headlight = match v {
                    "file" => false,
                    "head" => true,
                    _ => return Err(format!("--light {v}: expected file or head")),
                }
            }
            "--frames" => {
                let n: usize = v.parse().map_err(|_| format!("--frames {v}: expected a count"))?;
                if !(1..=3600).contains(&n) {
                    return Err("--frames must be 1 to 3600".into());
                }
                self.frames = Some(n);
            }
            _ => return Err(format!("unknown option {flag}")),
        }
        Ok(())
    }

    /// The file's camera with the orbit overrides applied.
    fn camera(&self, scene: &HostScene) -> Camera {
        let mut c = scene.camera_or_default();
        let d = c.position - c.target;
        let dist = d.length().max(1e-6);
        let yaw = self.yaw.map_or(d.x.atan2(-d.z), f32::to_radians);
        let pitch = self.pitch.map_or((d.y / dist).clamp(-1.0, 1.0).asin(), f32::to_radians);
        let dist = self.distance.unwrap_or(dist);
        if self.yaw.is_some() || self.pitch.is_some() || self.distance.is_some() {
            let dir = Vec3::new(pitch.cos() * yaw.sin(), pitch.sin(), -pitch.cos() * yaw.cos());
            c.position = c.target + dir * dist;
            c.up = Vec3::new(0.0, 1.0, 0.0);
        }
        if let Some(f) = self.fov {
            c.fov_y = f.to_radians();
        }
        c
    }
}

pub fn run(o: &Options) -> Result<(), String> {
    let scene = HostScene::load(&o.input).map_err(|e| e.to_string())?;
    for w in &scene.warnings {
        eprintln!("render: warning: {w}");
    }
    macro_rules! dispatch {
        ($($b:literal)*) => {
            match (o.subpixel_bits, o.float) {
                $(($b, false) => by_persp::<Precision<Fixed, $b>>(o, &scene),
                  ($b, true) => by_persp::<Precision<f32, $b>>(o, &scene),)*
                (b, _) => Err(format!("--subpixel-bits {b}: scenes support 0, 2, 4, 6 or 8")),
            }
        };
    }
    dispatch!(0 2 4 6 8)
}

fn by_persp<S: Settings>(o: &Options, scene: &HostScene) -> Result<(), String> {
    match (o.scene.persp, o.scene.bilinear) {
        (Persp::Exact, false) => frames::<S, PerPixel, Nearest>(o, scene),
        (Persp::Exact, true) => frames::<S, PerPixel, Bilinear>(o, scene),
        (Persp::Span16, false) => frames::<S, PerSpan<16>, Nearest>(o, scene),
        (Persp::Span16, true) => frames::<S, PerSpan<16>, Bilinear>(o, scene),
        (Persp::Affine, false) => frames::<S, Affine, Nearest>(o, scene),
        (Persp::Affine, true) => frames::<S, Affine, Bilinear>(o, scene),
    }
}

fn frames<S: Settings, P: Perspective, F: Filter>(o: &Options, scene: &HostScene) -> Result<(), String> {
    let choice = match o.effect.as_str() {
        "flat" => EffectChoice::Flat,
        "gouraud" => EffectChoice::Gouraud,
        "phong" => EffectChoice::Phong,
        _ => EffectChoice::Auto,
    };
    let materials = scene.materials::<F, Repeat, P>(choice);
    let camera = o.scene.camera(scene);
    let lights = if o.scene.headlight { HostScene::headlight(&camera) } else { scene.lights };
    let vertices: usize = scene.meshes.iter().map(|m| m.positions.len()).sum();
    let triangles: usize = scene.meshes.iter().map(|m| m.indices.len() / 3).sum();
    let strip = o.strip.unwrap_or(16).min(o.height);
    let mut renderer: HostRenderer<Rgb888, 6, S> =
        HostRenderer::new(o.width, o.height, strip, (vertices + 4096).min(65534), (2 * triangles + 1024).min(65534), Rgb888::BLACK)
            .map_err(|e| e.to_string())?;
    let n = o.scene.frames.unwrap_or(1);
    let center = scene.bounds().center;
    let gif = o.output.ends_with(".gif");
    let mut recorder = GifRecorder::new(o.width as u32, o.height as u32, 4);
    for i in 0..n {
        let angle = if o.scene.spin { i as f32 / n as f32 * core::f32::consts::TAU } else { 0.0 };
        let spin = Mat4::translation(center) * Mat4::rotation_y(angle) * Mat4::translation(-center);
        let mut frame = renderer.begin_frame(&camera, &lights, Rgb888::new(16, 16, 24));
        scene.draw(&mut frame, &materials, &spin).map_err(|e| format!("{}: {e}", o.input))?;
        let mut image = Image::new(o.width as u32, o.height as u32, Rgb888::BLACK);
        let Ok(_) = frame.finish(&mut image);
        if gif {
            recorder.push(&image);
        } else {
            let path = if n == 1 { o.output.clone() } else { numbered(&o.output, i) };
            image.save_png(&path).map_err(|e| format!("{path}: {e}"))?;
        }
    }
    if gif {
        recorder.save(&o.output).map_err(|e| format!("{}: {e}", o.output))?;
    }
    Ok(())
}

/// `out.png` → `out-007.png`.
fn numbered(path: &str, i: usize) -> String {
    match path.rsplit_once('.') {
        Some((stem, ext)) => format!("{stem}-{i:03}.{ext}"),
        None => format!("{path}-{i:03}"),
    }
}
