//! The pipeline driven end to end: run a scene's cases (`run`), then compare the records
//! (`compare`). The only place where producing and comparing meet, so that neither stage knows
//! the other.
//!
//! ```text
//!   scene ──> run ──> results ──> compare ──> report / check
//!             \_______ pipeline _______/
//! ```
//!
//! - this module: one scene or one case, run and compared;
//! - [`studies`]: the report's convergence and work-precision studies, run and compared;
//! - [`report_runs`]: everything the report shows, run in parallel with a progress bar;
//! - [`score`]: another code's result files read and graded (`courant score`, the report's
//!   other codes).
//!
//! Enters: scenes and studies. Leaves: compared outcomes. Must not know: documents, figures,
//! tables' layout, the command line.

pub mod report_runs;
pub mod score;
pub mod studies;

use crate::compare::cache::ProfileCache;
use crate::compare::case::{CaseResult, compare_case};
use crate::compare::outcome::SceneOutcome;
use crate::compare::scene::compare_scene;
use crate::run::scene::{RefusedRun, run_scene};
use crate::run::stepping::run_case;
use crate::scene::cases::{Case, Scene};
use courant_references::ReferenceError;
use courant_solver::RunError;
use thiserror::Error;

/// Why a scene could not be evaluated.
#[derive(Debug, Error)]
pub enum EvaluateError {
    /// The solver refused a case.
    #[error(transparent)]
    Run(#[from] RunError),
    /// A contact case the solver refused.
    #[error(transparent)]
    Contact(#[from] crate::run::contact::ContactRunError),
    /// A reference refused its parameters.
    #[error(transparent)]
    Reference(#[from] ReferenceError),
}

/// Run every case of a scene and compare the records with their references and expectations.
///
/// # Errors
/// The first case (in case order) the solver refuses, or a reference that refuses its
/// parameters.
pub fn evaluate_scene(scene: &Scene) -> Result<SceneOutcome, EvaluateError> {
    let records = run_scene(scene).map_err(|refused| match refused {
        RefusedRun::Case(e) => EvaluateError::Run(e),
        RefusedRun::Contact(e) => EvaluateError::Contact(e),
    })?;
    Ok(compare_scene(scene, records)?)
}

/// Run one time-stepping case and compare it with its reference.
///
/// # Errors
/// The solver refuses the case.
pub fn evaluate_case(case: &Case) -> Result<CaseResult, RunError> {
    let record = run_case(case)?;
    Ok(compare_case(
        record,
        case.reference.as_ref(),
        &ProfileCache::default(),
    ))
}
