//! The generated source compiles in a `#![no_std]` crate that depends on
//! soft3d and embedded-graphics, lint-clean (`missing_docs`, clippy
//! `-D warnings` when clippy is installed), and the compiled statics hold
//! exactly the baked bits: the shared assets are parsed again at run time
//! with `soft3d::babylon` inside that crate's tests and compared bit for
//! bit, the i16 meshes' compile-time dequantization is compared with
//! `soft3d_bake::dequantize`, and each scene is rendered. The `i16` bakes
//! carry face planes, which `Mesh::with_face_planes` checks against the
//! dequantized positions at compile time.
//!
//! The crate is written under cargo's per-target temporary directory and
//! built with its own target directory (the outer build's is locked while
//! tests run); the first run compiles soft3d's dependencies once.

mod common;

use common::{asset, inline_scene, write_png, write_rgba_png, PIXELS, SCENES};
use soft3d::babylon::requirements;
use soft3d::math::{Vec2, Vec3};
use soft3d_bake::{bake, bake_babylon, Baked, Options, Quantize, TextureFormat};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

const REPO: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

/// One baked file in the generated crate.
struct Module {
    name: String,
    baked: Baked,
    /// The `.babylon` file it came from, baked as f32: compared with the
    /// run-time parse.
    runtime_source: Option<PathBuf>,
    /// The `.babylon` file it came from, baked as i16: compared with the
    /// run-time parse quantized at run time.
    quantized_source: Option<PathBuf>,
}

fn bits3(v: &[Vec3]) -> String {
    let items: Vec<String> = v.iter().map(|v| format!("[{:#x}, {:#x}, {:#x}]", v.x.to_bits(), v.y.to_bits(), v.z.to_bits())).collect();
    format!("[{}]", items.join(", "))
}

fn bits2(v: &[Vec2]) -> String {
    let items: Vec<String> = v.iter().map(|v| format!("[{:#x}, {:#x}]", v.x.to_bits(), v.y.to_bits())).collect();
    format!("[{}]", items.join(", "))
}

/// The crate's lib.rs: the modules, the expected bits (written from the
/// bake's own arrays as hex, independently of the `{:?}` floats of the
/// generated source) and the tests.
fn lib_rs(modules: &[Module]) -> String {
    let mut lib = String::from(
        "//! Compiles baked scenes in a no_std crate.\n#![no_std]\n#![warn(missing_docs)]\n\n#[cfg(test)]\nextern crate std;\n\n",
    );
    let mut tests = String::from(
        "#[cfg(test)]
mod tests {
    use soft3d::math::{Vec2, Vec3};
    use soft3d::mesh::Mesh;
    use std::boxed::Box;
    use std::vec::Vec;

    fn bits3(v: &[Vec3]) -> Vec<[u32; 3]> {
        v.iter().map(|v| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()]).collect()
    }
    /// Positions or normals as the renderer reads them (dequantized if i16).
    fn vbits(v: soft3d::mesh::Vectors<'_>) -> Vec<[u32; 3]> {
        v.iter().map(|v| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()]).collect()
    }
    fn bits2(v: &[Vec2]) -> Vec<[u32; 2]> {
        v.iter().map(|v| [v.x.to_bits(), v.y.to_bits()]).collect()
    }
    fn same_camera(a: &soft3d::Camera, b: &soft3d::Camera) -> bool {
        bits3(&[a.position, a.target, a.up]) == bits3(&[b.position, b.target, b.up])
            && [a.fov_y, a.near, a.far].map(f32::to_bits) == [b.fov_y, b.near, b.far].map(f32::to_bits)
    }
    /// Draws every mesh of a scene into a 64×48 frame; returns the pixels drawn.
    fn render(
        meshes: &[(&Mesh<'static>, soft3d::math::Mat4, embedded_graphics::pixelcolor::Rgb888, soft3d::Cull)],
        camera: &soft3d::Camera,
        lights: &soft3d::Lights,
    ) -> u32 {
        use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
        use soft3d::{effect::Gouraud, Material, Renderer};
        let materials: Vec<Material<Gouraud>> =
            meshes.iter().map(|m| Material::new(Gouraud).with_color(m.2).with_cull(m.3)).collect();
        let mut renderer: Box<Renderer<Rgb565, 64, 48, 16, 2048, 4096>> = Box::new(Renderer::new(Rgb565::BLACK));
        let mut frame = renderer.begin_frame(camera, lights, Rgb565::BLACK);
        for (m, material) in meshes.iter().zip(&materials) {
            frame.draw(m.0, &m.1, material).unwrap();
        }
        let mut sink = soft3d::scenes::FrameChecksum::new(64, 48, Rgb565::BLACK);
        frame.finish(&mut sink).unwrap();
        sink.drawn
    }
    /// Checksum and pixels drawn of one Gouraud mesh in a 64×48 frame.
    fn checksum(mesh: &Mesh<'_>, model: &soft3d::math::Mat4, camera: &soft3d::Camera, lights: &soft3d::Lights) -> (u32, u32) {
        use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
        use soft3d::{effect::Gouraud, Material, Renderer};
        let material = Material::new(Gouraud);
        let mut renderer: Box<Renderer<Rgb565, 64, 48, 16, 2048, 4096>> = Box::new(Renderer::new(Rgb565::BLACK));
        let mut frame = renderer.begin_frame(camera, lights, Rgb565::BLACK);
        frame.draw(mesh, model, &material).unwrap();
        let mut sink = soft3d::scenes::FrameChecksum::new(64, 48, Rgb565::BLACK);
        frame.finish(&mut sink).unwrap();
        (sink.sum, sink.drawn)
    }
    /// Draws one mesh with a baked texture; returns the pixels drawn.
    fn render_textured(
        mesh: &Mesh<'static>,
        model: &soft3d::math::Mat4,
        texture: soft3d::texture::Texture<'static>,
        camera: &soft3d::Camera,
        lights: &soft3d::Lights,
    ) -> u32 {
        use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
        use soft3d::texture::{Nearest, Repeat};
        use soft3d::{effect::Textured, material::PerPixel, Cull, Material, Renderer};
        let material = Material::new(Textured::<Nearest, Repeat>::new(texture)).with_cull(Cull::None).with_perspective::<PerPixel>();
        let mut renderer: Box<Renderer<Rgb565, 64, 48, 16, 2048, 4096, 5>> = Box::new(Renderer::new(Rgb565::BLACK));
        let mut frame = renderer.begin_frame(camera, lights, Rgb565::BLACK);
        frame.draw(mesh, model, &material).unwrap();
        let mut sink = soft3d::scenes::FrameChecksum::new(64, 48, Rgb565::BLACK);
        frame.finish(&mut sink).unwrap();
        sink.drawn
    }
",
    );
    let mut expected = String::from("#[cfg(test)]\n#[allow(missing_docs, clippy::unreadable_literal)]\nmod expected {\n");
    for m in modules {
        let (name, b) = (&m.name, &m.baked);
        let p = if b.options.prefix.is_empty() { String::new() } else { b.options.prefix.to_ascii_uppercase() + "_" };
        let _ = writeln!(lib, "/// Baked from {:?}.\npub mod {name} {{\n    include!(\"{name}.rs\");\n}}\n", b.source);
        let _ = writeln!(tests, "    #[test]\n    fn {name}_holds_the_baked_bits() {{");
        for mesh in &b.meshes {
            let (id, e) = (format!("{p}{}", mesh.ident), format!("{}_{}", name.to_ascii_uppercase(), mesh.ident));
            let n = mesh.positions.len();
            let _ = writeln!(expected, "    pub static {e}_POSITIONS: [[u32; 3]; {n}] = {};", bits3(&mesh.positions));
            let _ = writeln!(expected, "    pub static {e}_NORMALS: [[u32; 3]; {n}] = {};", bits3(&mesh.normals));
            let _ = writeln!(tests, "        let m = &crate::{name}::{id};");
            let _ = writeln!(tests, "        assert_eq!(vbits(m.positions()), crate::expected::{e}_POSITIONS, \"{name} {id}\");");
            let _ = writeln!(tests, "        assert_eq!(vbits(m.normals()), crate::expected::{e}_NORMALS, \"{name} {id}\");");
            if let Some(uvs) = &mesh.uvs {
                let _ = writeln!(expected, "    pub static {e}_UVS: [[u32; 2]; {n}] = {};", bits2(uvs));
                let _ = writeln!(tests, "        assert_eq!(bits2(m.uvs().unwrap()), crate::expected::{e}_UVS);");
            } else {
                let _ = writeln!(tests, "        assert!(m.uvs().is_none());");
            }
            let _ = writeln!(tests, "        assert_eq!(m.indices(), &{:?}[..]);", mesh.indices);
            let model = mesh.model.m.map(|r| r.map(f32::to_bits));
            let _ = writeln!(tests, "        assert_eq!(crate::{name}::{id}_MODEL.m.map(|r| r.map(f32::to_bits)), {model:?});");
            if let Some(q) = &mesh.quantized {
                let _ = writeln!(tests, "        assert_eq!(crate::{name}::{id}_POSITIONS_I16, {:?});", q.steps.positions);
                let _ = writeln!(tests, "        assert_eq!(crate::{name}::{id}_NORMALS_I16, {:?});", q.steps.normals);
            }
        }
        for t in &b.textures {
            let id = format!("{p}{}", t.ident);
            let _ = writeln!(
                tests,
                "        assert_eq!((crate::{name}::{id}_TEXTURE_WIDTH, crate::{name}::{id}_TEXTURE_HEIGHT), {:?});",
                t.size
            );
            match &t.texels {
                soft3d_bake::Texels::Rgb565(texels) => {
                    let sum: u64 = texels.iter().map(|&t| t as u64).sum();
                    let _ =
                        writeln!(tests, "        assert_eq!(crate::{name}::{id}_TEXELS.iter().map(|&t| t as u64).sum::<u64>(), {sum});");
                }
                soft3d_bake::Texels::Palette8 { palette, indices } => {
                    let _ = writeln!(tests, "        assert_eq!(crate::{name}::{id}_PALETTE, {palette:?});");
                    let sum: u64 = indices.iter().map(|&t| t as u64).sum();
                    let _ =
                        writeln!(tests, "        assert_eq!(crate::{name}::{id}_TEXELS.iter().map(|&t| t as u64).sum::<u64>(), {sum});");
                }
            }
        }
        // Textured meshes draw with the core's `Textured` effect.
        for mesh in b.meshes.iter().filter(|m| m.uvs.is_some()) {
            let texture = mesh.material.and_then(|i| b.materials[i].texture).map(|t| &b.textures[t]);
            if let (Some(t), true) = (texture, b.camera.is_some() && b.lights.is_some()) {
                if matches!(t.texels, soft3d_bake::Texels::Rgb565(_)) {
                    let (id, tid) = (format!("{p}{}", mesh.ident), format!("{p}{}", t.ident));
                    let _ = writeln!(
                        tests,
                        "        assert!(render_textured(&crate::{name}::{id}, &crate::{name}::{id}_MODEL, crate::{name}::{tid}_TEXTURE, \
                         &crate::{name}::{p}CAMERA, &crate::{name}::{p}LIGHTS) > 0, \"{name} {id} textured\");"
                    );
                }
            }
        }
        if b.camera.is_some() && b.lights.is_some() {
            let _ = writeln!(
                tests,
                "        assert!(render(&crate::{name}::{p}MESHES, &crate::{name}::{p}CAMERA, &crate::{name}::{p}LIGHTS) > 20);"
            );
        }
        let _ = writeln!(tests, "    }}\n");

        if let Some(source) = &m.quantized_source {
            let json = std::fs::read(source).unwrap();
            let r = requirements(&json).unwrap();
            let caps = [r.meshes, r.materials, r.lights, r.vertices, r.uvs, r.indices].map(|c| c.max(1));
            let _ = writeln!(
                tests,
                "    #[test]
    fn {name}_renders_like_the_runtime_parse_quantized_at_run_time() {{
        let json = include_bytes!({source:?});
        let mut scene = Box::new(soft3d::babylon::BabylonScene::<{}, {}, {}, {}, {}, {}>::new());
        scene.load(json).unwrap();
        let items: Vec<_> = scene.iter().collect();
        assert_eq!(items.len(), crate::{name}::{p}MESHES.len());
        for (item, (baked, model, _, _)) in items.iter().zip(crate::{name}::{p}MESHES.iter()) {{
            let positions: Vec<Vec3> = item.mesh.positions().iter().collect();
            let normals: Vec<Vec3> = item.mesh.normals().iter().collect();
            let q = soft3d::mesh::QuantizedMesh::new(&positions, &normals).unwrap();
            let mut runtime = q.mesh(item.mesh.indices()).unwrap();
            if let Some(uvs) = item.mesh.uvs() {{
                runtime = runtime.with_uvs(uvs).unwrap();
            }}
            assert_eq!(runtime.positions(), baked.positions());
            assert_eq!(runtime.normals(), baked.normals());
            let camera = crate::{name}::{p}CAMERA;
            let lights = crate::{name}::{p}LIGHTS;
            let a = checksum(&runtime, model, &camera, &lights);
            assert_eq!(a, checksum(baked, model, &camera, &lights));
            assert!(a.1 > 20, \"{name}: only {{}} pixels drawn\", a.1);
        }}
    }}
",
                caps[0], caps[1], caps[2], caps[3], caps[4], caps[5]
            );
        }
        if let Some(source) = &m.runtime_source {
            let json = std::fs::read(source).unwrap();
            let r = requirements(&json).unwrap();
            let caps = [r.meshes, r.materials, r.lights, r.vertices, r.uvs, r.indices].map(|c| c.max(1));
            let _ = writeln!(
                tests,
                "    #[test]
    fn {name}_is_bit_identical_to_the_runtime_parse() {{
        let json = include_bytes!({source:?});
        let mut scene = Box::new(soft3d::babylon::BabylonScene::<{}, {}, {}, {}, {}, {}>::new());
        scene.load(json).unwrap();
        let items: Vec<_> = scene.iter().collect();
        assert_eq!(items.len(), crate::{name}::{p}MESHES.len());
        for (item, (mesh, model, color, cull)) in items.iter().zip(crate::{name}::{p}MESHES.iter()) {{
            assert_eq!(vbits(item.mesh.positions()), vbits(mesh.positions()));
            assert_eq!(vbits(item.mesh.normals()), vbits(mesh.normals()));
            assert_eq!(item.mesh.uvs().map(bits2), mesh.uvs().map(bits2));
            assert_eq!(item.mesh.indices(), mesh.indices());
            assert_eq!(item.model.m.map(|r| r.map(f32::to_bits)), model.m.map(|r| r.map(f32::to_bits)));
            if let Some(material) = item.material {{
                assert_eq!((material.color(), material.cull()), (*color, *cull));
            }}
        }}
        assert!(same_camera(&scene.to_camera().unwrap(), &crate::{name}::{p}CAMERA));
        assert_eq!(std::format!(\"{{:?}}\", scene.to_lights()), std::format!(\"{{:?}}\", crate::{name}::{p}LIGHTS));
    }}
",
                caps[0], caps[1], caps[2], caps[3], caps[4], caps[5]
            );
        }
    }
    // Materials from baked constants can be statics, as docs/bake.md shows.
    lib.push_str(
        "/// A material from baked constants.\npub static TRI_ANGLE_MATERIAL: soft3d::Material<soft3d::effect::Gouraud> =\n    \
         soft3d::Material::new(soft3d::effect::Gouraud).with_color(inline::TRI_ANGLE_COLOR).with_cull(inline::TRI_ANGLE_CULL);\n\n\
         /// A textured material from a baked texture.\npub static TINY_MATERIAL: soft3d::Material<soft3d::effect::Textured<'static>, soft3d::material::PerPixel> =\n    \
         soft3d::Material::new(soft3d::effect::Textured::new(inline::TINY_TEXTURE)).with_perspective::<soft3d::material::PerPixel>();\n\n",
    );
    // The same inline scene, baked by the crate's build script.
    lib.push_str("/// Baked by build.rs.\npub mod from_build_rs {\n    include!(concat!(env!(\"OUT_DIR\"), \"/scene.rs\"));\n}\n\n");
    tests.push_str(
        "    #[test]
    fn the_build_script_bakes_the_same_scene() {
        assert_eq!(vbits(crate::from_build_rs::BUILT_TRI_ANGLE.positions()), vbits(crate::inline::TRI_ANGLE.positions()));
        assert_eq!(crate::from_build_rs::BUILT_TINY_TEXELS, crate::inline::TINY_TEXELS);
        assert_eq!(crate::from_build_rs::BUILT_MESHES.len(), 2);
    }
",
    );
    expected.push_str("}\n");
    tests.push_str("}\n");
    lib + &expected + &tests
}

/// The documented build-script use: bake into OUT_DIR, rerun when an
/// input changes.
const BUILD_RS: &str = r#"fn main() {
    let out = std::path::PathBuf::from(std::env::var("OUT_DIR").unwrap()).join("scene.rs");
    let options = soft3d_bake::Options { prefix: "built".into(), ..Default::default() };
    let report = soft3d_bake::bake_file(std::path::Path::new("assets/scene.babylon"), &out, &options).unwrap_or_else(|e| panic!("{e}"));
    for input in &report.inputs {
        println!("cargo:rerun-if-changed={}", input.display());
    }
}
"#;

fn cargo(dir: &Path, args: &[&str]) {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let out = Command::new(cargo)
        .args(args)
        .current_dir(dir)
        .env("CARGO_TARGET_DIR", dir.join("target"))
        .env("CARGO_TERM_COLOR", "never")
        .env_remove("RUSTFLAGS")
        .output()
        .unwrap();
    let log = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "cargo {args:?} failed in {}:\n{log}", dir.display());
    // Show the generated crate's test results.
    for line in log.lines().filter(|l| l.starts_with("test ") || l.starts_with("test result")) {
        println!("  {line}");
    }
}

#[test]
fn generated_source_compiles_and_holds_the_baked_bits() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("generated-crate");
    let src = dir.join("src");
    // Keep target/ between runs; the sources are rewritten.
    let _ = std::fs::remove_dir_all(&src);
    std::fs::create_dir_all(&src).unwrap();
    let repo = std::fs::canonicalize(REPO).unwrap();
    std::fs::write(
        dir.join("Cargo.toml"),
        format!(
            "[package]\nname = \"soft3d-bake-check\"\nversion = \"0.0.0\"\nedition = \"2021\"\npublish = false\n\n[workspace]\n\n\
             [dependencies]\nsoft3d = {{ path = {:?} }}\nembedded-graphics = \"0.8.1\"\n\n\
             [dev-dependencies]\nsoft3d = {{ path = {:?}, features = [\"std\"] }}\n\n\
             [build-dependencies]\nsoft3d-bake = {{ path = {:?} }}\n",
            repo.to_str().unwrap(),
            repo.to_str().unwrap(),
            env!("CARGO_MANIFEST_DIR")
        ),
    )
    .unwrap();
    // The bake package's lock pins the same versions, and needs no index update.
    let lock = Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.lock");
    if lock.exists() {
        std::fs::copy(&lock, dir.join("Cargo.lock")).unwrap();
    }

    let mut modules = Vec::new();
    // The inline scene as files, for the crate's build script too.
    let textures = dir.join("assets");
    std::fs::create_dir_all(&textures).unwrap();
    write_png(&textures.join("tiny.png"), 4, 2, &PIXELS);
    std::fs::write(textures.join("scene.babylon"), inline_scene("tiny.png")).unwrap();
    std::fs::write(dir.join("build.rs"), BUILD_RS).unwrap();
    let inline = |options: Options| {
        bake_babylon(inline_scene("tiny.png").as_bytes(), &Options { textures: Some(textures.clone()), ..options }).unwrap()
    };
    modules.push(Module { name: "inline".into(), baked: inline(Options::default()), runtime_source: None, quantized_source: None });
    // A texture with transparent pixels: its alpha plane must compile into the texture.
    let glass: Vec<[u8; 4]> = PIXELS.iter().enumerate().map(|(i, &[r, g, b])| [r, g, b, (i * 36) as u8]).collect();
    write_rgba_png(&textures.join("glass.png"), 4, 2, &glass);
    let alpha =
        bake_babylon(inline_scene("glass.png").as_bytes(), &Options { textures: Some(textures.clone()), ..Options::default() }).unwrap();
    assert!(alpha.textures[0].alpha.is_some());
    modules.push(Module { name: "alpha".into(), baked: alpha, runtime_source: None, quantized_source: None });
    modules.push(Module {
        name: "inline_i16".into(),
        baked: inline(Options {
            quantize: Quantize::I16,
            texture_format: TextureFormat::Palette8,
            prefix: "small".into(),
            face_planes: true,
            ..Options::default()
        }),
        runtime_source: None,
        quantized_source: None,
    });
    for (name, _, _) in SCENES {
        let Some(path) = asset(&format!("{name}.babylon")) else { continue };
        modules.push(Module {
            name: name.into(),
            baked: bake(&path, &Options::default()).unwrap(),
            runtime_source: Some(path.clone()),
            quantized_source: None,
        });
        let i16 = Options {
            quantize: Quantize::I16,
            texture_format: TextureFormat::Palette8,
            max_texture_size: Some(64),
            face_planes: true,
            ..Options::default()
        };
        modules.push(Module {
            name: format!("{name}_i16"),
            baked: bake(&path, &i16).unwrap(),
            runtime_source: None,
            quantized_source: Some(path.clone()),
        });
    }
    for m in &modules {
        std::fs::write(src.join(format!("{}.rs", m.name)), m.baked.to_rust()).unwrap();
    }
    std::fs::write(src.join("lib.rs"), lib_rs(&modules)).unwrap();

    // The library alone is no_std; the tests add std.
    cargo(&dir, &["build", "--lib"]);
    let clippy = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into())).args(["clippy", "--version"]).output();
    if clippy.is_ok_and(|o| o.status.success()) {
        cargo(&dir, &["clippy", "--lib", "--", "-D", "warnings"]);
    } else {
        println!("note: clippy not installed; the generated source was not linted");
    }
    cargo(&dir, &["test"]);
}
