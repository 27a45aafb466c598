//! The scene's `[[expect]]` rows on a result set: an expectation's `cases` are matched with the
//! files' stems (an expectation without `cases` applies to every case), measured with the norms
//! and measures of `courant run`, judged by the same rule ([`judge`]). What files cannot carry
//! (energies, whether a run diverged) and cases without a file are skipped, with the reason.

use super::bind::profile_times;
use super::outcome::{Scored, ScoredCase, Skipped};
use crate::compare::expect::{at_time, judge};
use crate::compare::norms::ErrorNorms;
use crate::compare::verdict::{Measured, Verdict};
use crate::scene::cases::Scene;
use crate::scene::expectation::{Expectation, Metric};

/// Verdicts of every expectation of `scene` on `cases`, and the expectations skipped.
pub fn evaluate(scene: &Scene, cases: &[ScoredCase]) -> (Vec<Verdict>, Vec<Skipped>) {
    let (mut verdicts, mut skipped) = (Vec::new(), Vec::new());
    for expectation in &scene.expectations {
        for name in &expectation.cases {
            let skip = |reason: String| Skipped {
                case: name.clone(),
                metric: expectation.metric,
                at: expectation.at,
                reason,
                source: expectation.source.clone(),
            };
            let Some(case) = cases.iter().find(|c| &c.case == name) else {
                skipped.push(skip(format!("no {name}.csv in this set")));
                continue;
            };
            match measure(scene, expectation, case) {
                Ok(measured) => verdicts.push(judge(expectation, name.clone(), measured)),
                Err(reason) => skipped.push(skip(reason)),
            }
        }
    }
    (verdicts, skipped)
}

/// What a file says of the expectation's metric, or why it cannot say.
fn measure(
    scene: &Scene,
    expectation: &Expectation,
    case: &ScoredCase,
) -> Result<Measured, String> {
    let norm = |pick: fn(&ErrorNorms) -> f64| -> Result<Measured, String> {
        let Scored::Profiles { profiles, .. } = &case.scored else {
            return Err("the file holds no stress profiles".into());
        };
        let scene_case = scene.cases.iter().find(|c| c.name == case.case);
        let times = match (expectation.at, scene_case) {
            (Some(t), _) => vec![t],
            (None, Some(c)) => profile_times(c),
            (None, None) => profiles.iter().map(|p| p.time).collect(),
        };
        let dt = case.dt.map_or(0.0, |d| d.0);
        let mut worst = f64::NEG_INFINITY;
        for t in times {
            let at: Vec<f64> = profiles
                .iter()
                .filter(|p| at_time(Some(t), p.time, dt))
                .map(|p| pick(&p.norms))
                .collect();
            if at.is_empty() {
                return Ok(Measured::Missing(format!(
                    "the file has no profile at t = {t}"
                )));
            }
            worst = at.into_iter().fold(worst, f64::max);
        }
        Ok(Measured::Value(worst))
    };
    let force = |pick: fn(&super::outcome::ScoredForce) -> f64| match &case.scored {
        Scored::Force(f) => Ok(Measured::Value(pick(f))),
        _ => Err("the file holds no force history".to_string()),
    };
    match expectation.metric {
        Metric::L1 => norm(|n| n.l1),
        Metric::L2 => norm(|n| n.l2),
        Metric::Linf => norm(|n| n.linf),
        Metric::Overshoot => norm(|n| n.overshoot),
        Metric::TvRatio => norm(|n| n.tv_ratio),
        Metric::PlateauDeviation => force(|f| f.metrics.plateau_deviation),
        Metric::ImpulseError => force(|f| f.metrics.impulse_error),
        Metric::DurationError => force(|f| f.metrics.duration_error),
        Metric::ForceL1Error => force(|f| f.metrics.force_l1_error),
        Metric::ClosedFormDeviation => match &case.scored {
            Scored::Spectrum(s) => Ok(Measured::Value(s.deviation)),
            _ => Err("the file holds no spectrum".into()),
        },
        Metric::EnergyBalance | Metric::EnergyLost | Metric::EnergyRatio => {
            Err("not measurable from files: format 1 carries no energies".into())
        }
        Metric::Diverged => Err(
            "not measurable from files: a result file does not say whether its run diverged".into(),
        ),
        Metric::DispersionDeviation | Metric::PhaseErrorOrder | Metric::CourantDeviation => {
            Err("not measurable from files: format 1 has no dispersion or stability data".into())
        }
    }
}
