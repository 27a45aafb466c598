//! The built-in scenes, compiled into the binary from `scenes/` so that `courant list` and
//! `courant run NAME` work from any directory.

use super::cases::Scene;
use super::error::SceneError;
use super::limits::Limits;
use super::spelling::hint;
use std::path::Path;

/// (name, TOML text) of every built-in scene.
pub const BUILTIN_SCENES: &[(&str, &str)] = &[
    ("fig1", include_str!("../../scenes/fig1.toml")),
    ("fig1_masses", include_str!("../../scenes/fig1_masses.toml")),
    (
        "fig1_schemes",
        include_str!("../../scenes/fig1_schemes.toml"),
    ),
    ("fig2", include_str!("../../scenes/fig2.toml")),
    ("fig2_theta", include_str!("../../scenes/fig2_theta.toml")),
    (
        "fig2_reversed",
        include_str!("../../scenes/fig2_reversed.toml"),
    ),
    ("layered", include_str!("../../scenes/layered.toml")),
    ("fig3", include_str!("../../scenes/fig3.toml")),
    ("fig5", include_str!("../../scenes/fig5.toml")),
    ("fig6", include_str!("../../scenes/fig6.toml")),
    (
        "contact_wall",
        include_str!("../../scenes/contact_wall.toml"),
    ),
    (
        "contact_unequal",
        include_str!("../../scenes/contact_unequal.toml"),
    ),
    (
        "impact_layered",
        include_str!("../../scenes/impact_layered.toml"),
    ),
    (
        "impact_layered_combined",
        include_str!("../../scenes/impact_layered_combined.toml"),
    ),
    (
        "impact_layered_stability",
        include_str!("../../scenes/impact_layered_stability.toml"),
    ),
    (
        "impact_layered_below_limits",
        include_str!("../../scenes/impact_layered_below_limits.toml"),
    ),
    (
        "impact_layered_park_free",
        include_str!("../../scenes/impact_layered_park_free.toml"),
    ),
    (
        "impact_graded",
        include_str!("../../scenes/impact_graded.toml"),
    ),
    (
        "impact_graded_penalty",
        include_str!("../../scenes/impact_graded_penalty.toml"),
    ),
    (
        "impact_graded_stability",
        include_str!("../../scenes/impact_graded_stability.toml"),
    ),
    ("dispersion", include_str!("../../scenes/dispersion.toml")),
    (
        "courant_sweep",
        include_str!("../../scenes/courant_sweep.toml"),
    ),
    (
        "courant_sweep_schemes",
        include_str!("../../scenes/courant_sweep_schemes.toml"),
    ),
    (
        "courant_sweep_own_limits",
        include_str!("../../scenes/courant_sweep_own_limits.toml"),
    ),
    (
        "stability_extremes",
        include_str!("../../scenes/stability_extremes.toml"),
    ),
    (
        "stability_exact",
        include_str!("../../scenes/stability_exact.toml"),
    ),
    (
        "stability_park",
        include_str!("../../scenes/stability_park.toml"),
    ),
    (
        "stability_noh_bathe",
        include_str!("../../scenes/stability_noh_bathe.toml"),
    ),
    ("fig1_si", include_str!("../../scenes/fig1_si.toml")),
    ("long_run", include_str!("../../scenes/long_run.toml")),
    ("graded_1e4", include_str!("../../scenes/graded_1e4.toml")),
    (
        "graded_1e4_long",
        include_str!("../../scenes/graded_1e4_long.toml"),
    ),
    ("layered_1e4", include_str!("../../scenes/layered_1e4.toml")),
    (
        "contact_courant_sweep",
        include_str!("../../scenes/contact_courant_sweep.toml"),
    ),
    (
        "contact_extremes",
        include_str!("../../scenes/contact_extremes.toml"),
    ),
    ("pc_ratio", include_str!("../../scenes/pc_ratio.toml")),
    (
        "contact_impact_stability",
        include_str!("../../scenes/contact_impact_stability.toml"),
    ),
    (
        "fig2_park_printed",
        include_str!("../../scenes/fig2_park_printed.toml"),
    ),
    ("fig1_airy", include_str!("../../scenes/fig1_airy.toml")),
];

/// The text of a built-in scene.
pub fn builtin_text(name: &str) -> Option<&'static str> {
    BUILTIN_SCENES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
}

/// Parse a built-in scene.
pub fn builtin_scene(name: &str) -> Option<Result<Scene, SceneError>> {
    builtin_scene_within(name, Limits::DEFAULT)
}

fn builtin_scene_within(name: &str, limits: Limits) -> Option<Result<Scene, SceneError>> {
    builtin_text(name)
        .map(|text| Scene::parse_within(name, &format!("scenes/{name}.toml"), text, limits))
}

/// Resolve a command-line argument: a path to a `.toml` file, or the name of a built-in scene.
pub fn resolve(arg: &str) -> Result<Scene, SceneError> {
    resolve_within(arg, Limits::DEFAULT)
}

/// [`resolve`] against `limits` ([`Limits::LARGE`] for `courant run --large`).
pub fn resolve_within(arg: &str, limits: Limits) -> Result<Scene, SceneError> {
    let path = Path::new(arg);
    // A name ending in .toml is a path even when it does not exist (and a FIFO or device named
    // so is refused by what it is, never opened); a built-in name wins over a directory of the
    // same name; any other existing path is read as a scene file, which names what it is.
    if arg.ends_with(".toml") || path.is_file() {
        return Scene::from_path_within(path, limits);
    }
    if let Some(scene) = builtin_scene_within(arg, limits) {
        return scene;
    }
    if std::fs::metadata(path).is_ok() {
        return Scene::from_path_within(path, limits);
    }
    builtin_scene_within(arg, limits).unwrap_or_else(|| {
        let names: Vec<&str> = BUILTIN_SCENES.iter().map(|(n, _)| *n).collect();
        let hint = hint(arg, &names);
        Err(SceneError {
            file: arg.to_string(),
            line: 0,
            column: 0,
            key: String::new(),
            message: format!(
                "no such scene file, and no built-in scene of that name; {hint}(built-in: {}; `courant list` describes them)",
                names.join(", ")
            ),
            also: Vec::new(),
        })
    })
}

/// Every built-in scene, parsed.
///
/// # Errors
/// A built-in scene does not parse (a bug caught by the tests).
pub fn all() -> Result<Vec<Scene>, SceneError> {
    BUILTIN_SCENES
        .iter()
        .map(|(name, text)| Scene::parse(name, &format!("scenes/{name}.toml"), text))
        .collect()
}

/// Resolve every argument like [`resolve`] does (every built-in scene when there is none).
/// Every bad argument is reported, not just the first.
///
/// # Errors
/// Every argument that is neither a readable scene file nor a built-in scene, with its error.
pub fn resolve_all(args: &[String]) -> Result<Vec<Scene>, Vec<SceneError>> {
    let names: Vec<String> = if args.is_empty() {
        BUILTIN_SCENES.iter().map(|(n, _)| n.to_string()).collect()
    } else {
        args.to_vec()
    };
    let (mut scenes, mut errors) = (Vec::new(), Vec::new());
    for name in &names {
        match resolve(name) {
            Ok(scene) => scenes.push(scene),
            Err(e) => errors.push(e),
        }
    }
    if errors.is_empty() {
        Ok(scenes)
    } else {
        Err(errors)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::spelling::closest;

    /// Source of truth: Damerau's edit distance (`scene::spelling`). Proves: a misspelt built-in name gets the
    /// nearest name, an unrelated word gets none.
    #[test]
    fn misspelt_names_get_the_nearest_builtin() {
        let names: Vec<&str> = BUILTIN_SCENES.iter().map(|(n, _)| *n).collect();
        assert_eq!(closest("fgi1", &names), Some("fig1"));
        assert_eq!(closest("fig_1", &names), Some("fig1"));
        assert_eq!(closest("FIG5", &names), Some("fig5"));
        assert_eq!(closest("layerd", &names), Some("layered"));
        assert_eq!(closest("banana", &names), None);
        let e = resolve("fig_1").unwrap_err().to_string();
        assert!(e.starts_with("fig_1: no such scene file"), "{e}");
        assert!(e.contains("did you mean fig1?"), "{e}");
    }
}
