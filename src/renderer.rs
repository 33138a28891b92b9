//! The renderer: per-frame buffers, triangle assembly and binning, and the
//! strip loop that rasterizes and hands each strip to the `DrawTarget`.
//!
//! A frame has two phases. While draw calls are made, meshes go through
//! the vertex stage into a fixed-capacity vertex buffer, once per frame, and
//! their visible triangles (culled, clipped) are queued as 16-byte records.
//! [`Frame::finish`] then bins the records by first strip and, strip by
//! strip, clears the strip's color and depth, rasterizes the triangles that
//! overlap it in submission order, and sends it with one `fill_contiguous`.
//!
//! RAM (`size_of::<Renderer>()`, checked by a test):
//!
//! ```text
//! W·STRIP·(size_of::<C>() + Z)     color and depth strips (Z: 2 bytes
//!                                  for Depth16, 4 for Depth32, DepthF32)
//! + VERTS·(16 + 4·V)               transformed vertices
//! + TRIS·12                        queued triangles
//! + 2·H                            per-strip list heads
//! + size_of::<C>()                 the background the strips hold
//! ```
//! rounded up to a multiple of 4. A [`Frame`] adds about 80 bytes per
//! draw-call slot ([`MAX_DRAW_CALLS`]: the material and the draw call's
//! lights) on the stack while it is recorded.

use crate::clip::{self, BackFaceTest, ClipVertex, Polygon, SphereTest, WindowVertex, NO_SOURCE};
use crate::effect::{vertex_varyings, Color, Effect, FaceInput, VertexInput};
use crate::material::{Cull, DepthMode, Material, Perspective};
use crate::math::{Mat4, Vec2, Vec3};
use crate::mesh::Mesh;
use crate::raster::{self, first_row_at_or_below, signed_area2, snap_f64, ScreenVertex, SortedCorners, StripTarget};
use crate::scene::{Camera, Lighting, Lights};
use crate::settings::{DepthFormat, DepthValue, FixedPoint, Settings};
use crate::tri::TriVertex;
use crate::vertex::{self, FloatVertices, IntegerLighting, IntegerProjection, IntegerVertices, VertexArithmetic, VertexStage};
use core::marker::PhantomData;
use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use embedded_graphics::prelude::{Point, Size};
use embedded_graphics::primitives::Rectangle;
use heapless::Vec;

/// Most draw calls in one frame.
pub const MAX_DRAW_CALLS: usize = 32;

const NONE: u16 = u16::MAX;

/// A queued triangle: indices into the frame's vertex buffer, the link of
/// its strip list and the per-triangle color (12 bytes; its rows are
/// recomputed from its vertices when needed).
#[derive(Clone, Copy, Debug)]
struct TriRecord {
    /// Corners, sorted by `y` (top first) when queued.
    v: [u16; 3],
    /// Until `finish` bins the triangle, the first strip it covers (found
    /// when it was queued); then the next triangle of its strip's list.
    next: u16,
    /// Written only for effects that use a face color (others leave what
    /// a previous frame left there).
    face: [u8; 3],
}

impl TriRecord {
    // All zeros, so that a black renderer is zero-initialized.
    const EMPTY: Self = Self { v: [0; 3], next: 0, face: [0; 3] };
}

/// Why a draw call was refused. The frame is left as it was before the
/// call: nothing of the refused mesh is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawError {
    /// The vertex buffer (`VERTS`) cannot hold this mesh's vertices.
    VertexCapacity {
        /// Vertices the frame would need.
        needed: usize,
        /// The buffer's capacity.
        capacity: usize,
    },
    /// The triangle buffer (`TRIS`) filled up while queuing this mesh.
    TriangleCapacity {
        /// The buffer's capacity.
        capacity: usize,
    },
    /// More than [`MAX_DRAW_CALLS`] draw calls in one frame.
    DrawCallCapacity,
}

impl core::fmt::Display for DrawError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self {
            DrawError::VertexCapacity { needed, capacity } => {
                write!(f, "vertex buffer too small: frame needs {needed} vertices, capacity is {capacity}")
            }
            DrawError::TriangleCapacity { capacity } => {
                write!(f, "triangle buffer full: capacity is {capacity} visible triangles")
            }
            DrawError::DrawCallCapacity => write!(f, "more than {MAX_DRAW_CALLS} draw calls in one frame"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for DrawError {}

/// Largest window coordinate (pixels) a window-space triangle may have:
/// beyond it an edge's length could overflow `f64`.
pub const WINDOW_LIMIT: f64 = 1e300;

/// What happened to the geometry of a frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameStats {
    /// Draw calls accepted.
    pub draw_calls: u32,
    /// Meshes skipped whole: bounding sphere outside the frustum.
    pub meshes_culled: u32,
    /// Meshes skipped whole: non-finite model or view-projection matrix.
    pub meshes_invalid: u32,
    /// Vertices of the meshes drawn (not culled whole). With face planes,
    /// those only back faces use are counted but not transformed.
    pub vertices: u32,
    /// Triangles submitted.
    pub triangles: u32,
    /// Triangles dropped as back faces.
    pub back_facing: u32,
    /// Triangles with zero area after snapping.
    pub degenerate: u32,
    /// Triangles (or clipped pieces) that cover no pixel center: entirely
    /// off screen, between pixel centers (their bounds hold no row or no
    /// column center), behind the near plane or beyond the far plane.
    pub off_screen: u32,
    /// Triangles that needed clipping.
    pub clipped: u32,
    /// Triangles skipped for a non-finite vertex.
    pub invalid: u32,
    /// Triangle records queued for rasterization.
    pub queued: u32,
}

/// The rasterization half of a material, erased so that one frame can mix
/// materials. Implemented for every [`Material`]; each implementation is a
/// separate monomorphized span loop.
pub trait MaterialProgram<C, S: Settings, const V: usize> {
    /// Rasterizes into a strip the triangles `queue` holds next, up to
    /// (not including) triangle index `end` (where the next draw call
    /// starts), lit by `lights` (the draw call's, for effects that light
    /// pixels). One call per strip and draw call, not per triangle: the
    /// material's uniforms are set up once, and the triangle loop calls
    /// its rasterizer directly.
    fn rasterize_run(&self, target: &mut StripTarget<'_, C, DepthValue<S>>, queue: &mut StripQueue<'_, V>, end: u16, lights: &Lighting);
}

impl<C, S, E, P, D, const V: usize> MaterialProgram<C, S, V> for Material<E, P, D>
where
    C: Color,
    S: Settings,
    E: Effect,
    P: Perspective,
    D: DepthMode,
{
    fn rasterize_run(&self, target: &mut StripTarget<'_, C, DepthValue<S>>, queue: &mut StripQueue<'_, V>, end: u16, lights: &Lighting) {
        let uniforms = self.effect.uniforms::<S::Interp>(lights, self.color);
        while let Some((tri, face)) = queue.pop_before(end) {
            // Read and converted only for effects that use it.
            let face = if E::USES_FACE { C::from(Rgb888::new(face[0], face[1], face[2])) } else { C::BLACK };
            raster::rasterize::<C, S::Interp, E, P, D, S::Depth, V>(
                target,
                &self.effect,
                &uniforms,
                SortedCorners::presorted(tri),
                face,
                S::SUBPIXEL_BITS,
            );
        }
    }
}

/// The triangles one strip draws, in submission order: those binned to
/// it merged with those carried over from the strip above. Triangles that
/// reach below the strip are carried over to the next one as they are
/// taken.
pub struct StripQueue<'q, const V: usize> {
    tris: &'q mut [TriRecord],
    vertices: &'q [ScreenVertex<V>],
    /// Heads of the two lists: binned here, carried from above. In `u32`,
    /// not `u16` as stored: as `u16` they were zero-extended again at
    /// every use, five instructions a triangle on the M4F.
    fresh: u32,
    old: u32,
    /// The list carried to the next strip.
    next_head: u16,
    next_tail: u16,
    /// The center of the frame row below the strip (see
    /// [`raster::row_center`]): a triangle whose bottom vertex's snapped
    /// `y` is greater reaches below the strip. One compare a triangle,
    /// not the bottom vertex's row and a compare.
    carry_below: i32,
}

impl<const V: usize> StripQueue<'_, V> {
    /// Index of the next triangle, `NONE` when there is none: the two
    /// lists merged by index (an empty list's head, `NONE`, is above every
    /// index).
    #[inline(always)]
    fn head(&self) -> u32 {
        self.fresh.min(self.old)
    }

    /// [`StripQueue::head`] as stored.
    #[inline(always)]
    fn peek(&self) -> u16 {
        self.head() as u16
    }

    /// The next triangle's vertices and face color, if its index is below
    /// `end`.
    #[inline(always)]
    fn pop_before(&mut self, end: u16) -> Option<([&ScreenVertex<V>; 3], [u8; 3])> {
        let i = self.head();
        if i >= end as u32 {
            return None;
        }
        let rec = *self.tris.get(i as usize)?;
        if i == self.fresh {
            self.fresh = rec.next as u32;
        } else {
            self.old = rec.next as u32;
        }
        let i = i as u16;
        let vs = self.vertices;
        let tri = [&vs[rec.v[0] as usize], &vs[rec.v[1] as usize], &vs[rec.v[2] as usize]];
        // (Corners sorted by y when queued: the last is the bottom.)
        if tri[2].y > self.carry_below {
            self.tris[i as usize].next = NONE;
            if self.next_tail == NONE {
                self.next_head = i;
            } else {
                self.tris[self.next_tail as usize].next = i;
            }
            self.next_tail = i;
        }
        Some((tri, rec.face))
    }
}

/// A strip renderer for a `W`×`H` display, with all buffers inline.
///
/// - `C`: the display's color type (e.g. `Rgb565`).
/// - `STRIP`: rows rendered at a time; `STRIP == H` renders the full frame.
/// - `VERTS`: transformed vertices per frame (sum of all drawn meshes'
///   vertices, plus a few per clipped triangle).
/// - `TRIS`: visible triangles per frame (after culling).
/// - `V`: varyings stored per vertex (3 suffices for the color effects).
/// - `S`: numeric [`Settings`].
///
/// See the [module docs](self) for the RAM formula. `new` is a `const fn`,
/// so a renderer can be placed in a `static` rather than on the stack.
pub struct Renderer<
    C,
    const W: usize,
    const H: usize,
    const STRIP: usize,
    const VERTS: usize,
    const TRIS: usize,
    const V: usize = 3,
    S: Settings = FixedPoint,
> {
    color: [[C; W]; STRIP],
    depth: [[DepthValue<S>; W]; STRIP],
    vertices: [ScreenVertex<V>; VERTS],
    triangles: [TriRecord; TRIS],
    heads: [u16; H],
    clean: C,
    _settings: PhantomData<S>,
}

impl<C, const W: usize, const H: usize, const STRIP: usize, const VERTS: usize, const TRIS: usize, const V: usize, S>
    Renderer<C, W, H, STRIP, VERTS, TRIS, V, S>
where
    C: Color,
    S: Settings,
{
    const VALID: () = {
        assert!(W > 0 && H > 0 && STRIP > 0 && STRIP <= H, "need 0 < STRIP <= H and a non-empty screen");
        assert!(W <= MAX_SIZE && H <= MAX_SIZE, "screen too large");
        assert!(VERTS < NONE as usize && TRIS < NONE as usize, "VERTS and TRIS must be below 65535");
        assert!(S::SUBPIXEL_BITS <= 8, "at most 8 sub-pixel bits");
    };

    /// A renderer whose strips start filled with `fill`.
    pub const fn new(fill: C) -> Self {
        #[allow(clippy::let_unit_value)]
        let () = Self::VALID;
        Self {
            color: [[fill; W]; STRIP],
            depth: [[S::Depth::CLEAR; W]; STRIP],
            vertices: [ScreenVertex::ZERO; VERTS],
            triangles: [TriRecord::EMPTY; TRIS],
            heads: [0; H],
            clean: fill,
            _settings: PhantomData,
        }
    }

    /// Starts a frame seen from `camera`, lit by `lights`, on a
    /// `background` color.
    pub fn begin_frame<'r, 'm>(&'r mut self, camera: &Camera, lights: &Lights, background: C) -> Frame<'r, 'm, C, V, S> {
        let view_proj = camera.projection(W as f32 / H as f32) * camera.view();
        self.begin_frame_with(view_proj, lights, background)
    }

    /// Starts a frame with an explicit view-projection matrix (clip space
    /// as [`Mat4::perspective_fov_lh`] produces: `0 <= z <= w` visible).
    pub fn begin_frame_with<'r, 'm>(&'r mut self, view_proj: Mat4, lights: &Lights, background: C) -> Frame<'r, 'm, C, V, S> {
        let buffers = Buffers {
            color: self.color.as_flattened_mut(),
            depth: self.depth.as_flattened_mut(),
            vertices: &mut self.vertices,
            triangles: &mut self.triangles,
            heads: &mut self.heads,
            clean: &mut self.clean,
            width: W,
            height: H,
            strip: STRIP,
        };
        Frame::new(buffers, view_proj, lights, background)
    }
}

/// Largest width or height a renderer accepts.
pub const MAX_SIZE: usize = 1 << 14;

/// Why a [`HostRenderer`] cannot be built.
#[cfg(feature = "std")]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SizeError;

#[cfg(feature = "std")]
impl core::fmt::Display for SizeError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "need 1 <= width, height <= {MAX_SIZE}, 1 <= strip <= height, and capacities below 65535")
    }
}

#[cfg(feature = "std")]
impl std::error::Error for SizeError {}

/// [`Renderer`] with sizes chosen at run time and buffers on the heap, for
/// host tools (feature `std`). Renders the same pixels as [`Renderer`].
#[cfg(feature = "std")]
pub struct HostRenderer<C, const V: usize = 3, S: Settings = FixedPoint> {
    color: std::vec::Vec<C>,
    depth: std::vec::Vec<DepthValue<S>>,
    vertices: std::vec::Vec<ScreenVertex<V>>,
    triangles: std::vec::Vec<TriRecord>,
    heads: std::vec::Vec<u16>,
    clean: C,
    width: usize,
    height: usize,
    strip: usize,
    _settings: PhantomData<S>,
}

#[cfg(feature = "std")]
impl<C, const V: usize, S> HostRenderer<C, V, S>
where
    C: Color,
    S: Settings,
{
    /// A `width`×`height` renderer with `strip` rows per strip and room for
    /// `vertices` transformed vertices and `triangles` queued triangles.
    pub fn new(width: usize, height: usize, strip: usize, vertices: usize, triangles: usize, fill: C) -> Result<Self, SizeError> {
        let ok = (1..=MAX_SIZE).contains(&width)
            && (1..=MAX_SIZE).contains(&height)
            && (1..=height).contains(&strip)
            && vertices < NONE as usize
            && triangles < NONE as usize
            && S::SUBPIXEL_BITS <= 8;
        if !ok {
            return Err(SizeError);
        }
        Ok(Self {
            color: std::vec![fill; width * strip],
            depth: std::vec![S::Depth::CLEAR; width * strip],
            vertices: std::vec![ScreenVertex::ZERO; vertices],
            triangles: std::vec![TriRecord::EMPTY; triangles],
            heads: std::vec![0; height],
            clean: fill,
            width,
            height,
            strip,
            _settings: PhantomData,
        })
    }

    /// Starts a frame seen from `camera`.
    pub fn begin_frame<'r, 'm>(&'r mut self, camera: &Camera, lights: &Lights, background: C) -> Frame<'r, 'm, C, V, S> {
        let view_proj = camera.projection(self.width as f32 / self.height as f32) * camera.view();
        self.begin_frame_with(view_proj, lights, background)
    }

    /// Starts a frame with an explicit view-projection matrix.
    pub fn begin_frame_with<'r, 'm>(&'r mut self, view_proj: Mat4, lights: &Lights, background: C) -> Frame<'r, 'm, C, V, S> {
        let buffers = Buffers {
            color: &mut self.color,
            depth: &mut self.depth,
            vertices: &mut self.vertices,
            triangles: &mut self.triangles,
            heads: &mut self.heads,
            clean: &mut self.clean,
            width: self.width,
            height: self.height,
            strip: self.strip,
        };
        Frame::new(buffers, view_proj, lights, background)
    }
}

/// The memory a frame works in, borrowed from a renderer.
struct Buffers<'a, C, Z, const V: usize> {
    color: &'a mut [C],
    depth: &'a mut [Z],
    vertices: &'a mut [ScreenVertex<V>],
    triangles: &'a mut [TriRecord],
    heads: &'a mut [u16],
    /// The color every pixel of the strip buffer holds outside the columns
    /// a strip dirtied (which are cleared again after it is sent).
    clean: &'a mut C,
    width: usize,
    height: usize,
    strip: usize,
}

/// A frame being recorded. Draw calls queue geometry; [`Frame::finish`]
/// rasterizes and outputs it. Materials are borrowed until then (`'m`).
pub struct Frame<'r, 'm, C, const V: usize, S: Settings> {
    b: Buffers<'r, C, DepthValue<S>, V>,
    n_vertices: usize,
    n_triangles: usize,
    draws: Vec<(&'m dyn MaterialProgram<C, S, V>, u16, Lighting), MAX_DRAW_CALLS>,
    view_proj: Mat4,
    lights: Lighting,
    background: C,
    stats: FrameStats,
    /// `log2` of the strip height if it is a power of two (the usual).
    /// Read only on ARMv6-M, which has no divide instruction.
    strip_shift: Option<u32>,
}

/// Whether draw calls cull back faces in model space where meshes have
/// face planes (the `face-planes` feature).
const CULL_IN_MODEL_SPACE: bool = cfg!(feature = "face-planes");

/// A triangle in flight through assembly: its vertices' buffer indices.
type Corners = [u16; 3];

impl<'r, 'm, C, const V: usize, S> Frame<'r, 'm, C, V, S>
where
    C: Color,
    S: Settings,
{
    fn new(b: Buffers<'r, C, DepthValue<S>, V>, view_proj: Mat4, lights: &Lights, background: C) -> Self {
        Self {
            n_vertices: 0,
            n_triangles: 0,
            draws: Vec::new(),
            view_proj,
            lights: Lighting::new(lights, view_proj.eye().unwrap_or(Vec3::ZERO)),
            background,
            stats: FrameStats::default(),
            strip_shift: b.strip.is_power_of_two().then(|| b.strip.trailing_zeros()),
            b,
        }
    }

    /// Appends a vertex, or reports the buffer full.
    fn push_vertex(&mut self, v: ScreenVertex<V>) -> Result<u16, DrawError> {
        let i = self.n_vertices;
        let capacity = self.b.vertices.len();
        let slot = self.b.vertices.get_mut(i).ok_or(DrawError::VertexCapacity { needed: i + 1, capacity })?;
        *slot = v;
        self.n_vertices += 1;
        Ok(i as u16)
    }

    /// Statistics so far.
    pub fn stats(&self) -> FrameStats {
        // `queued` is the record count: kept there, not counted per triangle.
        FrameStats { queued: self.n_triangles as u32, ..self.stats }
    }

    /// Draws `mesh` placed by `model` with `material`.
    ///
    /// Errors leave the frame as it was; geometry that cannot be drawn
    /// (non-finite, off screen, back-facing) is skipped and counted in
    /// [`FrameStats`].
    ///
    /// With the `face-planes` feature, [face planes](Mesh::with_face_planes)
    /// and back-face culling, back faces are culled in model space
    /// before the vertex stage, which then skips the vertices only they
    /// use. The frame is the same, but for back faces that snapping turned
    /// front-facing (tiny ones, or with under 2 sub-pixel bits), which are
    /// then not drawn.
    #[inline]
    pub fn draw<E, P, D>(&mut self, mesh: &Mesh<'_>, model: &Mat4, material: &'m Material<E, P, D>) -> Result<(), DrawError>
    where
        E: Effect,
        P: Perspective,
        D: DepthMode,
    {
        // Two copies of the draw call, with and without culling in model
        // space: in one, the marking cost meshes without face planes 2% of
        // a frame (`f32` M4F; the vertex loop spilled registers). The copy
        // costs flash, so it is a feature.
        if CULL_IN_MODEL_SPACE && material.cull == Cull::Back && mesh.face_planes().is_some() {
            self.draw_mesh::<E, P, D, true>(mesh, model, material)
        } else {
            self.draw_mesh::<E, P, D, false>(mesh, model, material)
        }
    }

    /// [`Frame::draw`], culling back faces in model space first if
    /// `CULL_FIRST`.
    // Out of line: merged into a large caller (a firmware drawing every
    // effect), its per-triangle loop lost registers and took 1.6% more of
    // a flat frame than in a flat-only firmware (scripts/effects-bench.sh).
    #[inline(never)]
    fn draw_mesh<E, P, D, const CULL_FIRST: bool>(
        &mut self,
        mesh: &Mesh<'_>,
        model: &Mat4,
        material: &'m Material<E, P, D>,
    ) -> Result<(), DrawError>
    where
        E: Effect,
        P: Perspective,
        D: DepthMode,
    {
        const { assert!(E::VARYINGS <= V, "the renderer stores fewer varyings (V) than this effect needs") };
        if !model.is_finite() || !self.view_proj.is_finite() {
            self.stats.meshes_invalid += 1;
            return Ok(());
        }
        let b = mesh.bounds();
        let center = model.transform_point3(b.center);
        if clip::sphere_in_frustum(&self.view_proj, center, b.radius * model.max_scale()) == SphereTest::Outside {
            self.stats.meshes_culled += 1;
            return Ok(());
        }
        let base = self.n_vertices;
        let capacity = self.b.vertices.len();
        if mesh.vertex_count() > capacity - base {
            return Err(DrawError::VertexCapacity { needed: base + mesh.vertex_count(), capacity });
        }
        let lights = self.lights;
        let scale = if E::LIT_VERTICES { model.similarity_scale() } else { None };
        let vertex_lights = scale.map_or(lights, |s| lights.in_model_space(model, s));
        self.begin_draw(material, vertex_lights)?;
        let stage = VertexStage {
            model: *model,
            mvp: self.view_proj * *model,
            normal_matrix: model.normal_matrix(),
            lights: &vertex_lights,
            model_space: scale.is_some(),
            effect: &material.effect,
            color: material.color,
            width: self.b.width as f32,
            height: self.b.height as f32,
            subpixel_bits: S::SUBPIXEL_BITS,
        };
        if <S::Interp as crate::math::Interp>::INTEGER_VERTICES {
            let (w, h) = (stage.width, stage.height);
            let projection = IntegerProjection::new(&stage.mvp, mesh.positions(), mesh.bounds(), w, h, S::SUBPIXEL_BITS);
            let lit_in_model_space = E::LIT_COLOR && stage.model_space;
            let lighting = lit_in_model_space
                .then(|| IntegerLighting::new(stage.lights, mesh.normals(), mesh.unit_normals(), E::lit_scale::<C>()))
                .flatten();
            return self.queue_mesh::<E, P, D, _, CULL_FIRST>(
                mesh,
                material,
                &stage,
                &IntegerVertices { projection, lighting, perspective: P::CORRECT },
                base,
            );
        }
        self.queue_mesh::<E, P, D, _, CULL_FIRST>(mesh, material, &stage, &FloatVertices, base)
    }

    /// Runs the vertex stage over `mesh` into the vertex buffer from
    /// `base` on, then assembles and queues its triangles.
    #[inline(always)]
    fn queue_mesh<E, P, D, J, const CULL_FIRST: bool>(
        &mut self,
        mesh: &Mesh<'_>,
        material: &'m Material<E, P, D>,
        stage: &VertexStage<'_, E>,
        vertices: &J,
        base: usize,
    ) -> Result<(), DrawError>
    where
        E: Effect,
        P: Perspective,
        D: DepthMode,
        J: VertexArithmetic,
    {
        let (model, lights) = (&stage.model, self.lights);
        // With `CULL_FIRST`, back faces are culled in model space first,
        // and vertices only they use are not transformed (see
        // `mark_unused_vertices`).
        let test = if CULL_FIRST { BackFaceTest::new(&stage.mvp, mesh.bounds()) } else { None };
        let mut front = [0u32; FRONT_WORDS];
        let mut culled = 0;
        if let Some(test) = test {
            culled = mark_unused_vertices(test, mesh, &mut self.b.vertices[base..base + mesh.vertex_count()], &mut front);
        }
        vertices.vertices::<E, C, V>(stage, mesh, &mut self.b.vertices[base..base + mesh.vertex_count()], test.is_some());
        self.n_vertices += mesh.vertex_count();
        let snapshot = self.stats;
        let (p, idx) = (|i: usize| mesh.position(i), mesh.indices());
        // Counted once here, not per triangle in `assemble` (a store per
        // triangle in the hot loop).
        self.stats.triangles += (idx.len() / 3) as u32;
        self.stats.back_facing += culled;
        let lights = &lights;
        let mut assemble_face = |t: &[u16]| {
            let corners = [(base + t[0] as usize) as u16, (base + t[1] as usize) as u16, (base + t[2] as usize) as u16];
            // Lit only if the triangle is queued (not for the back faces).
            let face = move || {
                if !E::USES_FACE {
                    return None;
                }
                // Geometric normal in model space, to world by the normal matrix.
                let (a, b, c) = (p(t[0] as usize), p(t[1] as usize), p(t[2] as usize));
                let normal = stage.normal_matrix.transform((b - a).cross(c - a)).normalize_or_zero();
                let position = model.transform_point3((a + b + c) * (1.0 / 3.0));
                let color = mesh.colors().map_or(material.color, |cs| cs[t[0] as usize]);
                Some(material.effect.face(&FaceInput { position, normal, color }, lights))
            };
            // The indices from `t`: arrays of them captured by reference were
            // written to the stack for every triangle, for this rare path
            // (`torus.babylon`, M4F `f32`: 4 k instructions a frame).
            self.assemble(corners, face, material.cull, P::CORRECT, |vi| {
                let i = t[vi] as usize;
                ClipVertex {
                    pos: vertices.clip_position(stage, mesh, i),
                    attrs: vertices.varyings::<E, C, V>(stage, mesh, i),
                    src: (base + i) as u16,
                }
            })
        };
        // A mesh with face planes goes by the bits of its front faces; one
        // without, face by face (through the bits, every face took a few
        // instructions more: the built-in `torus` in `f32` on the M4F +2.1%).
        let res = if CULL_FIRST {
            let faces = FrontFaces { words: test.is_some().then_some(&front), word: 0, base: 0, faces: idx.len() / 3 };
            faces.map_while(|k| idx.get(3 * k..3 * k + 3)).try_for_each(&mut assemble_face)
        } else {
            idx.chunks_exact(3).try_for_each(&mut assemble_face)
        };
        if let Err(e) = res {
            self.rollback(base, snapshot);
            return Err(e);
        }
        self.stats.vertices += mesh.vertex_count() as u32;
        Ok(())
    }

    /// Draws triangles given in window coordinates (pixels, y down; the
    /// `.tri` format), entering the pipeline at triangle assembly: the same
    /// culling, guard-band clipping, setup and span loops as meshes. The
    /// colors go through the material's effect unlit; flat effects use the
    /// first vertex's color.
    pub fn draw_window_triangles<E, P, D, I>(&mut self, triangles: I, material: &'m Material<E, P, D>) -> Result<(), DrawError>
    where
        E: Effect,
        P: Perspective,
        D: DepthMode,
        I: IntoIterator<Item = [TriVertex; 3]>,
    {
        const { assert!(E::VARYINGS <= V, "the renderer stores fewer varyings (V) than this effect needs") };
        let base = self.n_vertices;
        self.begin_draw(material, Lighting::UNLIT)?;
        // After `begin_draw`, as in `draw`: `rollback` undoes its count.
        let snapshot = self.stats;
        let lights = Lighting::UNLIT;
        for tri in triangles {
            let attrs = |v: &TriVertex| -> [f32; V] {
                let input = VertexInput::new::<C, E>(Vec3::ZERO, Vec3::ZERO, v.color, Vec2::new(0.0, 0.0), &lights);
                vertex_varyings::<C, E, V>(&material.effect, &input, &lights)
            };
            let face = E::USES_FACE
                .then(|| material.effect.face(&FaceInput { position: Vec3::ZERO, normal: Vec3::ZERO, color: tri[0].color }, &lights));
            let mut poly: Polygon<WindowVertex<V>> = Polygon::new();
            let mut valid = true;
            for v in &tri {
                // Beyond ±1e300 pixels an edge's length can overflow f64 and
                // no clip could place it: such coordinates are invalid.
                let placeable = |c: f64| c.abs() <= WINDOW_LIMIT;
                valid &= placeable(v.x) && placeable(v.y) && v.z.is_finite() && v.w.is_finite() && v.w > 0.0;
                let _ = poly.push(WindowVertex { x: v.x, y: v.y, z: v.z, q: 1.0 / v.w, attrs: attrs(v), src: NO_SOURCE });
            }
            self.stats.triangles += 1;
            if !valid {
                self.stats.invalid += 1;
                continue;
            }
            if let Err(e) = self.emit_polygon(poly, face, material.cull, P::CORRECT) {
                self.rollback(base, snapshot);
                return Err(e);
            }
        }
        Ok(())
    }

    fn begin_draw(&mut self, program: &'m dyn MaterialProgram<C, S, V>, lights: Lighting) -> Result<(), DrawError> {
        let first = self.n_triangles as u16;
        self.draws.push((program, first, lights)).map_err(|_| DrawError::DrawCallCapacity)?;
        self.stats.draw_calls += 1;
        Ok(())
    }

    fn rollback(&mut self, vertices: usize, stats: FrameStats) {
        self.n_vertices = vertices;
        if let Some((_, first, _)) = self.draws.pop() {
            self.n_triangles = first as usize;
        }
        self.stats = stats;
        self.stats.draw_calls -= 1;
    }

    /// Assembles one mesh triangle whose corners are already in the vertex
    /// buffer: the common case goes straight to culling and queuing; a
    /// triangle with a vertex behind the near plane, beyond the far plane
    /// or outside the guard band is clipped (`clip_vertex` recomputes a
    /// corner in clip space).
    fn assemble(
        &mut self,
        corners: Corners,
        face: impl Fn() -> Option<Rgb888>,
        cull: Cull,
        perspective: bool,
        clip_vertex: impl Fn(usize) -> ClipVertex<V>,
    ) -> Result<(), DrawError> {
        let vs = &self.b.vertices;
        let v = [&vs[corners[0] as usize], &vs[corners[1] as usize], &vs[corners[2] as usize]];
        // The common case by three compares; flags are read only if a
        // corner has none.
        if v.iter().all(|v| v.x != vertex::UNPROJECTED) {
            return self.emit(corners, face, cull);
        }
        let fl = v.map(vertex::flags);
        // A vertex only faces culled in model space use was not
        // transformed: its triangles are such faces.
        if CULL_IN_MODEL_SPACE && fl.iter().any(|f| f & vertex::CULLED != 0) {
            self.stats.back_facing += 1;
            return Ok(());
        }
        if fl.iter().any(|f| f & vertex::NOT_FINITE != 0) {
            self.stats.invalid += 1;
            return Ok(());
        }
        if fl[0] & fl[1] & fl[2] & (vertex::BEHIND_NEAR | vertex::BEYOND_FAR) != 0 {
            self.stats.off_screen += 1;
            return Ok(());
        }
        self.stats.clipped += 1;
        let mut poly: Polygon<ClipVertex<V>> = (0..3).map(&clip_vertex).collect();
        clip::clip_near_far(&mut poly);
        if poly.len() < 3 {
            self.stats.off_screen += 1;
            return Ok(());
        }
        // Inside `0 <= z <= w`, w is positive unless the projection puts
        // the near plane through the eye (a degenerate matrix): nothing
        // sensible to draw, and projecting it would flip it across the screen.
        if !poly.iter().all(|v| v.pos.w > 0.0) {
            self.stats.invalid += 1;
            return Ok(());
        }
        let window: Polygon<WindowVertex<V>> = poly.iter().map(|v| clip::to_window(v, self.b.width as f32, self.b.height as f32)).collect();
        self.emit_polygon(window, face(), cull, perspective)
    }

    /// Snaps a convex window-space polygon (clipping it to the guard band
    /// if needed), stores its new vertices and queues it as a fan.
    fn emit_polygon(
        &mut self,
        mut poly: Polygon<WindowVertex<V>>,
        face: Option<Rgb888>,
        cull: Cull,
        perspective: bool,
    ) -> Result<(), DrawError> {
        // A vertex whose projection overflowed (w tiny next to x or y, from
        // a degenerate projection) has no place to clip from: the triangle
        // is skipped and counted invalid, as for window coordinates beyond
        // `WINDOW_LIMIT`.
        if !poly.iter().all(|v| v.x.abs() <= WINDOW_LIMIT && v.y.abs() <= WINDOW_LIMIT) {
            self.stats.invalid += 1;
            return Ok(());
        }
        let bits = S::SUBPIXEL_BITS;
        let fits = |v: &WindowVertex<V>| snap_f64(v.x, bits).is_some() && snap_f64(v.y, bits).is_some();
        if !poly.iter().all(fits) {
            // Stay a pixel inside the guard so snapping cannot push past it.
            let limit = ((raster::guard(bits) >> (bits + 1)) - 1) as f64;
            clip::clip_guard(&mut poly, limit, perspective);
        }
        let mut idx: Vec<u16, { clip::MAX_CLIPPED }> = Vec::new();
        for v in &poly {
            // A corner kept from the vertex buffer shares its stored
            // position, unless it has none (it was flagged): then it is
            // snapped here like a new vertex.
            let stored = self.b.vertices.get(v.src as usize).is_some_and(|s| vertex::flags(s) == 0);
            if v.src != NO_SOURCE && stored {
                let _ = idx.push(v.src);
                continue;
            }
            let (Some(x), Some(y)) = (snap_f64(v.x, bits), snap_f64(v.y, bits)) else {
                self.stats.invalid += 1;
                return Ok(());
            };
            let i = self.push_vertex(ScreenVertex { x, y, z: raster::window_depth(v.z), q: v.q, attrs: v.attrs })?;
            let _ = idx.push(i);
        }
        // Snapping can push a clipped polygon's nearly collinear vertices
        // past each other: a fan piece then turns over and would cover its
        // neighbours' pixels a second time. Pieces wound against the whole
        // polygon are such slivers and are dropped (counted degenerate).
        let cross = |a: (i64, i64), b: (i64, i64), c: (i64, i64)| (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
        let mut p = [(0i64, 0i64); clip::MAX_CLIPPED];
        for (slot, &i) in p.iter_mut().zip(&idx) {
            *slot = self.b.vertices.get(i as usize).map_or((0, 0), |v| (v.x as i64, v.y as i64));
        }
        let n = idx.len();
        let total: i64 = (1..n.saturating_sub(1)).map(|k| cross(p[0], p[k], p[k + 1])).sum();
        for k in 1..n.saturating_sub(1) {
            let piece = cross(p[0], p[k], p[k + 1]);
            if n > 3 && (piece > 0) != (total > 0) {
                self.stats.degenerate += 1;
                continue;
            }
            self.emit([idx[0], idx[k], idx[k + 1]], || face, cull)?;
        }
        Ok(())
    }

    /// Culls a snapped triangle (degenerate, back-facing, off screen) or
    /// queues it with its color `face()`, called only then (a flat effect
    /// lights a face per call; `None` for effects without face colors).
    /// Inlined into the draw loop, the hot path of geometry.
    #[inline(always)]
    fn emit(&mut self, corners: Corners, face: impl Fn() -> Option<Rgb888>, cull: Cull) -> Result<(), DrawError> {
        let vs = &self.b.vertices;
        let [a, b, c] = [&vs[corners[0] as usize], &vs[corners[1] as usize], &vs[corners[2] as usize]];
        let area = signed_area2(a, b, c);
        if area == 0 {
            self.stats.degenerate += 1;
            return Ok(());
        }
        if cull == Cull::Back && area < 0 {
            self.stats.back_facing += 1;
            return Ok(());
        }
        let bits = S::SUBPIXEL_BITS;
        // Sorted by y once here for the rasterizer (see
        // `raster::rasterize`).
        let sorted = raster::sort_by_y([(corners[0], a.y), (corners[1], b.y), (corners[2], c.y)], |(_, y)| y);
        let (corners, top, bottom) = (sorted.map(|(i, _)| i), sorted[0].1, sorted[2].1);
        let first = first_row_at_or_below(top, bits);
        let end = first_row_at_or_below(bottom, bits);
        // Columns work like rows: pixel x is covered only if x_min <= center < x_max.
        let left = first_row_at_or_below(a.x.min(b.x).min(c.x), bits);
        let right = first_row_at_or_below(a.x.max(b.x).max(c.x), bits);
        // A triangle between pixel centers (no row or no column center in
        // its bounds) covers nothing: dropped here, it costs no queueing,
        // binning or setup.
        let (width, height) = (self.b.width as i32, self.b.height as i32);
        if first >= end || left >= right || end <= 0 || right <= 0 || first >= height || left >= width {
            self.stats.off_screen += 1;
            return Ok(());
        }
        // `0 <= first < height`: a row of the frame. Without a divide
        // instruction (ARMv6-M) a division is a library call, and strips
        // of a power of two rows (the usual) take a shift.
        let first = first.max(0) as usize;
        let s = match self.strip_shift {
            Some(shift) if cfg!(soft3d_armv6m) => first >> shift,
            _ => first / self.b.strip,
        };
        let capacity = self.b.triangles.len();
        let rec = self.b.triangles.get_mut(self.n_triangles).ok_or(DrawError::TriangleCapacity { capacity })?;
        rec.v = corners;
        rec.next = s as u16;
        // Written only for effects that read it.
        if let Some(face) = face() {
            rec.face = [face.r(), face.g(), face.b()];
        }
        self.n_triangles += 1;
        Ok(())
    }

    /// Rasterizes the frame strip by strip into `target`.
    pub fn finish<T: DrawTarget<Color = C>>(self, target: &mut T) -> Result<FrameStats, T::Error> {
        let stats = self.stats();
        let Frame { b, n_triangles, draws, background, .. } = self;
        let (width, height, strip_rows) = (b.width, b.height, b.strip);
        let tris = &mut b.triangles[..n_triangles];
        let bits = S::SUBPIXEL_BITS;
        let strips = height.div_ceil(strip_rows);
        // Bin by first strip; pushing in reverse keeps each list in
        // submission order.
        b.heads[..strips].fill(NONE);
        for i in (0..tris.len()).rev() {
            let s = tris[i].next as usize;
            tris[i].next = b.heads[s];
            b.heads[s] = i as u16;
        }
        // The strip buffers stay clean between strips: only the columns a
        // strip dirtied are cleared after it is sent.
        if *b.clean != background {
            b.color.fill(background);
            *b.clean = background;
        }
        // Triangles that continue into the next strip, in submission order.
        let mut carried = NONE;
        for s in 0..strips {
            let y0 = s * strip_rows;
            let rows = strip_rows.min(height - y0);
            let mut strip = StripTarget {
                color: &mut b.color[..rows * width],
                depth: &mut b.depth[..rows * width],
                width,
                y0: y0 as i32,
                rows: rows as i32,
                dirty: (width, 0),
            };
            let mut queue = StripQueue {
                tris: &mut *tris,
                vertices: &*b.vertices,
                fresh: b.heads[s] as u32,
                old: carried as u32,
                next_head: NONE,
                next_tail: NONE,
                // (At most `MAX_SIZE` rows: within `row_center`'s range.)
                carry_below: raster::row_center((y0 + rows) as i32, bits),
            };
            // The draw call of the next triangle, and where the next one
            // starts.
            let mut draw = 0;
            let mut next_draw = draws.get(1).map_or(NONE, |d| d.1);
            loop {
                let i = queue.peek();
                if i == NONE {
                    break;
                }
                while i >= next_draw {
                    draw += 1;
                    next_draw = draws.get(draw + 1).map_or(NONE, |d| d.1);
                }
                let Some((program, _, lights)) = draws.get(draw) else {
                    break;
                };
                program.rasterize_run(&mut strip, &mut queue, next_draw, lights);
                if queue.peek() == i {
                    // Only if a list held an index past the records (it
                    // cannot): stop rather than loop.
                    break;
                }
            }
            carried = queue.next_head;
            let area = Rectangle::new(Point::new(0, y0 as i32), Size::new(width as u32, rows as u32));
            let sent = target.fill_contiguous(&area, strip.color.iter().copied());
            clean_columns::<C, S::Depth>(strip, background);
            sent?;
        }
        Ok(stats)
    }
}

/// Words of the bit set of a mesh's front faces that the face loop skips
/// culled faces by: its first 2,048 faces (256 bytes of stack). Faces
/// past them are culled at assembly, by their vertices' flags.
const FRONT_WORDS: usize = 64;

/// Marks the vertex slots of a mesh that only faces `test` culls use
/// (flagged [`vertex::CULLED`]), so that the vertex stage skips them and
/// the rest of their triangles are culled at assembly (a vertex no face
/// uses is skipped too), and sets the bits of `front` for the faces
/// `test` keeps among the first `32 * FRONT_WORDS`. Returns how many of
/// those it culls. Out of line: one copy per `V`, not one per material.
///
/// The faces go in windows of `32 * FRONT_WORDS`, the first last, so that
/// `front` ends with the first window's bits. A word's bits are gathered
/// in a register; the loop then runs short of registers: on `monkey`
/// (`f32`, M4F) this function takes 37 k instructions a frame, 27.5 k
/// without the bits, while the face loop saves 12 k (on `torus.babylon`,
/// half of whose faces are culled here, far more).
#[inline(never)]
fn mark_unused_vertices<const V: usize>(
    test: BackFaceTest,
    mesh: &Mesh<'_>,
    slots: &mut [ScreenVertex<V>],
    front: &mut [u32; FRONT_WORDS],
) -> u32 {
    for slot in slots.iter_mut() {
        slot.x = vertex::UNPROJECTED;
        slot.y = vertex::CULLED;
    }
    let (indices, planes) = (mesh.indices(), mesh.face_planes().unwrap_or(&[]));
    let faces = (indices.len() / 3).min(planes.len());
    const WINDOW: usize = 32 * FRONT_WORDS;
    for first in (0..faces.div_ceil(WINDOW)).rev().map(|w| w * WINDOW) {
        let window = &planes[first..faces.min(first + WINDOW)];
        let triangles = indices.get(3 * first..3 * (first + window.len())).unwrap_or(&[]);
        for (word, (triangles, planes)) in front.iter_mut().zip(triangles.chunks(96).zip(window.chunks(32))) {
            // Each face's bit enters at the top, so the word's first face
            // ends at bit 0 (a short last word is shifted down after).
            let mut bits = 0u32;
            for (t, plane) in triangles.chunks_exact(3).zip(planes) {
                let kept = !test.culls(plane);
                if kept {
                    for &v in t {
                        if let Some(slot) = slots.get_mut(v as usize) {
                            slot.x = 0;
                        }
                    }
                }
                bits = (bits >> 1) | ((kept as u32) << 31);
            }
            *word = bits >> (32 - planes.len());
        }
    }
    // The listed faces not kept.
    let listed = faces.min(WINDOW);
    (listed - front.iter().take(listed.div_ceil(32)).map(|w| w.count_ones() as usize).sum::<usize>()) as u32
}

/// The faces a draw call with face planes assembles, in order: with
/// `words`, those of the first `32 * FRONT_WORDS` whose bit is set (culled
/// faces cost nothing here), then every later one; without, every face.
struct FrontFaces<'a> {
    words: Option<&'a [u32; FRONT_WORDS]>,
    /// The faces of the current word still to yield, as bits.
    word: u32,
    /// The first face of the current word.
    base: usize,
    faces: usize,
}

impl Iterator for FrontFaces<'_> {
    type Item = usize;

    #[inline(always)]
    fn next(&mut self) -> Option<usize> {
        while self.word == 0 {
            if self.base >= self.faces {
                return None;
            }
            let word = self.words.and_then(|w| w.get(self.base / 32)).map_or(u32::MAX, |&w| w);
            // The faces past the last.
            let left = self.faces - self.base;
            self.word = if left < 32 { word & ((1 << left) - 1) } else { word };
            self.base += 32;
        }
        let k = self.base - 32 + self.word.trailing_zeros() as usize;
        self.word &= self.word - 1;
        Some(k)
    }
}

/// Restores the background color and cleared depth in the columns a strip
/// dirtied: the whole strip as one run where it dirtied every column, else
/// a run a row. (One call site per fill: each is unrolled code.)
fn clean_columns<C: Copy, Z: DepthFormat>(strip: StripTarget<'_, C, Z::Value>, background: C) {
    let (x0, x1) = strip.dirty;
    if x0 >= x1 {
        return;
    }
    // `x0 < x1 <= width`: the runs are not empty.
    let (stride, x0, x1) = if x1 - x0 == strip.width { (strip.color.len(), 0, strip.color.len()) } else { (strip.width, x0, x1) };
    for (c, z) in strip.color.chunks_exact_mut(stride).zip(strip.depth.chunks_exact_mut(stride)) {
        fill_colors(&mut c[x0..x1], background);
        fill_depths(&mut z[x0..x1], Z::CLEAR);
    }
}

/// Runs shorter than this are filled one value at a time: the setup of
/// the block stores costs more than they save there (at 64, strips of
/// `torus.babylon` in `f32` on the M4F took 0.4% more than at 32).
const LONG_RUN: usize = 32;

/// Fills a run of colors. A color type need not be plain bytes, so the
/// stores stay one pixel each, but a long run is written in blocks of
/// 16, one loop step a block, not unrolled further (flash): `fill` took
/// 1.75 instructions a pixel on the M4F.
#[inline(always)]
fn fill_colors<C: Copy>(run: &mut [C], value: C) {
    if run.len() < LONG_RUN {
        run.fill(value);
        return;
    }
    let mut blocks = run.chunks_exact_mut(16);
    for block in &mut blocks {
        block.copy_from_slice(&[value; 16]);
        raster::no_unroll();
    }
    blocks.into_remainder().fill(value);
}

/// Fills a run of depths, a long run in word-aligned blocks of 32 bytes,
/// which the M4F copies by load- and store-multiple (`memclr`, which
/// `fill` called, took 1.5 instructions a 16-bit depth there).
#[inline(always)]
fn fill_depths<T: bytemuck::Pod>(run: &mut [T], value: T) {
    let size = core::mem::size_of::<T>();
    if run.len() < LONG_RUN || 32 % size != 0 {
        run.fill(value);
        return;
    }
    let mut block = [0u32; 8];
    for bytes in bytemuck::bytes_of_mut(&mut block).chunks_exact_mut(size) {
        bytes.copy_from_slice(bytemuck::bytes_of(&value));
    }
    // Opaque: a zero block would be turned back into a call to `memclr`.
    let block = core::hint::black_box(block);
    let (head, blocks, tail) = bytemuck::pod_align_to_mut::<T, [u32; 8]>(run);
    head.fill(value);
    for b in blocks {
        *b = block;
        raster::no_unroll();
    }
    tail.fill(value);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every run of a buffer, at every start and length around the block
    /// sizes, is filled exactly: nothing outside it changes.
    fn fills_exactly<T: Copy + PartialEq + core::fmt::Debug>(old: T, new: T, fill: impl Fn(&mut [T], T)) {
        let mut buf = [old; 200];
        for start in 0..8 {
            for len in (0..LONG_RUN + 40).chain([150, 191]) {
                buf.fill(old);
                fill(&mut buf[start..start + len], new);
                for (i, v) in buf.iter().enumerate() {
                    let inside = (start..start + len).contains(&i);
                    assert_eq!(*v, if inside { new } else { old }, "start {start}, length {len}, index {i}");
                }
            }
        }
    }

    #[test]
    fn runs_of_depths_and_colors_are_filled_exactly() {
        fills_exactly(0xabcdu16, 0, fill_depths);
        fills_exactly(0u16, 0x1234, fill_depths);
        fills_exactly(7u32, 0, fill_depths);
        fills_exactly(-1.5f32, 0.25, fill_depths);
        fills_exactly(0u8, 9, fill_depths);
        fills_exactly(Rgb888::new(1, 2, 3), Rgb888::new(200, 100, 50), fill_colors);
        fills_exactly(embedded_graphics::pixelcolor::Rgb565::new(1, 2, 3), embedded_graphics::pixelcolor::Rgb565::BLACK, fill_colors);
    }
}
