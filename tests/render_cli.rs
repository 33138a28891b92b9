//! The `render` example as a user runs it: `.tri` in, PNGs out, errors
//! with line numbers and a non-zero exit.

mod common;
use common::*;
use std::path::PathBuf;
use std::process::Command;

/// The `render` example binary, built by `cargo test` next to the tests.
fn render_bin() -> Option<PathBuf> {
    let exe = std::env::current_exe().ok()?;
    let dir = exe.parent()?.parent()?; // target/<profile>/deps -> target/<profile>
    let bin = dir.join("examples").join(format!("render{}", std::env::consts::EXE_SUFFIX));
    if !bin.exists() && std::env::var_os("CI").is_some() {
        panic!("{} is missing: CI must run the full `cargo test --features simulator`", bin.display());
    }
    bin.exists().then_some(bin)
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("soft3d-cli-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

#[test]
fn render_writes_the_image_and_exact_coverage() {
    let Some(bin) = render_bin() else {
        eprintln!("SKIPPED: the render example is not built (run `cargo test --features simulator`)");
        return;
    };
    // A fan of four triangles around (20, 15) plus an overlapping one.
    let text = "# fan\n20 15 0.5 1 255 0 0\n5 2.5 0.5 1 255 0 0\n35 4 0.5 1 255 0 0\n\
                20 15 0.5 1 0 255 0\n35 4 0.5 1 0 255 0\n36 28 0.5 1 0 255 0\n\
                20 15 0.5 1 0 0 255\n36 28 0.5 1 0 0 255\n4 27.5 0.5 1 0 0 255\n\
                20 15 0.5 1 9 9 9\n4 27.5 0.5 1 9 9 9\n5 2.5 0.5 1 9 9 9\n\
                10 10 0.2 2 255 255 255\n30 12 0.2 1 255 255 255\n18 25 0.9 1 255 255 255\n";
    let (input, out, cov) = (tmp("fan.tri"), tmp("fan.png"), tmp("fan-cov.png"));
    std::fs::write(&input, text).unwrap();
    let status = Command::new(&bin)
        .arg(&input)
        .args(["-o", out.to_str().unwrap(), "--size", "40x30", "--strip", "7", "--subpixel-bits", "4", "--coverage", cov.to_str().unwrap()])
        .status()
        .unwrap();
    assert!(status.success());
    let img = soft3d::host::load_png(&out).unwrap();
    assert_eq!((img.width, img.height), (40, 30));
    let counts: Vec<u8> = soft3d::host::load_png(&cov).unwrap().pixels.iter().map(embedded_graphics::pixelcolor::RgbColor::r).collect();
    let tris: Vec<[(f64, f64); 3]> = soft3d::tri::parse(text).map(|t| t.unwrap().map(|v| (v.x, v.y))).collect();
    let mut want = vec![0u8; 40 * 30];
    for t in &tris {
        for (w, o) in want.iter_mut().zip(oracle(t, 40, 30, 4)) {
            *w += o;
        }
    }
    assert_eq!(counts, want, "{}", diff(&counts, &want, 40));
    assert!(want.iter().filter(|&&c| c == 2).count() > 50, "the last triangle overlaps the fan");
}

#[test]
fn render_rejects_malformed_files_with_the_line_number() {
    let Some(bin) = render_bin() else {
        eprintln!("SKIPPED: the render example is not built (run `cargo test --features simulator`)");
        return;
    };
    for (text, line) in
        [("0 0 0 1 0 0 0\n1 1 0 1 0 0 0\n\n2 2 0 0 0 0 0\n", 4), ("# c\n1 2 3\n", 2), ("0 0 0 1 0 0 0\n0 nan 0 1 0 0 0\n", 2)]
    {
        let (input, out) = (tmp("bad.tri"), tmp("bad.png"));
        let _ = std::fs::remove_file(&out);
        std::fs::write(&input, text).unwrap();
        let o = Command::new(&bin).arg(&input).args(["-o", out.to_str().unwrap()]).output().unwrap();
        assert_eq!(o.status.code(), Some(1));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(&format!("line {line}:")), "{err}");
        assert!(!out.exists(), "nothing is written on error");
    }
    let o = Command::new(&bin).args(["--bogus"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
}
