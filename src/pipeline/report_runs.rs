//! Everything the report shows, run and compared: every scene, the convergence studies and the
//! work-precision studies, in parallel (the results do not depend on the thread count: every
//! case is independent and results are collected in order).

use super::score::score_committed;
use super::studies::{run_convergence, run_work_precision};
use super::{EvaluateError, evaluate_scene};
use crate::compare::convergence::ConvergenceResult;
use crate::compare::outcome::SceneOutcome;
use crate::compare::score::outcome::ScoredSet;
use crate::compare::work_precision::WorkPoint;
use crate::io::parallel::in_order;
use crate::results::exchange::committed::CommittedSet;
use crate::run::force_floor::element_force_seconds;
use crate::scene::cases::Scene;
use crate::scene::studies::convergence::ConvergenceStudy;
use crate::scene::studies::work_precision::WORK_PRECISION_STUDIES;
use rayon::prelude::*;
use std::time::Instant;

/// The compared results the report renders.
#[derive(Debug, Clone, PartialEq)]
pub struct ReportRuns {
    /// Each scene's outcome with its wall time in seconds, in scene order.
    pub scenes: Vec<(SceneOutcome, f64)>,
    /// Each convergence study's levels, in study order.
    pub convergence: Vec<ConvergenceResult>,
    /// Each work-precision study's points, in the order of [`WORK_PRECISION_STUDIES`].
    pub work: Vec<Vec<WorkPoint>>,
    /// The committed result sets of other codes whose scene is among the scenes, scored: the
    /// set, the index of its scene, the scored set.
    pub other_codes: Vec<(&'static CommittedSet, usize, ScoredSet)>,
    /// Wall time of everything, in seconds.
    pub wall_time: f64,
    /// Seconds per lumped element force evaluation, measured after the work-precision studies
    /// ([`crate::run::force_floor::element_force_seconds`]); `None` without them.
    pub element_force_seconds: Option<f64>,
}

/// Run and compare `scenes`, `studies` and (unless `scenes_only`) the work-precision studies. A
/// progress bar shows on a terminal (indicatif draws to stderr and hides itself otherwise).
///
/// # Errors
/// The first scene or study, in order, that cannot run: `<scene>: <why>` or the study's message.
pub fn run_for_report(
    scenes: &[Scene],
    studies: &[ConvergenceStudy],
    scenes_only: bool,
) -> Result<ReportRuns, String> {
    let started = Instant::now();
    let progress = indicatif::ProgressBar::new((scenes.len() + studies.len()) as u64);
    progress.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let outcomes = scenes
        .par_iter()
        .map(|scene| {
            let t0 = Instant::now();
            let outcome = evaluate_scene(scene)
                .map(|o| (o, t0.elapsed().as_secs_f64()))
                .map_err(|e: EvaluateError| format!("{}: {e}", scene.name));
            progress.set_message(scene.name.clone());
            progress.inc(1);
            outcome
        })
        .collect::<Vec<Result<(SceneOutcome, f64), String>>>();
    let outcomes = in_order(outcomes)?;
    let convergence = studies
        .par_iter()
        .map(|study| {
            let result = run_convergence(study);
            progress.set_message(study.name);
            progress.inc(1);
            result
        })
        .collect::<Vec<Result<ConvergenceResult, String>>>();
    let convergence = in_order(convergence)?;
    progress.finish_and_clear();
    let work = if scenes_only {
        Vec::new()
    } else {
        in_order(
            WORK_PRECISION_STUDIES
                .par_iter()
                .map(run_work_precision)
                .collect(),
        )?
    };
    // Other codes' committed results answer the built-in scenes: only the built-in report.
    let other_codes = if scenes_only {
        Vec::new()
    } else {
        score_committed(scenes)?
    };
    let wall_time = started.elapsed().as_secs_f64();
    // Timed alone, after everything else: the floor the work-precision runs are stated against.
    let element_force_seconds = if scenes_only {
        None
    } else {
        element_force_seconds()
    };
    Ok(ReportRuns {
        scenes: outcomes,
        convergence,
        work,
        other_codes,
        wall_time,
        element_force_seconds,
    })
}
