//! Scoring result sets against a scene: bind every file to its case, compare each beside its
//! reference (in parallel, in case order), judge the expectations, and study convergence across
//! sets.

use super::bind::{Target, bind};
use super::convergence::convergence;
use super::expect::evaluate;
use super::force::score_force;
use super::outcome::{ScoreError, ScoreOutcome, ScoredCase, ScoredSet};
use super::profiles::score_profiles;
use super::spectrum::score_spectrum;
use crate::io::parallel::in_order;
use crate::results::exchange::error::ExchangeErrors;
use crate::results::exchange::record::{CaseData, ExchangeSet};
use crate::scene::cases::Scene;
use rayon::prelude::*;

/// Score one set against `scene`. Cases are compared in parallel and kept in the scene's case
/// order, so the result does not depend on the thread count.
///
/// # Errors
/// As [`bind`], or a mesh the solver's `Mesh` refuses.
pub fn score_set(scene: &Scene, set: &ExchangeSet) -> Result<ScoredSet, ScoreError> {
    let mut bound = bind(scene, set)?;
    let order = |name: &str| {
        let names = super::bind::SceneKind::of(scene)
            .map(|k| k.case_names(scene))
            .unwrap_or_default();
        names.iter().position(|n| n == name).unwrap_or(usize::MAX)
    };
    bound.sort_by_key(|b| order(&b.file.case));
    let cases: Vec<Result<ScoredCase, ScoreError>> = bound
        .par_iter()
        .map(|b| match (&b.target, &b.file.data) {
            (Target::Stepping(case, reference), CaseData::Profiles(p)) => {
                score_profiles(b, case, reference, p)
            }
            (Target::Contact(case), CaseData::Force(h)) => Ok(score_force(b, case, h)),
            (Target::Spectrum(case), CaseData::Spectrum(rows)) => Ok(score_spectrum(b, case, rows)),
            _ => Err(ScoreError::Scene(format!(
                "{}: its data does not match its case (a bug: binding checks this)",
                b.file.file
            ))),
        })
        .collect();
    let cases = in_order(cases)?;
    let (verdicts, skipped) = evaluate(scene, &cases);
    let meta = set.meta.as_ref();
    let missing_cases = super::bind::SceneKind::of(scene)
        .map(|k| k.case_names(scene))
        .unwrap_or_default()
        .into_iter()
        .filter(|name| !cases.iter().any(|c| &c.case == name))
        .collect();
    Ok(ScoredSet {
        missing_cases,
        require_all: false,
        stated: Vec::new(),
        label: set.label.clone(),
        code: set.code(),
        version: meta
            .and_then(|m| m.version.clone())
            .unwrap_or_else(|| "-".into()),
        cases,
        verdicts,
        skipped,
    })
}

/// Score every set (in argument order) and study the convergence of cases given at several N.
///
/// # Errors
/// Every file of every set that cannot be bound to the scene; or the first scene-level refusal.
pub fn score(scene: &Scene, sets: &[ExchangeSet]) -> Result<ScoreOutcome, ScoreError> {
    let mut scored = Vec::new();
    let mut errors = Vec::new();
    for set in sets {
        match score_set(scene, set) {
            Ok(s) => scored.push(s),
            Err(ScoreError::Input(e)) => errors.extend(e.0),
            Err(other) => return Err(other),
        }
    }
    if !errors.is_empty() {
        return Err(ScoreError::Input(ExchangeErrors(errors)));
    }
    Ok(ScoreOutcome {
        scene: scene.name.clone(),
        convergence: convergence(scene, &scored),
        sets: scored,
    })
}
