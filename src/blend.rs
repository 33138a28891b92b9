//! Blending: how a shaded color merges with the color already in the strip.
//!
//! A type parameter of the effects that can be translucent (so far
//! [`Textured`](crate::effect::Textured)): [`Opaque`] writes the color and
//! never reads an alpha value; [`AlphaBlend`] mixes it over the strip's color
//! by the texel's alpha times the material's opacity. Lighting scales the
//! color channels only, so the alpha reaches the blend unchanged.
//!
//! Blended surfaces still write depth. Draw them after the opaque ones,
//! farthest first, as usual for a depth-buffered renderer.

use crate::effect::Color;

/// How a color with an alpha is written over the strip's color.
pub trait Blend: 'static {
    /// Name for reports.
    const NAME: &'static str;
    /// Whether alpha is used at all: effects skip the alpha plane and the
    /// opacity when it is not.
    const ALPHA: bool;
    /// The color from channels `r`, `g`, `b` (in `C`'s depth) with opacity
    /// `alpha` (0 transparent to 255 opaque) over `dst`.
    fn blend<C: Color>(r: u8, g: u8, b: u8, alpha: u32, dst: C) -> C;
}

/// No blending: the color replaces what is there.
#[derive(Clone, Copy, Debug, Default)]
pub struct Opaque;

impl Blend for Opaque {
    const NAME: &'static str = "opaque";
    const ALPHA: bool = false;
    #[inline(always)]
    fn blend<C: Color>(r: u8, g: u8, b: u8, _: u32, _: C) -> C {
        C::from_channels(r, g, b)
    }
}

/// `src · α + dst · (1 − α)` per channel, rounded; α = 255 gives `src`
/// exactly and α = 0 leaves `dst`.
#[derive(Clone, Copy, Debug, Default)]
pub struct AlphaBlend;

impl Blend for AlphaBlend {
    const NAME: &'static str = "alpha";
    const ALPHA: bool = true;
    #[inline(always)]
    fn blend<C: Color>(r: u8, g: u8, b: u8, alpha: u32, dst: C) -> C {
        // 0..=255 to 0..=256, so both ends are exact with a shift.
        let a = alpha.min(255);
        let a = a + (a >> 7);
        let mix = |s: u8, d: u8| ((s as u32 * a + d as u32 * (256 - a) + 128) >> 8) as u8;
        C::from_channels(mix(r, dst.r()), mix(g, dst.g()), mix(b, dst.b()))
    }
}

/// `alpha · opacity / 255`, both 0–255, exact at both ends.
#[inline(always)]
pub(crate) fn scale_alpha(alpha: u32, opacity: u8) -> u32 {
    let o = opacity as u32 + (opacity as u32 >> 7);
    (alpha * o) >> 8
}
