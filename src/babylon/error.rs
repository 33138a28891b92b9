//! What went wrong while loading a scene, and where.

use super::{MAX_DEPTH, NAME_LEN};
use core::fmt;

/// serde-json-core's error kind, used for every malformed-JSON error (also
/// for those found by the loader's own syntax pre-scan, which knows the
/// byte offset).
pub use serde_json_core::de::Error as JsonError;

/// Which object of the scene file a [`Location`] is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Item {
    /// The top-level object (fields such as `ambientColor`, `meshes`).
    Scene,
    /// `meshes[i]`.
    Mesh(usize),
    /// `materials[i]`.
    Material(usize),
    /// `cameras[i]`.
    Camera(usize),
    /// `lights[i]` (the index in the file's array, skipped lights included).
    Light(usize),
}

/// The capacity of [`Location::name`]: names are shortened there so that
/// an [`Error`] stays small (under 128 bytes) to return.
pub const LOCATION_NAME_LEN: usize = 24;

/// Where in the file an error is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The object.
    pub item: Item,
    /// Its `name`, when it was read before the error (empty otherwise);
    /// names longer than [`LOCATION_NAME_LEN`] bytes are cut and end in `…`.
    pub name: heapless::String<LOCATION_NAME_LEN>,
    /// The field, if any; nested fields are joined by dots
    /// (`diffuseTexture.name`).
    pub field: Option<&'static str>,
    /// The element of an array field, if any (for `vertices` and the other
    /// geometry arrays, the position of the number in the array).
    pub element: Option<usize>,
    /// Byte offset in the input, when known.
    pub offset: Option<usize>,
}

impl Location {
    /// A location at the top level, in `field`.
    pub(crate) const fn scene(field: Option<&'static str>) -> Self {
        Self { item: Item::Scene, name: heapless::String::new(), field, element: None, offset: None }
    }

    /// A location in `item`, without a field.
    pub(crate) const fn item(item: Item) -> Self {
        Self { item, name: heapless::String::new(), field: None, element: None, offset: None }
    }

    /// Sets the item's name, shortened to fit.
    pub(crate) fn set_name(&mut self, name: &str) {
        self.name.clear();
        if self.name.push_str(name).is_err() {
            // Cut on a character boundary, leaving room for the ellipsis.
            let mut end = LOCATION_NAME_LEN - '…'.len_utf8();
            while !name.is_char_boundary(end) {
                end -= 1;
            }
            let _ = self.name.push_str(&name[..end]);
            let _ = self.name.push('…');
        }
    }

    /// The same location at byte `offset`.
    pub(crate) fn at(mut self, offset: usize) -> Self {
        self.offset = Some(offset);
        self
    }

    /// The same location in `field`.
    pub(crate) fn field(mut self, field: &'static str) -> Self {
        self.field = Some(field);
        self
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.item {
            Item::Scene => f.write_str("scene")?,
            Item::Mesh(i) => write!(f, "mesh {i}")?,
            Item::Material(i) => write!(f, "material {i}")?,
            Item::Camera(i) => write!(f, "camera {i}")?,
            Item::Light(i) => write!(f, "light {i}")?,
        }
        if !self.name.is_empty() {
            write!(f, " '{}'", self.name)?;
        }
        if let Some(field) = self.field {
            write!(f, " {field}")?;
        }
        if let Some(e) = self.element {
            write!(f, "[{e}]")?;
        }
        if let Some(o) = self.offset {
            write!(f, " (byte {o})")?;
        }
        Ok(())
    }
}

/// A container whose capacity was too small.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Container {
    /// The mesh list (`MESHES`).
    Meshes,
    /// The material list (`MATERIALS`).
    Materials,
    /// The list of point and directional lights (`LIGHTS`).
    Lights,
    /// The vertex pool shared by all meshes (`VERTICES`).
    Vertices,
    /// The texture-coordinate pool shared by the meshes that have them (`UVS`).
    Uvs,
    /// The index pool shared by all meshes (`INDICES`).
    Indices,
    /// A name, id or texture name ([`NAME_LEN`] bytes).
    Name,
}

impl Container {
    /// The const parameter (or constant) that sets this capacity.
    pub const fn parameter(self) -> &'static str {
        match self {
            Container::Meshes => "MESHES",
            Container::Materials => "MATERIALS",
            Container::Lights => "LIGHTS",
            Container::Vertices => "VERTICES",
            Container::Uvs => "UVS",
            Container::Indices => "INDICES",
            Container::Name => "NAME_LEN",
        }
    }
}

/// Why a scene was rejected. Every variant says what and where; loading
/// never panics, whatever the input.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    /// Malformed JSON, or JSON of the wrong shape (a string where numbers
    /// belong, say). The offset in `at` is known for syntax errors; for
    /// type errors it is looked up from the location.
    Json {
        /// serde-json-core's error kind.
        kind: JsonError,
        /// Where.
        at: Location,
    },
    /// Arrays and objects nested deeper than [`MAX_DEPTH`] (refused before
    /// parsing, because serde-json-core recurses once per level).
    TooDeep {
        /// The depth reached (`MAX_DEPTH + 1`).
        depth: usize,
        /// Byte offset of the bracket that went too deep.
        offset: usize,
    },
    /// A container is too small for the file.
    Capacity {
        /// Which container.
        container: Container,
        /// What did not fit: for the shared pools, the first mesh that
        /// overflows; for names, the field.
        at: Location,
        /// The capacity.
        capacity: usize,
        /// The size the whole file needs (for names, the name's length).
        needed: usize,
    },
    /// A triangle index names a vertex the mesh does not have.
    IndexOutOfRange {
        /// The mesh, with `field` `indices` and `element` the position in
        /// the index array.
        at: Location,
        /// The index found there.
        index: i64,
        /// The mesh's vertex count.
        vertices: usize,
    },
    /// A geometry array whose length is not a multiple of its stride.
    Stride {
        /// The mesh and the array (`vertices`, `positions`, `normals`, `uvs`).
        at: Location,
        /// The number of values in the array.
        len: usize,
        /// Values per vertex: 3 for positions and normals, 2 for uvs, 6, 8 or
        /// 10 for legacy `vertices` (by `uvCount`).
        stride: usize,
    },
    /// A number that is not a finite `f32` (too large, or `null` inside an
    /// array of numbers).
    NonFinite {
        /// Where.
        at: Location,
    },
    /// An index count that is not a multiple of three.
    IndexCount {
        /// The mesh's `indices`.
        at: Location,
        /// The count.
        count: usize,
    },
    /// A mesh with more vertices than a `u16` index can address.
    TooManyVertices {
        /// The mesh.
        at: Location,
        /// Its vertex count.
        count: usize,
    },
    /// `normals` or `uvs` do not have one entry per position.
    AttributeLength {
        /// The mesh and the array.
        at: Location,
        /// Entries in the array (values / stride).
        len: usize,
        /// The number of positions.
        expected: usize,
    },
    /// Anything else the loader refuses (a duplicate section, an
    /// unsupported `uvCount`, a vector of the wrong length, a sub-mesh
    /// outside its mesh).
    Invalid {
        /// Where.
        at: Location,
        /// What is wrong.
        problem: &'static str,
    },
}

impl Error {
    /// The location of the error, if it has one ([`Error::TooDeep`] has only
    /// an offset).
    pub fn location(&self) -> Option<&Location> {
        match self {
            Error::TooDeep { .. } => None,
            Error::Json { at, .. }
            | Error::Capacity { at, .. }
            | Error::IndexOutOfRange { at, .. }
            | Error::Stride { at, .. }
            | Error::NonFinite { at }
            | Error::IndexCount { at, .. }
            | Error::TooManyVertices { at, .. }
            | Error::AttributeLength { at, .. }
            | Error::Invalid { at, .. } => Some(at),
        }
    }

    /// The byte offset of the error in the input, when known.
    pub fn offset(&self) -> Option<usize> {
        match self {
            Error::TooDeep { offset, .. } => Some(*offset),
            e => e.location().and_then(|at| at.offset),
        }
    }

    pub(crate) fn location_mut(&mut self) -> Option<&mut Location> {
        match self {
            Error::TooDeep { .. } => None,
            Error::Json { at, .. }
            | Error::Capacity { at, .. }
            | Error::IndexOutOfRange { at, .. }
            | Error::Stride { at, .. }
            | Error::NonFinite { at }
            | Error::IndexCount { at, .. }
            | Error::TooManyVertices { at, .. }
            | Error::AttributeLength { at, .. }
            | Error::Invalid { at, .. } => Some(at),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Json { kind, at } => write!(f, "{at}: JSON error: {kind}"),
            Error::TooDeep { depth, offset } => {
                write!(f, "nesting depth {depth} at byte {offset} exceeds the limit of {MAX_DEPTH}")
            }
            Error::Capacity { container, at, capacity, needed } => {
                let p = container.parameter();
                write!(f, "{at}: capacity {p} = {capacity} is too small, {needed} needed")?;
                if *container == Container::Name {
                    write!(f, " (names hold at most {NAME_LEN} bytes)")?;
                }
                Ok(())
            }
            Error::IndexOutOfRange { at, index, vertices } => {
                write!(f, "{at}: index {index} is out of range (the mesh has {vertices} vertices)")
            }
            Error::Stride { at, len, stride } => write!(f, "{at}: {len} values is not a multiple of {stride}"),
            Error::NonFinite { at } => write!(f, "{at}: not a finite f32 (too large, or null)"),
            Error::IndexCount { at, count } => write!(f, "{at}: index count {count} is not a multiple of 3"),
            Error::TooManyVertices { at, count } => write!(f, "{at}: {count} vertices; at most 65536 can be indexed"),
            Error::AttributeLength { at, len, expected } => write!(f, "{at}: {len} entries for {expected} positions"),
            Error::Invalid { at, problem } => write!(f, "{at}: {problem}"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for Error {}
