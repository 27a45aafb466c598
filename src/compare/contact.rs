//! A contact record beside 1D wave theory (seed Figs. 4-5, methods.md §7): the force history
//! against the analytic impact force, with plateau, impulse, duration and L1 errors and the
//! energy left in the bars.

use crate::results::contact::ContactRecord;
use courant_references::contact::ImpactForce;
use courant_solver::DivergenceError;
use courant_solver::contact::{ContactRun, ContactSample};
use std::time::Duration;

/// A contact case's run beside its reference, with its accuracy figures.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactResult {
    /// Case name.
    pub case: String,
    /// `(beta_s, beta_m)` for the penalty schemes.
    pub penalty: Option<(f64, f64)>,
    /// The run (partial when it diverged).
    pub run: ContactRun,
    /// How it diverged, if it did.
    pub diverged: Option<DivergenceError>,
    /// Exact force at each sample time.
    pub reference: Vec<f64>,
    /// First-plateau force of the reference.
    pub plateau: f64,
    /// Largest `|F - F1|/F1` for samples inside the first plateau (10 % to 90 % of it).
    pub plateau_deviation: f64,
    /// `|impulse - exact|/exact`.
    pub impulse_error: f64,
    /// `|duration - exact|/exact`, the duration between the first and last crossings of half the
    /// smallest plateau force of the reference (NaN when the force never reached it).
    pub duration_error: f64,
    /// `sum_k |F(t_k) - F_exact(t_k)| (t_k - t_{k-1}) / impulse_exact` over the recorded
    /// samples: the L1 norm in time of the force error, relative to the exact impulse (a
    /// discrete L1 error of the force history, seed Figs. 4-5 against 1D wave theory).
    pub force_l1_error: f64,
    /// Energy of the real masses (kinetic + strain) at the end over the initial energy.
    pub energy_ratio: f64,
    /// Central difference's conserved energy of the real masses at the end,
    /// `1/2 v^{n-1/2} M v^{n+1/2} + 1/2 u^n K u^n` (Hughes 1987, §9.1), over the initial energy:
    /// once the bodies have separated, the energy the run left in them, without the step-scale
    /// oscillation that inflates `energy_ratio` near the critical step.
    pub energy_ratio_conserved: f64,
    /// Wall time of the run.
    pub wall_time: Duration,
}

/// The accuracy of a force history against 1D wave theory (the fields of [`ContactResult`] of
/// the same names).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForceMetrics {
    /// First-plateau force of the reference.
    pub plateau: f64,
    /// Largest `|F - F1|/F1` inside the first plateau (10 % to 90 % of it).
    pub plateau_deviation: f64,
    /// `|impulse - exact|/exact`.
    pub impulse_error: f64,
    /// `|duration - exact|/exact` from the half-smallest-plateau crossings.
    pub duration_error: f64,
    /// L1 norm in time of the force error over the exact impulse.
    pub force_l1_error: f64,
}

/// The exact force at each sample time and the accuracy of the history `(t_k, F_k)` whose total
/// impulse is `impulse` (see [`ContactResult`] for each measure).
pub fn force_metrics(
    samples: &[(f64, f64)],
    impulse: f64,
    reference: &ImpactForce,
) -> (Vec<f64>, ForceMetrics) {
    let exact: Vec<f64> = samples.iter().map(|s| reference.force(s.0)).collect();
    let plateau = reference.first_plateau();
    let first = reference
        .plateaus()
        .first()
        .map_or((0.0, 0.0), |p| (p.start, p.end));
    let (lo, hi) = (
        first.0 + 0.1 * (first.1 - first.0),
        first.0 + 0.9 * (first.1 - first.0),
    );
    let plateau_deviation = samples
        .iter()
        .filter(|s| s.0 >= lo && s.0 <= hi)
        .map(|s| (s.1 - plateau).abs() / plateau)
        .fold(0.0, f64::max);
    let impulse_error = (impulse - reference.impulse()).abs() / reference.impulse();
    // Half the smallest plateau of the reference: the staircase of unequal impedances steps down.
    let threshold = 0.5
        * reference
            .plateaus()
            .iter()
            .map(|p| p.force)
            .filter(|f| *f > 0.0)
            .fold(plateau, f64::min);
    let above: Vec<f64> = samples
        .iter()
        .filter(|s| s.1 >= threshold)
        .map(|s| s.0)
        .collect();
    let duration_error = match (above.first(), above.last()) {
        (Some(a), Some(b)) => ((b - a) - reference.duration()).abs() / reference.duration(),
        _ => f64::NAN,
    };
    let force_l1_error = samples
        .windows(2)
        .zip(exact.iter().skip(1))
        .map(|(pair, exact)| (pair[1].1 - exact).abs() * (pair[1].0 - pair[0].0))
        .sum::<f64>()
        / reference.impulse();
    let metrics = ForceMetrics {
        plateau,
        plateau_deviation,
        impulse_error,
        duration_error,
        force_l1_error,
    };
    (exact, metrics)
}

/// Compare a contact record with the analytic force of 1D wave theory.
pub fn compare_contact(record: ContactRecord, reference: &ImpactForce) -> ContactResult {
    let ContactRecord {
        case,
        penalty,
        run,
        diverged,
        wall_time,
    } = record;
    let samples: Vec<(f64, f64)> = run.history.iter().map(|s| (s.time, s.force)).collect();
    let (exact, m) = force_metrics(&samples, run.impulse, reference);
    let energy = |s: &ContactSample| s.kinetic + s.strain;
    let conserved = |s: &ContactSample| s.kinetic_staggered + s.strain;
    let (energy_ratio, energy_ratio_conserved) = match (run.history.first(), run.history.last()) {
        (Some(a), Some(b)) if energy(a) > 0.0 => (energy(b) / energy(a), conserved(b) / energy(a)),
        _ => (f64::NAN, f64::NAN),
    };
    ContactResult {
        case,
        penalty,
        run,
        diverged,
        reference: exact,
        plateau: m.plateau,
        plateau_deviation: m.plateau_deviation,
        impulse_error: m.impulse_error,
        duration_error: m.duration_error,
        force_l1_error: m.force_l1_error,
        energy_ratio,
        energy_ratio_conserved,
        wall_time,
    }
}
