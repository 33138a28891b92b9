//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::PathBuf;

/// The shared assets (never copied into the repository).
pub const ASSETS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../../shared/assets");

/// The three shared scenes and their (vertices, triangles).
pub const SCENES: [(&str, usize, usize); 3] = [("monkey", 886, 966), ("torus", 576, 1152), ("cube", 8, 12)];

/// An asset's path, or `None` (with a message) when the assets are absent.
pub fn asset(name: &str) -> Option<PathBuf> {
    let path = PathBuf::from(ASSETS).join(name);
    if path.exists() {
        Some(path)
    } else {
        println!("skipped: {} is not available", path.display());
        None
    }
}

/// A fresh scratch directory under cargo's per-target temporary directory.
pub fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A tiny scene in the newer layout: one textured triangle, one untextured
/// quad without normals, a camera given by rotation, both light kinds.
pub fn inline_scene(texture: &str) -> String {
    format!(
        r#"{{
  "ambientColor": [0.1, 0.2, 0.3],
  "clearColor": [0.2, 0.4, 0.6],
  "materials": [
    {{"name": "Painted", "id": "painted", "diffuse": [1, 0.5, 0.25], "backFaceCulling": false,
      "diffuseTexture": {{"name": "{texture}"}}}},
    {{"name": "plain", "id": "plain", "diffuse": [0.2, 0.4, 0.6]}}
  ],
  "meshes": [
    {{"name": "Tri angle", "id": "t", "materialId": "painted", "position": [1, 2, 3], "rotation": [0.1, 0.2, 0.3],
      "scaling": [2, 2, 2],
      "positions": [0, 0, 0, 1, 0, 0, 0, 1, 0.7071067811865476],
      "normals": [0, 0, -1, 0, 0, -2, 0.1, 0, -1],
      "uvs": [0, 0, 1, 0, 0, 1],
      "indices": [0, 2, 1]}},
    {{"name": "quad", "id": "q", "materialId": "plain", "rotationQuaternion": [0, 0.3826834, 0, 0.9238795],
      "positions": [-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1],
      "indices": [0, 2, 1, 0, 3, 2]}},
    {{"name": "empty", "id": "e", "positions": [], "indices": []}}
  ],
  "cameras": [{{"name": "cam", "id": "cam", "position": [0, 1, -5], "rotation": [0.1, 0.2, 0], "fov": 0.9, "minZ": 0.5, "maxZ": 50}}],
  "activeCamera": "cam",
  "lights": [
    {{"name": "sun", "id": "sun", "type": 1, "direction": [0, -1, 1], "intensity": 0.5}},
    {{"name": "bulb", "id": "bulb", "type": 0, "position": [1, 2, 3], "diffuse": [1, 0.5, 0]}},
    {{"name": "spot", "id": "spot", "type": 2, "position": [0, 0, 0]}}
  ]
}}"#
    )
}

/// A 4×2 image: top row red, green, blue, white; bottom row black, a
/// dark color that tests RGB565 rounding, gray, orange.
pub const PIXELS: [[u8; 3]; 8] =
    [[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 255], [0, 0, 0], [5, 3, 5], [128, 128, 128], [255, 128, 0]];

/// Writes a PNG of the given pixels (row-major, top row first).
pub fn write_png(path: &std::path::Path, width: u32, height: u32, pixels: &[[u8; 3]]) {
    let data: Vec<u8> = pixels.iter().flatten().copied().collect();
    encode(path, width, height, png::ColorType::Rgb, &data);
}

/// Writes an RGBA PNG of the given pixels (row-major, top row first).
pub fn write_rgba_png(path: &std::path::Path, width: u32, height: u32, pixels: &[[u8; 4]]) {
    let data: Vec<u8> = pixels.iter().flatten().copied().collect();
    encode(path, width, height, png::ColorType::Rgba, &data);
}

fn encode(path: &std::path::Path, width: u32, height: u32, color: png::ColorType, data: &[u8]) {
    let mut enc = png::Encoder::new(std::io::BufWriter::new(std::fs::File::create(path).unwrap()), width, height);
    enc.set_color(color);
    enc.set_depth(png::BitDepth::Eight);
    enc.write_header().unwrap().write_image_data(data).unwrap();
}
