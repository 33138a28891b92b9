//! Small `f32` vectors.

use core::ops::{Add, Mul, Neg, Sub};

/// A 2D vector (texture coordinates).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec2 {
    /// First component.
    pub x: f32,
    /// Second component.
    pub y: f32,
}

/// A 3D vector (positions, normals, directions, RGB light).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec3 {
    /// x component.
    pub x: f32,
    /// y component.
    pub y: f32,
    /// z component.
    pub z: f32,
}

/// A homogeneous 4D vector (clip-space positions).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec4 {
    /// x component.
    pub x: f32,
    /// y component.
    pub y: f32,
    /// z component.
    pub z: f32,
    /// w component.
    pub w: f32,
}

impl Vec2 {
    /// Builds a vector from its components.
    pub const fn new(x: f32, y: f32) -> Self {
        Self { x, y }
    }
}

impl Vec3 {
    /// The zero vector.
    pub const ZERO: Self = Self::new(0.0, 0.0, 0.0);
    /// All components one.
    pub const ONE: Self = Self::new(1.0, 1.0, 1.0);

    /// Builds a vector from its components.
    pub const fn new(x: f32, y: f32, z: f32) -> Self {
        Self { x, y, z }
    }

    /// The components `[x, y, z]`.
    pub const fn to_array(self) -> [f32; 3] {
        [self.x, self.y, self.z]
    }

    /// Dot product.
    #[inline]
    pub fn dot(self, o: Self) -> f32 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Cross product (left-handed frames use the same formula).
    #[inline]
    pub fn cross(self, o: Self) -> Self {
        Self::new(self.y * o.z - self.z * o.y, self.z * o.x - self.x * o.z, self.x * o.y - self.y * o.x)
    }

    /// Squared length.
    #[inline]
    pub fn length_squared(self) -> f32 {
        self.dot(self)
    }

    /// Length.
    #[inline]
    pub fn length(self) -> f32 {
        super::sqrt(self.length_squared())
    }

    /// Unit vector in the same direction; the zero vector (and any vector
    /// with a non-finite or vanishing length) maps to zero rather than NaN.
    #[inline]
    pub fn normalize_or_zero(self) -> Self {
        let len2 = self.length_squared();
        if len2 > 1e-30 && len2.is_finite() {
            self * super::rsqrt(len2)
        } else {
            Self::ZERO
        }
    }

    /// Component-wise product.
    #[inline]
    pub fn mul_elem(self, o: Self) -> Self {
        Self::new(self.x * o.x, self.y * o.y, self.z * o.z)
    }

    /// Extends to a homogeneous point (w = 1).
    #[inline]
    pub fn extend(self, w: f32) -> Vec4 {
        Vec4::new(self.x, self.y, self.z, w)
    }

    /// True if every component is finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
}

impl Vec4 {
    /// Builds a vector from its components.
    pub const fn new(x: f32, y: f32, z: f32, w: f32) -> Self {
        Self { x, y, z, w }
    }

    /// Linear interpolation `self + (o - self) * t`.
    #[inline]
    pub fn lerp(self, o: Self, t: f32) -> Self {
        self + (o - self) * t
    }

    /// The x, y, z components.
    #[inline]
    pub fn xyz(self) -> Vec3 {
        Vec3::new(self.x, self.y, self.z)
    }

    /// True if every component is finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.xyz().is_finite() && self.w.is_finite()
    }
}

macro_rules! impl_ops {
    ($t:ident { $($f:ident),* }) => {
        impl Add for $t {
            type Output = Self;
            #[inline]
            fn add(self, o: Self) -> Self { Self { $($f: self.$f + o.$f),* } }
        }
        impl Sub for $t {
            type Output = Self;
            #[inline]
            fn sub(self, o: Self) -> Self { Self { $($f: self.$f - o.$f),* } }
        }
        impl Mul<f32> for $t {
            type Output = Self;
            #[inline]
            fn mul(self, s: f32) -> Self { Self { $($f: self.$f * s),* } }
        }
        impl Neg for $t {
            type Output = Self;
            #[inline]
            fn neg(self) -> Self { Self { $($f: -self.$f),* } }
        }
    };
}
impl_ops!(Vec2 { x, y });
impl_ops!(Vec3 { x, y, z });
impl_ops!(Vec4 { x, y, z, w });

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cross_follows_the_right_hand_formula() {
        let x = Vec3::new(1.0, 0.0, 0.0);
        let y = Vec3::new(0.0, 1.0, 0.0);
        assert_eq!(x.cross(y), Vec3::new(0.0, 0.0, 1.0));
    }

    #[test]
    fn normalize_never_produces_nan() {
        assert_eq!(Vec3::ZERO.normalize_or_zero(), Vec3::ZERO);
        assert_eq!(Vec3::new(f32::NAN, 0.0, 0.0).normalize_or_zero(), Vec3::ZERO);
        assert_eq!(Vec3::new(f32::INFINITY, 0.0, 0.0).normalize_or_zero(), Vec3::ZERO);
        let n = Vec3::new(3.0, 0.0, 4.0).normalize_or_zero();
        assert!((n.length() - 1.0).abs() < 1e-6);
    }
}
