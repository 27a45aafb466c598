//! The built-in scenes, compiled into the binary from `scenes/` so that `courant list` and
//! `courant run NAME` work from any directory.

use crate::scene::{Scene, SceneError};
use std::path::Path;

/// (name, TOML text) of every built-in scene.
pub const BUILTIN_SCENES: &[(&str, &str)] = &[
    ("fig1", include_str!("../scenes/fig1.toml")),
    ("fig1_masses", include_str!("../scenes/fig1_masses.toml")),
    ("fig2", include_str!("../scenes/fig2.toml")),
    (
        "fig2_reversed",
        include_str!("../scenes/fig2_reversed.toml"),
    ),
    ("layered", include_str!("../scenes/layered.toml")),
    ("fig3", include_str!("../scenes/fig3.toml")),
    ("fig5", include_str!("../scenes/fig5.toml")),
    ("fig6", include_str!("../scenes/fig6.toml")),
    ("contact_wall", include_str!("../scenes/contact_wall.toml")),
    (
        "contact_unequal",
        include_str!("../scenes/contact_unequal.toml"),
    ),
    ("dispersion", include_str!("../scenes/dispersion.toml")),
    (
        "courant_sweep",
        include_str!("../scenes/courant_sweep.toml"),
    ),
    (
        "courant_sweep_schemes",
        include_str!("../scenes/courant_sweep_schemes.toml"),
    ),
    (
        "stability_extremes",
        include_str!("../scenes/stability_extremes.toml"),
    ),
    (
        "stability_exact",
        include_str!("../scenes/stability_exact.toml"),
    ),
    (
        "stability_park",
        include_str!("../scenes/stability_park.toml"),
    ),
    ("fig1_si", include_str!("../scenes/fig1_si.toml")),
    ("long_run", include_str!("../scenes/long_run.toml")),
    ("graded_1e4", include_str!("../scenes/graded_1e4.toml")),
    ("layered_1e4", include_str!("../scenes/layered_1e4.toml")),
    (
        "contact_courant_sweep",
        include_str!("../scenes/contact_courant_sweep.toml"),
    ),
    (
        "contact_extremes",
        include_str!("../scenes/contact_extremes.toml"),
    ),
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
    builtin_text(name).map(|text| Scene::parse(name, &format!("scenes/{name}.toml"), text))
}

/// Resolve a command-line argument: a path to a `.toml` file, or the name of a built-in scene.
pub fn resolve(arg: &str) -> Result<Scene, SceneError> {
    let path = Path::new(arg);
    if arg.ends_with(".toml") || path.is_file() {
        return Scene::from_path(path);
    }
    builtin_scene(arg).unwrap_or_else(|| {
        let names: Vec<&str> = BUILTIN_SCENES.iter().map(|(n, _)| *n).collect();
        Err(SceneError {
            file: arg.to_string(),
            line: 0,
            column: 0,
            key: String::new(),
            message: format!(
                "no such scene file, and no built-in scene of that name (built-in: {})",
                names.join(", ")
            ),
        })
    })
}
