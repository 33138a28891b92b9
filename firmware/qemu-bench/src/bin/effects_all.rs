//! "All effects": the general firmware. One renderer sized for the largest
//! effect (`V = 6`, Phong's normal and position) and a span loop for every
//! effect linked in. It first renders the effects scene flat, exactly as
//! `effects_flat` does (and flat without depth, as `effects_flat_nodepth`
//! does), then the same scene with every other effect, each frame timed,
//! so that the code of every effect is really in the binary.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use soft3d::blend::{AlphaBlend, Opaque};
use soft3d::effect::{BlinnPhong, Flat, FragmentCount, Gouraud, GrayLight, MonoGouraud, Phong, Textured, VertexColor};
use soft3d::material::{Affine, DepthLess, DepthOff, PerPixel, PerSpan};
use soft3d::scenes::study::CHECKER;
use soft3d::texture::{Bilinear, Clamp, Nearest, Repeat};

#[path = "effects/common.rs"]
mod common;

/// Every effect of the crate, in the combinations a general firmware would
/// offer: lit and unlit, per-vertex and per-pixel, textured opaque and
/// blended.
#[entry]
fn main() -> ! {
    let mut timer = common::start_timer();
    let renderer = common::static_renderer!(6);
    common::report_renderer::<6>("all");
    let t = &mut timer;
    // The frames the flat-only firmwares render, first, from the same
    // renderer state.
    let flat = common::materials::<Flat, Affine, DepthLess>(Flat);
    common::measure(t, renderer, "all", "flat", |frame| common::draw_scene(frame, &flat));
    let flat_nodepth = common::materials::<Flat, Affine, DepthOff>(Flat);
    common::measure(t, renderer, "all", "flat-nodepth", |frame| common::draw_scene(frame, &flat_nodepth));
    // The other effects: their code must be present, their cost is shown.
    let gouraud = common::materials::<Gouraud, Affine, DepthLess>(Gouraud);
    common::measure(t, renderer, "all", "gouraud", |frame| common::draw_scene(frame, &gouraud));
    let mono = common::materials::<MonoGouraud, Affine, DepthLess>(MonoGouraud);
    common::measure(t, renderer, "all", "gouraud-mono", |frame| common::draw_scene(frame, &mono));
    let unlit = common::materials::<VertexColor, Affine, DepthLess>(VertexColor);
    common::measure(t, renderer, "all", "vertex-color", |frame| common::draw_scene(frame, &unlit));
    let phong = common::materials::<Phong, Affine, DepthLess>(Phong::new());
    common::measure(t, renderer, "all", "phong", |frame| common::draw_scene(frame, &phong));
    let specular = BlinnPhong::with_specular(embedded_graphics::pixelcolor::Rgb888::new(255, 255, 255), 24.0);
    let blinn = common::materials::<BlinnPhong, Affine, DepthLess>(specular);
    common::measure(t, renderer, "all", "blinn-phong", |frame| common::draw_scene(frame, &blinn));
    let textured = common::materials::<Textured<'static, Nearest, Repeat>, PerSpan<32>, DepthLess>(Textured::new(CHECKER));
    common::measure(t, renderer, "all", "textured", |frame| common::draw_scene(frame, &textured));
    let gray = common::materials::<Textured<'static, Nearest, Repeat, Opaque, GrayLight>, PerSpan<32>, DepthLess>(Textured::new(CHECKER));
    common::measure(t, renderer, "all", "textured-gray", |frame| common::draw_scene(frame, &gray));
    let blended = Textured::<'static, Bilinear, Clamp, AlphaBlend>::new(CHECKER).with_opacity(160);
    let blended = common::materials::<_, PerPixel, DepthLess>(blended);
    common::measure(t, renderer, "all", "textured-blend", |frame| common::draw_scene(frame, &blended));
    let count = common::materials::<FragmentCount, Affine, DepthOff>(FragmentCount);
    common::measure(t, renderer, "all", "fragment-count", |frame| common::draw_scene(frame, &count));
    common::exit()
}
