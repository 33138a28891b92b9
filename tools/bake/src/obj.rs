//! Wavefront OBJ (and MTL) through `tobj`.
//!
//! OBJ is right-handed (y up, -z forward, counter-clockwise front faces,
//! `v = 0` at the bottom of the image); soft3d is left-handed like Babylon
//! (clockwise front faces) and the baked textures start with their top row.
//! So z is negated (positions and normals), each triangle's winding is
//! reversed and `v` becomes `1 - v`. Faces are triangulated as fans;
//! vertices are split where a face corner's normal or uv differs.

use crate::{BakeError, Baked, BakedMaterial, BakedMesh, Options};
use embedded_graphics::pixelcolor::Rgb888;
use soft3d::math::{Mat4, Vec2, Vec3};
use soft3d::Cull;
use std::cell::RefCell;
use std::io::Cursor;
use std::path::{Path, PathBuf};

pub(crate) fn bake(path: &Path, texture_dir: &Path, options: &Options) -> Result<Baked, BakeError> {
    let bytes = crate::read(path)?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    // MTL files read, and why one could not be.
    let mtl_inputs: RefCell<Vec<PathBuf>> = RefCell::new(Vec::new());
    let mtl_problems: RefCell<Vec<String>> = RefCell::new(Vec::new());
    let load = tobj::LoadOptions { single_index: true, triangulate: true, ignore_points: true, ignore_lines: true };
    let (models, materials) = tobj::load_obj_buf(&mut Cursor::new(&bytes), &load, |mtl: &Path| {
        let full = dir.join(mtl);
        match std::fs::read(&full) {
            Ok(b) => {
                mtl_inputs.borrow_mut().push(full.clone());
                if let Some(problem) = short_color(&b) {
                    mtl_problems.borrow_mut().push(format!("{}: {problem}", full.display()));
                    return Err(tobj::LoadError::MaterialParseError);
                }
                let r = tobj::load_mtl_buf(&mut Cursor::new(b));
                if let Err(e) = &r {
                    mtl_problems.borrow_mut().push(format!("{}: {e}", full.display()));
                }
                r
            }
            Err(e) => {
                mtl_problems.borrow_mut().push(format!("{}: {e}", full.display()));
                Err(tobj::LoadError::OpenFileFailed)
            }
        }
    })
    .map_err(|e| BakeError::Obj { path: path.to_path_buf(), problem: e.to_string() })?;

    let mut warnings: Vec<String> = mtl_problems.into_inner().into_iter().map(|p| format!("materials not loaded: {p}")).collect();
    let materials = match materials {
        Ok(m) => m,
        Err(e) => {
            if warnings.is_empty() {
                warnings.push(format!("materials not loaded: {e}"));
            }
            Vec::new()
        }
    };

    let mut meshes = Vec::with_capacity(models.len());
    for model in models {
        meshes.push(convert(model, materials.len())?);
    }
    let materials = materials
        .iter()
        .map(|m| {
            let c = m.diffuse.unwrap_or([1.0; 3]).map(|v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8);
            BakedMaterial {
                name: m.name.clone(),
                ident: String::new(),
                color: Rgb888::new(c[0], c[1], c[2]),
                cull: Cull::Back,
                texture_name: m.diffuse_texture.as_deref().and_then(texture_file),
                texture: None,
            }
        })
        .collect();
    let mut inputs = vec![path.to_path_buf()];
    inputs.extend(mtl_inputs.into_inner());
    let baked = Baked {
        source: path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default(),
        options: options.clone(),
        meshes,
        materials,
        textures: Vec::new(),
        camera: None,
        lights: None,
        clear_color: None,
        warnings,
        inputs,
    };
    crate::finish(baked, texture_dir)
}

/// tobj 4.0 panics on a color statement with fewer than three numbers
/// (`Kd 1 0`); such a file is refused here instead.
fn short_color(mtl: &[u8]) -> Option<String> {
    for (n, line) in String::from_utf8_lossy(mtl).lines().enumerate() {
        let mut words = line.split_whitespace();
        if let Some(key @ ("Ka" | "Kd" | "Ks" | "Ke")) = words.next() {
            if words.count() < 3 {
                return Some(format!("line {}: {key} needs three numbers", n + 1));
            }
        }
    }
    None
}

/// The file name in a `map_Kd` statement, whose options (`-bm 0.5`, ...)
/// come first: the last word when options are present.
fn texture_file(map: &str) -> Option<String> {
    let map = map.trim();
    let name = if map.starts_with('-') { map.split_whitespace().last()? } else { map };
    (!name.is_empty()).then(|| name.to_string())
}

fn convert(model: tobj::Model, materials: usize) -> Result<BakedMesh, BakeError> {
    let name = model.name;
    let m = model.mesh;
    let n = m.positions.len() / 3;
    let too_big =
        || BakeError::Mesh { name: name.clone(), problem: format!("{n} vertices after splitting; at most 65536 fit u16 indices") };
    if n > 1 << 16 {
        return Err(too_big());
    }
    // `0.0 - z` rather than `-z`: the same mirror, without turning 0 into -0.
    let positions: Vec<Vec3> = m.positions.chunks_exact(3).map(|p| Vec3::new(p[0], p[1], 0.0 - p[2])).collect();
    let mut indices = Vec::with_capacity(m.indices.len());
    for t in m.indices.chunks_exact(3) {
        // Reversed winding: (a, b, c) → (a, c, b).
        for i in [t[0], t[2], t[1]] {
            let bad = || BakeError::Mesh { name: name.clone(), problem: format!("index {i} out of range ({n} vertices)") };
            indices.push(u16::try_from(i).ok().filter(|&i| (i as usize) < n).ok_or_else(bad)?);
        }
    }
    let normals = if m.normals.len() == 3 * n {
        m.normals.chunks_exact(3).map(|v| unit_or_zero(Vec3::new(v[0], v[1], 0.0 - v[2]))).collect()
    } else {
        face_normals(&positions, &indices)
    };
    let uvs = (m.texcoords.len() == 2 * n && n > 0).then(|| m.texcoords.chunks_exact(2).map(|t| Vec2::new(t[0], 1.0 - t[1])).collect());
    Ok(BakedMesh {
        name,
        ident: String::new(),
        positions,
        normals,
        uvs,
        indices,
        model: Mat4::IDENTITY,
        material: m.material_id.filter(|&i| i < materials),
        quantized: None,
    })
}

/// Area-weighted vertex normals, as `soft3d::babylon` computes for a mesh
/// without normals.
fn face_normals(positions: &[Vec3], indices: &[u16]) -> Vec<Vec3> {
    let mut normals = vec![Vec3::ZERO; positions.len()];
    for t in indices.chunks_exact(3) {
        let [a, b, c] = [t[0], t[1], t[2]].map(usize::from);
        let n = (positions[b] - positions[a]).cross(positions[c] - positions[a]);
        for v in [a, b, c] {
            normals[v] = normals[v] + n;
        }
    }
    normals.into_iter().map(unit_or_zero).collect()
}

/// Unit length; zero and non-finite vectors become zero (scaled by the
/// largest component first, as the core's loader does).
fn unit_or_zero(v: Vec3) -> Vec3 {
    let m = v.x.abs().max(v.y.abs()).max(v.z.abs());
    if m > 0.0 && m.is_finite() {
        (v * (1.0 / m)).normalize_or_zero()
    } else {
        Vec3::ZERO
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_colors_are_refused_before_tobj_sees_them() {
        assert_eq!(short_color(b"newmtl a\nKd 1 0 0\n"), None);
        assert_eq!(short_color(b"newmtl a\n  Kd 1 0\n").as_deref(), Some("line 2: Kd needs three numbers"));
        assert!(short_color(b"Ka").is_some());
    }

    #[test]
    fn map_kd_options_are_skipped() {
        assert_eq!(texture_file("wood.png").as_deref(), Some("wood.png"));
        assert_eq!(texture_file("-bm 0.5 -clamp on wood.png").as_deref(), Some("wood.png"));
        assert_eq!(texture_file("  "), None);
    }
}
