//! The `[integrator]` of a time-stepping scene: step or Courant numbers (and their unit),
//! schemes, mass kinds, start, stability policy.

use super::error::{SceneError, Source, positive};
use super::mass::parse_mass;
use super::outputs::Outputs;
use super::schema::{RawCourantUnit, RawIntegrator, RawStart};
use courant_solver::{MassKind, ParkOptions, ParkVariant, StabilityPolicy, Start, TimePlan};
use std::ops::Range;

/// The integrator settings of a time-stepping scene.
pub(super) struct Stepping {
    pub(super) key: &'static str,
    pub(super) span: Range<usize>,
    pub(super) values: Vec<f64>,
    pub(super) by_courant: bool,
    /// What `courant` values are relative to.
    pub(super) unit: RawCourantUnit,
    /// `keep_step = true`: the step is kept exactly, output times snap to it.
    pub(super) keep_step: bool,
    pub(super) masses: Vec<MassKind>,
    /// (case-name prefix, Park options or `None` for CD).
    pub(super) schemes: Vec<(&'static str, Option<ParkOptions>)>,
    pub(super) start: Start,
    pub(super) stability: StabilityPolicy,
}

impl Stepping {
    pub(super) fn read(src: &Source, raw: &RawIntegrator) -> Result<Self, SceneError> {
        let (key, spanned, by_courant) = match (&raw.courant, &raw.dt) {
            (Some(c), None) => ("integrator.courant", c, true),
            (None, Some(d)) => ("integrator.dt", d, false),
            (Some(c), Some(_)) => {
                return Err(src.error(
                    Some(c.span()),
                    "integrator",
                    "give either `courant` or `dt`, not both",
                ));
            }
            (None, None) => {
                return Err(src.error(
                    None,
                    "integrator",
                    "needs `courant` (Courant numbers) or `dt` (time steps)",
                ));
            }
        };
        let span = spanned.span();
        let values = spanned.get_ref().values();
        if values.is_empty() {
            return Err(src.error(
                Some(span),
                key,
                "the list is empty; give at least one value",
            ));
        }
        if let Some(bad) = values.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
            return Err(src.error(
                Some(span),
                key,
                format!("{bad} must be positive and finite"),
            ));
        }
        let masses = match &raw.mass {
            None => vec![MassKind::Lumped],
            Some(m) => {
                let labels = m.get_ref().values();
                if labels.is_empty() {
                    return Err(src.error(
                        Some(m.span()),
                        "integrator.mass",
                        "the list is empty; give at least one mass",
                    ));
                }
                labels
                    .iter()
                    .map(|l| {
                        parse_mass(l)
                            .map_err(|msg| src.error(Some(m.span()), "integrator.mass", msg))
                    })
                    .collect::<Result<_, _>>()?
            }
        };
        let blowup_energy_ratio = match &raw.blowup_energy_ratio {
            Some(v) => positive(src, v, "integrator.blowup_energy_ratio")?,
            None => StabilityPolicy::default().blowup_energy_ratio,
        };
        let start = match raw.start {
            RawStart::HalfStep => Start::HalfStep,
            RawStart::ThreeLevel => Start::ThreeLevel,
        };
        let stability = StabilityPolicy {
            allow_unstable: raw.allow_unstable,
            blowup_energy_ratio,
        };
        let theta = match &raw.theta {
            None => 0.5,
            Some(t) if (0.0..=1.0).contains(t.get_ref()) => *t.get_ref(),
            Some(t) => {
                return Err(src.error(
                    Some(t.span()),
                    "integrator.theta",
                    format!("{} must lie in [0, 1]", t.get_ref()),
                ));
            }
        };
        let variant = match raw
            .park_variant
            .as_ref()
            .map(|v| (v.get_ref().as_str(), v.span()))
        {
            None | Some(("free", _)) => ParkVariant::Free,
            Some(("incremental", _)) => ParkVariant::Incremental,
            Some((other, span)) => {
                return Err(src.error(
                    Some(span),
                    "integrator.park_variant",
                    format!("\"{other}\" is not one of free, incremental"),
                ));
            }
        };
        let labels = raw
            .scheme
            .as_ref()
            .map(|s| s.get_ref().values())
            .unwrap_or_else(|| vec!["central-difference".into()]);
        let scheme_span = raw.scheme.as_ref().map(|s| s.span());
        if labels.is_empty() {
            return Err(src.error(
                scheme_span,
                "integrator.scheme",
                "the list is empty; give at least one scheme",
            ));
        }
        let schemes = labels
            .iter()
            .map(|label| match label.as_str() {
                "central-difference" | "cd" => Ok(("cd", None)),
                "park-lts" => Ok((
                    "park-lts",
                    Some(ParkOptions {
                        theta,
                        variant,
                        local_stepping: true,
                    }),
                )),
                "park-global" => Ok((
                    "park-global",
                    Some(ParkOptions {
                        theta,
                        variant,
                        local_stepping: false,
                    }),
                )),
                other => Err(src.error(
                    scheme_span.clone(),
                    "integrator.scheme",
                    format!(
                        "\"{other}\" is not one of central-difference (cd), park-lts, park-global"
                    ),
                )),
            })
            .collect::<Result<Vec<_>, _>>()?;
        if !schemes.iter().any(|s| s.1.is_some())
            && (raw.theta.is_some() || raw.park_variant.is_some())
        {
            return Err(src.error(
                scheme_span,
                "integrator",
                "`theta` and `park_variant` apply only to the park-lts and park-global schemes",
            ));
        }
        if schemes.iter().any(|s| s.1.is_some()) && masses.iter().any(|m| *m != MassKind::Lumped) {
            return Err(src.error(
                scheme_span,
                "integrator.scheme",
                "Park's scheme runs with the lumped mass only",
            ));
        }
        let unit = match (&raw.courant_unit, by_courant) {
            (None, _) => RawCourantUnit::StiffestElement,
            (Some(u), true) => *u.get_ref(),
            (Some(u), false) => {
                return Err(src.error(
                    Some(u.span()),
                    "integrator.courant_unit",
                    "applies to `courant` only; a `dt` is a time step in the scene's own unit",
                ));
            }
        };
        let keep_step = raw.keep_step.unwrap_or(false);
        Ok(Self {
            key,
            span,
            values,
            by_courant,
            unit,
            keep_step,
            masses,
            schemes,
            start,
            stability,
        })
    }
}

/// The plan of a `keep_step` case: the step as given, end and profile times snapped to their
/// nearest steps ([`courant_solver::plan_keeping_step`]); two profile times on one step are
/// refused (each needs its own profile).
pub(super) fn keep_step_plan(
    src: &Source,
    outputs: &Outputs,
    dt: f64,
    case_name: &str,
    stepping: (Range<usize>, &'static str),
) -> Result<TimePlan, SceneError> {
    // Blame the end time where the file sets it, else the step (courant or dt) that ran into it.
    let (span, key) = match outputs.raw.end_time.as_ref() {
        Some(end) => (end.span(), "output.end_time"),
        None => stepping,
    };
    let plan = courant_solver::plan_keeping_step(dt, &outputs.profile_times, outputs.end_time)
        .map_err(|e| {
            src.error(
                Some(span),
                key,
                format!(
                    "case {case_name}: {e} (times in absolute units, not the scene's time_unit)"
                ),
            )
        })?;
    let mut taken: Vec<(usize, f64)> = Vec::with_capacity(plan.output_steps.len());
    for (&t, &n) in outputs.profile_times.iter().zip(&plan.output_steps) {
        if let Some(&(_, other)) = taken.iter().find(|(m, u)| *m == n && *u != t) {
            return Err(src.error(
                outputs.raw.profile_times.as_ref().map(|p| p.span()),
                "output.profile_times",
                format!(
                    "case {case_name}: {} and {} fall on the same step {n} (dt = {dt:e}); with keep_step = true \
                     each profile time needs its own step",
                    other / outputs.unit,
                    t / outputs.unit
                ),
            ));
        }
        taken.push((n, t));
    }
    Ok(plan)
}
