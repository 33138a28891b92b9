//! Rust identifiers for the generated items.
//!
//! A file's names become `SCREAMING_SNAKE_CASE` bases; every item of a mesh,
//! material or texture is its base plus a fixed suffix. A base is taken only
//! if none of the identifiers it would produce is taken already, otherwise
//! `_2`, `_3`, ... is appended, so generated names never clash.

use std::collections::HashSet;

/// Suffixes of a mesh's items.
pub const MESH: &[&str] = &[
    "",
    "_POSITIONS",
    "_NORMALS",
    "_UVS",
    "_INDICES",
    "_MODEL",
    "_COLOR",
    "_CULL",
    "_POSITIONS_I16",
    "_POSITION_SCALE",
    "_POSITION_OFFSET",
    "_NORMALS_I16",
    "_NORMAL_SCALE",
];
/// Suffixes of a material's items.
pub const MATERIAL: &[&str] = &["_COLOR", "_CULL", "_TEXTURE_NAME"];
/// Suffixes of a texture's items.
pub const TEXTURE: &[&str] = &["_TEXELS", "_PALETTE", "_TEXTURE", "_TEXTURE_WIDTH", "_TEXTURE_HEIGHT"];
/// Scene-wide items.
const RESERVED: &[&str] = &["CAMERA", "LIGHTS", "MESHES", "CLEAR_COLOR"];

/// The identifiers handed out so far.
pub struct Names {
    used: HashSet<String>,
}

impl Names {
    pub fn new() -> Self {
        Self { used: RESERVED.iter().map(|s| s.to_string()).collect() }
    }

    /// A unique base for `name` (`kind` stands in for an empty name and
    /// precedes one that starts with a digit).
    pub fn claim(&mut self, name: &str, kind: &str, index: usize, suffixes: &[&str]) -> String {
        let base = base_ident(name, kind, index);
        let mut n = 1;
        loop {
            let candidate = if n == 1 { base.clone() } else { format!("{base}_{n}") };
            let all: Vec<String> = suffixes.iter().map(|s| format!("{candidate}{s}")).collect();
            if all.iter().all(|i| !self.used.contains(i)) {
                self.used.extend(all);
                return candidate;
            }
            n += 1;
        }
    }
}

/// `SuzanneHead.001` → `SUZANNE_HEAD_001`: ASCII letters and digits kept,
/// a word break before an upper-case letter that follows a lower-case one,
/// anything else becomes one `_`.
pub fn base_ident(name: &str, kind: &str, index: usize) -> String {
    let mut s = String::new();
    let mut prev_lower = false;
    for c in name.chars() {
        if c.is_ascii_alphanumeric() {
            if c.is_ascii_uppercase() && prev_lower && !s.ends_with('_') {
                s.push('_');
            }
            s.push(c.to_ascii_uppercase());
            prev_lower = c.is_ascii_lowercase();
        } else {
            if !s.is_empty() && !s.ends_with('_') {
                s.push('_');
            }
            prev_lower = false;
        }
    }
    while s.ends_with('_') {
        s.pop();
    }
    if s.is_empty() {
        format!("{kind}_{index}")
    } else if s.starts_with(|c: char| c.is_ascii_digit()) {
        format!("{kind}_{s}")
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bases() {
        assert_eq!(base_ident("Suzanne", "MESH", 0), "SUZANNE");
        assert_eq!(base_ident("SuzanneHead.001", "MESH", 0), "SUZANNE_HEAD_001");
        assert_eq!(base_ident("02 - Default", "MATERIAL", 0), "MATERIAL_02_DEFAULT");
        assert_eq!(base_ident("box.Material", "MATERIAL", 0), "BOX_MATERIAL");
        assert_eq!(base_ident("  ", "MESH", 3), "MESH_3");
        assert_eq!(base_ident("éé", "TEXTURE", 1), "TEXTURE_1");
        assert_eq!(base_ident("_x_", "MESH", 0), "X");
    }

    #[test]
    fn clashes_get_a_number() {
        let mut n = Names::new();
        assert_eq!(n.claim("Cube", "MESH", 0, MESH), "CUBE");
        assert_eq!(n.claim("cube", "MESH", 1, MESH), "CUBE_2");
        // A material named like a mesh would repeat CUBE_COLOR.
        assert_eq!(n.claim("Cube", "MATERIAL", 0, MATERIAL), "CUBE_3");
        // A mesh whose name is another mesh's item.
        assert_eq!(n.claim("Cube model", "MESH", 2, MESH), "CUBE_MODEL_2");
        assert_eq!(n.claim("Camera", "MESH", 3, MESH), "CAMERA_2");
        // Textures have their own suffixes, so they can share a mesh's base.
        assert_eq!(n.claim("Cube", "TEXTURE", 0, TEXTURE), "CUBE");
    }
}
