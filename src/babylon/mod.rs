//! A `no_std`, heap-free loader for Babylon.js `.babylon` scene files
//! (JSON, as exported from Blender): meshes, materials, the active camera
//! and point/directional lights.
//!
//! ```
//! use soft3d::babylon::BabylonScene;
//! use soft3d::math::Vec3;
//!
//! let json = br#"{
//!   "ambientColor": [0.1, 0.1, 0.1],
//!   "materials": [{"name": "red", "id": "red", "diffuse": [1, 0, 0]}],
//!   "meshes": [{
//!     "name": "triangle", "materialId": "red", "position": [0, 1, 0],
//!     "positions": [0, 0, 0,  1, 0, 0,  0, 1, 0],
//!     "normals": [0, 0, -2,  0, 0, -2,  0, 0, -2],
//!     "indices": [0, 2, 1]
//!   }],
//!   "cameras": [{"name": "cam", "id": "cam", "position": [0, 0, -5], "target": [0, 0, 0]}],
//!   "activeCamera": "cam",
//!   "lights": [{"name": "sun", "type": 1, "direction": [0, -1, 1], "intensity": 0.5}]
//! }"#;
//!
//! // Capacities: meshes, materials, lights, vertices, uvs, indices.
//! let mut scene: BabylonScene<1, 1, 1, 3, 0, 3> = BabylonScene::new();
//! scene.load(json)?;
//!
//! for item in scene.iter() {
//!     assert_eq!(item.mesh.triangle_count(), 1);
//!     assert_eq!(item.mesh.normal(0), Vec3::new(0.0, 0.0, -1.0)); // normalized on load
//!     assert_eq!(item.model.transform_point3(Vec3::ZERO), Vec3::new(0.0, 1.0, 0.0));
//!     assert_eq!(item.material.map(|m| m.diffuse), Some(Vec3::new(1.0, 0.0, 0.0)));
//!     // frame.draw(&item.mesh, &item.model, &material)?;
//! }
//! let camera = scene.to_camera().unwrap();
//! assert_eq!(camera.target, Vec3::ZERO);
//! let lights = scene.to_lights();
//! assert_eq!(lights.directional.unwrap().color, Vec3::new(0.5, 0.5, 0.5));
//! # Ok::<(), soft3d::babylon::Error>(())
//! ```
//!
//! ## What is read
//! - Meshes in both layouts: the legacy one (`vertices` interleaved as
//!   position, normal, then `uvCount` pairs of texture coordinates, so 6, 8
//!   or 10 floats per vertex; only the first uv set is kept) and the newer
//!   one (`positions`, `normals`, optional `uvs`, `indices`). `position`,
//!   `rotation` (or `rotationQuaternion`) and `scaling` give the model
//!   matrix; `materialId` names the material; `subMeshes` are only checked
//!   to lie inside their mesh (one material per mesh).
//! - **Normals are normalized on load**; zero-length normals stay zero. A
//!   mesh without normals gets area-weighted vertex normals computed from
//!   its triangles.
//! - Texture coordinates are kept as in the file (Babylon's convention).
//! - **Triangles are rewound**: Babylon's files wind front faces so that
//!   `(b - a) × (c - a)` points into the surface (counter-clockwise as
//!   seen from the front); [`Mesh`] expects it to point
//!   out, so the loader swaps the last two indices of every triangle.
//! - Materials (`diffuse`, `specular`, `specularPower`, `ambient`,
//!   `emissive`, `alpha`, `backFaceCulling`, `diffuseTexture.name`), with
//!   Babylon's `StandardMaterial` defaults for absent fields.
//! - The camera named by `activeCamera` (or `activeCameraID`), else the
//!   first, given by `target` or by `rotation`; Babylon's defaults for an
//!   absent `fov` (0.8), `minZ` (1) and `maxZ` (10000).
//! - Lights of `type` 0 (point) and 1 (directional); spot and hemispheric
//!   lights are skipped and counted.
//! - Every other field, known to Babylon or not, is skipped. `null` reads
//!   as an absent field. Mesh hierarchies (`parentId`), instances,
//!   skeletons, animations, multi-materials and vertex colors are ignored.
//!
//! ## Sizing the capacities
//! [`BabylonScene`]'s const parameters are the capacities of its lists
//! and pools, shared by all meshes:
//! `MESHES`, `MATERIALS`, `LIGHTS` (point and directional only),
//! `VERTICES` (all meshes' vertices), `UVS` (vertices of the meshes with
//! texture coordinates) and `INDICES` (all meshes' indices, three per
//! triangle). [`requirements`] reads a file and returns exactly these
//! numbers (run it on the host, e.g. in a test, and copy them); a file that
//! does not fit is refused with [`Error::Capacity`], which names the
//! container, the first mesh that did not fit, the capacity and the size
//! the whole file needs. Names, ids and texture names hold [`NAME_LEN`]
//! bytes.
//!
//! The scene takes `24 × VERTICES + 8 × UVS + 2 × INDICES` bytes plus, on
//! a 64-bit host, 352 per mesh, 288 per material, 192 per light and about
//! 300 for the camera and bookkeeping (less on 32-bit targets;
//! `core::mem::size_of` gives the exact figure). Suzanne (`monkey.babylon`:
//! 886 vertices with uvs, 2898 indices) needs
//! `BabylonScene<1, 1, 1, 886, 886, 2898>`, about 35 KB.
//!
//! Loading fills the scene in place ([`BabylonScene::load`]) and never
//! builds a copy of it on the stack, so on a device keep it in a `static`
//! (its constructor is `const`), e.g. behind a
//! `critical_section::Mutex<RefCell<_>>` or a `StaticCell`. On the host a
//! `Box` does for moderate capacities, but `Box::new` builds its value on
//! the stack first in unoptimized builds, so put large scenes in a
//! `static` too (`static SCENE: std::sync::Mutex<Scene> =
//! Mutex::new(Scene::new());`). [`BabylonScene::parse`] returns the scene by
//! value and is only for small capacities. The parse itself uses little
//! stack: nesting is limited to [`MAX_DEPTH`] levels, checked before
//! serde-json-core (which recurses once per level) sees the input. On an
//! x86-64 host, loading Suzanne or a file nested `MAX_DEPTH` deep fits in
//! a 16 KiB thread stack when optimized, and needs 32 to 48 KiB
//! unoptimized.
//!
//! ## Errors
//! Loading never panics. Every problem is an [`Error`] that says what is
//! wrong and where: the item (mesh 0 'Suzanne'), the field, the array
//! element and the byte offset. The input is first scanned without
//! recursion for syntax and nesting depth, with counts of every array the
//! scene must store; serde-json-core then reads it into the scene.

mod de;
mod error;
mod scan;

pub use error::{Container, Error, Item, JsonError, Location, LOCATION_NAME_LEN};

use crate::material::{Cull, Material};
use crate::math::{Mat4, Vec2, Vec3};
use crate::mesh::Mesh;
use crate::scene::{Camera, DirectionalLight, Lights, PointLight};
use de::{Geometry, Loader, MeshMeta, Store};
use embedded_graphics::pixelcolor::Rgb888;
use heapless::Vec;

/// The deepest nesting of arrays and objects accepted. Babylon files need
/// about 8 (animation keys inside meshes); serde-json-core recurses once per
/// level, so this bounds the stack the parse uses.
pub const MAX_DEPTH: usize = 32;

/// The capacity in bytes of names, ids and texture names.
pub const NAME_LEN: usize = 64;

/// A name, id or texture name (JSON escapes decoded).
pub type Name = heapless::String<NAME_LEN>;

/// The capacities a file needs; see the module's "Sizing" section.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Requirements {
    /// Meshes (`MESHES`).
    pub meshes: usize,
    /// Materials (`MATERIALS`).
    pub materials: usize,
    /// Point and directional lights (`LIGHTS`).
    pub lights: usize,
    /// Vertices of all meshes (`VERTICES`).
    pub vertices: usize,
    /// Vertices of the meshes with texture coordinates (`UVS`).
    pub uvs: usize,
    /// Indices of all meshes (`INDICES`).
    pub indices: usize,
}

/// Reads `json` just enough to size a [`BabylonScene`] for it: the syntax,
/// the nesting depth and the shape of every mesh are checked, values are
/// not (so a file that passes may still fail to load).
pub fn requirements(json: &[u8]) -> Result<Requirements, Error> {
    let s = scan::survey(json, &mut |_| {})?;
    Ok(Requirements { meshes: s.meshes, materials: s.materials, lights: s.lights, vertices: s.vertices, uvs: s.uvs, indices: s.indices })
}

/// A mesh's name, transform and material, and where its geometry is.
#[derive(Clone, Debug, PartialEq)]
pub struct BabylonMesh {
    /// `name`.
    pub name: Name,
    /// `id`.
    pub id: Name,
    /// `materialId`, if any.
    pub material_id: Option<Name>,
    /// `position` (zero if absent).
    pub position: Vec3,
    /// `rotation` in radians: x pitch, y yaw, z roll (zero if absent).
    pub rotation: Vec3,
    /// `rotationQuaternion` (x, y, z, w); when present it replaces
    /// `rotation`, as in Babylon.
    pub rotation_quaternion: Option<[f32; 4]>,
    /// `scaling` (one if absent).
    pub scaling: Vec3,
    material: Option<usize>,
    geometry: Geometry,
}

impl BabylonMesh {
    fn planned(geometry: Geometry) -> Self {
        let m = MeshMeta::default();
        Self {
            name: m.name,
            id: m.id,
            material_id: None,
            position: m.position,
            rotation: m.rotation,
            rotation_quaternion: None,
            scaling: m.scaling,
            material: None,
            geometry,
        }
    }

    /// The index of the material whose `id` is `materialId`, resolved at
    /// load (`None` if there is no `materialId` or no such material).
    pub fn material(&self) -> Option<usize> {
        self.material
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.geometry.vertices
    }

    /// Number of indices (three per triangle).
    pub fn index_count(&self) -> usize {
        self.geometry.indices
    }

    /// Whether the mesh has texture coordinates.
    pub fn has_uvs(&self) -> bool {
        self.geometry.first_uv.is_some()
    }

    /// Whether the file used the legacy interleaved `vertices` layout.
    pub fn is_legacy(&self) -> bool {
        self.geometry.stride > 0
    }

    /// The model matrix `T · R · S` (column vectors), as Babylon computes
    /// it from `position`, `rotation` (or `rotationQuaternion`) and
    /// `scaling`.
    pub fn model_matrix(&self) -> Mat4 {
        let r = match self.rotation_quaternion {
            Some(q) => quaternion_rotation(q),
            None => euler_rotation(self.rotation),
        };
        Mat4::translation(self.position) * r * Mat4::scaling(self.scaling)
    }
}

/// The rotation matrix of a Babylon `rotation` vector (x pitch, y yaw,
/// z roll, radians): `Ry(yaw) · Rx(pitch) · Rz(roll)`, so roll applies
/// first, as in Babylon's `RotationYawPitchRoll`.
pub fn euler_rotation(rotation: Vec3) -> Mat4 {
    Mat4::rotation_y(rotation.y) * Mat4::rotation_x(rotation.x) * Mat4::rotation_z(rotation.z)
}

/// The rotation matrix of a quaternion `[x, y, z, w]` (normalized here; a
/// zero or non-finite quaternion gives the identity).
pub fn quaternion_rotation(q: [f32; 4]) -> Mat4 {
    let n2 = q.iter().map(|c| c * c).sum::<f32>();
    if !(n2.is_finite() && n2 > 1e-30) {
        return Mat4::IDENTITY;
    }
    let s = 2.0 / n2;
    let [x, y, z, w] = q;
    Mat4 {
        m: [
            [1.0 - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w), 0.0],
            [s * (x * y + z * w), 1.0 - s * (x * x + z * z), s * (y * z - x * w), 0.0],
            [s * (x * z - y * w), s * (y * z + x * w), 1.0 - s * (x * x + y * y), 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    }
}

/// A Babylon `StandardMaterial`'s fields.
#[derive(Clone, Debug, PartialEq)]
pub struct BabylonMaterial {
    /// `name`.
    pub name: Name,
    /// `id` (what meshes' `materialId` refers to).
    pub id: Name,
    /// `diffuse` color (default white).
    pub diffuse: Vec3,
    /// `specular` color (default white).
    pub specular: Vec3,
    /// `specularPower` (default 64).
    pub specular_power: f32,
    /// `ambient` color (default black).
    pub ambient: Vec3,
    /// `emissive` color (default black).
    pub emissive: Vec3,
    /// `alpha` (default 1).
    pub alpha: f32,
    /// `backFaceCulling` (default true).
    pub back_face_culling: bool,
    /// `diffuseTexture.name`, the texture's file name.
    pub diffuse_texture: Option<Name>,
}

impl Default for BabylonMaterial {
    /// Babylon's `StandardMaterial` defaults.
    fn default() -> Self {
        Self {
            name: Name::new(),
            id: Name::new(),
            diffuse: Vec3::ONE,
            specular: Vec3::ONE,
            specular_power: 64.0,
            ambient: Vec3::ZERO,
            emissive: Vec3::ZERO,
            alpha: 1.0,
            back_face_culling: true,
            diffuse_texture: None,
        }
    }
}

impl BabylonMaterial {
    /// The diffuse color as 8-bit RGB (components clamped to [0, 1]).
    pub fn color(&self) -> Rgb888 {
        let c = |v: f32| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
        Rgb888::new(c(self.diffuse.x), c(self.diffuse.y), c(self.diffuse.z))
    }

    /// The culling mode `backFaceCulling` asks for.
    pub fn cull(&self) -> Cull {
        if self.back_face_culling {
            Cull::Back
        } else {
            Cull::None
        }
    }

    /// `material` with this material's color and culling.
    pub fn configure<E: crate::effect::Effect, P: crate::material::Perspective, D: crate::material::DepthMode>(
        &self,
        material: Material<E, P, D>,
    ) -> Material<E, P, D> {
        material.with_color(self.color()).with_cull(self.cull())
    }
}

/// A camera as the file gives it.
#[derive(Clone, Debug, PartialEq)]
pub struct BabylonCamera {
    /// `name`.
    pub name: Name,
    /// `id`.
    pub id: Name,
    /// `position`.
    pub position: Vec3,
    /// `target`, if given (it takes precedence over `rotation`, as in
    /// Babylon).
    pub target: Option<Vec3>,
    /// `rotation` (x pitch, y yaw, z roll, radians), used when there is no
    /// target.
    pub rotation: Vec3,
    /// `upVector` (default +y).
    pub up_vector: Vec3,
    /// `fov`: vertical field of view in radians (default 0.8).
    pub fov: f32,
    /// `minZ`: near plane (default 1).
    pub min_z: f32,
    /// `maxZ`: far plane (default 10000).
    pub max_z: f32,
}

impl Default for BabylonCamera {
    /// Babylon's camera defaults.
    fn default() -> Self {
        Self {
            name: Name::new(),
            id: Name::new(),
            position: Vec3::ZERO,
            target: None,
            rotation: Vec3::ZERO,
            up_vector: Vec3::new(0.0, 1.0, 0.0),
            fov: 0.8,
            min_z: 1.0,
            max_z: 10000.0,
        }
    }
}

impl BabylonCamera {
    /// Unit view direction: toward the target, or `R · (0, 0, 1)` with `R`
    /// the rotation matrix of `rotation` (zero if the target is the
    /// position).
    pub fn forward(&self) -> Vec3 {
        match self.target {
            Some(t) => (t - self.position).normalize_or_zero(),
            None => euler_rotation(self.rotation).transform_point3(Vec3::new(0.0, 0.0, 1.0)).normalize_or_zero(),
        }
    }

    /// Up direction: `upVector`, rotated by `rotation` when there is no
    /// target.
    pub fn up(&self) -> Vec3 {
        match self.target {
            Some(_) => self.up_vector,
            None => euler_rotation(self.rotation).transform_point3(self.up_vector),
        }
    }

    /// The renderer's camera.
    pub fn to_camera(&self) -> Camera {
        let target = match self.target {
            Some(t) => t,
            None => self.position + self.forward(),
        };
        Camera { position: self.position, target, up: self.up(), fov_y: self.fov, near: self.min_z, far: self.max_z }
    }
}

/// The kinds of light the loader keeps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// `type` 0.
    Point {
        /// `position` (or the legacy `data`).
        position: Vec3,
    },
    /// `type` 1.
    Directional {
        /// `direction` the light travels (or the legacy `data`).
        direction: Vec3,
    },
}

/// A point or directional light.
#[derive(Clone, Debug, PartialEq)]
pub struct BabylonLight {
    /// `name`.
    pub name: Name,
    /// `id`.
    pub id: Name,
    /// Point or directional, with its position or direction.
    pub kind: LightKind,
    /// `intensity` (default 1).
    pub intensity: f32,
    /// `diffuse` color (default white).
    pub diffuse: Vec3,
    /// `specular` color (default white).
    pub specular: Vec3,
}

impl Default for BabylonLight {
    fn default() -> Self {
        Self {
            name: Name::new(),
            id: Name::new(),
            kind: LightKind::Point { position: Vec3::ZERO },
            intensity: 1.0,
            diffuse: Vec3::ONE,
            specular: Vec3::ONE,
        }
    }
}

impl BabylonLight {
    /// The light's color for the renderer: `diffuse × intensity`.
    pub fn color(&self) -> Vec3 {
        self.diffuse * self.intensity
    }
}

/// One mesh ready to draw.
#[derive(Clone, Copy, Debug)]
pub struct SceneMesh<'a> {
    /// Its name, transform and material index.
    pub info: &'a BabylonMesh,
    /// The geometry, borrowing the scene's arrays.
    pub mesh: Mesh<'a>,
    /// The model matrix.
    pub model: Mat4,
    /// Its material, if resolved.
    pub material: Option<&'a BabylonMaterial>,
}

/// A loaded scene. The const parameters are capacities (see the module's
/// "Sizing" section): meshes, materials, point/directional lights, and the
/// vertex, texture-coordinate and index pools shared by all meshes.
#[derive(Clone, Debug)]
pub struct BabylonScene<
    const MESHES: usize,
    const MATERIALS: usize,
    const LIGHTS: usize,
    const VERTICES: usize,
    const UVS: usize,
    const INDICES: usize,
> {
    positions: Vec<Vec3, VERTICES>,
    normals: Vec<Vec3, VERTICES>,
    uvs: Vec<Vec2, UVS>,
    indices: Vec<u16, INDICES>,
    meshes: Vec<BabylonMesh, MESHES>,
    materials: Vec<BabylonMaterial, MATERIALS>,
    lights: Vec<BabylonLight, LIGHTS>,
    skipped_lights: usize,
    camera: Option<BabylonCamera>,
    ambient_color: Vec3,
    clear_color: Option<Vec3>,
}

impl<const MESHES: usize, const MATERIALS: usize, const LIGHTS: usize, const VERTICES: usize, const UVS: usize, const INDICES: usize>
    Default for BabylonScene<MESHES, MATERIALS, LIGHTS, VERTICES, UVS, INDICES>
{
    fn default() -> Self {
        Self::new()
    }
}

impl<const MESHES: usize, const MATERIALS: usize, const LIGHTS: usize, const VERTICES: usize, const UVS: usize, const INDICES: usize>
    BabylonScene<MESHES, MATERIALS, LIGHTS, VERTICES, UVS, INDICES>
{
    /// The capacities, as [`Requirements`].
    pub const CAPACITY: Requirements =
        Requirements { meshes: MESHES, materials: MATERIALS, lights: LIGHTS, vertices: VERTICES, uvs: UVS, indices: INDICES };

    /// An empty scene (usable in a `static`).
    pub const fn new() -> Self {
        Self {
            positions: Vec::new(),
            normals: Vec::new(),
            uvs: Vec::new(),
            indices: Vec::new(),
            meshes: Vec::new(),
            materials: Vec::new(),
            lights: Vec::new(),
            skipped_lights: 0,
            camera: None,
            ambient_color: Vec3::ZERO,
            clear_color: None,
        }
    }

    /// Loads a scene, replacing what was loaded before. On error the scene
    /// is left empty.
    pub fn load(&mut self, json: &[u8]) -> Result<(), Error> {
        self.clear();
        let result = self.load_inner(json);
        if result.is_err() {
            self.clear();
        }
        result
    }

    /// Loads a scene into a new value. The value is built on the stack
    /// and returned by value: only for small capacities (see
    /// [`load`](Self::load)).
    pub fn parse(json: &[u8]) -> Result<Self, Error> {
        let mut scene = Self::new();
        scene.load(json)?;
        Ok(scene)
    }

    /// Empties the scene.
    pub fn clear(&mut self) {
        // In place: `*self = Self::new()` would build a scene-sized
        // temporary on the stack in unoptimized builds.
        self.positions.clear();
        self.normals.clear();
        self.uvs.clear();
        self.indices.clear();
        self.meshes.clear();
        self.materials.clear();
        self.lights.clear();
        self.skipped_lights = 0;
        self.camera = None;
        self.ambient_color = Vec3::ZERO;
        self.clear_color = None;
    }

    fn load_inner(&mut self, json: &[u8]) -> Result<(), Error> {
        // Pass 1: syntax, depth, counts, and each mesh's place in the pools.
        let mut totals = [0usize; 3];
        let mut first_over: [Option<scan::MeshPlan>; 3] = [None, None, None];
        let caps = [VERTICES, UVS, INDICES];
        let meshes = &mut self.meshes;
        let survey = scan::survey(json, &mut |plan| {
            let geometry = Geometry {
                first_vertex: totals[0],
                vertices: plan.vertices,
                stride: plan.stride,
                first_uv: plan.has_uvs.then_some(totals[1]),
                first_index: totals[2],
                indices: plan.indices,
            };
            let sizes = [plan.vertices, if plan.has_uvs { plan.vertices } else { 0 }, plan.indices];
            for k in 0..3 {
                totals[k] += sizes[k];
                if totals[k] > caps[k] && first_over[k].is_none() {
                    first_over[k] = Some(plan.clone());
                }
            }
            // Past the capacity the count still goes on, for the error.
            let _ = meshes.push(BabylonMesh::planned(geometry));
        })?;
        let lists = [
            (Container::Meshes, "meshes", survey.meshes, MESHES),
            (Container::Materials, "materials", survey.materials, MATERIALS),
            (Container::Lights, "lights", survey.lights, LIGHTS),
        ];
        for (container, field, needed, capacity) in lists {
            if needed > capacity {
                let mut at = Location::scene(Some(field));
                at.offset = scan::locate(json, &at);
                return Err(Error::Capacity { container, at, capacity, needed });
            }
        }
        let pools = [(Container::Vertices, survey.vertices), (Container::Uvs, survey.uvs), (Container::Indices, survey.indices)];
        for (k, (container, needed)) in pools.into_iter().enumerate() {
            if let Some(plan) = first_over[k].take() {
                let field = match (container, plan.stride > 0) {
                    (Container::Indices, _) => "indices",
                    (_, true) => "vertices",
                    (Container::Uvs, false) => "uvs",
                    _ => "positions",
                };
                let mut at = Location::item(Item::Mesh(plan.index)).field(field);
                at.set_name(&plan.name);
                at.offset = scan::locate(json, &at).or(Some(plan.offset));
                return Err(Error::Capacity { container, at, capacity: caps[k], needed });
            }
        }

        // Pass 2: serde-json-core reads the values into place.
        let mut loader = Loader::new(self, survey.active_camera);
        let mut de = serde_json_core::de::Deserializer::new(json, None);
        let parsed = loader.run(&mut de).and_then(|()| de.end().map(|_| ()));
        if let Err(kind) = parsed {
            let mut error = loader.error.take().unwrap_or_else(|| Error::Json { kind, at: loader.at.clone() });
            if let Some(at) = error.location_mut() {
                if at.offset.is_none() {
                    at.offset = scan::locate(json, at);
                }
            }
            return Err(error);
        }
        self.camera = loader.camera.take();

        for i in 0..self.meshes.len() {
            let id = self.meshes[i].material_id.as_ref();
            let material = id.and_then(|id| self.materials.iter().position(|m| m.id == *id));
            self.meshes[i].material = material;
            if self.mesh(i).is_none() {
                let at = Location::item(Item::Mesh(i));
                return Err(Error::Invalid { at, problem: "internal: the mesh does not validate" });
            }
        }
        Ok(())
    }

    /// The meshes' names, transforms and materials.
    pub fn meshes(&self) -> &[BabylonMesh] {
        &self.meshes
    }

    /// Mesh `i`'s geometry, borrowing the scene's arrays (`None` if there
    /// is no such mesh). Building it costs a pass over its vertices and
    /// indices (bounds and validation), so keep it rather than rebuild it
    /// every frame.
    pub fn mesh(&self, i: usize) -> Option<Mesh<'_>> {
        let g = self.meshes.get(i)?.geometry;
        let vertices = g.first_vertex..g.first_vertex + g.vertices;
        let positions = self.positions.get(vertices.clone())?;
        let normals = self.normals.get(vertices)?;
        let indices = self.indices.get(g.first_index..g.first_index + g.indices)?;
        let mesh = Mesh::new(positions, normals, indices).ok()?;
        match g.first_uv {
            Some(u) => mesh.with_uvs(self.uvs.get(u..u + g.vertices)?).ok(),
            None => Some(mesh),
        }
    }

    /// Every mesh with its model matrix and material.
    pub fn iter(&self) -> impl Iterator<Item = SceneMesh<'_>> + '_ {
        self.meshes.iter().enumerate().filter_map(move |(i, info)| {
            Some(SceneMesh {
                info,
                mesh: self.mesh(i)?,
                model: info.model_matrix(),
                material: info.material.and_then(|m| self.materials.get(m)),
            })
        })
    }

    /// The materials.
    pub fn materials(&self) -> &[BabylonMaterial] {
        &self.materials
    }

    /// The material of mesh `i`, if it has one.
    pub fn mesh_material(&self, i: usize) -> Option<&BabylonMaterial> {
        self.materials.get(self.meshes.get(i)?.material?)
    }

    /// The active camera (the one `activeCamera` names, else the first).
    pub fn camera(&self) -> Option<&BabylonCamera> {
        self.camera.as_ref()
    }

    /// The active camera for the renderer.
    pub fn to_camera(&self) -> Option<Camera> {
        self.camera.as_ref().map(BabylonCamera::to_camera)
    }

    /// The point and directional lights, in file order.
    pub fn lights(&self) -> &[BabylonLight] {
        &self.lights
    }

    /// How many lights of other types (spot, hemispheric, unknown) were
    /// skipped.
    pub fn skipped_lights(&self) -> usize {
        self.skipped_lights
    }

    /// The renderer's lights: `ambientColor` as ambient, the first point
    /// light and the first directional light, each colored
    /// `diffuse × intensity`.
    pub fn to_lights(&self) -> Lights {
        let point = self.lights.iter().find_map(|l| match l.kind {
            LightKind::Point { position } => Some(PointLight { position, color: l.color() }),
            LightKind::Directional { .. } => None,
        });
        let directional = self.lights.iter().find_map(|l| match l.kind {
            LightKind::Directional { direction } => Some(DirectionalLight { direction, color: l.color() }),
            LightKind::Point { .. } => None,
        });
        Lights { ambient: self.ambient_color, point, directional }
    }

    /// The scene's `ambientColor` (default black).
    pub fn ambient_color(&self) -> Vec3 {
        self.ambient_color
    }

    /// The scene's `clearColor`, if given.
    pub fn clear_color(&self) -> Option<Vec3> {
        self.clear_color
    }
}

impl<const MESHES: usize, const MATERIALS: usize, const LIGHTS: usize, const VERTICES: usize, const UVS: usize, const INDICES: usize> Store
    for BabylonScene<MESHES, MATERIALS, LIGHTS, VERTICES, UVS, INDICES>
{
    fn geometry(&self, mesh: usize) -> Option<Geometry> {
        self.meshes.get(mesh).map(|m| m.geometry)
    }

    fn pool_lens(&self) -> [usize; 4] {
        [self.positions.len(), self.normals.len(), self.uvs.len(), self.indices.len()]
    }

    fn push_position(&mut self, v: Vec3) -> bool {
        self.positions.push(v).is_ok()
    }

    fn push_normal(&mut self, v: Vec3) -> bool {
        self.normals.push(v).is_ok()
    }

    fn push_uv(&mut self, v: Vec2) -> bool {
        self.uvs.push(v).is_ok()
    }

    fn push_index(&mut self, i: u16) -> bool {
        self.indices.push(i).is_ok()
    }

    fn finish_mesh(&mut self, mesh: usize, meta: MeshMeta) -> bool {
        let Some(g) = self.geometry(mesh) else { return false };
        let base = g.first_vertex;
        // Babylon's front faces wind the other way round from soft3d's:
        // in its files (b - a) × (c - a) points into the surface. Swapping
        // two corners of every triangle makes it point out, as `Mesh` expects.
        let Some(indices) = self.indices.get_mut(g.first_index..g.first_index + g.indices) else { return false };
        for t in indices.chunks_exact_mut(3) {
            t.swap(1, 2);
        }
        if self.normals.len() == base {
            // No normals in the file: area-weighted face normals.
            for _ in 0..g.vertices {
                if self.normals.push(Vec3::ZERO).is_err() {
                    return false;
                }
            }
            let Some(indices) = self.indices.get(g.first_index..g.first_index + g.indices) else { return false };
            for t in indices.chunks_exact(3) {
                let [a, b, c] = [t[0], t[1], t[2]].map(|i| base + i as usize);
                let (Some(&pa), Some(&pb), Some(&pc)) = (self.positions.get(a), self.positions.get(b), self.positions.get(c)) else {
                    return false;
                };
                let n = (pb - pa).cross(pc - pa);
                for v in [a, b, c] {
                    if let Some(slot) = self.normals.get_mut(v) {
                        *slot = *slot + n;
                    }
                }
            }
        }
        let Some(normals) = self.normals.get_mut(base..base + g.vertices) else { return false };
        for n in normals {
            *n = unit_or_zero(*n);
        }
        let Some(m) = self.meshes.get_mut(mesh) else { return false };
        m.name = meta.name;
        m.id = meta.id;
        m.material_id = meta.material_id;
        m.position = meta.position;
        m.rotation = meta.rotation;
        m.rotation_quaternion = meta.rotation_quaternion;
        m.scaling = meta.scaling;
        true
    }

    fn push_material(&mut self, m: BabylonMaterial) -> bool {
        self.materials.push(m).is_ok()
    }

    fn push_light(&mut self, l: BabylonLight) -> bool {
        self.lights.push(l).is_ok()
    }

    fn skip_light(&mut self) {
        self.skipped_lights += 1;
    }

    fn set_ambient(&mut self, c: Vec3) {
        self.ambient_color = c;
    }

    fn set_clear(&mut self, c: Vec3) {
        self.clear_color = Some(c);
    }
}

/// `v` normalized; zero (or non-finite) stays zero. Scaling by the largest
/// component first keeps huge and tiny normals from over- or underflowing.
fn unit_or_zero(v: Vec3) -> Vec3 {
    let m = v.x.abs().max(v.y.abs()).max(v.z.abs());
    if m > 0.0 && m.is_finite() {
        (v * (1.0 / m)).normalize_or_zero()
    } else {
        Vec3::ZERO
    }
}

/// Decodes a JSON string's raw content (escapes included) into `out`.
/// On overflow returns the decoded length in bytes. Malformed escapes
/// (the pre-scan rejects them) and lone surrogates become U+FFFD.
pub(crate) fn decode_name(raw: &str, out: &mut Name) -> Result<(), usize> {
    let mut needed = 0;
    let mut full = false;
    let mut push = |c: char| {
        needed += c.len_utf8();
        full = full || out.push(c).is_err();
    };
    let mut chars = raw.chars();
    while let Some(c) = chars.next() {
        if c != '\\' {
            push(c);
            continue;
        }
        let c = match chars.next() {
            Some('b') => '\u{8}',
            Some('f') => '\u{c}',
            Some('n') => '\n',
            Some('r') => '\r',
            Some('t') => '\t',
            Some('u') => {
                let hi = hex4(&mut chars);
                match hi {
                    Some(hi @ 0xD800..=0xDBFF) => {
                        // A high surrogate must be followed by `\u` and a low one.
                        let mut rest = chars.clone();
                        let lo = match (rest.next(), rest.next()) {
                            (Some('\\'), Some('u')) => hex4(&mut rest).filter(|lo| (0xDC00..=0xDFFF).contains(lo)),
                            _ => None,
                        };
                        match lo {
                            Some(lo) => {
                                chars = rest;
                                char::from_u32(0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00)).unwrap_or('\u{FFFD}')
                            }
                            None => '\u{FFFD}',
                        }
                    }
                    Some(u) => char::from_u32(u).unwrap_or('\u{FFFD}'),
                    None => '\u{FFFD}',
                }
            }
            Some(c @ ('"' | '\\' | '/')) => c,
            _ => '\u{FFFD}',
        };
        push(c);
    }
    if full {
        Err(needed)
    } else {
        Ok(())
    }
}

fn hex4(chars: &mut core::str::Chars<'_>) -> Option<u32> {
    let mut v = 0;
    for _ in 0..4 {
        v = v * 16 + chars.next()?.to_digit(16)?;
    }
    Some(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_decode_escapes_and_report_overflow() {
        let mut n = Name::new();
        decode_name(r#"a\"b\\c\/\n\u00e9\ud83d\ude00\ud800x"#, &mut n).unwrap();
        assert_eq!(n.as_str(), "a\"b\\c/\né😀\u{FFFD}x");
        let long = "é".repeat(40);
        let mut n = Name::new();
        assert_eq!(decode_name(&long, &mut n), Err(80));
    }

    #[test]
    fn quaternion_matches_euler() {
        let r = Vec3::new(0.3, -1.1, 0.7);
        // Babylon's RotationYawPitchRoll quaternion.
        let (hr, hp, hy) = (r.z * 0.5, r.x * 0.5, r.y * 0.5);
        let (sr, cr, sp, cp, sy, cy) = (hr.sin(), hr.cos(), hp.sin(), hp.cos(), hy.sin(), hy.cos());
        let q = [cy * sp * cr + sy * cp * sr, sy * cp * cr - cy * sp * sr, cy * cp * sr - sy * sp * cr, cy * cp * cr + sy * sp * sr];
        let (a, b) = (euler_rotation(r), quaternion_rotation(q));
        for i in 0..4 {
            for j in 0..4 {
                assert!((a.m[i][j] - b.m[i][j]).abs() < 1e-5, "{a:?} {b:?}");
            }
        }
    }

    #[test]
    fn errors_stay_small_and_names_are_shortened() {
        assert!(core::mem::size_of::<Error>() <= 128, "{}", core::mem::size_of::<Error>());
        let mut at = Location::item(Item::Mesh(0));
        at.set_name("ééééééééééééééééééééé"); // 42 bytes
        assert_eq!(at.name.as_str(), "éééééééééé…"); // 10 × 2 bytes + 3
        at.set_name("Suzanne");
        assert_eq!(at.name.as_str(), "Suzanne");
    }

    #[test]
    fn unit_or_zero_handles_extremes() {
        assert_eq!(unit_or_zero(Vec3::new(1e30, 0.0, 0.0)), Vec3::new(1.0, 0.0, 0.0));
        assert_eq!(unit_or_zero(Vec3::new(0.0, 1e-30, 0.0)), Vec3::new(0.0, 1.0, 0.0));
        assert_eq!(unit_or_zero(Vec3::ZERO), Vec3::ZERO);
        assert_eq!(unit_or_zero(Vec3::new(f32::NAN, 0.0, 0.0)), Vec3::ZERO);
    }
}
