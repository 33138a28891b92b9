//! `.babylon` scenes on the host: the file parsed by the no_std loader,
//! copied into owned arrays, its textures decoded from the files beside it,
//! ready to draw with one call per frame. Used by the `render` and `demo`
//! examples and by the tests.

use super::load_texture;
use crate::babylon::{BabylonScene, Error as BabylonError};
use crate::blend::{AlphaBlend, Opaque};
use crate::effect::{BlinnPhong, Color, Gouraud, Textured};
use crate::material::{Material, Perspective};
use crate::math::{Mat4, Vec2, Vec3};
use crate::mesh::{bounding_sphere, face_plane, FacePlane, Mesh, MeshError, QuantizeError, QuantizedMesh, Sphere, Vectors};
use crate::renderer::{DrawError, Frame};
use crate::scene::{Camera, Lights};
use crate::settings::Settings;
use crate::texture::{Filter, OwnedTexture, Texture, Wrap};
use std::boxed::Box;
use std::format;
use std::path::{Path, PathBuf};
use std::string::{String, ToString};
use std::sync::Mutex;
use std::vec::Vec;

/// Capacities of the parse buffer: enough for scenes of 65,536 vertices.
type Parser = BabylonScene<64, 256, 16, 65536, 65536, 393_216>;

/// One parse buffer for the whole process, in static memory: the loader
/// writes in place, so this keeps 3 MB off every thread's stack.
static PARSER: Mutex<Parser> = Mutex::new(BabylonScene::new());

/// Why a scene could not be loaded.
#[derive(Debug)]
pub enum SceneError {
    /// The file could not be read.
    Io(PathBuf, std::io::Error),
    /// The loader refused it.
    Babylon(PathBuf, Box<BabylonError>),
}

impl core::fmt::Display for SceneError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            SceneError::Io(p, e) => write!(f, "{}: {e}", p.display()),
            SceneError::Babylon(p, e) => write!(f, "{}: {e}", p.display()),
        }
    }
}

impl std::error::Error for SceneError {}

/// A mesh with its own arrays.
#[derive(Clone, Debug)]
pub struct OwnedMesh {
    /// Name from the file.
    pub name: String,
    /// Positions.
    pub positions: Vec<Vec3>,
    /// Unit normals.
    pub normals: Vec<Vec3>,
    /// Texture coordinates, if any.
    pub uvs: Option<Vec<Vec2>>,
    /// Indices.
    pub indices: Vec<u16>,
    /// Model matrix.
    pub model: Mat4,
    /// Index into [`HostScene::materials`].
    pub material: Option<usize>,
    /// Face planes, as `tools/bake --face-planes` bakes them (so that the
    /// host draws what a firmware with baked planes draws).
    pub planes: Vec<FacePlane>,
}

impl OwnedMesh {
    /// The mesh view of the arrays, with its face planes.
    pub fn mesh(&self) -> Mesh<'_> {
        self.complete(Mesh::new(&self.positions, &self.normals, &self.indices), &self.planes)
    }

    /// `geometry` (built from this mesh's arrays, or from their
    /// quantized steps) with this mesh's texture coordinates and `planes`.
    fn complete<'a>(&'a self, geometry: Result<Mesh<'a>, MeshError>, planes: &'a [FacePlane]) -> Mesh<'a> {
        // The arrays came from a validated mesh, so this cannot fail; an
        // empty mesh stands in if it somehow did.
        let m = geometry.unwrap_or(EMPTY);
        let m = match &self.uvs {
            Some(uv) => m.with_uvs(uv).unwrap_or(m),
            None => m,
        };
        m.with_face_planes(planes).unwrap_or(m)
    }

    /// The planes of the mesh's triangles ([`face_plane`]).
    fn face_planes(positions: &[Vec3], indices: &[u16]) -> Vec<FacePlane> {
        let bounds = bounding_sphere(&Vectors::F32(positions));
        let p = |i: u16| positions.get(i as usize).copied().unwrap_or(Vec3::ZERO);
        indices.chunks_exact(3).map(|t| face_plane(p(t[0]), p(t[1]), p(t[2]), bounds)).collect()
    }

    /// The mesh quantized as `soft3d-bake --quantize i16 --face-planes`
    /// bakes it: positions and normals in `i16` steps, and the planes of
    /// the positions the renderer reads from them.
    pub fn quantized(&self) -> Result<QuantizedOwnedMesh<'_>, QuantizeError> {
        let steps = QuantizedMesh::new(&self.positions, &self.normals)?;
        let planes = Self::face_planes(&steps.dequantized_positions(), &self.indices);
        Ok(QuantizedOwnedMesh { source: self, steps, planes })
    }
}

/// An [`OwnedMesh`] with `i16` positions and normals ([`OwnedMesh::quantized`]).
#[derive(Clone, Debug)]
pub struct QuantizedOwnedMesh<'a> {
    /// The mesh quantized (its indices, texture coordinates and model matrix).
    pub source: &'a OwnedMesh,
    /// Positions and normals in steps.
    pub steps: QuantizedMesh,
    /// Face planes of the dequantized positions.
    pub planes: Vec<FacePlane>,
}

impl QuantizedOwnedMesh<'_> {
    /// The mesh view of the steps, with its face planes.
    pub fn mesh(&self) -> Mesh<'_> {
        self.source.complete(self.steps.mesh(&self.source.indices), &self.planes)
    }
}

const EMPTY: Mesh<'static> = match Mesh::new(&[], &[], &[]) {
    Ok(m) => m,
    Err(_) => panic!("the empty mesh is valid"),
};

/// A material: color, culling, and its decoded texture if any.
#[derive(Clone, Debug)]
pub struct OwnedMaterial {
    /// Name from the file.
    pub name: String,
    /// The file's material settings.
    pub base: crate::babylon::BabylonMaterial,
    /// Index into [`HostScene::textures`].
    pub texture: Option<usize>,
}

/// A decoded texture and the file it came from.
#[derive(Clone, Debug)]
pub struct SceneTexture {
    /// File it came from.
    pub path: PathBuf,
    /// RGB565 texels (and alpha, if the image has transparent pixels).
    pub image: OwnedTexture,
}

impl SceneTexture {
    /// The texture view.
    pub fn texture(&self) -> Texture<'_> {
        self.image.texture().unwrap_or(ONE_TEXEL)
    }
}

const ONE_TEXEL: Texture<'static> = match Texture::new(&[0xFFFF], 1, 1) {
    Ok(t) => t,
    Err(_) => panic!("a 1×1 texture is valid"),
};

/// A loaded scene.
#[derive(Clone, Debug)]
pub struct HostScene {
    /// Meshes.
    pub meshes: Vec<OwnedMesh>,
    /// Materials.
    pub materials: Vec<OwnedMaterial>,
    /// Textures.
    pub textures: Vec<SceneTexture>,
    /// The file's camera, if it has one.
    pub camera: Option<Camera>,
    /// The file's lights (a default light if it has none).
    pub lights: Lights,
    /// Problems that did not stop the load (a texture file missing or
    /// unreadable: the material is drawn untextured).
    pub warnings: Vec<String>,
}

/// Which effect meshes are drawn with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EffectChoice {
    /// Textured where the material has a texture and the mesh UVs, else Gouraud.
    Auto,
    /// Gouraud everywhere.
    Gouraud,
    /// Flat everywhere.
    Flat,
    /// Per-pixel lighting with the material's specular highlights
    /// ([`BlinnPhong`]) everywhere (needs `V >= 6`).
    Phong,
}

impl HostScene {
    /// Loads a `.babylon` file and the textures its materials name, looked
    /// up beside it.
    pub fn load(path: impl AsRef<Path>) -> Result<Self, SceneError> {
        let path = path.as_ref();
        let json = std::fs::read(path).map_err(|e| SceneError::Io(path.to_path_buf(), e))?;
        let mut parser = PARSER.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        parser.load(&json).map_err(|e| SceneError::Babylon(path.to_path_buf(), Box::new(e)))?;
        let dir = path.parent().unwrap_or(Path::new("."));
        let mut warnings = Vec::new();
        let mut textures: Vec<SceneTexture> = Vec::new();
        let materials = parser
            .materials()
            .iter()
            .map(|m| {
                let texture = m.diffuse_texture.as_ref().and_then(|name| {
                    let file = dir.join(name.as_str());
                    if let Some(i) = textures.iter().position(|t| t.path == file) {
                        return Some(i);
                    }
                    match load_texture(&file) {
                        Ok(image) => {
                            textures.push(SceneTexture { path: file, image });
                            Some(textures.len() - 1)
                        }
                        Err(e) => {
                            warnings.push(format!("material '{}': texture {}: {e}; drawn untextured", m.name, file.display()));
                            None
                        }
                    }
                });
                OwnedMaterial { name: m.name.to_string(), base: m.clone(), texture }
            })
            .collect();
        let meshes = parser
            .iter()
            .map(|s| {
                let positions: Vec<Vec3> = (0..s.mesh.vertex_count()).map(|i| s.mesh.position(i)).collect();
                let indices = s.mesh.indices().to_vec();
                OwnedMesh {
                    name: s.info.name.to_string(),
                    planes: OwnedMesh::face_planes(&positions, &indices),
                    normals: (0..s.mesh.vertex_count()).map(|i| s.mesh.normal(i)).collect(),
                    uvs: s.mesh.uvs().map(<[Vec2]>::to_vec),
                    positions,
                    indices,
                    model: s.model,
                    material: s.info.material(),
                }
            })
            .collect();
        let lights = if parser.lights().is_empty() { Lights::default() } else { parser.to_lights() };
        Ok(Self { meshes, materials, textures, camera: parser.to_camera(), lights, warnings })
    }

    /// A bounding sphere of the whole scene in world space.
    pub fn bounds(&self) -> Sphere {
        let (mut lo, mut hi) = (Vec3::new(f32::MAX, f32::MAX, f32::MAX), Vec3::new(f32::MIN, f32::MIN, f32::MIN));
        for m in &self.meshes {
            for p in &m.positions {
                let w = m.model.transform_point3(*p);
                lo = Vec3::new(lo.x.min(w.x), lo.y.min(w.y), lo.z.min(w.z));
                hi = Vec3::new(hi.x.max(w.x), hi.y.max(w.y), hi.z.max(w.z));
            }
        }
        if lo.x > hi.x {
            return Sphere { center: Vec3::ZERO, radius: 1.0 };
        }
        let center = (lo + hi) * 0.5;
        Sphere { center, radius: ((hi - lo) * 0.5).length().max(1e-6) }
    }

    /// The file's camera, or one looking at the scene from the front.
    pub fn camera_or_default(&self) -> Camera {
        self.camera.unwrap_or_else(|| {
            let b = self.bounds();
            let mut c = Camera::looking_at(b.center + Vec3::new(0.0, 0.0, -3.0 * b.radius), b.center);
            c.near = b.radius * 0.01;
            c.far = b.radius * 100.0;
            c
        })
    }

    /// The materials of every mesh, built once and borrowed by frames.
    pub fn materials<'s, F: Filter, W: Wrap, P: Perspective>(&'s self, choice: EffectChoice) -> SceneMaterials<'s, F, W, P> {
        let lit = self.materials.iter().map(|m| m.base.configure(Material::new(Gouraud))).collect();
        let flat = self.materials.iter().map(|m| m.base.configure(Material::new(crate::effect::Flat))).collect();
        let phong = self
            .materials
            .iter()
            .map(|m| {
                let s = m.base.specular;
                let c = |v: f32| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
                let specular = embedded_graphics::pixelcolor::Rgb888::new(c(s.x), c(s.y), c(s.z));
                m.base.configure(Material::new(BlinnPhong::with_specular(specular, m.base.specular_power)))
            })
            .collect();
        // Opaque texturing unless the texture has alpha or the material is
        // translucent: only those pay for blending.
        let mut textured = Vec::new();
        let mut blended = Vec::new();
        for m in &self.materials {
            let t = m.texture.and_then(|t| self.textures.get(t));
            let opacity = (m.base.alpha.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
            let blend = t.is_some_and(|t| t.image.alpha.is_some()) || opacity < 255;
            let t = t.map(SceneTexture::texture);
            let opaque = t.filter(|_| !blend).map(Textured::<F, W, Opaque>::new);
            let translucent = t.filter(|_| blend).map(|t| Textured::<F, W, AlphaBlend>::new(t).with_opacity(opacity));
            textured.push(opaque.map(|e| m.base.configure(Material::new(e)).with_perspective::<P>()));
            blended.push(translucent.map(|e| m.base.configure(Material::new(e)).with_perspective::<P>()));
        }
        SceneMaterials {
            choice,
            lit,
            flat,
            phong,
            textured,
            blended,
            default: Material::new(Gouraud).with_color(embedded_graphics::pixelcolor::Rgb888::new(200, 200, 200)),
        }
    }

    /// Draws every mesh, each placed by `spin * model`: the opaque ones in
    /// file order, then the translucent (blended) ones, so what shows
    /// through them is already there. The renderer must store 6 varyings
    /// per vertex (`V >= 6`).
    pub fn draw<'m, C: Color, const V: usize, S: Settings, F: Filter, W: Wrap, P: Perspective>(
        &self,
        frame: &mut Frame<'_, 'm, C, V, S>,
        materials: &'m SceneMaterials<'m, F, W, P>,
        spin: &Mat4,
    ) -> Result<(), DrawError> {
        let blended = |m: &OwnedMesh| {
            materials.choice == EffectChoice::Auto
                && m.uvs.is_some()
                && m.material.is_some_and(|i| materials.blended.get(i).is_some_and(Option::is_some))
        };
        for translucent in [false, true] {
            for m in self.meshes.iter().filter(|m| blended(m) == translucent) {
                let model = *spin * m.model;
                let mesh = m.mesh();
                match (materials.choice, m.material) {
                    (EffectChoice::Flat, Some(i)) => frame.draw(&mesh, &model, &materials.flat[i])?,
                    (EffectChoice::Phong, Some(i)) => frame.draw(&mesh, &model, &materials.phong[i])?,
                    (EffectChoice::Auto, Some(i)) if m.uvs.is_some() && (materials.textured[i].is_some() || translucent) => {
                        if let Some(t) = &materials.textured[i] {
                            frame.draw(&mesh, &model, t)?
                        } else if let Some(t) = &materials.blended[i] {
                            frame.draw(&mesh, &model, t)?
                        }
                    }
                    (_, Some(i)) => frame.draw(&mesh, &model, &materials.lit[i])?,
                    (_, None) => frame.draw(&mesh, &model, &materials.default)?,
                }
            }
        }
        Ok(())
    }

    /// A directional light along the view direction with ambient 0.15 and
    /// diffuse 0.85: the lighting of the benchmark comparisons.
    pub fn headlight(camera: &Camera) -> Lights {
        crate::scenes::headlight(camera)
    }
}

/// A textured material of a scene.
type TexturedMaterial<'s, F, W, B, P> = Material<Textured<'s, F, W, B>, P>;

/// The materials a [`HostScene`] is drawn with (see [`HostScene::materials`]).
pub struct SceneMaterials<'s, F, W, P> {
    choice: EffectChoice,
    lit: Vec<Material<Gouraud>>,
    flat: Vec<Material<crate::effect::Flat>>,
    phong: Vec<Material<BlinnPhong>>,
    textured: Vec<Option<TexturedMaterial<'s, F, W, Opaque, P>>>,
    blended: Vec<Option<TexturedMaterial<'s, F, W, AlphaBlend, P>>>,
    default: Material<Gouraud>,
}
