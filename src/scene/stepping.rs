//! The `[integrator]` of a time-stepping scene: step or Courant numbers (and their unit),
//! schemes, mass kinds, start, stability policy.

use super::error::{SceneError, Source, positive};
use super::mass::parse_mass;
use super::outputs::Outputs;
use super::schema::{RawCourantUnit, RawIntegrator, RawStart};
use super::scheme_keys::SchemeKey;
use courant_solver::integrator::{ParameterValue, SchemeEntry};
use courant_solver::schemes;
use courant_solver::{MassKind, Scheme, StabilityPolicy, Start, TimePlan};
use std::ops::Range;
use std::sync::Arc;

/// A scheme of a scene with one value of each of its parameters.
pub(super) struct NamedScheme {
    /// The case-name prefix: the registry name when the scene lists several schemes, then one
    /// token per listed parameter (`theta0.25`, or the word itself: `incremental`); may be empty.
    pub(super) prefix: String,
    /// The scheme with its parameters.
    pub(super) scheme: Arc<dyn Scheme>,
    /// The values of the listed parameters it declares (a parameter sweep), in file order.
    pub(super) swept: Vec<(String, ParameterValue)>,
    /// Every parameter the scene gives this scheme, listed or not (what `results.toml`
    /// declares for an exported case).
    pub(super) parameters: Vec<(String, ParameterValue)>,
}

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
    /// Every scheme with every combination of its listed parameters' values.
    pub(super) schemes: Vec<NamedScheme>,
    pub(super) start: Start,
    pub(super) stability: StabilityPolicy,
}

impl Stepping {
    pub(super) fn read(
        src: &Source,
        raw: &RawIntegrator,
        scheme_keys: &[SchemeKey],
    ) -> Result<Self, SceneError> {
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
        let schemes = schemes(src, raw, scheme_keys, &masses, start)?;
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

/// The schemes of `integrator.scheme`, by their registry names, each built with the parameter
/// keys it declares; a key no listed scheme declares, a value that breaks its rule, or a mass or
/// start a scheme does not run with is an error at its line.
fn schemes(
    src: &Source,
    raw: &RawIntegrator,
    scheme_keys: &[SchemeKey],
    masses: &[MassKind],
    start: Start,
) -> Result<Vec<NamedScheme>, SceneError> {
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
    let entries: Vec<&'static SchemeEntry> = labels
        .iter()
        .map(|label| {
            schemes::find(label).ok_or_else(|| {
                src.error(
                    scheme_span.clone(),
                    "integrator.scheme",
                    format!("\"{label}\" is not one of {}", schemes::names()),
                )
            })
        })
        .collect::<Result<_, _>>()?;
    if let Some(unclaimed) = scheme_keys
        .iter()
        .find(|k| !entries.iter().any(|e| e.parameter(&k.key).is_some()))
    {
        let declared: Vec<String> = entries
            .iter()
            .map(|e| match e.parameters {
                [] => format!("{} takes none", e.name),
                ps => format!(
                    "{}: {}",
                    e.name,
                    ps.iter().map(|p| p.key).collect::<Vec<_>>().join(", ")
                ),
            })
            .collect();
        return Err(src.error(
            Some(unclaimed.span.clone()),
            &format!("integrator.{}", unclaimed.key),
            format!(
                "unknown field `{}`: neither a key of [integrator] nor a parameter of its schemes \
                 ({}); `courant list --schemes` lists every scheme's parameters",
                unclaimed.key,
                declared.join("; ")
            ),
        ));
    }
    let several = entries.len() > 1;
    let mut named = Vec::new();
    for entry in entries {
        let own: Vec<&SchemeKey> = scheme_keys
            .iter()
            .filter(|k| entry.parameter(&k.key).is_some())
            .collect();
        for combination in combinations(&own) {
            let scheme = entry.build_with(&combination).map_err(|e| {
                let span = scheme_keys
                    .iter()
                    .find(|k| k.key == e.key)
                    .map(|k| k.span.clone());
                src.error(span, &format!("integrator.{}", e.key), e.to_string())
            })?;
            for &mass in masses {
                scheme.check_settings(mass, start).map_err(|e| {
                    src.error(scheme_span.clone(), "integrator.scheme", e.to_string())
                })?;
            }
            let parameters = combination.clone();
            let swept: Vec<(String, ParameterValue)> = combination
                .into_iter()
                .filter(|(k, _)| own.iter().any(|o| o.listed && &o.key == k))
                .collect();
            let prefix: Vec<String> = several
                .then(|| entry.name.to_string())
                .into_iter()
                .chain(swept.iter().map(|(k, v)| match v {
                    ParameterValue::Number(x) => format!("{k}{}", super::names::number(*x)),
                    ParameterValue::Text(word) => word.clone(),
                }))
                .collect();
            named.push(NamedScheme {
                prefix: prefix.join("-"),
                scheme,
                swept,
                parameters,
            });
        }
    }
    Ok(named)
}

/// Every combination of one value per key (the cartesian product of the listed keys' values;
/// one combination when no key is a list), keys in file order.
fn combinations(keys: &[&SchemeKey]) -> Vec<Vec<(String, ParameterValue)>> {
    keys.iter().fold(vec![Vec::new()], |done, key| {
        done.iter()
            .flat_map(|partial| {
                key.values.iter().map(move |v| {
                    let mut next = partial.clone();
                    next.push((key.key.clone(), v.clone()));
                    next
                })
            })
            .collect()
    })
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
