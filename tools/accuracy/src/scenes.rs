//! The study's scenes, each held once and handed both to the core (as
//! `f32` meshes) and to the reference (converted to `f64`).

use crate::reference::{RefObject, RefScene, RefTexture};
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use soft3d::host::scene::HostScene;
use soft3d::math::{Mat4, Vec2, Vec3};
use soft3d::texture::OwnedTexture;
use soft3d::{Camera, Lights};
use std::path::Path;

/// Image size of every study render (the benchmark's display).
pub const WIDTH: usize = 320;
/// Image height.
pub const HEIGHT: usize = 240;

/// One object: mesh arrays, placement and material.
pub struct Object {
    /// Positions.
    pub positions: Vec<Vec3>,
    /// Unit normals.
    pub normals: Vec<Vec3>,
    /// Texture coordinates, for textured objects.
    pub uvs: Option<Vec<Vec2>>,
    /// Triangle indices.
    pub indices: Vec<u16>,
    /// Model matrix.
    pub model: Mat4,
    /// Material color.
    pub color: Rgb888,
    /// Index into [`Scene::textures`].
    pub texture: Option<usize>,
    /// Face planes, where the firmware's mesh has them baked (the shared
    /// files' meshes), so the host draws what the emulated core draws.
    pub planes: Option<Vec<soft3d::mesh::FacePlane>>,
}

/// A study scene.
pub struct Scene {
    /// Name in the report.
    pub name: &'static str,
    /// What it shows.
    pub about: &'static str,
    /// Camera.
    pub camera: Camera,
    /// Lights.
    pub lights: Lights,
    /// Objects, drawn in order.
    pub objects: Vec<Object>,
    /// Textures (RGB565, repeating).
    pub textures: Vec<OwnedTexture>,
}

fn v3(v: Vec3) -> [f64; 3] {
    [v.x as f64, v.y as f64, v.z as f64]
}

impl Scene {
    /// Whether any object is textured.
    pub fn textured(&self) -> bool {
        self.objects.iter().any(|o| o.texture.is_some())
    }

    /// The same scene for the reference renderer, in `f64`.
    pub fn reference(&self) -> RefScene {
        let c = &self.camera;
        let unit = |c: Rgb888| [c.r() as f64 / 255.0, c.g() as f64 / 255.0, c.b() as f64 / 255.0];
        RefScene {
            width: WIDTH,
            height: HEIGHT,
            eye: v3(c.position),
            target: v3(c.target),
            up: v3(c.up),
            fov_y: c.fov_y as f64,
            near: c.near as f64,
            far: c.far as f64,
            ambient: v3(self.lights.ambient),
            sun: self.lights.directional.map(|d| (v3(d.direction), v3(d.color))),
            point: self.lights.point.map(|p| (v3(p.position), v3(p.color))),
            objects: self
                .objects
                .iter()
                .map(|o| RefObject {
                    positions: o.positions.iter().map(|p| v3(*p)).collect(),
                    normals: o.normals.iter().map(|n| v3(*n)).collect(),
                    uvs: o.uvs.as_ref().map(|u| u.iter().map(|t| [t.x as f64, t.y as f64]).collect()),
                    triangles: o.indices.chunks_exact(3).map(|t| [t[0] as usize, t[1] as usize, t[2] as usize]).collect(),
                    model: o.model.m.map(|r| r.map(|v| v as f64)),
                    color: unit(o.color),
                    texture: o.texture,
                    cull_back: true,
                })
                .collect(),
            textures: self.textures.iter().map(|t| RefTexture::from_rgb565(t.width, t.height, &t.texels)).collect(),
        }
    }
}

/// Ambient 0.15 and 0.85 along the view: the benchmark's headlight.
fn headlight(camera: &Camera) -> Lights {
    soft3d::scenes::headlight(camera)
}

/// A shared Blender export, white, from its own camera under the
/// headlight; textured where the file gives a texture and UVs.
fn from_file(name: &'static str, about: &'static str, path: &Path) -> Result<Scene, String> {
    let hs = HostScene::load(path).map_err(|e| e.to_string())?;
    let camera = hs.camera.ok_or_else(|| format!("{}: no camera", path.display()))?;
    let mut textures = Vec::new();
    let objects = hs
        .meshes
        .iter()
        .map(|m| {
            let texture = m.uvs.as_ref().and(m.material).and_then(|i| hs.materials[i].texture).map(|t| {
                textures.push(hs.textures[t].image.clone());
                textures.len() - 1
            });
            Object {
                positions: m.positions.clone(),
                normals: m.normals.clone(),
                uvs: m.uvs.clone(),
                indices: m.indices.clone(),
                model: m.model,
                color: Rgb888::WHITE,
                texture,
                planes: Some(m.planes.clone()),
            }
        })
        .collect();
    Ok(Scene { name, about, lights: headlight(&camera), camera, objects, textures })
}

/// An object from a mesh of the core's built-in scenes.
fn object(mesh: &soft3d::mesh::Mesh<'_>, color: Rgb888, texture: Option<usize>) -> Object {
    Object {
        positions: mesh.positions().iter().collect(),
        normals: mesh.normals().iter().collect(),
        uvs: mesh.uvs().map(<[Vec2]>::to_vec),
        indices: mesh.indices().to_vec(),
        model: Mat4::IDENTITY,
        color,
        texture,
        planes: mesh.face_planes().map(<[_]>::to_vec),
    }
}

/// A checkerboard floor seen at a grazing angle: where affine texture
/// mapping swims and precision shows far away (`soft3d::scenes::study`).
fn floor() -> Scene {
    use soft3d::scenes::study::*;
    let checker = OwnedTexture { texels: CHECKER_TEXELS.to_vec(), alpha: None, width: CHECKER_SIDE, height: CHECKER_SIDE };
    Scene {
        name: "floor",
        about: "checkerboard floor, 2 triangles 12 × 30 m, 512 texels across, at a grazing angle (texture perspective)",
        camera: FLOOR_CAMERA,
        lights: FLOOR_LIGHTS,
        objects: vec![object(&FLOOR, Rgb888::WHITE, Some(0))],
        textures: vec![checker],
    }
}

/// Two planes crossing far from the camera: where depth precision decides
/// which is in front (`soft3d::scenes::study`).
fn zfight() -> Scene {
    use soft3d::scenes::study::*;
    Scene {
        name: "zfight",
        about: "two planes 40 m away crossing at 0.0017 rad, up to 4 cm apart, near 0.1, far 1000 (depth precision)",
        camera: ZFIGHT_CAMERA,
        lights: ZFIGHT_LIGHTS,
        objects: vec![object(&ZFIGHT_A, ZFIGHT_A_COLOR, None), object(&ZFIGHT_B, ZFIGHT_B_COLOR, None)],
        textures: vec![],
    }
}

/// The study's scenes: the built-in ones, and the shared Blender exports
/// when `assets` holds them (each missing one is reported and skipped).
pub fn all(assets: &Path, notes: &mut Vec<String>) -> Vec<Scene> {
    let mut scenes = Vec::new();
    for (name, about, file) in [
        ("torus", "torus.babylon: 1,152 triangles, white Gouraud, headlight (the benchmark scene)", "torus.babylon"),
        ("monkey", "monkey.babylon: Suzanne, 966 triangles, textured, headlight", "monkey.babylon"),
    ] {
        match from_file(name, about, &assets.join(file)) {
            Ok(s) => scenes.push(s),
            Err(e) => notes.push(format!("skipped: scene {name}: {e}")),
        }
    }
    scenes.push(floor());
    scenes.push(zfight());
    scenes
}
