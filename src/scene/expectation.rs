//! Expectations: the metric a scene bounds, the bound and its source of truth, as read from
//! `[[expect]]` tables (checked against the scene's cases and profile times when it is parsed).

pub use super::bound::Bound;
use super::contact::ForceMeasure;
use super::error::{SceneError, Source};
use super::mass::{mass_name, parse_mass};
use super::schema::RawExpect;
use courant_solver::MassKind;
use toml::Spanned;

use super::metric::{AUTOMATIC, METRICS};
pub use super::metric::{Metric, Study};

/// A requirement a case must meet, with its source of truth.
#[derive(Debug, Clone, PartialEq)]
pub struct Expectation {
    /// Cases it applies to.
    pub cases: Vec<String>,
    /// The metric.
    pub metric: Metric,
    /// Profile time (absolute), or `None` for the worst over all profile times.
    pub at: Option<f64>,
    /// The bound.
    pub bound: Bound,
    /// A case the measured value is relative to: the ratio `value(case) / value(relative_to)`,
    /// or for `force_history_difference` the distance between the two histories.
    pub relative_to: Option<String>,
    /// `mass_deviation`, `mode_error_ratio`: the mass kind compared and the one it is compared
    /// against.
    pub masses: Option<(MassKind, MassKind)>,
    /// Contact force metrics: the force measured, when not the scene's.
    pub force: Option<ForceMeasure>,
    /// An error bound or a signature of the case's scheme and mass.
    pub kind: RowKind,
    /// A stated finding (`finding = true`): a row that measures where a claim of the seed does
    /// not hold as stated; its verdict passes as a finding while the bound holds.
    pub finding: bool,
    /// Where the bound comes from.
    pub source: String,
}

/// What an expectation says of a result: that it is accurate (a bound every code at least as
/// accurate meets), or that it behaves as the case's scheme and mass behave (a signature).
///
/// courant's own runs are held to both. Another code's result set is held to every bound, and to
/// a signature only when its `results.toml` declares the case's scheme, parameters and mass
/// (`compare::score::applies`): a more accurate code must not fail `linf >= 0.3` (the dispersed
/// front of lumped central difference), and a less accurate one must not pass it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RowKind {
    /// An error bound: the exact answer meets it, and so does anything at least as accurate.
    Bound,
    /// A property of the case's scheme and mass (a band, a lower bound on an error, a ratio of
    /// two cases).
    Signature,
}

impl RowKind {
    /// Scene-file name.
    pub fn name(self) -> &'static str {
        match self {
            RowKind::Bound => "bound",
            RowKind::Signature => "signature",
        }
    }

    /// The kind a row has when the scene does not say: a bound when the metric is an error
    /// (zero for the exact answer: `l1`, `l2`, `linf`, `overshoot`, the contact force errors,
    /// the spectrum's, dispersion's and critical Courant number's deviation from their closed
    /// forms) bounded from above only, of one case; a signature otherwise (a lower bound on an
    /// error, a band, a ratio or a difference of two cases, an energy, divergence, a critical
    /// step, a mass deviation, a total-variation ratio).
    pub fn default_for(metric: Metric, bound: Bound, relative_to: Option<&str>) -> RowKind {
        match bound {
            Bound::Range {
                min: None,
                max: Some(_),
            } if relative_to.is_none() && metric.is_error() => RowKind::Bound,
            _ => RowKind::Signature,
        }
    }
}

/// What an `[[expect]]` table is checked against when the scene is parsed.
pub(super) struct ExpectContext<'a> {
    /// The scene's case names.
    pub names: &'a [String],
    /// Whether the cases have an analytic reference.
    pub has_reference: bool,
    /// The scene's study.
    pub study: Study,
    /// Profile times (absolute).
    pub profile_times: &'a [f64],
    /// The scene's time unit (absolute time per unit).
    pub unit: f64,
    /// The mass kinds of a spectrum scene.
    pub masses: &'a [MassKind],
}

pub(super) fn expectation(
    src: &Source,
    spanned: &Spanned<RawExpect>,
    ctx: &ExpectContext,
) -> Result<Expectation, SceneError> {
    let ExpectContext {
        names,
        has_reference,
        study,
        profile_times,
        unit,
        masses,
    } = *ctx;
    let raw = spanned.get_ref();
    let fail = |msg: String| src.error(Some(spanned.span()), "expect", msg);
    for (name, value) in [("min", raw.min), ("max", raw.max), ("at", raw.at)] {
        if let Some(v) = value.filter(|v| !v.is_finite()) {
            return Err(src.error(
                Some(src.value_span(spanned.span(), name)),
                &format!("expect.{name}"),
                format!("{name} = {v} is not a finite number; a bound (or time) must be one"),
            ));
        }
    }
    let metric = Metric::parse(&raw.metric).ok_or_else(|| {
        let all: Vec<&str> = METRICS
            .iter()
            .filter(|m| !AUTOMATIC.contains(&m.0))
            .map(|m| m.1)
            .collect();
        let hint = crate::scene::spelling::hint(&raw.metric, &all);
        src.error(
            Some(src.value_span(spanned.span(), "metric")),
            "expect.metric",
            format!(
                "\"{}\" is not one of the metrics: {hint}(all: {})",
                raw.metric,
                all.join(", ")
            ),
        )
    })?;
    if metric == Metric::Stability {
        return Err(fail(
            "the stability verdict is automatic in a stability scene (`[scene] stability = true`); declare a disagreement with `[[finding]]`".into(),
        ));
    }
    if AUTOMATIC.contains(&metric) {
        return Err(fail(format!(
            "metric \"{}\" is a convergence study's own verdict, not an expectation",
            metric.name()
        )));
    }
    if metric.needs_reference() && !has_reference {
        return Err(fail(format!(
            "metric \"{}\" compares with a reference, but the scene has none",
            metric.name()
        )));
    }
    if !metric.applies_to(study) {
        return Err(fail(format!(
            "metric \"{}\" does not apply to a {} scene",
            metric.name(),
            study.name()
        )));
    }
    let selected = match &raw.cases {
        None => names.to_vec(),
        Some(list) => {
            if let Some(unknown) = list.iter().find(|c| !names.contains(c)) {
                return Err(fail(format!(
                    "case \"{unknown}\" does not exist (cases: {})",
                    names.join(", ")
                )));
            }
            list.clone()
        }
    };
    let at = match raw.at {
        None => None,
        Some(t) => {
            let t = t * unit;
            if !profile_times
                .iter()
                .any(|&p| (p - t).abs() <= 1e-9 * p.abs().max(1e-300))
            {
                return Err(fail(format!(
                    "at = {} is not one of the profile times",
                    t / unit
                )));
            }
            Some(t)
        }
    };
    let bound = match (metric, raw.min, raw.max, raw.equals) {
        (Metric::Diverged, None, None, Some(b)) => Bound::Equals(b),
        (Metric::Diverged, _, _, _) => {
            return Err(fail(
                "metric \"diverged\" takes `equals = true|false` only".into(),
            ));
        }
        (_, _, _, Some(_)) => {
            return Err(fail("`equals` applies only to metric \"diverged\"".into()));
        }
        (_, None, None, None) => return Err(fail("needs `max`, `min` or both".into())),
        (_, Some(lo), Some(hi), None) if lo > hi => {
            return Err(fail(format!("min = {lo} is above max = {hi}")));
        }
        (_, min, max, None) => Bound::Range { min, max },
    };
    let relative_to = match (&raw.relative_to, metric) {
        (Some(_), Metric::Diverged | Metric::MassDeviation | Metric::ModeErrorRatio) => {
            return Err(fail(format!(
                "`relative_to` does not apply to metric \"{}\"",
                metric.name()
            )));
        }
        (None, m) if m.compares_cases() => {
            return Err(fail(format!(
                "metric \"{}\" needs `relative_to`: the case it is compared with",
                m.name()
            )));
        }
        (Some(other), _) if !names.contains(other) => {
            return Err(fail(format!(
                "relative_to = \"{other}\" is not a case (cases: {})",
                names.join(", ")
            )));
        }
        (other, _) => other.clone(),
    };
    let masses = match (metric, &raw.mass, &raw.against) {
        (m, Some(mass), Some(against)) if m.compares_masses() => {
            let kind = |label: &str| -> Result<MassKind, SceneError> {
                let kind = parse_mass(label).map_err(&fail)?;
                if masses.contains(&kind) {
                    Ok(kind)
                } else {
                    let listed: Vec<String> = masses.iter().map(|m| mass_name(*m)).collect();
                    Err(fail(format!(
                        "mass \"{label}\" is not one of the scene's masses ({})",
                        listed.join(", ")
                    )))
                }
            };
            Some((kind(mass)?, kind(against)?))
        }
        (m, _, _) if m.compares_masses() => {
            return Err(fail(format!(
                "metric \"{}\" needs `mass` and `against` (two of the scene's mass kinds)",
                m.name()
            )));
        }
        (_, None, None) => None,
        (_, _, _) => {
            return Err(fail(
                "`mass` and `against` apply only to metrics \"mass_deviation\" and \"mode_error_ratio\"".into(),
            ));
        }
    };
    let force_metric = matches!(
        metric,
        Metric::PlateauDeviation
            | Metric::DurationError
            | Metric::ForceL1Error
            | Metric::ForceL1OffJumps
            | Metric::SeparationError
            | Metric::MaxForce
            | Metric::ForceHistoryDifference
    );
    let force = match raw.force.as_deref() {
        None => None,
        Some(_) if !force_metric => {
            return Err(fail(format!(
                "`force` applies only to the contact force metrics, not to \"{}\"",
                metric.name()
            )));
        }
        Some("penalty") => Some(ForceMeasure::PenaltyForce),
        Some("transferred") => Some(ForceMeasure::TransferredMomentum),
        Some(other) => {
            return Err(fail(format!(
                "force = \"{other}\" is not one of penalty, transferred"
            )));
        }
    };
    let kind = match raw.kind.as_deref() {
        None => RowKind::default_for(metric, bound, relative_to.as_deref()),
        Some("signature") => RowKind::Signature,
        Some("bound") => {
            if RowKind::default_for(metric, bound, relative_to.as_deref()) != RowKind::Bound {
                return Err(src.error(
                    Some(src.value_span(spanned.span(), "kind")),
                    "expect.kind",
                    format!(
                        "kind = \"bound\" needs an error metric ({}) bounded by `max` only, of one case (no `relative_to`): an error bound is met by the exact answer and by every result at least as accurate; `{}` {} is a signature of the case's scheme",
                        METRICS
                            .iter()
                            .filter(|m| m.0.is_error())
                            .map(|m| m.1)
                            .collect::<Vec<_>>()
                            .join(", "),
                        metric.name(),
                        bound
                    ),
                ));
            }
            RowKind::Bound
        }
        Some(other) => {
            return Err(src.error(
                Some(src.value_span(spanned.span(), "kind")),
                "expect.kind",
                format!("kind = \"{other}\" is not one of bound, signature"),
            ));
        }
    };
    if raw.source.trim().is_empty() {
        return Err(fail(
            "`source` must name the source of truth of the bound".into(),
        ));
    }
    Ok(Expectation {
        cases: selected,
        metric,
        at,
        bound,
        relative_to,
        masses,
        force,
        kind,
        finding: raw.finding.unwrap_or(false),
        source: raw.source.clone(),
    })
}
