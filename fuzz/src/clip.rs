//! The `clip` case: a small mesh with arbitrary positions, normals and
//! colors, arbitrary model and view-projection matrices (NaN, infinities,
//! w = 0, w < 0, vertices on and behind the near plane included) and
//! arbitrary lights, drawn through the mesh path with `Flat`, `Gouraud`,
//! `VertexColor` and `Phong`, depth test on, into an `Rgb565` frame.
//!
//! Input layout (missing bytes read as zero):
//!
//! ```text
//! byte 0      bit 0: f32 (else fixed); (>> 1) % 3: 0, 4, 8 sub-pixel bits;
//!             bit 3: Cull::Back; (>> 4) % 3: Affine, PerPixel, PerSpan<4>;
//!             bit 6: lit by decoded lights (else unlit)
//! bytes 1-3   width 1..=48, height 1..=40, strip 1..=height
//! bytes 4, 5  vertex and triangle capacity: below 16 that many, else ample
//! byte 6      which of the two model matrices each draw call uses (bits 0-3)
//! then        view-projection, two model matrices, lights, and the mesh:
//!             1-8 vertices (position, normal, color), 0-8 triangles
//! ```
//!
//! Invariants: no panic; every pixel written once, inside the frame
//! ([`CheckedTarget`]); a refused draw call leaves the statistics as they
//! were, and with ample capacity none is refused; the statistics add up
//! (each draw call is counted once as drawn, culled or invalid; each
//! triangle that needed no clipping has exactly one outcome, a clipped one
//! at most 7); nothing drawn if nothing was queued; and every pixel is
//! the background or a color the effects can make from these inputs: with
//! no lights, within the per-channel range of the vertex and material
//! colors (one level of rounding either way); lit, at most their maximum,
//! since diffuse light is clamped to 1 (`Phong` without specular).

use crate::check::CheckedTarget;
use crate::input::Bytes;
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use soft3d::effect::{Flat, Gouraud, Phong, VertexColor};
use soft3d::material::{Affine, PerPixel, PerSpan, Perspective};
use soft3d::math::{Fixed, Mat4, Vec3};
use soft3d::mesh::Mesh;
use soft3d::{Camera, Cull, DirectionalLight, DrawError, FrameStats, HostRenderer, Lights, Material, PointLight, Precision, Settings};

/// One `f32`: mostly scene-sized, sometimes anything at all.
fn float(b: &mut Bytes) -> f32 {
    let tag = b.u8();
    match tag % 8 {
        0 => b.i8() as f32 / 8.0,
        1 => b.i16() as f32 / 256.0,
        2 => b.i16() as f32 / 4.0,
        3 => f32::from_bits(b.u32()),
        4 => [
            0.0,
            -0.0,
            1.0,
            -1.0,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MAX,
            f32::MIN,
            1e-7,
            -1e-7,
            1e30,
            -1e30,
            f32::MIN_POSITIVE,
            1e-40, // subnormal
            0.1,   // the default near plane
        ][(b.u8() % 16) as usize],
        _ => b.i8() as f32 / 32.0,
    }
}

fn vec3(b: &mut Bytes) -> Vec3 {
    Vec3::new(float(b), float(b), float(b))
}

fn matrix(b: &mut Bytes) -> Mat4 {
    let mut m = Mat4::IDENTITY;
    for row in &mut m.m {
        for v in row {
            *v = float(b);
        }
    }
    m
}

fn model(b: &mut Bytes) -> Mat4 {
    match b.u8() % 4 {
        0 => Mat4::IDENTITY,
        1 => matrix(b),
        2 => Mat4::translation(vec3(b)) * Mat4::rotation_y(float(b)) * Mat4::scaling(vec3(b)),
        _ => Mat4::translation(vec3(b)) * Mat4::rotation_x(float(b)),
    }
}

fn color(b: &mut Bytes) -> Rgb888 {
    Rgb888::new(b.u8(), b.u8(), b.u8())
}

/// A decoded case.
#[derive(Clone, Debug)]
pub struct Case {
    pub float: bool,
    pub bits: u32,
    pub cull: Cull,
    pub perspective: u8,
    pub lit: bool,
    pub width: usize,
    pub height: usize,
    pub strip: usize,
    /// Capacities; `None`: ample.
    pub vertex_capacity: Option<usize>,
    pub triangle_capacity: Option<usize>,
    pub model_choice: u8,
    pub view_proj: Mat4,
    pub models: [Mat4; 2],
    pub lights: Lights,
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
    pub colors: Vec<Rgb888>,
    pub indices: Vec<u16>,
}

pub fn decode(data: &[u8]) -> Case {
    let mut b = Bytes::new(data);
    let mode = b.u8();
    let width = 1 + (b.u8() % 48) as usize;
    let height = 1 + (b.u8() % 40) as usize;
    let strip = 1 + (b.u8() as usize % height);
    let capacity = |v: u8| (v < 16).then_some(v as usize);
    let (vertex_capacity, triangle_capacity) = (capacity(b.u8()), capacity(b.u8()));
    let model_choice = b.u8();
    let view_proj = match b.u8() % 4 {
        0 => Mat4::IDENTITY, // mesh positions are clip space (w = 1)
        1 => matrix(&mut b),
        _ => {
            // Through the camera, whose projection repairs bad planes.
            let camera = Camera {
                position: vec3(&mut b),
                target: vec3(&mut b),
                up: vec3(&mut b),
                fov_y: float(&mut b),
                near: float(&mut b),
                far: float(&mut b),
            };
            camera.projection(width as f32 / height as f32) * camera.view()
        }
    };
    let models = [model(&mut b), model(&mut b)];
    let lit = mode & 64 != 0;
    let lights = if lit {
        let ambient = vec3(&mut b);
        let flags = b.u8();
        let point = (flags & 1 != 0).then(|| PointLight { position: vec3(&mut b), color: vec3(&mut b) });
        let directional = (flags & 2 != 0).then(|| DirectionalLight { direction: vec3(&mut b), color: vec3(&mut b) });
        Lights { ambient, point, directional }
    } else {
        Lights::UNLIT
    };
    let n = 1 + (b.u8() % 8) as usize;
    let positions: Vec<Vec3> = (0..n).map(|_| vec3(&mut b)).collect();
    let normals: Vec<Vec3> = (0..n).map(|_| vec3(&mut b)).collect();
    let colors: Vec<Rgb888> = (0..n).map(|_| color(&mut b)).collect();
    let triangles = (b.u8() % 9) as usize;
    let indices: Vec<u16> = (0..3 * triangles).map(|_| (b.u8() as usize % n) as u16).collect();
    Case {
        float: mode & 1 == 1,
        bits: [0, 4, 8][((mode >> 1) % 3) as usize],
        cull: if mode & 8 != 0 { Cull::Back } else { Cull::None },
        perspective: (mode >> 4) % 3,
        lit,
        width,
        height,
        strip,
        vertex_capacity,
        triangle_capacity,
        model_choice,
        view_proj,
        models,
        lights,
        positions,
        normals,
        colors,
        indices,
    }
}

/// Triangle outcomes that [`FrameStats`] counts.
fn outcomes(s: &FrameStats) -> u32 {
    s.invalid + s.off_screen + s.degenerate + s.back_facing + s.queued
}

/// Checks the statistics of one accepted draw call of `vertices` vertices
/// and `triangles` triangles, from `a` (before) to `b` (after).
fn check_draw(a: &FrameStats, b: &FrameStats, vertices: u32, triangles: u32, matrices: (bool, bool), cull: Cull) {
    let unchanged_but = |field: &str, x: FrameStats| assert_eq!(x, *b, "only {field} changes: {a:?} -> {b:?}");
    let (model_finite, view_proj_finite) = matrices;
    if !model_finite {
        return unchanged_but("meshes_invalid", FrameStats { meshes_invalid: a.meshes_invalid + 1, ..*a });
    }
    if !view_proj_finite && b.meshes_invalid != a.meshes_invalid {
        // A non-finite view-projection skips the mesh whole, counted as
        // invalid or (by the bounding-sphere test) culled.
        return unchanged_but("meshes_invalid", FrameStats { meshes_invalid: a.meshes_invalid + 1, ..*a });
    }
    if b.meshes_culled != a.meshes_culled {
        return unchanged_but("meshes_culled", FrameStats { meshes_culled: a.meshes_culled + 1, ..*a });
    }
    assert_eq!(b.meshes_invalid, a.meshes_invalid, "{a:?} -> {b:?}");
    assert_eq!(b.draw_calls, a.draw_calls + 1, "{a:?} -> {b:?}");
    assert_eq!((b.vertices - a.vertices, b.triangles - a.triangles), (vertices, triangles), "{a:?} -> {b:?}");
    let clipped = b.clipped - a.clipped;
    let extra = (outcomes(b) - outcomes(a)).checked_sub(triangles - clipped);
    assert!(clipped <= triangles && extra.is_some_and(|e| e <= 7 * clipped), "outcomes do not add up: {a:?} -> {b:?}");
    if cull == Cull::None {
        assert_eq!(b.back_facing, a.back_facing);
    }
}

/// The per-channel range (in `Rgb565` levels) pixels may take.
fn channel_bounds(case: &Case) -> [(u8, u8); 3] {
    let level = |c: u8, max: u8| (c as f32 * max as f32 / 255.0).round() as u8;
    let maxes = [Rgb565::MAX_R, Rgb565::MAX_G, Rgb565::MAX_B];
    let mut out = [(u8::MAX, 0); 3];
    for c in &case.colors {
        for (k, ch) in [c.r(), c.g(), c.b()].into_iter().enumerate() {
            let l = level(ch, maxes[k]);
            out[k] = (out[k].0.min(l), out[k].1.max(l));
        }
    }
    for (k, o) in out.iter_mut().enumerate() {
        // One level of rounding either way.
        *o = (if case.lit { 0 } else { o.0.saturating_sub(1) }, (o.1 + 1).min(maxes[k]));
    }
    out
}

const BACKGROUND: Rgb565 = Rgb565::new(31, 0, 31);

fn render<S: Settings, P: Perspective>(case: &Case) {
    let mesh = Mesh::new(&case.positions, &case.normals, &case.indices)
        .and_then(|m| m.with_colors(&case.colors))
        .expect("indices are reduced modulo the vertex count");
    let (nv, nt) = (mesh.vertex_count(), mesh.triangle_count());
    // The material color is the first vertex's, so it is inside the range too.
    let color = case.colors[0];
    let flat = Material::new(Flat).with_color(color).with_cull(case.cull).with_perspective::<P>();
    let gouraud = Material::new(Gouraud).with_color(color).with_cull(case.cull).with_perspective::<P>();
    let unlit = Material::new(VertexColor).with_color(color).with_cull(case.cull).with_perspective::<P>();
    let phong = Material::new(Phong::new()).with_color(color).with_cull(case.cull).with_perspective::<P>();
    // Per draw call: every vertex, plus up to 9 new vertices and 7 pieces
    // per clipped triangle.
    let ample_v = 4 * (nv + 9 * nt) + 1;
    let ample_t = 4 * 7 * nt + 1;
    let mut r: HostRenderer<Rgb565, 6, S> = HostRenderer::new(
        case.width,
        case.height,
        case.strip,
        case.vertex_capacity.unwrap_or(ample_v),
        case.triangle_capacity.unwrap_or(ample_t),
        Rgb565::BLACK,
    )
    .expect("valid sizes");
    let mut frame = r.begin_frame_with(case.view_proj, &case.lights, BACKGROUND);
    let ample = case.vertex_capacity.is_none() && case.triangle_capacity.is_none();
    for k in 0..4 {
        let model = &case.models[(case.model_choice >> k) as usize & 1];
        let before = frame.stats();
        let result: Result<(), DrawError> = match k {
            0 => frame.draw(&mesh, model, &flat),
            1 => frame.draw(&mesh, model, &gouraud),
            2 => frame.draw(&mesh, model, &unlit),
            _ => frame.draw(&mesh, model, &phong),
        };
        let after = frame.stats();
        match result {
            Ok(()) => check_draw(&before, &after, nv as u32, nt as u32, (model.is_finite(), case.view_proj.is_finite()), case.cull),
            Err(e) => {
                assert!(!ample, "refused with ample capacity: {e:?}");
                assert_eq!(before, after, "a refused draw call ({e:?}) leaves the frame as it was");
            }
        }
    }
    let recorded = frame.stats();
    let mut target = CheckedTarget::new(case.width, case.height);
    let Ok(stats) = frame.finish(&mut target);
    assert_eq!(stats, recorded, "finish returns the recorded statistics");
    let pixels = target.finished();
    if stats.queued == 0 {
        assert!(pixels.iter().all(|&c| c == BACKGROUND), "nothing queued, yet something drawn");
    }
    let bounds = channel_bounds(case);
    for (i, c) in pixels.iter().enumerate() {
        let ok = [c.r(), c.g(), c.b()].iter().zip(&bounds).all(|(v, (lo, hi))| (lo..=hi).contains(&v));
        assert!(*c == BACKGROUND || ok, "pixel ({}, {}) is {c:?}, outside the channel ranges {bounds:?}", i % case.width, i / case.width);
    }
}

fn render_mode<P: Perspective>(case: &Case) {
    match (case.bits, case.float) {
        (0, false) => render::<Precision<Fixed, 0>, P>(case),
        (0, true) => render::<Precision<f32, 0>, P>(case),
        (4, false) => render::<Precision<Fixed, 4>, P>(case),
        (4, true) => render::<Precision<f32, 4>, P>(case),
        (8, false) => render::<Precision<Fixed, 8>, P>(case),
        (8, true) => render::<Precision<f32, 8>, P>(case),
        _ => unreachable!("bits are 0, 4 or 8"),
    }
}

/// Decodes `data`, draws it and checks every invariant (panics on a
/// violation).
pub fn run(data: &[u8]) {
    let case = decode(data);
    match case.perspective {
        0 => render_mode::<Affine>(&case),
        1 => render_mode::<PerPixel>(&case),
        _ => render_mode::<PerSpan<4>>(&case),
    }
}
