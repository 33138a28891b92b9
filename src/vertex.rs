//! The vertex stage: model, view and projection to clip space, normals
//! through the normal matrix, per-vertex effect work (lighting), and the
//! projection of visible vertices to snapped window coordinates. A draw
//! call goes through it in `f32` ([`FloatVertices`]) or, for fixed-point
//! settings, in integers ([`IntegerVertices`]: positions by
//! [`IntegerProjection`], the lit color by [`IntegerLighting`] where it
//! covers the lights).

use crate::clip::ClipVertex;
use crate::effect::{lit, lit_input, scaled_lit, vertex_varyings, Color, Effect, VertexInput};
use crate::math::{Mat3, Mat4, Vec2, Vec3, Vec4};
use crate::mesh::Mesh;
use crate::raster::{snap, ScreenVertex};
use crate::scene::Lighting;
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

mod integer;
mod integer_lighting;

pub use integer::IntegerProjection;
pub use integer_lighting::IntegerLighting;

/// Vertex outside the near plane (in front of it is inside).
pub const BEHIND_NEAR: i32 = 1;
/// Vertex beyond the far plane.
pub const BEYOND_FAR: i32 = 2;
/// Vertex outside the guard band of the fixed-point setup.
pub const OUTSIDE_GUARD: i32 = 4;
/// Vertex with a non-finite position or varying.
pub const NOT_FINITE: i32 = 8;
/// Vertex that only faces culled in model space use: not transformed.
pub const CULLED: i32 = 16;
/// `x` of a vertex that has no window position; its `y` holds the flags
/// above. (Keeps the flags without growing every stored vertex.)
pub const UNPROJECTED: i32 = i32::MIN;

/// The flags of a stored vertex (0 if it has a window position).
#[inline]
pub fn flags<const V: usize>(v: &ScreenVertex<V>) -> i32 {
    if v.x == UNPROJECTED {
        v.y
    } else {
        0
    }
}

/// Everything the vertex stage needs for one draw call.
pub struct VertexStage<'a, E> {
    /// Model matrix.
    pub model: Mat4,
    /// Model-view-projection matrix.
    pub mvp: Mat4,
    /// Normal matrix of the model.
    pub normal_matrix: Mat3,
    /// Lights of the frame, in model space if `model_space` is set, else
    /// in world space.
    pub lights: &'a Lighting,
    /// Whether the model matrix is a similarity and `lights` were moved
    /// into model space ([`Lighting::in_model_space`]): vertices are then
    /// lit from their model-space position and normal, with no transform
    /// and no normalization per vertex.
    pub model_space: bool,
    /// Effect of the material.
    pub effect: &'a E,
    /// Material color, for meshes without vertex colors.
    pub color: Rgb888,
    /// Viewport size in pixels.
    pub width: f32,
    /// Viewport height in pixels.
    pub height: f32,
    /// Sub-pixel bits.
    pub subpixel_bits: u32,
}

impl<E: Effect> VertexStage<'_, E> {
    /// Clip-space position of a model-space point. The single definition
    /// used both here and when a triangle is clipped, so a clipped triangle
    /// keeps exactly the vertices its unclipped neighbors use.
    #[inline]
    pub fn clip_position(&self, p: Vec3) -> Vec4 {
        self.mvp.transform_point(p)
    }

    /// Varyings of mesh vertex `i`, lit in `f32`.
    #[inline(always)]
    pub fn varyings<C: Color, const V: usize>(&self, mesh: &Mesh<'_>, i: usize) -> [f32; V] {
        self.varyings_at::<C, V>(mesh, i, mesh.position(i), self.lights)
    }

    /// Varyings of mesh vertex `i` at model-space position `p` (read once
    /// by the caller), with its lit color from `lights` if the effect
    /// reads it.
    #[inline(always)]
    fn varyings_at<C: Color, const V: usize>(&self, mesh: &Mesh<'_>, i: usize, p: Vec3, lights: &impl LitColor) -> [f32; V] {
        let v = MeshVertex::read(mesh, i, p, self.color);
        self.varyings_of::<C, V>(&v, (self.model_space, mesh.unit_normals()), lights, i)
    }

    /// Varyings of mesh vertex `i` as read into `v`. `(model_space,
    /// unit_normals)`: whether it is lit in model space, and whether its
    /// normal is a unit vector there (see [`VertexStage::model_space`]).
    #[inline(always)]
    fn varyings_of<C: Color, const V: usize>(
        &self,
        v: &MeshVertex,
        (model_space, unit_normals): (bool, bool),
        lights: &impl LitColor,
        i: usize,
    ) -> [f32; V] {
        if E::VARYINGS == 0 {
            return [0.0; V];
        }
        let (position, normal) = if !E::LIT_VERTICES {
            (Vec3::ZERO, Vec3::ZERO)
        } else if model_space {
            // A mesh of unit normals (checked once, when it was built) is
            // used as it is; any other is normalized like the world path.
            (v.position, if unit_normals { v.normal } else { v.normal.normalize_or_zero() })
        } else {
            let n = self.normal_matrix.transform(v.normal).normalize_or_zero();
            (self.model.transform_point3(v.position), n)
        };
        let input = VertexInput {
            position,
            normal,
            color: v.color,
            uv: v.uv,
            lit: if E::LIT_COLOR {
                lights.lit::<C, E>(i, position, normal, if E::LIT_WHITE { Rgb888::WHITE } else { v.color })
            } else {
                [0.0; 3]
            },
        };
        vertex_varyings::<C, E, V>(self.effect, &input, self.lights)
    }

    /// Transforms mesh vertex `i` into the stored vertex `out`: projected
    /// and snapped if it is inside the near/far planes and the guard band,
    /// otherwise flagged. Inlined into the draw loop, where the viewport
    /// and sub-pixel bits are constants; written in place, not returned
    /// and copied (a copy of the whole vertex per vertex).
    #[inline(always)]
    pub fn vertex<C: Color, const V: usize>(&self, mesh: &Mesh<'_>, i: usize, out: &mut ScreenVertex<V>) {
        let v = MeshVertex::read(mesh, i, mesh.position(i), self.color);
        self.vertex_of::<C, V>(&v, (self.model_space, mesh.unit_normals()), self.lights, i, out)
    }

    /// [`VertexStage::vertex`] from the vertex as read into `v` (see
    /// [`VertexStage::varyings_of`]).
    #[inline(always)]
    fn vertex_of<C: Color, const V: usize>(
        &self,
        v: &MeshVertex,
        space: (bool, bool),
        lights: &impl LitColor,
        i: usize,
        out: &mut ScreenVertex<V>,
    ) {
        let clip = self.clip_position(v.position);
        let attrs = self.varyings_of::<C, V>(v, space, lights, i);
        project_into(&ClipVertex { pos: clip, attrs, src: 0 }, self.width, self.height, self.subpixel_bits, E::VARYINGS, out)
    }
}

/// One mesh vertex as the vertex stage reads it. Each field is read
/// without a side effect (no panic), so what an effect does not use is
/// not read at all once this is inlined.
#[derive(Clone, Copy)]
struct MeshVertex {
    position: Vec3,
    normal: Vec3,
    color: Rgb888,
    uv: Vec2,
}

impl MeshVertex {
    /// Vertex `i` of `mesh` at position `position`, in `color` if the
    /// mesh has no vertex colors.
    #[inline(always)]
    fn read(mesh: &Mesh<'_>, i: usize, position: Vec3, color: Rgb888) -> Self {
        Self {
            position,
            normal: mesh.normal(i),
            color: mesh.colors().and_then(|c| c.get(i).copied()).unwrap_or(color),
            uv: mesh.uvs().and_then(|u| u.get(i).copied()).unwrap_or(Vec2::new(0.0, 0.0)),
        }
    }
}

/// Where the vertex stage's lit colors ([`VertexInput::lit`]) come from:
/// the lights in `f32` or in integers ([`IntegerLighting`]). A trait, not
/// a closure, so that its inlining is decided here: as a closure, a
/// firmware with two lit effects (`Gouraud`, `MonoGouraud`) called the
/// integer lighting out of line (+0.5% of `torus.babylon` in fixed point
/// on the M4F).
trait LitColor {
    /// The lit color of mesh vertex `i` at `position` with unit `normal`
    /// in color `color`, for effect `E` and display color `C`.
    fn lit<C: Color, E: Effect>(&self, i: usize, position: Vec3, normal: Vec3, color: Rgb888) -> [f32; 3];
}

impl LitColor for Lighting {
    #[inline(always)]
    fn lit<C: Color, E: Effect>(&self, _: usize, position: Vec3, normal: Vec3, color: Rgb888) -> [f32; 3] {
        lit_input::<C, E>(self, position, normal, color)
    }
}

/// [`Lighting`] without a point light: the diffuse light is the ambient
/// term plus the sun's share ([`Lighting::add_sun`]), the same arithmetic
/// as [`Lighting::diffuse`] without its test for a point light at every
/// vertex.
struct SunLight<'a>(&'a Lighting);

impl<'a> SunLight<'a> {
    /// `lights` if they have no point light.
    fn new(lights: &'a Lighting) -> Option<Self> {
        lights.point.is_none().then_some(Self(lights))
    }
}

impl LitColor for SunLight<'_> {
    #[inline(always)]
    fn lit<C: Color, E: Effect>(&self, _: usize, _: Vec3, normal: Vec3, color: Rgb888) -> [f32; 3] {
        let light = self.0.add_sun(self.0.ambient, normal);
        scaled_lit::<C, E>(lit(light, color, !self.0.in_unit_range()))
    }
}

impl LitColor for IntegerLighting<'_> {
    /// (It lights the mesh's own normals, in model space.) Out of line on
    /// ARMv6-M, as the compiler had chosen for the closure: inlined there,
    /// `torus.babylon` took 0.4% more.
    #[cfg_attr(soft3d_armv6m, inline(never))]
    #[cfg_attr(not(soft3d_armv6m), inline(always))]
    fn lit<C: Color, E: Effect>(&self, i: usize, _: Vec3, _: Vec3, color: Rgb888) -> [f32; 3] {
        IntegerLighting::lit(self, i, color, E::LIT_CHANNELS)
    }
}

/// Whether every value is finite, without a branch per value. With an
/// FPU: `v * 0` is zero for a finite `v` and NaN otherwise, and NaN
/// survives the sum (one multiply-add per value). Without: tests on the
/// bits (a float operation would be a library call).
#[inline(always)]
fn all_finite<'a>(values: impl IntoIterator<Item = &'a f32>) -> bool {
    if crate::math::HARD_FLOAT {
        values.into_iter().fold(0.0, |sum, v| sum + v * 0.0) == 0.0
    } else {
        values.into_iter().fold(true, |ok, v| ok & v.is_finite())
    }
}

/// Projects and snaps a clip-space vertex, or flags why it cannot be.
#[inline(always)]
pub fn project<const V: usize>(v: &ClipVertex<V>, width: f32, height: f32, subpixel_bits: u32) -> ScreenVertex<V> {
    let mut out = ScreenVertex::ZERO;
    project_into(v, width, height, subpixel_bits, V, &mut out);
    out
}

/// [`project`] into `out`, where the vertex is stored: built in place,
/// not built and then copied (the vertex loop's common path).
#[inline(always)]
///
/// Only the first `varyings` attributes are stored (see [`store_projected`]).
pub(crate) fn project_into<const V: usize>(
    v: &ClipVertex<V>,
    width: f32,
    height: f32,
    subpixel_bits: u32,
    varyings: usize,
    out: &mut ScreenVertex<V>,
) {
    let c = v.pos;
    let mut flags = 0;
    // A non-finite varying (a NaN texture coordinate) would be drawn as
    // garbage: the vertex is invalid like a non-finite position.
    // (One test for both: a compare less a vertex than two.)
    if !all_finite([c.x, c.y, c.z, c.w].iter().chain(&v.attrs)) {
        flags |= NOT_FINITE;
    } else {
        if c.z < 0.0 {
            flags |= BEHIND_NEAR;
        }
        if c.z > c.w {
            flags |= BEYOND_FAR;
        }
    }
    if flags == 0 {
        // The same arithmetic as `clip::to_window`, kept in f32 (its f64
        // result would only be rounded back).
        let q = 1.0 / c.w;
        let (x, y) = ((c.x * q + 1.0) * 0.5 * width, (1.0 - c.y * q) * 0.5 * height);
        if let (Some(x), Some(y)) = (snap(x, subpixel_bits), snap(y, subpixel_bits)) {
            store_projected(out, (x, y, crate::raster::window_depth(c.z * q), q), &v.attrs, varyings);
            return;
        }
        flags |= OUTSIDE_GUARD;
    }
    store_unprojected(out, flags)
}

/// Stores a projected vertex `(x, y, z, q)` with the first `varyings` of
/// `attrs` into `out`. The others are left as they were: the draw call's
/// material never reads them (its rasterizer takes `E::VARYINGS`), and a
/// renderer sized for more varyings than a material uses then does not
/// store them at every vertex (a flat draw call in a renderer of six
/// varyings wrote six zeros a vertex).
#[inline(always)]
pub(crate) fn store_projected<const V: usize>(
    out: &mut ScreenVertex<V>,
    (x, y, z, q): (i32, i32, u32, f32),
    attrs: &[f32; V],
    varyings: usize,
) {
    (out.x, out.y, out.z, out.q) = (x, y, z, q);
    let n = varyings.min(V);
    out.attrs[..n].copy_from_slice(&attrs[..n]);
}

/// Stores a vertex without a window position, flagged why. Cold and out
/// of line: built inline, its zeros were set up on the common path of
/// every vertex (ten moves a vertex, `f32` on the M4F).
#[cold]
#[inline(never)]
pub(crate) fn store_unprojected<const V: usize>(out: &mut ScreenVertex<V>, flags: i32) {
    *out = ScreenVertex { x: UNPROJECTED, y: flags, ..ScreenVertex::ZERO };
}

/// [`project`] as a call, for the rare draw call of a fixed-point
/// renderer that integers cannot hold: one copy per `V`, not one inlined
/// into every material's vertex loop.
#[inline(never)]
#[cold]
fn project_out_of_line<const V: usize>(v: &ClipVertex<V>, width: f32, height: f32, subpixel_bits: u32) -> ScreenVertex<V> {
    project(v, width, height, subpixel_bits)
}

/// The arithmetic a draw call's vertices go through: `f32`
/// ([`FloatVertices`]) or, for fixed-point settings, integers
/// ([`IntegerVertices`]). The triangle loop is generic over it.
pub trait VertexArithmetic {
    /// The varyings of mesh vertex `i`.
    fn varyings<E: Effect, C: Color, const V: usize>(&self, stage: &VertexStage<'_, E>, mesh: &Mesh<'_>, i: usize) -> [f32; V];
    /// Stores the vertex of mesh vertex `i` in `out`.
    fn vertex<E: Effect, C: Color, const V: usize>(&self, stage: &VertexStage<'_, E>, mesh: &Mesh<'_>, i: usize, out: &mut ScreenVertex<V>);
    /// Clip-space position of mesh vertex `i`, as the clipper sees it: the
    /// one its stored vertex was flagged by.
    fn clip_position<E: Effect>(&self, stage: &VertexStage<'_, E>, mesh: &Mesh<'_>, i: usize) -> Vec4;
    /// Stores every vertex of `mesh` in `slots` (one per vertex), except
    /// those already flagged (model-space culling's marks) if
    /// `skip_flagged`.
    #[inline(always)]
    fn vertices<E: Effect, C: Color, const V: usize>(
        &self,
        stage: &VertexStage<'_, E>,
        mesh: &Mesh<'_>,
        slots: &mut [ScreenVertex<V>],
        skip_flagged: bool,
    ) {
        for (i, slot) in slots.iter_mut().enumerate() {
            if skip_flagged && slot.x == UNPROJECTED {
                continue;
            }
            self.vertex::<E, C, V>(stage, mesh, i, slot);
        }
    }
}

/// The vertex stage in `f32`.
pub struct FloatVertices;

impl VertexArithmetic for FloatVertices {
    #[inline(always)]
    fn varyings<E: Effect, C: Color, const V: usize>(&self, stage: &VertexStage<'_, E>, mesh: &Mesh<'_>, i: usize) -> [f32; V] {
        stage.varyings::<C, V>(mesh, i)
    }
    #[inline(always)]
    fn vertex<E: Effect, C: Color, const V: usize>(
        &self,
        stage: &VertexStage<'_, E>,
        mesh: &Mesh<'_>,
        i: usize,
        out: &mut ScreenVertex<V>,
    ) {
        stage.vertex::<C, V>(mesh, i, out)
    }
    #[inline(always)]
    fn clip_position<E: Effect>(&self, stage: &VertexStage<'_, E>, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        stage.clip_position(mesh.position(i))
    }
    /// The usual draw call (`f32` positions and normals, no vertex colors,
    /// lit in model space from unit normals, or not lit) takes a loop in
    /// which all of that is known: it reads positions and normals in step
    /// with the slots and tests none of those per vertex (nor, without a
    /// point light, that light). Any other takes the general loop, which
    /// is the trait's own written out again: through a shared function
    /// taking a closure, `torus` (built-in, `f32`, M4F) took 1.6% more and
    /// `torus.babylon` in fixed point 1.2% more. The same arithmetic
    /// either way.
    #[inline(always)]
    fn vertices<E: Effect, C: Color, const V: usize>(
        &self,
        stage: &VertexStage<'_, E>,
        mesh: &Mesh<'_>,
        slots: &mut [ScreenVertex<V>],
        skip_flagged: bool,
    ) {
        let lit_in_model_space = !E::LIT_VERTICES || (stage.model_space && mesh.unit_normals());
        let arrays = mesh.positions().as_f32().zip(mesh.normals().as_f32());
        let (Some((positions, normals)), None, true) = (arrays, mesh.colors(), lit_in_model_space) else {
            for (i, slot) in slots.iter_mut().enumerate() {
                if skip_flagged && slot.x == UNPROJECTED {
                    continue;
                }
                stage.vertex::<C, V>(mesh, i, slot);
            }
            return;
        };
        // Without a point light, lit without its test at every vertex.
        let arrays = MeshArrays { positions, normals, uvs: mesh.uvs() };
        match SunLight::new(stage.lights) {
            Some(sun) => arrays.vertices::<E, C, V>(stage, &sun, slots, skip_flagged),
            None => arrays.vertices::<E, C, V>(stage, stage.lights, slots, skip_flagged),
        }
    }
}

/// The arrays of a mesh of `f32` positions and normals without vertex
/// colors, for [`FloatVertices`]'s usual loop.
struct MeshArrays<'a> {
    positions: &'a [Vec3],
    normals: &'a [Vec3],
    uvs: Option<&'a [Vec2]>,
}

impl MeshArrays<'_> {
    /// The vertex loop of a draw call lit in model space from unit
    /// normals (or unlit) by `lights`, in the material's color.
    #[inline(always)]
    fn vertices<E: Effect, C: Color, const V: usize>(
        &self,
        stage: &VertexStage<'_, E>,
        lights: &impl LitColor,
        slots: &mut [ScreenVertex<V>],
        skip_flagged: bool,
    ) {
        for (i, ((slot, &position), &normal)) in slots.iter_mut().zip(self.positions).zip(self.normals).enumerate() {
            if skip_flagged && slot.x == UNPROJECTED {
                continue;
            }
            let uv = self.uvs.and_then(|u| u.get(i).copied()).unwrap_or(Vec2::new(0.0, 0.0));
            let v = MeshVertex { position, normal, color: stage.color, uv };
            stage.vertex_of::<C, V>(&v, (true, true), lights, i, slot);
        }
    }
}

/// The vertex stage in integers: positions where [`IntegerProjection`]
/// holds the draw call, the lit color where [`IntegerLighting`] covers its
/// lights, the rest in `f32`. (One type for all cases, decided per draw
/// call, so that a firmware holds one triangle loop per material.)
pub struct IntegerVertices<'a> {
    /// The draw call's transform and viewport, if integers hold them.
    pub projection: Option<IntegerProjection<'a>>,
    /// Its lights, if integers cover them.
    pub lighting: Option<IntegerLighting<'a>>,
    /// Whether its material corrects for perspective: only then is `q`
    /// (`1 / w`) converted and stored; otherwise it is 1.
    pub perspective: bool,
}

impl VertexArithmetic for IntegerVertices<'_> {
    #[inline(always)]
    fn varyings<E: Effect, C: Color, const V: usize>(&self, stage: &VertexStage<'_, E>, mesh: &Mesh<'_>, i: usize) -> [f32; V] {
        match &self.lighting {
            Some(l) => stage.varyings_at::<C, V>(mesh, i, mesh.position(i), l),
            None => stage.varyings::<C, V>(mesh, i),
        }
    }
    #[inline(always)]
    fn vertex<E: Effect, C: Color, const V: usize>(
        &self,
        stage: &VertexStage<'_, E>,
        mesh: &Mesh<'_>,
        i: usize,
        out: &mut ScreenVertex<V>,
    ) {
        let attrs = self.varyings::<E, C, V>(stage, mesh, i);
        match &self.projection {
            Some(p) => p.project_into(i, attrs, self.perspective, E::VARYINGS, out),
            None => {
                let v = ClipVertex { pos: stage.clip_position(mesh.position(i)), attrs, src: 0 };
                *out = project_out_of_line(&v, stage.width, stage.height, stage.subpixel_bits);
            }
        }
    }
    #[inline(always)]
    fn clip_position<E: Effect>(&self, stage: &VertexStage<'_, E>, mesh: &Mesh<'_>, i: usize) -> Vec4 {
        match &self.projection {
            Some(p) => p.clip_position(i),
            None => stage.clip_position(mesh.position(i)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effect::{Gouraud, MonoGouraud, Textured};
    use crate::mesh::{torus_index_count, torus_vertex_count, MeshData};
    use crate::scene::{DirectionalLight, Lights, PointLight};
    use crate::texture::Texture;
    use embedded_graphics::pixelcolor::Rgb565;

    const N: usize = torus_vertex_count(12, 8);
    static TORUS: MeshData<N, { torus_index_count(12, 8) }> = MeshData::torus(12, 8, 1.0, 0.4);
    static COLORS: [Rgb888; N] = {
        let mut c = [Rgb888::BLACK; N];
        let mut i = 0;
        while i < N {
            c[i] = Rgb888::new((i * 37 % 256) as u8, (i * 91 % 256) as u8, (i * 13 % 256) as u8);
            i += 1;
        }
        c
    };
    static UVS: [Vec2; N] = {
        let mut u = [Vec2::new(0.0, 0.0); N];
        let mut i = 0;
        while i < N {
            u[i] = Vec2::new(i as f32 * 0.37 - 3.0, 1.5 - i as f32 * 0.11);
            i += 1;
        }
        u
    };
    static TEXELS: [u16; 4] = [0x1234, 0xffff, 0, 0x8410];

    /// The stored vertex's bits, so that equal means bit for bit.
    fn bits<const V: usize>(v: &ScreenVertex<V>) -> (i32, i32, u32, u32, [u32; V]) {
        (v.x, v.y, v.z, v.q.to_bits(), v.attrs.map(f32::to_bits))
    }

    /// Runs [`FloatVertices`]'s loop over `mesh` and checks each vertex
    /// against [`VertexStage::vertex`], the general path, for effect `E`.
    fn loop_matches_each_vertex<E: Effect, const V: usize>(effect: &E, mesh: &Mesh<'_>, model: Mat4, lights: &Lights) {
        let view_proj = Mat4::perspective_fov_lh(0.9, 320.0 / 240.0, 0.1, 100.0)
            * Mat4::look_at_lh(Vec3::new(0.5, 1.5, -3.5), Vec3::ZERO, Vec3::new(0.0, 1.0, 0.0));
        let lighting = Lighting::new(lights, view_proj.eye().unwrap_or(Vec3::ZERO));
        let scale = model.similarity_scale();
        let vertex_lights = scale.map_or(lighting, |s| lighting.in_model_space(&model, s));
        let stage = VertexStage {
            model,
            mvp: view_proj * model,
            normal_matrix: model.normal_matrix(),
            lights: &vertex_lights,
            model_space: scale.is_some(),
            effect,
            color: Rgb888::new(200, 150, 100),
            width: 320.0,
            height: 240.0,
            subpixel_bits: 6,
        };
        // Every third slot flagged: skipped, so left as it was.
        let flagged = ScreenVertex { x: UNPROJECTED, y: CULLED, ..ScreenVertex::ZERO };
        let mut slots = [ScreenVertex::<V>::ZERO; N];
        for slot in slots.iter_mut().step_by(3) {
            *slot = flagged;
        }
        FloatVertices.vertices::<E, Rgb565, V>(&stage, mesh, &mut slots, true);
        for (i, slot) in slots.iter().enumerate() {
            let mut one = ScreenVertex::ZERO;
            stage.vertex::<Rgb565, V>(mesh, i, &mut one);
            let expected = if i % 3 == 0 { flagged } else { one };
            assert_eq!(bits(slot), bits(&expected), "vertex {i}");
        }
    }

    /// The loop for the usual draw call (with and without a point light,
    /// with clamped light, without a sun) stores the same bits as the
    /// general path, and so do draw calls it does not take (vertex
    /// colors, a model matrix that is not a similarity), for effects
    /// that read the lit color and texture coordinates.
    #[test]
    fn the_usual_draw_calls_loop_stores_what_the_general_path_does() {
        let mesh = TORUS.mesh();
        let colored = mesh.with_colors(&COLORS).unwrap();
        let textured: Textured<'_> = Textured::new(Texture::new(&TEXELS, 2, 2).unwrap());
        assert!(mesh.unit_normals());
        let turned = Mat4::translation(Vec3::new(0.2, -0.1, 0.3)) * Mat4::rotation_y(0.7) * Mat4::rotation_x(0.4);
        let squashed = turned * Mat4::scaling(Vec3::new(1.0, 0.5, 1.3));
        let sun = DirectionalLight { direction: Vec3::new(0.5, -0.7, 1.0), color: Vec3::new(0.85, 0.85, 0.85) };
        let point = PointLight { position: Vec3::new(2.0, 1.0, -2.0), color: Vec3::new(0.5, 0.4, 0.3) };
        let lights = [
            Lights::default(),
            // Brighter than 1: clamped.
            Lights { ambient: Vec3::new(0.5, 0.4, 0.3), point: None, directional: Some(sun) },
            Lights { ambient: Vec3::new(0.1, 0.1, 0.1), point: Some(point), directional: Some(sun) },
            Lights { ambient: Vec3::new(0.3, 0.3, 0.3), point: None, directional: None },
        ];
        for l in &lights {
            for model in [turned, turned * Mat4::scaling(Vec3::new(2.0, 2.0, 2.0)), squashed] {
                for m in [mesh, colored, mesh.with_uvs(&UVS).unwrap()] {
                    loop_matches_each_vertex::<_, 3>(&Gouraud, &m, model, l);
                    loop_matches_each_vertex::<_, 1>(&MonoGouraud, &m, model, l);
                    loop_matches_each_vertex::<_, 5>(&textured, &m, model, l);
                }
            }
        }
    }
}
