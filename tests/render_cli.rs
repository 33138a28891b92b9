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

const ASSETS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/assets");

/// Renders a scene file with `render`, returning the exit code and stderr.
fn render_scene(bin: &PathBuf, input: &std::path::Path, out: &std::path::Path, extra: &[&str]) -> (Option<i32>, String) {
    let o = Command::new(bin).arg(input).args(["-o", out.to_str().unwrap()]).args(extra).output().unwrap();
    (o.status.code(), String::from_utf8_lossy(&o.stderr).into_owned())
}

#[test]
fn render_draws_every_shared_scene_and_a_textured_turntable() {
    let Some(bin) = render_bin() else {
        eprintln!("SKIPPED: the render example is not built (run `cargo test --features simulator`)");
        return;
    };
    let Ok(dir) = std::fs::read_dir(ASSETS) else {
        println!("skipped: {ASSETS} is not available");
        return;
    };
    let mut scenes: Vec<PathBuf> =
        dir.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.extension().is_some_and(|e| e == "babylon")).collect();
    scenes.sort();
    assert!(!scenes.is_empty());
    for scene in &scenes {
        let out = tmp("scene.png");
        let _ = std::fs::remove_file(&out);
        let (code, err) = render_scene(&bin, scene, &out, &["--size", "160x120"]);
        assert_eq!(code, Some(0), "{}: {err}", scene.display());
        assert!(err.is_empty(), "{}: unexpected warnings: {err}", scene.display());
        let img = soft3d::host::load_png(&out).unwrap();
        let background = img.pixels[0];
        let drawn = img.pixels.iter().filter(|&&p| p != background).count();
        assert!(drawn > 300, "{}: only {drawn} pixels drawn", scene.display());
    }
    // A turntable of the textured monkey, into numbered frames.
    let monkey = std::path::Path::new(ASSETS).join("monkey.babylon");
    let out = tmp("spin.png");
    let (code, err) =
        render_scene(&bin, &monkey, &out, &["--size", "80x60", "--frames", "3", "--spin", "--persp", "span16", "--filter", "bilinear"]);
    assert_eq!(code, Some(0), "{err}");
    let frames: Vec<_> = (0..3).map(|i| soft3d::host::load_png(tmp(&format!("spin-{i:03}.png"))).unwrap().pixels).collect();
    assert_ne!(frames[0], frames[1], "the model turns between frames");
}

#[test]
fn broken_scenes_fail_with_a_message_and_status_1() {
    let Some(bin) = render_bin() else {
        eprintln!("SKIPPED: the render example is not built (run `cargo test --features simulator`)");
        return;
    };
    for (text, expect) in [
        ("{\"meshes\": [", "JSON"),
        ("{\"meshes\": [{\"positions\": [0,0,0, 1,0,0], \"indices\": [0,1,2]}]}", "index"),
        ("\u{0}\u{1}garbage", "JSON"),
        ("{\"meshes\": [{\"positions\": [0,0,1e999], \"indices\": []}]}", "finite"),
    ] {
        let (input, out) = (tmp("bad.babylon"), tmp("bad-scene.png"));
        let _ = std::fs::remove_file(&out);
        std::fs::write(&input, text).unwrap();
        let (code, err) = render_scene(&bin, &input, &out, &[]);
        assert_eq!(code, Some(1), "{text}: {err}");
        assert!(err.to_lowercase().contains(&expect.to_lowercase()), "{text}: {err}");
        assert!(!out.exists());
    }
    let (code, err) = render_scene(&bin, &tmp("missing.babylon"), &tmp("x.png"), &[]);
    assert_eq!(code, Some(1), "{err}");
    let (code, _) = render_scene(&bin, &tmp("missing.babylon"), &tmp("x.png"), &["--persp", "sideways"]);
    assert_eq!(code, Some(2));
}
