//! Another code's results read and scored: each results directory read into an exchange set
//! (`results::exchange`), then graded against the scene (`compare::score`); and the result sets
//! committed in this repository, scored for the report.

use crate::compare::score::bind::bind;
use crate::compare::score::outcome::{ScoreError, ScoreOutcome, ScoredSet};
use crate::compare::score::set::{score, score_set};
use crate::results::exchange::committed::{COMMITTED, CommittedSet};
use crate::results::exchange::error::ExchangeErrors;
use crate::results::exchange::files::read_dir_partial;
use crate::scene::cases::Scene;
use std::path::{Path, PathBuf};

/// The directory of a set: `dir` itself, or `dir/<scene>` when `dir` holds no case file and
/// has that subdirectory (the layout `courant reference --out dir` and `run --exchange dir`
/// write).
pub fn set_dir(scene: &Scene, dir: &Path) -> PathBuf {
    let has_cases = std::fs::read_dir(dir).is_ok_and(|entries| {
        entries
            .flatten()
            .any(|e| e.path().extension().is_some_and(|x| x == "csv"))
    });
    let nested = dir.join(&scene.name);
    if !has_cases && nested.is_dir() {
        nested
    } else {
        dir.to_path_buf()
    }
}

/// Read every directory (in order) and score the sets against `scene`.
///
/// # Errors
/// Every file of every directory that cannot be read or bound to the scene, each naming file,
/// line, column and key.
pub fn score_dirs(scene: &Scene, dirs: &[PathBuf]) -> Result<ScoreOutcome, ScoreError> {
    let mut sets = Vec::new();
    let mut errors = Vec::new();
    for dir in dirs {
        let (set, read_errors) = read_dir_partial(&set_dir(scene, dir));
        if read_errors.is_empty() {
            sets.extend(set);
            continue;
        }
        errors.extend(read_errors);
        // The files that did read are still bound to the scene, so that one run reports
        // everything to fix.
        if let Some(set) = set
            && let Err(ScoreError::Input(e)) = bind(scene, &set)
        {
            errors.extend(e.0);
        }
    }
    if !errors.is_empty() {
        return Err(ScoreError::Input(ExchangeErrors(errors)));
    }
    score(scene, &sets)
}

/// Every committed result set whose scene is among `scenes`, scored: `(set, scene index, scored
/// set)` in the order of [`COMMITTED`].
///
/// # Errors
/// A committed set that does not read or score (a bug caught by the tests): `<dir>: <why>`.
pub fn score_committed(
    scenes: &[Scene],
) -> Result<Vec<(&'static CommittedSet, usize, ScoredSet)>, String> {
    COMMITTED
        .iter()
        .filter_map(|set| {
            let index = scenes.iter().position(|s| s.name == set.scene)?;
            let scored = set
                .read()
                .map_err(ScoreError::from)
                .and_then(|read| score_set(&scenes[index], &read))
                .map_err(|e| format!("{}: {e}", set.dir));
            Some(scored.map(|s| (set, index, s)))
        })
        .collect()
}
