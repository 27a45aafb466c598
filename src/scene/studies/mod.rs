//! The report's studies, as scenes: each is a built-in scene with text substitutions (a list of
//! meshes, one Courant number, fewer profile times), parsed like any scene file. What they
//! measure is computed by `compare`, how they run by `pipeline`, how they read by `report`.
//!
//! - [`convergence`]: h-refinement studies with the order bands theory allows;
//! - [`work_precision`]: error against work per scheme, with Courant variants;

pub mod convergence;
pub mod work_precision;

use super::builtin::builtin_text;
use super::cases::Scene;

/// A study's scene: the built-in scene `scene` without its expectations, with each
/// `(from, to)` substitution applied once; an error names the study when a substitution no
/// longer matches (the built-in scene changed under the study).
pub fn derived_scene(
    name: &str,
    scene: &str,
    replacements: &[(&str, &str)],
) -> Result<Scene, String> {
    let mut text = builtin_text(scene)
        .ok_or_else(|| format!("no built-in scene {scene}"))?
        .to_string();
    if let Some(i) = text.find("[[expect]]") {
        text.truncate(i);
    }
    for (from, to) in replacements {
        if !text.contains(from) {
            return Err(format!(
                "study {name}: scene {scene} no longer contains {from:?}"
            ));
        }
        text = text.replacen(from, to, 1);
    }
    Scene::parse(name, &format!("study {name}"), &text).map_err(|e| e.to_string())
}
