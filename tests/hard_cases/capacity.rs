//! Category 11, capacity: more vertices, triangles or draw calls than the
//! fixed buffers hold, in the static `Renderer` and the `HostRenderer`. A
//! refused draw returns a typed `DrawError` and leaves the frame exactly as
//! it was: the finished image equals the image without that call.

use super::depth::{all_modes, mode};
use embedded_graphics::mock_display::MockDisplay;
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use embedded_graphics::prelude::Point;
use soft3d::effect::{Gouraud, VertexColor};
use soft3d::host::Image;
use soft3d::math::{Mat4, Vec3};
use soft3d::mesh::{Mesh, MeshData, MeshError};
use soft3d::scenes::{SPHERE, TORUS};
use soft3d::tri::TriVertex;
use soft3d::{Camera, Cull, DrawError, Frame, FrameStats, HostRenderer, Lights, Material, Renderer, Settings, SizeError};

static CUBE: MeshData<24, 36> = MeshData::cube(1.0);
static ORANGE: Material<Gouraud> = Material::new(Gouraud).with_color(Rgb888::new(255, 160, 0));
static UNLIT: Material<VertexColor> = Material::new(VertexColor).with_cull(Cull::None);

fn camera() -> Camera {
    Camera::looking_at(Vec3::new(0.0, 1.5, -4.0), Vec3::ZERO)
}

fn finish<S: Settings>(frame: Frame<'_, '_, Rgb565, 3, S>) -> (Vec<Rgb565>, FrameStats) {
    let mut img = Image::new(64, 48, Rgb565::BLACK);
    let Ok(stats) = frame.finish(&mut img);
    (img.pixels, stats)
}

/// The cube alone, as the reference frame.
fn cube_alone<S: Settings>() -> (Vec<Rgb565>, FrameStats) {
    let mut r: HostRenderer<Rgb565, 3, S> = HostRenderer::new(64, 48, 16, 500, 100, Rgb565::BLACK).unwrap();
    let mut frame = r.begin_frame(&camera(), &Lights::default(), Rgb565::BLACK);
    frame.draw(&CUBE.mesh(), &Mat4::rotation_y(0.3), &ORANGE).unwrap();
    finish(frame)
}

/// Refused draws (too many vertices, too many visible triangles), then
/// the cube: with 500 vertices and 100 triangles of room.
fn overflowing_draws<S: Settings>(frame: &mut Frame<'_, 'static, Rgb565, 3, S>) {
    let m = mode::<S>();
    // The torus has 561 vertices.
    assert_eq!(frame.draw(&TORUS, &Mat4::IDENTITY, &ORANGE), Err(DrawError::VertexCapacity { needed: 561, capacity: 500 }), "{m}");
    // The sphere's 425 vertices fit, its ~360 visible triangles do not.
    assert_eq!(frame.draw(&SPHERE, &Mat4::IDENTITY, &ORANGE), Err(DrawError::TriangleCapacity { capacity: 100 }), "{m}");
    assert_eq!(frame.stats(), FrameStats::default(), "{m}: refused draws leave no trace");
    frame.draw(&CUBE.mesh(), &Mat4::rotation_y(0.3), &ORANGE).unwrap();
}

#[test]
fn capacity_errors_are_typed_and_leave_the_frame_unchanged() {
    fn case<S: Settings>() {
        let (want, want_stats) = cube_alone::<S>();
        assert!(want.iter().filter(|&&c| c != Rgb565::BLACK).count() > 200);
        let mut host: HostRenderer<Rgb565, 3, S> = HostRenderer::new(64, 48, 16, 500, 100, Rgb565::BLACK).unwrap();
        let mut frame = host.begin_frame(&camera(), &Lights::default(), Rgb565::BLACK);
        overflowing_draws(&mut frame);
        assert_eq!(finish(frame), (want.clone(), want_stats), "{} host", mode::<S>());
        // The static renderer, into a MockDisplay that panics on a pixel
        // drawn twice or outside the display.
        let mut r: Box<Renderer<Rgb565, 64, 48, 16, 500, 100, 3, S>> = Box::new(Renderer::new(Rgb565::BLACK));
        let mut frame = r.begin_frame(&camera(), &Lights::default(), Rgb565::BLACK);
        overflowing_draws(&mut frame);
        let mut display: MockDisplay<Rgb565> = MockDisplay::new();
        assert_eq!(frame.finish(&mut display), Ok(want_stats), "{} static", mode::<S>());
        for (i, c) in want.iter().enumerate() {
            assert_eq!(display.get_pixel(Point::new((i % 64) as i32, (i / 64) as i32)), Some(*c), "{} static", mode::<S>());
        }
    }
    all_modes!(case);
}

#[test]
fn vertex_capacity_is_shared_by_the_draws_of_a_frame() {
    // 60 vertices: two cubes (48) fit, a third needs 72; exactly 48 fit.
    fn case<S: Settings>() {
        let models = [Mat4::translation(Vec3::new(-1.2, 0.0, 0.0)), Mat4::translation(Vec3::new(1.2, 0.0, 0.0))];
        let render = |capacity: usize, third: bool| {
            let mut r: HostRenderer<Rgb565, 3, S> = HostRenderer::new(64, 48, 16, capacity, 100, Rgb565::BLACK).unwrap();
            let mut frame = r.begin_frame(&camera(), &Lights::default(), Rgb565::BLACK);
            for model in &models {
                frame.draw(&CUBE.mesh(), model, &ORANGE).unwrap();
            }
            if third {
                let err = frame.draw(&CUBE.mesh(), &Mat4::IDENTITY, &ORANGE);
                assert_eq!(err, Err(DrawError::VertexCapacity { needed: 72, capacity }), "{}", mode::<S>());
            }
            finish(frame)
        };
        let (exact, stats) = render(48, false);
        assert_eq!((stats.vertices, stats.queued), (48, 12), "{}", mode::<S>());
        assert_eq!(render(60, true), (exact, stats), "{}", mode::<S>());
    }
    all_modes!(case);
}

#[test]
fn clipping_that_needs_more_vertices_than_fit_is_refused() {
    // A floor reaching behind the camera fits 4 vertices, but clipping it
    // at the near plane adds vertices: with room for 4 the draw is refused
    // and nothing is drawn; with room for 16 it is drawn.
    fn case<S: Settings>() {
        let p = [Vec3::new(-9.0, -1.0, -9.0), Vec3::new(9.0, -1.0, -9.0), Vec3::new(9.0, -1.0, 9.0), Vec3::new(-9.0, -1.0, 9.0)];
        let n = [Vec3::new(0.0, 1.0, 0.0); 4];
        let i = [0u16, 2, 1, 0, 3, 2];
        let floor = Mesh::new(&p, &n, &i).unwrap();
        let cam = Camera::looking_at(Vec3::new(0.0, 0.0, -2.0), Vec3::new(0.0, -0.5, 0.0));
        let render = |capacity: usize| {
            let mut r: HostRenderer<Rgb565, 3, S> = HostRenderer::new(64, 48, 16, capacity, 16, Rgb565::BLACK).unwrap();
            let mut frame = r.begin_frame(&cam, &Lights::default(), Rgb565::BLACK);
            let res = frame.draw(&floor, &Mat4::IDENTITY, &ORANGE);
            let (img, stats) = finish(frame);
            (res, img, stats)
        };
        let (res, img, stats) = render(4);
        assert_eq!(res, Err(DrawError::VertexCapacity { needed: 5, capacity: 4 }), "{}", mode::<S>());
        assert_eq!(stats, FrameStats::default(), "{}", mode::<S>());
        assert!(img.iter().all(|&c| c == Rgb565::BLACK), "{}", mode::<S>());
        let (res, img, stats) = render(16);
        assert_eq!(res, Ok(()));
        assert!(stats.clipped >= 1 && img.iter().filter(|&&c| c != Rgb565::BLACK).count() > 500, "{}", mode::<S>());
    }
    all_modes!(case);
}

#[test]
fn the_thirty_third_draw_call_is_refused() {
    // MAX_DRAW_CALLS = 32: the 33rd call (mesh or window triangles) is
    // refused; the image is that of the first 32.
    fn case<S: Settings>() {
        let model =
            |k: usize| Mat4::translation(Vec3::new(k as f32 * 0.2 - 3.2, (k % 4) as f32 * 0.4 - 0.6, 2.0)) * Mat4::scaling(Vec3::ONE * 0.3);
        let render = |calls: usize| {
            let mut r: HostRenderer<Rgb565, 3, S> = HostRenderer::new(64, 48, 16, 2000, 1000, Rgb565::BLACK).unwrap();
            let mut frame = r.begin_frame(&camera(), &Lights::default(), Rgb565::BLACK);
            for k in 0..calls.min(32) {
                frame.draw(&CUBE.mesh(), &model(k), &ORANGE).unwrap();
            }
            if calls > 32 {
                assert_eq!(frame.draw(&CUBE.mesh(), &model(32), &ORANGE), Err(DrawError::DrawCallCapacity));
                let tri = [(1.0, 1.0), (30.0, 2.0), (5.0, 40.0)].map(|(x, y)| TriVertex { x, y, z: 0.01, w: 1.0, color: Rgb888::WHITE });
                assert_eq!(frame.draw_window_triangles([tri], &UNLIT), Err(DrawError::DrawCallCapacity));
            }
            finish(frame)
        };
        let (img, stats) = render(33);
        assert_eq!(stats.draw_calls, 32, "{}", mode::<S>());
        assert_eq!((img, stats), render(32), "{}", mode::<S>());
    }
    all_modes!(case);
}

#[test]
fn window_triangles_beyond_the_triangle_buffer_are_refused_whole() {
    // Three visible window triangles with room for two, as the first and
    // as a later draw call: refused, nothing of them drawn, stats as before.
    fn case<S: Settings>() {
        let tri =
            |x: f64, c: Rgb888| [(x, 2.0), (x + 12.0, 4.0), (x + 3.0, 40.0)].map(|(x, y)| TriVertex { x, y, z: 0.5, w: 1.0, color: c });
        let three = [tri(2.0, Rgb888::RED), tri(20.0, Rgb888::GREEN), tri(40.0, Rgb888::BLUE)];
        let render = |first: bool, second: bool| {
            let mut r: HostRenderer<Rgb565, 3, S> = HostRenderer::new(64, 48, 16, 64, 2, Rgb565::BLACK).unwrap();
            let mut frame = r.begin_frame_with(Mat4::IDENTITY, &Lights::UNLIT, Rgb565::BLACK);
            if first {
                assert_eq!(frame.draw_window_triangles(three, &UNLIT), Err(DrawError::TriangleCapacity { capacity: 2 }));
                assert_eq!(frame.stats(), FrameStats::default(), "{}", mode::<S>());
            }
            frame.draw_window_triangles([tri(10.0, Rgb888::WHITE)], &UNLIT).unwrap();
            if second {
                let before = frame.stats();
                assert_eq!(frame.draw_window_triangles(three, &UNLIT), Err(DrawError::TriangleCapacity { capacity: 2 }));
                assert_eq!(frame.stats(), before, "{}", mode::<S>());
            }
            finish(frame)
        };
        let want = render(false, false);
        assert_eq!(want.1.queued, 1);
        assert_eq!(render(true, true), want, "{}", mode::<S>());
    }
    all_modes!(case);
}

#[test]
fn sizes_beyond_the_limits_are_typed_errors() {
    // Host renderer sizes: 1 to 16,384 pixels a side, 1 <= strip <= height,
    // capacities below 65,535 (indices are u16 with one reserved).
    let new = |w, h, strip, v, t| HostRenderer::<Rgb565>::new(w, h, strip, v, t, Rgb565::BLACK).err();
    assert_eq!(new(0, 10, 1, 8, 8), Some(SizeError));
    assert_eq!(new(10, 0, 1, 8, 8), Some(SizeError));
    assert_eq!(new(16_385, 1, 1, 8, 8), Some(SizeError));
    assert_eq!(new(10, 10, 0, 8, 8), Some(SizeError));
    assert_eq!(new(10, 10, 11, 8, 8), Some(SizeError));
    assert_eq!(new(10, 10, 10, 65_535, 8), Some(SizeError));
    assert_eq!(new(10, 10, 10, 8, 65_535), Some(SizeError));
    assert_eq!(new(16_384, 1, 1, 65_534, 65_534), None);
    // Zero capacities are valid: every draw that needs room is refused.
    let mut r: HostRenderer<Rgb565> = HostRenderer::new(8, 8, 8, 0, 0, Rgb565::BLACK).unwrap();
    let mut frame = r.begin_frame(&camera(), &Lights::default(), Rgb565::BLACK);
    assert_eq!(frame.draw(&CUBE.mesh(), &Mat4::IDENTITY, &ORANGE), Err(DrawError::VertexCapacity { needed: 24, capacity: 0 }));
    // Meshes: u16 indices address at most 65,536 vertices.
    let many = vec![Vec3::ZERO; 65_537];
    assert_eq!(Mesh::new(&many, &many, &[]).err(), Some(MeshError::TooManyVertices(65_537)));
    assert!(Mesh::new(&many[..65_536], &many[..65_536], &[65_535, 0, 1]).is_ok());
}
