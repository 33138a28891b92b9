//! `docs/accuracy.md` and its figures.

use crate::metrics::Errors;
use crate::reference::RefImage;
use crate::render::CoreImages;
use crate::scenes::{HEIGHT, WIDTH};
use crate::{all_keys, backend, Results, CHOICES, CONFIGS};
use embedded_graphics::mono_font::{ascii::FONT_6X10, MonoTextStyle};
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics::text::Text;
use soft3d::host::Image;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// Emulator figures: `(key, scene, core) -> (instructions per frame, checksum)`.
pub type TargetRows = BTreeMap<(String, String, String), (u64, u32)>;

/// The emulator figures and a view of the instruction counts.
pub struct Target {
    /// All rows.
    pub rows: TargetRows,
    /// Instructions only.
    pub instructions: BTreeMap<(String, String, String), u64>,
}

impl Target {
    fn get(&self, key: &(String, String, String)) -> Option<&u64> {
        self.instructions.get(key)
    }
    fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }
}

/// Reads `key,scene,core,instructions,checksum` rows (missing file: no figures).
pub fn read_target(path: &Path) -> Target {
    let mut rows = TargetRows::new();
    if let Ok(text) = std::fs::read_to_string(path) {
        for line in text.lines().skip(1) {
            let f: Vec<&str> = line.split(',').collect();
            if let [key, scene, core, n, crc] = f[..] {
                if let (Ok(n), Ok(crc)) = (n.trim().parse(), u32::from_str_radix(crc.trim(), 16)) {
                    rows.insert((key.into(), scene.into(), core.into()), (n, crc));
                }
            }
        }
    }
    let instructions = rows.iter().map(|(k, v)| (k.clone(), v.0)).collect();
    Target { rows, instructions }
}

/// Host against emulated images.
pub struct Parity {
    /// Frames compared.
    pub compared: usize,
    /// Frames whose checksums differ, described.
    pub mismatches: Vec<String>,
}

/// Scenes loaded from the shared Blender exports (baked for the emulator).
const FILE_SCENES: &[&str] = &["torus", "monkey"];

/// Compares the host's checksums with the emulated targets' for every
/// frame both rendered.
pub fn parity(results: &Results, target: &Target) -> Parity {
    let mut p = Parity { compared: 0, mismatches: Vec::new() };
    for ((key, scene, core), (_, crc)) in &target.rows {
        // The emulator's file scenes are baked at build time by the bake
        // tool, with libm; the host's micromath build loads the files with
        // micromath (normals normalized a few percent off), so those frames
        // differ by construction. Loading is not timed: the times stand.
        if key.ends_with(backend::SUFFIX) && FILE_SCENES.contains(&scene.as_str()) {
            continue;
        }
        let host = results.checksums.iter().find(|((k, s), _)| k == key && s == scene).map(|(_, c)| *c);
        if let Some(host) = host {
            p.compared += 1;
            if host != *crc {
                p.mismatches.push(format!("{key} {scene} on {core}: target {crc:08x}, host {host:08x}"));
            }
        }
    }
    p
}

/// Mean instructions per frame of a configuration over `scenes` on `core`,
/// if every one was measured.
fn time(target: &Target, key: &str, scenes: &[&str], core: &str) -> Option<f64> {
    let v: Option<Vec<u64>> = scenes.iter().map(|s| target.get(&(key.to_string(), s.to_string(), core.to_string())).copied()).collect();
    v.filter(|v| !v.is_empty()).map(|v| v.iter().sum::<u64>() as f64 / v.len() as f64)
}

fn thousands(v: f64) -> String {
    let s = format!("{}", v.round() as u64);
    let mut out = String::new();
    for (i, c) in s.chars().enumerate() {
        if i > 0 && (s.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}

fn psnr(v: f64) -> String {
    if v.is_infinite() {
        "∞".into()
    } else {
        format!("{v:.1}")
    }
}

/// The errors of `key` over `scenes` combined: mean PSNR (identical
/// images counted as 99 dB), worst max and p99, summed pixel counts.
fn combined(results: &Results, key: &str, scenes: &[&str], ideal: bool) -> Option<Errors> {
    let all: Vec<Errors> =
        scenes.iter().filter_map(|s| results.errors.get(&(key, *s)).map(|e| if ideal { e.1 } else { e.0 })).collect::<Vec<_>>();
    // Keys are 'static in the map; look them up by value.
    let all = if all.is_empty() {
        results.errors.iter().filter(|((k, s), _)| *k == key && scenes.contains(s)).map(|(_, e)| if ideal { e.1 } else { e.0 }).collect()
    } else {
        all
    };
    if all.is_empty() {
        return None;
    }
    let n = all.len() as f64;
    let max_opt = |f: fn(&Errors) -> Option<f64>| all.iter().filter_map(f).fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))));
    Some(Errors {
        psnr: all.iter().map(|e| e.psnr.min(99.0)).sum::<f64>() / n,
        max: all.iter().map(|e| e.max).max().unwrap_or(0),
        p99: all.iter().map(|e| e.p99).max().unwrap_or(0),
        mean: all.iter().map(|e| e.mean).sum::<f64>() / n,
        coverage: all.iter().map(|e| e.coverage).sum(),
        depth: all.iter().map(|e| e.depth).sum(),
        uv_max: max_opt(|e| e.uv_max),
        uv_p99: max_opt(|e| e.uv_p99),
        pixels: all.iter().map(|e| e.pixels).sum(),
    })
}

fn uv(v: Option<f64>) -> String {
    v.map_or("–".into(), |v| format!("{v:.3}"))
}

/// Mean host time per frame of a configuration over `scenes`, in
/// milliseconds, if every one was measured.
fn host_ms(results: &Results, key: &str, scenes: &[&str]) -> Option<f64> {
    let v: Option<Vec<f64>> = scenes.iter().map(|s| results.host.get(&(key.to_string(), s.to_string())).copied()).collect();
    v.filter(|v| !v.is_empty()).map(|v| v.iter().sum::<f64>() / v.len() as f64 / 1e6)
}

fn row(label: &str, e: &Errors, ideal: Option<&Errors>, m4f: Option<f64>, m0: Option<f64>, host: Option<f64>) -> String {
    let t = |v: Option<f64>| v.map_or("not measured".into(), thousands);
    let ideal = ideal.map_or(String::new(), |i| format!(" {} / {:.2} |", psnr(i.psnr), i.mean));
    let host = host.map_or("–".into(), |ms| format!("{ms:.2}"));
    format!(
        "| {label} | {} / {:.2} |{ideal} {} / {} | {} | {} | {} | {} | {} | {host} |\n",
        psnr(e.psnr),
        e.mean,
        e.max,
        e.p99,
        e.coverage,
        e.depth,
        uv(e.uv_p99),
        t(m4f),
        t(m0)
    )
}

/// Start and end markers of the per-scene tables that `--check` compares.
const SCENE_BEGIN: &str = "<!-- scene:";
const SCENE_END: &str = "<!-- end scene -->";

/// The per-scene tables of a document whose scene is in `scenes` (all
/// when empty): what `--check` compares (they depend on nothing but the
/// code and the committed emulator figures).
pub fn tables(doc: &str, scenes: &[&str]) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = doc;
    while let Some(i) = rest.find(SCENE_BEGIN) {
        let tail = &rest[i..];
        let end = tail.find(SCENE_END).map_or(tail.len(), |e| e + SCENE_END.len());
        let name = tail[SCENE_BEGIN.len()..].split_whitespace().next().unwrap_or("");
        if scenes.is_empty() || scenes.contains(&name) {
            out.push(tail[..end].to_string());
        }
        rest = &tail[end..];
    }
    out
}

/// Whether two sets of scene tables agree: the same text, but for
/// instruction counts (integers from 10,000 on) within 0.2% of each other.
/// The emulator's counts move with where the linker puts read-only data,
/// which holds the clone's path in panic messages: between two clones of
/// the same commit (`/work/main`, `/tmp/fresh2/main`) by up to 0.016% on
/// the built-in scenes' rows and 0.1% on the files', on both cores. Every
/// other figure must be equal.
pub fn tables_match(a: &[String], b: &[String]) -> bool {
    let count = |c: &str| c.trim().replace(',', "").parse::<u64>().ok().filter(|&n| n >= 10_000);
    let cells_match = |x: &str, y: &str| {
        x == y
            || match (count(x), count(y)) {
                (Some(u), Some(v)) => u.abs_diff(v) as f64 <= 2e-3 * u.max(v) as f64,
                _ => false,
            }
    };
    let lines_match = |x: &str, y: &str| {
        let (cx, cy): (Vec<&str>, Vec<&str>) = (x.split('|').collect(), y.split('|').collect());
        cx.len() == cy.len() && cx.iter().zip(&cy).all(|(u, v)| cells_match(u, v))
    };
    a.len() == b.len()
        && a.iter().zip(b).all(|(x, y)| x.lines().count() == y.lines().count() && x.lines().zip(y.lines()).all(|(u, v)| lines_match(u, v)))
}

/// The document.
pub fn markdown(results: &Results, target: &Target, parity: &Parity, quick: bool) -> String {
    let mut d = String::new();
    let scene_names: Vec<&str> = results.scenes.iter().map(|s| s.0).collect();
    let _ = writeln!(d, "# What accuracy costs\n");
    let _ = writeln!(
        d,
        "Regenerate: `bash scripts/accuracy.sh` (emulator figures into `docs/accuracy/target.csv`, the micromath \
         builds, the math functions per call, `scripts/effects-bench.sh`, the host's `cargo bench --bench study`, \
         then `cargo run --release --manifest-path tools/accuracy/Cargo.toml`, which renders every configuration and \
         rewrites this file and `docs/accuracy/`). `bash scripts/accuracy.sh --quick` checks that the tables of the \
         built-in scenes are current (CI runs it).\n"
    );
    if quick {
        let _ = writeln!(d, "*Quick run: built-in scenes only.*\n");
    }
    for n in &results.notes {
        let _ = writeln!(d, "*{n}*\n");
    }
    let _ = writeln!(d, "{}", recommendation(results, target));
    let _ = writeln!(d, "{}", include_str!("method.md"));
    if parity.compared > 0 {
        let _ = writeln!(
            d,
            "Host and emulated images: the checksums of all {} frames rendered on both (every configuration, scene and \
             core) are equal, except the micromath frames of the file scenes, which are not compared: the emulator's \
             copies of `torus` and `monkey` are baked on the host with libm, while the host's micromath build loads \
             the files with micromath (normals normalized a few percent off). Loading is not timed, so the times \
             stand; the errors are those of a micromath firmware that loads the files itself.\n",
            parity.compared
        );
    }
    for c in CHOICES {
        let scenes: Vec<&str> = c.scenes.iter().copied().filter(|s| scene_names.contains(s)).collect();
        if scenes.is_empty() {
            continue;
        }
        let _ = writeln!(d, "## {}\n\nScenes: {}.\n", c.name, scenes.join(", "));
        let ideal = if c.model { " PSNR / mean vs ideal |" } else { "" };
        let ideal_rule = if c.model { " ---: |" } else { "" };
        let _ = writeln!(
            d,
            "| option | PSNR dB / mean error |{ideal} max / p99 error | coverage px | depth px | UV p99 (texels) | M4F instr / frame | M0+ instr / frame | host ms / frame |"
        );
        let _ = writeln!(d, "| --- | ---: |{ideal_rule} ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
        for (label, key) in c.options {
            let Some(e) = combined(results, key, &scenes, false) else { continue };
            let i = if c.model { combined(results, key, &scenes, true) } else { None };
            let _ = write!(
                d,
                "{}",
                row(
                    label,
                    &e,
                    i.as_ref(),
                    time(target, key, &scenes, "m4f"),
                    time(target, key, &scenes, "m0"),
                    host_ms(results, key, &scenes)
                )
            );
        }
        let _ = writeln!(d);
    }
    let _ = writeln!(d, "{}", functions(results));
    let _ = writeln!(d, "{}", crate::effects::markdown(&results.effects, thousands));
    let _ = writeln!(d, "## Error against time\n");
    if target.is_empty() {
        let _ = writeln!(d, "No emulator figures yet (`docs/accuracy/target.csv` is missing).\n");
    } else {
        let _ = writeln!(
            d,
            "![Mean PSNR against the ideal of the shaded scenes (torus, monkey, floor) against Cortex-M4F instructions per \
             frame, one point per configuration](accuracy/error-vs-time.svg)\n"
        );
    }
    let _ = writeln!(d, "## Artifacts\n\n{}\n", include_str!("artifacts.md"));
    let _ = writeln!(d, "## Per scene\n");
    for (name, about) in &results.scenes {
        let _ = writeln!(d, "{SCENE_BEGIN} {name} -->\n### `{name}`\n\n{about}.\n");
        let _ = writeln!(d, "| configuration | PSNR dB | mean / max / p99 error | coverage px | depth px | UV max / p99 (texels) | PSNR vs ideal | M4F instr / frame | M0+ instr / frame |");
        let _ = writeln!(d, "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
        for key in all_keys() {
            let Some((e, i)) = results.errors.get(&(key, *name)) else { continue };
            let t = |core: &str| {
                target.get(&(key.to_string(), name.to_string(), core.to_string())).map_or("–".into(), |v| thousands(*v as f64))
            };
            let _ = writeln!(
                d,
                "| `{}` | {} | {:.2} / {} / {} | {} | {} | {} / {} | {} | {} | {} |",
                key,
                psnr(e.psnr),
                e.mean,
                e.max,
                e.p99,
                e.coverage,
                e.depth,
                uv(e.uv_max),
                uv(e.uv_p99),
                psnr(i.psnr),
                t("m4f"),
                t("m0")
            );
        }
        let _ = writeln!(d, "\n{SCENE_END}\n");
    }
    d
}

/// What the wide depth formats change on the other scenes: per scene
/// whose frame changes (by checksum), the PSNR with `Depth16` and with
/// `Depth32` (fixed point).
fn depth_elsewhere(results: &Results) -> String {
    let (base, wide) = ("fixed-6-span16-nearest-gouraud", "fixed-6-span16-nearest-gouraud-d32");
    let mut changed = Vec::new();
    let mut compared = 0;
    for (scene, _) in results.scenes.iter().filter(|s| s.0 != "zfight") {
        let sums = (results.checksums.get(&(base, *scene)), results.checksums.get(&(wide, *scene)));
        let (Some(a), Some(b)) = sums else { continue };
        compared += 1;
        if a != b {
            let p = |k| results.errors.get(&(k, *scene)).map_or("?".into(), |e| psnr(e.0.psnr));
            changed.push(format!("`{scene}` ({} → {} dB: its own surfaces nearly touch)", p(base), p(wide)));
        }
    }
    match (compared, changed.is_empty()) {
        (0, _) => String::new(),
        (_, true) => "On the other scenes `Depth32` draws the same frames as `Depth16`.".into(),
        _ => format!("On the other scenes `Depth32` changes {}, the rest not at all.", changed.join(", ")),
    }
}

/// The "which to choose" section, its figures taken from the results.
fn recommendation(results: &Results, target: &Target) -> String {
    let shaded = ["torus", "monkey", "floor"];
    let textured = ["monkey", "floor"];
    let e = |key: &str, scenes: &[&str]| combined(results, key, scenes, false);
    let i = |key: &str, scenes: &[&str]| combined(results, key, scenes, true);
    let t = |key: &str, scenes: &[&str], core: &str| time(target, key, scenes, core);
    let pct = |a: Option<f64>, b: Option<f64>| {
        a.zip(b).map_or("?".into(), |(a, b)| {
            let p = (a / b - 1.0) * 100.0;
            format!("{:.0}% {} instructions", p.abs(), if p < 0.0 { "fewer" } else { "more" })
        })
    };
    let db = |a: Option<Errors>, b: Option<Errors>| a.zip(b).map_or("?".into(), |(a, b)| format!("{:+.1} dB", a.psnr - b.psnr));
    let (fixed, float) = ("fixed-6-span16-nearest-gouraud", "f32-6-span16-nearest-gouraud");
    let mut r = String::from("## Which to choose\n\n");
    let _ = writeln!(
        r,
        "- **Cortex-M0+ (RP2040): `FixedPoint`.** Without an FPU, `f32` interpolation takes {} per frame than fixed \
         point on the shaded scenes.",
        pct(t(float, &shaded, "m0"), t(fixed, &shaded, "m0"))
    );
    // The wording follows the figures: which mode is closer, and whether
    // 16.16's texture coordinates lag behind far down the floor.
    let (closeness, than) = match e(float, &shaded).zip(e(fixed, &shaded)).map(|(a, b)| a.psnr - b.psnr) {
        Some(d) if d >= 0.05 => ("closer to", "than"),
        Some(d) if d <= -0.05 => ("farther from", "than"),
        _ => ("as close to", "as"),
    };
    let (uv_fixed, uv_float) = (e(fixed, &textured).and_then(|e| e.uv_p99), e(float, &textured).and_then(|e| e.uv_p99));
    let texels = match uv_fixed.zip(uv_float) {
        Some((a, b)) if a > b * 1.1 + 0.01 => {
            "16.16, whose texture coordinates divided by a small `1/w` far down the floor move texel edges"
        }
        _ => "16.16, whose texture coordinates keep up far down the floor, its `1/w` carrying 13 more fractional bits",
    };
    let _ = writeln!(
        r,
        "- **Cortex-M4F, M33F (STM32F4, RP2350): `FloatingPoint`.** With an FPU, `f32` takes {} on the shaded \
         scenes and is {closeness} the exact image ({}) {than} {texels} (UV p99 {} against {} texels).",
        pct(t(float, &shaded, "m4f"), t(fixed, &shaded, "m4f")),
        db(e(float, &shaded), e(fixed, &shaded)),
        uv(uv_fixed),
        uv(uv_float)
    );
    let _ = writeln!(
        r,
        "- **Sub-pixel bits: 6, the default of both settings.** Against 4: {}, pixels covered wrongly {} → {}, with {} \
         (M4F); 8 adds {} more but shrinks the guard band to 2,048 pixels (32,768 at 6).",
        db(e("fixed-6-span16-nearest-gouraud", &shaded), e("fixed-4-span16-nearest-gouraud", &shaded)),
        e("fixed-4-span16-nearest-gouraud", &shaded).map_or(0, |e| e.coverage),
        e(fixed, &shaded).map_or(0, |e| e.coverage),
        pct(t(fixed, &shaded, "m4f"), t("fixed-4-span16-nearest-gouraud", &shaded, "m4f")),
        db(e("fixed-8-span16-nearest-gouraud", &shaded), e(fixed, &shaded))
    );
    let _ = writeln!(
        r,
        "- **Perspective: `Affine` for untextured materials (the default), `PerSpan<32>` for textured ones.** On the \
         textured scenes affine mapping is off by {} texels (p99); correction every 32 pixels gains as much as every \
         pixel ({} against {} over affine) with {} than every pixel (M4F, fixed). On the Gouraud torus it gains only \
         {} and takes {}.",
        uv(e("fixed-6-affine-nearest-gouraud", &textured).and_then(|e| e.uv_p99)),
        db(e("fixed-6-span32-nearest-gouraud", &textured), e("fixed-6-affine-nearest-gouraud", &textured)),
        db(e("fixed-6-exact-nearest-gouraud", &textured), e("fixed-6-affine-nearest-gouraud", &textured)),
        pct(t("fixed-6-span32-nearest-gouraud", &textured, "m4f"), t("fixed-6-exact-nearest-gouraud", &textured, "m4f")),
        db(e(fixed, &["torus"]), e("fixed-6-affine-nearest-gouraud", &["torus"])),
        pct(t(fixed, &["torus"], "m4f"), t("fixed-6-affine-nearest-gouraud", &["torus"], "m4f"))
    );
    let _ = writeln!(
        r,
        "- **Texture filter: `Nearest` by default, `Bilinear` where the budget allows**: {} against the ideal, with {} \
         (M4F).",
        db(i("fixed-6-span16-bilinear-gouraud", &textured), i(fixed, &textured)),
        pct(t("fixed-6-span16-bilinear-gouraud", &textured, "m4f"), t(fixed, &textured, "m4f"))
    );
    let _ = writeln!(
        r,
        "- **Lighting: Gouraud; per-pixel `Phong` on an FPU.** Phong is {} closer to the ideal on the torus; in `f32` \
         it takes {} than fixed-point Gouraud (M4F), in fixed point {}.",
        db(i("f32-6-span16-nearest-phong", &["torus"]), i(fixed, &["torus"])),
        pct(t("f32-6-span16-nearest-phong", &["torus"], "m4f"), t(fixed, &["torus"], "m4f")),
        pct(t("fixed-6-span16-nearest-phong", &["torus"], "m4f"), t(fixed, &["torus"], "m4f"))
    );
    let wrong = |key: &str| e(key, &["zfight"]).map_or("?".into(), |e| e.depth.to_string());
    let _ = writeln!(
        r,
        "- **Depth: `Depth16` by default, `Depth32` where distant surfaces nearly touch.** On `zfight` 16 bits show \
         the wrong plane at {} pixels; `Depth32` at {} with fixed-point interpolation (whose depth carries 15 \
         fraction bits) and {} with `f32`, for {} per frame (M4F, fixed) and twice the depth strip's RAM (4 bytes \
         a pixel instead of 2). `DepthF32` orders as `Depth32` does ({} pixels, f32) at the same size. {}",
        wrong(fixed),
        wrong("fixed-6-span16-nearest-gouraud-d32"),
        wrong("f32-6-span16-nearest-gouraud-d32"),
        pct(t("fixed-6-span16-nearest-gouraud-d32", &["zfight"], "m4f"), t(fixed, &["zfight"], "m4f")),
        wrong("f32-6-span16-nearest-gouraud-df32"),
        depth_elsewhere(results),
    );
    let mm = |key: &'static str| backend::twin(key).unwrap_or(key);
    let worst_root = results.functions.iter().filter(|f| f.0.contains("sqrt")).map(|f| f.1 .1).fold(0.0, f64::max);
    let _ = writeln!(
        r,
        "- **Math backend: `libm` (the default).** micromath's functions are bit tricks and short polynomials, off by \
         0.1% (`sin`, `cos`) to {:.1}% (`sqrt`): its `tan` moves the projection ({} pixels covered differently on the \
         shaded scenes) and its roots misnormalize normals. Against libm, fixed-point Gouraud scores {} with {}, \
         `f32` Phong {} with {} (M4F). Its trigonometry is 25 to 50 times cheaper per call on the M4F (libm's runs \
         `f64` steps in software), but the pipeline calls it per draw call, not per vertex.\n",
        worst_root * 100.0,
        e(mm(fixed), &shaded).map_or("?".into(), |e| e.coverage.to_string()),
        db(e(mm(fixed), &shaded), e(fixed, &shaded)),
        pct(t(mm(fixed), &shaded, "m4f"), t(fixed, &shaded, "m4f")),
        db(i(mm("f32-6-span16-nearest-phong"), &shaded), i("f32-6-span16-nearest-phong", &shaded)),
        pct(t(mm("f32-6-span16-nearest-phong"), &shaded, "m4f"), t("f32-6-span16-nearest-phong", &shaded, "m4f")),
    );
    r
}

/// The math functions alone: error and instructions per call.
fn functions(results: &Results) -> String {
    let mut d = String::from("## Math functions\n\n");
    let _ = writeln!(
        d,
        "The functions soft3d takes from its math backend, each alone: largest error over 100,001 arguments against `f64` \
         (relative for the roots and `tan`, absolute for `sin` and `cos`; host), and instructions per call on the \
         emulated cores (`firmware/qemu-bench/src/bin/mathfns.rs`, the call included, the loop subtracted). \
         With `libm`, the roots on the M4F are the FPU's `vsqrt.f32`, the same bits as libm's `sqrtf` (the \
         firmware compares them over 262,144 arguments spanning the `f32` range). \
         `pow` is not among them: highlights use integer powers.\n"
    );
    let _ = writeln!(d, "| function | used for | libm error | micromath error | libm M4F / M0+ instr | micromath M4F / M0+ instr |");
    let _ = writeln!(d, "| --- | --- | ---: | ---: | ---: | ---: |");
    let calls = |name: &str, b: &str| {
        let get = |core: &str| {
            results.calls.get(&(name.to_string(), b.to_string(), core.to_string())).map_or("?".into(), |n| thousands(*n as f64))
        };
        format!("{} / {}", get("m4f"), get("m0"))
    };
    for f in backend::functions() {
        let Some((_, (l, m))) = results.functions.iter().find(|(n, _)| *n == f.name) else { continue };
        let _ = writeln!(
            d,
            "| {} | {} | {:.1e} | {:.1e} | {} | {} |",
            f.name,
            f.used_for,
            l,
            m,
            calls(f.name, "libm"),
            calls(f.name, "micromath")
        );
    }
    d
}

/// Writes the document, the plot and the crops.
pub fn write_all(
    out: &Path,
    doc: &str,
    results: &Results,
    target: &Target,
    images: &BTreeMap<(&'static str, &'static str), CoreImages>,
    references: &BTreeMap<&'static str, BTreeMap<(bool, bool), RefImage>>,
) -> Result<(), String> {
    let dir = out.join("accuracy");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    std::fs::write(out.join("accuracy.md"), doc).map_err(|e| e.to_string())?;
    if !target.is_empty() {
        plot(&dir.join("error-vs-time.svg"), results, target)?;
    }
    crops(&dir, images, references)
}

fn plot(path: &Path, results: &Results, target: &Target) -> Result<(), String> {
    use plotters::prelude::*;
    // The shaded scenes (the depth scene's PSNR is the same for all).
    let scenes: Vec<&str> = results.scenes.iter().map(|s| s.0).filter(|s| crate::SHADED.contains(s)).collect();
    let points: Vec<(f64, f64, &str)> = CONFIGS
        .iter()
        .filter_map(|c| Some((time(target, c.key, &scenes, "m4f")?, combined(results, c.key, &scenes, true)?.psnr, c.key)))
        .collect();
    if points.is_empty() {
        return Ok(());
    }
    let (x0, x1) = points.iter().fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.0), b.max(p.0)));
    let (y0, y1) = points.iter().fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    root.fill(&WHITE).map_err(e)?;
    let mut chart = ChartBuilder::on(&root)
        .caption("Error against time: every configuration, the shaded scenes", ("sans-serif", 20))
        .margin(20)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(x0 * 0.95..x1 * 1.05, (y0 - 1.0)..(y1 + 1.0))
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("Cortex-M4F instructions per frame (mean of the scenes)")
        .y_desc("PSNR against the ideal, dB (higher is better)")
        .draw()
        .map_err(e)?;
    chart.draw_series(points.iter().map(|&(x, y, _)| Circle::new((x, y), 4, BLUE.filled()))).map_err(e)?;
    chart.draw_series(points.iter().map(|&(x, y, k)| Text::new(k.to_string(), (x, y), ("sans-serif", 11).into_font()))).map_err(e)?;
    root.present().map_err(e)?;
    Ok(())
}

/// The window of `w`×`h` pixels where `score` sums highest.
fn worst_window(score: &[f64], w: usize, h: usize) -> (usize, usize) {
    let mut best = (0.0, 0, 0);
    for y in (0..=HEIGHT - h).step_by(4) {
        for x in (0..=WIDTH - w).step_by(4) {
            let s: f64 = (y..y + h).map(|yy| score[yy * WIDTH + x..yy * WIDTH + x + w].iter().sum::<f64>()).sum();
            if s > best.0 {
                best = (s, x, y);
            }
        }
    }
    (best.1, best.2)
}

fn reference_color(r: &RefImage, i: usize) -> Rgb888 {
    let q = |v: f64, max: f64| (v.clamp(0.0, 1.0) * max).round() as u8;
    Rgb888::from(Rgb565::new(q(r.color[i][0], 31.0), q(r.color[i][1], 63.0), q(r.color[i][2], 31.0)))
}

/// A labeled panel of a crop strip: the color of pixel `i` of an image.
type Panel<'a> = (&'a str, Box<dyn Fn(usize) -> Rgb888 + 'a>);

/// Side-by-side crops, three times enlarged, each labeled.
fn strip(path: &Path, panels: &[Panel<'_>], (x0, y0): (usize, usize), (w, h): (usize, usize)) -> Result<(), String> {
    const ZOOM: usize = 3;
    const GAP: usize = 6;
    const LABEL: usize = 14;
    let width = panels.len() * (w * ZOOM + GAP) - GAP;
    let mut img = Image::new(width as u32, (h * ZOOM + LABEL) as u32, Rgb888::WHITE);
    for (k, (label, color)) in panels.iter().enumerate() {
        let left = k * (w * ZOOM + GAP);
        for y in 0..h * ZOOM {
            for x in 0..w * ZOOM {
                let c = color((y0 + y / ZOOM) * WIDTH + x0 + x / ZOOM);
                img.pixels[(LABEL + y) * width + left + x] = c;
            }
        }
        let style = MonoTextStyle::new(&FONT_6X10, Rgb888::BLACK);
        let _ = Text::new(label, Point::new(left as i32 + 2, 10), style).draw(&mut img);
    }
    img.save_png(path).map_err(|e| format!("{}: {e}", path.display()))
}

fn crops(
    dir: &Path,
    images: &BTreeMap<(&'static str, &'static str), CoreImages>,
    references: &BTreeMap<&'static str, BTreeMap<(bool, bool), RefImage>>,
) -> Result<(), String> {
    let core = |key: &str, scene: &str| images.iter().find(|((k, s), _)| *k == key && *s == scene).map(|(_, v)| v);
    let size = (72, 40);
    // Affine swimming: where affine texturing is farthest from the reference.
    if let (Some(affine), Some(span), Some(exact), Some(r)) = (
        core("fixed-6-affine-nearest-gouraud", "floor"),
        core("fixed-6-span16-nearest-gouraud", "floor"),
        core("fixed-6-exact-nearest-gouraud", "floor"),
        references.get("floor").and_then(|m| m.get(&(false, false))),
    ) {
        let score: Vec<f64> = (0..WIDTH * HEIGHT).map(|i| (Rgb888::from(affine.color[i]) != reference_color(r, i)) as u8 as f64).collect();
        let at = worst_window(&score, size.0, size.1);
        strip(
            &dir.join("affine.png"),
            &[
                ("affine", Box::new(|i| Rgb888::from(affine.color[i]))),
                ("every 16 px", Box::new(|i| Rgb888::from(span.color[i]))),
                ("every pixel", Box::new(|i| Rgb888::from(exact.color[i]))),
                ("reference", Box::new(|i| reference_color(r, i))),
            ],
            at,
            size,
        )?;
    }
    // Depth fighting: where the baseline's visible plane is most often wrong.
    if let (Some(fixed), Some(d32), Some(float), Some(r)) = (
        core("fixed-6-span16-nearest-gouraud", "zfight"),
        core("fixed-6-span16-nearest-gouraud-d32", "zfight"),
        core("f32-6-span16-nearest-gouraud-d32", "zfight"),
        references.get("zfight").and_then(|m| m.get(&(false, false))),
    ) {
        // Centered where the reference's planes cross (both in view).
        let crossing = (0..WIDTH * HEIGHT)
            .filter(|&i| i % WIDTH + 1 < WIDTH && r.object[i].is_some() && r.object[i] != r.object[i + 1])
            .collect::<Vec<_>>();
        let at = match crossing.get(crossing.len() / 2) {
            Some(&i) => {
                ((i % WIDTH).saturating_sub(size.0 / 2).min(WIDTH - size.0), (i / WIDTH).saturating_sub(size.1 / 2).min(HEIGHT - size.1))
            }
            None => (0, 0),
        };
        strip(
            &dir.join("depth.png"),
            &[
                ("Depth16, fixed", Box::new(|i| Rgb888::from(fixed.color[i]))),
                ("Depth32, fixed", Box::new(|i| Rgb888::from(d32.color[i]))),
                ("Depth32, f32", Box::new(|i| Rgb888::from(float.color[i]))),
                ("reference", Box::new(|i| reference_color(r, i))),
            ],
            at,
            size,
        )?;
    }
    // Fixed-point texture coordinates far away: where 16.16 misses most.
    if let (Some(fixed), Some(float), Some(r)) = (
        core("fixed-6-span16-nearest-gouraud", "floor"),
        core("f32-6-span16-nearest-gouraud", "floor"),
        references.get("floor").and_then(|m| m.get(&(false, false))),
    ) {
        let score: Vec<f64> = (0..WIDTH * HEIGHT).map(|i| (Rgb888::from(fixed.color[i]) != reference_color(r, i)) as u8 as f64).collect();
        let at = worst_window(&score, size.0, size.1);
        strip(
            &dir.join("fixed.png"),
            &[
                ("fixed 16.16", Box::new(|i| Rgb888::from(fixed.color[i]))),
                ("f32", Box::new(|i| Rgb888::from(float.color[i]))),
                ("reference", Box::new(|i| reference_color(r, i))),
            ],
            at,
            size,
        )?;
    }
    // Sub-pixel precision: where 0 bits moves edges most.
    let scene = if images.keys().any(|(_, s)| *s == "torus") { "torus" } else { "floor" };
    if let (Some(b0), Some(b2), Some(b6), Some(r)) = (
        core("fixed-0-span16-nearest-gouraud", scene),
        core("fixed-2-span16-nearest-gouraud", scene),
        core("fixed-6-span16-nearest-gouraud", scene),
        references.get(scene).and_then(|m| m.get(&(false, false))),
    ) {
        let score: Vec<f64> = (0..WIDTH * HEIGHT).map(|i| (b0.object[i].is_some() != r.object[i].is_some()) as u8 as f64).collect();
        let at = worst_window(&score, size.0, size.1);
        strip(
            &dir.join("subpixel.png"),
            &[
                ("0 sub-pixel bits", Box::new(|i| Rgb888::from(b0.color[i]))),
                ("2 bits", Box::new(|i| Rgb888::from(b2.color[i]))),
                ("6 bits (default)", Box::new(|i| Rgb888::from(b6.color[i]))),
                ("reference", Box::new(|i| reference_color(r, i))),
            ],
            at,
            size,
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_match_but_for_tiny_count_differences() {
        let t = |s: &str| vec![s.to_string()];
        let a = t("| `fixed` | 37.7 | 3,093,360 | 6,213,000 | 9,000 |\n");
        assert!(tables_match(&a, &t("| `fixed` | 37.7 | 3,093,360 | 6,206,000 | 9,000 |\n")));
        assert!(!tables_match(&a, &t("| `fixed` | 37.8 | 3,093,360 | 6,213,000 | 9,000 |\n")));
        assert!(!tables_match(&a, &t("| `fixed` | 37.7 | 3,093,360 | 6,113,000 | 9,000 |\n")));
        // Decimals and small numbers are not counts: equal or not at all.
        assert!(!tables_match(&a, &t("| `fixed` | 37.71 | 3,093,360 | 6,213,000 | 9,000 |\n")));
        assert!(!tables_match(&a, &t("| `fixed` | 37.7 | 3,093,360 | 6,213,000 | 9,001 |\n")));
        assert!(!tables_match(&a, &t("| `f32` | 37.7 | 3,093,360 | 6,213,000 |\n")));
        assert!(!tables_match(&a, &[]));
    }
}
