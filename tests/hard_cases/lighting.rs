//! Category 8, lighting: zero and non-unit normals, a point light on the
//! surface, light along the surface, over-bright light. Each lit effect
//! (Flat, Gouraud, Phong, Blinn-Phong) must give the stated color at every
//! covered pixel: finite, clamped, never a NaN turned into a stray channel.

use super::depth::{all_modes, mode};
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use soft3d::effect::{BlinnPhong, Effect, Flat, Gouraud, Phong};
use soft3d::host::Image;
use soft3d::math::{Mat4, Vec3};
use soft3d::mesh::Mesh;
use soft3d::{Camera, Cull, DirectionalLight, HostRenderer, Lights, Material, PointLight, Settings};

const BG: Rgb888 = Rgb888::new(0, 0, 255);
const N: usize = 24;

/// A 2×2 quad in the plane z = 0 facing the camera at z = -3 (its face
/// normal is -z), with the given vertex normals, drawn white with `effect`
/// under `lights` and placed by `model`.
fn render<S: Settings, E: Effect>(effect: E, normals: [Vec3; 4], lights: &Lights, model: &Mat4) -> Image<Rgb888> {
    let p = [Vec3::new(-1.0, 1.0, 0.0), Vec3::new(1.0, 1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(-1.0, -1.0, 0.0)];
    let i = [0u16, 1, 2, 0, 2, 3];
    let mesh = Mesh::new(&p, &normals, &i).unwrap();
    let material = Material::new(effect).with_color(Rgb888::WHITE).with_cull(Cull::None);
    let mut r: HostRenderer<Rgb888, 6, S> = HostRenderer::new(N, N, 8, 16, 16, BG).unwrap();
    let mut frame = r.begin_frame(&Camera::looking_at(Vec3::new(0.0, 0.0, -3.0), Vec3::ZERO), lights, BG);
    frame.draw(&mesh, model, &material).unwrap();
    let mut img = Image::new(N as u32, N as u32, BG);
    let Ok(_) = frame.finish(&mut img);
    img
}

/// White lit by `light` in [0, 1] as the effects round it: `light · 255`
/// to nearest.
fn gray(light: f64) -> Rgb888 {
    let v = (light.clamp(0.0, 1.0) * 255.0 + 0.5).floor() as u8;
    Rgb888::new(v, v, v)
}

/// Every covered pixel is `want` (and the quad covers most of the frame).
fn assert_uniform(img: &Image<Rgb888>, want: Rgb888, what: &str) {
    let covered: Vec<Rgb888> = img.pixels.iter().copied().filter(|&c| c != BG).collect();
    assert!(covered.len() > 150, "{what}: only {} pixels covered", covered.len());
    if let Some(bad) = covered.iter().find(|&&c| c != want) {
        panic!("{what}: found {bad:?}, want {want:?} everywhere");
    }
}

/// Runs `check(effect name, image)` for each lit effect.
fn each_effect<S: Settings>(normals: [Vec3; 4], lights: &Lights, model: &Mat4, check: impl Fn(&str, &Image<Rgb888>)) {
    check("flat", &render::<S, _>(Flat, normals, lights, model));
    check("gouraud", &render::<S, _>(Gouraud, normals, lights, model));
    check("phong", &render::<S, _>(Phong::new(), normals, lights, model));
    check("blinn-phong", &render::<S, _>(BlinnPhong::with_specular(Rgb888::WHITE, 8.0), normals, lights, model));
}

const TOWARD_CAMERA: Vec3 = Vec3::new(0.0, 0.0, -1.0);

/// Ambient 0.12 and a directional light of 0.7 whose direction to the
/// light makes N·L = 0.6 with the quad's normal: lit 0.54 in all.
fn oblique() -> Lights {
    Lights {
        ambient: Vec3::new(0.12, 0.12, 0.12),
        point: None,
        directional: Some(DirectionalLight { direction: Vec3::new(0.8, 0.0, 0.6), color: Vec3::new(0.7, 0.7, 0.7) }),
    }
}

/// Models that take both vertex paths: lit in model space (a similarity)
/// and in world space (non-uniform scale, normals through the normal matrix).
fn models() -> [Mat4; 2] {
    [Mat4::translation(Vec3::new(0.1, 0.0, 0.0)), Mat4::scaling(Vec3::new(0.9, 0.8, 1.0))]
}

#[test]
fn zero_length_normals_get_ambient_light_only() {
    // Flat lights its face normal (from the positions), so it is fully lit;
    // the per-vertex and per-pixel effects see no normal: ambient 0.12.
    fn case<S: Settings>() {
        for model in models() {
            each_effect::<S>([Vec3::ZERO; 4], &oblique(), &model, |name, img| {
                let want = if name == "flat" { gray(0.12 + 0.7 * 0.6) } else { gray(0.12) };
                assert_uniform(img, want, &format!("{} {name}", mode::<S>()));
            });
        }
    }
    all_modes!(case);
}

#[test]
fn normals_of_any_length_light_like_unit_normals() {
    // Normals toward the camera of lengths 3, 0.5, 0.01 and 10: only their
    // direction counts, N·L = 0.6, lit 0.12 + 0.7 · 0.6 = 0.54. Blinn-Phong
    // adds a highlight: it must equal its own rendering with unit normals.
    fn case<S: Settings>() {
        let scaled = [3.0, 0.5, 0.01, 10.0].map(|k| TOWARD_CAMERA * k);
        for model in models() {
            let unit = render::<S, _>(BlinnPhong::with_specular(Rgb888::WHITE, 8.0), [TOWARD_CAMERA; 4], &oblique(), &model);
            each_effect::<S>(scaled, &oblique(), &model, |name, img| {
                let what = format!("{} {name}", mode::<S>());
                if name == "blinn-phong" {
                    assert_eq!(img.pixels, unit.pixels, "{what}");
                    assert!(img.pixels.iter().all(|c| c == &BG || c.r() >= gray(0.54).r()), "{what}: highlights only add light");
                } else {
                    assert_uniform(img, gray(0.54), &what);
                }
            });
        }
    }
    all_modes!(case);
}

#[test]
fn a_point_light_on_a_vertex_lights_nothing_but_ambient() {
    // The light sits on a corner of the quad, so its direction from every
    // point of the quad lies in the quad: N·L = 0 (and 0/0 at the corner
    // itself must not become NaN). Ambient 0.3 only.
    fn case<S: Settings>() {
        let lights = Lights {
            ambient: Vec3::new(0.3, 0.3, 0.3),
            point: Some(PointLight { position: Vec3::new(1.0, 1.0, 0.0), color: Vec3::new(5.0, 5.0, 5.0) }),
            directional: None,
        };
        each_effect::<S>([TOWARD_CAMERA; 4], &lights, &Mat4::IDENTITY, |name, img| {
            assert_uniform(img, gray(0.3), &format!("{} {name}", mode::<S>()));
        });
    }
    all_modes!(case);
}

#[test]
fn light_along_the_surface_or_without_direction_adds_nothing() {
    // A directional light travelling along the quad (N·L = 0), and one
    // with a zero direction vector: ambient 0.3 only.
    fn case<S: Settings>() {
        for direction in [Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, -1.0, 0.0), Vec3::ZERO] {
            let lights = Lights {
                ambient: Vec3::new(0.3, 0.3, 0.3),
                point: None,
                directional: Some(DirectionalLight { direction, color: Vec3::new(4.0, 4.0, 4.0) }),
            };
            each_effect::<S>([TOWARD_CAMERA; 4], &lights, &Mat4::IDENTITY, |name, img| {
                assert_uniform(img, gray(0.3), &format!("{} {name} direction {direction:?}", mode::<S>()));
            });
        }
    }
    all_modes!(case);
}

#[test]
fn over_bright_light_saturates_at_the_material_color() {
    // Ambient 3 plus lights of 4: clamped to the white material, 255.
    fn case<S: Settings>() {
        let lights = Lights {
            ambient: Vec3::new(3.0, 3.0, 3.0),
            point: Some(PointLight { position: Vec3::new(0.0, 0.0, -2.0), color: Vec3::new(4.0, 4.0, 4.0) }),
            directional: Some(DirectionalLight { direction: Vec3::new(0.0, 0.0, 1.0), color: Vec3::new(4.0, 4.0, 4.0) }),
        };
        each_effect::<S>([TOWARD_CAMERA; 4], &lights, &Mat4::IDENTITY, |name, img| {
            assert_uniform(img, Rgb888::WHITE, &format!("{} {name}", mode::<S>()));
        });
    }
    all_modes!(case);
}
