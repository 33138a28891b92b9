//! "A scene pays only for the effects it uses": the figures of
//! `scripts/effects-bench.sh` (firmware builds with only the `Flat` effect
//! against one with every effect, on the emulated cores), as a section of
//! the document.

use std::fmt::Write as _;
use std::path::Path;

/// One frame of one firmware build.
pub struct Row {
    /// `flat-only`, `flat-nodepth-only`, `flat-only-v6` or `all`.
    pub build: String,
    /// `m4f` or `m0`.
    pub core: String,
    /// The frame: `flat`, `flat-nodepth`, `gouraud`, ...
    pub scene: String,
    /// Instructions per frame.
    pub instructions: u64,
    /// Flash bytes of the build.
    pub flash: u64,
    /// Static RAM bytes of the build.
    pub ram: u64,
}

/// Reads `build,core,scene,instructions,geometry,flash,ram,checksum` rows
/// (missing file: none).
pub fn read(path: &Path) -> Vec<Row> {
    let Ok(text) = std::fs::read_to_string(path) else { return Vec::new() };
    text.lines()
        .skip(1)
        .filter_map(|line| match line.split(',').collect::<Vec<_>>()[..] {
            [build, core, scene, n, _, flash, ram, _] => Some(Row {
                build: build.into(),
                core: core.into(),
                scene: scene.into(),
                instructions: n.parse().ok()?,
                flash: flash.parse().ok()?,
                ram: ram.parse().ok()?,
            }),
            _ => None,
        })
        .collect()
}

/// The section.
pub fn markdown(rows: &[Row], thousands: fn(f64) -> String) -> String {
    let mut d = String::from("## Pay for what you use\n\n");
    if rows.is_empty() {
        let _ = writeln!(d, "No figures yet (`docs/accuracy/effects.csv` is missing).\n");
        return d;
    }
    let _ = writeln!(
        d,
        "`bash scripts/effects-bench.sh` builds firmware for the emulated cores in which only the `Flat` effect \
         exists, and a general one (6 varyings per vertex, every effect linked in and drawn), and times the same \
         flat-shaded scene (built-in torus, sphere and cubes, 1,768 triangles, depth test on) in both. It fails if \
         the general build takes more than 1% more instructions for it, if the frames differ, or if the flat-only \
         firmware is not smaller.\n"
    );
    let _ = writeln!(d, "| build | core | flat frame, instr | flash bytes | static RAM bytes |");
    let _ = writeln!(d, "| --- | --- | ---: | ---: | ---: |");
    let find = |build: &str, core: &str, scene: &str| rows.iter().find(|r| r.build == build && r.core == core && r.scene == scene);
    for core in ["m4f", "m0"] {
        for (build, label) in [("flat-only", "only `Flat`"), ("all", "every effect")] {
            if let Some(r) = find(build, core, "flat") {
                let _ = writeln!(
                    d,
                    "| {label} | {} | {} | {} | {} |",
                    if core == "m4f" { "M4F" } else { "M0+" },
                    thousands(r.instructions as f64),
                    thousands(r.flash as f64),
                    thousands(r.ram as f64)
                );
            }
        }
    }
    let _ = writeln!(d);
    for core in ["m4f", "m0"] {
        let name = if core == "m4f" { "M4F" } else { "M0+" };
        if let (Some(flat), Some(all)) = (find("flat-only", core, "flat"), find("all", core, "flat")) {
            let _ = writeln!(
                d,
                "- {name}: the flat scene in the general build takes {:+.2}% instructions against the flat-only build; \
                 the flat-only firmware is {} bytes of flash smaller ({:.1}× less). The general build's extra RAM is \
                 its wider vertex buffer (6 varyings), which a firmware sizes for the effects it uses.",
                (all.instructions as f64 / flat.instructions as f64 - 1.0) * 100.0,
                thousands(all.flash.saturating_sub(flat.flash) as f64),
                all.flash as f64 / flat.flash as f64
            );
        }
        if let (Some(on), Some(off)) = (find("flat-only", core, "flat"), find("flat-nodepth-only", core, "flat-nodepth")) {
            let _ = writeln!(
                d,
                "- {name}: the depth test costs {:+.1}% instructions on that scene and {} bytes of flash; a material \
                 with `DepthOff` pays neither.",
                (on.instructions as f64 / off.instructions as f64 - 1.0) * 100.0,
                thousands(on.flash.saturating_sub(off.flash) as f64)
            );
        }
    }
    let _ = writeln!(d);
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_script_rows_and_reports_the_ratio() {
        let path = std::env::temp_dir().join(format!("soft3d-effects-{}.csv", std::process::id()));
        std::fs::write(
            &path,
            "build,core,scene,instructions,geometry,flash,ram,checksum\n\
             flat-only,m4f,flat,1000,10,100,50,aa\nall,m4f,flat,1005,10,300,80,aa\nbroken,line\n",
        )
        .unwrap();
        let rows = read(&path);
        let _ = std::fs::remove_file(&path);
        assert_eq!(rows.len(), 2);
        let md = markdown(&rows, |v| format!("{v}"));
        assert!(md.contains("+0.50% instructions"), "{md}");
        assert!(md.contains("200 bytes of flash smaller (3.0× less)"), "{md}");
    }
}
