//! The bake library and CLI: the shared assets (counts, bit-exact agreement
//! with `soft3d::babylon`, i16 error bounds, the Suzanne texture), textures
//! from small generated PNGs, OBJ input, and the error paths.
//!
//! Whether the generated source compiles is checked in `compile.rs`.

mod common;

use common::{asset, inline_scene, scratch, write_png, PIXELS, SCENES};
use soft3d::babylon::BabylonScene;
use soft3d::math::{Vec2, Vec3};
use soft3d::Cull;
use soft3d_bake::{
    bake, bake_babylon, bake_file, bake_obj, dequantize, rgb565, BakeError, Baked, Options, Quantize, Texels, TextureFormat, NORMAL_SCALE,
};
use std::process::Command;

/// Room for every shared asset.
type HostScene = BabylonScene<8, 8, 8, 4096, 4096, 8192>;

fn bits3(v: &[Vec3]) -> Vec<[u32; 3]> {
    v.iter().map(|v| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()]).collect()
}

fn bits2(v: &[Vec2]) -> Vec<[u32; 2]> {
    v.iter().map(|v| [v.x.to_bits(), v.y.to_bits()]).collect()
}

fn bake_asset(name: &str, options: &Options) -> Option<Baked> {
    let path = asset(&format!("{name}.babylon"))?;
    Some(bake(&path, options).unwrap_or_else(|e| panic!("{name}: {e}")))
}

// ---------------------------------------------------------------- assets

#[test]
fn shared_assets_bake_with_their_counts() {
    for (name, vertices, triangles) in SCENES {
        let Some(baked) = bake_asset(name, &Options::default()) else { return };
        assert_eq!(baked.meshes.len(), 1, "{name}");
        let m = &baked.meshes[0];
        assert_eq!((m.positions.len(), m.indices.len() / 3), (vertices, triangles), "{name}");
        assert!(baked.camera.is_some(), "{name}");
        let report = baked.report();
        assert_eq!(report.meshes[0].vertices, vertices);
        assert_eq!(report.meshes[0].triangles, triangles);
        assert!(baked.to_rust().contains(&format!("pub static {}: ::soft3d::mesh::Mesh<'static>", m.ident)));
    }
}

#[test]
fn monkey_has_its_material_and_texture() {
    let Some(baked) = bake_asset("monkey", &Options::default()) else { return };
    let m = &baked.meshes[0];
    assert_eq!((m.name.as_str(), m.ident.as_str()), ("Suzanne", "SUZANNE"));
    assert!(m.uvs.is_some());
    let material = &baked.materials[m.material.unwrap()];
    assert_eq!(material.ident, "MATERIAL_02_DEFAULT");
    assert_eq!(material.texture_name.as_deref(), Some("Suzanne.jpg"));
    assert_eq!(material.cull, Cull::Back);
    let t = &baked.textures[material.texture.unwrap()];
    assert_eq!((t.size, t.source_size), ((512, 512), (512, 512)));
    assert!(t.psnr_rgb565 > 40.0, "{}", t.psnr_rgb565);
    let Texels::Rgb565(texels) = &t.texels else { panic!("rgb565 expected") };
    assert_eq!(texels.len(), 512 * 512);
    // The texel values are the image's pixels, rounded to RGB565.
    let jpeg = std::path::PathBuf::from(common::ASSETS.to_string() + "/Suzanne.jpg");
    let (_, _, pixels) = soft3d::texture::read_jpeg(&jpeg).unwrap();
    for (x, y) in [(0, 0), (511, 0), (0, 511), (256, 300), (100, 77)] {
        let [r, g, b, _] = pixels[y * 512 + x];
        assert_eq!(texels[y * 512 + x], rgb565(r, g, b), "texel ({x}, {y})");
    }
    // The simulator's loader gives the very same texels.
    let loaded = soft3d::texture::OwnedTexture::load(&jpeg, 1 << 15).unwrap();
    assert_eq!((&loaded.texels, &loaded.alpha), (texels, &t.alpha));
    assert!(baked.warnings.is_empty(), "{:?}", baked.warnings);
    assert!(baked.inputs.iter().any(|p| p.ends_with("Suzanne.jpg")));
}

/// The baked arrays, model matrix, camera and lights are exactly what the
/// core's loader produces from the same file at run time.
#[test]
fn f32_bakes_are_bit_identical_to_the_runtime_parse() {
    for (name, _, _) in SCENES {
        let Some(path) = asset(&format!("{name}.babylon")) else { return };
        let json = std::fs::read(&path).unwrap();
        let baked = bake(&path, &Options::default()).unwrap();
        let mut scene = Box::new(HostScene::new());
        scene.load(&json).unwrap();
        let items: Vec<_> = scene.iter().collect();
        assert_eq!(items.len(), baked.meshes.len());
        for (item, m) in items.iter().zip(&baked.meshes) {
            assert_eq!(bits3(&item.mesh.positions().iter().collect::<Vec<_>>()), bits3(&m.positions), "{name} positions");
            assert_eq!(bits3(&item.mesh.normals().iter().collect::<Vec<_>>()), bits3(&m.normals), "{name} normals");
            assert_eq!(item.mesh.uvs().map(bits2), m.uvs.as_deref().map(bits2), "{name} uvs");
            assert_eq!(item.mesh.indices(), &m.indices[..], "{name} indices");
            assert_eq!(item.model.m.map(|r| r.map(f32::to_bits)), m.model.m.map(|r| r.map(f32::to_bits)), "{name} model");
        }
        let (c, b) = (scene.to_camera().unwrap(), baked.camera.unwrap());
        assert_eq!(bits3(&[c.position, c.target, c.up]), bits3(&[b.position, b.target, b.up]));
        assert_eq!([c.fov_y, c.near, c.far].map(f32::to_bits), [b.fov_y, b.near, b.far].map(f32::to_bits));
        assert_eq!(format!("{:?}", scene.to_lights()), format!("{:?}", baked.lights.unwrap()));
    }
}

#[test]
fn i16_errors_are_within_half_a_step() {
    let options = Options { quantize: Quantize::I16, ..Options::default() };
    for (name, _, _) in SCENES {
        let Some(f32_bake) = bake_asset(name, &Options::default()) else { return };
        let baked = bake_asset(name, &options).unwrap();
        let (orig, m) = (&f32_bake.meshes[0], &baked.meshes[0]);
        let q = m.quantized.as_ref().expect("quantized");
        let (s, o) = (q.steps.position_scale, q.steps.position_offset);
        for (i, (p, qp)) in orig.positions.iter().zip(&q.steps.positions).enumerate() {
            let deq = [0, 1, 2].map(|k| dequantize(qp[k], s[k], o[k]));
            assert_eq!(bits3(&[m.positions[i]]), bits3(&[Vec3::new(deq[0], deq[1], deq[2])]), "{name}: Mesh built from dequantize()");
            for (k, (a, d)) in [p.x, p.y, p.z].into_iter().zip(deq).enumerate() {
                // Half a step, plus the f32 rounding of q·scale + offset.
                let bound = 0.5 * s[k] as f64 + f32::EPSILON as f64 * (a.abs() as f64 + o[k].abs() as f64);
                assert!((a as f64 - d as f64).abs() <= bound, "{name} vertex {i} axis {k}: {a} vs {d}");
            }
        }
        for (n, qn) in m.normals.iter().zip(&q.steps.normals) {
            assert_eq!(n.x, dequantize(qn[0], NORMAL_SCALE, 0.0));
        }
        let e = q.error;
        assert!(e.max_axis_steps <= 0.51, "{name}: {e:?}");
        assert!(e.max_relative() < 1e-4 && e.rms_position <= e.max_position, "{name}: {e:?}");
        assert!(e.max_normal_degrees < 0.01, "{name}: {e:?}");
        let r = baked.report();
        assert_eq!(r.meshes[0].quantization, Some(e));
        assert!(r.meshes[0].i16_flash_bytes < r.meshes[0].flash_bytes);
        println!(
            "{name}: max {:.3e} ({:.2e} of radius {:.4}), rms {:.3e}, {:.3} steps, normals {:.4}°",
            e.max_position,
            e.max_relative(),
            e.radius,
            e.rms_position,
            e.max_axis_steps,
            e.max_normal_degrees
        );
    }
}

// ---------------------------------------------------------------- inline scenes and textures

#[test]
fn inline_scene_bakes_meshes_materials_camera_and_lights() {
    let dir = scratch("inline");
    write_png(&dir.join("tiny.png"), 4, 2, &PIXELS);
    let options = Options { textures: Some(dir.clone()), prefix: "demo".into(), ..Options::default() };
    let baked = bake_babylon(inline_scene("tiny.png").as_bytes(), &options).unwrap();
    assert_eq!(baked.meshes.iter().map(|m| m.ident.as_str()).collect::<Vec<_>>(), ["TRI_ANGLE", "QUAD"]);
    assert!(baked.warnings.iter().any(|w| w.contains("'empty' has no triangles")), "{:?}", baked.warnings);
    assert!(baked.warnings.iter().any(|w| w.contains("1 light(s)")), "{:?}", baked.warnings);
    let tri = &baked.meshes[0];
    assert_eq!(tri.normals[1], Vec3::new(0.0, 0.0, -1.0)); // normalized on load, as at run time
    assert_eq!(baked.materials[0].cull, Cull::None);
    let lights = baked.lights.unwrap();
    assert!(lights.point.is_some() && lights.directional.is_some());
    let source = baked.to_rust();
    for item in [
        "DEMO_CAMERA",
        "DEMO_LIGHTS",
        "DEMO_CLEAR_COLOR",
        "DEMO_MESHES",
        "DEMO_TRI_ANGLE_UVS",
        "DEMO_PAINTED_TEXTURE_NAME",
        "DEMO_TINY_TEXTURE",
        "DEMO_TINY_TEXELS",
    ] {
        assert!(source.contains(&format!("pub static {item}")) || source.contains(&format!("pub const {item}")), "{item}");
    }
    assert!(!source.contains("DEMO_QUAD_UVS"));
}

#[test]
fn textures_are_rgb565_row_major_top_row_first() {
    let dir = scratch("tiny-texture");
    write_png(&dir.join("tiny.png"), 4, 2, &PIXELS);
    let options = Options { textures: Some(dir.clone()), ..Options::default() };
    let baked = bake_babylon(inline_scene("tiny.png").as_bytes(), &options).unwrap();
    let t = &baked.textures[0];
    assert_eq!((t.size, t.ident.as_str()), ((4, 2), "TINY"));
    let Texels::Rgb565(texels) = &t.texels else { panic!() };
    assert_eq!(texels, &[0xF800, 0x07E0, 0x001F, 0xFFFF, 0x0000, 0x0821, 0x8410, 0xFC00]);
    let source = baked.to_rust();
    assert!(source.contains("pub const TINY_TEXTURE_WIDTH: usize = 4;"));
    assert!(
        source.contains("pub static TINY_TEXELS: [u16; 8] = [\n    0xf800, 0x07e0, 0x001f, 0xffff, 0x0000, 0x0821, 0x8410, 0xfc00,\n];")
    );

    // Eight colors fit a palette exactly.
    let options = Options { texture_format: TextureFormat::Palette8, ..options };
    let baked = bake_babylon(inline_scene("tiny.png").as_bytes(), &options).unwrap();
    let t = &baked.textures[0];
    let Texels::Palette8 { palette, indices } = &t.texels else { panic!() };
    let mapped: Vec<u16> = indices.iter().map(|&i| palette[i as usize]).collect();
    assert_eq!(mapped, [0xF800, 0x07E0, 0x001F, 0xFFFF, 0x0000, 0x0821, 0x8410, 0xFC00]);
    assert_eq!(t.psnr_palette, Some(f64::INFINITY));
}

#[test]
fn other_sizes_are_scaled_down_to_powers_of_two_with_a_warning() {
    let dir = scratch("npot");
    let pixels: Vec<[u8; 3]> = (0..15).map(|i| [i as u8 * 16, 255 - i as u8 * 16, 100]).collect();
    write_png(&dir.join("odd.png"), 3, 5, &pixels);
    let options = Options { textures: Some(dir.clone()), ..Options::default() };
    let baked = bake_babylon(inline_scene("odd.png").as_bytes(), &options).unwrap();
    assert_eq!((baked.textures[0].source_size, baked.textures[0].size), ((3, 5), (2, 4)));
    assert!(baked.warnings.iter().any(|w| w.contains("3×5 resized to 2×4")), "{:?}", baked.warnings);

    let options = Options { max_texture_size: Some(3), ..options };
    let baked = bake_babylon(inline_scene("odd.png").as_bytes(), &options).unwrap();
    assert_eq!(baked.textures[0].size, (2, 2));
}

/// Transparent pixels give an alpha plane, emitted and attached to the
/// texture; baked texels and alpha equal the simulator's loader's, resized
/// or not.
#[test]
fn alpha_is_kept_and_baked_textures_equal_the_simulators() {
    let dir = scratch("alpha");
    let pixels: Vec<[u8; 4]> =
        (0..15).map(|i| [i as u8 * 16, 255 - i as u8 * 16, 100, if i % 4 == 0 { 0 } else { 255 - i as u8 }]).collect();
    common::write_rgba_png(&dir.join("glass.png"), 3, 5, &pixels);
    for max in [None, Some(2)] {
        let options = Options { textures: Some(dir.clone()), max_texture_size: max, ..Options::default() };
        let baked = bake_babylon(inline_scene("glass.png").as_bytes(), &options).unwrap();
        let t = &baked.textures[0];
        let loaded = soft3d::texture::OwnedTexture::load(&dir.join("glass.png"), max.unwrap_or(1 << 15) as usize).unwrap();
        let Texels::Rgb565(texels) = &t.texels else { panic!("rgb565 expected") };
        assert_eq!((texels, &t.alpha), (&loaded.texels, &loaded.alpha));
        assert!(t.alpha.as_ref().is_some_and(|a| a.iter().any(|&a| a < 255)));
        let source = baked.to_rust();
        assert!(source.contains("_ALPHA: [u8; "), "{source}");
        assert!(source.contains(".with_alpha(&"), "{source}");
    }
}

#[test]
fn suzanne_palettizes_with_a_reported_psnr() {
    let Some(path) = asset("monkey.babylon") else { return };
    let options = Options { texture_format: TextureFormat::Palette8, ..Options::default() };
    let baked = bake(&path, &options).unwrap();
    let t = &baked.textures[0];
    let psnr = t.psnr_palette.unwrap();
    assert!(psnr > 35.0 && psnr.is_finite(), "{psnr}");
    let Texels::Palette8 { palette, indices } = &t.texels else { panic!() };
    assert_eq!((palette.len(), indices.len()), (256, 512 * 512));
    let r = baked.report();
    assert_eq!(r.textures[0].flash_bytes, 512 * 512 + 512);
    println!("Suzanne.jpg: RGB565 {:.2} dB against 8-bit, palette8 {psnr:.2} dB against RGB565", t.psnr_rgb565);
}

// ---------------------------------------------------------------- OBJ

const OBJ: &str = "\
# a textured quad facing +z (right-handed) and a bare triangle
mtllib quad.mtl
o Quad
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
usemtl red
f 1/1/1 2/2/1 3/3/1 4/4/1
o Tri
v 0 0 1
v 1 0 1
v 0 1 1
f 5 6 7
";

#[test]
fn obj_is_mirrored_into_the_left_handed_frame() {
    let dir = scratch("obj");
    std::fs::write(dir.join("quad.obj"), OBJ).unwrap();
    std::fs::write(dir.join("quad.mtl"), "newmtl red\nKd 1 0 0\nmap_Kd tiny.png\n").unwrap();
    write_png(&dir.join("tiny.png"), 4, 2, &PIXELS);
    let baked = bake_obj(&dir.join("quad.obj"), &Options::default()).unwrap();
    assert!(baked.warnings.is_empty(), "{:?}", baked.warnings);
    assert!(baked.camera.is_none() && baked.lights.is_none());
    let [quad, tri] = &baked.meshes[..] else { panic!("{:?}", baked.meshes) };
    assert_eq!((quad.ident.as_str(), quad.positions.len(), quad.indices.len()), ("QUAD", 4, 6));
    assert_eq!(quad.positions[2], Vec3::new(1.0, 1.0, 0.0));
    assert!(quad.positions.iter().all(|p| p.z.to_bits() == 0), "no -0.0");
    assert!(quad.normals.iter().all(|n| *n == Vec3::new(0.0, 0.0, -1.0)));
    assert_eq!(quad.uvs.as_ref().unwrap()[0], Vec2::new(0.0, 1.0)); // v flipped
    assert_eq!(&quad.indices[..3], &[0, 2, 1]); // winding reversed
    let material = &baked.materials[quad.material.unwrap()];
    assert_eq!((material.color, material.texture), (embedded_graphics::pixelcolor::Rgb888::new(255, 0, 0), Some(0)));
    assert_eq!(baked.textures[0].size, (4, 2));
    // No normals in the file: area-weighted face normals, facing -z after the mirror.
    assert_eq!(tri.positions[0], Vec3::new(0.0, 0.0, -1.0));
    assert!(tri.normals.iter().all(|n| *n == Vec3::new(0.0, 0.0, -1.0)), "{:?}", tri.normals);
    // `usemtl` state carries over to the next object, as OBJ specifies.
    assert!(tri.uvs.is_none() && tri.material == quad.material);
    for suffix in ["quad.obj", "quad.mtl", "tiny.png"] {
        assert!(baked.inputs.iter().any(|p| p.ends_with(suffix)), "{suffix}: {:?}", baked.inputs);
    }
}

#[test]
fn obj_without_its_mtl_bakes_with_a_warning() {
    let dir = scratch("obj-no-mtl");
    std::fs::write(dir.join("quad.obj"), OBJ).unwrap();
    let baked = bake_obj(&dir.join("quad.obj"), &Options::default()).unwrap();
    assert!(baked.warnings.iter().any(|w| w.contains("materials not loaded") && w.contains("quad.mtl")), "{:?}", baked.warnings);
    assert!(baked.materials.is_empty());
}

// ---------------------------------------------------------------- errors

#[test]
fn malformed_json_is_a_clear_error() {
    for json in ["{\"meshes\": [", "", "{\"meshes\": [{\"positions\": [0, 0], \"indices\": [0, 1, 2]}]}", "[1, 2, 3]"] {
        let e = bake_babylon(json.as_bytes(), &Options::default()).unwrap_err();
        assert!(matches!(e, BakeError::Babylon(_)), "{json}: {e:?}");
        assert!(e.to_string().starts_with("invalid .babylon scene: "), "{e}");
    }
}

#[test]
fn a_missing_texture_is_an_error_unless_textures_are_skipped() {
    let dir = scratch("missing-texture");
    let options = Options { textures: Some(dir.clone()), ..Options::default() };
    let e = bake_babylon(inline_scene("nope.png").as_bytes(), &options).unwrap_err();
    assert!(matches!(e, BakeError::Texture { .. }), "{e:?}");
    let message = e.to_string();
    assert!(message.contains("nope.png") && message.contains("--texture-format none"), "{message}");

    std::fs::write(dir.join("bad.png"), b"not a png").unwrap();
    let e = bake_babylon(inline_scene("bad.png").as_bytes(), &options).unwrap_err();
    assert!(e.to_string().contains("cannot decode"), "{e}");

    let options = Options { texture_format: TextureFormat::None, ..options };
    let baked = bake_babylon(inline_scene("nope.png").as_bytes(), &options).unwrap();
    assert!(baked.textures.is_empty());
    assert!(baked.to_rust().contains("pub const PAINTED_TEXTURE_NAME: &str = \"nope.png\";"));
}

#[test]
fn other_errors() {
    let dir = scratch("errors");
    let options = Options { prefix: "9lives".into(), ..Options::default() };
    assert!(matches!(bake_babylon(b"{}", &options), Err(BakeError::Options(_))));
    std::fs::write(dir.join("notes.txt"), "hello").unwrap();
    assert!(matches!(bake(&dir.join("notes.txt"), &Options::default()), Err(BakeError::UnknownFormat(_))));
    assert!(matches!(bake(&dir.join("absent.babylon"), &Options::default()), Err(BakeError::Io { .. })));
    std::fs::write(dir.join("bad.obj"), "v 0 0 0\nf 1 2 3\n").unwrap();
    let e = bake(&dir.join("bad.obj"), &Options::default()).unwrap_err();
    assert!(matches!(e, BakeError::Obj { .. }), "{e:?}");
    std::fs::write(dir.join("garbage.obj"), "v x y z\n\u{0}\u{1}f -7 0 9999999999999\n").unwrap();
    assert!(bake(&dir.join("garbage.obj"), &Options::default()).is_err());
}

// ---------------------------------------------------------------- files and the CLI

#[test]
fn bake_file_is_deterministic_and_leaves_unchanged_output_alone() {
    let dir = scratch("bake-file");
    std::fs::write(dir.join("scene.babylon"), inline_scene("tiny.png")).unwrap();
    write_png(&dir.join("tiny.png"), 4, 2, &PIXELS);
    let out = dir.join("scene.rs");
    let report = bake_file(&dir.join("scene.babylon"), &out, &Options::default()).unwrap();
    assert_eq!(report.source_bytes, std::fs::metadata(&out).unwrap().len() as usize);
    assert_eq!(report.inputs, [dir.join("scene.babylon"), dir.join("tiny.png")]);
    let first = std::fs::metadata(&out).unwrap().modified().unwrap();
    std::thread::sleep(std::time::Duration::from_millis(20));
    bake_file(&dir.join("scene.babylon"), &out, &Options::default()).unwrap();
    assert_eq!(std::fs::metadata(&out).unwrap().modified().unwrap(), first);
    assert!(!dir.join("scene.rs.tmp").exists());
}

fn cli(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_soft3d-bake")).args(args).output().unwrap();
    (out.status.code().unwrap_or(-1), String::from_utf8_lossy(&out.stdout).into_owned(), String::from_utf8_lossy(&out.stderr).into_owned())
}

#[test]
fn cli_exit_codes() {
    let dir = scratch("cli");
    let scene = dir.join("scene.babylon");
    std::fs::write(&scene, inline_scene("tiny.png")).unwrap();
    write_png(&dir.join("tiny.png"), 4, 2, &PIXELS);
    let out = dir.join("out.rs");
    let (s, o) = (scene.to_str().unwrap(), out.to_str().unwrap());

    let (code, stdout, stderr) =
        cli(&[s, "-o", o, "--quantize", "i16", "--texture-format=palette8", "--prefix", "inline", "--face-planes"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("mesh 'Tri angle' (TRI_ANGLE): 3 vertices, 1 triangles") && stdout.contains("i16 positions: error max"),
        "{stdout}"
    );
    assert!(stderr.contains("warning: mesh 'empty' has no triangles"), "{stderr}");
    let source = std::fs::read_to_string(&out).unwrap();
    assert!(source.contains("pub static INLINE_TRI_ANGLE_POSITIONS_I16"));
    assert!(
        source.contains("pub static INLINE_TRI_ANGLE_FACE_PLANES: [[i16; 4]; 1]")
            && source.contains("with_face_planes(&INLINE_TRI_ANGLE_FACE_PLANES)")
    );

    for bad in
        [&[][..], &[s][..], &[s, "-o"][..], &[s, "-o", o, "--quantize", "f16"][..], &[s, "-o", o, "--frobnicate"][..], &[s, s, "-o", o][..]]
    {
        let (code, _, stderr) = cli(bad);
        assert_eq!(code, 2, "{bad:?}: {stderr}");
        assert!(stderr.contains("usage: soft3d-bake"), "{stderr}");
    }
    let (code, stdout, _) = cli(&["--help"]);
    assert_eq!(code, 0);
    assert!(stdout.contains("--texture-format"));

    std::fs::write(dir.join("broken.babylon"), "{\"meshes\": [}").unwrap();
    for input in ["broken.babylon", "absent.babylon"] {
        let (code, _, stderr) = cli(&[dir.join(input).to_str().unwrap(), "-o", o]);
        assert_eq!(code, 1, "{stderr}");
        assert!(stderr.starts_with("soft3d-bake: error: ") && !stderr.contains("panicked"), "{stderr}");
    }
    let (code, _, stderr) = cli(&[s, "-o", o, "--textures", dir.join("nowhere").to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(stderr.contains("tiny.png"), "{stderr}");
}

/// `meshes` meshes of `vertices` vertices each (all at the origin, one triangle).
fn big_scene(meshes: usize, vertices: usize) -> String {
    let positions = vec!["0"; 3 * vertices].join(",");
    let mesh = format!(r#"{{"name": "m", "positions": [{positions}], "indices": [0, 1, 2]}}"#);
    format!(r#"{{"meshes": [{}]}}"#, vec![mesh; meshes].join(","))
}

#[test]
fn large_scenes_use_the_larger_loader_and_huge_ones_are_refused() {
    // 80,000 vertices: more than the small loader's 65,536.
    let baked = bake_babylon(big_scene(2, 40_000).as_bytes(), &Options::default()).unwrap();
    assert_eq!(baked.meshes.iter().map(|m| m.positions.len()).sum::<usize>(), 80_000);
    assert_eq!(baked.meshes[1].ident, "M_2");
    let e = bake_babylon(big_scene(17, 65_536).as_bytes(), &Options::default()).unwrap_err();
    assert!(matches!(e, BakeError::TooLarge { .. }), "{e:?}");
    assert!(e.to_string().contains("1114112 vertices"), "{e}");
}

#[test]
fn malformed_obj_and_mtl_never_panic() {
    let dir = scratch("obj-garbage");
    // tobj itself panics on this MTL line; the tool refuses it first.
    std::fs::write(dir.join("quad.obj"), OBJ).unwrap();
    std::fs::write(dir.join("quad.mtl"), "newmtl red\nKd 1 0\n").unwrap();
    let baked = bake_obj(&dir.join("quad.obj"), &Options::default()).unwrap();
    assert!(baked.warnings.iter().any(|w| w.contains("line 2: Kd needs three numbers")), "{:?}", baked.warnings);

    // Random statements: errors or bakes, never a panic.
    let obj_words =
        ["v", "vt", "vn", "f", "o", "g", "usemtl", "mtllib m.mtl", "s", "1", "-1", "0", "2/3", "1//2", "3/1/2", "-3", "1e40", "nan", "x"];
    let mtl_words = ["newmtl", "Kd", "Ka", "Ks", "Ke", "Ns", "d", "illum", "map_Kd", "bump", "1", "0.5", "-2", "x", "tex.png"];
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut pick = |n: usize| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % n as u64) as usize
    };
    let options = Options { texture_format: TextureFormat::None, quantize: Quantize::I16, ..Options::default() };
    for _ in 0..300 {
        let mut text = [String::new(), String::new()];
        for (t, words) in text.iter_mut().zip([&obj_words[..], &mtl_words[..]]) {
            for _ in 0..pick(40) {
                t.push_str(words[pick(words.len())]);
                t.push_str(if pick(4) == 0 { "\n" } else { " " });
            }
        }
        std::fs::write(dir.join("f.obj"), &text[0]).unwrap();
        std::fs::write(dir.join("m.mtl"), &text[1]).unwrap();
        if let Ok(baked) = bake_obj(&dir.join("f.obj"), &options) {
            let _ = baked.to_rust();
        }
    }
}
