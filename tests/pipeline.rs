//! End-to-end behaviour of the mesh pipeline: golden images, strips versus
//! full frames, near-plane clipping, culling, lighting invariants, memory.
//! Depth, capacity and bad-number cases are in tests/hard_cases/.

use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use soft3d::effect::{Color, Effect, FaceInput, Flat, FragmentCount, Gouraud, VertexInput, MAX_VARYINGS};
use soft3d::host::Image;
use soft3d::math::Interp;
use soft3d::scene::Lighting;
use std::sync::atomic::{AtomicUsize, Ordering};

mod common;
use common::golden;
use soft3d::material::DepthOff;
use soft3d::math::{Mat4, Vec3};
use soft3d::mesh::{Mesh, MeshData};
use soft3d::scenes::{demo_camera, demo_lights, draw_demo, DemoLoop, DEMO_TRIANGLES, DEMO_VARYINGS, DEMO_VERTICES, SPHERE, TORUS};
use soft3d::{Camera, Cull, DrawError, FixedPoint, FloatingPoint, HostRenderer, Lights, Material, Renderer, Settings};

fn demo_image<S: Settings>(w: usize, h: usize, strip: usize, t: f32) -> Image<Rgb565> {
    let mut r: HostRenderer<Rgb565, DEMO_VARYINGS, S> =
        HostRenderer::new(w, h, strip, DEMO_VERTICES, DEMO_TRIANGLES, Rgb565::BLACK).unwrap();
    let mut frame = r.begin_frame(&demo_camera(), &demo_lights(), Rgb565::new(2, 4, 6));
    draw_demo(&mut frame, t).unwrap();
    let mut img = Image::new(w as u32, h as u32, Rgb565::BLACK);
    let Ok(_) = frame.finish(&mut img);
    img
}

#[test]
fn golden_images_of_the_builtin_scene() {
    golden("demo-fixed-t0", &demo_image::<FixedPoint>(160, 120, 16, 0.0));
    golden("demo-fixed-t17", &demo_image::<FixedPoint>(160, 120, 16, 1.7));
    golden("demo-f32-t17", &demo_image::<FloatingPoint>(160, 120, 16, 1.7));
}

#[test]
fn fixed_and_float_interpolation_agree_to_a_color_step() {
    // Same coverage and depth decisions; colors within one Rgb565 step,
    // except where texture coordinates sit on a texel edge and the two
    // scalars round to neighbouring texels of the crate.
    let a = demo_image::<FixedPoint>(160, 120, 16, 1.7);
    let b = demo_image::<FloatingPoint>(160, 120, 16, 1.7);
    let (mut one, mut texel) = (0, 0);
    for (p, q) in a.pixels.iter().zip(&b.pixels) {
        let d = (p.r() as i32 - q.r() as i32).abs().max((p.g() as i32 - q.g() as i32).abs()).max((p.b() as i32 - q.b() as i32).abs());
        one += (d == 1) as u32;
        texel += (d > 1) as u32;
    }
    println!("{one} pixels differ by one step, {texel} by more");
    assert!(one < 200 && texel < 20, "{one} pixels differ by one step, {texel} by more");
}

#[test]
fn strips_render_exactly_the_full_frame() {
    let full = demo_image::<FixedPoint>(160, 120, 120, 0.9);
    for strip in [1, 7, 16, 33, 119] {
        let img = demo_image::<FixedPoint>(160, 120, strip, 0.9);
        assert_eq!(img.pixels, full.pixels, "strip {strip}");
        assert_eq!(img.fills, 120u32.div_ceil(strip as u32), "one fill_contiguous per strip");
    }
    let f = demo_image::<FloatingPoint>(160, 120, 120, 0.9);
    assert_eq!(demo_image::<FloatingPoint>(160, 120, 13, 0.9).pixels, f.pixels);
}

#[test]
fn a_renderer_drawing_frame_after_frame_draws_what_a_fresh_one_draws() {
    // Each strip restores only the columns it dirtied, by runs of every
    // length and alignment: a wrong clear would leave the last frame's
    // pixels or depths behind.
    fn check<S: Settings>(w: usize, strip: usize) {
        let mut r: HostRenderer<Rgb565, DEMO_VARYINGS, S> =
            HostRenderer::new(w, 120, strip, DEMO_VERTICES, DEMO_TRIANGLES, Rgb565::BLACK).unwrap();
        for (k, t) in [0.0, 0.9, 1.7, 2.6, 0.3].into_iter().enumerate() {
            let background = if k / 2 == 1 { Rgb565::new(2, 4, 6) } else { Rgb565::BLACK };
            let mut frame = r.begin_frame(&demo_camera(), &demo_lights(), background);
            draw_demo(&mut frame, t).unwrap();
            let mut img = Image::new(w as u32, 120, Rgb565::BLACK);
            let Ok(_) = frame.finish(&mut img);
            let mut fresh: HostRenderer<Rgb565, DEMO_VARYINGS, S> =
                HostRenderer::new(w, 120, strip, DEMO_VERTICES, DEMO_TRIANGLES, Rgb565::BLACK).unwrap();
            let mut frame = fresh.begin_frame(&demo_camera(), &demo_lights(), background);
            draw_demo(&mut frame, t).unwrap();
            let mut want = Image::new(w as u32, 120, Rgb565::BLACK);
            let Ok(_) = frame.finish(&mut want);
            assert_eq!(img.pixels, want.pixels, "width {w}, strip {strip}, frame {k}");
        }
    }
    for (w, strip) in [(160, 16), (157, 7), (33, 120), (8, 120), (40, 5)] {
        check::<FixedPoint>(w, strip);
        check::<FloatingPoint>(w, strip);
    }
}

#[test]
fn the_static_renderer_matches_the_host_renderer_and_draws_each_pixel_once() {
    // MockDisplay panics if any pixel is drawn twice (strips must not overlap).
    static CUBE: MeshData<24, 36> = MeshData::cube(1.0);
    let mut r: Renderer<Rgb565, 64, 64, 8, 64, 64> = Renderer::new(Rgb565::BLACK);
    let camera = Camera::looking_at(Vec3::new(1.5, 1.5, -3.0), Vec3::ZERO);
    let m = Material::new(Gouraud).with_color(Rgb888::new(255, 160, 0));
    let model = Mat4::rotation_y(0.5);
    let mut frame = r.begin_frame(&camera, &Lights::default(), Rgb565::BLACK);
    frame.draw(&CUBE.mesh(), &model, &m).unwrap();
    let mut display: MockDisplay<Rgb565> = MockDisplay::new();
    frame.finish(&mut display).unwrap();

    let mut h: HostRenderer<Rgb565> = HostRenderer::new(64, 64, 64, 64, 64, Rgb565::BLACK).unwrap();
    let mut frame = h.begin_frame(&camera, &Lights::default(), Rgb565::BLACK);
    frame.draw(&CUBE.mesh(), &model, &m).unwrap();
    let mut img = Image::new(64, 64, Rgb565::BLACK);
    let Ok(_) = frame.finish(&mut img);
    for y in 0..64 {
        for x in 0..64 {
            assert_eq!(display.get_pixel(embedded_graphics::prelude::Point::new(x, y)), Some(img.get(x as u32, y as u32)));
        }
    }
    assert!(img.pixels.iter().filter(|&&c| c != Rgb565::BLACK).count() > 300);
}

/// Renders one mesh and returns fragment counts (no depth test).
fn mesh_coverage(mesh: &Mesh<'_>, model: &Mat4, camera: &Camera, cull: Cull, w: usize, h: usize) -> Vec<u8> {
    let mut r: HostRenderer<Rgb888> = HostRenderer::new(w, h, 16, 4000, 8000, Rgb888::BLACK).unwrap();
    let m = Material::new(FragmentCount).with_cull(cull).with_depth::<DepthOff>();
    let mut frame = r.begin_frame(camera, &Lights::UNLIT, Rgb888::BLACK);
    frame.draw(mesh, model, &m).unwrap();
    let mut img = Image::new(w as u32, h as u32, Rgb888::BLACK);
    let Ok(_) = frame.finish(&mut img);
    img.pixels.iter().map(|c| c.r()).collect()
}

#[test]
fn back_face_culling_is_right_under_perspective() {
    // For a closed convex mesh, the front faces alone cover the silhouette
    // exactly once, even far off-axis where a view-space normal test fails.
    let camera = Camera { fov_y: 1.4, ..Camera::looking_at(Vec3::new(0.0, 0.0, -4.0), Vec3::ZERO) };
    for (x, y) in [(0.0, 0.0), (2.8, 0.0), (-2.5, 1.8), (1.0, -2.2)] {
        let model = Mat4::translation(Vec3::new(x, y, 0.0)) * Mat4::rotation_y(0.4);
        let front = mesh_coverage(&SPHERE, &model, &camera, Cull::Back, 120, 90);
        let all = mesh_coverage(&SPHERE, &model, &camera, Cull::None, 120, 90);
        assert!(front.iter().all(|&c| c <= 1), "at ({x}, {y}) a front face overlaps another");
        for (f, a) in front.iter().zip(&all) {
            assert_eq!(*f == 1, *a > 0, "at ({x}, {y}) the front faces do not cover the silhouette");
        }
        assert!(front.iter().filter(|&&c| c == 1).count() > 100);
    }
}

#[test]
fn closed_meshes_have_no_cracks_or_overlaps() {
    // Every silhouette pixel of a closed mesh is covered by exactly two
    // faces (front and back), never once (a crack) or three times.
    let camera = Camera::looking_at(Vec3::new(0.3, 1.0, -3.5), Vec3::ZERO);
    for t in 0..6 {
        let model = Mat4::rotation_y(t as f32 * 0.7) * Mat4::rotation_x(0.3 * t as f32);
        let cov = mesh_coverage(&TORUS, &model, &camera, Cull::None, 96, 80);
        // A torus seen from here overlaps itself, so 2 or 4 layers.
        assert!(cov.iter().all(|&c| c % 2 == 0), "odd coverage: a crack or an overlap");
        assert!(cov.iter().filter(|&&c| c > 0).count() > 500);
    }
}

#[test]
fn geometry_crossing_the_camera_plane_draws_only_what_is_in_front() {
    // A large floor quad under the eye extends behind the camera. The
    // oracle casts a ray through every pixel center and hits the floor in
    // front of the near plane (f64, independent of the pipeline).
    static P: [Vec3; 4] =
        [Vec3::new(-20.0, -1.0, -20.0), Vec3::new(20.0, -1.0, -20.0), Vec3::new(20.0, -1.0, 20.0), Vec3::new(-20.0, -1.0, 20.0)];
    static N: [Vec3; 4] = [Vec3::new(0.0, 1.0, 0.0); 4];
    static I: [u16; 6] = [0, 2, 1, 0, 3, 2];
    let mesh = Mesh::new(&P, &N, &I).unwrap();
    let (w, h) = (80usize, 60usize);
    for (pitch, yaw) in [(0.0f32, 0.0f32), (0.3, 0.5), (-0.2, 2.0), (0.6, -1.2)] {
        let eye = Vec3::new(0.5, 0.0, -2.0);
        let dir = Vec3::new(yaw.sin() * pitch.cos(), -pitch.sin(), yaw.cos() * pitch.cos());
        let camera = Camera { near: 0.1, far: 100.0, ..Camera::looking_at(eye, eye + dir) };
        let got = mesh_coverage(&mesh, &Mat4::IDENTITY, &camera, Cull::None, w, h);
        // Oracle.
        let view = camera.view();
        let tan = (camera.fov_y as f64 * 0.5).tan();
        let aspect = w as f64 / h as f64;
        let mut want = vec![0u8; w * h];
        for y in 0..h {
            for x in 0..w {
                let ndc_x = (x as f64 + 0.5) / w as f64 * 2.0 - 1.0;
                let ndc_y = 1.0 - (y as f64 + 0.5) / h as f64 * 2.0;
                // View-space ray (x right, y up, z forward), to world with
                // the transpose of the view rotation.
                let r = [ndc_x * tan * aspect, ndc_y * tan, 1.0];
                let m = view.m;
                let world: Vec<f64> = (0..3).map(|c| (0..3).map(|k| m[k][c] as f64 * r[k]).sum()).collect();
                if world[1] < 0.0 {
                    let t = -1.0 / world[1]; // from y = 0 down to y = -1
                    let (px, pz) = (eye.x as f64 + world[0] * t, eye.z as f64 + world[2] * t);
                    // Depth along the view axis is t (r.z = 1) and must be within near..far.
                    if px.abs() < 20.0 && pz.abs() < 20.0 && t > 0.1 && t < 100.0 {
                        want[y * w + x] = 1;
                    }
                }
            }
        }
        let differ = got.iter().zip(&want).filter(|(a, b)| a != b).count();
        // Only pixels whose centers are within a sub-pixel of the far edge
        // or horizon may differ; nothing mirrored, nothing drawn twice.
        assert!(got.iter().all(|&c| c <= 1), "pitch {pitch} yaw {yaw}: overlap");
        assert!(differ <= 4, "pitch {pitch} yaw {yaw}: {differ} pixels differ from the ray-cast oracle");
    }
}

#[test]
fn lighting_does_not_change_when_mesh_and_camera_move_together() {
    // Seeds' bug 3: normals transformed with the translation. Moving the
    // mesh, the camera and the lights by the same offset changes nothing.
    let render = |offset: Vec3| {
        let lights = Lights {
            ambient: Vec3::new(0.1, 0.1, 0.1),
            point: Some(soft3d::PointLight { position: Vec3::new(2.0, 2.0, -2.0) + offset, color: Vec3::ONE }),
            directional: None,
        };
        let camera = Camera::looking_at(Vec3::new(0.0, 0.5, -3.0) + offset, offset);
        let mut r: HostRenderer<Rgb888> = HostRenderer::new(64, 48, 16, 1000, 2000, Rgb888::BLACK).unwrap();
        let m = Material::new(Gouraud).with_color(Rgb888::WHITE);
        let mut frame = r.begin_frame(&camera, &lights, Rgb888::BLACK);
        frame.draw(&SPHERE, &(Mat4::translation(offset) * Mat4::rotation_y(0.3)), &m).unwrap();
        let mut img = Image::new(64, 48, Rgb888::BLACK);
        let Ok(_) = frame.finish(&mut img);
        img
    };
    let a = render(Vec3::ZERO);
    let b = render(Vec3::new(3.0, -2.0, 5.0));
    let max = a.pixels.iter().zip(&b.pixels).map(|(p, q)| (p.r() as i32 - q.r() as i32).abs()).max().unwrap();
    assert!(max <= 2, "lighting changed by {max} levels when everything moved");
    assert!(a.pixels.iter().any(|p| p.r() > 200) && a.pixels.iter().any(|p| p.r() > 0 && p.r() < 60));
}

#[test]
fn ram_formula_matches_size_of() {
    /// `pixel`: bytes of one color and one depth value.
    fn formula(w: usize, h: usize, strip: usize, verts: usize, tris: usize, v: usize, pixel: (usize, usize)) -> usize {
        let (color, depth) = pixel;
        let bytes = w * strip * (color + depth) + verts * (16 + 4 * v) + tris * 12 + 2 * h + color;
        bytes.div_ceil(4) * 4
    }
    assert_eq!(size_of::<Renderer<Rgb565, 320, 240, 16, 1000, 1200>>(), formula(320, 240, 16, 1000, 1200, 3, (2, 2)));
    assert_eq!(size_of::<Renderer<Rgb565, 240, 240, 8, 600, 700, 0>>(), formula(240, 240, 8, 600, 700, 0, (2, 2)));
    assert_eq!(size_of::<Renderer<Rgb888, 128, 64, 64, 100, 100, 4>>(), formula(128, 64, 64, 100, 100, 4, (size_of::<Rgb888>(), 2)));
    // Wider depth formats: 4 bytes a pixel.
    type Deep = soft3d::Precision<soft3d::math::Fixed, 6, soft3d::Depth32>;
    assert_eq!(size_of::<Renderer<Rgb565, 320, 240, 16, 1000, 1200, 3, Deep>>(), formula(320, 240, 16, 1000, 1200, 3, (2, 4)));
    type Float = soft3d::Precision<f32, 6, soft3d::DepthF32>;
    assert_eq!(size_of::<Renderer<Rgb565, 100, 50, 10, 10, 10, 5, Float>>(), formula(100, 50, 10, 10, 10, 5, (2, 4)));
}

/// `Flat`, counting the faces it is asked to light.
#[derive(Clone, Copy, Default)]
struct CountingFlat;

static FACES_LIT: AtomicUsize = AtomicUsize::new(0);

impl Effect for CountingFlat {
    const VARYINGS: usize = Flat::VARYINGS;
    const LIT_VERTICES: bool = Flat::LIT_VERTICES;
    const USES_FACE: bool = Flat::USES_FACE;
    const NAME: &'static str = "counting-flat";
    type Uniforms<S: Interp> = ();
    fn uniforms<S: Interp>(&self, _: &Lighting, _: Rgb888) {}
    fn vertex<C: Color>(&self, v: &VertexInput, lights: &Lighting) -> [f32; MAX_VARYINGS] {
        Flat.vertex::<C>(v, lights)
    }
    fn face(&self, f: &FaceInput, lights: &Lighting) -> Rgb888 {
        FACES_LIT.fetch_add(1, Ordering::Relaxed);
        Flat.face(f, lights)
    }
    fn shade<C: Color, S: Interp>(&self, _: &(), face: C, v: &[S; MAX_VARYINGS], dst: C) -> C {
        Flat.shade::<C, S>(&(), face, v, dst)
    }
}

/// A cube seen from a corner with `effect`: the faces lit, the triangles
/// queued and the frame.
fn cube_from_a_corner<E: Effect>(effect: E) -> (usize, u32, Image<Rgb565>) {
    static CUBE: MeshData<24, 36> = MeshData::cube(1.0);
    let camera = Camera::looking_at(Vec3::new(2.0, 2.5, -3.0), Vec3::ZERO);
    let mut r: HostRenderer<Rgb565, 3, FixedPoint> = HostRenderer::new(64, 64, 8, 64, 64, Rgb565::BLACK).unwrap();
    let material = Material::new(effect).with_color(Rgb888::new(200, 120, 40));
    FACES_LIT.store(0, Ordering::Relaxed);
    let mut frame = r.begin_frame(&camera, &Lights::default(), Rgb565::BLACK);
    frame.draw(&CUBE.mesh(), &Mat4::IDENTITY, &material).unwrap();
    let mut img = Image::new(64, 64, Rgb565::BLACK);
    let Ok(stats) = frame.finish(&mut img);
    (FACES_LIT.load(Ordering::Relaxed), stats.queued, img)
}

#[test]
fn flat_faces_are_lit_only_for_the_triangles_queued() {
    // Three faces (six triangles) toward the camera, three culled.
    // Lighting a face costs a normalization and the lights (library
    // calls on a core without an FPU): the culled ones are not lit.
    let (lit, queued, counted) = cube_from_a_corner(CountingFlat);
    assert_eq!((lit, queued), (6, 6), "faces lit and triangles queued, of 12");
    // The frame is `Flat`'s.
    let (_, _, flat) = cube_from_a_corner(Flat);
    assert!(counted == flat);
}

/// A clock that returns the given readings in turn.
fn clock(readings: &[u32]) -> impl FnMut() -> u32 + '_ {
    let mut next = readings.iter();
    move || *next.next().expect("the loop read the clock more often than expected")
}

fn demo_renderer(w: usize, h: usize, vertices: usize) -> HostRenderer<Rgb565, DEMO_VARYINGS, FixedPoint> {
    HostRenderer::new(w, h, 16, vertices, DEMO_TRIANGLES, Rgb565::BLACK).unwrap()
}

#[test]
fn demo_loop_times_each_frame_and_animates_by_the_measured_time() {
    let mut r = demo_renderer(160, 120, DEMO_VERTICES);
    let mut demo = DemoLoop::new(1_000_000);
    let background = Rgb565::new(2, 4, 6);
    // Frame 0: 2 ms of draw calls, 10 ms in all.
    let mut img = Image::new(160, 120, Rgb565::BLACK);
    let frame = r.begin_frame(&demo_camera(), &demo_lights(), background);
    let report = demo.render(frame, &mut img, clock(&[1_000, 3_000, 11_000])).unwrap();
    assert_eq!(img, demo_image::<FixedPoint>(160, 120, 16, 0.0), "frame 0 is the demo at t = 0");
    assert!(report.stats.queued > 500, "{:?}", report.stats);
    assert_eq!((report.index, report.geometry_ticks, report.total_ticks, report.draw_error), (0, 2_000, 10_000, None));
    assert_eq!(
        report.to_string(),
        format!("frame 0: 10000 us (geometry 2000 us, raster + display 8000 us), 100.0 fps, {} triangles", report.stats.queued)
    );
    assert_eq!(demo.seconds(), 0.01);

    // Frame 1 is drawn at the 10 ms frame 0 took, across the clock's wrap.
    let mut img = Image::new(160, 120, Rgb565::BLACK);
    let frame = r.begin_frame(&demo_camera(), &demo_lights(), background);
    let report = demo.render(frame, &mut img, clock(&[u32::MAX - 499, 1_500, 40_000])).unwrap();
    assert_eq!(img, demo_image::<FixedPoint>(160, 120, 16, 0.01), "frame 1 is the demo at t = 0.01 s");
    assert_ne!(img, demo_image::<FixedPoint>(160, 120, 16, 0.0), "the scene moved");
    assert_eq!((report.index, report.geometry_ticks, report.total_ticks), (1, 2_000, 40_500));
    assert_eq!(
        report.to_string(),
        format!("frame 1: 40500 us (geometry 2000 us, raster + display 38500 us), 24.6 fps, {} triangles", report.stats.queued)
    );
    assert_eq!(demo.seconds(), 0.0505);
}

#[test]
fn demo_loop_reports_a_cycle_counter_in_microseconds_and_ticks() {
    let mut r = demo_renderer(64, 48, DEMO_VERTICES);
    // A 100 MHz cycle counter: 4,000,000 cycles are 40 ms.
    let mut demo = DemoLoop::new(100_000_000);
    let frame = r.begin_frame(&demo_camera(), &demo_lights(), Rgb565::BLACK);
    let report = demo.render(frame, &mut Image::new(64, 48, Rgb565::BLACK), clock(&[0, 1_234_567, 4_000_000])).unwrap();
    assert_eq!((report.micros(report.geometry_ticks), report.micros(report.total_ticks), report.tenths_fps()), (12_345, 40_000, 250));
    assert_eq!(
        report.to_string(),
        format!(
            "frame 0: 40000 us = 4000000 ticks (geometry 12345 us, raster + display 27655 us), 25.0 fps, {} triangles",
            report.stats.queued
        )
    );
    assert_eq!(demo.seconds(), 0.04);
    // A clock of 0 ticks a second is taken as 1, and a frame of 0 ticks as 1.
    let mut demo = DemoLoop::new(0);
    let frame = r.begin_frame(&demo_camera(), &demo_lights(), Rgb565::BLACK);
    let report = demo.render(frame, &mut Image::new(64, 48, Rgb565::BLACK), clock(&[7, 7, 7])).unwrap();
    assert_eq!((report.ticks_per_second, report.total_ticks, report.tenths_fps()), (1, 0, 10));
    assert_eq!(demo.seconds(), 0.0);
}

#[test]
fn demo_loop_sends_the_frame_and_reports_a_failed_draw_call() {
    // Room for 100 vertices: the torus (561) does not fit, and draw_demo
    // stops at its first draw call.
    let mut r = demo_renderer(64, 48, 100);
    let mut demo = DemoLoop::new(1_000_000);
    let mut img = Image::new(64, 48, Rgb565::RED);
    let frame = r.begin_frame(&demo_camera(), &demo_lights(), Rgb565::BLUE);
    let report = demo.render(frame, &mut img, clock(&[0, 10, 30])).unwrap();
    assert_eq!(report.draw_error, Some(DrawError::VertexCapacity { needed: 561, capacity: 100 }));
    assert_eq!(report.stats.queued, 0);
    let background = (0..48).flat_map(|y| (0..64).map(move |x| (x, y))).filter(|&(x, y)| img.get(x, y) == Rgb565::BLUE).count();
    assert_eq!(background, 64 * 48, "the frame was still sent, empty");
    assert_eq!(
        report.to_string(),
        "frame 0: 30 us (geometry 10 us, raster + display 20 us), 33333.3 fps, 0 triangles; \
         draw_demo: vertex buffer too small: frame needs 561 vertices, capacity is 100"
    );
}

/// A display whose every write fails.
struct BrokenDisplay;

impl embedded_graphics::geometry::OriginDimensions for BrokenDisplay {
    fn size(&self) -> embedded_graphics::geometry::Size {
        embedded_graphics::geometry::Size::new(64, 48)
    }
}

impl embedded_graphics::draw_target::DrawTarget for BrokenDisplay {
    type Color = Rgb565;
    type Error = &'static str;
    fn draw_iter<I: IntoIterator<Item = embedded_graphics::Pixel<Rgb565>>>(&mut self, _: I) -> Result<(), &'static str> {
        Err("bus error")
    }
}

#[test]
fn demo_loop_passes_on_the_display_error_without_counting_the_frame() {
    let mut r = demo_renderer(64, 48, DEMO_VERTICES);
    let mut demo = DemoLoop::new(1_000_000);
    let frame = r.begin_frame(&demo_camera(), &demo_lights(), Rgb565::BLACK);
    assert_eq!(demo.render(frame, &mut BrokenDisplay, clock(&[0, 10])), Err("bus error"));
    assert_eq!(demo.seconds(), 0.0);
    let frame = r.begin_frame(&demo_camera(), &demo_lights(), Rgb565::BLACK);
    let report = demo.render(frame, &mut Image::new(64, 48, Rgb565::BLACK), clock(&[0, 10, 20])).unwrap();
    assert_eq!(report.index, 0, "the failed frame is not numbered");
}
