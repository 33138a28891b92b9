//! Category 10, bad numbers: NaN and infinities in positions, normals,
//! texture coordinates, model and camera matrices and window-space input.
//! What cannot be drawn is skipped and counted in `FrameStats`; the rest
//! of the frame is exactly the image without it.

use super::depth::{all_modes, mode};
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use soft3d::effect::{BlinnPhong, Effect, Gouraud, Phong, Textured, VertexColor};
use soft3d::host::Image;
use soft3d::material::PerPixel;
use soft3d::math::{Mat4, Vec2, Vec3};
use soft3d::mesh::{Mesh, MeshData};
use soft3d::texture::Texture;
use soft3d::tri::TriVertex;
use soft3d::{Camera, Cull, FrameStats, HostRenderer, Lights, Material, Settings};

const NAN: f32 = f32::NAN;
const INF: f32 = f32::INFINITY;
const BG: Rgb888 = Rgb888::new(0, 0, 90);
const W: usize = 32;

fn camera() -> Camera {
    Camera::looking_at(Vec3::new(0.0, 0.0, -4.0), Vec3::ZERO)
}

/// Draws each `(mesh, model)` with `material` and returns the image and stats.
fn draw<S: Settings, E: Effect>(
    camera: &Camera,
    lights: &Lights,
    calls: &[(&Mesh<'_>, Mat4)],
    material: &Material<E>,
) -> (Image<Rgb888>, FrameStats) {
    let mut r: HostRenderer<Rgb888, 6, S> = HostRenderer::new(W, W, 8, 64, 64, BG).unwrap();
    let mut frame = r.begin_frame(camera, lights, BG);
    for (mesh, model) in calls {
        frame.draw(mesh, model, material).unwrap();
    }
    let mut img = Image::new(W as u32, W as u32, BG);
    let Ok(stats) = frame.finish(&mut img);
    (img, stats)
}

/// One good triangle (vertices 0 to 2) and bad ones that reuse them.
const GOOD: [Vec3; 3] = [Vec3::new(-1.0, 1.0, 0.0), Vec3::new(1.0, 0.8, 0.0), Vec3::new(-0.6, -1.0, 0.0)];

#[test]
fn non_finite_positions_skip_their_triangles() {
    // Triangles with a NaN, +inf or -inf coordinate, one of them also
    // reaching behind the camera (which would otherwise be clipped): each
    // is counted invalid and the image is the good triangle's alone.
    fn case<S: Settings>() {
        let mut p = GOOD.to_vec();
        p.extend([Vec3::new(NAN, 0.0, 0.0), Vec3::new(0.5, INF, 0.0), Vec3::new(0.0, 0.0, -INF), Vec3::new(0.3, 0.2, -9.0)]);
        let n = vec![Vec3::new(0.0, 0.0, -1.0); p.len()];
        let bad = [0u16, 1, 2, 3, 1, 2, 0, 4, 2, 0, 1, 5, 6, 3, 1];
        let mesh = Mesh::new(&p, &n, &bad).unwrap();
        let good = Mesh::new(&p, &n, &bad[..3]).unwrap();
        let m = Material::new(Gouraud).with_cull(Cull::None);
        let (img, stats) = draw::<S, _>(&camera(), &Lights::default(), &[(&mesh, Mat4::IDENTITY)], &m);
        let (want, _) = draw::<S, _>(&camera(), &Lights::default(), &[(&good, Mat4::IDENTITY)], &m);
        assert_eq!((stats.triangles, stats.invalid, stats.queued), (5, 4, 1), "{}", mode::<S>());
        assert_eq!(img.pixels, want.pixels, "{}", mode::<S>());
        assert!(img.pixels.iter().filter(|&&c| c != BG).count() > 50);
    }
    all_modes!(case);
}

#[test]
fn non_finite_normals_light_as_zero_normals() {
    // A NaN or infinite normal is no direction at all: like a zero normal
    // (see `VertexInput::normal`) it gets ambient light only, 0.25 of the
    // white material (64), in both vertex paths and per pixel. The
    // triangles are drawn, not counted invalid.
    fn case<S: Settings>() {
        let p = [Vec3::new(-1.0, 1.0, 0.0), Vec3::new(1.0, 1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(-1.0, -1.0, 0.0)];
        let n = [Vec3::new(NAN, 0.0, -1.0), Vec3::new(0.0, INF, 0.0), Vec3::new(-INF, INF, 0.0), Vec3::new(0.0, 0.0, NAN)];
        let i = [0u16, 1, 2, 0, 2, 3];
        let mesh = Mesh::new(&p, &n, &i).unwrap();
        let lights = Lights { ambient: Vec3::new(0.25, 0.25, 0.25), ..Lights::default() };
        let gray = Rgb888::new(64, 64, 64);
        let check = |(img, stats): (Image<Rgb888>, FrameStats), what: &str| {
            assert_eq!((stats.invalid, stats.queued), (0, 2), "{} {what}", mode::<S>());
            let lit: Vec<_> = img.pixels.iter().filter(|&&c| c != BG).collect();
            assert!(lit.len() > 100 && lit.iter().all(|&&c| c == gray), "{} {what}: {:?}", mode::<S>(), lit.iter().find(|&&&c| c != gray));
        };
        for model in [Mat4::IDENTITY, Mat4::scaling(Vec3::new(1.0, 0.7, 1.0))] {
            let call = [(&mesh, model)];
            check(draw::<S, _>(&camera(), &lights, &call, &Material::new(Gouraud).with_cull(Cull::None)), "gouraud");
            check(draw::<S, _>(&camera(), &lights, &call, &Material::new(Phong::new()).with_cull(Cull::None)), "phong");
            let blinn = Material::new(BlinnPhong::with_specular(Rgb888::WHITE, 4.0)).with_cull(Cull::None);
            check(draw::<S, _>(&camera(), &lights, &call, &blinn), "blinn-phong");
        }
    }
    all_modes!(case);
}

#[test]
fn non_finite_texture_coordinates_skip_their_triangles() {
    // A quad whose second triangle has a NaN, an infinite or an
    // f32-overflowing (u · width) coordinate: that triangle is counted
    // invalid, the first is drawn as it is without it.
    fn case<S: Settings>() {
        let texels: Vec<u16> = (0..16u16).map(|i| i * 0x1111).collect();
        let tex = Texture::new(&texels, 4, 4).unwrap();
        let p = [Vec3::new(-1.0, 1.0, 0.0), Vec3::new(1.0, 1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(-1.0, -1.0, 0.0)];
        let n = [Vec3::new(0.0, 0.0, -1.0); 4];
        let i = [0u16, 1, 2, 0, 2, 3];
        for bad in [Vec2::new(NAN, 0.5), Vec2::new(0.5, INF), Vec2::new(-INF, NAN), Vec2::new(f32::MAX, 0.0)] {
            let uv = [Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(1.0, 1.0), bad];
            let mesh = Mesh::new(&p, &n, &i).unwrap().with_uvs(&uv).unwrap();
            let first = Mesh::new(&p, &n, &i[..3]).unwrap().with_uvs(&uv).unwrap();
            let render = |mesh: &Mesh<'_>| {
                let mut r: HostRenderer<Rgb565, 5, S> = HostRenderer::new(W, W, 8, 16, 16, Rgb565::BLACK).unwrap();
                let m = Material::new(Textured::<soft3d::texture::Bilinear>::new(tex)).with_cull(Cull::None).with_perspective::<PerPixel>();
                let mut frame = r.begin_frame(&camera(), &Lights::UNLIT, Rgb565::BLACK);
                frame.draw(mesh, &Mat4::IDENTITY, &m).unwrap();
                let mut img = Image::new(W as u32, W as u32, Rgb565::BLACK);
                let Ok(stats) = frame.finish(&mut img);
                (img.pixels, stats)
            };
            let (got, stats) = render(&mesh);
            let (want, _) = render(&first);
            assert_eq!((stats.invalid, stats.queued), (1, 1), "{} uv {bad:?}", mode::<S>());
            assert_eq!(got, want, "{} uv {bad:?}", mode::<S>());
        }
    }
    all_modes!(case);
}

#[test]
fn non_finite_model_matrices_skip_the_mesh() {
    // Any NaN or infinite entry (rotation, translation, projective row):
    // the mesh is counted in `meshes_invalid` and nothing of it is drawn;
    // the good draw in the same frame is unaffected.
    fn case<S: Settings>() {
        static CUBE: MeshData<24, 36> = MeshData::cube(1.0);
        let cube = CUBE.mesh();
        let m = Material::new(Gouraud);
        let (want, _) = draw::<S, _>(&camera(), &Lights::default(), &[(&cube, Mat4::rotation_y(0.4))], &m);
        for (r, c, v) in [(0, 0, NAN), (1, 2, INF), (2, 3, -INF), (3, 0, NAN), (3, 3, INF)] {
            let mut bad = Mat4::rotation_y(0.9);
            bad.m[r][c] = v;
            let calls = [(&cube, bad), (&cube, Mat4::rotation_y(0.4)), (&cube, bad)];
            let (img, stats) = draw::<S, _>(&camera(), &Lights::default(), &calls, &m);
            assert_eq!((stats.meshes_invalid, stats.draw_calls, stats.triangles), (2, 1, 12), "{} m[{r}][{c}] = {v}", mode::<S>());
            assert_eq!(img.pixels, want.pixels, "{} m[{r}][{c}] = {v}", mode::<S>());
        }
        // Finite, but every transformed coordinate overflows to infinity:
        // the bounding sphere is infinite and the mesh is culled whole.
        let (img, stats) = draw::<S, _>(&camera(), &Lights::default(), &[(&cube, Mat4::scaling(Vec3::new(3e38, 3e38, 3e38)))], &m);
        assert_eq!((stats.meshes_culled, stats.queued), (1, 0), "{} overflowing model", mode::<S>());
        assert!(img.pixels.iter().all(|&c| c == BG));
    }
    all_modes!(case);
}

#[test]
fn non_finite_cameras_skip_every_mesh_or_are_repaired() {
    // A NaN or infinite camera position (or an explicit NaN
    // view-projection): every mesh is counted in `meshes_invalid` and the
    // frame is the background. A non-finite target or up vector is a
    // degenerate frame, which `look_at_lh` repairs (view along +z; an up
    // vector perpendicular to it): the image is that repaired camera's.
    fn case<S: Settings>() {
        static CUBE: MeshData<24, 36> = MeshData::cube(1.0);
        let cube = CUBE.mesh();
        let m = Material::new(Gouraud);
        let good = camera();
        let calls = [(&cube, Mat4::IDENTITY), (&cube, Mat4::rotation_x(1.0))];
        for cam in [Camera { position: Vec3::new(NAN, 0.0, -4.0), ..good }, Camera { position: Vec3::new(0.0, 0.0, -INF), ..good }] {
            let (img, stats) = draw::<S, _>(&cam, &Lights::default(), &calls, &m);
            assert_eq!((stats.meshes_invalid, stats.draw_calls), (2, 0), "{} {cam:?}", mode::<S>());
            assert!(img.pixels.iter().all(|&c| c == BG), "{} {cam:?}", mode::<S>());
        }
        let sideways = Camera { up: Vec3::new(1.0, 0.0, 0.0), ..good };
        for (cam, same_as) in [
            (Camera { target: Vec3::new(0.0, INF, 0.0), ..good }, good),
            (Camera { target: Vec3::new(NAN, 0.0, 0.0), ..good }, good),
            (Camera { up: Vec3::new(NAN, NAN, NAN), ..good }, sideways),
            (Camera { up: Vec3::new(0.0, -INF, 0.0), ..good }, sideways),
        ] {
            let (img, stats) = draw::<S, _>(&cam, &Lights::default(), &calls, &m);
            let (want, _) = draw::<S, _>(&same_as, &Lights::default(), &calls, &m);
            assert_eq!((stats.meshes_invalid, stats.draw_calls), (0, 2), "{} {cam:?}", mode::<S>());
            assert_eq!(img.pixels, want.pixels, "{} {cam:?}", mode::<S>());
        }
        let mut r: HostRenderer<Rgb888, 3, S> = HostRenderer::new(W, W, 8, 64, 64, BG).unwrap();
        let mut vp = Mat4::IDENTITY;
        vp.m[3][2] = NAN;
        let mut frame = r.begin_frame_with(vp, &Lights::default(), BG);
        frame.draw(&cube, &Mat4::IDENTITY, &m).unwrap();
        let mut img = Image::new(W as u32, W as u32, BG);
        let Ok(stats) = frame.finish(&mut img);
        assert_eq!((stats.meshes_invalid, stats.queued), (1, 0), "{} NaN view-projection", mode::<S>());
        // Planes and field of view that make no sense are repaired as
        // `Camera::projection` documents: near at least 1e-4, far 1000
        // times near when not beyond it, fov 0.8.
        let call = [(&cube, Mat4::rotation_x(1.0))];
        for (cam, same_as) in [
            (Camera { near: NAN, far: 100.0, fov_y: INF, ..good }, Camera { near: 1e-4, far: 100.0, fov_y: 0.8, ..good }),
            (Camera { near: 0.5, far: NAN, fov_y: NAN, ..good }, Camera { near: 0.5, far: 500.0, fov_y: 0.8, ..good }),
            (Camera { near: 0.002, far: -INF, fov_y: -1.0, ..good }, Camera { near: 0.002, far: 2.0, fov_y: 0.8, ..good }),
        ] {
            let (img, _) = draw::<S, _>(&cam, &Lights::default(), &call, &m);
            let (want, _) = draw::<S, _>(&same_as, &Lights::default(), &call, &m);
            assert_eq!(img.pixels, want.pixels, "{} {cam:?}", mode::<S>());
        }
        // Far at 2 is nearer than any of the cube (about 3.5 away): nothing drawn.
        let (img, _) = draw::<S, _>(&Camera { near: 0.002, far: -INF, ..good }, &Lights::default(), &call, &m);
        assert!(img.pixels.iter().all(|&c| c == BG));
    }
    all_modes!(case);
}

#[test]
fn non_finite_window_triangles_are_skipped() {
    // Window-space input (the `.tri` path): NaN or infinite x, y, z or w,
    // and w <= 0, each skip their triangle and count it invalid.
    fn case<S: Settings>() {
        let v = |x: f64, y: f64, z: f32, w: f32| TriVertex { x, y, z, w, color: Rgb888::RED };
        let good = [v(2.0, 3.0, 0.5, 1.0), v(29.0, 6.0, 0.5, 1.0), v(8.0, 28.0, 0.5, 2.0)];
        let bad = [
            [v(f64::NAN, 3.0, 0.5, 1.0), good[1], good[2]],
            [good[0], v(29.0, f64::INFINITY, 0.5, 1.0), good[2]],
            [good[0], good[1], v(8.0, 28.0, NAN, 1.0)],
            [good[0], good[1], v(8.0, 28.0, -INF, 1.0)],
            [good[0], v(29.0, 6.0, 0.5, INF), good[2]],
            [good[0], v(29.0, 6.0, 0.5, 0.0), good[2]],
            [v(2.0, 3.0, 0.5, -1.0), good[1], good[2]],
            [good[0], good[1], v(f64::NEG_INFINITY, f64::NAN, 0.5, NAN)],
        ];
        let render = |tris: &[[TriVertex; 3]]| {
            let mut r: HostRenderer<Rgb888, 3, S> = HostRenderer::new(W, W, 8, 64, 64, BG).unwrap();
            let m = Material::new(VertexColor).with_cull(Cull::None);
            let mut frame = r.begin_frame_with(Mat4::IDENTITY, &Lights::UNLIT, BG);
            frame.draw_window_triangles(tris.iter().copied(), &m).unwrap();
            let mut img = Image::new(W as u32, W as u32, BG);
            let Ok(stats) = frame.finish(&mut img);
            (img.pixels, stats)
        };
        let mut all = bad.to_vec();
        all.insert(4, good);
        let (got, stats) = render(&all);
        let (want, _) = render(&[good]);
        assert_eq!((stats.triangles, stats.invalid, stats.queued), (9, 8, 1), "{}", mode::<S>());
        assert_eq!(got, want, "{}", mode::<S>());
    }
    all_modes!(case);
}
