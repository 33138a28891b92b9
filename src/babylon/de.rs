//! The serde pass: seeds that deserialize straight into the scene.
//!
//! Going through `DeserializeSeed` rather than a derived `Deserialize`
//! writes the geometry into the scene's pools in place, so nothing the size
//! of the scene is ever built on the stack. The pre-scan has already
//! checked the syntax, the depth, the capacities and the shape of every
//! mesh, so this pass checks values: types, finiteness, index ranges.

use super::error::{Container, Error, Item, JsonError, Location};
use super::{decode_name, BabylonCamera, BabylonLight, BabylonMaterial, LightKind, Name, NAME_LEN};
use crate::math::{Vec2, Vec3};
use core::fmt;
use core::marker::PhantomData;
use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};

/// Where a mesh's geometry goes in the pools, fixed by the pre-scan.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Geometry {
    pub first_vertex: usize,
    pub vertices: usize,
    /// Floats per legacy interleaved vertex, 0 for separate arrays.
    pub stride: usize,
    pub first_uv: Option<usize>,
    pub first_index: usize,
    pub indices: usize,
}

/// The non-geometry fields of a mesh.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct MeshMeta {
    pub name: Name,
    pub id: Name,
    pub material_id: Option<Name>,
    pub position: Vec3,
    pub rotation: Vec3,
    pub rotation_quaternion: Option<[f32; 4]>,
    pub scaling: Vec3,
}

impl Default for MeshMeta {
    fn default() -> Self {
        Self {
            name: Name::new(),
            id: Name::new(),
            material_id: None,
            position: Vec3::ZERO,
            rotation: Vec3::ZERO,
            rotation_quaternion: None,
            scaling: Vec3::ONE,
        }
    }
}

/// What the serde pass writes to; implemented by the scene so the seeds
/// need not carry its six capacities.
pub(crate) trait Store {
    fn geometry(&self, mesh: usize) -> Option<Geometry>;
    /// Lengths of the position, normal, uv and index pools.
    fn pool_lens(&self) -> [usize; 4];
    fn push_position(&mut self, v: Vec3) -> bool;
    fn push_normal(&mut self, v: Vec3) -> bool;
    fn push_uv(&mut self, v: Vec2) -> bool;
    fn push_index(&mut self, i: u16) -> bool;
    /// Normalizes (or computes) the mesh's normals and stores its fields.
    fn finish_mesh(&mut self, mesh: usize, meta: MeshMeta) -> bool;
    fn push_material(&mut self, m: BabylonMaterial) -> bool;
    fn push_light(&mut self, l: BabylonLight) -> bool;
    fn skip_light(&mut self);
    fn set_ambient(&mut self, c: Vec3);
    fn set_clear(&mut self, c: Vec3);
}

/// Loading state shared by all seeds.
pub(crate) struct Loader<'s, S: Store> {
    pub store: &'s mut S,
    /// Where the parse is, for error messages.
    pub at: Location,
    /// The loader's own error, when a seed failed for a reason serde-json-core
    /// has no kind for.
    pub error: Option<Error>,
    /// The id named by `activeCamera`.
    pub active: Option<Name>,
    /// The camera chosen so far, and whether it is the active one.
    pub camera: Option<BabylonCamera>,
    pub camera_is_active: bool,
}

const INTERNAL: &str = "internal: the pre-scan and the parse disagree";

/// What a seed reads.
#[derive(Clone, Copy)]
enum What {
    Root,
    Items(Section),
    Mesh(usize),
    Material,
    Camera,
    Light,
    Texture,
    /// A geometry array.
    Geo(Part, Geometry),
    SubMeshes(Geometry),
    SubMesh(Geometry),
    /// A short array of numbers: at least `min`, at most `max`.
    Floats {
        min: usize,
        max: usize,
        problem: &'static str,
    },
    Name,
}

#[derive(Clone, Copy)]
enum Section {
    Meshes,
    Materials,
    Cameras,
    Lights,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Part {
    Legacy,
    Positions,
    Normals,
    Uvs,
    Indices,
}

/// What a seed produced.
enum Out {
    Unit,
    Floats([f32; 4]),
    Name(Name),
    Texture(Option<Name>),
}

struct Seed<'l, 's, S: Store> {
    l: &'l mut Loader<'s, S>,
    what: What,
}

/// `null` reads as an absent field.
struct Opt<T>(T);

impl<'de, T: DeserializeSeed<'de>> DeserializeSeed<'de> for Opt<T> {
    type Value = Option<T::Value>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_option(self)
    }
}

impl<'de, T: DeserializeSeed<'de>> Visitor<'de> for Opt<T> {
    type Value = Option<T::Value>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a value or null")
    }
    fn visit_none<E: de::Error>(self) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_unit<E: de::Error>(self) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_some<D: Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        self.0.deserialize(d).map(Some)
    }
}

impl<'s, S: Store> Loader<'s, S> {
    pub(crate) fn new(store: &'s mut S, active: Option<Name>) -> Self {
        Self { store, at: Location::scene(None), error: None, active, camera: None, camera_is_active: false }
    }

    /// Deserializes the whole document.
    pub(crate) fn run<'de, D: Deserializer<'de>>(&mut self, d: D) -> Result<(), D::Error> {
        Seed { l: self, what: What::Root }.deserialize(d).map(|_| ())
    }

    /// Records `e` and returns the serde error that unwinds the parse.
    fn fail<E: de::Error>(&mut self, e: Error) -> E {
        if self.error.is_none() {
            self.error = Some(e);
        }
        E::custom("see the loader's error")
    }

    fn here(&self) -> Location {
        self.at.clone()
    }

    fn non_finite<E: de::Error>(&mut self) -> E {
        let at = self.here();
        self.fail(Error::NonFinite { at })
    }

    fn internal<E: de::Error>(&mut self) -> E {
        let at = self.here();
        self.fail(Error::Invalid { at, problem: INTERNAL })
    }

    fn enter(&mut self, field: &'static str) {
        self.at.field = Some(field);
        self.at.element = None;
    }

    fn value<'de, A: MapAccess<'de>>(&mut self, map: &mut A, what: What) -> Result<Option<Out>, A::Error> {
        map.next_value_seed(Opt(Seed { l: self, what }))
    }

    fn skip<'de, A: MapAccess<'de>>(&mut self, map: &mut A) -> Result<(), A::Error> {
        self.at.field = None;
        self.at.element = None;
        map.next_value::<IgnoredAny>().map(|_| ())
    }

    fn name<'de, A: MapAccess<'de>>(&mut self, map: &mut A, field: &'static str) -> Result<Option<Name>, A::Error> {
        self.enter(field);
        Ok(match self.value(map, What::Name)? {
            Some(Out::Name(n)) => Some(n),
            _ => None,
        })
    }

    fn floats<'de, A: MapAccess<'de>>(
        &mut self,
        map: &mut A,
        field: &'static str,
        min: usize,
        max: usize,
    ) -> Result<Option<[f32; 4]>, A::Error> {
        self.enter(field);
        let problem = match (min, max) {
            (3, 3) => "expected 3 numbers",
            (3, 4) => "expected 3 or 4 numbers",
            _ => "expected 4 numbers",
        };
        Ok(match self.value(map, What::Floats { min, max, problem })? {
            Some(Out::Floats(v)) => Some(v),
            _ => None,
        })
    }

    fn vec3<'de, A: MapAccess<'de>>(&mut self, map: &mut A, field: &'static str) -> Result<Option<Vec3>, A::Error> {
        Ok(self.floats(map, field, 3, 3)?.map(|v| Vec3::new(v[0], v[1], v[2])))
    }

    /// A `Color3`; a fourth (alpha) value is accepted and ignored.
    fn color<'de, A: MapAccess<'de>>(&mut self, map: &mut A, field: &'static str) -> Result<Option<Vec3>, A::Error> {
        Ok(self.floats(map, field, 3, 4)?.map(|v| Vec3::new(v[0], v[1], v[2])))
    }

    fn f32<'de, A: MapAccess<'de>>(&mut self, map: &mut A, field: &'static str) -> Result<Option<f32>, A::Error> {
        self.enter(field);
        match map.next_value_seed(Opt(PhantomData::<f32>))? {
            Some(v) if !v.is_finite() => Err(self.non_finite()),
            v => Ok(v),
        }
    }

    fn f64<'de, A: MapAccess<'de>>(&mut self, map: &mut A, field: &'static str) -> Result<Option<f64>, A::Error> {
        self.enter(field);
        match map.next_value_seed(Opt(PhantomData::<f64>))? {
            Some(v) if !v.is_finite() => Err(self.non_finite()),
            v => Ok(v),
        }
    }

    fn bool<'de, A: MapAccess<'de>>(&mut self, map: &mut A, field: &'static str) -> Result<Option<bool>, A::Error> {
        self.enter(field);
        map.next_value_seed(Opt(PhantomData::<bool>))
    }

    fn root<'de, A: MapAccess<'de>>(&mut self, mut map: A) -> Result<(), A::Error> {
        while let Some(key) = map.next_key::<&str>()? {
            self.at = Location::scene(None);
            let section = match key {
                "meshes" => Section::Meshes,
                "materials" => Section::Materials,
                "cameras" => Section::Cameras,
                "lights" => Section::Lights,
                "ambientColor" => {
                    if let Some(c) = self.color(&mut map, "ambientColor")? {
                        self.store.set_ambient(c);
                    }
                    continue;
                }
                "clearColor" => {
                    if let Some(c) = self.color(&mut map, "clearColor")? {
                        self.store.set_clear(c);
                    }
                    continue;
                }
                _ => {
                    self.skip(&mut map)?;
                    continue;
                }
            };
            self.enter(key_name(section));
            self.value(&mut map, What::Items(section))?;
        }
        self.at = Location::scene(None);
        Ok(())
    }

    fn items<'de, A: SeqAccess<'de>>(&mut self, section: Section, mut seq: A) -> Result<(), A::Error> {
        let mut i = 0;
        loop {
            let (item, what) = match section {
                Section::Meshes => (Item::Mesh(i), What::Mesh(i)),
                Section::Materials => (Item::Material(i), What::Material),
                Section::Cameras => (Item::Camera(i), What::Camera),
                Section::Lights => (Item::Light(i), What::Light),
            };
            self.at = Location::item(item);
            if seq.next_element_seed(Seed { l: self, what })?.is_none() {
                break;
            }
            i += 1;
        }
        self.at = Location::scene(Some(key_name(section)));
        Ok(())
    }

    fn mesh<'de, A: MapAccess<'de>>(&mut self, i: usize, mut map: A) -> Result<(), A::Error> {
        let Some(g) = self.store.geometry(i) else { return Err(self.internal()) };
        // The previous meshes filled exactly the places the pre-scan gave them.
        let [p, n, u, x] = self.store.pool_lens();
        if p != g.first_vertex || n != g.first_vertex || g.first_uv.is_some_and(|f| f != u) || x != g.first_index {
            return Err(self.internal());
        }
        let mut meta = MeshMeta::default();
        while let Some(key) = map.next_key::<&str>()? {
            match key {
                "name" => {
                    if let Some(n) = self.name(&mut map, "name")? {
                        self.at.set_name(&n);
                        meta.name = n;
                    }
                }
                "id" => meta.id = self.name(&mut map, "id")?.unwrap_or_default(),
                "materialId" => meta.material_id = self.name(&mut map, "materialId")?,
                "position" => meta.position = self.vec3(&mut map, "position")?.unwrap_or(Vec3::ZERO),
                "rotation" => meta.rotation = self.vec3(&mut map, "rotation")?.unwrap_or(Vec3::ZERO),
                "scaling" => meta.scaling = self.vec3(&mut map, "scaling")?.unwrap_or(Vec3::ONE),
                "rotationQuaternion" => meta.rotation_quaternion = self.floats(&mut map, "rotationQuaternion", 4, 4)?,
                "uvCount" => {
                    // Only its type is checked here: the pre-scan read the value.
                    self.f64(&mut map, "uvCount")?;
                }
                "vertices" | "positions" | "normals" | "uvs" | "indices" => {
                    let (field, part) = match key {
                        "vertices" => ("vertices", Part::Legacy),
                        "positions" => ("positions", Part::Positions),
                        "normals" => ("normals", Part::Normals),
                        "uvs" => ("uvs", Part::Uvs),
                        _ => ("indices", Part::Indices),
                    };
                    self.enter(field);
                    self.value(&mut map, What::Geo(part, g))?;
                }
                "subMeshes" => {
                    self.enter("subMeshes");
                    self.value(&mut map, What::SubMeshes(g))?;
                }
                _ => self.skip(&mut map)?,
            }
        }
        self.at.field = None;
        self.at.element = None;
        let [p, n, u, x] = self.store.pool_lens();
        let uv_end = g.first_uv.map_or(u, |f| f + g.vertices);
        let normals_ok = n == g.first_vertex || n == g.first_vertex + g.vertices;
        if p != g.first_vertex + g.vertices || !normals_ok || u != uv_end || x != g.first_index + g.indices {
            return Err(self.internal());
        }
        if !self.store.finish_mesh(i, meta) {
            return Err(self.internal());
        }
        Ok(())
    }

    fn geometry<'de, A: SeqAccess<'de>>(&mut self, part: Part, g: Geometry, mut seq: A) -> Result<(), A::Error> {
        if part == Part::Indices {
            return self.indices(g, seq);
        }
        let stride = match part {
            Part::Legacy => g.stride,
            Part::Positions | Part::Normals => 3,
            _ => 2,
        };
        if stride == 0 || (part == Part::Uvs && g.first_uv.is_none()) {
            return Err(self.internal());
        }
        let mut buf = [0.0f32; 10];
        let mut k = 0;
        loop {
            self.at.element = Some(k);
            let Some(v) = seq.next_element::<f32>()? else { break };
            if !v.is_finite() {
                return Err(self.non_finite());
            }
            // The pre-scan counted this array, so k stays below its length.
            buf[k % stride] = v;
            k += 1;
            if k % stride == 0 {
                let p = Vec3::new(buf[0], buf[1], buf[2]);
                let ok = match part {
                    Part::Positions => self.store.push_position(p),
                    Part::Normals => self.store.push_normal(p),
                    Part::Uvs => self.store.push_uv(Vec2::new(buf[0], buf[1])),
                    // Legacy: position, normal, then uv sets; the first is kept.
                    _ => {
                        self.store.push_position(p)
                            && self.store.push_normal(Vec3::new(buf[3], buf[4], buf[5]))
                            && (stride == 6 || self.store.push_uv(Vec2::new(buf[6], buf[7])))
                    }
                };
                if !ok {
                    return Err(self.internal());
                }
            }
        }
        self.at.element = None;
        Ok(())
    }

    fn indices<'de, A: SeqAccess<'de>>(&mut self, g: Geometry, mut seq: A) -> Result<(), A::Error> {
        let mut k = 0;
        loop {
            self.at.element = Some(k);
            // f64 so that `3.0` is accepted (some exporters write integers so).
            let Some(v) = seq.next_element::<f64>()? else { break };
            if !v.is_finite() {
                return Err(self.non_finite());
            }
            let integral = v == (v as i64) as f64;
            if !integral && v.abs() < 9.0e18 {
                let at = self.here();
                return Err(self.fail(Error::Json { kind: JsonError::InvalidNumber, at }));
            }
            if v < 0.0 || v >= g.vertices as f64 {
                let at = self.here();
                return Err(self.fail(Error::IndexOutOfRange { at, index: v as i64, vertices: g.vertices }));
            }
            if !self.store.push_index(v as u16) {
                return Err(self.internal());
            }
            k += 1;
        }
        self.at.element = None;
        Ok(())
    }

    fn sub_meshes<'de, A: SeqAccess<'de>>(&mut self, g: Geometry, mut seq: A) -> Result<(), A::Error> {
        let mut k = 0;
        loop {
            self.at.field = Some("subMeshes");
            self.at.element = Some(k);
            if seq.next_element_seed(Seed { l: self, what: What::SubMesh(g) })?.is_none() {
                break;
            }
            k += 1;
        }
        self.at.element = None;
        Ok(())
    }

    /// Checks that a sub-mesh's ranges lie inside its mesh.
    fn sub_mesh<'de, A: MapAccess<'de>>(&mut self, g: Geometry, mut map: A) -> Result<(), A::Error> {
        let mut v = [0.0f64; 4];
        while let Some(key) = map.next_key::<&str>()? {
            let slot = match key {
                "verticesStart" => 0,
                "verticesCount" => 1,
                "indexStart" => 2,
                "indexCount" => 3,
                _ => {
                    map.next_value::<IgnoredAny>()?;
                    continue;
                }
            };
            match map.next_value_seed(Opt(PhantomData::<f64>))? {
                Some(x) if !x.is_finite() => return Err(self.non_finite()),
                Some(x) => v[slot] = x,
                None => {}
            }
        }
        let whole = v.iter().all(|x| *x >= 0.0 && *x == (*x as u64) as f64);
        if !whole || v[0] + v[1] > g.vertices as f64 || v[2] + v[3] > g.indices as f64 {
            let at = self.here();
            return Err(self.fail(Error::Invalid { at, problem: "subMesh range outside the mesh" }));
        }
        Ok(())
    }

    fn floats_seq<'de, A: SeqAccess<'de>>(&mut self, min: usize, max: usize, problem: &'static str, mut seq: A) -> Result<Out, A::Error> {
        let mut out = [0.0f32; 4];
        let mut n = 0;
        loop {
            self.at.element = Some(n);
            let Some(v) = seq.next_element::<f32>()? else { break };
            if !v.is_finite() {
                return Err(self.non_finite());
            }
            if n == max {
                self.at.element = None;
                let at = self.here();
                return Err(self.fail(Error::Invalid { at, problem }));
            }
            out[n] = v;
            n += 1;
        }
        self.at.element = None;
        if n < min {
            let at = self.here();
            return Err(self.fail(Error::Invalid { at, problem }));
        }
        Ok(Out::Floats(out))
    }

    fn material<'de, A: MapAccess<'de>>(&mut self, mut map: A) -> Result<(), A::Error> {
        let mut m = BabylonMaterial::default();
        while let Some(key) = map.next_key::<&str>()? {
            match key {
                "name" => {
                    if let Some(n) = self.name(&mut map, "name")? {
                        self.at.set_name(&n);
                        m.name = n;
                    }
                }
                "id" => m.id = self.name(&mut map, "id")?.unwrap_or_default(),
                "diffuse" => m.diffuse = self.color(&mut map, "diffuse")?.unwrap_or(m.diffuse),
                "specular" => m.specular = self.color(&mut map, "specular")?.unwrap_or(m.specular),
                "ambient" => m.ambient = self.color(&mut map, "ambient")?.unwrap_or(m.ambient),
                "emissive" => m.emissive = self.color(&mut map, "emissive")?.unwrap_or(m.emissive),
                "specularPower" => m.specular_power = self.f32(&mut map, "specularPower")?.unwrap_or(m.specular_power),
                "alpha" => m.alpha = self.f32(&mut map, "alpha")?.unwrap_or(m.alpha),
                "backFaceCulling" => m.back_face_culling = self.bool(&mut map, "backFaceCulling")?.unwrap_or(true),
                "diffuseTexture" => {
                    self.enter("diffuseTexture");
                    if let Some(Out::Texture(t)) = self.value(&mut map, What::Texture)? {
                        m.diffuse_texture = t;
                    }
                }
                _ => self.skip(&mut map)?,
            }
        }
        self.at.field = None;
        if !self.store.push_material(m) {
            return Err(self.internal());
        }
        Ok(())
    }

    fn texture<'de, A: MapAccess<'de>>(&mut self, mut map: A) -> Result<Option<Name>, A::Error> {
        let mut name = None;
        while let Some(key) = map.next_key::<&str>()? {
            match key {
                "name" => name = self.name(&mut map, "diffuseTexture.name")?,
                _ => map.next_value::<IgnoredAny>().map(|_| ())?,
            }
        }
        Ok(name)
    }

    fn camera<'de, A: MapAccess<'de>>(&mut self, mut map: A) -> Result<(), A::Error> {
        let mut c = BabylonCamera::default();
        while let Some(key) = map.next_key::<&str>()? {
            match key {
                "name" => {
                    if let Some(n) = self.name(&mut map, "name")? {
                        self.at.set_name(&n);
                        c.name = n;
                    }
                }
                "id" => c.id = self.name(&mut map, "id")?.unwrap_or_default(),
                "position" => c.position = self.vec3(&mut map, "position")?.unwrap_or(Vec3::ZERO),
                "target" => c.target = self.vec3(&mut map, "target")?,
                "rotation" => c.rotation = self.vec3(&mut map, "rotation")?.unwrap_or(Vec3::ZERO),
                "upVector" => c.up_vector = self.vec3(&mut map, "upVector")?.unwrap_or(c.up_vector),
                "fov" => c.fov = self.f32(&mut map, "fov")?.unwrap_or(c.fov),
                "minZ" => c.min_z = self.f32(&mut map, "minZ")?.unwrap_or(c.min_z),
                "maxZ" => c.max_z = self.f32(&mut map, "maxZ")?.unwrap_or(c.max_z),
                _ => self.skip(&mut map)?,
            }
        }
        self.at.field = None;
        // Babylon names the active camera by id; a camera without one by name.
        let key = if c.id.is_empty() { &c.name } else { &c.id };
        let active = self.active.as_ref() == Some(key);
        if (active && !self.camera_is_active) || self.camera.is_none() {
            self.camera = Some(c);
            self.camera_is_active = active;
        }
        Ok(())
    }

    fn light<'de, A: MapAccess<'de>>(&mut self, mut map: A) -> Result<(), A::Error> {
        let mut l = BabylonLight::default();
        let (mut kind, mut position, mut direction, mut data) = (None, None, None, None);
        while let Some(key) = map.next_key::<&str>()? {
            match key {
                "name" => {
                    if let Some(n) = self.name(&mut map, "name")? {
                        self.at.set_name(&n);
                        l.name = n;
                    }
                }
                "id" => l.id = self.name(&mut map, "id")?.unwrap_or_default(),
                // Some exporters write `0.0`.
                "type" => kind = self.f64(&mut map, "type")?,
                "position" => position = self.vec3(&mut map, "position")?,
                "direction" => direction = self.vec3(&mut map, "direction")?,
                "data" => data = self.vec3(&mut map, "data")?,
                "intensity" => l.intensity = self.f32(&mut map, "intensity")?.unwrap_or(l.intensity),
                "diffuse" => l.diffuse = self.color(&mut map, "diffuse")?.unwrap_or(l.diffuse),
                "specular" => l.specular = self.color(&mut map, "specular")?.unwrap_or(l.specular),
                _ => self.skip(&mut map)?,
            }
        }
        self.at.field = None;
        // Legacy files put the position (point) or direction (directional)
        // in `data`.
        l.kind = match kind {
            Some(0.0) => LightKind::Point { position: position.or(data).unwrap_or(Vec3::ZERO) },
            Some(1.0) => LightKind::Directional { direction: direction.or(data).unwrap_or(Vec3::ZERO) },
            _ => {
                self.store.skip_light();
                return Ok(());
            }
        };
        if !self.store.push_light(l) {
            return Err(self.internal());
        }
        Ok(())
    }
}

fn key_name(section: Section) -> &'static str {
    match section {
        Section::Meshes => "meshes",
        Section::Materials => "materials",
        Section::Cameras => "cameras",
        Section::Lights => "lights",
    }
}

impl<'de, S: Store> DeserializeSeed<'de> for Seed<'_, '_, S> {
    type Value = Out;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Out, D::Error> {
        match self.what {
            What::Name => d.deserialize_str(self),
            What::Items(_) | What::Geo(..) | What::SubMeshes(_) | What::Floats { .. } => d.deserialize_seq(self),
            _ => d.deserialize_map(self),
        }
    }
}

impl<'de, S: Store> Visitor<'de> for Seed<'_, '_, S> {
    type Value = Out;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self.what {
            What::Name => "a string",
            What::Items(_) | What::Geo(..) | What::SubMeshes(_) | What::Floats { .. } => "an array",
            _ => "an object",
        })
    }

    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Out, A::Error> {
        let l = self.l;
        match self.what {
            What::Root => l.root(map).map(|()| Out::Unit),
            What::Mesh(i) => l.mesh(i, map).map(|()| Out::Unit),
            What::Material => l.material(map).map(|()| Out::Unit),
            What::Camera => l.camera(map).map(|()| Out::Unit),
            What::Light => l.light(map).map(|()| Out::Unit),
            What::Texture => l.texture(map).map(Out::Texture),
            What::SubMesh(g) => l.sub_mesh(g, map).map(|()| Out::Unit),
            _ => Err(l.internal()),
        }
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Out, A::Error> {
        let l = self.l;
        match self.what {
            What::Items(section) => l.items(section, seq).map(|()| Out::Unit),
            What::Geo(part, g) => l.geometry(part, g, seq).map(|()| Out::Unit),
            What::SubMeshes(g) => l.sub_meshes(g, seq).map(|()| Out::Unit),
            What::Floats { min, max, problem } => l.floats_seq(min, max, problem, seq),
            _ => Err(l.internal()),
        }
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Out, E> {
        let l = self.l;
        let mut name = Name::new();
        match decode_name(v, &mut name) {
            Ok(()) => Ok(Out::Name(name)),
            Err(needed) => {
                let at = l.here();
                Err(l.fail(Error::Capacity { container: Container::Name, at, capacity: NAME_LEN, needed }))
            }
        }
    }
}
