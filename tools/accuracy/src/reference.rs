//! The yardstick: an exact reference renderer, written apart from the
//! core and sharing none of its code.
//!
//! Everything is `f64`. Triangles are clipped against the near and far
//! planes in homogeneous space, projected without snapping, and a pixel is
//! covered when its center is inside (the top-left rule on ties, as in the
//! core). Attributes use exact perspective-correct barycentrics at the
//! pixel center; lighting is evaluated exactly (per vertex for Gouraud, per
//! pixel for Phong) and textures are sampled exactly from the same texels
//! the core reads. The depth test is "less" on the exact window depth.

/// A vector of three `f64`.
pub type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn scale(a: V3, k: f64) -> V3 {
    [a[0] * k, a[1] * k, a[2] * k]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn normalize(a: V3) -> V3 {
    let l = dot(a, a).sqrt();
    if l > 0.0 && l.is_finite() {
        scale(a, 1.0 / l)
    } else {
        [0.0; 3]
    }
}

/// A 4×4 matrix, row-major, column vectors (`M * p`).
pub type M4 = [[f64; 4]; 4];

fn mul4(a: &M4, b: &M4) -> M4 {
    let mut m = [[0.0; 4]; 4];
    for (r, row) in m.iter_mut().enumerate() {
        for (c, v) in row.iter_mut().enumerate() {
            *v = (0..4).map(|k| a[r][k] * b[k][c]).sum();
        }
    }
    m
}

fn apply4(m: &M4, p: [f64; 4]) -> [f64; 4] {
    let mut o = [0.0; 4];
    for (r, v) in o.iter_mut().enumerate() {
        *v = (0..4).map(|k| m[r][k] * p[k]).sum();
    }
    o
}

/// The inverse transpose of the upper 3×3 (for normals), by cofactors.
fn normal_matrix(m: &M4) -> [[f64; 3]; 3] {
    let a = |r: usize, c: usize| m[r][c];
    let cof = |r: usize, c: usize| {
        let (r0, r1) = ([1, 0, 0][r], [2, 2, 1][r]);
        let (c0, c1) = ([1, 0, 0][c], [2, 2, 1][c]);
        let minor = a(r0, c0) * a(r1, c1) - a(r0, c1) * a(r1, c0);
        if (r + c).is_multiple_of(2) {
            minor
        } else {
            -minor
        }
    };
    let det: f64 = (0..3).map(|c| a(0, c) * cof(0, c)).sum();
    let mut n = [[0.0; 3]; 3];
    for (r, row) in n.iter_mut().enumerate() {
        for (c, v) in row.iter_mut().enumerate() {
            // (M^-1)^T = cofactor matrix / det.
            *v = cof(r, c) / det;
        }
    }
    n
}

/// A texture: texels as exact fractions of their channel maxima.
#[derive(Clone, Debug)]
pub struct RefTexture {
    /// Width in texels.
    pub width: usize,
    /// Height in texels.
    pub height: usize,
    /// Red, green, blue in [0, 1], row-major, row 0 at v = 0.
    pub texels: Vec<V3>,
}

impl RefTexture {
    /// From RGB565 texels (the very values the core samples).
    pub fn from_rgb565(width: usize, height: usize, texels: &[u16]) -> Self {
        let texels = texels.iter().map(|&t| [(t >> 11) as f64 / 31.0, ((t >> 5) & 63) as f64 / 63.0, (t & 31) as f64 / 31.0]).collect();
        Self { width, height, texels }
    }

    fn texel(&self, x: i64, y: i64) -> V3 {
        // Repeat: the floor modulo.
        let x = x.rem_euclid(self.width as i64) as usize;
        let y = y.rem_euclid(self.height as i64) as usize;
        self.texels[y * self.width + x]
    }

    /// The texel under `(u, v)` in texel units (nearest), or the exact
    /// bilinear blend of the four around it (centers at half units).
    pub fn sample(&self, u: f64, v: f64, filter: RefFilter) -> V3 {
        match filter {
            RefFilter::Nearest => self.texel(u.floor() as i64, v.floor() as i64),
            RefFilter::Bilinear => {
                let (u, v) = (u - 0.5, v - 0.5);
                let (x, y) = (u.floor(), v.floor());
                let (fx, fy) = (u - x, v - y);
                let (x, y) = (x as i64, y as i64);
                let t = |dx, dy| self.texel(x + dx, y + dy);
                let row0 = add(scale(t(0, 0), 1.0 - fx), scale(t(1, 0), fx));
                let row1 = add(scale(t(0, 1), 1.0 - fx), scale(t(1, 1), fx));
                add(scale(row0, 1.0 - fy), scale(row1, fy))
            }
        }
    }
}

/// Texture filter of the reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefFilter {
    /// The texel the point falls in.
    Nearest,
    /// Exact bilinear interpolation of texel centers.
    Bilinear,
}

/// How untextured objects are lit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefShading {
    /// Lit exactly at each vertex, the colors interpolated perspective-correctly.
    Gouraud,
    /// Lit exactly at each pixel from the interpolated, normalized normal.
    Phong,
}

/// One object of a scene.
#[derive(Clone, Debug)]
pub struct RefObject {
    /// Model-space positions.
    pub positions: Vec<V3>,
    /// Model-space normals.
    pub normals: Vec<V3>,
    /// Texture coordinates (u right, v down the image), if textured.
    pub uvs: Option<Vec<[f64; 2]>>,
    /// Triangles.
    pub triangles: Vec<[usize; 3]>,
    /// Model matrix.
    pub model: M4,
    /// Material color in [0, 1].
    pub color: V3,
    /// Index into [`RefScene::textures`] (textured objects are Gouraud-lit
    /// texture times color, like the core's `Textured`).
    pub texture: Option<usize>,
    /// Whether back faces are dropped.
    pub cull_back: bool,
}

/// A scene as the reference sees it.
#[derive(Clone, Debug)]
pub struct RefScene {
    /// Image width.
    pub width: usize,
    /// Image height.
    pub height: usize,
    /// Camera position, target, up.
    pub eye: V3,
    /// Point looked at.
    pub target: V3,
    /// Up vector.
    pub up: V3,
    /// Vertical field of view, radians.
    pub fov_y: f64,
    /// Near plane.
    pub near: f64,
    /// Far plane.
    pub far: f64,
    /// Ambient light.
    pub ambient: V3,
    /// Directional light: direction it shines along, color.
    pub sun: Option<(V3, V3)>,
    /// Point light: position, color.
    pub point: Option<(V3, V3)>,
    /// Objects, drawn in order.
    pub objects: Vec<RefObject>,
    /// Textures.
    pub textures: Vec<RefTexture>,
}

/// The reference image: exact colors and what produced them.
#[derive(Clone, Debug)]
pub struct RefImage {
    /// Width.
    pub width: usize,
    /// Height.
    pub height: usize,
    /// Color in [0, 1] per pixel (black where nothing is drawn).
    pub color: Vec<V3>,
    /// Index of the visible object, or `None`.
    pub object: Vec<Option<usize>>,
    /// Index of the visible triangle, counting through the objects in order.
    pub triangle: Vec<Option<usize>>,
    /// Texture coordinate (texel units) of the visible textured object.
    pub uv: Vec<Option<[f64; 2]>>,
    /// Window depth of the visible surface (infinite where none).
    pub depth: Vec<f64>,
}

/// A clipped polygon vertex: clip-space position and the barycentric
/// weights of the original triangle's vertices.
#[derive(Clone, Copy)]
struct ClipVertex {
    pos: [f64; 4],
    weights: V3,
}

fn lerp_vertex(a: &ClipVertex, b: &ClipVertex, t: f64) -> ClipVertex {
    let mut pos = [0.0; 4];
    for (k, p) in pos.iter_mut().enumerate() {
        *p = a.pos[k] + (b.pos[k] - a.pos[k]) * t;
    }
    ClipVertex { pos, weights: add(a.weights, scale(sub(b.weights, a.weights), t)) }
}

/// Keeps the part of a polygon where `d(v) >= 0`.
fn clip(poly: Vec<ClipVertex>, d: impl Fn(&ClipVertex) -> f64) -> Vec<ClipVertex> {
    let mut out = Vec::with_capacity(poly.len() + 1);
    for i in 0..poly.len() {
        let (a, b) = (&poly[i], &poly[(i + 1) % poly.len()]);
        let (da, db) = (d(a), d(b));
        if da >= 0.0 {
            out.push(*a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            out.push(lerp_vertex(a, b, da / (da - db)));
        }
    }
    out
}

impl RefScene {
    /// View-projection matrix: Babylon's left-handed look-at and
    /// perspective (clip z from 0 at near to w at far; w = view depth).
    pub fn view_projection(&self) -> M4 {
        let z = normalize(sub(self.target, self.eye));
        let x = normalize(cross(self.up, z));
        let y = cross(z, x);
        let view = [
            [x[0], x[1], x[2], -dot(x, self.eye)],
            [y[0], y[1], y[2], -dot(y, self.eye)],
            [z[0], z[1], z[2], -dot(z, self.eye)],
            [0.0, 0.0, 0.0, 1.0],
        ];
        let ys = 1.0 / (self.fov_y * 0.5).tan();
        let xs = ys / (self.width as f64 / self.height as f64);
        let q = self.far / (self.far - self.near);
        let proj = [[xs, 0.0, 0.0, 0.0], [0.0, ys, 0.0, 0.0], [0.0, 0.0, q, -self.near * q], [0.0, 0.0, 1.0, 0.0]];
        mul4(&proj, &view)
    }

    /// Diffuse light at a point with unit normal `n`.
    fn light(&self, p: V3, n: V3) -> V3 {
        let clamp01 = |x: f64| x.clamp(0.0, 1.0);
        let mut l = self.ambient;
        if let Some((dir, color)) = self.sun {
            l = add(l, scale(color, clamp01(dot(n, normalize(scale(dir, -1.0))))));
        }
        if let Some((pos, color)) = self.point {
            l = add(l, scale(color, clamp01(dot(n, normalize(sub(pos, p))))));
        }
        l
    }

    /// Renders the scene exactly.
    pub fn render(&self, shading: RefShading, filter: RefFilter) -> RefImage {
        let (w, h) = (self.width, self.height);
        let mut img = RefImage {
            width: w,
            height: h,
            color: vec![[0.0; 3]; w * h],
            object: vec![None; w * h],
            triangle: vec![None; w * h],
            uv: vec![None; w * h],
            depth: vec![f64::INFINITY; w * h],
        };
        let vp = self.view_projection();
        let mut first_triangle = 0;
        for (oi, obj) in self.objects.iter().enumerate() {
            let nm = normal_matrix(&obj.model);
            let world: Vec<V3> = obj
                .positions
                .iter()
                .map(|p| {
                    let q = apply4(&obj.model, [p[0], p[1], p[2], 1.0]);
                    [q[0], q[1], q[2]]
                })
                .collect();
            let normals: Vec<V3> = obj.normals.iter().map(|n| normalize([dot(nm[0], *n), dot(nm[1], *n), dot(nm[2], *n)])).collect();
            // Exact per-vertex lighting (Gouraud, and the textured objects'
            // light), clamped as the core clamps it.
            let vertex_light: Vec<V3> = world.iter().zip(&normals).map(|(p, n)| self.light(*p, *n).map(|c| c.clamp(0.0, 1.0))).collect();
            for (ti, tri) in obj.triangles.iter().enumerate() {
                let id = (oi, first_triangle + ti);
                let corners: Vec<ClipVertex> = (0..3)
                    .map(|k| {
                        let p = world[tri[k]];
                        let mut weights = [0.0; 3];
                        weights[k] = 1.0;
                        ClipVertex { pos: apply4(&vp, [p[0], p[1], p[2], 1.0]), weights }
                    })
                    .collect();
                let poly = clip(clip(corners, |v| v.pos[2]), |v| v.pos[3] - v.pos[2]);
                if poly.len() < 3 {
                    continue;
                }
                // Window space: x right, y down, z in [0, 1]; 1/w and
                // weights/w for perspective-correct interpolation.
                let win: Vec<([f64; 3], f64, V3)> = poly
                    .iter()
                    .map(|v| {
                        let q = 1.0 / v.pos[3];
                        let x = (v.pos[0] * q + 1.0) * 0.5 * w as f64;
                        let y = (1.0 - v.pos[1] * q) * 0.5 * h as f64;
                        ([x, y, v.pos[2] * q], q, scale(v.weights, q))
                    })
                    .collect();
                let area: f64 = (0..win.len())
                    .map(|i| {
                        let (a, b) = (win[i].0, win[(i + 1) % win.len()].0);
                        a[0] * b[1] - b[0] * a[1]
                    })
                    .sum();
                if area == 0.0 || (obj.cull_back && area < 0.0) {
                    continue;
                }
                for k in 1..win.len() - 1 {
                    self.fill(&mut img, id, obj, tri, &world, &normals, &vertex_light, [&win[0], &win[k], &win[k + 1]], shading, filter);
                }
            }
            first_triangle += obj.triangles.len();
        }
        img
    }

    #[allow(clippy::too_many_arguments)]
    fn fill(
        &self,
        img: &mut RefImage,
        (oi, ti): (usize, usize),
        obj: &RefObject,
        tri: &[usize; 3],
        world: &[V3],
        normals: &[V3],
        vertex_light: &[V3],
        v: [&([f64; 3], f64, V3); 3],
        shading: RefShading,
        filter: RefFilter,
    ) {
        let (w, h) = (img.width, img.height);
        let p = [v[0].0, v[1].0, v[2].0];
        let area = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
        if area == 0.0 {
            return;
        }
        // Orient counter-wise triangles (drawn without culling) like the others.
        let sign = area.signum();
        let x0 = p.iter().map(|q| q[0]).fold(f64::INFINITY, f64::min).floor().max(0.0) as usize;
        let x1 = (p.iter().map(|q| q[0]).fold(f64::NEG_INFINITY, f64::max).ceil().min(w as f64)).max(0.0) as usize;
        let y0 = p.iter().map(|q| q[1]).fold(f64::INFINITY, f64::min).floor().max(0.0) as usize;
        let y1 = (p.iter().map(|q| q[1]).fold(f64::NEG_INFINITY, f64::max).ceil().min(h as f64)).max(0.0) as usize;
        // Edge i runs from vertex i to vertex i+1; its function is positive
        // inside for a clockwise (front, area > 0) triangle.
        let edge = |i: usize, x: f64, y: f64| {
            let (a, b) = (p[i], p[(i + 1) % 3]);
            ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) * sign
        };
        // Top-left rule for centers exactly on an edge: a top edge
        // (horizontal, interior below) or a left edge keeps them.
        let owns = |i: usize| {
            let (a, b) = (p[i], p[(i + 1) % 3]);
            let (dx, dy) = ((b[0] - a[0]) * sign, (b[1] - a[1]) * sign);
            (dy == 0.0 && dx > 0.0) || dy < 0.0
        };
        for y in y0..y1 {
            for x in x0..x1 {
                let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                let e = [edge(1, cx, cy), edge(2, cx, cy), edge(0, cx, cy)];
                // e[k] is the edge opposite vertex k: its screen barycentric.
                if !(0..3).all(|k| e[k] > 0.0 || (e[k] == 0.0 && owns((k + 1) % 3))) {
                    continue;
                }
                let total = e[0] + e[1] + e[2];
                let b = [e[0] / total, e[1] / total, e[2] / total];
                let z = b[0] * p[0][2] + b[1] * p[1][2] + b[2] * p[2][2];
                let i = y * w + x;
                // "Less": NaN never passes, ties keep the first drawn.
                if z.partial_cmp(&img.depth[i]) != Some(std::cmp::Ordering::Less) {
                    continue;
                }
                // Perspective-correct weights of the original triangle.
                let q = b[0] * v[0].1 + b[1] * v[1].1 + b[2] * v[2].1;
                let lam: V3 = std::array::from_fn(|k| (b[0] * v[0].2[k] + b[1] * v[1].2[k] + b[2] * v[2].2[k]) / q);
                let interp = |a: &[V3]| add(add(scale(a[tri[0]], lam[0]), scale(a[tri[1]], lam[1])), scale(a[tri[2]], lam[2]));
                let color = match (obj.texture, &obj.uvs) {
                    (Some(t), Some(uvs)) => {
                        let tex = &self.textures[t];
                        let uv = [0, 1].map(|c| lam[0] * uvs[tri[0]][c] + lam[1] * uvs[tri[1]][c] + lam[2] * uvs[tri[2]][c]);
                        let (u, vv) = (uv[0] * tex.width as f64, uv[1] * tex.height as f64);
                        img.uv[i] = Some([u, vv]);
                        let texel = tex.sample(u, vv, filter);
                        let light = interp(vertex_light);
                        [0, 1, 2].map(|c| texel[c] * light[c] * obj.color[c])
                    }
                    _ => {
                        img.uv[i] = None;
                        match shading {
                            RefShading::Gouraud => {
                                let light = interp(vertex_light);
                                [0, 1, 2].map(|c| light[c] * obj.color[c])
                            }
                            RefShading::Phong => {
                                let n = normalize(interp(normals));
                                let l = self.light(interp(world), n).map(|c| c.clamp(0.0, 1.0));
                                [0, 1, 2].map(|c| l[c] * obj.color[c])
                            }
                        }
                    }
                };
                img.color[i] = color;
                img.object[i] = Some(oi);
                img.triangle[i] = Some(ti);
                img.depth[i] = z;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quad_scene(z: f64) -> RefScene {
        // A 2×2 square facing the camera at distance `z`, lit head-on.
        RefScene {
            width: 64,
            height: 48,
            eye: [0.0, 0.0, 0.0],
            target: [0.0, 0.0, 1.0],
            up: [0.0, 1.0, 0.0],
            fov_y: 0.8,
            near: 0.1,
            far: 100.0,
            ambient: [0.25; 3],
            sun: Some(([0.0, 0.0, 1.0], [0.5; 3])),
            point: None,
            objects: vec![RefObject {
                positions: vec![[-1.0, -1.0, z], [-1.0, 1.0, z], [1.0, 1.0, z], [1.0, -1.0, z]],
                normals: vec![[0.0, 0.0, -1.0]; 4],
                uvs: Some(vec![[0.0, 1.0], [0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]),
                triangles: vec![[0, 1, 2], [0, 2, 3]],
                model: [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]],
                color: [1.0; 3],
                texture: None,
                cull_back: true,
            }],
            textures: vec![],
        }
    }

    #[test]
    fn a_square_covers_the_pixels_its_projection_covers_and_is_lit_exactly() {
        let s = quad_scene(4.0);
        let img = s.render(RefShading::Gouraud, RefFilter::Nearest);
        // Half-width in pixels: tan-scaled 1/4, times the projection scale.
        let ys = 1.0 / (0.4f64).tan();
        let half_h = 0.25 * ys * 24.0;
        let half_w = 0.25 * ys / (64.0 / 48.0) * 32.0;
        let mut covered = 0;
        for y in 0..48 {
            for x in 0..64 {
                let inside = ((x as f64 + 0.5) - 32.0).abs() < half_w && ((y as f64 + 0.5) - 24.0).abs() < half_h;
                let i = y * 64 + x;
                assert_eq!(img.object[i].is_some(), inside, "pixel {x},{y}");
                if inside {
                    covered += 1;
                    // Ambient 0.25 plus the sun head-on, 0.5.
                    assert!((img.color[i][0] - 0.75).abs() < 1e-12);
                }
            }
        }
        assert!(covered > 100);
    }

    #[test]
    fn back_faces_are_dropped_and_behind_the_eye_nothing_is_drawn() {
        let mut s = quad_scene(4.0);
        s.target = [0.0, 0.0, -1.0];
        let img = s.render(RefShading::Gouraud, RefFilter::Nearest);
        assert!(img.object.iter().all(Option::is_none));
        let s = quad_scene(-4.0);
        let img = s.render(RefShading::Gouraud, RefFilter::Nearest);
        assert!(img.object.iter().all(Option::is_none));
    }

    #[test]
    fn texture_coordinates_are_perspective_correct() {
        // A floor receding from the camera: at the pixel whose center sees
        // world point (x, y0, z), u and v are the exact ones of that point.
        let mut s = quad_scene(4.0);
        s.objects[0].positions = vec![[-1.0, -1.0, 1.0], [-1.0, -1.0, 9.0], [1.0, -1.0, 9.0], [1.0, -1.0, 1.0]];
        s.objects[0].normals = vec![[0.0, 1.0, 0.0]; 4];
        s.objects[0].texture = Some(0);
        s.textures = vec![RefTexture { width: 8, height: 8, texels: vec![[0.5; 3]; 64] }];
        let img = s.render(RefShading::Gouraud, RefFilter::Nearest);
        let vp = s.view_projection();
        let mut checked = 0;
        for y in 0..48 {
            for x in 0..64 {
                let Some(uv) = img.uv[y * 64 + x] else { continue };
                // Cast the pixel's ray onto the plane y = -1.
                let ys = vp[1][1];
                let xs = vp[0][0];
                let (ndx, ndy) = ((x as f64 + 0.5) / 32.0 - 1.0, 1.0 - (y as f64 + 0.5) / 24.0);
                let dir = [ndx / xs, ndy / ys, 1.0];
                let t = -1.0 / dir[1];
                let (wx, wz) = (dir[0] * t, dir[2] * t);
                let (u, v) = ((wx + 1.0) / 2.0 * 8.0, (9.0 - wz) / 8.0 * 8.0);
                assert!((uv[0] - u).abs() < 1e-9 && (uv[1] - v).abs() < 1e-9, "{x},{y}: {uv:?} vs {u},{v}");
                checked += 1;
            }
        }
        assert!(checked > 200);
    }

    #[test]
    fn bilinear_sampling_blends_texel_centers() {
        let t = RefTexture { width: 2, height: 1, texels: vec![[0.0; 3], [1.0; 3]] };
        assert_eq!(t.sample(0.5, 0.5, RefFilter::Bilinear)[0], 0.0);
        assert_eq!(t.sample(1.0, 0.5, RefFilter::Bilinear)[0], 0.5);
        assert_eq!(t.sample(1.5, 0.5, RefFilter::Bilinear)[0], 1.0);
        // Repeat wraps: halfway between the last texel and the first.
        assert_eq!(t.sample(2.0, 0.5, RefFilter::Bilinear)[0], 0.5);
        assert_eq!(t.sample(1.99, 0.5, RefFilter::Nearest)[0], 1.0);
        assert_eq!(t.sample(-0.01, 0.5, RefFilter::Nearest)[0], 1.0);
    }
}
