//! Effects: what color a pixel gets.
//!
//! An effect is a type. It says which per-vertex values (varyings) it needs
//! interpolated, computes them in the vertex stage, may compute one value
//! per triangle, and turns the interpolated values into a color in the span
//! loop. Each effect (with its material's other choices) is compiled into
//! its own span loop, so there is no per-pixel branch on a feature, and an
//! effect that no draw call uses is not in the binary.

use crate::blend::{scale_alpha, Blend, Opaque};
use crate::math::{Interp, Vec2, Vec3};
use crate::scene::Lighting;
use crate::texture::{Filter, Nearest, Repeat, Texture, Wrap};
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

/// The color types the renderer draws in: the RGB colors of
/// `embedded-graphics` (`Rgb565`, `Bgr565`, `Rgb555`, `Bgr555`, `Rgb666`,
/// `Bgr666`, `Rgb888`, `Bgr888`). Effects interpolate channels in the
/// display's own depth (0 to `MAX_R` etc.), so a pixel is built from its
/// channels with no conversion.
pub trait Color: RgbColor + From<Rgb888> {
    /// The color with these channels, each at most `MAX_R`, `MAX_G`,
    /// `MAX_B` (higher bits are dropped).
    fn from_channels(r: u8, g: u8, b: u8) -> Self;
    /// The color with these channels, which the caller keeps at most
    /// `MAX_R`, `MAX_G`, `MAX_B`: they are put in place without a mask (a
    /// larger channel gives an unspecified color, but no panic). See
    /// [`Interp::FREE_CHANNEL_MASK`] for which a span loop takes. (By
    /// default the masked [`Color::from_channels`]: the same color.)
    #[inline(always)]
    fn from_channels_in_range(r: u32, g: u32, b: u32) -> Self {
        Self::from_channels(r as u8, g as u8, b as u8)
    }
}

macro_rules! impl_color {
    ($($t:ident($raw:ident, $int:ty): $order:ident, $g_bits:literal, $low_bits:literal;)*) => {$(
        impl Color for embedded_graphics::pixelcolor::$t {
            #[inline(always)]
            fn from_channels(r: u8, g: u8, b: u8) -> Self {
                Self::new(r, g, b)
            }
            #[inline(always)]
            fn from_channels_in_range(r: u32, g: u32, b: u32) -> Self {
                let (high, low) = impl_color!(@ $order, r, b);
                let (high, g, low) = (high as $int, g as $int, low as $int);
                embedded_graphics::pixelcolor::raw::$raw::new(high << ($g_bits + $low_bits) | g << $low_bits | low).into()
            }
        }
    )*};
    (@ Rgb, $r:ident, $b:ident) => { ($r, $b) };
    (@ Bgr, $r:ident, $b:ident) => { ($b, $r) };
}

// Each color's raw value, its channel order, and the bits of its green and
// low channels.
impl_color! {
    Rgb565(RawU16, u16): Rgb, 6, 5;
    Bgr565(RawU16, u16): Bgr, 6, 5;
    Rgb555(RawU16, u16): Rgb, 5, 5;
    Bgr555(RawU16, u16): Bgr, 5, 5;
    Rgb666(RawU24, u32): Rgb, 6, 6;
    Bgr666(RawU24, u32): Bgr, 6, 6;
    Rgb888(RawU24, u32): Rgb, 8, 8;
    Bgr888(RawU24, u32): Bgr, 8, 8;
}

/// Most varyings any effect may ask for.
pub const MAX_VARYINGS: usize = 8;

/// The range of a color-channel varying whose channel is at most `max`:
/// its integer part is the channel.
pub const fn channel_range(max: u8) -> (f32, f32) {
    (0.0, max as f32 + 0.996)
}

/// Per-vertex input to an effect (world space).
#[derive(Clone, Copy, Debug)]
pub struct VertexInput {
    /// Position.
    pub position: Vec3,
    /// Unit normal (zero if the mesh's normal was zero or invalid).
    pub normal: Vec3,
    /// Vertex color, or the material color if the mesh has none.
    pub color: Rgb888,
    /// Texture coordinate (zero if the mesh has none).
    pub uv: Vec2,
    /// The color lit by the lights, per channel in the effect's units
    /// plus one half (the span loop's truncation then rounds):
    /// `clamp(ambient + Σ light·clamp(N·L, 0, 1), 0, 1) · color · scale +
    /// 0.5`, with `color` in `[0, 255]` and `scale` the effect's
    /// [`Effect::lit_scale`]. Computed by the vertex stage for effects
    /// with [`Effect::LIT_COLOR`] (in integers for fixed-point settings
    /// where it can, the scale folded into the lights), zero for others.
    pub lit: [f32; 3],
}

impl VertexInput {
    /// The input of a vertex at `position` with unit `normal`, `color`
    /// and `uv`, lit by `lights` in `f32` for display color `C` if `E`
    /// reads [`VertexInput::lit`].
    #[inline(always)]
    pub fn new<C: Color, E: Effect>(position: Vec3, normal: Vec3, color: Rgb888, uv: Vec2, lights: &Lighting) -> Self {
        let lit = if E::LIT_COLOR { lit_input::<C, E>(lights, position, normal, color) } else { [0.0; 3] };
        Self { position, normal, color, uv, lit }
    }
}

/// Per-triangle input to an effect (world space).
#[derive(Clone, Copy, Debug)]
pub struct FaceInput {
    /// Centroid.
    pub position: Vec3,
    /// Unit geometric normal of the triangle as wound.
    pub normal: Vec3,
    /// Color of the first vertex (or the material color).
    pub color: Rgb888,
}

/// A way of coloring pixels. See the [module docs](self).
pub trait Effect: Copy {
    /// Number of interpolated values (at most [`MAX_VARYINGS`]).
    const VARYINGS: usize;
    /// Whether [`Effect::vertex`] uses the lights (and so the world-space
    /// position and normal), so unlit effects skip that work.
    const LIT_VERTICES: bool;
    /// Whether [`Effect::face`] is used, so other effects skip the face
    /// normal (default: not used).
    const USES_FACE: bool = false;
    /// Whether [`Effect::vertex`] reads [`VertexInput::lit`], which the
    /// vertex stage then computes (false: it is left zero).
    const LIT_COLOR: bool = false;
    /// Whether [`VertexInput::lit`] is white lit (the light alone, in
    /// levels of 0 to 255) instead of the vertex's color lit, for an
    /// effect that applies its color per pixel.
    const LIT_WHITE: bool = false;
    /// Which channels of [`VertexInput::lit`] (red, green, blue) the
    /// effect reads: the vertex stage computes only those (the others are
    /// left zero), which matters where lighting is integer products in
    /// software (ARMv6-M).
    const LIT_CHANNELS: [bool; 3] = [true; 3];
    /// Name for reports.
    const NAME: &'static str;

    /// Per channel, what [`VertexInput::lit`] is scaled by for display
    /// color `C` (1: levels of 0 to 255). An effect interpolating the lit
    /// color in `C`'s own channel depth asks for `C`'s maximum over 255,
    /// and the vertex stage folds it into its lighting (in integers, into
    /// the lights, once per draw call).
    fn lit_scale<C: Color>() -> [f32; 3] {
        [1.0; 3]
    }

    /// The range each varying must stay in at every pixel (inclusive).
    /// The rasterizer guarantees it: with a wrapping scalar it checks each
    /// triangle's planes and, where rounding could leave the range, clamps
    /// the ends of every span. The default: red, green, blue channels of `C`.
    fn ranges<C: Color>() -> [(f32, f32); MAX_VARYINGS] {
        let mut r = [(0.0, 0.0); MAX_VARYINGS];
        r[..3].copy_from_slice(&[channel_range(C::MAX_R), channel_range(C::MAX_G), channel_range(C::MAX_B)]);
        r
    }

    /// For each varying, the period by which it may be shifted without
    /// changing the image (a repeating texture's size), or 0. The
    /// rasterizer shifts each triangle's values near zero, so that huge
    /// texture coordinates keep their precision.
    fn periods(&self) -> [f32; MAX_VARYINGS] {
        [0.0; MAX_VARYINGS]
    }

    /// Per-draw values the span loop reads, converted to the scalar `S`
    /// once per triangle (the lights, for per-pixel lighting); `()` for
    /// most effects.
    type Uniforms<S: Interp>: Copy;
    /// The uniforms for a draw call lit by `lights` (in the space the
    /// vertices were lit in) with material color `color`.
    fn uniforms<S: Interp>(&self, lights: &Lighting, color: Rgb888) -> Self::Uniforms<S>;

    /// Varyings of one vertex, for display color type `C`.
    fn vertex<C: Color>(&self, v: &VertexInput, lights: &Lighting) -> [f32; MAX_VARYINGS];
    /// The per-triangle color, called only where [`Effect::USES_FACE`] is
    /// set (default: black).
    fn face(&self, f: &FaceInput, lights: &Lighting) -> Rgb888 {
        let _ = (f, lights);
        Rgb888::BLACK
    }
    /// The color of a pixel from the triangle's color (converted once per
    /// triangle), the interpolated varyings and the color already there
    /// (for effects that blend; the others ignore it and the load is
    /// optimized away).
    fn shade<C: Color, S: Interp>(&self, u: &Self::Uniforms<S>, face: C, v: &[S; MAX_VARYINGS], dst: C) -> C;

    /// Whether [`Effect::shade`] can read what it samples: false for a
    /// texture without texels (which [`Texture::new`] never makes). Tested
    /// once a span, so that the span loop, knowing it, has no such test
    /// at each pixel's texel fetch.
    ///
    /// [`Texture::new`]: crate::texture::Texture::new
    #[inline(always)]
    fn samples(&self) -> bool {
        true
    }
}

/// The first `V` varyings `effect` computes for one vertex (the renderer
/// stores `V` per vertex; `V >= E::VARYINGS` is checked at compile time).
#[inline(always)]
pub(crate) fn vertex_varyings<C: Color, E: Effect, const V: usize>(effect: &E, input: &VertexInput, lights: &Lighting) -> [f32; V] {
    let mut out = [0.0; V];
    if E::VARYINGS > 0 {
        let all = effect.vertex::<C>(input, lights);
        let n = V.min(all.len());
        out[..n].copy_from_slice(&all[..n]);
    }
    out
}

/// `color` lit by `lights` at `position` with unit `normal`, in `f32`:
/// [`VertexInput::lit`].
#[inline(always)]
pub(crate) fn lit_by(lights: &Lighting, position: Vec3, normal: Vec3, color: Rgb888) -> [f32; 3] {
    lit(lights.diffuse(position, normal), color, !lights.in_unit_range())
}

/// [`VertexInput::lit`] for effect `E` and display color `C`, in `f32`.
#[inline(always)]
pub(crate) fn lit_input<C: Color, E: Effect>(lights: &Lighting, position: Vec3, normal: Vec3, color: Rgb888) -> [f32; 3] {
    scaled_lit::<C, E>(lit_by(lights, position, normal, color))
}

/// A lit color in [0, 255] per channel as [`VertexInput::lit`]: times the
/// effect's scale, plus one half, in the channels it reads.
#[inline(always)]
pub(crate) fn scaled_lit<C: Color, E: Effect>(l: [f32; 3]) -> [f32; 3] {
    let s = E::lit_scale::<C>();
    let channel = |k: usize| if E::LIT_CHANNELS[k] { l[k] * s[k] + 0.5 } else { 0.0 };
    [channel(0), channel(1), channel(2)]
}

/// Light times color, per channel, in [0, 255]: the light is clamped to
/// [0, 1] unless the lights keep it there (`clamp` false, the usual: a
/// lit vertex then skips three clamps).
#[inline]
pub(crate) fn lit(light: Vec3, c: Rgb888, clamp: bool) -> [f32; 3] {
    let ch = |l: f32, v: u8| if clamp { crate::scene::clamp01(l) } else { l } * v as f32;
    [ch(light.x, c.r()), ch(light.y, c.g()), ch(light.z, c.b())]
}

/// Channels in [0, 255] as varyings in the depth of `C`. They carry an
/// extra 0.5 so that the span loop's truncation rounds to nearest, as
/// `embedded-graphics` does when it converts colors.
#[inline]
fn rgb_varyings<C: Color>(c: [f32; 3]) -> [f32; MAX_VARYINGS] {
    let scale = |v: f32, max: u8| v * channel_scale(max) + 0.5;
    let mut v = [0.0; MAX_VARYINGS];
    v[..3].copy_from_slice(&[scale(c[0], C::MAX_R), scale(c[1], C::MAX_G), scale(c[2], C::MAX_B)]);
    v
}

/// A channel of at most `max` per level of 0 to 255.
#[inline(always)]
fn channel_scale(max: u8) -> f32 {
    max as f32 * (1.0 / 255.0)
}

/// The channel scales of `C`.
#[inline(always)]
fn channel_scales<C: Color>() -> [f32; 3] {
    [channel_scale(C::MAX_R), channel_scale(C::MAX_G), channel_scale(C::MAX_B)]
}

#[inline]
fn to_rgb888(c: [f32; 3]) -> Rgb888 {
    // `as` saturates; inputs are already in [0, 255].
    Rgb888::new((c[0] + 0.5) as u8, (c[1] + 0.5) as u8, (c[2] + 0.5) as u8)
}

#[inline(always)]
fn shade_rgb<C: Color, S: Interp>(v: &[S; MAX_VARYINGS]) -> C {
    pixel::<C, S>(v[0].channel(), v[1].channel(), v[2].channel())
}

/// The pixel of three channels a span loop keeps in range: masked where
/// that is free ([`Interp::FREE_CHANNEL_MASK`]), else put in place as they
/// are.
#[inline(always)]
fn pixel<C: Color, S: Interp>(r: u32, g: u32, b: u32) -> C {
    if S::FREE_CHANNEL_MASK {
        C::from_channels(r as u8, g as u8, b as u8)
    } else {
        C::from_channels_in_range(r, g, b)
    }
}

/// Flat shading: one N·L per triangle from its geometric normal.
#[derive(Clone, Copy, Debug, Default)]
pub struct Flat;

impl Effect for Flat {
    type Uniforms<S: Interp> = ();
    fn uniforms<S: Interp>(&self, _: &Lighting, _: Rgb888) {}
    const VARYINGS: usize = 0;
    const LIT_VERTICES: bool = false;
    const USES_FACE: bool = true;
    const NAME: &'static str = "flat";
    #[inline(always)]
    fn vertex<C: Color>(&self, _: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        [0.0; MAX_VARYINGS]
    }
    // Inlined into each draw loop: called once per triangle, and in a
    // firmware using `Flat` with two depth modes a real call cost 1.3% of
    // a flat frame (scripts/effects-bench.sh).
    #[inline(always)]
    fn face(&self, f: &FaceInput, lights: &Lighting) -> Rgb888 {
        to_rgb888(lit_by(lights, f.position, f.normal, f.color))
    }
    #[inline(always)]
    fn shade<C: Color, S: Interp>(&self, _: &Self::Uniforms<S>, face: C, _: &[S; MAX_VARYINGS], _: C) -> C {
        face
    }
}

/// Gouraud shading: N·L per vertex, the lit color interpolated.
#[derive(Clone, Copy, Debug, Default)]
pub struct Gouraud;

impl Effect for Gouraud {
    type Uniforms<S: Interp> = ();
    fn uniforms<S: Interp>(&self, _: &Lighting, _: Rgb888) {}
    const VARYINGS: usize = 3;
    const LIT_VERTICES: bool = true;
    const LIT_COLOR: bool = true;
    const NAME: &'static str = "gouraud";
    fn lit_scale<C: Color>() -> [f32; 3] {
        channel_scales::<C>()
    }
    #[inline(always)]
    fn vertex<C: Color>(&self, v: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        let mut out = [0.0; MAX_VARYINGS];
        out[..3].copy_from_slice(&v.lit);
        out
    }
    #[inline(always)]
    fn shade<C: Color, S: Interp>(&self, _: &Self::Uniforms<S>, _: C, v: &[S; MAX_VARYINGS], _: C) -> C {
        shade_rgb(v)
    }
}

/// Gouraud shading under white light: one light level per vertex (the
/// lights' green channel, which for white or gray lights is each of
/// them), interpolated, and the material color times it per pixel. A
/// single-colored mesh lit by white light looks as under [`Gouraud`]
/// (each channel within one level: the level is rounded to 8 bits first)
/// with one interpolated value instead of three: two planes a triangle
/// instead of four with the depth's. A mesh's vertex colors are not used.
#[derive(Clone, Copy, Debug, Default)]
pub struct MonoGouraud;

/// [`MonoGouraud`]'s product of a level and a channel of depth `max` is
/// `(level m + 2^23) >> 24` with `m = channel max MONO_SCALE`: `2^24 /
/// 255^2` is 258.01, so this is `level channel max / 255^2` rounded (the
/// product within 0.01% before rounding), at most `max`, and below 2^32
/// for every depth up to 255.
const MONO_SCALE: u32 = 258;

/// [`MonoGouraud`]'s channel of depth `max` for a material channel and a
/// light level (both 0 to 255).
#[inline(always)]
fn mono_channel(level: u32, channel: u8, max: u8) -> u8 {
    ((level * (channel as u32 * max as u32 * MONO_SCALE) + (1 << 23)) >> 24) as u8
}

impl Effect for MonoGouraud {
    /// The material color (its products are taken out of the span loop).
    type Uniforms<S: Interp> = Rgb888;
    #[inline(always)]
    fn uniforms<S: Interp>(&self, _: &Lighting, color: Rgb888) -> Rgb888 {
        color
    }
    const VARYINGS: usize = 1;
    const LIT_VERTICES: bool = true;
    const LIT_COLOR: bool = true;
    const LIT_WHITE: bool = true;
    const LIT_CHANNELS: [bool; 3] = [false, true, false];
    const NAME: &'static str = "gouraud-mono";
    fn ranges<C: Color>() -> [(f32, f32); MAX_VARYINGS] {
        let mut r = [(0.0, 0.0); MAX_VARYINGS];
        r[0] = LIGHT_RANGE;
        r
    }
    #[inline(always)]
    fn vertex<C: Color>(&self, v: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        let mut out = [0.0; MAX_VARYINGS];
        out[0] = v.lit[1];
        out
    }
    #[inline(always)]
    fn shade<C: Color, S: Interp>(&self, color: &Rgb888, _: C, v: &[S; MAX_VARYINGS], _: C) -> C {
        // (Each channel's factor is the same for every pixel: the compiler
        // takes it out of the span loop.)
        // A byte, as the products below assume (on the M0+ the mask also
        // measured quicker: torus.babylon-mono 0.3%).
        let level = v[0].channel() as u8 as u32;
        C::from_channels(
            mono_channel(level, color.r(), C::MAX_R),
            mono_channel(level, color.g(), C::MAX_G),
            mono_channel(level, color.b(), C::MAX_B),
        )
    }
}

/// Unlit vertex colors, interpolated (the material color where the mesh
/// has no colors).
#[derive(Clone, Copy, Debug, Default)]
pub struct VertexColor;

impl Effect for VertexColor {
    type Uniforms<S: Interp> = ();
    fn uniforms<S: Interp>(&self, _: &Lighting, _: Rgb888) {}
    const VARYINGS: usize = 3;
    const LIT_VERTICES: bool = false;
    const NAME: &'static str = "unlit";
    #[inline(always)]
    fn vertex<C: Color>(&self, v: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        rgb_varyings::<C>([v.color.r() as f32, v.color.g() as f32, v.color.b() as f32])
    }
    #[inline(always)]
    fn shade<C: Color, S: Interp>(&self, _: &Self::Uniforms<S>, _: C, v: &[S; MAX_VARYINGS], _: C) -> C {
        shade_rgb(v)
    }
}

/// A diagnostic effect: adds one to every channel of the pixel per
/// fragment (saturating at the channel's maximum), so that the image counts how many
/// fragments covered each pixel. Use it with [`DepthOff`](crate::material::DepthOff)
/// and an 8-bit-per-channel color type to count fragments before the depth
/// test, or to find overdraw.
#[derive(Clone, Copy, Debug, Default)]
pub struct FragmentCount;

impl Effect for FragmentCount {
    type Uniforms<S: Interp> = ();
    fn uniforms<S: Interp>(&self, _: &Lighting, _: Rgb888) {}
    const VARYINGS: usize = 0;
    const LIT_VERTICES: bool = false;
    const NAME: &'static str = "count";
    #[inline(always)]
    fn vertex<C: Color>(&self, _: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        [0.0; MAX_VARYINGS]
    }
    #[inline(always)]
    fn shade<C: Color, S: Interp>(&self, _: &Self::Uniforms<S>, _: C, _: &[S; MAX_VARYINGS], dst: C) -> C {
        let up = |v: u8, max: u8| if v < max { v + 1 } else { max };
        C::from_channels(up(dst.r(), C::MAX_R), up(dst.g(), C::MAX_G), up(dst.b(), C::MAX_B))
    }
}

/// A channel of `from_max` levels rescaled to `to_max` levels, rounded
/// (free when the depths match, as for an RGB565 texture on an RGB565
/// display).
#[inline(always)]
fn rescale(v: u32, from_max: u32, to_max: u8) -> u8 {
    if from_max == to_max as u32 {
        v as u8
    } else {
        ((v * to_max as u32 + from_max / 2) / from_max) as u8
    }
}

/// A texture modulated by the lit material color: Gouraud lighting (N·L
/// per vertex, interpolated) times the texel, which `F` filters and `W`
/// wraps, written over the strip by `B` ([`Opaque`] by default; with
/// [`AlphaBlend`](crate::blend::AlphaBlend) the texel's alpha times the
/// material's opacity, untouched by the lighting, mixes it with what is
/// there). `L` says how much of the lighting is interpolated: the lit
/// color's three channels ([`ColorLight`], the default) or one level for
/// all three ([`GrayLight`]: the same image under gray light, for two
/// interpolated values fewer). Texture coordinates are interpolated in
/// texel units. Use it with
/// [`PerSpan<32>`](crate::material::PerSpan) (or
/// [`PerPixel`](crate::material::PerPixel)) so the texture does not swim:
/// the accuracy study (`docs/accuracy.md`) measured correction every 32
/// pixels as close to the exact image as every pixel, for about half the
/// instructions.
///
/// Varyings: `u · width`, `v · height`, then the lit color's red, green
/// and blue in `[0, 256)` (5 in all, so the renderer needs `V >= 5`), or
/// with [`GrayLight`] its green alone (3 in all).
pub struct Textured<'a, F = Nearest, W = Repeat, B = Opaque, L = ColorLight> {
    /// The texture.
    pub texture: Texture<'a>,
    /// Opacity of the material, 0 to 255, multiplying the texels' alpha
    /// (only read when `B` blends).
    pub opacity: u8,
    _modes: core::marker::PhantomData<(F, W, B, L)>,
}

/// How many lit channels [`Textured`] interpolates: [`ColorLight`] or
/// [`GrayLight`]. Sealed: `Textured` reads its varyings by these two
/// layouts (three channels in order, or one level).
///
/// ```compile_fail
/// // Another model does not compile: the trait is sealed.
/// struct BlueLight;
/// impl soft3d::effect::LightModel for BlueLight {
///     const CHANNELS: &'static [usize] = &[2];
/// }
/// ```
pub trait LightModel: sealed::Sealed {
    /// The channels of [`VertexInput::lit`] interpolated (0 red, 1 green,
    /// 2 blue); with one, it lights all three.
    const CHANNELS: &'static [usize];
}

mod sealed {
    /// Implemented by the light models only.
    pub trait Sealed {}
    impl Sealed for super::ColorLight {}
    impl Sealed for super::GrayLight {}
}

/// Channel numbers (0 red, 1 green, 2 blue) as flags.
const fn channel_set(channels: &[usize]) -> [bool; 3] {
    let mut set = [false; 3];
    let mut k = 0;
    while k < channels.len() {
        if channels[k] < 3 {
            set[channels[k]] = true;
        }
        k += 1;
    }
    set
}

/// [`Textured`] interpolates the lit color's red, green and blue: colored
/// lights and materials are lit exactly.
#[derive(Clone, Copy, Debug, Default)]
pub struct ColorLight;

impl LightModel for ColorLight {
    const CHANNELS: &'static [usize] = &[0, 1, 2];
}

/// [`Textured`] interpolates one light level, the lit color's green
/// channel, and scales all three texel channels by it: under gray (white
/// included) lights on a gray (or white) material, where the three lit
/// channels are equal, exactly the image of [`ColorLight`], for two planes
/// a triangle and two interpolated values a pixel fewer. Colored lights or
/// materials give their green channel's brightness in gray.
#[derive(Clone, Copy, Debug, Default)]
pub struct GrayLight;

impl LightModel for GrayLight {
    const CHANNELS: &'static [usize] = &[1];
}

// Not derived: the marker types need not be `Copy` themselves.
impl<F, W, B, L> Clone for Textured<'_, F, W, B, L> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<F, W, B, L> Copy for Textured<'_, F, W, B, L> {}
impl<F, W, B, L> core::fmt::Debug for Textured<'_, F, W, B, L> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Textured").field("texture", &self.texture).field("opacity", &self.opacity).finish()
    }
}

impl<'a, F: Filter, W: Wrap, B: Blend, L: LightModel> Textured<'a, F, W, B, L> {
    /// The effect for `texture`, fully opaque material.
    pub const fn new(texture: Texture<'a>) -> Self {
        Self { texture, opacity: 255, _modes: core::marker::PhantomData }
    }

    /// The same with the material's opacity (0 to 255; Babylon's `alpha`
    /// times 255).
    pub const fn with_opacity(self, opacity: u8) -> Self {
        Self { opacity, ..self }
    }
}

/// Range of a texture coordinate in texel units: what 16.16 fixed point
/// holds, with room for a span's steps.
const TEXEL_RANGE: (f32, f32) = (-30_000.0, 30_000.0);
/// Range of an interpolated light level of 0 to 255 (`channel_range(255)`):
/// its integer part scales a texel by `(l + 1) / 256`, or a material
/// channel ([`MonoGouraud`]).
const LIGHT_RANGE: (f32, f32) = (0.0, 255.996);
const _: () = assert!(LIGHT_RANGE.0 == channel_range(255).0 && LIGHT_RANGE.1 == channel_range(255).1);

impl<F: Filter, W: Wrap, B: Blend, L: LightModel> Effect for Textured<'_, F, W, B, L> {
    type Uniforms<S: Interp> = ();
    fn uniforms<S: Interp>(&self, _: &Lighting, _: Rgb888) {}
    const VARYINGS: usize = 2 + L::CHANNELS.len();
    const LIT_VERTICES: bool = true;
    const LIT_COLOR: bool = true;
    const LIT_CHANNELS: [bool; 3] = channel_set(L::CHANNELS);
    const NAME: &'static str = if L::CHANNELS.len() == 1 { "textured-gray" } else { "textured" };

    fn ranges<C: Color>() -> [(f32, f32); MAX_VARYINGS] {
        let mut r = [(0.0, 0.0); MAX_VARYINGS];
        r[..2].copy_from_slice(&[TEXEL_RANGE, TEXEL_RANGE]);
        r[2..Self::VARYINGS].fill(LIGHT_RANGE);
        r
    }

    fn periods(&self) -> [f32; MAX_VARYINGS] {
        let mut p = [0.0; MAX_VARYINGS];
        if W::PERIODIC {
            p[0] = self.texture.width() as f32;
            p[1] = self.texture.height() as f32;
        }
        p
    }

    #[inline(always)]
    fn vertex<C: Color>(&self, v: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        // The light carries half a level, like the color effects'
        // channels: truncation then rounds, and the values keep half a
        // level of margin inside their range (values on its bounds would
        // send every triangle whose rounded planes overshoot them to the
        // careful path).
        let mut out = [0.0; MAX_VARYINGS];
        out[0] = v.uv.x * self.texture.width() as f32;
        out[1] = v.uv.y * self.texture.height() as f32;
        for (o, &c) in out[2..].iter_mut().zip(L::CHANNELS) {
            *o = v.lit[c];
        }
        out
    }

    #[inline(always)]
    fn samples(&self) -> bool {
        !self.texture.texels().is_empty()
    }

    #[inline(always)]
    fn shade<C: Color, S: Interp>(&self, _: &Self::Uniforms<S>, _: C, v: &[S; MAX_VARYINGS], dst: C) -> C {
        let t = self.texture.sample::<F, W>(v[0].to_bits16(), v[1].to_bits16(), B::ALPHA);
        // Channel `c`'s light: its own varying, or the one level. The
        // planes keep a level below 256, so nothing wraps; the wrapping
        // operations make a level out of range a wrong color rather than
        // a panic, without a mask to a byte at every pixel.
        let level = |c: usize| v[2 + if L::CHANNELS.len() == 1 { 0 } else { c }].channel().wrapping_add(1);
        let light = |t: u32, c: usize| t.wrapping_mul(level(c)) >> 8;
        let alpha = if B::ALPHA { scale_alpha(t.a, self.opacity) } else { 255 };
        B::blend(
            rescale(light(t.r, 0), 31, C::MAX_R),
            rescale(light(t.g, 1), 63, C::MAX_G),
            rescale(light(t.b, 2), 31, C::MAX_B),
            alpha,
            dst,
        )
    }
}

/// Per-pixel (Phong) lighting: the normal and the position are
/// interpolated and every pixel is lit, so highlights and the edge of the
/// lit side stay sharp on coarse meshes. With `SPECULAR`
/// ([`BlinnPhong`]) it adds Blinn-Phong highlights of the given color and
/// power. The material color is lit; vertex colors are not used.
///
/// Varyings: normal and position in the lighting space (6). In fixed point
/// the position must stay within about ±180 units of the lights and the
/// eye (squared distances must fit 16.16).
#[derive(Clone, Copy, Debug)]
pub struct Phong<const SPECULAR: bool = false> {
    /// Specular color (with `SPECULAR`).
    pub specular: Rgb888,
    /// Specular power, rounded to an integer from 1 to 256.
    pub power: f32,
}

/// [`Phong`] with Blinn-Phong specular highlights.
pub type BlinnPhong = Phong<true>;

impl Phong<false> {
    /// Diffuse per-pixel lighting.
    pub const fn new() -> Self {
        Self { specular: Rgb888::new(0, 0, 0), power: 1.0 }
    }
}

impl Default for Phong<false> {
    fn default() -> Self {
        Self::new()
    }
}

impl Phong<true> {
    /// Diffuse per-pixel lighting plus highlights of `specular` color and
    /// `power` (Babylon's `specularColor` and `specularPower`).
    pub const fn with_specular(specular: Rgb888, power: f32) -> Self {
        Self { specular, power }
    }
}

/// The lights of a draw call in the span loop's scalar.
#[derive(Clone, Copy, Debug)]
pub struct PhongUniforms<S> {
    color: [S; 3],
    ambient: [S; 3],
    sun: Option<([S; 3], [S; 3])>,
    point: Option<([S; 3], [S; 3])>,
    eye: [S; 3],
    specular: [S; 3],
    power: u32,
}

fn vec_s<S: Interp>(v: Vec3) -> [S; 3] {
    [S::from_f32(v.x), S::from_f32(v.y), S::from_f32(v.z)]
}

#[inline(always)]
fn dot_s<S: Interp>(a: &[S; 3], b: &[S; 3]) -> S {
    a[0].mul(b[0]).add(a[1].mul(b[1])).add(a[2].mul(b[2]))
}

#[inline(always)]
fn normalize_s<S: Interp>(v: [S; 3]) -> [S; 3] {
    let k = dot_s(&v, &v).rsqrt();
    [v[0].mul(k), v[1].mul(k), v[2].mul(k)]
}

/// `x^n` by squaring.
#[inline(always)]
fn powi_s<S: Interp>(mut x: S, mut n: u32) -> S {
    let mut r = S::from_f32(1.0);
    while n > 0 {
        if n & 1 == 1 {
            r = r.mul(x);
        }
        x = x.mul(x);
        n >>= 1;
    }
    r
}

impl<const SPECULAR: bool> Effect for Phong<SPECULAR> {
    const VARYINGS: usize = 6;
    const LIT_VERTICES: bool = true;
    const NAME: &'static str = if SPECULAR { "blinn-phong" } else { "phong" };
    type Uniforms<S: Interp> = PhongUniforms<S>;

    fn uniforms<S: Interp>(&self, lights: &Lighting, color: Rgb888) -> PhongUniforms<S> {
        let unit = |c: Rgb888| Vec3::new(c.r() as f32, c.g() as f32, c.b() as f32) * (1.0 / 255.0);
        PhongUniforms {
            color: vec_s(unit(color)),
            ambient: vec_s(lights.ambient),
            sun: lights.sun.map(|(l, c)| (vec_s(l), vec_s(c))),
            point: lights.point.map(|p| (vec_s(p.position), vec_s(p.color))),
            eye: vec_s(lights.eye),
            specular: vec_s(unit(self.specular)),
            power: if self.power >= 1.0 { (self.power + 0.5).min(256.0) as u32 } else { 1 },
        }
    }

    fn ranges<C: Color>() -> [(f32, f32); MAX_VARYINGS] {
        let mut r = [(0.0, 0.0); MAX_VARYINGS];
        r[..6].copy_from_slice(&[(-1.01, 1.01), (-1.01, 1.01), (-1.01, 1.01), TEXEL_RANGE, TEXEL_RANGE, TEXEL_RANGE]);
        r
    }

    #[inline(always)]
    fn vertex<C: Color>(&self, v: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        let n = v.normal.normalize_or_zero();
        let mut out = [0.0; MAX_VARYINGS];
        out[..6].copy_from_slice(&[n.x, n.y, n.z, v.position.x, v.position.y, v.position.z]);
        out
    }

    #[inline(always)]
    fn shade<C: Color, S: Interp>(&self, u: &PhongUniforms<S>, _: C, v: &[S; MAX_VARYINGS], _: C) -> C {
        let zero = S::default();
        let n = normalize_s([v[0], v[1], v[2]]);
        let p = [v[3], v[4], v[5]];
        let mut light = u.ambient;
        let mut shine = [zero; 3];
        let view = if SPECULAR { normalize_s([u.eye[0].sub(p[0]), u.eye[1].sub(p[1]), u.eye[2].sub(p[2])]) } else { [zero; 3] };
        let mut add = |l: [S; 3], c: &[S; 3]| {
            let d = dot_s(&n, &l);
            if d > zero {
                for k in 0..3 {
                    light[k] = light[k].add(c[k].mul(d));
                }
                if SPECULAR {
                    let h = normalize_s([l[0].add(view[0]), l[1].add(view[1]), l[2].add(view[2])]);
                    let s = powi_s(dot_s(&n, &h).clamp_between(zero, S::from_f32(1.0)), u.power);
                    for k in 0..3 {
                        shine[k] = shine[k].add(c[k].mul(s));
                    }
                }
            }
        };
        if let Some((l, c)) = &u.sun {
            add(*l, c);
        }
        if let Some((lp, c)) = &u.point {
            add(normalize_s([lp[0].sub(p[0]), lp[1].sub(p[1]), lp[2].sub(p[2])]), c);
        }
        let one = S::from_f32(1.0);
        let channel = |k: usize, max: u8| {
            let lit = u.color[k].mul(light[k].clamp_between(zero, one)).add(u.specular[k].mul(shine[k]));
            lit.clamp_between(zero, one).mul(S::from_f32(max as f32)).add(S::from_f32(0.5)).channel()
        };
        pixel::<C, S>(channel(0, C::MAX_R), channel(1, C::MAX_G), channel(2, C::MAX_B))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::pixelcolor::{Bgr555, Bgr565, Bgr666, Bgr888, Rgb555, Rgb565, Rgb666};

    /// Every channel value in range, each channel on its own and with the
    /// others at their largest: the unmasked constructor puts each where
    /// embedded-graphics does.
    fn in_range_channels_build_what_masked_ones_do<C: Color + core::fmt::Debug>() {
        let (mr, mg, mb) = (C::MAX_R, C::MAX_G, C::MAX_B);
        for v in 0..=255u8 {
            let cases =
                [(v.min(mr), 0, 0), (0, v.min(mg), 0), (0, 0, v.min(mb)), (v.min(mr), mg, mb), (mr, v.min(mg), mb), (mr, mg, v.min(mb))];
            for (r, g, b) in cases {
                let built = C::from_channels_in_range(r.into(), g.into(), b.into());
                assert_eq!(built, C::from_channels(r, g, b), "{r},{g},{b}");
                assert_eq!((built.r(), built.g(), built.b()), (r, g, b));
            }
        }
    }

    #[test]
    fn every_color_type_places_its_channels() {
        in_range_channels_build_what_masked_ones_do::<Rgb565>();
        in_range_channels_build_what_masked_ones_do::<Bgr565>();
        in_range_channels_build_what_masked_ones_do::<Rgb555>();
        in_range_channels_build_what_masked_ones_do::<Bgr555>();
        in_range_channels_build_what_masked_ones_do::<Rgb666>();
        in_range_channels_build_what_masked_ones_do::<Bgr666>();
        in_range_channels_build_what_masked_ones_do::<Rgb888>();
        in_range_channels_build_what_masked_ones_do::<Bgr888>();
    }

    #[test]
    fn mono_channels_are_the_rounded_product_within_the_depth() {
        for max in [31u8, 63, 255] {
            for level in 0..=255u32 {
                for c in 0..=255u8 {
                    let got = mono_channel(level, c, max);
                    let exact = level as f64 * c as f64 * max as f64 / (255.0 * 255.0);
                    assert!(got <= max, "level {level}, channel {c}, depth {max}: {got}");
                    // Rounded, but for the product's 0.005% (at most 0.013 of a level).
                    assert!((got as f64 - exact).abs() <= 0.513, "level {level}, channel {c}, depth {max}: {got} for {exact}");
                }
            }
        }
    }
}
