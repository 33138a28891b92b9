//! The math backend choice: soft3d's elementary functions from `libm`
//! (exact, the default) or `micromath` (fast approximations).
//!
//! A backend is a cargo feature of the whole crate, so one build of this
//! tool renders with one backend. `scripts/accuracy.sh` builds it a second
//! time with `--no-default-features --features micromath`: that build
//! renders the configurations of [`PAIRS`] and writes their errors to a CSV
//! ([`write`]), which the default build reads back ([`read`]) as the
//! configurations' `+micromath` twins. The emulated study does the same
//! (`firmware/qemu-bench/src/bin/study.rs`, keys suffixed `+micromath`).
//!
//! Each function is also measured alone: its error here against `f64`
//! ([`function_errors`]), its instructions per call on the emulated cores
//! (`firmware/qemu-bench/src/bin/mathfns.rs`, read by [`read_calls`]).

use crate::metrics::Errors;
use std::collections::BTreeMap;
use std::path::Path;

/// Appended to a configuration's key for its micromath twin.
pub const SUFFIX: &str = "+micromath";

/// Whether this build renders with micromath.
pub const MICROMATH: bool = cfg!(not(feature = "libm"));

/// The configurations rendered with both backends, and their twins' keys.
pub const PAIRS: &[(&str, &str)] = &[
    ("fixed-6-span16-nearest-gouraud", "fixed-6-span16-nearest-gouraud+micromath"),
    ("f32-6-span16-nearest-gouraud", "f32-6-span16-nearest-gouraud+micromath"),
    ("f32-6-span16-nearest-phong", "f32-6-span16-nearest-phong+micromath"),
];

/// The `+micromath` key of a configuration.
pub fn twin(key: &str) -> Option<&'static str> {
    PAIRS.iter().find(|p| p.0 == key).map(|p| p.1)
}

/// One configuration's result on one scene.
pub struct Row {
    /// The `+micromath` key.
    pub key: &'static str,
    /// Scene name.
    pub scene: String,
    /// Errors against the reference of the same shading model, and the ideal.
    pub errors: (Errors, Errors),
    /// Frame checksum.
    pub checksum: u32,
}

const HEADER: &str = "key,scene,errors (psnr,max,p99,mean,coverage,depth,uv_max,uv_p99,pixels) same model then ideal,checksum";

/// Writes the rows (the micromath build).
pub fn write(path: &Path, rows: &[Row]) -> Result<(), String> {
    let mut out = format!("{HEADER}\n");
    for r in rows {
        out += &format!("{},{},{},{},{:08x}\n", r.key, r.scene, r.errors.0.to_fields(), r.errors.1.to_fields(), r.checksum);
    }
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    std::fs::write(path, out).map_err(|e| format!("{}: {e}", path.display()))
}

/// Reads the rows back; a missing file or a malformed line gives none.
pub fn read(path: &Path) -> Vec<Row> {
    let Ok(text) = std::fs::read_to_string(path) else { return Vec::new() };
    let n = Errors::FIELDS;
    text.lines()
        .skip(1)
        .filter_map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            if f.len() != 3 + 2 * n {
                return None;
            }
            let key = PAIRS.iter().find(|p| p.1 == f[0])?.1;
            Some(Row {
                key,
                scene: f[1].to_string(),
                errors: (Errors::from_fields(&f[2..2 + n])?, Errors::from_fields(&f[2 + n..2 + 2 * n])?),
                checksum: u32::from_str_radix(f[2 + 2 * n], 16).ok()?,
            })
        })
        .collect()
}

/// A function the pipeline calls, how its error is measured, and where.
pub struct Function {
    /// Name, as the emulated benchmark prints it.
    pub name: &'static str,
    /// What the pipeline calls it for.
    pub used_for: &'static str,
    /// Whether the error is relative (else absolute).
    pub relative: bool,
    /// libm, micromath and exact (`f64`) versions.
    pub libm: fn(f32) -> f32,
    /// micromath's.
    pub micromath: fn(f32) -> f32,
    /// The exact value.
    pub exact: fn(f64) -> f64,
    /// Argument range swept.
    pub range: (f64, f64),
}

/// The functions soft3d takes from its backend (`src/math/elementary.rs`).
/// (`pow` is not among them: specular highlights use integer powers by
/// repeated multiplication.)
pub fn functions() -> [Function; 5] {
    use micromath::F32Ext;
    [
        Function {
            name: "sqrt",
            used_for: "lengths, the normal matrix's scale",
            relative: true,
            libm: libm::sqrtf,
            micromath: |x| F32Ext::sqrt(x),
            exact: f64::sqrt,
            range: (1e-4, 1e4),
        },
        Function {
            name: "inverse sqrt",
            used_for: "normalizing normals and light vectors (per vertex; per pixel in f32 Phong)",
            relative: true,
            libm: |x| 1.0 / libm::sqrtf(x),
            micromath: |x| F32Ext::invsqrt(x),
            exact: |x| 1.0 / x.sqrt(),
            range: (1e-4, 1e4),
        },
        Function {
            name: "sin",
            used_for: "rotation matrices (per draw call)",
            relative: false,
            libm: libm::sinf,
            micromath: |x| F32Ext::sin(x),
            exact: f64::sin,
            range: (-4.0, 4.0),
        },
        Function {
            name: "cos",
            used_for: "rotation matrices (per draw call)",
            relative: false,
            libm: libm::cosf,
            micromath: |x| F32Ext::cos(x),
            exact: f64::cos,
            range: (-4.0, 4.0),
        },
        Function {
            name: "tan",
            used_for: "the projection (per frame)",
            relative: true,
            libm: libm::tanf,
            micromath: |x| F32Ext::tan(x),
            exact: f64::tan,
            range: (-1.4, 1.4),
        },
    ]
}

/// Largest error of `f` against `exact` over 100,001 arguments spread over
/// `range` (geometrically for positive ranges, as the roots' arguments are).
pub fn max_error(f: fn(f32) -> f32, exact: fn(f64) -> f64, range: (f64, f64), relative: bool) -> f64 {
    const N: usize = 100_000;
    (0..=N)
        .map(|i| {
            let t = i as f64 / N as f64;
            let x = if range.0 > 0.0 { range.0 * (range.1 / range.0).powf(t) } else { range.0 + (range.1 - range.0) * t } as f32;
            let (got, want) = (f(x) as f64, exact(x as f64));
            let e = (got - want).abs();
            if relative {
                e / want.abs()
            } else {
                e
            }
        })
        .fold(0.0, f64::max)
}

/// Each function's largest error with each backend: `(libm, micromath)`.
pub fn function_errors() -> Vec<(&'static str, (f64, f64))> {
    functions()
        .iter()
        .map(|f| (f.name, (max_error(f.libm, f.exact, f.range, f.relative), max_error(f.micromath, f.exact, f.range, f.relative))))
        .collect()
}

/// Instructions per call from the emulated benchmark's
/// `function,backend,core,instructions_per_call` rows.
pub fn read_calls(path: &Path) -> BTreeMap<(String, String, String), u32> {
    let Ok(text) = std::fs::read_to_string(path) else { return BTreeMap::new() };
    text.lines()
        .filter_map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            match f[..] {
                [name, backend, core, n] => Some(((name.into(), backend.into(), core.into()), n.parse().ok()?)),
                _ => None,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn libm_is_exact_and_micromath_is_not() {
        for (name, (libm, micromath)) in function_errors() {
            assert!(libm < 1e-6, "{name}: libm {libm}");
            assert!(micromath > 1e-4 && micromath < 0.1, "{name}: micromath {micromath}");
        }
    }

    #[test]
    fn rows_round_trip() {
        let e = Errors { psnr: 41.25, max: 3, p99: 1, mean: 0.125, coverage: 7, depth: 0, uv_max: None, uv_p99: Some(0.5), pixels: 99 };
        let path = std::env::temp_dir().join(format!("soft3d-backend-{}.csv", std::process::id()));
        let rows = [Row { key: PAIRS[1].1, scene: "floor".into(), errors: (e, e), checksum: 0xdead_beef }];
        write(&path, &rows).unwrap();
        let back = read(&path);
        let _ = std::fs::remove_file(&path);
        assert_eq!(back.len(), 1);
        assert_eq!((back[0].key, back[0].scene.as_str(), back[0].checksum), (PAIRS[1].1, "floor", 0xdead_beef));
        assert_eq!(back[0].errors.1.to_fields(), e.to_fields());
        assert_eq!(twin(PAIRS[0].0), Some(PAIRS[0].1));
    }
}
