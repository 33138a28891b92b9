//! Texture mapping (bounds: at most 0.5% of pixels differ from the ray
//! cast with exact perspective, 1% with 16-pixel spans): exact texels on a
//! screen-aligned quad, and affine versus perspective-correct mapping of a
//! checkerboard seen at a grazing angle against an independent `f64`
//! ray-cast reference. Wrapping, clamping, odd sizes and bilinear borders
//! are hard cases: tests/hard_cases/texture.rs.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use soft3d::blend::Opaque;
use soft3d::effect::{ColorLight, GrayLight, LightModel, Textured};
use soft3d::host::Image;
use soft3d::material::{Affine, PerPixel, PerSpan, Perspective};
use soft3d::math::{Mat4, Vec2, Vec3};
use soft3d::mesh::Mesh;
use soft3d::texture::{Nearest, Repeat, Texture};
use soft3d::{Camera, Cull, DirectionalLight, FixedPoint, FloatingPoint, HostRenderer, Lights, Material, PointLight, Settings};

mod common;

const WHITE: u16 = 0xFFFF;
const BLACK: u16 = 0x0000;

fn raw(c: Rgb565) -> u16 {
    embedded_graphics::pixelcolor::IntoStorage::into_storage(c)
}

/// A 4×4 texture whose texels are all different.
fn distinct() -> Vec<u16> {
    (0..16u16).map(|i| (i << 11) | ((i * 3) << 5) | (31 - i)).collect()
}

fn both_modes(test: impl Fn(bool)) {
    test(false);
    test(true);
}

#[test]
fn nearest_texels_land_exactly_on_their_pixels() {
    let texels = distinct();
    let tex = Texture::new(&texels, 4, 4).unwrap();
    both_modes(|float| {
        let img = if float {
            common::render_textured_quad::<FloatingPoint, Nearest, Repeat>(tex, (0.0, 0.0), (1.0, 1.0), 32)
        } else {
            common::render_textured_quad::<FixedPoint, Nearest, Repeat>(tex, (0.0, 0.0), (1.0, 1.0), 32)
        };
        // Each texel covers an 8×8 block; row 0 of the texture is at the top.
        for y in 0..32 {
            for x in 0..32 {
                let want = texels[(y / 8) * 4 + x / 8];
                assert_eq!(raw(img.get(x as u32, y as u32)), want, "float {float} pixel {x},{y}");
            }
        }
    });
}

/// A checkerboard floor seen at a grazing angle: pixels whose color
/// differs from an `f64` ray cast, among the pixels the reference covers.
fn checker_mismatch<S: Settings, P: Perspective>() -> (usize, usize) {
    const W: usize = 160;
    const H: usize = 120;
    // A 2×2 checker repeated: u over [0, 8], v over [0, 32].
    let texels = [WHITE, BLACK, BLACK, WHITE];
    let tex = Texture::new(&texels, 2, 2).unwrap();
    let (x0, x1, z0, z1) = (-2.0f32, 2.0f32, 0.0f32, 16.0f32);
    let p = vec![Vec3::new(x0, 0.0, z1), Vec3::new(x1, 0.0, z1), Vec3::new(x1, 0.0, z0), Vec3::new(x0, 0.0, z0)];
    let n = vec![Vec3::new(0.0, 1.0, 0.0); 4];
    let (us, vs) = (8.0f32, 32.0f32);
    let uv = vec![Vec2::new(0.0, 0.0), Vec2::new(us, 0.0), Vec2::new(us, vs), Vec2::new(0.0, vs)];
    let idx = vec![0u16, 1, 2, 0, 2, 3];
    let mesh = Mesh::new(&p, &n, &idx).unwrap().with_uvs(&uv).unwrap();
    let material = Material::new(Textured::<Nearest, Repeat>::new(tex)).with_cull(Cull::None).with_perspective::<P>();
    let mut camera = Camera::looking_at(Vec3::new(0.0, 0.6, -1.0), Vec3::new(0.0, 0.0, 6.0));
    camera.near = 0.05;
    let mut r: HostRenderer<Rgb565, 5, S> = HostRenderer::new(W, H, 16, 64, 64, Rgb565::new(0, 63, 0)).unwrap();
    let mut frame = r.begin_frame(&camera, &Lights::UNLIT, Rgb565::new(0, 63, 0));
    frame.draw(&mesh, &Mat4::IDENTITY, &material).unwrap();
    let mut img = Image::new(W as u32, H as u32, Rgb565::BLACK);
    let Ok(_) = frame.finish(&mut img);

    // Reference: a ray through each pixel center, intersected with y = 0.
    let eye = [0.0f64, 0.6, -1.0];
    let target = [0.0f64, 0.0, 6.0];
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let norm = |a: [f64; 3]| {
        let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        [a[0] / l, a[1] / l, a[2] / l]
    };
    let cross = |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let fwd = norm(sub(target, eye));
    let right = norm(cross([0.0, 1.0, 0.0], fwd));
    let up = cross(fwd, right);
    let t = (camera.fov_y as f64 / 2.0).tan();
    let aspect = W as f64 / H as f64;
    let (mut covered, mut differ) = (0, 0);
    for py in 0..H {
        for px in 0..W {
            let sx = ((px as f64 + 0.5) / W as f64 * 2.0 - 1.0) * t * aspect;
            let sy = (1.0 - (py as f64 + 0.5) / H as f64 * 2.0) * t;
            let d = [fwd[0] + sx * right[0] + sy * up[0], fwd[1] + sx * right[1] + sy * up[1], fwd[2] + sx * right[2] + sy * up[2]];
            if d[1] >= 0.0 {
                continue;
            }
            let k = -eye[1] / d[1];
            let (x, z) = (eye[0] + k * d[0], eye[2] + k * d[2]);
            if x < x0 as f64 || x > x1 as f64 || z < z0 as f64 || z > z1 as f64 {
                continue;
            }
            let u = (x - x0 as f64) / (x1 - x0) as f64 * us as f64 * 2.0;
            let v = (z1 as f64 - z) / (z1 - z0) as f64 * vs as f64 * 2.0;
            let want = texels[(v.floor() as usize % 2) * 2 + u.floor() as usize % 2];
            covered += 1;
            differ += (raw(img.get(px as u32, py as u32)) != want) as usize;
        }
    }
    (differ, covered)
}

#[test]
fn perspective_correct_mapping_matches_the_ray_cast_and_affine_does_not() {
    for (name, (differ, covered), bound) in [
        ("fixed exact", checker_mismatch::<FixedPoint, PerPixel>(), 0.005),
        ("f32 exact", checker_mismatch::<FloatingPoint, PerPixel>(), 0.005),
        ("fixed span16", checker_mismatch::<FixedPoint, PerSpan<16>>(), 0.01),
        ("f32 span16", checker_mismatch::<FloatingPoint, PerSpan<16>>(), 0.01),
    ] {
        let share = differ as f64 / covered as f64;
        eprintln!("{name}: {differ} of {covered} pixels differ from the ray cast ({:.2}%)", share * 100.0);
        assert!(covered > 5000, "{name}: the floor should cover much of the image");
        assert!(share <= bound, "{name}: {differ} of {covered} differ");
    }
    let (differ, covered) = checker_mismatch::<FixedPoint, Affine>();
    let share = differ as f64 / covered as f64;
    eprintln!("fixed affine: {differ} of {covered} pixels differ ({:.2}%)", share * 100.0);
    assert!(share > 0.2, "affine mapping should visibly swim at this angle, {differ} of {covered} differ");
}

/// The baked crate, turned to show three lit faces, drawn with its texture
/// lit as `L` says by `lights` on a material of `color`.
fn lit_crate<S: Settings, L: LightModel>(lights: &Lights, color: Rgb888) -> Image<Rgb565> {
    use soft3d::scenes::crate_scene::{CRATE, CRATE_TEXTURE};
    let material =
        Material::new(Textured::<Nearest, Repeat, Opaque, L>::new(CRATE_TEXTURE)).with_color(color).with_perspective::<PerSpan<32>>();
    let camera = Camera::looking_at(Vec3::new(0.0, 1.5, -3.5), Vec3::new(0.0, 0.0, 0.0));
    let model = Mat4::rotation_y(0.7) * Mat4::rotation_x(0.3);
    let mut r: HostRenderer<Rgb565, 5, S> = HostRenderer::new(160, 120, 16, 64, 64, Rgb565::BLACK).unwrap();
    let mut frame = r.begin_frame(&camera, lights, Rgb565::BLACK);
    frame.draw(&CRATE, &model, &material).unwrap();
    let mut img = Image::new(160, 120, Rgb565::BLACK);
    let Ok(_) = frame.finish(&mut img);
    img
}

/// `lights` with each color replaced by its green channel in all three.
fn grayed(lights: &Lights) -> Lights {
    let gray = |c: Vec3| Vec3::new(c.y, c.y, c.y);
    let mut g = *lights;
    g.ambient = gray(g.ambient);
    if let Some(p) = g.point.as_mut() {
        p.color = gray(p.color);
    }
    if let Some(d) = g.directional.as_mut() {
        d.color = gray(d.color);
    }
    g
}

#[test]
fn gray_light_draws_the_color_light_image_of_the_green_channel() {
    // Colored lights: each channel differs, so the two models differ
    // unless the gray one is compared with the lights' green channel.
    let lights = Lights {
        ambient: Vec3::new(0.1, 0.15, 0.2),
        point: Some(PointLight { position: Vec3::new(3.0, 2.0, -3.0), color: Vec3::new(0.7, 0.4, 0.2) }),
        directional: Some(DirectionalLight { direction: Vec3::new(0.5, -0.8, 0.6), color: Vec3::new(0.3, 0.5, 0.6) }),
    };
    fn check<S: Settings>(lights: &Lights) {
        let name = <S::Interp as soft3d::math::Interp>::NAME;
        let count =
            |pixel: &dyn Fn(u32, u32) -> bool| (0..120).flat_map(|y| (0..160).map(move |x| (x, y))).filter(|&(x, y)| pixel(x, y)).count();
        for color in [Rgb888::WHITE, Rgb888::new(150, 150, 150)] {
            let gray = lit_crate::<S, GrayLight>(lights, color);
            let same = lit_crate::<S, ColorLight>(&grayed(lights), color);
            let colored = lit_crate::<S, ColorLight>(lights, color);
            let covered = count(&|x, y| gray.get(x, y) != Rgb565::BLACK);
            assert!(covered > 3000, "{name}: the crate covers {covered} pixels");
            assert!(gray == same, "{name}, {color:?}: gray light differs from the green channel's color light");
            let differ = count(&|x, y| gray.get(x, y) != colored.get(x, y));
            assert!(differ > covered / 2, "{name}: colored lights changed only {differ} of {covered} pixels");
        }
    }
    check::<FixedPoint>(&lights);
    check::<FloatingPoint>(&lights);
}
