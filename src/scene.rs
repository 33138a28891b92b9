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
    /// Whether diffuse light stays within [0, 1] without clamping (see
    /// [`Lighting::in_unit_range`]).
    in_unit: bool,
}

impl Lighting {
    /// Full ambient and no light sources.
    pub const UNLIT: Self = Self { ambient: Vec3::ONE, point: None, sun: None, eye: Vec3::ZERO, in_unit: true };

    /// Prepares `lights` seen from `eye`.
    pub fn new(lights: &Lights, eye: Vec3) -> Self {
        let (ambient, point) = (lights.ambient, lights.point);
        let sun = lights.directional.map(|d| ((-d.direction).normalize_or_zero(), d.color));
        Self { ambient, point, sun, eye, in_unit: Self::bounded(ambient, point.map(|p| p.color), sun.map(|s| s.1)) }
    }

    /// Whether every channel of `ambient + Σ colors` is in [0, 1], each
    /// term non-negative (false for NaN). Then so is the diffuse light at
    /// every point: each color is scaled by a factor in [0, 1] and summed
    /// in the same order, and rounding is monotonic.
    fn bounded(ambient: Vec3, point: Option<Vec3>, sun: Option<Vec3>) -> bool {
        let non_negative = |v: Vec3| v.x >= 0.0 && v.y >= 0.0 && v.z >= 0.0;
        let mut sum = ambient;
        let mut ok = non_negative(ambient);
        for color in [point, sun].into_iter().flatten() {
            ok &= non_negative(color);
            sum = sum + color;
        }
        ok && sum.x <= 1.0 && sum.y <= 1.0 && sum.z <= 1.0
    }

    /// Whether the diffuse light ([`Lighting::diffuse`]) is within [0, 1]
    /// in every channel at every point, so that lighting needs no clamp.
    pub fn in_unit_range(&self) -> bool {
        self.in_unit
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
            in_unit: self.in_unit,
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
        self.add_sun(light, normal)
    }

    /// `light` plus the directional light's share at `normal`: the last
    /// term of [`Lighting::diffuse`], which without a point light is all
    /// of it after the ambient term.
    #[inline(always)]
    pub(crate) fn add_sun(&self, light: Vec3, normal: Vec3) -> Vec3 {
        match self.sun {
            Some((l, color)) => light + color * clamp01(normal.dot(l)),
            None => light,
        }
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
    use embedded_graphics::pixelcolor::Rgb888;

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
    fn lights_within_the_unit_range_skip_the_clamp_and_others_keep_it() {
        let sun = |color: Vec3| Some(DirectionalLight { direction: Vec3::new(0.3, -0.4, 1.0), color });
        let point = |color: Vec3| Some(PointLight { position: Vec3::new(1.0, 2.0, -3.0), color });
        let lighting = |ambient: Vec3, point, directional| Lighting::new(&Lights { ambient, point, directional }, Vec3::ZERO);
        let grey = Vec3::new;
        // Default lights sum to 1 (0.15 + 0.85 rounds to 1.0 in f32).
        assert!(Lighting::new(&Lights::default(), Vec3::ZERO).in_unit_range());
        assert!(lighting(grey(0.25, 0.0, 0.5), point(grey(0.25, 1.0, 0.25)), sun(grey(0.5, 0.0, 0.25))).in_unit_range());
        assert!(Lighting::UNLIT.in_unit_range());
        for (ambient, p, d) in [
            (grey(0.5, 0.5, 0.5), None, sun(grey(0.6, 0.6, 0.6))),
            (grey(0.0, 0.0, 0.0), point(grey(0.7, 0.0, 0.0)), sun(grey(0.4, 0.0, 0.0))),
            (grey(-0.1, 0.0, 0.0), None, sun(grey(0.5, 0.5, 0.5))),
            (grey(0.1, 0.1, 0.1), None, sun(grey(0.5, -0.2, 0.5))),
            (grey(f32::NAN, 0.1, 0.1), None, None),
            (grey(0.1, 0.1, 0.1), point(grey(0.1, f32::INFINITY, 0.1)), None),
        ] {
            assert!(!lighting(ambient, p, d).in_unit_range(), "{ambient:?} {p:?} {d:?}");
        }
        // Out of range, lit colors are clamped; in range they need not be.
        let n = Vec3::new(-0.3, 0.4, -1.0).normalize_or_zero();
        let bright = lighting(grey(1.0, 1.0, 1.0), None, sun(grey(1.0, 1.0, 1.0)));
        assert_eq!(crate::effect::lit_by(&bright, Vec3::ZERO, n, Rgb888::new(200, 100, 50)), [200.0, 100.0, 50.0]);
        let moved = bright.in_model_space(&Mat4::translation(Vec3::new(1.0, 2.0, 3.0)), 1.0);
        assert!(!moved.in_unit_range());
        // In range, the unclamped light stays in [0, 1] at every point and
        // normal of a sweep.
        let lit = lighting(grey(0.15, 0.3, 0.0), point(grey(0.35, 0.2, 0.5)), sun(grey(0.5, 0.5, 0.5)));
        assert!(lit.in_unit_range() && lit.in_model_space(&Mat4::translation(Vec3::ONE), 1.0).in_unit_range());
        for k in 0..2000 {
            let t = k as f32 * 0.37;
            let normal = Vec3::new(t.sin(), (t * 1.7).cos(), (t * 0.3).sin() - 0.5).normalize_or_zero();
            let light = lit.diffuse(Vec3::new(t.cos(), 0.5, -t.sin()), normal);
            for c in [light.x, light.y, light.z] {
                assert!((0.0..=1.0).contains(&c), "{light:?} at {normal:?}");
            }
        }
    }

    #[test]
    fn projection_repairs_invalid_planes() {
        let mut c = Camera::looking_at(Vec3::new(0.0, 0.0, -5.0), Vec3::ZERO);
        c.near = 0.0;
        c.far = f32::NAN;
        assert!(c.projection(1.0).is_finite());
    }
}
