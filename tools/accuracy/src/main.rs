//! The accuracy study: every precision choice of soft3d rendered against
//! an exact `f64` reference, with its measured cost, written to
//! `docs/accuracy.md`.
//!
//! ```sh
//! bash scripts/accuracy.sh            # everything: emulator figures, then this tool
//! cargo run --release --manifest-path tools/accuracy/Cargo.toml -- [--quick] [--check] [--assets DIR] [--out DIR] [--target CSV]
//! ```
//!
//! `--quick` renders only the built-in scenes; `--check` writes nothing
//! and fails if `docs/accuracy.md` differs from what it would write.
//! Built with `--no-default-features --features micromath`, the tool
//! renders the math-backend configurations only and writes their errors to
//! the `--micromath` CSV (see `backend.rs`).

mod backend;
mod effects;
mod host_time;
mod metrics;
mod reference;
mod render;
mod report;
mod scenes;

use metrics::Errors;
use reference::{RefFilter, RefImage, RefShading};
use render::CoreImages;
use scenes::Scene;
use soft3d::material::{Affine, PerPixel, PerSpan};
use soft3d::math::Fixed;
use soft3d::texture::{Bilinear, Nearest};
use soft3d::{Depth16, Depth32, DepthF32, Precision};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::ExitCode;

/// One combination of the precision choices.
#[derive(Clone, Copy)]
pub struct Config {
    /// Stable key, joined with the emulator's figures.
    pub key: &'static str,
    /// Interpolation scalar.
    pub interp: &'static str,
    /// Sub-pixel bits.
    pub bits: u32,
    /// Perspective mode.
    pub perspective: &'static str,
    /// Texture filter.
    pub filter: RefFilter,
    /// Per-pixel lighting for untextured objects.
    pub phong: bool,
    render: fn(&Scene, bool) -> CoreImages,
}

/// Expands the shared list (`configs.rs`) into [`CONFIGS`].
macro_rules! study_configs {
    ($(($key:literal, $interp:literal, $scalar:ty, $bits:literal, $persp:literal, $p:ty, $filter:ident, $phong:literal, $z:ident)),* $(,)?) => {
        /// Every configuration the study renders (`configs.rs`); the first
        /// is the baseline, the crate's defaults: `FixedPoint` (16.16, 6
        /// sub-pixel bits), exact perspective every 16 pixels, nearest
        /// texels, Gouraud.
        pub const CONFIGS: &[Config] = &[$(
            Config {
                key: $key,
                interp: $interp,
                bits: $bits,
                perspective: $persp,
                filter: RefFilter::$filter,
                phong: $phong,
                render: render::render::<Precision<$scalar, $bits, $z>, $p, $filter>,
            }
        ),*];
    };
}

include!("../configs.rs");

/// A question the study answers: one choice, its options (keys into
/// [`CONFIGS`]), each differing from the baseline in that choice only.
pub struct Choice {
    /// Title.
    pub name: &'static str,
    /// Which scenes show it (others do not change).
    pub scenes: &'static [&'static str],
    /// Option label and configuration key.
    pub options: &'static [(&'static str, &'static str)],
    /// Whether the options change the shading model (then errors are also
    /// given against the ideal: per-pixel lighting, bilinear texels).
    pub model: bool,
}

/// Scenes whose shading the choices change (the planes of `zfight` only
/// test depth).
pub const SHADED: &[&str] = &["torus", "monkey", "floor"];

/// The choices, each alone against the baseline, then combinations.
pub const CHOICES: &[Choice] = &[
    Choice {
        name: "Interpolation scalar",
        scenes: SHADED,
        options: &[("fixed 16.16", "fixed-6-span16-nearest-gouraud"), ("f32", "f32-6-span16-nearest-gouraud")],
        model: false,
    },
    Choice {
        name: "Sub-pixel bits",
        scenes: SHADED,
        options: &[
            ("0", "fixed-0-span16-nearest-gouraud"),
            ("2", "fixed-2-span16-nearest-gouraud"),
            ("4", "fixed-4-span16-nearest-gouraud"),
            ("6 (default)", "fixed-6-span16-nearest-gouraud"),
            ("8", "fixed-8-span16-nearest-gouraud"),
        ],
        model: false,
    },
    Choice {
        name: "Perspective correction",
        scenes: SHADED,
        options: &[
            ("fixed, affine", "fixed-6-affine-nearest-gouraud"),
            ("fixed, every 32 px", "fixed-6-span32-nearest-gouraud"),
            ("fixed, every 16 px", "fixed-6-span16-nearest-gouraud"),
            ("fixed, every 8 px", "fixed-6-span8-nearest-gouraud"),
            ("fixed, every pixel", "fixed-6-exact-nearest-gouraud"),
            ("f32, affine", "f32-6-affine-nearest-gouraud"),
            ("f32, every 32 px", "f32-6-span32-nearest-gouraud"),
            ("f32, every 16 px", "f32-6-span16-nearest-gouraud"),
            ("f32, every pixel", "f32-6-exact-nearest-gouraud"),
        ],
        model: false,
    },
    Choice {
        name: "Texture filter",
        scenes: &["monkey", "floor"],
        options: &[("nearest", "fixed-6-span16-nearest-gouraud"), ("bilinear", "fixed-6-span16-bilinear-gouraud")],
        model: true,
    },
    Choice {
        name: "Lighting",
        scenes: &["torus"],
        options: &[
            ("fixed, Gouraud (per vertex)", "fixed-6-span16-nearest-gouraud"),
            ("fixed, Phong (per pixel)", "fixed-6-span16-nearest-phong"),
            ("f32, Phong (per pixel)", "f32-6-span16-nearest-phong"),
        ],
        model: true,
    },
    Choice {
        name: "Depth",
        scenes: &["zfight"],
        options: &[
            ("16-bit, fixed (default)", "fixed-6-span16-nearest-gouraud"),
            ("32-bit (16.16 units), fixed", "fixed-6-span16-nearest-gouraud-d32"),
            ("16-bit, f32", "f32-6-span16-nearest-gouraud"),
            ("32-bit (16.16 units), f32", "f32-6-span16-nearest-gouraud-d32"),
            ("f32 depth, f32", "f32-6-span16-nearest-gouraud-df32"),
        ],
        model: false,
    },
    Choice {
        name: "Math backend",
        scenes: SHADED,
        options: &[
            ("libm, fixed, Gouraud (default)", "fixed-6-span16-nearest-gouraud"),
            ("micromath, fixed, Gouraud", "fixed-6-span16-nearest-gouraud+micromath"),
            ("libm, f32, Gouraud", "f32-6-span16-nearest-gouraud"),
            ("micromath, f32, Gouraud", "f32-6-span16-nearest-gouraud+micromath"),
            ("libm, f32, Phong", "f32-6-span16-nearest-phong"),
            ("micromath, f32, Phong", "f32-6-span16-nearest-phong+micromath"),
        ],
        model: true,
    },
    Choice {
        name: "Combinations",
        scenes: SHADED,
        options: &[
            ("cheapest: fixed, affine, nearest, Gouraud", "fixed-6-affine-nearest-gouraud"),
            ("f32, affine, nearest, Gouraud", "f32-6-affine-nearest-gouraud"),
            ("baseline: fixed, every 16 px, nearest, Gouraud", "fixed-6-span16-nearest-gouraud"),
            ("f32, every 32 px, bilinear, Gouraud", "f32-6-span32-bilinear-gouraud"),
            ("fixed, 8 bits, every pixel, bilinear, Gouraud", "fixed-8-exact-bilinear-gouraud"),
            ("fixed, affine, nearest, Phong", "fixed-6-affine-nearest-phong"),
            ("best: f32, 8 bits, every pixel, bilinear, Phong", "f32-8-exact-bilinear-phong"),
        ],
        model: true,
    },
];

/// Results: per configuration key and scene, the errors against the
/// reference of the same shading model and against the ideal.
pub struct Results {
    /// `(key, scene) -> (same model, ideal)`.
    pub errors: BTreeMap<(&'static str, &'static str), (Errors, Errors)>,
    /// Scene names and descriptions, in order.
    pub scenes: Vec<(&'static str, &'static str)>,
    /// Notes (skipped scenes).
    pub notes: Vec<String>,
    /// Checksum of each color image (`soft3d::scenes::FrameChecksum`), to
    /// compare with the emulated targets'.
    pub checksums: BTreeMap<(&'static str, &'static str), u32>,
    /// Each backend function's largest error: `(libm, micromath)`.
    pub functions: Vec<(&'static str, (f64, f64))>,
    /// Instructions per call on the emulated cores: `(function, backend, core)`.
    pub calls: BTreeMap<(String, String, String), u32>,
    /// Host nanoseconds per frame (`benches/study.rs`): `(key, scene)`.
    pub host: host_time::HostTimes,
    /// The effects benchmark (`scripts/effects-bench.sh`).
    pub effects: Vec<effects::Row>,
}

/// Every configuration key: the study's, then the micromath twins.
pub fn all_keys() -> impl Iterator<Item = &'static str> {
    CONFIGS.iter().map(|c| c.key).chain(backend::PAIRS.iter().map(|p| p.1))
}

/// The benchmark's frame checksum of an image.
fn checksum(pixels: &[embedded_graphics::pixelcolor::Rgb565]) -> u32 {
    use embedded_graphics::pixelcolor::Rgb565;
    use embedded_graphics::prelude::*;
    let mut sink = soft3d::scenes::FrameChecksum::new(scenes::WIDTH as u32, scenes::HEIGHT as u32, Rgb565::BLACK);
    let area = embedded_graphics::primitives::Rectangle::new(Point::zero(), sink.size());
    let Ok(()) = sink.fill_contiguous(&area, pixels.iter().copied());
    sink.sum
}

struct Args {
    quick: bool,
    check: bool,
    assets: PathBuf,
    out: PathBuf,
    target: PathBuf,
    micromath: PathBuf,
    calls: PathBuf,
    criterion: Option<PathBuf>,
}

fn parse_args() -> Result<Args, String> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut a = Args {
        quick: false,
        check: false,
        assets: root.join("../shared/assets"),
        out: root.join("docs"),
        target: root.join("docs/accuracy/target.csv"),
        micromath: root.join("docs/accuracy/micromath.csv"),
        calls: root.join("docs/accuracy/mathfns.csv"),
        criterion: None,
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().ok_or_else(|| format!("{name} needs a value"));
        match arg.as_str() {
            "--quick" => a.quick = true,
            "--check" => a.check = true,
            "--assets" => a.assets = PathBuf::from(value("--assets")?),
            "--out" => a.out = PathBuf::from(value("--out")?),
            "--target" => a.target = PathBuf::from(value("--target")?),
            "--micromath" => a.micromath = PathBuf::from(value("--micromath")?),
            "--calls" => a.calls = PathBuf::from(value("--calls")?),
            "--criterion" => a.criterion = Some(PathBuf::from(value("--criterion")?)),
            other => return Err(format!("unknown option {other}")),
        }
    }
    Ok(a)
}

/// Host times: fresh from criterion's output with `--criterion DIR` (and
/// then written to `docs/accuracy/host.csv`), else the committed CSV.
fn host_times(args: &Args) -> host_time::HostTimes {
    let csv = args.out.join("accuracy/host.csv");
    let Some(dir) = &args.criterion else { return host_time::read_csv(&csv) };
    let mut times = host_time::from_criterion(dir);
    // Keys no longer studied may linger in criterion's directory.
    times.retain(|(key, _), _| CONFIGS.iter().any(|c| c.key == key));
    if !args.check {
        if let Err(e) = host_time::write_csv(&csv, &times) {
            eprintln!("accuracy: {e}");
        }
    }
    times
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("accuracy: {e}");
            return ExitCode::from(2);
        }
    };
    let mut notes = Vec::new();
    let mut scenes = scenes::all(&args.assets, &mut notes);
    if args.quick {
        scenes.retain(|s| s.name == "floor" || s.name == "zfight");
        notes.push("quick mode: built-in scenes only".into());
    }
    for n in &notes {
        eprintln!("{n}");
    }
    let mut errors = BTreeMap::new();
    let mut checksums = BTreeMap::new();
    let mut images: BTreeMap<(&'static str, &'static str), CoreImages> = BTreeMap::new();
    let mut references: BTreeMap<&'static str, BTreeMap<(bool, bool), RefImage>> = BTreeMap::new();
    for scene in &scenes {
        let r = scene.reference();
        let refs = references.entry(scene.name).or_default();
        for phong in [false, true] {
            for bilinear in [false, true] {
                let shading = if phong { RefShading::Phong } else { RefShading::Gouraud };
                let filter = if bilinear { RefFilter::Bilinear } else { RefFilter::Nearest };
                refs.insert((phong, bilinear), r.render(shading, filter));
            }
        }
        let wrap = scene.textures.iter().map(|t| (t.width as f64, t.height as f64)).next();
        // The micromath build renders the math-backend configurations only.
        for c in CONFIGS.iter().filter(|c| !backend::MICROMATH || backend::twin(c.key).is_some()) {
            let img = (c.render)(scene, c.phong);
            let same = &refs[&(c.phong, c.filter == RefFilter::Bilinear)];
            let ideal = &refs[&(true, true)];
            errors.insert((c.key, scene.name), (metrics::compare(&img, same, wrap), metrics::compare(&img, ideal, wrap)));
            checksums.insert((c.key, scene.name), checksum(&img.color));
            images.insert((c.key, scene.name), img);
        }
        eprintln!("{}: {} configurations", scene.name, CONFIGS.len());
    }
    if backend::MICROMATH {
        let rows: Vec<backend::Row> = errors
            .iter()
            .filter_map(|(&(key, scene), &e)| {
                Some(backend::Row { key: backend::twin(key)?, scene: scene.into(), errors: e, checksum: checksums[&(key, scene)] })
            })
            .collect();
        return match backend::write(&args.micromath, &rows) {
            Ok(()) => {
                eprintln!("accuracy: wrote {} (micromath)", args.micromath.display());
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("accuracy: {e}");
                ExitCode::FAILURE
            }
        };
    }
    // The micromath twins, from the micromath build's CSV.
    let mut missing = 0;
    for row in backend::read(&args.micromath) {
        match scenes.iter().find(|s| s.name == row.scene) {
            Some(s) => {
                errors.insert((row.key, s.name), row.errors);
                checksums.insert((row.key, s.name), row.checksum);
            }
            None => missing += 1,
        }
    }
    if missing > 0 {
        eprintln!("accuracy: {missing} micromath rows for scenes not rendered here, ignored");
    }
    let results = Results {
        errors,
        scenes: scenes.iter().map(|s| (s.name, s.about)).collect(),
        notes,
        checksums,
        functions: backend::function_errors(),
        calls: backend::read_calls(&args.calls),
        host: host_times(&args),
        effects: effects::read(&args.out.join("accuracy/effects.csv")),
    };
    let target = report::read_target(&args.target);
    let parity = report::parity(&results, &target);
    for line in &parity.mismatches {
        eprintln!("accuracy: {line}");
    }
    if !parity.mismatches.is_empty() {
        eprintln!("accuracy: host and emulated images differ ({} frames)", parity.mismatches.len());
        return ExitCode::FAILURE;
    }
    let doc = report::markdown(&results, &target, &parity, args.quick);
    let path = args.out.join("accuracy.md");
    if args.check {
        let old = std::fs::read_to_string(&path).unwrap_or_default();
        let names: Vec<&str> = results.scenes.iter().map(|s| s.0).collect();
        if !report::tables_match(&report::tables(&old, &names), &report::tables(&doc, &names)) {
            eprintln!("accuracy: {} is not current; run bash scripts/accuracy.sh", path.display());
            return ExitCode::FAILURE;
        }
        eprintln!("accuracy: {} is current", path.display());
        return ExitCode::SUCCESS;
    }
    if let Err(e) = report::write_all(&args.out, &doc, &results, &target, &images, &references) {
        eprintln!("accuracy: {e}");
        return ExitCode::FAILURE;
    }
    eprintln!("accuracy: wrote {}", path.display());
    ExitCode::SUCCESS
}
