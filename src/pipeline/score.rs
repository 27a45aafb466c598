//! Another code's results read and scored: each results directory read into an exchange set
//! (`results::exchange`), then graded against the scene (`compare::score`); and the result sets
//! committed in this repository, scored for the report.

use crate::compare::score::outcome::{ScoreError, ScoreOutcome, ScoredSet};
use crate::compare::score::set::{score, score_set};
use crate::results::exchange::committed::{COMMITTED, CommittedSet};
use crate::results::exchange::reader::read_dir;
use crate::scene::cases::Scene;
use std::path::PathBuf;

/// Read every directory (in order) and score the sets against `scene`.
///
/// # Errors
/// The first directory that cannot be read or scored, naming file, line, column and key.
pub fn score_dirs(scene: &Scene, dirs: &[PathBuf]) -> Result<ScoreOutcome, ScoreError> {
    let sets = dirs
        .iter()
        .map(|d| read_dir(d))
        .collect::<Result<Vec<_>, _>>()?;
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
