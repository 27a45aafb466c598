//! Expectations: the metric a scene bounds, the bound and its source of truth, as read from
//! `[[expect]]` tables (checked against the scene's cases and profile times when it is parsed).

use super::error::{SceneError, Source};
use super::schema::RawExpect;
use toml::Spanned;

/// A metric an expectation bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Metric {
    /// L1 error of the element stresses, `(1/L) sum_e h_e |sigma_e - sigma_ref,e| / |sigma0|`.
    L1,
    /// L2 error, `sqrt((1/L) sum_e h_e (sigma_e - sigma_ref,e)^2) / |sigma0|`.
    L2,
    /// Max error, `max_e |sigma_e - sigma_ref,e| / |sigma0|`.
    Linf,
    /// Overshoot beyond the exact solution's envelope, as a fraction of the jump |sigma0|.
    Overshoot,
    /// Largest |energy balance error| relative to the energy scale of the run.
    EnergyBalance,
    /// Whether the run diverged.
    Diverged,
    /// Total variation of the profile over the exact one's (1 = no spurious oscillation).
    TvRatio,
    /// Energy the scheme dissipated by the end of the run, relative to the energy scale:
    /// `-(T + U - W)_end / scale` (0 for CD up to round-off; Park dissipates a little).
    EnergyLost,
    /// Spectrum scenes: largest relative deviation of the computed elastic frequencies from the
    /// closed-form discrete spectra (methods.md §5), over every mode and mass kind.
    ClosedFormDeviation,
    /// Dispersion scenes: largest `|measured - closed form|` of the phase-speed ratio.
    DispersionDeviation,
    /// Dispersion scenes: smallest observed order of the phase error between modes `n` and `2n`.
    PhaseErrorOrder,
    /// Contact: largest `|F - F1|/F1` inside the first plateau (10 % to 90 % of it).
    PlateauDeviation,
    /// Contact: `|impulse - exact| / exact`.
    ImpulseError,
    /// Contact: `|duration - exact| / exact` (duration from the half-plateau crossings).
    DurationError,
    /// Contact: L1 norm in time of the force error over the exact impulse.
    ForceL1Error,
    /// Contact: energy of the real masses at the end over the initial energy.
    EnergyRatio,
    /// Contact stability: largest relative deviation of the solver's critical Courant number
    /// from the closed form.
    CourantDeviation,
}

/// The kind of study a scene is; each metric belongs to one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Study {
    /// Time-stepping cases.
    TimeStepping,
    /// Spectra.
    Spectrum,
    /// Single-mode dispersion runs.
    Dispersion,
    /// Contact-impact runs.
    Contact,
    /// Contact stability sweep.
    ContactStability,
}

impl Study {
    /// Name in messages.
    pub fn name(self) -> &'static str {
        match self {
            Study::TimeStepping => "time-stepping",
            Study::Spectrum => "spectrum",
            Study::Dispersion => "dispersion",
            Study::Contact => "contact",
            Study::ContactStability => "contact stability",
        }
    }
}

impl Metric {
    /// Scene-file name.
    pub fn name(self) -> &'static str {
        match self {
            Metric::L1 => "l1",
            Metric::L2 => "l2",
            Metric::Linf => "linf",
            Metric::Overshoot => "overshoot",
            Metric::TvRatio => "tv_ratio",
            Metric::EnergyLost => "energy_lost",
            Metric::EnergyBalance => "energy_balance",
            Metric::Diverged => "diverged",
            Metric::ClosedFormDeviation => "closed_form_deviation",
            Metric::DispersionDeviation => "dispersion_deviation",
            Metric::PhaseErrorOrder => "phase_error_order",
            Metric::PlateauDeviation => "plateau_deviation",
            Metric::ImpulseError => "impulse_error",
            Metric::DurationError => "duration_error",
            Metric::ForceL1Error => "force_l1_error",
            Metric::EnergyRatio => "energy_ratio",
            Metric::CourantDeviation => "courant_deviation",
        }
    }

    fn parse(s: &str) -> Option<Self> {
        [
            Metric::L1,
            Metric::L2,
            Metric::Linf,
            Metric::Overshoot,
            Metric::EnergyBalance,
            Metric::Diverged,
            Metric::TvRatio,
            Metric::EnergyLost,
            Metric::ClosedFormDeviation,
            Metric::DispersionDeviation,
            Metric::PhaseErrorOrder,
            Metric::PlateauDeviation,
            Metric::ImpulseError,
            Metric::DurationError,
            Metric::ForceL1Error,
            Metric::EnergyRatio,
            Metric::CourantDeviation,
        ]
        .into_iter()
        .find(|m| m.name() == s)
    }

    /// The study the metric belongs to.
    pub fn study(self) -> Study {
        match self {
            Metric::ClosedFormDeviation => Study::Spectrum,
            Metric::DispersionDeviation | Metric::PhaseErrorOrder => Study::Dispersion,
            Metric::PlateauDeviation
            | Metric::ImpulseError
            | Metric::DurationError
            | Metric::ForceL1Error
            | Metric::EnergyRatio => Study::Contact,
            Metric::CourantDeviation => Study::ContactStability,
            _ => Study::TimeStepping,
        }
    }

    /// True for metrics measured on profiles (they need a reference).
    pub fn needs_reference(self) -> bool {
        matches!(
            self,
            Metric::L1 | Metric::L2 | Metric::Linf | Metric::Overshoot
        )
    }
}

/// The bound of an expectation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    /// `min <= value <= max` (either side optional).
    Range {
        /// Lower bound.
        min: Option<f64>,
        /// Upper bound.
        max: Option<f64>,
    },
    /// A boolean metric equals this.
    Equals(bool),
}

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
    /// Where the bound comes from.
    pub source: String,
}

pub(super) fn expectation(
    src: &Source,
    spanned: &Spanned<RawExpect>,
    names: &[String],
    has_reference: bool,
    study: Study,
    profile_times: &[f64],
    unit: f64,
) -> Result<Expectation, SceneError> {
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
        fail(format!(
            "metric = \"{}\" is not one of l1, l2, linf, overshoot, energy_balance, energy_lost, tv_ratio, diverged, closed_form_deviation, dispersion_deviation, phase_error_order, plateau_deviation, impulse_error, duration_error, force_l1_error, energy_ratio, courant_deviation",
            raw.metric
        ))
    })?;
    if metric.needs_reference() && !has_reference {
        return Err(fail(format!(
            "metric \"{}\" compares with a reference, but the scene has none",
            metric.name()
        )));
    }
    let applies =
        metric.study() == study || (metric == Metric::Diverged && study == Study::Contact);
    if !applies {
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
        source: raw.source.clone(),
    })
}
