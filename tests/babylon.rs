//! The `.babylon` loader: the real asset files, both mesh layouts, the
//! transform and camera conventions, and every error path (table-driven,
//! plus property tests on arbitrary and mutated input).
//!
//! The assets are read from `../shared/assets` and never copied into the
//! repository; tests that need them print a message and pass when they are
//! absent.
#![cfg(feature = "babylon")]

use proptest::prelude::*;
use soft3d::babylon::{
    euler_rotation, quaternion_rotation, requirements, BabylonScene, Container, Error, Item, JsonError, LightKind, Requirements, MAX_DEPTH,
    NAME_LEN,
};
use soft3d::math::{Vec2, Vec3};
use soft3d::Cull;
use std::sync::Mutex;

/// Generous host capacities (about 160 KB, boxed).
type HostScene = BabylonScene<16, 16, 16, 4096, 4096, 16384>;
/// Small capacities for the error tests.
type Small = BabylonScene<4, 4, 4, 64, 64, 192>;

const ASSETS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/assets");

fn asset(name: &str) -> Option<Vec<u8>> {
    let path = format!("{ASSETS}/{name}");
    match std::fs::read(&path) {
        Ok(bytes) => Some(bytes),
        Err(e) => {
            println!("skipped: {path} is not available ({e})");
            None
        }
    }
}

fn host(json: &[u8]) -> Box<HostScene> {
    let mut scene = Box::new(HostScene::new());
    scene.load(json).unwrap_or_else(|e| panic!("{e}"));
    scene
}

fn small(json: &str) -> Result<Box<Small>, Error> {
    let mut scene = Box::new(Small::new());
    scene.load(json.as_bytes()).map(|()| scene)
}

fn err(json: &str) -> Error {
    match small(json) {
        Ok(_) => panic!("loaded: {json}"),
        Err(e) => e,
    }
}

fn close(a: Vec3, b: Vec3, tol: f32) -> bool {
    (a - b).length() <= tol
}

#[track_caller]
fn assert_close(a: Vec3, b: Vec3, tol: f32) {
    assert!(close(a, b, tol), "{a:?} != {b:?} (tolerance {tol})");
}

// ---------------------------------------------------------------- assets

#[test]
fn monkey_loads_with_its_material_camera_and_light() {
    let Some(json) = asset("monkey.babylon") else { return };
    assert_eq!(requirements(&json).unwrap(), Requirements { meshes: 1, materials: 1, lights: 1, vertices: 886, uvs: 886, indices: 2898 });
    let scene = host(&json);
    assert_eq!(scene.meshes().len(), 1);
    let info = &scene.meshes()[0];
    assert_eq!(info.name.as_str(), "Suzanne");
    assert!(info.is_legacy() && info.has_uvs());
    assert_eq!(info.position, Vec3::new(0.001, 0.001, 0.001));
    let mesh = scene.mesh(0).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (886, 966));
    // First vertex: position, normal (normalized), uv, as interleaved in the file.
    assert_eq!(mesh.position(0), Vec3::new(-0.4688, 0.3517, -0.7136));
    assert_close(mesh.normal(0), Vec3::new(-0.6826, 0.1047, -0.7232).normalize_or_zero(), 1e-6);
    assert_eq!(mesh.uvs().unwrap()[0], Vec2::new(0.4891, 0.8913));
    // The file's triangles are [0, 1, 2], [2, 3, 0], rewound for soft3d.
    assert_eq!(&mesh.indices()[..6], &[0, 2, 1, 2, 0, 3]);
    assert!(mesh.normals().iter().all(|n| (n.length() - 1.0).abs() < 1e-5));

    let material = scene.mesh_material(0).unwrap();
    assert_eq!(material.name.as_str(), "02 - Default");
    assert_eq!(material.diffuse_texture.as_deref(), Some("Suzanne.jpg"));
    assert_eq!(material.diffuse, Vec3::new(0.4706, 0.4706, 0.4706));
    assert_eq!(material.specular, Vec3::new(0.449, 0.449, 0.449));
    assert_eq!((material.specular_power, material.alpha, material.back_face_culling), (50.0, 1.0, true));

    let camera = scene.camera().unwrap();
    assert_eq!(camera.name.as_str(), "Camera");
    let c = scene.to_camera().unwrap();
    assert_eq!(c.position, Vec3::new(4.0768, 1.3828, -4.8015));
    assert_eq!(c.target, Vec3::new(-0.1386, 0.9719, 0.1904));
    assert_eq!((c.fov_y, c.near, c.far), (0.8576, 0.1, 100.0));
    assert_eq!(c.up, Vec3::new(0.0, 1.0, 0.0));

    // `"type": 0.0` with the position in the legacy `data`.
    assert_eq!(scene.lights().len(), 1);
    assert_eq!(scene.lights()[0].kind, LightKind::Point { position: Vec3::new(4.0762, 5.9039, 1.0055) });
    let lights = scene.to_lights();
    assert_eq!(lights.ambient, Vec3::ZERO);
    assert_eq!(lights.point.unwrap().color, Vec3::ONE);
    assert!(lights.directional.is_none());
}

#[test]
fn monkey_fits_exact_capacities() {
    let Some(json) = asset("monkey.babylon") else { return };
    let mut scene = Box::new(BabylonScene::<1, 1, 1, 886, 886, 2898>::new());
    scene.load(&json).unwrap();
    assert_eq!(scene.mesh(0).unwrap().triangle_count(), 966);
    // One vertex short: the error names the mesh, the pool and both sizes.
    let mut scene = Box::new(BabylonScene::<1, 1, 1, 885, 886, 2898>::new());
    let e = scene.load(&json).unwrap_err();
    match &e {
        Error::Capacity { container: Container::Vertices, at, capacity: 885, needed: 886 } => {
            assert_eq!((at.item, at.name.as_str(), at.field), (Item::Mesh(0), "Suzanne", Some("vertices")));
            assert_eq!(&json[at.offset.unwrap()..][..12], b"[-0.4688,0.3");
        }
        other => panic!("{other:?}"),
    }
    let message = e.to_string();
    assert!(message.starts_with("mesh 0 'Suzanne' vertices (byte "), "{message}");
    assert!(message.ends_with("capacity VERTICES = 885 is too small, 886 needed"), "{message}");
    // The scene is left empty after an error.
    assert!(scene.meshes().is_empty() && scene.camera().is_none());
}

#[test]
fn torus_loads_without_uvs_or_materials() {
    let Some(json) = asset("torus.babylon") else { return };
    let scene = host(&json);
    let mesh = scene.mesh(0).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (576, 1152));
    assert!(mesh.uvs().is_none());
    assert!(scene.materials().is_empty());
    assert_eq!(scene.meshes()[0].material(), None);
    assert_eq!(scene.to_camera().unwrap().target, Vec3::new(-0.3174, 0.8953, 0.3125));
    assert_eq!(requirements(&json).unwrap().uvs, 0);
}

#[test]
fn cube_loads_in_the_newer_layout() {
    let Some(json) = asset("cube.babylon") else { return };
    let scene = host(&json);
    let info = &scene.meshes()[0];
    assert_eq!(info.name.as_str(), "Cube");
    assert!(!info.is_legacy() && !info.has_uvs());
    assert_eq!((info.vertex_count(), info.index_count()), (8, 36));
    let mesh = scene.mesh(0).unwrap();
    assert_eq!(mesh.triangle_count(), 12);
    assert_eq!(mesh.position(1), Vec3::new(-1.0, -1.0, 1.0));
    assert_close(mesh.normal(1), Vec3::new(-1.0, -1.0, 1.0).normalize_or_zero(), 1e-6);

    let m = scene.mesh_material(0).unwrap();
    assert_eq!((m.name.as_str(), m.id.as_str()), ("box.Material", "box.Material"));
    assert_eq!(m.diffuse, Vec3::new(0.64, 0.64, 0.64));
    assert_eq!(m.specular, Vec3::new(0.5, 0.5, 0.5));
    assert_eq!(m.ambient, Vec3::new(0.8, 0.8, 0.8));
    assert_eq!((m.specular_power, m.alpha, m.back_face_culling, m.cull()), (50.0, 1.0, true, Cull::Back));
    assert!(m.diffuse_texture.is_none());
    assert_eq!(m.color(), embedded_graphics::pixelcolor::Rgb888::new(163, 163, 163));

    let camera = scene.camera().unwrap();
    assert_eq!(camera.target, None);
    assert_eq!(camera.rotation, Vec3::new(0.4615, -0.8149, 0.0));
    // forward = Ry(-0.8149) · Rx(0.4615) · (0, 0, 1), computed independently.
    let forward = camera.forward();
    assert_close(forward, Vec3::new(-0.651_533_6, -0.445_291_7, 0.614_181_8), 1e-5);
    // Blender's default camera looks near, not exactly at, the origin: the
    // view ray passes 0.54 from it, 2.8° off the direction to it.
    let to_origin = (-camera.position).normalize_or_zero();
    let degrees = forward.dot(to_origin).clamp(-1.0, 1.0).acos().to_degrees();
    assert!((degrees - 2.77).abs() < 0.05, "{degrees}°");
    let c = scene.to_camera().unwrap();
    assert_close(c.target, camera.position + forward, 1e-6);
    assert!(c.up.dot(forward).abs() < 1e-6 && c.up.y > 0.8, "{:?}", c.up);
    assert_eq!((c.fov_y, c.near, c.far), (0.8576, 0.1, 100.0));

    assert_eq!(scene.lights()[0].kind, LightKind::Point { position: Vec3::new(4.0762, 5.9039, 1.0055) });
    assert_eq!(scene.lights()[0].intensity, 1.0);
    assert_eq!(scene.clear_color(), Some(Vec3::new(0.0509, 0.0509, 0.0509)));
}

#[test]
fn every_asset_file_loads() {
    let Ok(dir) = std::fs::read_dir(ASSETS) else {
        println!("skipped: {ASSETS} is not available");
        return;
    };
    let mut n = 0;
    for entry in dir {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "babylon") {
            let json = std::fs::read(&path).unwrap();
            let scene = host(&json);
            assert!(scene.iter().count() >= 1, "{path:?}");
            assert!(scene.to_camera().is_some(), "{path:?}");
            n += 1;
        }
    }
    println!("{n} asset files loaded");
}

/// A scene of 2.4 MB kept in a `static` (it never touches the stack) loads
/// every asset and the largest mesh a `u16` index allows on the 2 MB test
/// thread.
#[test]
fn large_scene_in_a_static_does_not_touch_the_stack() {
    type Big = BabylonScene<64, 64, 64, 65536, 65536, 196608>;
    static BIG: Mutex<Big> = Mutex::new(Big::new());
    assert!(std::mem::size_of::<Big>() > 2 << 20);
    let mut scene = BIG.lock().unwrap();
    for name in ["monkey.babylon", "torus.babylon", "cube.babylon"] {
        if let Some(json) = asset(name) {
            scene.load(&json).unwrap();
        }
    }
    let json = grid(65536);
    scene.load(json.as_bytes()).unwrap();
    assert_eq!(scene.mesh(0).unwrap().vertex_count(), 65536);
    let json = grid(65537);
    assert!(matches!(scene.load(json.as_bytes()), Err(Error::TooManyVertices { count: 65537, .. })));
}

/// A mesh of `n` vertices on a line, one triangle.
fn grid(n: usize) -> String {
    let mut s = String::from(r#"{"meshes":[{"name":"grid","positions":["#);
    for i in 0..n {
        if i > 0 {
            s.push(',');
        }
        s.push_str(&format!("{i},0,0"));
    }
    s.push_str(r#"],"indices":[0,1,2]}]}"#);
    s
}

// ---------------------------------------------------------------- layouts

struct Quad {
    positions: [[f32; 3]; 4],
    normals: [[f32; 3]; 4],
    uvs: [[f32; 2]; 4],
}

const QUAD: Quad = Quad {
    positions: [[-1.0, -1.0, 0.5], [1.0, -1.0, 0.5], [1.0, 1.0, 0.5], [-1.0, 1.0, 0.5]],
    normals: [[0.0, 0.0, -2.0], [0.0, 0.5, -0.5], [0.0, 0.0, 0.0], [3.0, 0.0, -4.0]],
    uvs: [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.25, 0.75]],
};

fn list<const N: usize>(items: &[[f32; N]]) -> String {
    items.iter().flatten().map(|v| v.to_string()).collect::<Vec<_>>().join(",")
}

fn legacy(uv_count: usize) -> String {
    let mut v = Vec::new();
    for i in 0..4 {
        v.extend(QUAD.positions[i]);
        v.extend(QUAD.normals[i]);
        if uv_count >= 1 {
            v.extend(QUAD.uvs[i]);
        }
        if uv_count == 2 {
            v.extend([9.0, 9.0]);
        }
    }
    let v = v.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(",");
    let uv = if uv_count == 0 { String::new() } else { format!(r#""uvCount":{uv_count},"#) };
    format!(r#"{{"meshes":[{{"name":"q",{uv}"vertices":[{v}],"indices":[0,1,2,0,2,3]}}]}}"#)
}

fn separate(uvs: bool) -> String {
    let uv = if uvs { format!(r#","uvs":[{}]"#, list(&QUAD.uvs)) } else { String::new() };
    format!(
        r#"{{"meshes":[{{"name":"q","positions":[{}],"normals":[{}]{uv},"indices":[0,1,2,0,2,3]}}]}}"#,
        list(&QUAD.positions),
        list(&QUAD.normals)
    )
}

#[test]
fn legacy_and_separate_layouts_give_identical_meshes() {
    for (legacy_json, separate_json) in [(legacy(1), separate(true)), (legacy(2), separate(true)), (legacy(0), separate(false))] {
        let (a, b) = (small(&legacy_json).unwrap(), small(&separate_json).unwrap());
        let (ma, mb) = (a.mesh(0).unwrap(), b.mesh(0).unwrap());
        assert_eq!(ma.positions(), mb.positions());
        assert_eq!(ma.normals(), mb.normals());
        assert_eq!(ma.uvs(), mb.uvs());
        assert_eq!(ma.indices(), mb.indices());
        assert!(a.meshes()[0].is_legacy() && !b.meshes()[0].is_legacy());
    }
    let scene = small(&legacy(2)).unwrap();
    let mesh = scene.mesh(0).unwrap();
    // Stride 10: the first uv set is kept, the second (all 9s) dropped.
    assert_eq!(mesh.uvs().unwrap()[3], Vec2::new(0.25, 0.75));
    assert_eq!(mesh.position(2), Vec3::new(1.0, 1.0, 0.5));
    // Normalized on load; a zero normal stays zero.
    assert_eq!(mesh.normal(0), Vec3::new(0.0, 0.0, -1.0));
    assert_close(mesh.normal(1), Vec3::new(0.0, 0.70710677, -0.70710677), 1e-7);
    assert_eq!(mesh.normal(2), Vec3::ZERO);
    assert_eq!(mesh.normal(3), Vec3::new(0.6, 0.0, -0.8));
    // `uvCount` absent means 0 (stride 6).
    let no_count = legacy(0);
    assert!(!no_count.contains("uvCount") && small(&no_count).unwrap().mesh(0).unwrap().uvs().is_none());
}

#[test]
fn missing_normals_are_computed_from_the_triangles() {
    let json = r#"{"meshes":[{"positions":[0,0,0, 1,0,0, 0,1,0, 5,5,5],"indices":[0,2,1]}]}"#;
    let scene = small(json).unwrap();
    let n = scene.mesh(0).unwrap().normals().as_f32().unwrap();
    // In the file (b - a) × (c - a) for a = 0, b = (0,1,0), c = (1,0,0) is
    // -z, and Babylon's front side is the opposite one (its
    // ComputeNormals gives +z); vertex 3 is in no triangle.
    assert_eq!(n, &[Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 0.0, 1.0), Vec3::ZERO]);
}

#[test]
fn several_meshes_share_the_pools() {
    let json = format!(
        r#"{{"meshes":[{},{},{}]}}"#,
        r#"{"name":"a","positions":[0,0,0,1,0,0,0,1,0],"uvs":[0,0,1,0,0,1],"indices":[0,1,2]}"#,
        r#"{"name":"b","uvCount":0,"vertices":[0,0,2,0,0,-1, 1,0,2,0,0,-1, 0,1,2,0,0,-1, 1,1,2,0,0,-1],"indices":[0,1,2,1,3,2]}"#,
        r#"{"name":"c","positions":[0,0,3,1,0,3,0,1,3],"normals":[0,0,1,0,0,1,0,0,1],"uvs":[0.5,0.5,1,1,0,0],"indices":[2,1,0]}"#
    );
    assert_eq!(
        requirements(json.as_bytes()).unwrap(),
        Requirements { meshes: 3, materials: 0, lights: 0, vertices: 10, uvs: 6, indices: 12 }
    );
    let scene = small(&json).unwrap();
    let names: Vec<_> = scene.iter().map(|m| (m.info.name.clone(), m.mesh.vertex_count(), m.mesh.uvs().is_some())).collect();
    assert_eq!(names.len(), 3);
    assert_eq!((names[1].1, names[1].2, names[2].1), (4, false, 3));
    let c = scene.mesh(2).unwrap();
    assert_eq!(c.position(0), Vec3::new(0.0, 0.0, 3.0));
    assert_eq!(c.uvs().unwrap()[0], Vec2::new(0.5, 0.5));
    // Rewound: the last two corners of every triangle swapped.
    assert_eq!(c.indices(), &[2, 0, 1]);
    let b = scene.mesh(1).unwrap();
    assert_eq!(b.indices(), &[0, 2, 1, 1, 2, 3]);
}

// ---------------------------------------------------------------- transforms

/// Babylon's `Quaternion.RotationYawPitchRoll`, applied as `q v q*`: an
/// oracle independent of `Mat4`.
fn babylon_rotate(rotation: Vec3, v: Vec3) -> Vec3 {
    let (hr, hp, hy) = (rotation.z * 0.5, rotation.x * 0.5, rotation.y * 0.5);
    let (sr, cr, sp, cp, sy, cy) = (hr.sin(), hr.cos(), hp.sin(), hp.cos(), hy.sin(), hy.cos());
    let q = [cy * sp * cr + sy * cp * sr, sy * cp * cr - cy * sp * sr, cy * cp * sr - sy * sp * cr, cy * cp * cr + sy * sp * sr];
    let u = Vec3::new(q[0], q[1], q[2]);
    let w = q[3];
    // v + 2w (u × v) + 2 u × (u × v)
    let t = u.cross(v) * 2.0;
    v + t * w + u.cross(t)
}

#[test]
fn rotated_cube_vertices_land_where_babylon_puts_them() {
    let json = r#"{"meshes":[{"name":"box","position":[1,2,3],"rotation":[0.3,-1.1,0.7],"scaling":[2,1,0.5],
        "positions":[1,-1,-1,-1,-1,1,1,-1,1,-1,1,1,1,1,-1,1,1,1,-1,-1,-1,-1,1,-1],"indices":[0,1,2]}]}"#;
    let scene = small(json).unwrap();
    let item = scene.iter().next().unwrap();
    let (r, s, t) = (Vec3::new(0.3, -1.1, 0.7), Vec3::new(2.0, 1.0, 0.5), Vec3::new(1.0, 2.0, 3.0));
    for p in item.mesh.positions().iter() {
        let expected = babylon_rotate(r, p.mul_elem(s)) + t;
        assert_close(item.model.transform_point3(p), expected, 1e-5);
    }
    // By hand: pitch π/2 turns +y to +z, then yaw π/2 turns +z to +x.
    let h = core::f32::consts::FRAC_PI_2;
    assert_close(euler_rotation(Vec3::new(h, h, 0.0)).transform_point3(Vec3::new(0.0, 1.0, 0.0)), Vec3::new(1.0, 0.0, 0.0), 1e-6);
    // Roll π/2 turns +x to +y.
    assert_close(euler_rotation(Vec3::new(0.0, 0.0, h)).transform_point3(Vec3::new(1.0, 0.0, 0.0)), Vec3::new(0.0, 1.0, 0.0), 1e-6);
    // Absent transform fields are the identity.
    let plain = small(r#"{"meshes":[{"positions":[1,2,3],"indices":[]}]}"#).unwrap();
    assert_eq!(plain.meshes()[0].model_matrix(), soft3d::math::Mat4::IDENTITY);
}

#[test]
fn rotation_quaternion_replaces_rotation() {
    // A quarter turn about y (yaw): +z goes to +x.
    let s = core::f32::consts::FRAC_1_SQRT_2;
    let json = format!(r#"{{"meshes":[{{"rotation":[1,2,3],"rotationQuaternion":[0,{s},0,{s}],"positions":[0,0,1],"indices":[]}}]}}"#);
    let scene = small(&json).unwrap();
    let m = scene.meshes()[0].model_matrix();
    assert_close(m.transform_point3(Vec3::new(0.0, 0.0, 1.0)), Vec3::new(1.0, 0.0, 0.0), 1e-6);
    assert_eq!(quaternion_rotation([0.0; 4]), soft3d::math::Mat4::IDENTITY);
}

// ---------------------------------------------------------------- camera, lights, materials

#[test]
fn camera_defaults_and_active_camera() {
    let json = r#"{"cameras":[{"name":"a","id":"a","position":[0,0,-1]},{"name":"b","id":"b","position":[0,0,-2],"target":[0,0,0],"fov":1.2}],
        "activeCamera":"b"}"#;
    let c = small(json).unwrap().to_camera().unwrap();
    assert_eq!((c.position, c.fov_y, c.near, c.far), (Vec3::new(0.0, 0.0, -2.0), 1.2, 1.0, 10000.0));
    // Unknown or absent active camera: the first, with Babylon's defaults.
    for json in [
        r#"{"cameras":[{"id":"a","position":[0,0,-1]},{"id":"b"}],"activeCamera":"zz"}"#,
        r#"{"cameras":[{"id":"a","position":[0,0,-1]},{"id":"b"}]}"#,
    ] {
        let scene = small(json).unwrap();
        let cam = scene.camera().unwrap();
        assert_eq!((cam.id.as_str(), cam.fov, cam.min_z, cam.max_z), ("a", 0.8, 1.0, 10000.0));
        // No target, no rotation: looking down +z.
        assert_eq!(scene.to_camera().unwrap().target, Vec3::new(0.0, 0.0, 0.0));
    }
    // activeCameraID (the name Babylon's loader reads) works too.
    let json = r#"{"activeCameraID":"b","cameras":[{"id":"a"},{"id":"b","position":[5,0,0]}]}"#;
    assert_eq!(small(json).unwrap().to_camera().unwrap().position, Vec3::new(5.0, 0.0, 0.0));
    // Rotation cameras rotate the up vector too: roll π/2 turns +y to -x.
    let json = r#"{"cameras":[{"position":[0,0,0],"rotation":[0,0,1.5707964]}]}"#;
    let c = small(json).unwrap().to_camera().unwrap();
    assert_close(c.up, Vec3::new(-1.0, 0.0, 0.0), 1e-6);
    assert_close(c.target, Vec3::new(0.0, 0.0, 1.0), 1e-6);
    assert!(small("{}").unwrap().to_camera().is_none());
}

#[test]
fn lights_of_each_type() {
    let json = r#"{"ambientColor":[0.1,0.2,0.3],"lights":[
        {"name":"spot","type":2,"position":[0,9,0],"direction":[0,-1,0]},
        {"name":"sun","type":1,"data":[0,-1,0],"intensity":0.5,"diffuse":[1,0.5,0]},
        {"name":"hemi","type":3,"direction":[0,1,0]},
        {"name":"bulb","type":0,"position":[1,2,3],"intensity":2,"specular":[0,0,1]},
        {"name":"sun2","type":1,"direction":[1,0,0]},
        {"name":"none"}]}"#;
    let scene = small(json).unwrap();
    assert_eq!(scene.skipped_lights(), 3);
    assert_eq!(requirements(json.as_bytes()).unwrap().lights, 3);
    let names: Vec<_> = scene.lights().iter().map(|l| l.name.as_str()).collect();
    assert_eq!(names, ["sun", "bulb", "sun2"]);
    assert_eq!(scene.lights()[1].specular, Vec3::new(0.0, 0.0, 1.0));
    let lights = scene.to_lights();
    assert_eq!(lights.ambient, Vec3::new(0.1, 0.2, 0.3));
    let point = lights.point.unwrap();
    assert_eq!((point.position, point.color), (Vec3::new(1.0, 2.0, 3.0), Vec3::new(2.0, 2.0, 2.0)));
    let sun = lights.directional.unwrap();
    assert_eq!((sun.direction, sun.color), (Vec3::new(0.0, -1.0, 0.0), Vec3::new(0.5, 0.25, 0.0)));
}

#[test]
fn material_defaults_and_resolution() {
    let json = r#"{"materials":[{"name":"plain","id":"m1"},{"name":"two","id":"m2","backFaceCulling":false,"diffuse":[2,-1,0.5,1],
        "diffuseTexture":{"level":1,"name":"a\/b \u00e9.png"}}],
        "meshes":[{"materialId":"m2","positions":[],"indices":[]},{"materialId":"nope"},{"materialId":null}]}"#;
    let scene = small(json).unwrap();
    let m = &scene.materials()[0];
    assert_eq!((m.diffuse, m.specular, m.specular_power, m.alpha, m.back_face_culling), (Vec3::ONE, Vec3::ONE, 64.0, 1.0, true));
    assert_eq!((m.ambient, m.emissive), (Vec3::ZERO, Vec3::ZERO));
    assert_eq!(scene.meshes().iter().map(|m| m.material()).collect::<Vec<_>>(), [Some(1), None, None]);
    let two = scene.mesh_material(0).unwrap();
    assert_eq!((two.cull(), two.diffuse_texture.as_deref()), (Cull::None, Some("a/b é.png")));
    assert_eq!(two.color(), embedded_graphics::pixelcolor::Rgb888::new(255, 0, 128));
    // An empty mesh is a valid mesh with nothing to draw.
    assert_eq!(scene.mesh(1).unwrap().triangle_count(), 0);
}

#[test]
fn unknown_fields_and_nulls_are_skipped() {
    let json = r#"{"producer":{"name":"x","deep":[[[{"a":[1e999]}]]]},"meshes":[{"name":"m","animations":[{"keys":[{"values":[1,2]}]}],
        "tags":"","position":null,"positions":[0,0,0,1,0,0,0,1,0],"weird":true,"indices":[0,1,2],"instances":[],"subMeshes":[
        {"materialIndex":0,"verticesStart":0,"verticesCount":3,"indexStart":0,"indexCount":3}]}],"gravity":[0,-9.81,0],"x":null}"#;
    let scene = small(json).unwrap();
    assert_eq!(scene.meshes()[0].position, Vec3::ZERO);
    assert_eq!(scene.mesh(0).unwrap().triangle_count(), 1);
}

// ---------------------------------------------------------------- errors

const VALID: &str = r#"{"materials":[{"name":"m","id":"m","diffuse":[1,0.5,0]}],"meshes":[{"name":"tri","materialId":"m","uvCount":1,"vertices":[0,0,0,0,0,-1,0,0,1,0,0,0,0,-1,1,0,0,1,0,0,0,-1,0,1],"indices":[0,2,1]}],"cameras":[{"name":"c","position":[0,0,-3],"target":[0,0,0]}],"lights":[{"name":"l","type":0,"position":[0,5,0]}]}"#;

#[test]
fn every_prefix_of_a_valid_file_is_an_error() {
    assert!(small(VALID).is_ok());
    for n in 0..VALID.len() {
        let e = err(&VALID[..n]);
        assert!(matches!(e, Error::Json { .. }), "prefix {n}: {e:?}");
        assert!(e.offset().is_some_and(|o| o <= n), "prefix {n}: {e:?}");
    }
    assert!(matches!(err(""), Error::Json { kind: JsonError::EofWhileParsingValue, .. }));
    assert!(matches!(err(&VALID[..VALID.len() - 1]), Error::Json { kind: JsonError::EofWhileParsingObject, .. }));
    if let Some(json) = asset("cube.babylon") {
        let json = std::str::from_utf8(&json).unwrap().trim_end();
        for n in 0..json.len() {
            assert!(matches!(err(&json[..n]), Error::Json { .. }), "cube prefix {n}");
        }
    }
}

/// One expected error: the JSON, and a check of the error.
type Case = (&'static str, fn(&Error) -> bool);

fn at(e: &Error) -> (&Item, &str, Option<&'static str>, Option<usize>) {
    let l = e.location().unwrap();
    (&l.item, l.name.as_str(), l.field, l.element)
}

#[test]
fn error_table() {
    let cases: &[Case] = &[
        // Garbage and malformed JSON, with serde-json-core's kinds and offsets.
        ("\u{0}\u{1}garbage", |e| matches!(e, Error::Json { kind: JsonError::ExpectedSomeValue, .. }) && e.offset() == Some(0)),
        ("hello", |e| matches!(e, Error::Json { kind: JsonError::ExpectedSomeValue, .. })),
        (r#"{"meshes":[{"name":"a"}]} {"#, |e| {
            matches!(e, Error::Json { kind: JsonError::TrailingCharacters, .. }) && e.offset() == Some(26)
        }),
        (r#"{"meshes":[1,]}"#, |e| matches!(e, Error::Json { kind: JsonError::TrailingComma, .. }) && e.offset() == Some(13)),
        (r#"{"a":NaN}"#, |e| matches!(e, Error::Json { kind: JsonError::ExpectedSomeValue, .. }) && e.offset() == Some(5)),
        (r#"{"a":"\q"}"#, |e| matches!(e, Error::Json { kind: JsonError::InvalidEscapeSequence, .. }) && e.offset() == Some(6)),
        (r#"{"a":01}"#, |e| matches!(e, Error::Json { kind: JsonError::InvalidNumber, .. })),
        // Wrong types: found by serde-json-core, located by the loader.
        (r#"{"meshes":[{"name":"m","positions":"abc"}]}"#, |e| {
            matches!(e, Error::Json { kind: JsonError::InvalidType, .. })
                && at(e) == (&Item::Mesh(0), "m", Some("positions"), None)
                && e.offset() == Some(35)
        }),
        (r#"{"meshes":[{"name":5}]}"#, |e| matches!(e, Error::Json { kind: JsonError::InvalidType, .. }) && at(e).2 == Some("name")),
        // serde-json-core reads a number's characters, finds none: InvalidNumber.
        (r#"{"meshes":[{"positions":[0,"x",0]}]}"#, |e| {
            matches!(e, Error::Json { kind: JsonError::InvalidNumber, .. }) && at(e).3 == Some(1) && e.offset() == Some(27)
        }),
        (r#"{"meshes":{}}"#, |e| {
            matches!(e, Error::Json { kind: JsonError::InvalidType, .. }) && at(e) == (&Item::Scene, "", Some("meshes"), None)
        }),
        (r#"{"meshes":[7]}"#, |e| matches!(e, Error::Json { kind: JsonError::InvalidType, .. }) && at(e).0 == &Item::Mesh(0)),
        ("[1,2,3]", |e| matches!(e, Error::Json { kind: JsonError::InvalidType, .. })),
        (r#"{"materials":[{"name":"m","backFaceCulling":"yes"}]}"#, |e| {
            matches!(e, Error::Json { kind: JsonError::InvalidType, .. })
                && at(e) == (&Item::Material(0), "m", Some("backFaceCulling"), None)
        }),
        (r#"{"lights":[{"type":"point"}]}"#, |e| {
            matches!(e, Error::Json { kind: JsonError::InvalidNumber, .. }) && at(e).2 == Some("type")
        }),
        (r#"{"meshes":[{"uvCount":"1","vertices":[]}]}"#, |e| {
            matches!(e, Error::Json { kind: JsonError::InvalidNumber, .. }) && at(e).2 == Some("uvCount")
        }),
        (r#"{"meshes":[{"positions":[[0],0,0]}]}"#, |e| {
            matches!(e, Error::Json { kind: JsonError::InvalidNumber, .. }) && at(e).3 == Some(0)
        }),
        (r#"{"materials":[{"diffuseTexture":{"name":7}}]}"#, |e| {
            matches!(e, Error::Json { kind: JsonError::InvalidType, .. })
                && at(e).2 == Some("diffuseTexture.name")
                && e.offset() == Some(40)
        }),
        // Indices.
        (r#"{"meshes":[{"name":"t","positions":[0,0,0,1,0,0,0,1,0],"indices":[0,1,2,2,1,3]}]}"#, |e| {
            matches!(e, Error::IndexOutOfRange { index: 3, vertices: 3, .. }) && at(e) == (&Item::Mesh(0), "t", Some("indices"), Some(5))
        }),
        (r#"{"meshes":[{"positions":[0,0,0],"indices":[0,-1,0]}]}"#, |e| {
            matches!(e, Error::IndexOutOfRange { index: -1, vertices: 1, .. })
        }),
        (r#"{"meshes":[{"positions":[0,0,0],"indices":[0,0,70000]}]}"#, |e| matches!(e, Error::IndexOutOfRange { index: 70000, .. })),
        (r#"{"meshes":[{"positions":[0,0,0],"indices":[0,0.5,0]}]}"#, |e| {
            matches!(e, Error::Json { kind: JsonError::InvalidNumber, .. }) && at(e).3 == Some(1)
        }),
        (r#"{"meshes":[{"positions":[0,0,0],"indices":[0,0,0,0]}]}"#, |e| {
            matches!(e, Error::IndexCount { count: 4, .. }) && at(e).2 == Some("indices")
        }),
        // Strides and attribute lengths.
        (r#"{"meshes":[{"name":"s","vertices":[0,0,0,0,0,1,0]}]}"#, |e| {
            matches!(e, Error::Stride { len: 7, stride: 6, .. })
                && at(e) == (&Item::Mesh(0), "s", Some("vertices"), None)
                && e.offset() == Some(34)
        }),
        (r#"{"meshes":[{"uvCount":2,"vertices":[0,0,0,0,0,1,0,0]}]}"#, |e| matches!(e, Error::Stride { len: 8, stride: 10, .. })),
        (r#"{"meshes":[{"positions":[0,0,0,1]}]}"#, |e| matches!(e, Error::Stride { len: 4, stride: 3, .. })),
        (r#"{"meshes":[{"positions":[0,0,0],"uvs":[1]}]}"#, |e| {
            matches!(e, Error::Stride { len: 1, stride: 2, .. }) && at(e).2 == Some("uvs")
        }),
        (r#"{"meshes":[{"positions":[0,0,0],"normals":[0,0,1,0,0,1]}]}"#, |e| {
            matches!(e, Error::AttributeLength { len: 2, expected: 1, .. }) && at(e).2 == Some("normals")
        }),
        (r#"{"meshes":[{"uvCount":3,"vertices":[]}]}"#, |e| matches!(e, Error::Invalid { problem: "uvCount must be 0, 1 or 2", .. })),
        (r#"{"meshes":[{"vertices":[],"positions":[]}]}"#, |e| matches!(e, Error::Invalid { .. }) && at(e).2 == Some("vertices")),
        (r#"{"meshes":[{"positions":[],"positions":[]}]}"#, |e| {
            matches!(e, Error::Invalid { problem: "duplicate field", .. }) && e.offset() == Some(39)
        }),
        (r#"{"meshes":[],"meshes":[]}"#, |e| matches!(e, Error::Invalid { problem: "duplicate field", .. }) && at(e).2 == Some("meshes")),
        (r#"{"meshes":[{"position":[1,2]}]}"#, |e| {
            matches!(e, Error::Invalid { problem: "expected 3 numbers", .. }) && at(e).2 == Some("position")
        }),
        (r#"{"meshes":[{"scaling":[1,2,3,4]}]}"#, |e| matches!(e, Error::Invalid { problem: "expected 3 numbers", .. })),
        (r#"{"meshes":[{"positions":[0,0,0],"indices":[],"subMeshes":[{"verticesStart":0,"verticesCount":2}]}]}"#, |e| {
            matches!(e, Error::Invalid { problem: "subMesh range outside the mesh", .. })
                && at(e).2 == Some("subMeshes")
                && at(e).3 == Some(0)
        }),
        // Non-finite numbers: too large for f32, or null inside a number array.
        (r#"{"meshes":[{"name":"big","positions":[0,1e999,0]}]}"#, |e| {
            matches!(e, Error::NonFinite { .. }) && at(e) == (&Item::Mesh(0), "big", Some("positions"), Some(1)) && e.offset() == Some(40)
        }),
        (r#"{"meshes":[{"positions":[0,3.5e38,0]}]}"#, |e| matches!(e, Error::NonFinite { .. })),
        (r#"{"meshes":[{"positions":[0,null,0]}]}"#, |e| matches!(e, Error::NonFinite { .. })),
        (r#"{"meshes":[{"positions":[0,0,0],"indices":[0,0,1e999]}]}"#, |e| matches!(e, Error::NonFinite { .. }) && at(e).3 == Some(2)),
        (r#"{"cameras":[{"name":"c","fov":-1e40}]}"#, |e| {
            matches!(e, Error::NonFinite { .. }) && at(e) == (&Item::Camera(0), "c", Some("fov"), None)
        }),
        (r#"{"lights":[{"type":0,"diffuse":[1,1,1e400]}]}"#, |e| matches!(e, Error::NonFinite { .. }) && at(e).3 == Some(2)),
        (r#"{"ambientColor":[1e39,0,0]}"#, |e| {
            matches!(e, Error::NonFinite { .. }) && at(e) == (&Item::Scene, "", Some("ambientColor"), Some(0))
        }),
        // Capacities (Small: 4 meshes, 4 materials, 4 lights, 64 vertices, 64 uvs, 192 indices).
        (r#"{"meshes":[{},{},{},{},{}]}"#, |e| {
            matches!(e, Error::Capacity { container: Container::Meshes, capacity: 4, needed: 5, .. }) && e.offset() == Some(10)
        }),
        (r#"{"materials":[{},{},{},{},{},{}]}"#, |e| {
            matches!(e, Error::Capacity { container: Container::Materials, capacity: 4, needed: 6, .. })
        }),
        (r#"{"lights":[{"type":0},{"type":1},{"type":2},{"type":0},{"type":0},{"type":1}]}"#, |e| {
            matches!(e, Error::Capacity { container: Container::Lights, capacity: 4, needed: 5, .. })
        }),
        (r#"{"meshes":[{"name":"x","indices":[]},{"name":"y","indices":[0,0,0]}]}"#, |e| {
            matches!(e, Error::IndexOutOfRange { vertices: 0, .. })
        }),
        (r#"{"meshes":[{"name":"0123456789012345678901234567890123456789012345678901234567890123456789"}]}"#, |e| {
            matches!(e, Error::Capacity { container: Container::Name, capacity: NAME_LEN, needed: 70, .. }) && at(e).2 == Some("name")
        }),
        // Nesting.
        (
            r#"{"a":[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]}"#,
            |e| matches!(e, Error::TooDeep { depth, offset } if *depth == MAX_DEPTH + 1 && *offset == 5 + MAX_DEPTH - 1),
        ),
    ];
    for (json, check) in cases {
        let e = err(json);
        assert!(check(&e), "{json}\n  gave {e:?}\n  ({e})");
        // Every error prints its location.
        assert!(!e.to_string().is_empty());
    }
}

#[test]
fn indices_may_come_before_positions() {
    // The pre-scan knows the vertex count before the indices are read.
    let scene = small(r#"{"meshes":[{"indices":[0,1,1],"positions":[0,0,0,1,1,1]}]}"#).unwrap();
    assert_eq!(scene.mesh(0).unwrap().indices(), &[0, 1, 1]);
}

#[test]
fn pool_capacity_errors_name_the_first_mesh_that_overflows() {
    // 40 + 40 vertices in a 64-vertex pool: mesh 1 overflows, 80 needed.
    let line = |n: usize| (0..n).map(|i| format!("{i},0,0")).collect::<Vec<_>>().join(",");
    let json = format!(r#"{{"meshes":[{{"name":"a","positions":[{}]}},{{"name":"b","positions":[{}]}}]}}"#, line(40), line(40));
    let e = err(&json);
    match &e {
        Error::Capacity { container: Container::Vertices, at, capacity: 64, needed: 80 } => {
            assert_eq!((at.item, at.name.as_str(), at.field), (Item::Mesh(1), "b", Some("positions")));
            assert_eq!(&json.as_bytes()[at.offset.unwrap()..][..4], b"[0,0");
        }
        other => panic!("{other:?}"),
    }
    assert!(e.to_string().contains("mesh 1 'b' positions"), "{e}");
    assert!(e.to_string().contains("VERTICES = 64 is too small, 80 needed"), "{e}");
    // 70 uvs in a 64-uv pool (legacy uvCount 1).
    let verts = (0..35).map(|_| "0,0,0,0,0,1,0,0").collect::<Vec<_>>().join(",");
    let json = format!(r#"{{"meshes":[{{"name":"u","uvCount":1,"vertices":[{verts}]}},{{"name":"v","uvCount":1,"vertices":[{verts}]}}]}}"#);
    let mut roomy = Box::new(BabylonScene::<4, 4, 4, 128, 64, 192>::new());
    match roomy.load(json.as_bytes()) {
        Err(Error::Capacity { container: Container::Uvs, at, capacity: 64, needed: 70 }) => assert_eq!(at.name.as_str(), "v"),
        other => panic!("{other:?}"),
    }
    // Separate layout: the uvs array is named and located.
    let uvs = (0..35).map(|_| "0,0").collect::<Vec<_>>().join(",");
    let pos = (0..35).map(|_| "0,0,0").collect::<Vec<_>>().join(",");
    let mesh = format!(r#"{{"name":"w","positions":[{pos}],"uvs":[{uvs}]}}"#);
    let json = format!(r#"{{"meshes":[{mesh},{mesh}]}}"#);
    match roomy.load(json.as_bytes()) {
        Err(Error::Capacity { container: Container::Uvs, at, .. }) => {
            assert_eq!(at.field, Some("uvs"));
            assert_eq!(at.offset, Some(json.rfind(r#""uvs":"#).unwrap() + 6));
        }
        other => panic!("{other:?}"),
    }
    // 195 indices in a 192-index pool.
    let idx = vec!["0"; 195].join(",");
    let json = format!(r#"{{"meshes":[{{"name":"i","positions":[0,0,0],"indices":[{idx}]}}]}}"#);
    match err(&json) {
        Error::Capacity { container: Container::Indices, at, capacity: 192, needed: 195 } => {
            assert_eq!((at.name.as_str(), at.field), ("i", Some("indices")));
            assert_eq!(json.as_bytes()[at.offset.unwrap()], b'[');
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn hundred_thousand_deep_nesting_is_refused_before_parsing() {
    const N: usize = 100_000;
    for prefix in [r#"{"x":"#, r#"{"meshes":[{"name":"m","extra":"#] {
        let json = format!("{prefix}{}{}}}", "[".repeat(N), "]".repeat(N));
        let e = err(&json);
        // The root and the enclosing levels count: the bracket that reaches
        // MAX_DEPTH + 1 is named.
        let open = prefix.matches(['{', '[']).count();
        assert_eq!(e, Error::TooDeep { depth: MAX_DEPTH + 1, offset: prefix.len() + MAX_DEPTH - open });
        assert_eq!(
            e.to_string(),
            format!("nesting depth {} at byte {} exceeds the limit of {MAX_DEPTH}", MAX_DEPTH + 1, e.offset().unwrap())
        );
        assert!(requirements(json.as_bytes()).is_err());
    }
    // Objects nest the same way.
    let json = format!("{}1{}", r#"{"a":"#.repeat(N), "}".repeat(N));
    assert!(matches!(err(&json), Error::TooDeep { .. }));
    // Exactly MAX_DEPTH levels are fine.
    let json = format!(r#"{{"x":{}{}}}"#, "[".repeat(MAX_DEPTH - 1), "]".repeat(MAX_DEPTH - 1));
    assert!(small(&json).is_ok());
}

#[test]
fn invalid_utf8_is_refused_where_it_is() {
    let mut scene = Box::new(Small::new());
    let mut json = br#"{"meshes":[{"name":"ab","positions":[]}]}"#.to_vec();
    json[21] = 0xff; // inside "ab"
    match scene.load(&json) {
        Err(Error::Json { kind: JsonError::InvalidUnicodeCodePoint, at }) => assert_eq!(at.offset, Some(21)),
        other => panic!("{other:?}"),
    }
    // A truncated multi-byte sequence, and bytes outside strings.
    let json = b"{\"a\":\"\xc3\"}";
    assert!(matches!(scene.load(json), Err(Error::Json { kind: JsonError::InvalidUnicodeCodePoint, .. })));
    assert!(matches!(scene.load(b"{\xff:1}"), Err(Error::Json { kind: JsonError::KeyMustBeAString, .. })));
    // An unknown field's string is checked too (Babylon would refuse the file).
    assert!(matches!(scene.load(b"{\"tags\":\"\xe2\x82\"}"), Err(Error::Json { kind: JsonError::InvalidUnicodeCodePoint, .. })));
}

#[test]
fn errors_say_what_and_where() {
    fn is_std_error<E: std::error::Error>(_: &E) {}
    let e = err(r#"{"meshes":[{"name":"Suzanne","positions":[0,0,0],"indices":[0,0,9]}]}"#);
    is_std_error(&e);
    assert_eq!(e.to_string(), "mesh 0 'Suzanne' indices[2] (byte 64): index 9 is out of range (the mesh has 1 vertices)");
    let e = err(r#"{"meshes":[{"name":"m","positions":"abc"}]}"#);
    assert_eq!(e.to_string(), "mesh 0 'm' positions (byte 35): JSON error: Invalid type");
    let e = err(r#"{"meshes":[{"positions":[0,0,1e999]}]}"#);
    assert_eq!(e.to_string(), "mesh 0 positions[2] (byte 29): not a finite f32 (too large, or null)");
    let e = err(r#"{"meshes":[}"#);
    assert_eq!(e.to_string(), "scene (byte 11): JSON error: Expected this character to start a JSON value.");
}

#[test]
fn a_failed_load_leaves_the_scene_empty() {
    let mut scene = Box::new(Small::new());
    scene.load(VALID.as_bytes()).unwrap();
    assert_eq!((scene.meshes().len(), scene.materials().len(), scene.lights().len()), (1, 1, 1));
    assert!(scene.load(br#"{"meshes":[{"positions":[0,0,0],"indices":[0,0,5]}]}"#).is_err());
    assert!(scene.meshes().is_empty() && scene.materials().is_empty() && scene.lights().is_empty() && scene.camera().is_none());
    // And a scene can be loaded again.
    scene.load(VALID.as_bytes()).unwrap();
    assert_eq!(scene.mesh(0).unwrap().triangle_count(), 1);
    assert_eq!(Small::CAPACITY.vertices, 64);
}

/// Loads arbitrary bytes; on success builds every mesh. Never panics.
fn exercise(bytes: &[u8]) {
    let mut scene = Box::new(Small::new());
    if scene.load(bytes).is_ok() {
        assert_eq!(scene.iter().count(), scene.meshes().len());
        let _ = (scene.to_camera(), scene.to_lights());
    } else {
        assert!(scene.meshes().is_empty());
    }
    let _ = requirements(bytes);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        exercise(&bytes);
    }

    #[test]
    fn arbitrary_json_tokens_never_panic(tokens in proptest::collection::vec(prop_oneof![
        Just("{"), Just("}"), Just("["), Just("]"), Just(","), Just(":"), Just("\"meshes\""), Just("\"positions\""),
        Just("\"indices\""), Just("\"vertices\""), Just("\"uvCount\""), Just("\"normals\""), Just("\"uvs\""), Just("\"lights\""),
        Just("\"type\""), Just("\"cameras\""), Just("\"name\""), Just("0"), Just("1"), Just("2"), Just("-1"), Just("0.5"),
        Just("1e999"), Just("null"), Just("true"), Just("\"x\""), Just("\"\\u00e9\""),
    ], 0..60)) {
        exercise(tokens.concat().as_bytes());
    }

    #[test]
    fn mutated_valid_files_never_panic(edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0..3u8), 1..6)) {
        let mut bytes = VALID.as_bytes().to_vec();
        for (at, byte, op) in edits {
            let i = at.index(bytes.len() + 1);
            match op {
                0 if i < bytes.len() => bytes[i] = byte,
                1 => bytes.insert(i, byte),
                _ if i < bytes.len() => { bytes.remove(i); }
                _ => {}
            }
        }
        exercise(&bytes);
    }
}

fn data(name: &str) -> Vec<u8> {
    std::fs::read(format!("{}/tests/data/babylon/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

#[test]
fn hand_written_scenes_load() {
    // Legacy layout, texture, legacy light `data`, no back-face culling.
    let scene = host(&data("legacy_quad.babylon"));
    let mesh = scene.mesh(0).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (4, 2));
    assert_eq!(mesh.uvs().unwrap()[3], Vec2::new(0.0, 1.0));
    let m = scene.mesh_material(0).unwrap();
    assert_eq!((m.cull(), m.diffuse_texture.as_deref(), m.specular_power), (Cull::None, Some("checker.png"), 16.0));
    let c = scene.to_camera().unwrap();
    assert_eq!((c.position, c.fov_y, c.near, c.far), (Vec3::new(0.0, 0.0, -4.0), 0.9, 0.5, 50.0));
    let lights = scene.to_lights();
    assert_eq!(lights.ambient, Vec3::new(0.05, 0.05, 0.05));
    let p = lights.point.unwrap();
    assert_eq!(p.position, Vec3::new(1.0, 2.0, -3.0));
    assert_close(p.color, Vec3::new(0.8, 0.72, 0.64), 1e-6);

    // Newer layout with a transform, animations skipped, spot and hemispheric lights skipped.
    let json = data("tetrahedron.babylon");
    assert_eq!(requirements(&json).unwrap(), Requirements { meshes: 1, materials: 1, lights: 1, vertices: 4, uvs: 4, indices: 12 });
    let scene = host(&json);
    let item = scene.iter().next().unwrap();
    assert_eq!((item.mesh.triangle_count(), item.mesh.uvs().map(<[_]>::len)), (4, Some(4)));
    // Scale 2, yaw π/2 (+z to +x), then move by (0, 1, 2).
    assert_close(item.model.transform_point3(Vec3::new(0.0, 1.0, 0.0)), Vec3::new(0.0, 3.0, 2.0), 1e-5);
    assert_close(item.model.transform_point3(Vec3::new(0.0, -1.0, 1.0)), Vec3::new(2.0, -1.0, 2.0), 1e-5);
    let m = item.material.unwrap();
    assert_eq!((m.alpha, m.specular_power, m.diffuse), (0.5, 32.0, Vec3::new(1.0, 0.8, 0.2)));
    assert_eq!(scene.skipped_lights(), 2);
    let sun = scene.to_lights().directional.unwrap();
    assert_eq!((sun.direction, sun.color), (Vec3::new(0.5, -1.0, 0.5), Vec3::new(1.5, 1.5, 1.5)));
    assert_eq!(scene.to_camera().unwrap().target, Vec3::new(0.0, 0.0, -9.0));

    // Two meshes: uvCount 2 keeps the first set; normals computed; second camera active.
    let json = data("two_meshes.babylon");
    assert_eq!(requirements(&json).unwrap(), Requirements { meshes: 2, materials: 0, lights: 0, vertices: 7, uvs: 3, indices: 9 });
    let scene = host(&json);
    assert_eq!(scene.mesh(0).unwrap().uvs().unwrap(), &[Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0)]);
    assert_eq!(scene.mesh(1).unwrap().normals().as_f32(), Some(&[Vec3::new(0.0, 0.0, 1.0); 4][..]));
    assert_eq!(scene.camera().unwrap().name.as_str(), "Second");
    assert_eq!((scene.skipped_lights(), scene.to_lights().point, scene.to_lights().directional), (1, None, None));
}

#[test]
fn loaded_triangles_face_the_way_their_normals_point() {
    // soft3d's meshes face the side (b - a) × (c - a) points to; after the
    // loader rewinds Babylon's triangles that must agree with the normals
    // the exporter wrote, or back-face culling would show the insides.
    for name in ["monkey.babylon", "torus.babylon", "cube.babylon"] {
        let Some(json) = asset(name) else { continue };
        let scene = host(&json);
        let mesh = scene.mesh(0).unwrap();
        let (p, n) = (mesh.positions().as_f32().unwrap(), mesh.normals().as_f32().unwrap());
        let (mut agree, mut total) = (0, 0);
        for t in mesh.indices().chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(usize::from);
            let face = (p[b] - p[a]).cross(p[c] - p[a]);
            total += 1;
            agree += (face.dot(n[a] + n[b] + n[c]) > 0.0) as usize;
        }
        assert_eq!(agree, total, "{name}: {agree} of {total} triangles face along their normals");
    }
}
