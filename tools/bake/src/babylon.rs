//! `.babylon` scenes, read with the core's own loader so that the baked
//! arrays are exactly what `soft3d::babylon` yields at run time.

use crate::{BakeError, Baked, BakedMaterial, BakedMesh, Options};
use soft3d::babylon::{requirements, BabylonMaterial, BabylonScene, Requirements};
use soft3d::math::{Mat4, Vec2, Vec3};
use soft3d::{Camera, Lights};
use std::path::Path;

/// What is taken out of a loaded scene, owned, so the scene can go.
pub(crate) struct Loaded {
    pub meshes: Vec<LoadedMesh>,
    pub materials: Vec<BabylonMaterial>,
    pub camera: Option<Camera>,
    pub lights: Lights,
    pub clear_color: Option<Vec3>,
    pub skipped_lights: usize,
}

pub(crate) struct LoadedMesh {
    pub name: String,
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
    pub uvs: Option<Vec<Vec2>>,
    pub indices: Vec<u16>,
    pub model: Mat4,
    pub material: Option<usize>,
}

// The loader's capacities are const parameters. Two sizes: one for
// ordinary scenes (about 2.6 MB) and one for large ones (about 40 MB),
// chosen from `requirements`, so that small bakes stay small.
type Small = BabylonScene<64, 64, 16, 65_536, 65_536, 196_608>;
type Large = BabylonScene<1024, 1024, 256, 1_048_576, 1_048_576, 4_194_304>;

fn fits(need: &Requirements, cap: &Requirements) -> bool {
    need.meshes <= cap.meshes
        && need.materials <= cap.materials
        && need.lights <= cap.lights
        && need.vertices <= cap.vertices
        && need.uvs <= cap.uvs
        && need.indices <= cap.indices
}

/// Loads `json` with `soft3d::babylon`.
pub(crate) fn load(json: &[u8]) -> Result<Loaded, BakeError> {
    let need = requirements(json).map_err(BakeError::Babylon)?;
    if fits(&need, &Small::CAPACITY) {
        on_big_stack::<64, 64, 16, 65_536, 65_536, 196_608>(json)
    } else if fits(&need, &Large::CAPACITY) {
        on_big_stack::<1024, 1024, 256, 1_048_576, 1_048_576, 4_194_304>(json)
    } else {
        Err(BakeError::TooLarge { needed: need, capacity: Large::CAPACITY })
    }
}

/// `Box::new(BabylonScene::new())` builds the scene on the stack first in
/// unoptimized builds (a build script's usual profile), so the load runs on
/// a thread whose stack can hold it twice over.
fn on_big_stack<const M: usize, const MA: usize, const L: usize, const V: usize, const U: usize, const I: usize>(
    json: &[u8],
) -> Result<Loaded, BakeError> {
    let stack = 2 * std::mem::size_of::<BabylonScene<M, MA, L, V, U, I>>() + (4 << 20);
    let internal = |what: &str| BakeError::Internal(what.to_string());
    std::thread::scope(|s| {
        let worker = std::thread::Builder::new()
            .name("soft3d-bake-loader".into())
            .stack_size(stack)
            .spawn_scoped(s, || load_into(&mut Box::new(BabylonScene::<M, MA, L, V, U, I>::new()), json))
            .map_err(|e| internal(&format!("cannot start the loader thread: {e}")))?;
        worker.join().map_err(|_| internal("the loader thread panicked"))?
    })
}

fn load_into<const M: usize, const MA: usize, const L: usize, const V: usize, const U: usize, const I: usize>(
    scene: &mut BabylonScene<M, MA, L, V, U, I>,
    json: &[u8],
) -> Result<Loaded, BakeError> {
    scene.load(json).map_err(BakeError::Babylon)?;
    let meshes = scene
        .iter()
        .map(|item| LoadedMesh {
            name: item.info.name.to_string(),
            positions: item.mesh.positions().iter().collect(),
            normals: item.mesh.normals().iter().collect(),
            uvs: item.mesh.uvs().map(<[Vec2]>::to_vec),
            indices: item.mesh.indices().to_vec(),
            model: item.model,
            material: item.info.material(),
        })
        .collect();
    Ok(Loaded {
        meshes,
        materials: scene.materials().to_vec(),
        camera: scene.to_camera(),
        lights: scene.to_lights(),
        clear_color: scene.clear_color(),
        skipped_lights: scene.skipped_lights(),
    })
}

/// Bakes a `.babylon` scene; `source` names it in the output, textures
/// are looked up in `texture_dir`.
pub(crate) fn bake(json: &[u8], source: &str, texture_dir: &Path, options: &Options) -> Result<Baked, BakeError> {
    let loaded = load(json)?;
    let mut warnings = Vec::new();
    if loaded.skipped_lights > 0 {
        warnings.push(format!("{} light(s) of unsupported types (spot, hemispheric) skipped", loaded.skipped_lights));
    }
    let materials = loaded
        .materials
        .iter()
        .map(|m| BakedMaterial {
            name: m.name.to_string(),
            ident: String::new(),
            color: m.color(),
            cull: m.cull(),
            texture_name: m.diffuse_texture.as_ref().map(|t| t.to_string()),
            texture: None,
        })
        .collect();
    let meshes = loaded
        .meshes
        .into_iter()
        .map(|m| BakedMesh {
            name: m.name,
            ident: String::new(),
            positions: m.positions,
            normals: m.normals,
            uvs: m.uvs,
            indices: m.indices,
            model: m.model,
            material: m.material,
            quantized: None,
        })
        .collect();
    let clear_color = loaded.clear_color.map(|c| BabylonMaterial { diffuse: c, ..Default::default() }.color());
    let baked = Baked {
        source: source.to_string(),
        options: options.clone(),
        meshes,
        materials,
        textures: Vec::new(),
        camera: loaded.camera,
        lights: Some(loaded.lights),
        clear_color,
        warnings,
        inputs: Vec::new(),
    };
    crate::finish(baked, texture_dir)
}
