//! Checking a scene's expectations against its compared results.
//!
//! Each expectation is measured on every case it names, in the scene's study: time-stepping
//! results, spectra, dispersion runs, contact runs or the contact stability sweep. With
//! `relative_to` the value is the ratio `value(case) / value(relative_to)`; for
//! `force_history_difference` it is the distance between the two force histories.

use super::case::{CaseResult, ProfileComparison};
use super::contact::{
    ContactResult, DURATION_UNDEFINED, ENERGY_RATIO_UNDEFINED, ForceErrors, PLATEAU_UNDEFINED,
    SEPARATION_UNDEFINED,
};
use super::front_width::{FRONT_WIDTH_UNDEFINED, front_width};
use super::norms::ErrorNorms;
use super::outcome::SceneOutcome;
use super::spectrum::SpectrumResult;
use super::stress_difference::{ProfileView, stress_difference};
use super::verdict::{Measured, Verdict};
use crate::results::case::Status;
use crate::scene::cases::Scene;
use crate::scene::contact::ForceMeasure;
use crate::scene::expectation::{Bound, Expectation, Metric};

/// Evaluate every expectation of `scene` on the matching results.
pub fn evaluate(scene: &Scene, outcome: &SceneOutcome) -> Vec<Verdict> {
    let mut verdicts = Vec::new();
    for expectation in &scene.expectations {
        for (case, measured) in measure_all(expectation, outcome) {
            verdicts.push(judge(expectation, case, measured));
        }
    }
    verdicts
}

/// The verdict of `expectation` on `case` given what was `measured`: a finite value within the
/// range, or the flag it must equal; anything missing fails.
pub fn judge(expectation: &Expectation, case: String, measured: Measured) -> Verdict {
    let pass = match (&measured, expectation.bound) {
        (Measured::Value(x), Bound::Range { min, max }) => {
            x.is_finite() && min.is_none_or(|lo| *x >= lo) && max.is_none_or(|hi| *x <= hi)
        }
        (Measured::Flag(b), Bound::Equals(want)) => *b == want,
        _ => false,
    };
    Verdict {
        case,
        metric: expectation.metric,
        at: expectation.at,
        relative_to: expectation.relative_to.clone(),
        masses: expectation.masses,
        force: expectation.force,
        measured,
        bound: expectation.bound,
        pass,
        finding: pass && expectation.finding,
        source: expectation.source.clone(),
    }
}

/// True when a profile at `time` is the one an expectation `at` names: hit exactly by a planned
/// step, or (keep_step) the step nearest to `at`, within half a step `dt`. Every profile when
/// `at` is `None`.
pub fn at_time(at: Option<f64>, time: f64, dt: f64) -> bool {
    at.is_none_or(|t| (time - t).abs() <= (1e-9 * t.abs()).max(0.5 * dt).max(1e-300))
}

/// `(case, measured)` for every case the expectation names, in the scene's study.
fn measure_all(e: &Expectation, outcome: &SceneOutcome) -> Vec<(String, Measured)> {
    let wanted = |case: &str| e.cases.iter().any(|c| c == case);
    if !outcome.contact.is_empty() {
        return outcome
            .contact
            .iter()
            .filter(|r| wanted(&r.case))
            .map(|r| {
                (
                    r.case.clone(),
                    relative(e, r, &outcome.contact, contact_value),
                )
            })
            .collect();
    }
    if !outcome.sweeps.is_empty() {
        return outcome
            .sweeps
            .iter()
            .map(|s| {
                let value = match e.metric {
                    Metric::UnitCourantDeviation => s.unit_deviation(),
                    Metric::PenaltyAsymptoteDeviation => s.penalty_asymptote_deviation(),
                    _ => Some(s.deviation()),
                };
                let measured = value.map_or(
                    Measured::Missing("the sweep has no such curve".into()),
                    Measured::Value,
                );
                ("stability".to_string(), measured)
            })
            .collect();
    }
    if !outcome.spectra.is_empty() {
        return outcome
            .spectra
            .iter()
            .filter(|r| wanted(&r.case))
            .map(|r| (r.case.clone(), spectrum_value(e, r)))
            .collect();
    }
    if !outcome.dispersion.is_empty() {
        return outcome
            .dispersion
            .iter()
            .filter(|r| wanted(&r.case.name))
            .map(|r| {
                let value = match e.metric {
                    Metric::PhaseErrorOrder => r.min_order().map_or(
                        Measured::Missing("no mode pair n, 2n".into()),
                        Measured::Value,
                    ),
                    _ => Measured::Value(r.deviation()),
                };
                (r.case.name.clone(), value)
            })
            .collect();
    }
    outcome
        .results
        .iter()
        .filter(|r| wanted(&r.run.case))
        .map(|r| {
            (
                r.run.case.clone(),
                relative(e, r, &outcome.results, case_value),
            )
        })
        .collect()
}

/// A case's result, found by name among its scene's.
trait Named {
    fn name(&self) -> &str;
}

impl Named for CaseResult {
    fn name(&self) -> &str {
        &self.run.case
    }
}

impl Named for ContactResult {
    fn name(&self) -> &str {
        &self.case
    }
}

/// The value of `e` on `r`, or relative to the case `e.relative_to` (a ratio, or the metric's
/// own comparison when it takes the other case itself).
fn relative<R: Named>(
    e: &Expectation,
    r: &R,
    all: &[R],
    value: fn(&Expectation, &R, Option<&R>) -> Measured,
) -> Measured {
    let Some(other) = &e.relative_to else {
        return value(e, r, None);
    };
    let Some(reference) = all.iter().find(|x| x.name() == other) else {
        return Measured::Missing(format!("no result for {other}"));
    };
    if e.metric.compares_cases() {
        return value(e, r, Some(reference));
    }
    ratio(value(e, r, None), value(e, reference, None), other)
}

/// `a / b` of a case's value and the value of the case `other` it is relative to (missing
/// when either is, or `b` is 0).
pub fn ratio(a: Measured, b: Measured, other: &str) -> Measured {
    match (a, b) {
        (Measured::Value(a), Measured::Value(b)) if b != 0.0 => Measured::Value(a / b),
        (Measured::Value(_), Measured::Value(_)) => {
            Measured::Missing(format!("{other} measures 0: no ratio"))
        }
        (Measured::Missing(why), _) => Measured::Missing(why),
        (_, Measured::Missing(why)) => Measured::Missing(format!("{other}: {why}")),
        _ => Measured::Missing("not a number".into()),
    }
}

/// A time-stepping metric of one case.
fn case_value(e: &Expectation, result: &CaseResult, other: Option<&CaseResult>) -> Measured {
    // The worst over the selected profiles of a value each profile may lack (`None`: no
    // reference) or leave undefined (`Some(None)`, with `undefined` the reason).
    let per_profile =
        |pick: &dyn Fn(&ProfileComparison) -> Option<Option<f64>>, undefined: &str| -> Measured {
            let selected: Vec<Option<f64>> = result
                .profiles
                .iter()
                .filter(|p| at_time(e.at, p.time, result.run.dt))
                .filter_map(pick)
                .collect();
            let expected = if e.at.is_some() {
                1
            } else {
                result.run.profiles_requested
            };
            if selected.len() < expected {
                return Measured::Missing("the run ended before every profile time".into());
            }
            let defined: Vec<f64> = selected.into_iter().flatten().collect();
            if defined.is_empty() {
                return Measured::Missing(undefined.into());
            }
            Measured::Value(defined.into_iter().fold(f64::NEG_INFINITY, f64::max))
        };
    let norm_of = |pick: fn(&ErrorNorms) -> Option<f64>| -> Measured {
        per_profile(
            &|p| p.norms.as_ref().map(pick),
            "undefined: the exact profile has no variation (one element, or no front yet)",
        )
    };
    match e.metric {
        Metric::L1 => norm_of(|n| Some(n.l1)),
        Metric::L2 => norm_of(|n| Some(n.l2)),
        Metric::Linf => norm_of(|n| Some(n.linf)),
        Metric::Overshoot => norm_of(|n| Some(n.overshoot)),
        Metric::FrontWidth => per_profile(
            &|p| {
                p.reference
                    .as_ref()
                    .map(|r| front_width(&p.x, &p.stress, r))
            },
            FRONT_WIDTH_UNDEFINED,
        ),
        Metric::TvRatio => norm_of(|n| n.tv_ratio),
        Metric::EnergyLost => Measured::Value(result.energy_lost()),
        Metric::EnergyBalance => Measured::Value(result.energy.relative_balance_error()),
        Metric::Diverged => Measured::Flag(matches!(result.run.status, Status::Diverged(_))),
        Metric::ElementBoundRatio => {
            Measured::Value(result.run.critical.element / result.run.critical.exact)
        }
        Metric::CriticalCourant => {
            Measured::Value(result.run.courant * result.run.limit.dt() / result.run.dt)
        }
        Metric::StressDifference => match other {
            Some(other) => {
                fn views(r: &CaseResult, at: Option<f64>) -> Vec<ProfileView<'_>> {
                    r.profiles
                        .iter()
                        .filter(|p| at_time(at, p.time, r.run.dt))
                        .map(|p| ProfileView {
                            time: p.time,
                            x: &p.x,
                            stress: &p.stress,
                        })
                        .collect()
                }
                stress_difference(
                    &views(result, e.at),
                    &views(other, e.at),
                    0.5 * result.run.dt,
                )
                .map_or_else(Measured::Missing, Measured::Value)
            }
            None => Measured::Missing("needs relative_to".into()),
        },
        _ => Measured::Missing("not a time-stepping metric".into()),
    }
}

/// A contact metric of one case (`other`: the case of `force_history_difference`).
fn contact_value(e: &Expectation, r: &ContactResult, other: Option<&ContactResult>) -> Measured {
    let errors = match e.force {
        None => Some(&r.errors),
        Some(measure) => r.errors_of(measure),
    };
    let of = |pick: fn(&ForceErrors) -> f64| {
        errors.map_or(
            Measured::Missing("the scheme has no penalty force".into()),
            |errors| Measured::Value(pick(errors)),
        )
    };
    match e.metric {
        Metric::PlateauDeviation => match errors.map(|e| e.plateau_deviation) {
            Some(Some(d)) => Measured::Value(d),
            Some(None) => Measured::Missing(PLATEAU_UNDEFINED.into()),
            None => Measured::Missing("the scheme has no penalty force".into()),
        },
        Metric::ImpulseError => Measured::Value(r.impulse_error),
        Metric::DurationError => match errors.map(|e| e.duration_error) {
            Some(Some(d)) => Measured::Value(d),
            Some(None) => Measured::Missing(DURATION_UNDEFINED.into()),
            None => Measured::Missing("the scheme has no penalty force".into()),
        },
        Metric::ForceL1Error => of(|e| e.force_l1_error),
        Metric::ForceL1OffJumps => of(|e| e.force_l1_off_jumps),
        Metric::SeparationError => match errors.map(|e| e.separation_error) {
            Some(Some(d)) => Measured::Value(d),
            Some(None) => Measured::Missing(SEPARATION_UNDEFINED.into()),
            None => Measured::Missing("the scheme has no penalty force".into()),
        },
        Metric::EnergyRatio => r.energy_ratio.map_or(
            Measured::Missing(ENERGY_RATIO_UNDEFINED.into()),
            Measured::Value,
        ),
        Metric::MaxForce => of(|e| e.max_force),
        Metric::CriticalCourant => Measured::Value(r.run.critical.critical_courant()),
        Metric::Diverged => Measured::Flag(r.diverged.is_some()),
        Metric::ForceHistoryDifference => match other {
            Some(other) => force_history_difference(r, other, e.force.unwrap_or(r.measure)),
            None => Measured::Missing("needs relative_to".into()),
        },
        _ => Measured::Missing("not a contact metric".into()),
    }
}

/// `max_k |F_a(t_k) - F_b(t_k)| / F1` over the samples both runs took at the same time (bit for
/// bit: same step and sampling), F1 the exact first plateau of `a`.
fn force_history_difference(
    a: &ContactResult,
    b: &ContactResult,
    measure: ForceMeasure,
) -> Measured {
    let (ha, hb) = (&a.run.history, &b.run.history);
    let common = ha.len().min(hb.len());
    if common == 0 || (0..common).any(|k| ha[k].time.to_bits() != hb[k].time.to_bits()) {
        return Measured::Missing(format!(
            "{} and {} do not sample the same times (same step and history_every needed)",
            a.case, b.case
        ));
    }
    let worst = (0..common)
        .map(|k| (measure.force(&ha[k]) - measure.force(&hb[k])).abs())
        .fold(0.0, f64::max);
    Measured::Value(worst / a.plateau)
}

/// A spectrum metric of one case.
fn spectrum_value(e: &Expectation, r: &SpectrumResult) -> Measured {
    match (e.metric, e.masses) {
        (Metric::ClosedFormDeviation, _) => r.closed_form_deviation().map_or(
            Measured::Missing("no closed form for this case".into()),
            Measured::Value,
        ),
        (Metric::MassDeviation, Some((mass, against))) => {
            let column = |kind| r.masses.iter().position(|m| *m == kind);
            match (column(mass), column(against)) {
                (Some(a), Some(b)) => {
                    // Elastic modes only: the rigid mode of a free bar is 0 up to round-off.
                    let top = r.computed[b].iter().copied().fold(0.0, f64::max);
                    Measured::Value(
                        r.computed[a]
                            .iter()
                            .zip(&r.computed[b])
                            .filter(|(_, w)| **w > 1e-6 * top)
                            .map(|(v, w)| (v / w - 1.0).abs())
                            .fold(0.0, f64::max),
                    )
                }
                _ => Measured::Missing("the case lacks one of the two masses".into()),
            }
        }
        (Metric::ModeErrorRatio, Some((mass, against))) => {
            if r.continuum.is_none() {
                Measured::Missing("no continuum reference for this case".into())
            } else {
                r.max_mode_error_ratio(mass, against).map_or(
                    Measured::Missing("the case lacks one of the two masses".into()),
                    Measured::Value,
                )
            }
        }
        _ => Measured::Missing("not a spectrum metric".into()),
    }
}
