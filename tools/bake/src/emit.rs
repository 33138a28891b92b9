//! The generated Rust source.
//!
//! Every path is absolute (`::soft3d`, `::embedded_graphics`, `::core`), so
//! the file can be `include!`d into any module of a `no_std` crate that
//! depends on both crates; it has no `use` items and no inner attributes
//! (neither works inside `include!`). Floats are written with `{:?}`, the
//! shortest decimal that reads back as the same `f32` (non-finite values as
//! constants or bits), so the compiled data is bit-identical to the baked.

use crate::{Baked, BakedMesh, Quantize, Texels, NORMAL_SCALE};
use soft3d::math::{Mat4, Vec2, Vec3};
use soft3d::mesh::{bounding_sphere, face_plane, Vectors};
use soft3d::Cull;
use std::fmt::Write as _;

const VEC3: &str = "::soft3d::math::Vec3";
const VEC2: &str = "::soft3d::math::Vec2";
const MAT4: &str = "::soft3d::math::Mat4";
const RGB: &str = "::embedded_graphics::pixelcolor::Rgb888";
const SOME: &str = "::core::option::Option::Some";
const NONE: &str = "::core::option::Option::None";
/// Literals such as 0.70710677 (a normal at 45°) would trip clippy's
/// `approx_constant`, which denies by default; they are data, not π.
const ALLOW_FLOATS: &str = "#[allow(clippy::approx_constant)]";
/// Soft line length for arrays.
const WIDTH: usize = 120;

/// A float literal that reads back bit-exactly.
pub fn float(v: f32) -> String {
    if v.is_nan() {
        format!("f32::from_bits({:#010x})", v.to_bits())
    } else if v == f32::INFINITY {
        "f32::INFINITY".to_string()
    } else if v == f32::NEG_INFINITY {
        "f32::NEG_INFINITY".to_string()
    } else {
        format!("{v:?}")
    }
}

fn vec3(v: Vec3) -> String {
    format!("{VEC3}::new({}, {}, {})", float(v.x), float(v.y), float(v.z))
}

fn vec2(v: Vec2) -> String {
    format!("{VEC2}::new({}, {})", float(v.x), float(v.y))
}

fn floats<const N: usize>(v: [f32; N]) -> String {
    format!("[{}]", v.map(float).join(", "))
}

fn mat4(m: &Mat4) -> String {
    format!("{MAT4} {{ m: [{}] }}", m.m.map(floats).join(", "))
}

fn rgb(c: embedded_graphics::pixelcolor::Rgb888) -> String {
    use embedded_graphics::pixelcolor::RgbColor;
    format!("{RGB}::new({}, {}, {})", c.r(), c.g(), c.b())
}

fn cull(c: Cull) -> &'static str {
    match c {
        Cull::Back => "::soft3d::Cull::Back",
        Cull::None => "::soft3d::Cull::None",
    }
}

/// A name from the file, quoted and escaped, for doc comments.
fn quoted(name: &str) -> String {
    format!("`{name:?}`")
}

/// Array elements, several per line up to [`WIDTH`] columns.
fn packed(out: &mut String, items: impl IntoIterator<Item = String>) {
    let mut line = String::new();
    for item in items {
        if !line.is_empty() && line.len() + item.len() + 2 > WIDTH {
            let _ = writeln!(out, "    {}", line.trim_end());
            line.clear();
        }
        line.push_str(&item);
        line.push_str(", ");
    }
    if !line.is_empty() {
        let _ = writeln!(out, "    {}", line.trim_end());
    }
}

/// Array elements, one per line.
fn listed(out: &mut String, items: impl IntoIterator<Item = String>) {
    for item in items {
        let _ = writeln!(out, "    {item},");
    }
}

pub fn to_rust(b: &Baked) -> String {
    // The prefix was checked when baking; an invalid one cannot reach here.
    let p = crate::normalized_prefix(&b.options.prefix).unwrap_or_default();
    let mut o = String::new();
    header(&mut o, b);
    scene(&mut o, b, &p);
    for m in &b.materials {
        let id = format!("{p}{}", m.ident);
        let _ = writeln!(o, "/// Material {}: diffuse color.", quoted(&m.name));
        let _ = writeln!(o, "pub const {id}_COLOR: {RGB} = {};", rgb(m.color));
        let _ = writeln!(o, "/// Material {}: culling (`backFaceCulling`).", quoted(&m.name));
        let _ = writeln!(o, "pub const {id}_CULL: ::soft3d::Cull = {};", cull(m.cull));
        if let Some(name) = &m.texture_name {
            match m.texture.and_then(|t| b.textures.get(t)) {
                Some(t) => {
                    let what = match t.texels {
                        Texels::Rgb565(_) => format!("`{p}{}_TEXTURE`", t.ident),
                        Texels::Palette8 { .. } => format!("`{p}{0}_PALETTE` and `{p}{0}_TEXELS`", t.ident),
                    };
                    let _ =
                        writeln!(o, "/// Material {}: diffuse texture file, baked as {what} ({}×{}).", quoted(&m.name), t.size.0, t.size.1);
                }
                None => {
                    let _ = writeln!(o, "/// Material {}: diffuse texture file (not baked).", quoted(&m.name));
                }
            }
            let _ = writeln!(o, "pub const {id}_TEXTURE_NAME: &str = {name:?};");
        }
        o.push('\n');
    }
    for m in &b.meshes {
        mesh(&mut o, b, m, &p);
    }
    for t in &b.textures {
        let id = format!("{p}{}", t.ident);
        let n = t.size.0 as usize * t.size.1 as usize;
        let _ = writeln!(o, "/// Width of texture {} in texels (a power of two).", quoted(&t.name));
        let _ = writeln!(o, "pub const {id}_TEXTURE_WIDTH: usize = {};", t.size.0);
        let _ = writeln!(o, "/// Height of texture {} in texels (a power of two).", quoted(&t.name));
        let _ = writeln!(o, "pub const {id}_TEXTURE_HEIGHT: usize = {};\n", t.size.1);
        match &t.texels {
            Texels::Rgb565(texels) => {
                let _ = writeln!(o, "/// Texture {} for `soft3d::effect::Textured`, validated at compile time.", quoted(&t.name));
                // With an alpha plane, the texture carries it (for `AlphaBlend`).
                let new = format!("::soft3d::texture::Texture::new(&{id}_TEXELS, {id}_TEXTURE_WIDTH, {id}_TEXTURE_HEIGHT)");
                let new = if t.alpha.is_some() {
                    format!(
                        "match {new} {{\n        ::core::result::Result::Ok(texture) => texture.with_alpha(&{id}_ALPHA),\n        error => error,\n    }}"
                    )
                } else {
                    new
                };
                let _ = writeln!(
                    o,
                    "pub static {id}_TEXTURE: ::soft3d::texture::Texture<'static> =
    match {new} {{
        ::core::result::Result::Ok(texture) => texture,
        ::core::result::Result::Err(_) => ::core::panic!(\"baked texture {id} is invalid\"),
    }};\n"
                );
                let _ = writeln!(o, "/// Texels of {}: RGB565, row-major, row 0 = top of the image (v = 0);", quoted(&t.name));
                let _ = writeln!(o, "/// texel (x, y) is `{id}_TEXELS[y * {id}_TEXTURE_WIDTH + x]`.");
                let _ = writeln!(o, "pub static {id}_TEXELS: [u16; {n}] = [");
                packed(&mut o, texels.iter().map(|t| format!("{t:#06x}")));
            }
            Texels::Palette8 { palette, indices } => {
                let _ = writeln!(o, "/// Palette of {}: 256 RGB565 colors (unused entries 0).", quoted(&t.name));
                let _ = writeln!(o, "pub static {id}_PALETTE: [u16; 256] = [");
                packed(&mut o, palette.iter().map(|t| format!("{t:#06x}")));
                let _ = writeln!(o, "];\n");
                let _ = writeln!(o, "/// Texels of {}: indices into `{id}_PALETTE`, row-major, row 0 = top of", quoted(&t.name));
                let _ = writeln!(o, "/// the image (v = 0); texel (x, y) is `{id}_TEXELS[y * {id}_TEXTURE_WIDTH + x]`.");
                let _ = writeln!(o, "pub static {id}_TEXELS: [u8; {n}] = [");
                packed(&mut o, indices.iter().map(|t| t.to_string()));
            }
        }
        let _ = writeln!(o, "];\n");
        if let Some(alpha) = &t.alpha {
            let _ = writeln!(o, "/// Alpha of {}: one byte per texel in the order of the texels, 0 transparent.", quoted(&t.name));
            let _ = writeln!(o, "pub static {id}_ALPHA: [u8; {n}] = [");
            packed(&mut o, alpha.iter().map(|a| a.to_string()));
            let _ = writeln!(o, "];\n");
        }
    }
    while o.ends_with("\n\n") {
        o.pop();
    }
    o
}

fn header(o: &mut String, b: &Baked) {
    let q = match b.options.quantize {
        Quantize::F32 => "f32",
        Quantize::I16 => "i16",
    };
    let _ = writeln!(
        o,
        "// Generated by soft3d-bake {} from {:?} ({q} vertices). Do not edit: rebake instead.",
        env!("CARGO_PKG_VERSION"),
        b.source
    );
    let _ = writeln!(o, "// Include it with `include!` in a module of a crate that depends on soft3d and embedded-graphics;");
    let _ = writeln!(o, "// see docs/bake.md in the soft3d repository for the items.");
    for m in &b.meshes {
        let _ = writeln!(o, "//   mesh {:?}: {} vertices, {} triangles", m.name, m.positions.len(), m.indices.len() / 3);
    }
    for t in &b.textures {
        let _ = writeln!(o, "//   texture {:?}: {}×{}", t.name, t.size.0, t.size.1);
    }
    o.push('\n');
}

fn scene(o: &mut String, b: &Baked, p: &str) {
    if let Some(c) = &b.camera {
        let _ = writeln!(o, "/// The scene's active camera.");
        let _ = writeln!(o, "{ALLOW_FLOATS}");
        let _ = writeln!(
            o,
            "pub const {p}CAMERA: ::soft3d::Camera = ::soft3d::Camera {{\n    position: {},\n    target: {},\n    up: {},\n    fov_y: {},\n    near: {},\n    far: {},\n}};\n",
            vec3(c.position),
            vec3(c.target),
            vec3(c.up),
            float(c.fov_y),
            float(c.near),
            float(c.far)
        );
    }
    if let Some(l) = &b.lights {
        let point = match l.point {
            Some(pl) => format!("{SOME}(::soft3d::PointLight {{ position: {}, color: {} }})", vec3(pl.position), vec3(pl.color)),
            None => NONE.to_string(),
        };
        let directional = match l.directional {
            Some(d) => format!("{SOME}(::soft3d::DirectionalLight {{ direction: {}, color: {} }})", vec3(d.direction), vec3(d.color)),
            None => NONE.to_string(),
        };
        let _ = writeln!(o, "/// The scene's lights: ambient color, the first point and the first directional light.");
        let _ = writeln!(o, "{ALLOW_FLOATS}");
        let _ = writeln!(
            o,
            "pub const {p}LIGHTS: ::soft3d::Lights = ::soft3d::Lights {{\n    ambient: {},\n    point: {point},\n    directional: {directional},\n}};\n",
            vec3(l.ambient)
        );
    }
    if let Some(c) = b.clear_color {
        let _ = writeln!(o, "/// The scene's background (`clearColor`).");
        let _ = writeln!(o, "pub const {p}CLEAR_COLOR: {RGB} = {};\n", rgb(c));
    }
    let _ = writeln!(o, "/// Every mesh with its model matrix, color and culling, in file order.");
    let _ = writeln!(o, "pub static {p}MESHES: [(&::soft3d::mesh::Mesh<'static>, {MAT4}, {RGB}, ::soft3d::Cull); {}] = [", b.meshes.len());
    listed(o, b.meshes.iter().map(|m| format!("(&{p}{0}, {p}{0}_MODEL, {p}{0}_COLOR, {p}{0}_CULL)", m.ident)));
    let _ = writeln!(o, "];\n");
}

fn mesh(o: &mut String, b: &Baked, m: &BakedMesh, p: &str) {
    let id = format!("{p}{}", m.ident);
    let n = m.positions.len();
    let name = quoted(&m.name);
    let material = m.material.and_then(|i| b.materials.get(i));
    match &m.quantized {
        None => {
            let _ = writeln!(o, "/// Positions of mesh {name}.\n{ALLOW_FLOATS}\npub static {id}_POSITIONS: [{VEC3}; {n}] = [");
            listed(o, m.positions.iter().map(|v| vec3(*v)));
            let _ = writeln!(o, "];\n");
            let _ = writeln!(o, "/// Unit normals of mesh {name}.\n{ALLOW_FLOATS}\npub static {id}_NORMALS: [{VEC3}; {n}] = [");
            listed(o, m.normals.iter().map(|v| vec3(*v)));
            let _ = writeln!(o, "];\n");
        }
        Some(q) => {
            let _ = writeln!(o, "/// Positions of mesh {name} in steps: `q as f32 * {id}_POSITION_SCALE[k] + {id}_POSITION_OFFSET[k]`.");
            let _ = writeln!(o, "pub static {id}_POSITIONS_I16: [[i16; 3]; {n}] = [");
            packed(o, q.steps.positions.iter().map(|v| format!("[{}, {}, {}]", v[0], v[1], v[2])));
            let _ = writeln!(o, "];\n");
            let _ = writeln!(o, "/// Model units per position step, per axis.\n{ALLOW_FLOATS}");
            let _ = writeln!(o, "pub const {id}_POSITION_SCALE: [f32; 3] = {};", floats(q.steps.position_scale));
            let _ = writeln!(o, "/// The position offset (middle of the bounding box), per axis.\n{ALLOW_FLOATS}");
            let _ = writeln!(o, "pub const {id}_POSITION_OFFSET: [f32; 3] = {};\n", floats(q.steps.position_offset));
            let _ = writeln!(o, "/// Normals of mesh {name} in steps of `{id}_NORMAL_SCALE`.");
            let _ = writeln!(o, "pub static {id}_NORMALS_I16: [[i16; 3]; {n}] = [");
            packed(o, q.steps.normals.iter().map(|v| format!("[{}, {}, {}]", v[0], v[1], v[2])));
            let _ = writeln!(o, "];\n");
            let _ = writeln!(o, "/// Units per normal step (1/32767).\npub const {id}_NORMAL_SCALE: f32 = {};\n", float(NORMAL_SCALE));
        }
    }
    if let Some(uvs) = &m.uvs {
        let _ =
            writeln!(o, "/// Texture coordinates of mesh {name} (as in the file).\n{ALLOW_FLOATS}\npub static {id}_UVS: [{VEC2}; {n}] = [");
        listed(o, uvs.iter().map(|v| vec2(*v)));
        let _ = writeln!(o, "];\n");
    }
    let _ = writeln!(o, "/// Triangle indices of mesh {name}, three per triangle.");
    let _ = writeln!(o, "pub static {id}_INDICES: [u16; {}] = [", m.indices.len());
    packed(o, m.indices.iter().map(|i| i.to_string()));
    let _ = writeln!(o, "];\n");

    if b.options.face_planes {
        // Computed from the positions as the mesh stores them, by the
        // function that checks them at compile time.
        let stored = match &m.quantized {
            None => Vectors::F32(&m.positions),
            Some(q) => Vectors::I16 { steps: &q.steps.positions, scale: q.steps.position_scale, offset: q.steps.position_offset },
        };
        let bounds = bounding_sphere(&stored);
        let planes = m.indices.chunks_exact(3).map(|t| {
            let p = face_plane(stored.get(t[0] as usize), stored.get(t[1] as usize), stored.get(t[2] as usize), bounds);
            format!("[{}, {}, {}, {}]", p[0], p[1], p[2], p[3])
        });
        let _ = writeln!(o, "/// Face planes of mesh {name} (unit normal, offset from the bounds' center), one per triangle.");
        let _ = writeln!(o, "pub static {id}_FACE_PLANES: [[i16; 4]; {}] = [", m.indices.len() / 3);
        packed(o, planes);
        let _ = writeln!(o, "];\n");
    }
    let what = match material {
        Some(mat) => format!(", material {}", quoted(&mat.name)),
        None => String::new(),
    };
    let _ = writeln!(o, "/// Mesh {name}: {n} vertices, {} triangles{what}. Validated at compile time.", m.indices.len() / 3);
    let new = match &m.quantized {
        None => format!("::soft3d::mesh::Mesh::new(&{id}_POSITIONS, &{id}_NORMALS, &{id}_INDICES)"),
        Some(_) => format!(
            "::soft3d::mesh::Mesh::new_i16(&{id}_POSITIONS_I16, {id}_POSITION_SCALE, {id}_POSITION_OFFSET, &{id}_NORMALS_I16, &{id}_INDICES)"
        ),
    };
    // Each optional part is one more validated step: `match step { Ok(mesh) => <next>, Err(_) => panic }`.
    let mut steps = vec![(new, format!("baked mesh {id} is invalid"))];
    if m.uvs.is_some() {
        steps.push((format!("mesh.with_uvs(&{id}_UVS)"), format!("baked mesh {id}: bad uvs")));
    }
    if b.options.face_planes {
        steps.push((format!("mesh.with_face_planes(&{id}_FACE_PLANES)"), format!("baked mesh {id}: bad face planes")));
    }
    let _ = write!(o, "pub static {id}: ::soft3d::mesh::Mesh<'static> = match {} {{", steps[0].0);
    for depth in 1..=steps.len() {
        let pad = "    ".repeat(depth);
        match steps.get(depth) {
            Some((step, _)) => {
                let _ = write!(o, "\n{pad}::core::result::Result::Ok(mesh) => match {step} {{");
            }
            None => {
                let _ = write!(o, "\n{pad}::core::result::Result::Ok(mesh) => mesh,");
            }
        }
    }
    for (depth, (_, message)) in steps.iter().enumerate().rev() {
        let pad = "    ".repeat(depth);
        let end = if depth == 0 { ";" } else { "," };
        let _ = write!(o, "\n{pad}    ::core::result::Result::Err(_) => ::core::panic!(\"{message}\"),\n{pad}}}{end}");
    }
    let _ = writeln!(o, "\n");
    let _ = writeln!(o, "/// Model matrix of mesh {name} (rows, column vectors: `T · R · S`).\n{ALLOW_FLOATS}");
    let _ = writeln!(o, "pub const {id}_MODEL: {MAT4} = {};", mat4(&m.model));
    match material {
        Some(mat) => {
            let _ = writeln!(o, "/// Diffuse color of mesh {name} (its material's).");
            let _ = writeln!(o, "pub const {id}_COLOR: {RGB} = {p}{}_COLOR;", mat.ident);
            let _ = writeln!(o, "/// Culling of mesh {name} (its material's).");
            let _ = writeln!(o, "pub const {id}_CULL: ::soft3d::Cull = {p}{}_CULL;\n", mat.ident);
        }
        None => {
            let _ = writeln!(o, "/// Diffuse color of mesh {name} (no material: Babylon's default, white).");
            let _ = writeln!(o, "pub const {id}_COLOR: {RGB} = {RGB}::new(255, 255, 255);");
            let _ = writeln!(o, "/// Culling of mesh {name} (no material: back faces culled).");
            let _ = writeln!(o, "pub const {id}_CULL: ::soft3d::Cull = ::soft3d::Cull::Back;\n");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_read_back_exactly() {
        for v in [0.0f32, -0.0, 1.0, 0.1, -0.4688, 1e-7, 3.4028235e38, 1e-45, 16777217.0, 0.70710677] {
            let s = float(v);
            assert_eq!(s.parse::<f32>().unwrap().to_bits(), v.to_bits(), "{s}");
        }
        assert_eq!(float(f32::INFINITY), "f32::INFINITY");
        assert_eq!(float(f32::from_bits(0x7fc0_0001)), "f32::from_bits(0x7fc00001)");
    }
}
