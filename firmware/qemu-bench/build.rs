//! Puts the emulated board's memory map where the linker finds it, as
//! memory.x, and bakes the shared Blender exports (when `../shared/assets`
//! is there) into Rust statics with `tools/bake`, so the benchmark draws
//! them from flash exactly as the host parses them.
use std::path::{Path, PathBuf};

fn main() {
    let out = PathBuf::from(std::env::var_os("OUT_DIR").unwrap());
    // The ARMv8-M build runs on mps2-an505, whose memory map and SysTick
    // clock (20 MHz) differ from the an385's and an386's.
    let an505 = std::env::var("TARGET").is_ok_and(|t| t.starts_with("thumbv8m"));
    // Not named memory.x here: the linker looks in the crate's directory
    // before the search path.
    let memory = if an505 { "memory-an505.x" } else { "memory-mps2.x" };
    std::fs::copy(memory, out.join("memory.x")).unwrap();
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory-mps2.x");
    println!("cargo:rerun-if-changed=memory-an505.x");
    println!("cargo::rustc-check-cfg=cfg(soft3d_an505)");
    if an505 {
        println!("cargo:rustc-cfg=soft3d_an505");
    }
    println!("cargo:rerun-if-env-changed=SOFT3D_BENCH_ONLY");
    println!("cargo:rerun-if-env-changed=SOFT3D_STUDY_ONLY");
    println!("cargo::rustc-check-cfg=cfg(soft3d_assets)");

    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/assets");
    println!("cargo:rerun-if-changed={}", assets.display());
    let scenes = [("torus.babylon", "torus_file.rs"), ("monkey.babylon", "monkey_file.rs")];
    if !scenes.iter().all(|(file, _)| assets.join(file).exists()) {
        println!("cargo:warning=../shared/assets is absent: the Babylon benchmark scenes are skipped");
        return;
    }
    // The torus as geometry only, in `f32` and `i16`
    // (`soft3d::scenes::QUANTIZED_SCENES`); the monkey with its texture
    // (RGB565, full size), which the accuracy study draws.
    let quantized = ("torus.babylon", "torus_i16_file.rs");
    for (file, rust) in scenes.into_iter().chain([quantized]) {
        let texture_format = if file == "monkey.babylon" { soft3d_bake::TextureFormat::Rgb565 } else { soft3d_bake::TextureFormat::None };
        let quantize = if (file, rust) == quantized { soft3d_bake::Quantize::I16 } else { soft3d_bake::Quantize::F32 };
        let options = soft3d_bake::Options { texture_format, quantize, face_planes: true, ..Default::default() };
        match soft3d_bake::bake_file(&assets.join(file), &out.join(rust), &options) {
            Ok(report) => {
                for input in report.inputs {
                    println!("cargo:rerun-if-changed={}", input.display());
                }
            }
            Err(e) => panic!("baking {file}: {e}"),
        }
    }
    println!("cargo:rustc-cfg=soft3d_assets");
}
