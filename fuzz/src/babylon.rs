//! The `babylon` case: any bytes must load or give an error, never panic,
//! and a scene that loads must give valid meshes.

use soft3d::babylon::BabylonScene;
use std::sync::Mutex;

/// Small capacities so that capacity errors are reached as well; a `static`
/// because the scene is too large to rebuild on the stack for every input.
type Scene = BabylonScene<8, 8, 8, 2048, 2048, 6144>;
static SCENE: Mutex<Scene> = Mutex::new(Scene::new());

/// Loads `data` and checks the result (panics on a violation).
pub fn run(data: &[u8]) {
    let mut scene = SCENE.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    match scene.load(data) {
        Ok(()) => {
            for (i, info) in scene.meshes().iter().enumerate() {
                let mesh = scene.mesh(i).expect("every loaded mesh validates");
                assert_eq!(mesh.vertex_count(), info.vertex_count());
                assert!(mesh.positions().iter().all(|p| p.is_finite()));
                // Normalized on load, or zero.
                assert!(mesh.normals().iter().all(|n| n == soft3d::math::Vec3::ZERO || (n.length() - 1.0).abs() < 1e-4));
                let _ = info.model_matrix();
            }
            assert_eq!(scene.iter().count(), scene.meshes().len());
            let _ = (scene.to_camera(), scene.to_lights());
        }
        Err(e) => {
            // Every error formats, and a failed load leaves the scene empty.
            assert!(!e.to_string().is_empty());
            assert!(scene.meshes().is_empty() && scene.camera().is_none());
        }
    }
}
