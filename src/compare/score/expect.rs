//! The scene's `[[expect]]` rows on a result set: an expectation's `cases` are matched with the
//! files' stems (an expectation without `cases` applies to every case), measured with the norms
//! and measures of `courant run`, judged by the same rule ([`judge`]). With `relative_to` the
//! value is the ratio to that case's file (`force_history_difference`: the distance between the
//! two files' histories). A file's force is graded whatever force measure an expectation names
//! (a file has one force). What files cannot carry (energies, whether a run diverged, critical
//! steps, stability verdicts) and cases without a file are skipped, with the reason. A file on
//! another mesh than the scene's case is held to the same bounds: those measured on the scene's
//! mesh may not hold there (fig1's `overshoot / co0.5 >= 1.05` of co0.1: 1.10 at N = 100, 1.02
//! at 400, 1.00 at 800).

use super::applies::Applies;
use super::bind::profile_times;
use super::outcome::{Scored, ScoredCase, ScoredForce, ScoredProfile, SkipKind, Skipped};
use crate::compare::contact::ForceErrors;
use crate::compare::contact::{DURATION_UNDEFINED, PLATEAU_UNDEFINED, SEPARATION_UNDEFINED};
use crate::compare::expect::{at_time, judge, ratio};
use crate::compare::front_width::{FRONT_WIDTH_UNDEFINED, front_width};
use crate::compare::norms::ErrorNorms;
use crate::compare::stress_difference::{ProfileView, stress_difference};
use crate::compare::verdict::{Measured, Verdict};
use crate::scene::bound::Bound;
use crate::scene::cases::Scene;
use crate::scene::expectation::{Expectation, Metric, RowKind};

/// Verdicts of every expectation of `scene` on `cases`, and the expectations skipped: a
/// signature row ([`RowKind::Signature`]) of a case whose file does not declare its scheme,
/// parameters and mass is not applicable; a case with no file, or a time with no profile, is
/// not supplied; what files cannot carry is not measurable.
pub fn evaluate(scene: &Scene, cases: &[ScoredCase]) -> (Vec<Verdict>, Vec<Skipped>) {
    let (mut verdicts, mut skipped) = (Vec::new(), Vec::new());
    let file = |name: &str| cases.iter().find(|c| c.case == name);
    for expectation in &scene.expectations {
        for name in &expectation.cases {
            let skip = |kind: SkipKind, reason: String| {
                let label = judge(expectation, name.clone(), Measured::Missing(String::new()))
                    .metric_label();
                Skipped {
                    kind,
                    case: name.clone(),
                    metric: expectation.metric,
                    label,
                    at: expectation.at,
                    reason,
                    source: expectation.source.clone(),
                }
            };
            let Some(case) = file(name) else {
                skipped.push(skip(
                    SkipKind::NotSupplied,
                    format!("not supplied: no {name}.csv in this set"),
                ));
                continue;
            };
            let other = match &expectation.relative_to {
                None => None,
                Some(other) => match file(other) {
                    Some(o) => Some(o),
                    None => {
                        skipped.push(skip(
                            SkipKind::NotSupplied,
                            format!("not supplied: no {other}.csv in this set"),
                        ));
                        continue;
                    }
                },
            };
            if expectation.kind == RowKind::Signature {
                let why = std::iter::once(case)
                    .chain(other)
                    .find_map(|c| match &c.applies {
                        Applies::Yes => None,
                        Applies::No(why) => Some(if other.is_some() {
                            format!("{}: {why}", c.case)
                        } else {
                            why.clone()
                        }),
                    });
                if let Some(why) = why {
                    skipped.push(skip(
                        SkipKind::NotApplicable,
                        format!(
                            "not applicable ({why}): a signature of the case's scheme and mass"
                        ),
                    ));
                    continue;
                }
            }
            let measured = match (other, expectation.metric) {
                (Some(o), Metric::ForceHistoryDifference) => {
                    force_history_difference(case, o).map_err(Unmeasured::Other)
                }
                (Some(o), Metric::StressDifference) => {
                    file_stress_difference(case, o, expectation.at).map_err(Unmeasured::Other)
                }
                (Some(o), _) => measure(scene, expectation, case)
                    .and_then(|a| measure(scene, expectation, o).map(|b| ratio(a, b, &o.case))),
                (None, _) => measure(scene, expectation, case),
            };
            match measured {
                Ok(m) => verdicts.push(judge(expectation, name.clone(), m)),
                Err(Unmeasured::NotSupplied(reason)) => {
                    skipped.push(skip(SkipKind::NotSupplied, reason));
                }
                Err(Unmeasured::Other(reason)) => {
                    skipped.push(skip(SkipKind::NotMeasurable, reason));
                }
            }
        }
    }
    (verdicts, skipped)
}

/// The stress difference of two files' profiles ([`stress_difference`]), at their common
/// profile times (to half of `a`'s step, or exactly without one), at `at` only when given.
fn file_stress_difference(
    a: &ScoredCase,
    b: &ScoredCase,
    at: Option<f64>,
) -> Result<Measured, String> {
    fn views(c: &ScoredCase, at: Option<f64>) -> Result<Vec<ProfileView<'_>>, String> {
        let dt = c.dt.map_or(0.0, |d| d.0);
        match &c.scored {
            Scored::Profiles { profiles, .. } => Ok(profiles
                .iter()
                .filter(|p| at_time(at, p.time, dt))
                .map(|p| ProfileView {
                    time: p.time,
                    x: &p.x,
                    stress: &p.stress,
                })
                .collect()),
            _ => Err(format!("{}.csv holds no stress profiles", c.case)),
        }
    }
    let tolerance = a.dt.map_or(0.0, |d| 0.5 * d.0);
    Ok(stress_difference(&views(a, at)?, &views(b, at)?, tolerance)
        .map_or_else(Measured::Missing, Measured::Value))
}

/// `max_k |F_a(t_k) - F_b(t_k)| / F1` over the samples of two files at the same times (bit for
/// bit), F1 the exact first plateau of `a`.
fn force_history_difference(a: &ScoredCase, b: &ScoredCase) -> Result<Measured, String> {
    let (Scored::Force(fa), Scored::Force(fb)) = (&a.scored, &b.scored) else {
        return Err("the files hold no force histories".into());
    };
    let common = fa.time.len().min(fb.time.len());
    if common == 0 || (0..common).any(|k| fa.time[k].to_bits() != fb.time[k].to_bits()) {
        return Ok(Measured::Missing(format!(
            "{} and {} do not sample the same times",
            a.case, b.case
        )));
    }
    let worst = (0..common)
        .map(|k| (fa.force[k] - fb.force[k]).abs())
        .fold(0.0, f64::max);
    Ok(Measured::Value(worst / fa.plateau))
}

/// Why a file gives no value for an expectation.
#[derive(Debug)]
enum Unmeasured {
    /// A profile time the file does not have.
    NotSupplied(String),
    /// Anything else (files cannot carry it, the file holds other data).
    Other(String),
}

impl From<String> for Unmeasured {
    fn from(why: String) -> Self {
        Unmeasured::Other(why)
    }
}

impl From<&str> for Unmeasured {
    fn from(why: &str) -> Self {
        Unmeasured::Other(why.to_string())
    }
}

/// What a file says of the expectation's metric, or why it cannot say.
fn measure(
    scene: &Scene,
    expectation: &Expectation,
    case: &ScoredCase,
) -> Result<Measured, Unmeasured> {
    // The worst over the profiles at the expectation's times of a value a profile may leave
    // undefined (`None`, with `undefined` the reason).
    let per_profile = |pick: &dyn Fn(&ScoredProfile) -> Option<f64>,
                       undefined: &str|
     -> Result<Measured, Unmeasured> {
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
            let at: Vec<Option<f64>> = profiles
                .iter()
                .filter(|p| at_time(Some(t), p.time, dt))
                .map(pick)
                .collect();
            if at.is_empty() {
                return Err(Unmeasured::NotSupplied(format!(
                    "not supplied: the file has no profile at t = {t}"
                )));
            }
            worst = at.into_iter().flatten().fold(worst, f64::max);
        }
        if worst == f64::NEG_INFINITY {
            return Ok(Measured::Missing(undefined.into()));
        }
        Ok(Measured::Value(worst))
    };
    let norm = |pick: fn(&ErrorNorms) -> Option<f64>| -> Result<Measured, Unmeasured> {
        per_profile(
            &|p| pick(&p.norms),
            "undefined: the exact profile has no variation (one element, or no front yet)",
        )
    };
    let force = |pick: fn(&ScoredForce) -> Option<f64>, why: &str| match &case.scored {
        Scored::Force(f) => Ok(pick(f).map_or(Measured::Missing(why.into()), Measured::Value)),
        _ => Err(Unmeasured::from("the file holds no force history")),
    };
    let errors = |f: &ScoredForce| -> ForceErrors { f.errors };
    match expectation.metric {
        Metric::L1 => norm(|n| Some(n.l1)),
        Metric::L2 => norm(|n| Some(n.l2)),
        Metric::Linf => norm(|n| Some(n.linf)),
        Metric::Overshoot => norm(|n| Some(n.overshoot)),
        Metric::FrontWidth => per_profile(
            &|p| front_width(&p.x, &p.stress, &p.reference),
            FRONT_WIDTH_UNDEFINED,
        ),
        Metric::TvRatio => norm(|n| n.tv_ratio),
        Metric::PlateauDeviation => force(|f| f.errors.plateau_deviation, PLATEAU_UNDEFINED),
        Metric::ImpulseError => force(
            |f| Some(f.impulse_error).filter(|e| e.is_finite()),
            "undefined: the impulse of the force history is not finite",
        ),
        Metric::DurationError => force(|f| f.errors.duration_error, DURATION_UNDEFINED),
        Metric::SeparationError => force(|f| f.errors.separation_error, SEPARATION_UNDEFINED),
        Metric::ForceL1OffJumps => force(
            |f| Some(f.errors.force_l1_off_jumps).filter(|e| e.is_finite()),
            "undefined: the L1 error of the force history is not finite",
        ),
        Metric::ForceL1Error => force(
            |f| Some(f.errors.force_l1_error).filter(|e| e.is_finite()),
            "undefined: the L1 error of the force history is not finite",
        ),
        Metric::MaxForce => match &case.scored {
            Scored::Force(f) => Ok(Measured::Value(errors(f).max_force)),
            _ => Err("the file holds no force history".into()),
        },
        Metric::ForceHistoryDifference | Metric::StressDifference => {
            Err("needs relative_to".into())
        }
        Metric::ClosedFormDeviation => match &case.scored {
            Scored::Spectrum(s) => Ok(Measured::Value(s.deviation)),
            _ => Err("the file holds no spectrum".into()),
        },
        Metric::MassDeviation => mass_deviation(expectation, case),
        Metric::ModeErrorRatio => mode_error_ratio(scene, expectation, case),
        Metric::EnergyBalance | Metric::EnergyLost | Metric::EnergyRatio => {
            Err("not measurable from files: format 1 carries no energies".into())
        }
        Metric::Diverged => Err(
            "not measurable from files: a result file does not say whether its run diverged".into(),
        ),
        Metric::FittedOrder | Metric::MaxError => {
            Err("convergence verdicts come from several sets (the study across --results)".into())
        }
        Metric::CriticalCourant | Metric::ElementBoundRatio | Metric::Stability => Err(
            "not measurable from files: format 1 carries no critical steps or stability verdicts"
                .into(),
        ),
        Metric::DispersionDeviation
        | Metric::PhaseErrorOrder
        | Metric::CourantDeviation
        | Metric::UnitCourantDeviation
        | Metric::PenaltyAsymptoteDeviation => {
            Err("not measurable from files: format 1 has no dispersion or stability data".into())
        }
    }
}

/// `(mode, omega)` rows of one mass kind of a spectrum file.
type ModeRows = Vec<(usize, f64)>;

/// The rows of the two mass kinds of a `mass_deviation` or `mode_error_ratio` row; not supplied
/// when the file has no rows of one of them.
fn two_masses(
    expectation: &Expectation,
    case: &ScoredCase,
) -> Result<(ModeRows, ModeRows), Unmeasured> {
    let Scored::Spectrum(s) = &case.scored else {
        return Err("the file holds no spectrum".into());
    };
    let Some((mass, against)) = expectation.masses else {
        return Err("needs the two mass kinds".into());
    };
    let of = |label: String| -> ModeRows {
        s.rows
            .iter()
            .filter(|r| r.0 == label)
            .map(|r| (r.1, r.2))
            .collect()
    };
    let (a, b) = (of(mass.label()), of(against.label()));
    if a.is_empty() || b.is_empty() {
        let missing = if a.is_empty() { mass } else { against };
        return Err(Unmeasured::NotSupplied(format!(
            "not supplied: the file has no {} rows",
            missing.label()
        )));
    }
    Ok((a, b))
}

/// `max |omega_a / omega_b - 1|` over the elastic modes both mass kinds of the file give (the
/// rigid mode, 0 up to round-off, left out), as `courant run` measures it; not supplied when the
/// file has no rows of one of the two masses.
fn mass_deviation(expectation: &Expectation, case: &ScoredCase) -> Result<Measured, Unmeasured> {
    let (a, b) = two_masses(expectation, case)?;
    let top = b.iter().map(|r| r.1).fold(0.0, f64::max);
    Ok(Measured::Value(
        a.iter()
            .filter_map(|(mode, v)| b.iter().find(|r| r.0 == *mode).map(|r| (v, r.1)))
            .filter(|(_, w)| *w > 1e-6 * top)
            .map(|(v, w)| (v / w - 1.0).abs())
            .fold(0.0, f64::max),
    ))
}

/// The largest [`mode_error_ratio`] over the elastic modes both mass kinds of the file give,
/// against the continuum frequency of each mode number (the rigid mode left out), as
/// `courant run` measures it; not measurable without a continuum reference for the case. A row
/// with a lower bound needs the case's top mode in both masses (the ratio peaks there,
/// methods.md §5): a file that gives fewer modes is not supplied for it, rather than failed.
fn mode_error_ratio(
    scene: &Scene,
    expectation: &Expectation,
    case: &ScoredCase,
) -> Result<Measured, Unmeasured> {
    let (a, b) = two_masses(expectation, case)?;
    let Some(bar) = scene
        .spectra
        .iter()
        .find(|c| c.name == case.case)
        .and_then(|c| c.closed_form.as_ref())
    else {
        return Err("no continuum reference for this case".into());
    };
    let top = *bar.modes().end();
    let has_top = |rows: &[(usize, f64)]| rows.iter().any(|r| r.0 == top);
    if matches!(expectation.bound, Bound::Range { min: Some(_), .. })
        && !(has_top(&a) && has_top(&b))
    {
        return Ok(Measured::Missing(format!(
            "the lower bound needs mode {top} (the top mode, where the ratio peaks) in both masses"
        )));
    }
    Ok(a.iter()
        .filter(|(mode, _)| bar.modes().contains(mode))
        .filter_map(|(mode, v)| {
            let w = b.iter().find(|r| r.0 == *mode)?.1;
            crate::compare::spectrum::mode_error_ratio(*v, w, bar.continuum_frequency(*mode))
        })
        .reduce(f64::max)
        .map_or(
            Measured::Missing("no elastic mode in both masses".into()),
            Measured::Value,
        ))
}
