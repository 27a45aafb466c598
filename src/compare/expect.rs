//! Checking a scene's expectations against its compared results.

use super::case::CaseResult;
use super::contact::{DURATION_UNDEFINED, ENERGY_RATIO_UNDEFINED};
use super::norms::ErrorNorms;
use super::outcome::SceneOutcome;
use super::verdict::{Measured, Verdict};
use crate::results::case::Status;
use crate::scene::cases::Scene;
use crate::scene::expectation::{Bound, Expectation, Metric, Study};

/// Evaluate every expectation of `scene` on the matching results.
pub fn evaluate(scene: &Scene, outcome: &SceneOutcome) -> Vec<Verdict> {
    let (results, spectra, dispersion) = (&outcome.results, &outcome.spectra, &outcome.dispersion);
    let mut verdicts = Vec::new();
    for expectation in &scene.expectations {
        let wanted = |case: &String| expectation.cases.contains(case);
        let study = match expectation.metric {
            Metric::Diverged if !outcome.contact.is_empty() => Study::Contact,
            m => m.study(),
        };
        let measured: Vec<(String, Measured)> = match study {
            Study::Spectrum => spectra
                .iter()
                .filter(|r| wanted(&r.case))
                .map(|r| {
                    let value = r.closed_form_deviation();
                    (
                        r.case.clone(),
                        value.map_or(
                            Measured::Missing("no closed form for this case".into()),
                            Measured::Value,
                        ),
                    )
                })
                .collect(),
            Study::Dispersion => dispersion
                .iter()
                .filter(|r| wanted(&r.case.name))
                .map(|r| {
                    let value = match expectation.metric {
                        Metric::PhaseErrorOrder => r.min_order().map_or(
                            Measured::Missing("no mode pair n, 2n".into()),
                            Measured::Value,
                        ),
                        _ => Measured::Value(r.deviation()),
                    };
                    (r.case.name.clone(), value)
                })
                .collect(),
            Study::Contact => outcome
                .contact
                .iter()
                .filter(|r| wanted(&r.case))
                .map(|r| {
                    let value = match expectation.metric {
                        Metric::PlateauDeviation => Measured::Value(r.plateau_deviation),
                        Metric::ImpulseError => Measured::Value(r.impulse_error),
                        Metric::DurationError => r.duration_error.map_or(
                            Measured::Missing(DURATION_UNDEFINED.into()),
                            Measured::Value,
                        ),
                        Metric::ForceL1Error => Measured::Value(r.force_l1_error),
                        Metric::EnergyRatio => r.energy_ratio.map_or(
                            Measured::Missing(ENERGY_RATIO_UNDEFINED.into()),
                            Measured::Value,
                        ),
                        _ => Measured::Flag(r.diverged.is_some()),
                    };
                    (r.case.clone(), value)
                })
                .collect(),
            Study::ContactStability => outcome
                .sweeps
                .iter()
                .map(|s| ("stability".to_string(), Measured::Value(s.deviation())))
                .collect(),
            Study::TimeStepping => results
                .iter()
                .filter(|r| wanted(&r.case))
                .map(|r| (r.case.clone(), measure(expectation, r)))
                .collect(),
        };
        for (case, measured) in measured {
            let pass = match (&measured, expectation.bound) {
                (Measured::Value(x), Bound::Range { min, max }) => {
                    x.is_finite() && min.is_none_or(|lo| *x >= lo) && max.is_none_or(|hi| *x <= hi)
                }
                (Measured::Flag(b), Bound::Equals(want)) => *b == want,
                _ => false,
            };
            verdicts.push(Verdict {
                case,
                metric: expectation.metric,
                at: expectation.at,
                measured,
                bound: expectation.bound,
                pass,
                source: expectation.source.clone(),
            });
        }
    }
    verdicts
}

fn measure(expectation: &Expectation, result: &CaseResult) -> Measured {
    let norm_of = |pick: fn(&ErrorNorms) -> Option<f64>| -> Measured {
        let selected: Vec<Option<f64>> = result
            .profiles
            .iter()
            .filter(|p| {
                // The profile of time t: hit exactly by a planned step, or (keep_step) the step
                // nearest to t, within half a step.
                expectation.at.is_none_or(|t| {
                    (p.time - t).abs() <= (1e-9 * t.abs()).max(0.5 * result.dt).max(1e-300)
                })
            })
            .filter_map(|p| p.norms.as_ref().map(pick))
            .collect();
        let expected = if expectation.at.is_some() {
            1
        } else {
            result.profiles_requested
        };
        if selected.len() < expected {
            return Measured::Missing("the run ended before every profile time".into());
        }
        let defined: Vec<f64> = selected.into_iter().flatten().collect();
        if defined.is_empty() {
            return Measured::Missing(
                "undefined: the exact profile has no variation (one element, or no front yet)"
                    .into(),
            );
        }
        Measured::Value(defined.into_iter().fold(f64::NEG_INFINITY, f64::max))
    };
    match expectation.metric {
        Metric::L1 => norm_of(|n| Some(n.l1)),
        Metric::L2 => norm_of(|n| Some(n.l2)),
        Metric::Linf => norm_of(|n| Some(n.linf)),
        Metric::Overshoot => norm_of(|n| Some(n.overshoot)),
        Metric::TvRatio => norm_of(|n| n.tv_ratio),
        Metric::EnergyLost => Measured::Value(result.energy_lost()),
        Metric::EnergyBalance => Measured::Value(result.energy.relative_balance_error()),
        Metric::Diverged => Measured::Flag(matches!(result.status, Status::Diverged(_))),
        Metric::ClosedFormDeviation
        | Metric::DispersionDeviation
        | Metric::PhaseErrorOrder
        | Metric::PlateauDeviation
        | Metric::ImpulseError
        | Metric::DurationError
        | Metric::ForceL1Error
        | Metric::EnergyRatio
        | Metric::CourantDeviation => Measured::Missing("not a time-stepping metric".into()),
    }
}
