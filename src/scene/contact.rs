//! Contact scenes (the seed's Figs. 3-5): a striker onto a target bar or a rigid wall with the
//! penalty, bipenalty, predictor-corrector and Lagrange-multiplier schemes, and the stability
//! sweep of the critical Courant number against the penalty stiffness.

use super::budget;
pub use super::contact_bar::ContactReference;
pub use super::contact_bulk::CombinedBulk;
use super::contact_problem::{Bodies, bodies};
use super::error::{SceneError, Source, positive};
use super::magnitude;
use super::schema::{RawContact, RawContactCourantUnit, RawContactScene, RawContactStability};
use courant_solver::StabilityPolicy;
use courant_solver::contact::{
    ContactCriticalStep, ContactIntegrator, ContactProblem, ContactSample, ContactScheme,
    MassPenalty,
};

/// A case name, its scheme and its dimensionless penalties.
type Variant = (String, ContactScheme, Option<(f64, f64)>);

/// One contact case: a scheme (with one `beta_s` for the penalty schemes).
#[derive(Debug, Clone)]
pub struct ContactCase {
    /// Case name, e.g. `predictor-corrector-bs25`.
    pub name: String,
    /// The problem.
    pub problem: ContactProblem,
    /// Scheme, step and stability policy.
    pub integrator: ContactIntegrator,
    /// Steps to run.
    pub steps: usize,
    /// Keep a sample every this many steps.
    pub history_every: usize,
    /// `(beta_s, beta_m)`, when the scheme has penalties.
    pub penalty: Option<(f64, f64)>,
    /// The analytic contact force of 1D wave theory (methods.md §7).
    pub reference: ContactReference,
    /// The force graded and plotted.
    pub force: ForceMeasure,
    /// Transit time of the striker, `L1/c1`: the time unit of the contact figures.
    pub striker_transit: f64,
    /// The combined bulk (`None`: central difference with the lumped mass, the contact stepper).
    pub bulk: Option<CombinedBulk>,
}

/// The force a contact case is graded and plotted by.
///
/// For the penalty schemes the seed's contact force is `f_cont = -K_p u + f_p = eps_s x
/// penetration` (seed eq. 15 and the last step of its predictor-corrector flowchart, §3.2): the
/// force whose amplitude the seed says grows with `beta_s` under central difference and which
/// its Fig. 5 shows independent of `beta_s` for the stabilized scheme at C = 0.5. Measured here
/// (`contact_courant_sweep`): for the predictor-corrector scheme with r = 1 that holds at its own
/// limit (C = 0.5, where it is the Lagrange multiplier method), while at a tenth of it `f_cont`
/// settles near `beta_s` times the force the bars receive (about 1238 for a plateau of 0.5 at
/// beta_s = 2500): the penetration it needs grows as the correction per step shrinks. The
/// momentum delivered to the real masses per step over dt is the force the bars receive under
/// every scheme and step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ForceMeasure {
    /// The seed's `f_cont = eps_s x penetration` at level n (penalty, bipenalty,
    /// predictor-corrector).
    PenaltyForce,
    /// The momentum delivered to the real masses at level n over the span of its velocity update
    /// (the Lagrange multiplier method).
    TransferredMomentum,
}

impl ForceMeasure {
    /// The measure a case of `scheme` uses when the scene asks for `asked`: the Lagrange
    /// multiplier method has no penalty and always uses the transferred momentum.
    pub fn for_scheme(asked: ForceMeasure, scheme: &ContactScheme) -> Self {
        match scheme {
            ContactScheme::LagrangeMultiplier => ForceMeasure::TransferredMomentum,
            _ => asked,
        }
    }

    /// The graded force of a sample.
    pub fn force(self, s: &ContactSample) -> f64 {
        match self {
            ForceMeasure::PenaltyForce => s.penalty_force,
            ForceMeasure::TransferredMomentum => s.force,
        }
    }

    /// Short label for tables: `eps_s x penetration` or `momentum/dt`.
    pub fn label(self) -> &'static str {
        match self {
            ForceMeasure::PenaltyForce => "eps_s x penetration",
            ForceMeasure::TransferredMomentum => "momentum/dt",
        }
    }
}

/// A stability sweep (seed Fig. 3).
#[derive(Debug, Clone, PartialEq)]
pub struct StabilitySweep {
    /// Elements of the unit bar against the wall.
    pub elements: usize,
    /// The `beta_s` grid.
    pub beta_s: Vec<f64>,
    /// Penalty ratios `r`; `None` is the penalty-only curve.
    pub ratios: Vec<Option<f64>>,
}

/// Build the cases of a `[contact]` study.
pub(super) fn cases(
    src: &Source,
    raw: &RawContactScene,
    study: &RawContact,
) -> Result<Vec<ContactCase>, SceneError> {
    let Bodies {
        problem,
        reference,
        striker_transit,
    } = bodies(src, raw, study)?;
    let courants = study.courant.get_ref().values();
    if courants.is_empty() {
        return Err(src.error(
            Some(study.courant.span()),
            "contact.courant",
            "give at least one Courant number",
        ));
    }
    if let Some(bad) = courants.iter().find(|c| !(c.is_finite() && **c > 0.0)) {
        return Err(src.error(
            Some(study.courant.span()),
            "contact.courant",
            format!("{bad} must be positive and finite"),
        ));
    }
    let end = positive(src, &study.end_time, "contact.end_time")?;
    let end_time = end * striker_transit;
    let history_every = match &study.history_every {
        None => 1,
        Some(h) if *h.get_ref() >= 1 => *h.get_ref() as usize,
        Some(h) => {
            return Err(src.error(
                Some(h.span()),
                "contact.history_every",
                format!("{} must be at least 1", h.get_ref()),
            ));
        }
    };
    let force = match study
        .force
        .as_ref()
        .map(|f| (f.get_ref().as_str(), f.span()))
    {
        None | Some(("penalty", _)) => ForceMeasure::PenaltyForce,
        Some(("transferred", _)) => ForceMeasure::TransferredMomentum,
        Some((other, span)) => {
            return Err(src.error(
                Some(span),
                "contact.force",
                format!("\"{other}\" is not one of penalty, transferred"),
            ));
        }
    };
    let mass_penalties: Vec<(String, MassPenalty)> = match (&study.ratio, &study.beta_m) {
        (Some(_), Some(b)) => {
            return Err(src.error(
                Some(b.span()),
                "contact.beta_m",
                "give either `ratio` or `beta_m`, not both",
            ));
        }
        (Some(r), None) => {
            let values = r.get_ref().values();
            if values.is_empty() {
                return Err(src.error(
                    Some(r.span()),
                    "contact.ratio",
                    "the list is empty; give at least one ratio",
                ));
            }
            if let Some(bad) = values.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
                return Err(src.error(
                    Some(r.span()),
                    "contact.ratio",
                    format!("{bad} must be positive and finite"),
                ));
            }
            magnitude::inputs(
                src,
                Some(r.span()),
                "contact.ratio",
                "ratio",
                values.iter().copied(),
            )?;
            let named = values.len() > 1;
            values
                .into_iter()
                .map(|v| {
                    let suffix = if named {
                        format!("-r{}", super::names::number(v))
                    } else {
                        String::new()
                    };
                    (suffix, MassPenalty::Ratio(v))
                })
                .collect()
        }
        (None, Some(b)) => {
            magnitude::input(
                src,
                Some(b.span()),
                "contact.beta_m",
                "beta_m",
                *b.get_ref(),
            )?;
            vec![(String::new(), MassPenalty::Dimensionless(*b.get_ref()))]
        }
        (None, None) => vec![(String::new(), MassPenalty::Ratio(1.0))],
    };
    let betas = study
        .beta_s
        .as_ref()
        .map(|b| b.get_ref().values())
        .unwrap_or_default();
    let beta_span = study.beta_s.as_ref().map(|b| b.span());
    magnitude::inputs(
        src,
        beta_span.clone(),
        "contact.beta_s",
        "beta_s",
        betas.iter().copied(),
    )?;
    let schemes = study.schemes.get_ref().values();
    let penalised = schemes
        .iter()
        .filter(|s| s.as_str() != "lagrange-multiplier")
        .count();
    // cd-penalty takes no mass penalty; the other penalty schemes one case per ratio.
    let per_beta = |s: &String| {
        if s.as_str() == "cd-penalty" {
            1
        } else {
            mass_penalties.len()
        }
    };
    let penalty_cases: usize = schemes
        .iter()
        .filter(|s| s.as_str() != "lagrange-multiplier")
        .map(|s| per_beta(s) * betas.len().max(1))
        .sum();
    let bulks = super::contact_bulk::bulks(src, study)?;
    let cases = (schemes.len() - penalised + penalty_cases) * courants.len() * bulks.len();
    budget::validation(
        src,
        &(Some(study.schemes.span()), "contact.schemes"),
        cases,
        cases as f64 * problem.node_count() as f64 * budget::CONTACT_WEIGHT,
    )?;
    let stability = StabilityPolicy {
        allow_unstable: study.allow_unstable,
        ..StabilityPolicy::default()
    };
    let mut cases = Vec::new();
    let mut free_limits = Vec::new();
    for label in study.schemes.get_ref().values() {
        let penalty_scheme =
            |beta_s: f64, mass: MassPenalty| -> Result<(ContactScheme, (f64, f64)), String> {
                let penalty = problem.penalty(beta_s, mass).map_err(|e| e.to_string())?;
                for (what, value) in [
                    ("penalty stiffness k_s = beta_s E A/h", penalty.stiffness),
                    ("penalty mass m_p = beta_m rho A h", penalty.mass),
                ] {
                    if !magnitude::within(value) {
                        return Err(format!(
                            "beta_s = {beta_s:e} gives the {what} = {value:e}: {}",
                            magnitude::rule()
                        ));
                    }
                }
                let dimensionless = problem.dimensionless(penalty);
                let scheme = match label.as_str() {
                    "cd-penalty" => ContactScheme::Penalty {
                        stiffness: penalty.stiffness,
                    },
                    "cd-bipenalty" => ContactScheme::Bipenalty(penalty),
                    _ => ContactScheme::PredictorCorrector(penalty),
                };
                Ok((scheme, dimensionless))
            };
        let variants: Vec<Variant> = match label.as_str() {
            "lagrange-multiplier" => vec![(label.clone(), ContactScheme::LagrangeMultiplier, None)],
            "cd-penalty" | "cd-bipenalty" | "predictor-corrector" => {
                if betas.is_empty() {
                    return Err(src.error(
                        Some(study.schemes.span()),
                        "contact.beta_s",
                        format!("scheme {label} needs `beta_s`"),
                    ));
                }
                let masses = if label == "cd-penalty" {
                    vec![(String::new(), MassPenalty::None)]
                } else {
                    mass_penalties.clone()
                };
                masses
                    .iter()
                    .flat_map(|(suffix, mass)| betas.iter().map(move |&b| (suffix, *mass, b)))
                    .map(|(suffix, mass, b)| {
                        let (scheme, dimensionless) = penalty_scheme(b, mass)
                            .map_err(|m| src.error(beta_span.clone(), "contact.beta_s", m))?;
                        let name = format!("{label}{suffix}-bs{}", super::names::number(b));
                        Ok((name, scheme, Some(dimensionless)))
                    })
                    .collect::<Result<_, SceneError>>()?
            }
            other => {
                return Err(src.error(
                    Some(study.schemes.span()),
                    "contact.schemes",
                    format!("\"{other}\" is not one of cd-penalty, cd-bipenalty, predictor-corrector, lagrange-multiplier"),
                ));
            }
        };
        for ((prefix, bulk), (name, scheme, penalty)) in bulks
            .iter()
            .flat_map(|b| variants.iter().map(move |v| (b, v)))
        {
            let (name, scheme, penalty) = (format!("{prefix}{name}"), *scheme, *penalty);
            let combined = bulk
                .map(|b| {
                    super::contact_bulk::critical(
                        &problem,
                        b,
                        scheme,
                        study.courant_unit,
                        &mut free_limits,
                    )
                })
                .transpose()
                .map_err(|m| {
                    let at = study
                        .bulk
                        .as_ref()
                        .map_or(study.courant.span(), |b| b.span());
                    src.error(Some(at), "contact.bulk", format!("case {name}: {m}"))
                })?;
            for &courant in &courants {
                let case_name = if courants.len() > 1 {
                    format!("{name}-co{}", super::names::number(courant))
                } else {
                    name.clone()
                };
                let fail = |key: &str, msg: String| {
                    src.error(
                        Some(study.courant.span()),
                        key,
                        format!("case {case_name}: {msg}"),
                    )
                };
                let dt = match (study.courant_unit, &combined) {
                    (RawContactCourantUnit::StiffestElement, _) => {
                        courant * problem.stiffest_transit()
                    }
                    (
                        _,
                        Some(CombinedBulk {
                            critical: Some(c), ..
                        }),
                    ) => courant * c.applicable,
                    // `bulks` makes every case of the measured unit combined.
                    (RawContactCourantUnit::Critical | RawContactCourantUnit::Measured, _) => {
                        scheme
                            .validate()
                            .map_err(|e| fail("contact.beta_s", e.to_string()))?;
                        let critical = ContactCriticalStep::of(&problem, &scheme)
                            .map_err(|e| fail("contact.courant_unit", e.to_string()))?;
                        courant * critical.applicable
                    }
                };
                let steps_f = (end_time / dt).ceil();
                if steps_f > 1e8 {
                    return Err(src.error(
                        Some(study.end_time.span()),
                        "contact.end_time",
                        format!("case {case_name}: needs {steps_f:.2e} steps; at most 1e8"),
                    ));
                }
                magnitude::courant(
                    src,
                    Some(study.courant.span()),
                    "contact.courant",
                    &case_name,
                    dt / problem.stiffest_transit(),
                )?;
                let integrator = ContactIntegrator {
                    dt,
                    scheme,
                    stability,
                };
                match &combined {
                    None => integrator
                        .check_stability(&problem)
                        .map(|_| ())
                        .map_err(|e| fail("contact.courant", e.to_string()))?,
                    Some(c) => super::contact_bulk::check(c, dt, study.allow_unstable)
                        .map_err(|m| fail("contact.courant", m))?,
                }
                cases.push(ContactCase {
                    name: case_name,
                    problem: problem.clone(),
                    integrator,
                    steps: steps_f as usize,
                    history_every,
                    penalty,
                    reference: reference.clone(),
                    force: ForceMeasure::for_scheme(force, &scheme),
                    striker_transit,
                    bulk: combined,
                });
            }
        }
    }
    let mut seen = std::collections::HashSet::new();
    if let Some(dup) = cases.iter().find(|c| !seen.insert(c.name.clone())) {
        return Err(src.error(
            Some(study.schemes.span()),
            "contact.schemes",
            format!("case {} appears twice", dup.name),
        ));
    }
    Ok(cases)
}

/// Build a `[contact_stability]` sweep.
pub(super) fn sweep(
    src: &Source,
    study: &RawContactStability,
) -> Result<StabilitySweep, SceneError> {
    let elements = *study.elements.get_ref();
    if !(2..=100_000).contains(&elements) {
        return Err(src.error(
            Some(study.elements.span()),
            "contact_stability.elements",
            format!("{elements} must lie in 2..=100000"),
        ));
    }
    let [lo, hi] = *study.beta_s_range.get_ref();
    let range_span = Some(study.beta_s_range.span());
    if !(lo.is_finite() && hi.is_finite() && lo > 0.0 && hi >= lo) {
        return Err(src.error(
            range_span,
            "contact_stability.beta_s_range",
            format!("[{lo}, {hi}] must be positive, finite and ordered"),
        ));
    }
    magnitude::inputs(
        src,
        range_span,
        "contact_stability.beta_s_range",
        "beta_s",
        [lo, hi],
    )?;
    let points = *study.points.get_ref();
    if !(2..=1000).contains(&points) {
        return Err(src.error(
            Some(study.points.span()),
            "contact_stability.points",
            format!("{points} must lie in 2..=1000"),
        ));
    }
    // Both ends within the magnitude bounds: hi/lo <= 1e100 stays finite.
    let beta_s = (0..points)
        .map(|i| lo * (hi / lo).powf(i as f64 / (points - 1) as f64))
        .collect();
    let mut ratios: Vec<Option<f64>> = Vec::new();
    if study.penalty_only.unwrap_or(true) {
        ratios.push(None);
    }
    for &r in study.ratios.get_ref() {
        if !(r.is_finite() && r > 0.0) {
            return Err(src.error(
                Some(study.ratios.span()),
                "contact_stability.ratios",
                format!("{r} must be positive and finite"),
            ));
        }
        magnitude::input(
            src,
            Some(study.ratios.span()),
            "contact_stability.ratios",
            "r",
            r,
        )?;
        ratios.push(Some(r));
    }
    Ok(StabilitySweep {
        elements: elements as usize,
        beta_s,
        ratios,
    })
}
