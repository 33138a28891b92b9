//! Materials: an effect plus the per-draw choices (color, culling,
//! perspective correction, depth test), all fixed at compile time except
//! the color and the culling mode.

use crate::effect::Effect;
use core::marker::PhantomData;
use embedded_graphics::pixelcolor::Rgb888;

/// Which triangles are dropped by winding.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Cull {
    /// Draw both sides.
    None,
    /// Drop triangles whose snapped screen-space winding is
    /// counter-clockwise as seen on screen (their back faces).
    #[default]
    Back,
}

/// How varyings are interpolated across a triangle: [`Affine`],
/// [`PerSpan`] or [`PerPixel`].
pub trait Perspective: 'static {
    /// Whether values are divided by the interpolated `1/w`.
    const CORRECT: bool;
    /// With `CORRECT`: pixels per exactly divided segment, values linear in
    /// between (1 = every pixel).
    const SPAN: u32;
    /// Name for reports.
    const NAME: &'static str;
}

/// Affine (screen-linear) interpolation: cheapest, bends under perspective.
#[derive(Clone, Copy, Debug, Default)]
pub struct Affine;
impl Perspective for Affine {
    const CORRECT: bool = false;
    const SPAN: u32 = 1;
    const NAME: &'static str = "affine";
}

/// Perspective-correct interpolation, exact at every pixel (interpolates
/// `value / w` and `1 / w`, one reciprocal per pixel).
#[derive(Clone, Copy, Debug, Default)]
pub struct PerPixel;
impl Perspective for PerPixel {
    const CORRECT: bool = true;
    const SPAN: u32 = 1;
    const NAME: &'static str = "exact";
}

/// Perspective-correct at every `N`-th pixel of a span (and at its first),
/// linear in between: one reciprocal per `N` pixels. `N` is a power of two
/// from 2 to 256.
#[derive(Clone, Copy, Debug, Default)]
pub struct PerSpan<const N: u32>;
impl<const N: u32> Perspective for PerSpan<N> {
    const CORRECT: bool = true;
    const SPAN: u32 = {
        assert!(N.is_power_of_two() && N >= 2 && N <= 256, "PerSpan<N> needs a power of two from 2 to 256");
        N
    };
    const NAME: &'static str = "span";
}

/// Depth buffer use.
pub trait DepthMode: 'static {
    /// Whether a fragment must be nearer than the stored depth ("less").
    const TEST: bool;
    /// Whether a drawn fragment stores its depth.
    const WRITE: bool;
}

/// Test "less" and write: the default.
#[derive(Clone, Copy, Debug, Default)]
pub struct DepthLess;
impl DepthMode for DepthLess {
    const TEST: bool = true;
    const WRITE: bool = true;
}

/// Neither test nor write the depth buffer (overlays, drawn in order).
#[derive(Clone, Copy, Debug, Default)]
pub struct DepthOff;
impl DepthMode for DepthOff {
    const TEST: bool = false;
    const WRITE: bool = false;
}

/// What a mesh is drawn with.
///
/// ```
/// use soft3d::{Material, effect::Gouraud, Cull};
/// use embedded_graphics::pixelcolor::Rgb888;
/// let m = Material::new(Gouraud).with_color(Rgb888::new(200, 120, 40)).with_cull(Cull::None);
/// # let _ = m;
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Material<E, P = Affine, D = DepthLess> {
    /// The effect.
    pub effect: E,
    /// Diffuse color (used where the mesh has no vertex colors).
    pub color: Rgb888,
    /// Back-face culling.
    pub cull: Cull,
    _modes: PhantomData<(P, D)>,
}

impl<E: Effect> Material<E> {
    /// A white, back-face culled, depth-tested material with affine
    /// interpolation.
    pub const fn new(effect: E) -> Self {
        Self { effect, color: Rgb888::new(255, 255, 255), cull: Cull::Back, _modes: PhantomData }
    }
}

impl<E: Effect, P: Perspective, D: DepthMode> Material<E, P, D> {
    /// Sets the diffuse color.
    pub const fn with_color(mut self, color: Rgb888) -> Self {
        self.color = color;
        self
    }

    /// Sets back-face culling.
    pub const fn with_cull(mut self, cull: Cull) -> Self {
        self.cull = cull;
        self
    }

    /// Chooses how varyings are interpolated.
    pub const fn with_perspective<P2: Perspective>(self) -> Material<E, P2, D> {
        Material { effect: self.effect, color: self.color, cull: self.cull, _modes: PhantomData }
    }

    /// Chooses how the depth buffer is used.
    pub const fn with_depth<D2: DepthMode>(self) -> Material<E, P, D2> {
        Material { effect: self.effect, color: self.color, cull: self.cull, _modes: PhantomData }
    }
}
