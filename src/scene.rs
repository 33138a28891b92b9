//! Camera and lights: what a frame is seen from and lit by.

use crate::math::{Mat4, Vec3};

/// A perspective camera (left-handed, Babylon conventions).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Eye position in world space.
    pub position: Vec3,
    /// Point looked at.
    pub target: Vec3,
    /// Up direction (need not be exactly perpendicular to the view).
    pub up: Vec3,
    /// Vertical field of view in radians.
    pub fov_y: f32,
    /// Near plane distance (> 0). Geometry closer than this is clipped.
    pub near: f32,
    /// Far plane distance (> near).
    pub far: f32,
}

impl Camera {
    /// A camera at `position` looking at `target`, y up, 0.8 rad field of
    /// view (Babylon's default), near 0.1, far 1000.
    pub const fn looking_at(position: Vec3, target: Vec3) -> Self {
        Self { position, target, up: Vec3::new(0.0, 1.0, 0.0), fov_y: 0.8, near: 0.1, far: 1000.0 }
    }

    /// The view matrix.
    pub fn view(&self) -> Mat4 {
        Mat4::look_at_lh(self.position, self.target, self.up)
    }

    /// The projection matrix for a viewport of the given aspect (width / height).
    ///
    /// Invalid planes are repaired rather than producing NaN: `near` is at
    /// least 1e-4 and `far` beyond `near`.
    pub fn projection(&self, aspect: f32) -> Mat4 {
        let near = if self.near.is_finite() && self.near > 1e-4 { self.near } else { 1e-4 };
        let far = if self.far.is_finite() && self.far > near * 1.001 { self.far } else { near * 1000.0 };
        let fov = if self.fov_y.is_finite() && self.fov_y > 1e-3 && self.fov_y < 3.1 { self.fov_y } else { 0.8 };
        Mat4::perspective_fov_lh(fov, aspect, near, far)
    }
}

/// A point light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// Position in world space.
    pub position: Vec3,
    /// RGB color times intensity (1.0 = full).
    pub color: Vec3,
}

/// A directional light (like the sun).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectionalLight {
    /// Direction the light travels, in world space (need not be unit length).
    pub direction: Vec3,
    /// RGB color times intensity (1.0 = full).
    pub color: Vec3,
}

/// The lights of a frame: ambient, one optional point light and one
/// optional directional light.
///
/// Diffuse lighting at a point with unit normal `n` is
/// `ambient + Σ color_i · clamp(n · l_i, 0, 1)` where `l_i` is the unit
/// direction from the point toward light `i`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lights {
    /// Ambient RGB term.
    pub ambient: Vec3,
    /// Optional point light.
    pub point: Option<PointLight>,
    /// Optional directional light.
    pub directional: Option<DirectionalLight>,
}

impl Lights {
    /// No light sources, full ambient: surfaces show their own color.
    pub const UNLIT: Self = Self { ambient: Vec3::ONE, point: None, directional: None };

    /// Diffuse light reaching a point with the given (unit) normal.
    /// Every term is finite for finite inputs; a zero normal gets ambient only.
    pub fn diffuse(&self, position: Vec3, normal: Vec3) -> Vec3 {
        Lighting::new(self, Vec3::ZERO).diffuse(position, normal)
    }
}

/// [`Lights`] prepared once per frame for the vertex stage: the
/// directional light's direction is normalized here, not per vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lighting {
    /// Ambient term.
    pub ambient: Vec3,
    /// The point light.
    pub point: Option<PointLight>,
    /// Unit direction toward the directional light, and its color.
    pub sun: Option<(Vec3, Vec3)>,
    /// The eye (camera position), for specular highlights.
    pub eye: Vec3,
}

impl Lighting {
    /// Full ambient and no light sources.
    pub const UNLIT: Self = Self { ambient: Vec3::ONE, point: None, sun: None, eye: Vec3::ZERO };

    /// Prepares `lights` seen from `eye`.
    pub fn new(lights: &Lights, eye: Vec3) -> Self {
        Self {
            ambient: lights.ambient,
            point: lights.point,
            sun: lights.directional.map(|d| ((-d.direction).normalize_or_zero(), d.color)),
            eye,
        }
    }

    /// The same lights seen from the model space of a mesh placed by a
    /// similarity `model` with scale `s` (see [`Mat4::similarity_scale`]):
    /// unit model-space normals then light exactly as in world space.
    pub fn in_model_space(&self, model: &Mat4, s: f32) -> Self {
        let inverse = model.similarity_inverse(s);
        Self {
            ambient: self.ambient,
            point: self.point.map(|p| PointLight { position: inverse.transform_point3(p.position), color: p.color }),
            sun: self.sun.map(|(l, color)| (inverse.upper3().transform(l).normalize_or_zero(), color)),
            eye: inverse.transform_point3(self.eye),
        }
    }

    /// Diffuse light reaching a point with the given (unit) normal:
    /// `ambient + Σ color_i · clamp(n · l_i, 0, 1)`.
    #[inline]
    pub fn diffuse(&self, position: Vec3, normal: Vec3) -> Vec3 {
        let mut light = self.ambient;
        if let Some(p) = self.point {
            let l = (p.position - position).normalize_or_zero();
            light = light + p.color * clamp01(normal.dot(l));
        }
        if let Some((l, color)) = self.sun {
            light = light + color * clamp01(normal.dot(l));
        }
        light
    }
}

impl Default for Lights {
    /// Ambient 0.15 and a white directional light from the upper left front.
    fn default() -> Self {
        Self {
            ambient: Vec3::new(0.15, 0.15, 0.15),
            point: None,
            directional: Some(DirectionalLight { direction: Vec3::new(0.5, -0.7, 1.0), color: Vec3::new(0.85, 0.85, 0.85) }),
        }
    }
}

/// `x` clamped to [0, 1]; NaN gives 0.
#[inline]
pub(crate) fn clamp01(x: f32) -> f32 {
    if x > 0.0 {
        if x < 1.0 {
            x
        } else {
            1.0
        }
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn n_dot_l_is_clamped_and_never_nan() {
        let lights = Lights {
            ambient: Vec3::ZERO,
            point: Some(PointLight { position: Vec3::new(0.0, 0.0, -1.0), color: Vec3::ONE }),
            directional: None,
        };
        let n = Vec3::new(0.0, 0.0, -1.0);
        assert_eq!(lights.diffuse(Vec3::ZERO, n), Vec3::ONE);
        assert_eq!(lights.diffuse(Vec3::ZERO, -n), Vec3::ZERO);
        // Light exactly at the surface point, zero normal, NaN normal.
        assert_eq!(lights.diffuse(Vec3::new(0.0, 0.0, -1.0), n), Vec3::ZERO);
        assert_eq!(lights.diffuse(Vec3::ZERO, Vec3::ZERO), Vec3::ZERO);
        assert_eq!(lights.diffuse(Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 0.0)), Vec3::ZERO);
    }

    #[test]
    fn projection_repairs_invalid_planes() {
        let mut c = Camera::looking_at(Vec3::new(0.0, 0.0, -5.0), Vec3::ZERO);
        c.near = 0.0;
        c.far = f32::NAN;
        assert!(c.projection(1.0).is_finite());
    }
}
