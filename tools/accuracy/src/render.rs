//! The core's side: a scene rendered with one configuration of the
//! precision choices (type parameters, as a firmware would pick them),
//! in three passes that share the geometry: the colors, which object is
//! visible at each pixel, and the interpolated texture coordinates.

use crate::scenes::{Scene, HEIGHT, WIDTH};
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use soft3d::effect::{Color, Effect, Gouraud, Phong, Textured, VertexColor, VertexInput, MAX_VARYINGS};
use soft3d::host::Image;
use soft3d::material::Perspective;
use soft3d::math::Interp;
use soft3d::mesh::Mesh;
use soft3d::scene::Lighting;
use soft3d::texture::{Filter, Repeat};
use soft3d::{HostRenderer, Material, Settings};

/// What the core drew.
pub struct CoreImages {
    /// Colors.
    pub color: Vec<Rgb565>,
    /// The object visible at each pixel.
    pub object: Vec<Option<usize>>,
    /// The triangle visible at each pixel, counting through the objects.
    pub triangle: Vec<Option<usize>>,
    /// Texture coordinates (texel units) where a textured object is visible.
    pub uv: Vec<Option<[f64; 2]>>,
}

/// Varyings the study's renderer stores (Phong needs six).
const V: usize = 6;

fn renderer<C: Color, S: Settings>(scene: &Scene) -> HostRenderer<C, V, S> {
    let verts: usize = scene.objects.iter().map(|o| o.positions.len() + o.indices.len()).sum();
    let tris: usize = scene.objects.iter().map(|o| o.indices.len()).sum::<usize>() + 16;
    HostRenderer::new(WIDTH, HEIGHT, 16, verts + 64, tris, C::BLACK).expect("valid sizes")
}

fn mesh<'a>(o: &'a crate::scenes::Object) -> Mesh<'a> {
    let m = Mesh::new(&o.positions, &o.normals, &o.indices).expect("a valid mesh");
    let m = match &o.uvs {
        Some(uv) => m.with_uvs(uv).expect("one UV per vertex"),
        None => m,
    };
    match &o.planes {
        Some(planes) => m.with_face_planes(planes).expect("the mesh's own planes"),
        None => m,
    }
}

/// An object index as a color that survives the trip to RGB565 exactly
/// (through the unlit vertex-color effect, which rounds `c · max / 255`).
fn id_color(k: usize) -> Rgb888 {
    let id = k + 1;
    let up = |v: usize, max: usize| ((v * 255 + max / 2) / max) as u8;
    Rgb888::new(up(id & 31, 31), up((id >> 5) & 63, 63), 0)
}

fn id_of(c: Rgb565) -> Option<usize> {
    let id = c.r() as usize | (c.g() as usize) << 5;
    id.checked_sub(1)
}

/// Renders `scene` with interpolation and sub-pixel bits `S`, perspective
/// mode `P` and texture filter `F`; untextured objects lit per vertex
/// (Gouraud) or, with `phong`, per pixel.
pub fn render<S: Settings, P: Perspective, F: Filter>(scene: &Scene, phong: bool) -> CoreImages {
    let textures: Vec<_> = scene.textures.iter().map(|t| t.texture().expect("a valid texture")).collect();
    let meshes: Vec<Mesh<'_>> = scene.objects.iter().map(mesh).collect();

    // Colors.
    let mut r = renderer::<Rgb565, S>(scene);
    let textured: Vec<Option<Material<Textured<'_, F, Repeat>, P>>> = scene
        .objects
        .iter()
        .map(|o| o.texture.map(|t| Material::new(Textured::<F, Repeat>::new(textures[t])).with_color(o.color).with_perspective::<P>()))
        .collect();
    let gouraud: Vec<_> = scene.objects.iter().map(|o| Material::new(Gouraud).with_color(o.color).with_perspective::<P>()).collect();
    let per_pixel: Vec<_> = scene.objects.iter().map(|o| Material::new(Phong::new()).with_color(o.color).with_perspective::<P>()).collect();
    let mut frame = r.begin_frame(&scene.camera, &scene.lights, Rgb565::BLACK);
    for (k, o) in scene.objects.iter().enumerate() {
        let res = match (&textured[k], phong) {
            (Some(t), _) => frame.draw(&meshes[k], &o.model, t),
            (None, false) => frame.draw(&meshes[k], &o.model, &gouraud[k]),
            (None, true) => frame.draw(&meshes[k], &o.model, &per_pixel[k]),
        };
        res.expect("buffers sized for the scene");
    }
    let mut color = Image::new(WIDTH as u32, HEIGHT as u32, Rgb565::BLACK);
    let Ok(_) = frame.finish(&mut color);

    // Which object and which triangle is visible: each drawn in its own
    // unlit color (triangles from unshared vertices).
    let object =
        id_pass::<S, P>(scene, |k, o| (o.positions.clone(), o.normals.clone(), o.indices.clone(), vec![id_color(k); o.positions.len()]));
    let mut first = 0;
    let triangle = id_pass::<S, P>(scene, |_, o| {
        let idx = &o.indices;
        let positions = idx.iter().map(|&i| o.positions[i as usize]).collect();
        let normals = idx.iter().map(|&i| o.normals[i as usize]).collect();
        let colors = (0..idx.len()).map(|i| id_color(first + i / 3)).collect();
        first += idx.len() / 3;
        (positions, normals, (0..idx.len() as u16).collect(), colors)
    });

    // Texture coordinates, interpolated exactly as `Textured` does: u and
    // v in a pass each, 23 bits of the texture's side per pass.
    let mut uv = vec![None; WIDTH * HEIGHT];
    if scene.textured() {
        let u = uv_pass::<S, P, 0>(scene, &meshes);
        let v = uv_pass::<S, P, 1>(scene, &meshes);
        for i in 0..WIDTH * HEIGHT {
            if let (Some(u), Some(v)) = (u[i], v[i]) {
                uv[i] = Some([u, v]);
            }
        }
    }
    CoreImages { color: color.pixels, object, triangle, uv }
}

/// Arrays of a mesh drawn for identification: positions, normals,
/// indices, one color per vertex.
type IdMesh = (Vec<soft3d::math::Vec3>, Vec<soft3d::math::Vec3>, Vec<u16>, Vec<Rgb888>);

/// Draws every object unlit in the colors `arrays` gives it and reads the
/// ids back.
fn id_pass<S: Settings, P: Perspective>(
    scene: &Scene,
    mut arrays: impl FnMut(usize, &crate::scenes::Object) -> IdMesh,
) -> Vec<Option<usize>> {
    let arrays: Vec<IdMesh> = scene.objects.iter().enumerate().map(|(k, o)| arrays(k, o)).collect();
    let meshes: Vec<Mesh<'_>> =
        arrays.iter().map(|(p, n, i, c)| Mesh::new(p, n, i).and_then(|m| m.with_colors(c)).expect("a valid mesh")).collect();
    let unlit = Material::new(VertexColor).with_perspective::<P>();
    let mut r = renderer::<Rgb565, S>(scene);
    let mut frame = r.begin_frame(&scene.camera, &scene.lights, Rgb565::BLACK);
    for (k, o) in scene.objects.iter().enumerate() {
        frame.draw(&meshes[k], &o.model, &unlit).expect("buffers sized for the scene");
    }
    let mut img = Image::new(WIDTH as u32, HEIGHT as u32, Rgb565::BLACK);
    let Ok(_) = frame.finish(&mut img);
    img.pixels.iter().map(|c| id_of(*c)).collect()
}

/// One texture coordinate (`AXIS` 0: u, 1: v) of the textured objects, in
/// texels, wrapped into the texture.
fn uv_pass<S: Settings, P: Perspective, const AXIS: usize>(scene: &Scene, meshes: &[Mesh<'_>]) -> Vec<Option<f64>> {
    let probes: Vec<Option<Material<UvProbe<AXIS>, P>>> = scene
        .objects
        .iter()
        .map(|o| o.texture.map(|t| Material::new(UvProbe::new(scene.textures[t].width, scene.textures[t].height)).with_perspective::<P>()))
        .collect();
    let mut r = renderer::<Rgb888, S>(scene);
    let mut frame = r.begin_frame(&scene.camera, &scene.lights, Rgb888::BLACK);
    for (k, o) in scene.objects.iter().enumerate() {
        if let Some(p) = &probes[k] {
            frame.draw(&meshes[k], &o.model, p).expect("buffers sized for the scene");
        }
    }
    let mut img = Image::new(WIDTH as u32, HEIGHT as u32, Rgb888::BLACK);
    let Ok(_) = frame.finish(&mut img);
    let side = scene.textures.iter().map(|t| t.width.max(t.height)).max().unwrap_or(1);
    img.pixels.iter().map(|c| UvProbe::<AXIS>::decode(*c, side)).collect()
}

/// A diagnostic effect: one texture coordinate `Textured` would sample
/// with (`AXIS` 0: u, 1: v), wrapped into the texture, written as the
/// pixel's color: 23 bits of fraction of the texture's side, and a flag
/// bit that marks a written pixel.
#[derive(Clone, Copy, Debug)]
pub struct UvProbe<const AXIS: usize> {
    width: f32,
    height: f32,
}

/// Steps of the probe per texture side.
const PROBE_STEPS: f64 = (1 << 23) as f64;

impl<const AXIS: usize> UvProbe<AXIS> {
    fn new(width: usize, height: usize) -> Self {
        Self { width: width as f32, height: height as f32 }
    }

    fn decode(c: Rgb888, side: usize) -> Option<f64> {
        let bits = (c.r() as u32) << 16 | (c.g() as u32) << 8 | c.b() as u32;
        if bits == 0 {
            return None;
        }
        Some((bits & 0x7F_FFFF) as f64 / PROBE_STEPS * side as f64)
    }
}

impl<const AXIS: usize> Effect for UvProbe<AXIS> {
    type Uniforms<S: Interp> = ();
    fn uniforms<S: Interp>(&self, _: &Lighting, _: Rgb888) {}
    const VARYINGS: usize = 2;
    const LIT_VERTICES: bool = false;
    const NAME: &'static str = "uv-probe";

    fn ranges<C: Color>() -> [(f32, f32); MAX_VARYINGS] {
        let mut r = [(0.0, 0.0); MAX_VARYINGS];
        // The same ranges and periods as `Textured`.
        r[..2].copy_from_slice(&[(-30_000.0, 30_000.0), (-30_000.0, 30_000.0)]);
        r
    }

    fn periods(&self) -> [f32; MAX_VARYINGS] {
        let mut p = [0.0; MAX_VARYINGS];
        p[0] = self.width;
        p[1] = self.height;
        p
    }

    fn vertex<C: Color>(&self, v: &VertexInput, _: &Lighting) -> [f32; MAX_VARYINGS] {
        let mut out = [0.0; MAX_VARYINGS];
        out[..2].copy_from_slice(&[v.uv.x * self.width, v.uv.y * self.height]);
        out
    }

    fn shade<C: Color, S: Interp>(&self, _: &(), _: C, v: &[S; MAX_VARYINGS], _: C) -> C {
        // All textures of a scene share the side used to decode (the
        // largest); the others are scaled to it.
        let size = if AXIS == 0 { self.width } else { self.height };
        let t = (v[AXIS].to_f32() as f64).rem_euclid(size as f64) / size as f64;
        let bits = 1 << 23 | ((t * PROBE_STEPS) as u32).min((1 << 23) - 1);
        C::from_channels((bits >> 16) as u8, (bits >> 8) as u8, bits as u8)
    }
}
