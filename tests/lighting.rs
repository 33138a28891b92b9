//! Per-pixel lighting against an `f64` reference: a lit sphere ray-cast
//! exactly, compared with the Gouraud and Phong renderings of the built-in
//! sphere mesh; Blinn-Phong highlights where the half vector says.

use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use soft3d::effect::{BlinnPhong, Effect, Gouraud, MonoGouraud, Phong};
use soft3d::host::Image;
use soft3d::math::{Mat4, Vec3};
use soft3d::scenes::SPHERE;
use soft3d::{Camera, DirectionalLight, FixedPoint, FloatingPoint, HostRenderer, Lights, Material, Settings};

const W: usize = 96;
const H: usize = 96;
const RADIUS: f64 = 0.8; // the built-in sphere's radius

fn lights() -> Lights {
    Lights {
        ambient: Vec3::new(0.1, 0.1, 0.1),
        point: None,
        directional: Some(DirectionalLight { direction: Vec3::new(1.0, -0.6, 1.2), color: Vec3::new(0.9, 0.9, 0.9) }),
    }
}

fn camera() -> Camera {
    Camera::looking_at(Vec3::new(0.0, 0.0, -3.0), Vec3::ZERO)
}

fn render<S: Settings, E: Effect>(effect: E) -> Image<Rgb888> {
    render_in::<Rgb888, S, E>(effect, Rgb888::WHITE)
}

/// The sphere in display color `C` with `effect` and material `color`.
fn render_in<C: soft3d::effect::Color, S: Settings, E: Effect>(effect: E, color: Rgb888) -> Image<C> {
    let material = Material::new(effect).with_color(color);
    let mut r: HostRenderer<C, 6, S> = HostRenderer::new(W, H, 16, 1024, 1024, C::BLACK).unwrap();
    let mut frame = r.begin_frame(&camera(), &lights(), C::BLACK);
    frame.draw(&SPHERE, &Mat4::IDENTITY, &material).unwrap();
    let mut img = Image::new(W as u32, H as u32, C::BLACK);
    let Ok(_) = frame.finish(&mut img);
    img
}

/// The exact sphere, lit per pixel: `None` where the ray misses it.
fn reference(px: usize, py: usize) -> Option<(f64, [f64; 3])> {
    let t = (0.8f64 / 2.0).tan(); // the camera's default field of view
    let d = [((px as f64 + 0.5) / W as f64 * 2.0 - 1.0) * t, (1.0 - (py as f64 + 0.5) / H as f64 * 2.0) * t, 1.0];
    let o = [0.0, 0.0, -3.0];
    // |o + k d|² = r²
    let a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    let b = 2.0 * (o[2] * d[2]);
    let c = o[2] * o[2] - RADIUS * RADIUS;
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None;
    }
    let k = (-b - disc.sqrt()) / (2.0 * a);
    let p = [o[0] + k * d[0], o[1] + k * d[1], o[2] + k * d[2]];
    let n = [p[0] / RADIUS, p[1] / RADIUS, p[2] / RADIUS];
    let l = {
        let v: [f64; 3] = [-1.0, 0.6, -1.2];
        let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] / len, v[1] / len, v[2] / len]
    };
    let ndl = (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]).max(0.0);
    Some((0.1 + 0.9 * ndl, p))
}

/// Mean and largest error (in 8-bit levels) over the pixels away from the
/// silhouette (where the mesh's polygon outline differs from the circle).
fn error(img: &Image<Rgb888>) -> (f64, u8) {
    let (mut sum, mut n, mut worst) = (0.0, 0, 0u8);
    for y in 0..H {
        for x in 0..W {
            let Some((lit, p)) = reference(x, y) else { continue };
            // Skip the rim: the tessellated outline is inside the true one.
            if p[2] > -0.25 {
                continue;
            }
            let got = img.get(x as u32, y as u32);
            if got == Rgb888::BLACK {
                continue; // not covered by the mesh: a coverage, not a lighting, difference
            }
            let want = (lit.min(1.0) * 255.0).round() as i32;
            let got = got.g() as i32;
            let e = (got - want).unsigned_abs() as u8;
            sum += e as f64;
            n += 1;
            worst = worst.max(e);
        }
    }
    (sum / n as f64, worst)
}

#[test]
fn phong_is_closer_to_the_exact_sphere_than_gouraud() {
    for float in [false, true] {
        let (gouraud, phong) = if float {
            (error(&render::<FloatingPoint, _>(Gouraud)), error(&render::<FloatingPoint, _>(Phong::new())))
        } else {
            (error(&render::<FixedPoint, _>(Gouraud)), error(&render::<FixedPoint, _>(Phong::new())))
        };
        eprintln!("float {float}: Gouraud mean {:.2} max {}, Phong mean {:.2} max {}", gouraud.0, gouraud.1, phong.0, phong.1);
        assert!(phong.0 < gouraud.0, "Phong should be nearer the exact sphere on average");
        // Measured: mean 1.2 levels, largest 26 (at the terminator, where the
        // tessellated surface and the sphere are lit at different points).
        assert!(phong.0 <= 1.5 && phong.1 <= 30, "Phong error: mean {:.2}, max {}", phong.0, phong.1);
    }
}

#[test]
fn blinn_phong_highlight_sits_at_the_half_vector() {
    let img = render::<FixedPoint, _>(BlinnPhong::with_specular(Rgb888::new(255, 255, 255), 40.0));
    let diffuse = render::<FixedPoint, _>(Phong::new());
    // The brightest pixel of the highlight image, and where the exact
    // highlight is: the sphere point whose normal is the half vector of
    // the light and view directions (seen from the pixel's own ray).
    let (mut n, mut cx, mut cy) = (0, 0.0f32, 0.0f32);
    for y in 0..H {
        for x in 0..W {
            let c = img.get(x as u32, y as u32);
            if c == Rgb888::WHITE {
                (n, cx, cy) = (n + 1, cx + x as f32 + 0.5, cy + y as f32 + 0.5);
            }
            let d = diffuse.get(x as u32, y as u32);
            assert!(c.g() >= d.g(), "highlights only add light ({x}, {y})");
        }
    }
    assert!(n > 3, "the highlight saturates a few pixels");
    let at = (cx / n as f32, cy / n as f32);
    // Half vector of l = (-1, 0.6, -1.2)/|..| and v ≈ (0, 0, -1).
    let l = Vec3::new(-1.0, 0.6, -1.2).normalize_or_zero();
    let h = (l + Vec3::new(0.0, 0.0, -1.0)).normalize_or_zero();
    let p = h * RADIUS as f32;
    // Project p: x right, y up, depth 3 + p.z.
    let t = (0.4f32).tan();
    let sx = ((p.x / (3.0 + p.z)) / t + 1.0) * 0.5 * W as f32;
    let sy = (1.0 - (p.y / (3.0 + p.z)) / t) * 0.5 * H as f32;
    let (dx, dy) = (at.0 - sx, at.1 - sy);
    assert!(dx * dx + dy * dy < 16.0, "highlight centered at {at:?}, expected near ({sx:.1}, {sy:.1})");
}

/// Under white light, one interpolated level times the material color
/// gives what Gouraud's three channels give: the same pixels covered, each
/// channel within one level, and most pixels exactly equal.
#[test]
fn mono_gouraud_matches_gouraud_under_white_light_within_a_level() {
    fn compare<S: Settings>(color: Rgb888) {
        let (rgb, mono) = (render_in::<Rgb565, S, _>(Gouraud, color), render_in::<Rgb565, S, _>(MonoGouraud, color));
        let (mut covered, mut equal) = (0, 0);
        for y in 0..H as u32 {
            for x in 0..W as u32 {
                let (a, b) = (rgb.get(x, y), mono.get(x, y));
                assert_eq!(
                    a == Rgb565::BLACK,
                    b == Rgb565::BLACK,
                    "coverage differs at ({x}, {y}), {color:?}, {}",
                    std::any::type_name::<S>()
                );
                let off = |p: u8, q: u8| p.abs_diff(q);
                let worst = off(a.r(), b.r()).max(off(a.g(), b.g())).max(off(a.b(), b.b()));
                assert!(worst <= 1, "({x}, {y}): {a:?} against {b:?}, {color:?}, {}", std::any::type_name::<S>());
                covered += (a != Rgb565::BLACK) as u32;
                equal += (a != Rgb565::BLACK && a == b) as u32;
            }
        }
        assert!(covered > 2500, "the sphere covers {covered} pixels");
        assert!(equal * 100 >= covered * 85, "{equal} of {covered} pixels equal, {color:?}, {}", std::any::type_name::<S>());
    }
    for color in [Rgb888::WHITE, Rgb888::new(255, 140, 40), Rgb888::new(90, 220, 110), Rgb888::new(7, 0, 129)] {
        compare::<FixedPoint>(color);
        compare::<FloatingPoint>(color);
    }
}
