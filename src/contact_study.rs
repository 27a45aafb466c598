//! Running contact scenes and tabulating them: force histories against 1D wave theory (seed
//! Figs. 4-5) and the stability sweep of the critical Courant number (seed Fig. 3).

use crate::scene::contact::{ContactCase, StabilitySweep};
use crate::table::{Cell, Table};
use courant_references::contact as closed;
use courant_solver::contact::{
    ContactCriticalStep, ContactError, ContactProblem, ContactRequest, ContactRun, ContactScheme,
    MassPenalty,
};
use courant_solver::{Bar, DivergenceError, End, InputError, Mesh};
use rayon::prelude::*;
use std::time::{Duration, Instant};

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

/// Run one contact case.
pub fn run_contact(case: &ContactCase) -> Result<ContactResult, InputError> {
    let started = Instant::now();
    let request = ContactRequest {
        history_every: case.history_every,
        profile_steps: Vec::new(),
    };
    let (run, diverged) = match case.integrator.run(&case.problem, case.steps, &request) {
        Ok(run) => (run, None),
        Err(ContactError::Diverged { error, partial }) => (*partial, Some(error)),
        Err(ContactError::Input(e)) => return Err(e),
        Err(ContactError::Unstable(e)) => return Err(InputError::Other(e.to_string())),
    };
    let wall_time = started.elapsed();
    let reference: Vec<f64> = run
        .history
        .iter()
        .map(|s| case.reference.force(s.time))
        .collect();
    let plateau = case.reference.first_plateau();
    let first = case
        .reference
        .plateaus()
        .first()
        .map_or((0.0, 0.0), |p| (p.start, p.end));
    let (lo, hi) = (
        first.0 + 0.1 * (first.1 - first.0),
        first.0 + 0.9 * (first.1 - first.0),
    );
    let plateau_deviation = run
        .history
        .iter()
        .filter(|s| s.time >= lo && s.time <= hi)
        .map(|s| (s.force - plateau).abs() / plateau)
        .fold(0.0, f64::max);
    let impulse_error = (run.impulse - case.reference.impulse()).abs() / case.reference.impulse();
    // Half the smallest plateau of the reference: the staircase of unequal impedances steps down.
    let threshold = 0.5
        * case
            .reference
            .plateaus()
            .iter()
            .map(|p| p.force)
            .filter(|f| *f > 0.0)
            .fold(plateau, f64::min);
    let above: Vec<f64> = run
        .history
        .iter()
        .filter(|s| s.force >= threshold)
        .map(|s| s.time)
        .collect();
    let duration_error = match (above.first(), above.last()) {
        (Some(a), Some(b)) => {
            ((b - a) - case.reference.duration()).abs() / case.reference.duration()
        }
        _ => f64::NAN,
    };
    let force_l1_error = run
        .history
        .windows(2)
        .zip(reference.iter().skip(1))
        .map(|(pair, exact)| (pair[1].force - exact).abs() * (pair[1].time - pair[0].time))
        .sum::<f64>()
        / case.reference.impulse();
    let energy = |s: &courant_solver::contact::ContactSample| s.kinetic + s.strain;
    let conserved = |s: &courant_solver::contact::ContactSample| s.kinetic_staggered + s.strain;
    let (energy_ratio, energy_ratio_conserved) = match (run.history.first(), run.history.last()) {
        (Some(a), Some(b)) if energy(a) > 0.0 => (energy(b) / energy(a), conserved(b) / energy(a)),
        _ => (f64::NAN, f64::NAN),
    };
    Ok(ContactResult {
        case: case.name.clone(),
        penalty: case.penalty,
        run,
        diverged,
        reference,
        plateau,
        plateau_deviation,
        impulse_error,
        duration_error,
        force_l1_error,
        energy_ratio,
        energy_ratio_conserved,
        wall_time,
    })
}

/// The force history: `t, force, reference, penalty_force, gap, active, impulse, kinetic,
/// strain, penalty_spring, penalty_kinetic, total`.
pub fn force_table(r: &ContactResult) -> Table {
    let mut table = Table::new(&[
        "t",
        "force",
        "reference",
        "penalty_force",
        "gap",
        "active",
        "impulse",
        "kinetic",
        "strain",
        "penalty_spring",
        "penalty_kinetic",
        "total",
    ]);
    for (s, reference) in r.run.history.iter().zip(&r.reference) {
        table.push(vec![
            s.time.into(),
            s.force.into(),
            (*reference).into(),
            s.penalty_force.into(),
            s.gap.into(),
            Cell::Int(s.active as u64),
            s.impulse.into(),
            s.kinetic.into(),
            s.strain.into(),
            s.penalty_spring.into(),
            s.penalty_kinetic.into(),
            s.total.into(),
        ]);
    }
    table
}

/// One row per contact case: cost beside accuracy.
pub fn contact_summary_table(results: &[ContactResult]) -> Table {
    let mut table = Table::new(&[
        "case",
        "scheme",
        "beta_s",
        "beta_m",
        "Co",
        "Co_crit",
        "binding_limit",
        "dt",
        "steps",
        "plateau",
        "plateau_deviation",
        "impulse_error",
        "duration_error",
        "force_l1_error",
        "energy_ratio",
        "energy_ratio_conserved",
        "max_force",
        "status",
        "wall_time_s",
    ]);
    for r in results {
        let status = match &r.diverged {
            None => "completed".to_string(),
            Some(d) => format!("diverged at step {}", d.step),
        };
        table.push(vec![
            r.case.as_str().into(),
            r.run.scheme.label().into(),
            r.penalty.map(|p| p.0).into(),
            r.penalty.map(|p| p.1).into(),
            r.run.courant.into(),
            r.run.critical.critical_courant().into(),
            format!("{:?}", r.run.critical.binding).into(),
            r.run.dt.into(),
            r.run.steps.into(),
            r.plateau.into(),
            r.plateau_deviation.into(),
            r.impulse_error.into(),
            r.duration_error.into(),
            r.force_l1_error.into(),
            r.energy_ratio.into(),
            r.energy_ratio_conserved.into(),
            r.run.max_force.into(),
            status.into(),
            r.wall_time.as_secs_f64().into(),
        ]);
    }
    table
}

/// One row of the stability sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepRow {
    /// `beta_s`.
    pub beta_s: f64,
    /// Penalty ratio, `None` for penalty only.
    pub ratio: Option<f64>,
    /// Critical Courant number of the contact-active system from the solver's eigenvalues.
    pub courant: f64,
    /// The closed form of `courant-references` (semi-infinite bar).
    pub closed_form: f64,
}

/// The stability sweep's rows.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepResult {
    /// Rows, curve by curve.
    pub rows: Vec<SweepRow>,
    /// Wall time.
    pub wall_time: Duration,
}

impl SweepResult {
    /// Largest `|courant - closed_form| / closed_form`.
    pub fn deviation(&self) -> f64 {
        self.rows
            .iter()
            .map(|r| (r.courant - r.closed_form).abs() / r.closed_form)
            .fold(0.0, f64::max)
    }
}

/// Evaluate the sweep: a unit free bar (E = rho = A = 1) of `elements` elements against a rigid
/// wall; the critical Courant number of its contact-active system (`(K + K_p, M + M_p)`,
/// exact bisection) beside the closed form. The rows are independent and evaluated in parallel
/// (rayon), kept in curve order; an error is that of the first failing row in that order.
pub fn run_sweep(sweep: &StabilitySweep) -> Result<SweepResult, InputError> {
    let started = Instant::now();
    let bar = Bar::homogeneous(Mesh::uniform(1.0, sweep.elements)?, 1.0, 1.0, 1.0)?;
    let problem = ContactProblem::wall_impact(bar, End::Right, 1.0, 0.0)?;
    let grid: Vec<(Option<f64>, f64)> = sweep
        .ratios
        .iter()
        .flat_map(|&ratio| sweep.beta_s.iter().map(move |&beta_s| (ratio, beta_s)))
        .collect();
    let rows = crate::run::in_order(
        grid.par_iter()
            .map(|&(ratio, beta_s)| sweep_row(&problem, ratio, beta_s))
            .collect(),
    )?;
    Ok(SweepResult {
        rows,
        wall_time: started.elapsed(),
    })
}

/// One row of [`run_sweep`]: penalty only (`ratio` `None`) or bipenalty with penalty ratio `r`.
fn sweep_row(
    problem: &ContactProblem,
    ratio: Option<f64>,
    beta_s: f64,
) -> Result<SweepRow, InputError> {
    let mass = ratio.map_or(MassPenalty::None, MassPenalty::Ratio);
    let penalty = problem.penalty(beta_s, mass)?;
    let scheme = if ratio.is_some() {
        ContactScheme::Bipenalty(penalty)
    } else {
        ContactScheme::Penalty {
            stiffness: penalty.stiffness,
        }
    };
    let critical = ContactCriticalStep::of(problem, &scheme);
    let courant = critical.contact_active / critical.stiffest_transit;
    let closed_form = match ratio {
        None => closed::signorini_critical_courant_penalty(beta_s),
        Some(r) => closed::signorini_critical_courant_ratio(beta_s, r),
    }
    .map_err(|e| InputError::Other(e.to_string()))?;
    Ok(SweepRow {
        beta_s,
        ratio,
        courant,
        closed_form,
    })
}

/// `beta_s, r, cr, cr_closed_form` (`r` empty on the penalty-only curve).
pub fn sweep_table(r: &SweepResult) -> Table {
    let mut table = Table::new(&["beta_s", "r", "cr", "cr_closed_form"]);
    for row in &r.rows {
        table.push(vec![
            row.beta_s.into(),
            row.ratio.into(),
            row.courant.into(),
            row.closed_form.into(),
        ]);
    }
    table
}
