//! The report's "stability at the extremes" table: one row per time-stepping case of the
//! stability scenes, with the step ratio `dt / dt_crit` (exact `dt_crit = 2 / omega_max` of the
//! assembled system, Hughes, *The Finite Element Method*, 2000, §9.3), the verdict theory predicts
//! (stable when `dt < dt_crit`, marginal within 1e-9 of it, unstable above), what the run did,
//! and whether courant's divergence guard caught it (step, node, Courant number).

use crate::run::{CaseResult, Status};
use crate::table::Table;

/// Scenes whose cases sit at the stability extremes (Co at 0.99/1.00/1.01 of each critical value,
/// modulus ratio 1e4, 1e6-step runs, SI units).
pub const STABILITY_SCENES: &[&str] = &[
    "stability_extremes",
    "courant_sweep",
    "graded_1e4",
    "layered",
    "long_run",
    "fig1_si",
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
    /// Relative energy-balance error of the run (0 when not logged).
    pub energy_balance: f64,
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
            energy_balance: r.energy.relative_balance_error(),
        }
    }

    /// Theory and run agree: a predicted-stable run completes, a predicted-unstable run is caught
    /// by the guard; a marginal run may do either.
    pub fn agrees(&self) -> bool {
        match self.predicted {
            "stable" => self.completed,
            "unstable" => self.caught.is_some(),
            _ => true,
        }
    }
}

/// `scene, case, dt_over_dt_crit, predicted, observed, guard, steps, energy_balance, agrees`.
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
}
