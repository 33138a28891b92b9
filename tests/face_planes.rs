//! Baked face planes change how a frame is computed, not what it shows:
//! with them, back faces are culled in model space before the vertex
//! stage and vertices only back faces use are skipped; the frames must be
//! the same pixels as without them, for every camera tried (inside the
//! mesh's bounds, at its surface, far away, mirrored models), in both
//! numeric modes, and at least 2 sub-pixel bits (coarser snapping turns a
//! few back faces front-facing, which only the screen-space test draws). (Only with the `face-planes` feature, which `simulator` includes.)
#![cfg(feature = "face-planes")]

use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use soft3d::effect::Gouraud;
use soft3d::host::Image;
use soft3d::math::Fixed;
use soft3d::math::{Mat4, Vec3};
use soft3d::mesh::{face_plane, FacePlane, Mesh, MeshData, MeshError};
use soft3d::{Camera, FixedPoint, FloatingPoint, FrameStats, HostRenderer, Lights, Material, Precision, Settings};

fn planes_of(mesh: &Mesh<'_>) -> Vec<FacePlane> {
    mesh.indices()
        .chunks_exact(3)
        .map(|t| face_plane(mesh.position(t[0] as usize), mesh.position(t[1] as usize), mesh.position(t[2] as usize), mesh.bounds()))
        .collect()
}

fn render<S: Settings>(mesh: &Mesh<'_>, camera: &Camera, model: &Mat4) -> (Image<Rgb565>, FrameStats) {
    let mut r: HostRenderer<Rgb565, 3, S> = HostRenderer::new(320, 240, 16, 8192, 16384, Rgb565::BLACK).unwrap();
    let material = Material::new(Gouraud).with_color(Rgb888::new(255, 160, 0));
    let mut frame = r.begin_frame(camera, &Lights::default(), Rgb565::BLACK);
    frame.draw(mesh, model, &material).unwrap();
    let mut img = Image::new(320, 240, Rgb565::MAGENTA);
    let Ok(stats) = frame.finish(&mut img);
    (img, stats)
}

/// Pixels that differ with and without planes, and the queued triangles
/// fewer with them, from `camera`.
fn frames_apart<S: Settings>(mesh: &Mesh<'_>, planes: &[FacePlane], camera: &Camera, model: &Mat4) -> (usize, u32) {
    let with = mesh.with_face_planes(planes).unwrap();
    let (a, sa) = render::<S>(mesh, camera, model);
    let (b, sb) = render::<S>(&with, camera, model);
    (a.pixels.iter().zip(&b.pixels).filter(|(p, q)| p != q).count(), sa.queued - sb.queued)
}

/// Eyes around a mesh of radius `r`: outside, inside its bounds, at its
/// surface, far away.
const EYES: [(f32, f32, f32); 6] =
    [(0.0, 0.5, -4.0), (3.0, -2.0, 1.5), (0.2, 0.1, -0.3), (1.1, 0.0, 0.0), (-40.0, 25.0, 60.0), (0.0, 3.0, 0.01)];

fn same_frames<S: Settings>(mesh: &Mesh<'_>, planes: &[FacePlane], name: &str) {
    let with = mesh.with_face_planes(planes).unwrap();
    let models = [Mat4::IDENTITY, Mat4::rotation_y(0.7) * Mat4::scaling(Vec3::new(-1.0, 1.3, 0.8))];
    let b = mesh.bounds();
    let mut drawn = 0;
    for (e, &(x, y, z)) in EYES.iter().enumerate() {
        for (m, model) in models.iter().enumerate() {
            let camera = Camera::looking_at(b.center + Vec3::new(x, y, z) * b.radius, b.center + Vec3::new(0.1, 0.0, 0.0) * b.radius);
            let (a, sa) = render::<S>(mesh, &camera, model);
            let (b, sb) = render::<S>(&with, &camera, model);
            let differ = a.pixels.iter().zip(&b.pixels).filter(|(p, q)| p != q).count();
            assert_eq!(differ, 0, "{name}, eye {e}, model {m}: {differ} pixels differ with face planes");
            // Far away, a back face smaller than the snapping error can
            // snap to a front winding and be queued (covering no pixel
            // here); culled in model space, it is not. Nothing else
            // changes.
            let fewer = sa.queued.checked_sub(sb.queued);
            // Every back face is counted, also those the face loop skips
            // (by the front faces' bit set) without looking at them.
            assert!(sb.back_facing >= sa.back_facing && sb.triangles == sa.triangles, "{name}, eye {e}, model {m}: {sa:?} / {sb:?}");
            // Unclipped, each triangle is counted once, whichever test
            // drops it.
            let once = |s: &FrameStats| s.back_facing + s.degenerate + s.off_screen + s.invalid + s.queued;
            if sa.clipped == 0 && sb.clipped == 0 {
                assert_eq!(once(&sa), sa.triangles, "{name}, eye {e}, model {m}: {sa:?}");
                assert_eq!(once(&sb), sb.triangles, "{name}, eye {e}, model {m}: {sb:?}");
            }
            assert!(fewer.is_some_and(|k| k <= sa.queued / 50 + 1), "{name}, eye {e}, model {m}: {sa:?} / {sb:?}");
            drawn += sa.queued;
        }
    }
    assert!(drawn > 100, "{name}: the cameras see too little ({drawn} triangles)");
}

static TORUS: MeshData<{ soft3d::mesh::torus_vertex_count(24, 12) }, { soft3d::mesh::torus_index_count(24, 12) }> =
    MeshData::torus(24, 12, 1.0, 0.35);
static SPHERE: MeshData<{ soft3d::mesh::sphere_vertex_count(16, 10) }, { soft3d::mesh::sphere_index_count(16, 10) }> =
    MeshData::uv_sphere(16, 10, 1.0);

/// 5,120 faces: past the 2,048 whose culling the face loop reads from a
/// bit set; the rest go by their vertices' flags.
static LARGE_TORUS: MeshData<{ soft3d::mesh::torus_vertex_count(64, 40) }, { soft3d::mesh::torus_index_count(64, 40) }> =
    MeshData::torus(64, 40, 1.0, 0.35);

#[test]
fn face_planes_leave_frames_unchanged() {
    for (name, mesh) in [("torus", TORUS.mesh()), ("sphere", SPHERE.mesh()), ("large torus", LARGE_TORUS.mesh())] {
        let planes = planes_of(&mesh);
        same_frames::<FloatingPoint>(&mesh, &planes, name);
        same_frames::<FixedPoint>(&mesh, &planes, name);
    }
}

#[test]
fn face_planes_of_other_positions_are_rejected() {
    let mesh = TORUS.mesh();
    let mut planes = planes_of(&mesh);
    assert_eq!(
        mesh.with_face_planes(&planes[1..]).unwrap_err(),
        MeshError::FacePlaneCount { planes: planes.len() - 1, triangles: mesh.triangle_count() }
    );
    planes[7][3] += 1;
    assert_eq!(mesh.with_face_planes(&planes).unwrap_err(), MeshError::FacePlane(7));
    assert_eq!(MeshError::FacePlane(7).to_string(), "face plane 7 is not the plane of triangle 7");
}

#[test]
fn face_planes_leave_the_blender_exports_unchanged() {
    for file in ["torus.babylon", "monkey.babylon"] {
        let path = format!("{}/../shared/assets/{file}", env!("CARGO_MANIFEST_DIR"));
        let scene = match soft3d::host::scene::HostScene::load(&path) {
            Ok(scene) => scene,
            Err(e) => {
                println!("skipped: {path} is not available ({e})");
                continue;
            }
        };
        for owned in &scene.meshes {
            // The host scene's mesh has planes (as the firmware's baked
            // one): here, the same arrays without.
            assert_eq!(owned.mesh().face_planes(), Some(&owned.planes[..]));
            let mesh = Mesh::new(&owned.positions, &owned.normals, &owned.indices).unwrap();
            let planes = planes_of(&mesh);
            same_frames::<FloatingPoint>(&mesh, &planes, file);
            same_frames::<FixedPoint>(&mesh, &planes, file);
            // Quantized to i16 as `soft3d-bake --quantize i16` does (the
            // benchmark's `torus.babylon-i16`): its planes are those of the
            // positions it reads (accepted, not dropped), and leave its
            // frames unchanged too.
            let quantized = owned.quantized().unwrap();
            assert_eq!(quantized.mesh().face_planes(), Some(&quantized.planes[..]));
            let steps = quantized.steps.mesh(&owned.indices).unwrap();
            assert_eq!(steps.vertex_count(), mesh.vertex_count());
            same_frames::<FixedPoint>(&steps, &quantized.planes, file);
            // Coarse snapping can turn a back face front-facing: the
            // screen-space test alone then queues it, and it may cover a
            // pixel or two. Culled in model space, it is not drawn.
            let camera = scene.camera_or_default();
            let apart = [
                frames_apart::<Precision<Fixed, 0>>(&mesh, &planes, &camera, &owned.model),
                frames_apart::<Precision<Fixed, 1>>(&mesh, &planes, &camera, &owned.model),
                frames_apart::<Precision<Fixed, 2>>(&mesh, &planes, &camera, &owned.model),
            ];
            println!("{file}: pixels and triangles apart at 0, 1, 2 sub-pixel bits: {apart:?}");
            assert!(apart.iter().all(|&(pixels, triangles)| pixels <= 4 && triangles <= 8), "{file}: {apart:?}");
            assert_eq!(apart[2].0, 0, "{file}: {apart:?}");
        }
    }
}
