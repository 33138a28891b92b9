//! The vertex stage: model, view and projection to clip space, normals
//! through the normal matrix, per-vertex effect work (lighting), and the
//! projection of visible vertices to snapped window coordinates.

use crate::clip::{to_window, ClipVertex};
use crate::effect::{vertex_varyings, Color, Effect, VertexInput};
use crate::math::{Mat3, Mat4, Vec2, Vec3, Vec4};
use crate::mesh::Mesh;
use crate::raster::{snap, ScreenVertex};
use crate::scene::Lighting;
use embedded_graphics::pixelcolor::Rgb888;

/// Vertex outside the near plane (in front of it is inside).
pub const BEHIND_NEAR: i32 = 1;
/// Vertex beyond the far plane.
pub const BEYOND_FAR: i32 = 2;
/// Vertex outside the guard band of the fixed-point setup.
pub const OUTSIDE_GUARD: i32 = 4;
/// Vertex with a non-finite position.
pub const NOT_FINITE: i32 = 8;
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
    /// View-projection matrix.
    pub view_proj: Mat4,
    /// Model-view-projection matrix.
    pub mvp: Mat4,
    /// Normal matrix of the model.
    pub normal_matrix: Mat3,
    /// Lights of the frame.
    pub lights: &'a Lighting,
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
        if E::LIT_VERTICES {
            self.view_proj.transform_point(self.model.transform_point3(p))
        } else {
            self.mvp.transform_point(p)
        }
    }

    /// Varyings of mesh vertex `i`.
    #[inline]
    pub fn varyings<C: Color, const V: usize>(&self, mesh: &Mesh<'_>, i: usize) -> [f32; V] {
        let world = if E::LIT_VERTICES { self.model.transform_point3(mesh.positions()[i]) } else { Vec3::ZERO };
        self.varyings_at::<C, V>(mesh, i, world)
    }

    /// Varyings of mesh vertex `i` whose world position is known (only
    /// used by lit effects).
    #[inline]
    fn varyings_at<C: Color, const V: usize>(&self, mesh: &Mesh<'_>, i: usize, position: Vec3) -> [f32; V] {
        if E::VARYINGS == 0 {
            return [0.0; V];
        }
        let normal = if E::LIT_VERTICES { self.normal_matrix.transform(mesh.normals()[i]).normalize_or_zero() } else { Vec3::ZERO };
        let input = VertexInput {
            position,
            normal,
            color: mesh.colors().map_or(self.color, |c| c[i]),
            uv: mesh.uvs().map_or(Vec2::new(0.0, 0.0), |u| u[i]),
        };
        vertex_varyings::<C, E, V>(self.effect, &input, self.lights)
    }

    /// Transforms mesh vertex `i` into a stored vertex: projected and
    /// snapped if it is inside the near/far planes and the guard band,
    /// otherwise flagged. The world position is computed once, for both
    /// the projection and the lighting.
    #[inline]
    pub fn vertex<C: Color, const V: usize>(&self, mesh: &Mesh<'_>, i: usize) -> ScreenVertex<V> {
        let p = mesh.positions()[i];
        let (clip, world) = if E::LIT_VERTICES {
            let w = self.model.transform_point3(p);
            (self.view_proj.transform_point(w), w)
        } else {
            (self.mvp.transform_point(p), Vec3::ZERO)
        };
        let attrs = self.varyings_at::<C, V>(mesh, i, world);
        project(&ClipVertex { pos: clip, attrs, src: 0 }, self.width, self.height, self.subpixel_bits)
    }
}

/// Projects and snaps a clip-space vertex, or flags why it cannot be.
#[inline]
pub fn project<const V: usize>(v: &ClipVertex<V>, width: f32, height: f32, subpixel_bits: u32) -> ScreenVertex<V> {
    let c = v.pos;
    let mut flags = 0;
    if !c.is_finite() {
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
        let w = to_window(v, width, height);
        if let (Some(x), Some(y)) = (snap(w.x as f32, subpixel_bits), snap(w.y as f32, subpixel_bits)) {
            return ScreenVertex { x, y, z: w.z, q: w.q, attrs: v.attrs };
        }
        flags |= OUTSIDE_GUARD;
    }
    ScreenVertex { x: UNPROJECTED, y: flags, ..ScreenVertex::ZERO }
}
