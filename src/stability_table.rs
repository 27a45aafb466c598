//! The report's "stability at the extremes" table: one row per time-stepping case of the
//! stability scenes, with the step ratio `dt / dt_crit` (exact `dt_crit = 2 / omega_max` of the
//! assembled system, Hughes, *The Finite Element Method*, 2000, §9.3), the verdict theory predicts
//! (stable when `dt < dt_crit`, marginal within 1e-9 of it, unstable above), what the run did,
//! and whether courant's divergence guard caught it (step, node, Courant number).
//!
//! Contact rows (methods.md §7) take `dt_crit` of the case's scheme (`ContactCriticalStep::
//! applicable`: the contact-active pencil `(K + K_p, M + M_p)` for CD with (bi)penalty, the
//! predictor-corrector's `sqrt((m_c + m_p)/k_s)`). Linear theory of the *closed* contact predicts
//! growth above it; a unilateral contact opens as soon as the contact-local mode grows, so a run
//! between that limit and the contact-free one is predicted `contact-unstable`: bounded, possibly
//! pumping energy into the bars (the `energy_ratio` column), while above the contact-free limit
//! the bulk modes grow and the run is `unstable`.

use crate::contact_study::ContactResult;
use crate::run::{CaseResult, Status};
use crate::table::Table;

/// Scenes whose cases sit at the stability extremes (Co at 0.99/1.00/1.01 of each critical value,
/// modulus ratio 1e4 on graded and layered bars, 1e6-step runs, SI units, contact with beta_s up
/// to 1e8).
pub const STABILITY_SCENES: &[&str] = &[
    "stability_extremes",
    "courant_sweep",
    "graded_1e4",
    "layered_1e4",
    "layered",
    "long_run",
    "fig1_si",
    "contact_extremes",
];

/// Width of the "marginal" band of `dt / dt_crit` around 1.
const MARGINAL: f64 = 1e-9;

/// The predicted verdict for a step ratio `dt / dt_crit`.
pub fn predicted(ratio: f64) -> &'static str {
    if ratio > 1.0 + MARGINAL {
        "unstable"
    } else if ratio >= 1.0 - MARGINAL {
        "marginal"
    } else {
        "stable"
    }
}

/// The predicted verdict of a contact run from `dt / dt_crit` of its scheme and
/// `dt / dt_free` of the contact-free bodies: as [`predicted`], except that a step above the
/// contact limit but below the contact-free one is `contact-unstable` (bounded by the opening of
/// the unilateral contact).
pub fn predicted_contact(ratio: f64, ratio_free: f64) -> &'static str {
    match predicted(ratio) {
        "unstable" if predicted(ratio_free) == "stable" => "contact-unstable",
        verdict => verdict,
    }
}

/// One row of the table.
#[derive(Debug, Clone, PartialEq)]
pub struct StabilityRow {
    /// Scene name.
    pub scene: String,
    /// Case name.
    pub case: String,
    /// `dt / dt_crit`.
    pub ratio: f64,
    /// Predicted verdict.
    pub predicted: &'static str,
    /// True when the run completed every step.
    pub completed: bool,
    /// The guard's report when the run diverged.
    pub caught: Option<String>,
    /// Steps taken.
    pub steps: usize,
    /// Relative energy-balance error of the run (0 when not logged; none for contact).
    pub energy_balance: Option<f64>,
    /// Contact: energy of the real masses at the end over the initial energy.
    pub energy_ratio: Option<f64>,
}

impl StabilityRow {
    /// Build a row from a case result.
    pub fn new(scene: &str, r: &CaseResult) -> Self {
        let ratio = r.dt / r.critical.exact;
        let caught = match &r.status {
            Status::Completed => None,
            Status::Diverged(d) => Some(format!(
                "step {}, node {}, Co {:.4}",
                d.step, d.node, d.courant
            )),
        };
        Self {
            scene: scene.to_string(),
            case: r.case.clone(),
            ratio,
            predicted: predicted(ratio),
            completed: caught.is_none(),
            caught,
            steps: r.steps,
            energy_balance: Some(r.energy.relative_balance_error()),
            energy_ratio: None,
        }
    }

    /// Build a row from a contact result.
    pub fn from_contact(scene: &str, r: &ContactResult) -> Self {
        let critical = &r.run.critical;
        let ratio = r.run.dt / critical.applicable;
        let caught = r
            .diverged
            .as_ref()
            .map(|d| format!("step {}, node {}, Co {:.4}", d.step, d.node, d.courant));
        Self {
            scene: scene.to_string(),
            case: r.case.clone(),
            ratio,
            predicted: predicted_contact(ratio, r.run.dt / critical.contact_free),
            completed: caught.is_none(),
            caught,
            steps: r.run.steps,
            energy_balance: None,
            energy_ratio: Some(r.energy_ratio),
        }
    }

    /// Theory and run agree: a predicted-stable run completes, a predicted-unstable run is caught
    /// by the guard, a contact-unstable run stays bounded (completes); a marginal run may do
    /// either.
    pub fn agrees(&self) -> bool {
        match self.predicted {
            "stable" | "contact-unstable" => self.completed,
            "unstable" => self.caught.is_some(),
            _ => true,
        }
    }
}

/// `scene, case, dt_over_dt_crit, predicted, observed, guard, steps, energy_balance,
/// energy_ratio, agrees`.
pub fn stability_table(rows: &[StabilityRow]) -> Table {
    let mut table = Table::new(&[
        "scene",
        "case",
        "dt_over_dt_crit",
        "predicted",
        "observed",
        "guard",
        "steps",
        "energy_balance",
        "energy_ratio",
        "agrees",
    ]);
    for row in rows {
        table.push(vec![
            row.scene.as_str().into(),
            row.case.as_str().into(),
            row.ratio.into(),
            row.predicted.into(),
            if row.completed { "stable" } else { "diverged" }.into(),
            row.caught.clone().unwrap_or_else(|| "-".into()).into(),
            row.steps.into(),
            row.energy_balance.into(),
            row.energy_ratio.into(),
            if row.agrees() { "yes" } else { "no" }.into(),
        ]);
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The verdict bands: below, within 1e-9 of, and above the critical step.
    #[test]
    fn predicted_verdict_bands() {
        assert_eq!(predicted(0.99), "stable");
        assert_eq!(predicted(1.0 - 1e-6), "stable");
        assert_eq!(predicted(1.0), "marginal");
        assert_eq!(predicted(1.0 + 1e-10), "marginal");
        assert_eq!(predicted(1.01), "unstable");
    }

    /// Contact: above the contact limit but below the contact-free one the closed-contact mode
    /// grows, the unilateral contact bounds it; above both the run is unstable.
    #[test]
    fn contact_verdict_bands() {
        assert_eq!(predicted_contact(0.99, 0.5), "stable");
        assert_eq!(predicted_contact(1.01, 0.5), "contact-unstable");
        assert_eq!(predicted_contact(2.0, 1.1), "unstable");
        assert_eq!(predicted_contact(1.0, 1.0), "marginal");
    }
}
