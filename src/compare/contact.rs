//! A contact record beside 1D wave theory (seed Figs. 4-5, methods.md §7): the force history
//! against the analytic impact force, with plateau, impulse, duration and L1 errors and the
//! energy left in the bars.
//!
//! Which force is graded is the case's [`ForceMeasure`] (chosen by the scene); the impulse is
//! always the momentum delivered, whatever force is graded.

use crate::results::contact::ContactRecord;
use crate::results::table::{Cell, Table};
use crate::scene::contact::ForceMeasure;
use courant_references::ContactHistory;
use courant_solver::DivergenceError;
use courant_solver::contact::{ContactRun, ContactSample};
use std::time::Duration;

/// How one force history compares with 1D wave theory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForceErrors {
    /// Largest `|F - F1|/F1` for samples inside the first plateau (10 % to 90 % of it); `None`
    /// when no sample lies there (nothing to judge: a history cut short, or too coarse).
    pub plateau_deviation: Option<f64>,
    /// `|duration - exact|/exact`, the duration between the first and last crossings of half the
    /// smallest plateau force of the reference (`None` when the force never reached it).
    pub duration_error: Option<f64>,
    /// `sum_k |F(t_k) - F_exact(t_k)| (t_k - t_{k-1}) / impulse_exact` over the recorded
    /// samples: the L1 norm in time of the force error, relative to the exact impulse (a
    /// discrete L1 error of the force history, seed Figs. 4-5 against 1D wave theory).
    pub force_l1_error: f64,
    /// The L1 error as `force_l1_error`, over the samples farther than
    /// [`JUMP_EXCLUSION_SAMPLES`] sample intervals from every jump of the exact force (its
    /// plateau starts and ends): the error of the smooth stretches, without the smearing of each
    /// jump over a few steps that every scheme shows and no mesh removes at a fixed Courant
    /// number.
    pub force_l1_off_jumps: f64,
    /// `|t_open - t_exact| / t_exact` for the first opening of the contact: `t_open` is the
    /// first sample, after the force first reached half the first plateau, that starts
    /// [`JUMP_EXCLUSION_SAMPLES`] consecutive zero-force samples; `t_exact` the reference's
    /// separation time. `None` when the recorded force never opens so.
    pub separation_error: Option<f64>,
    /// Largest force over the run.
    pub max_force: f64,
    /// Fraction of the samples inside the first plateau (10 % to 90 % of it) at which the force
    /// is zero: a contact that opens and closes within steps (chatter) reads a plateau deviation
    /// near 1 without a plateau at all.
    pub open_in_plateau: f64,
}

impl ForceErrors {
    /// The errors of the force `measure` of `history` against `exact` (the reference at each
    /// sample time).
    fn of(
        measure: ForceMeasure,
        history: &[ContactSample],
        exact: &[f64],
        reference: &dyn ContactHistory,
    ) -> Self {
        let samples: Vec<(f64, f64)> = history.iter().map(|s| (s.time, measure.force(s))).collect();
        Self::of_samples(&samples, exact, reference)
    }

    /// The errors of a force history given as `(t_k, F_k)` samples (a run's, or another code's
    /// file) against `exact` (the reference at each sample time).
    pub fn of_samples(
        samples: &[(f64, f64)],
        exact: &[f64],
        reference: &dyn ContactHistory,
    ) -> Self {
        let plateau = reference.first_plateau_force();
        let first = reference
            .force_plateaus()
            .first()
            .map_or((0.0, 0.0), |p| (p.start, p.end));
        let (lo, hi) = (
            first.0 + 0.1 * (first.1 - first.0),
            first.0 + 0.9 * (first.1 - first.0),
        );
        let inside: Vec<f64> = samples
            .iter()
            .filter(|s| s.0 >= lo && s.0 <= hi)
            .map(|s| s.1)
            .collect();
        let plateau_deviation = (!inside.is_empty()).then(|| {
            inside
                .iter()
                .map(|f| (f - plateau).abs() / plateau)
                .fold(0.0, f64::max)
        });
        let open_in_plateau = if inside.is_empty() {
            0.0
        } else {
            inside.iter().filter(|f| **f == 0.0).count() as f64 / inside.len() as f64
        };
        // Half the smallest plateau of the reference: the staircase of unequal impedances steps
        // down.
        let threshold = 0.5
            * reference
                .force_plateaus()
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
            (Some(a), Some(b)) => {
                Some(((b - a) - reference.contact_duration()).abs() / reference.contact_duration())
            }
            _ => None,
        };
        let force_l1_error = samples
            .windows(2)
            .zip(exact.iter().skip(1))
            .map(|(pair, exact)| (pair[1].1 - exact).abs() * (pair[1].0 - pair[0].0))
            .sum::<f64>()
            / reference.contact_impulse();
        let (force_l1_off_jumps, separation_error) =
            away_from_jumps(samples, exact, reference, plateau);
        Self {
            plateau_deviation,
            duration_error,
            force_l1_error,
            force_l1_off_jumps,
            separation_error,
            max_force: samples.iter().map(|s| s.1).fold(0.0, f64::max),
            open_in_plateau,
        }
    }
}

/// Largest force, relative to the first plateau, read as an open contact: courant writes an
/// exact 0, another code may write round-off (1e-17) or a tiny tension; both are open.
const OPEN_FORCE: f64 = 1e-9;

/// The L1 force error away from the jumps of the exact force and the separation-time error
/// ([`ForceErrors`]).
fn away_from_jumps(
    samples: &[(f64, f64)],
    exact: &[f64],
    reference: &dyn ContactHistory,
    plateau: f64,
) -> (f64, Option<f64>) {
    let mut jumps: Vec<f64> = reference
        .force_plateaus()
        .iter()
        .flat_map(|p| [p.start, p.end])
        .collect();
    jumps.sort_by(f64::total_cmp);
    let window = JUMP_EXCLUSION_SAMPLES as f64;
    let mut l1 = 0.0;
    for (pair, e) in samples.windows(2).zip(exact.iter().skip(1)) {
        let (t, dt) = (pair[1].0, pair[1].0 - pair[0].0);
        let k = jumps.partition_point(|&j| j < t);
        let near = |j: Option<&f64>| j.is_some_and(|j| (j - t).abs() <= window * dt);
        if !near(jumps.get(k)) && !near(k.checked_sub(1).and_then(|k| jumps.get(k))) {
            l1 += (pair[1].1 - e).abs() * dt;
        }
    }
    let started = samples.iter().position(|s| s.1 >= 0.5 * plateau);
    let opened = started.and_then(|first| {
        (first..samples.len()).find(|&k| {
            samples[k..]
                .iter()
                .take(JUMP_EXCLUSION_SAMPLES)
                .filter(|s| s.1.abs() <= OPEN_FORCE * plateau.abs())
                .count()
                == JUMP_EXCLUSION_SAMPLES
        })
    });
    let exact_open = reference.separation_time();
    let separation = opened.map(|k| (samples[k].0 - exact_open).abs() / exact_open);
    (l1 / reference.contact_impulse(), separation)
}

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
    /// The force graded and plotted.
    pub measure: ForceMeasure,
    /// Exact force at each sample time.
    pub reference: Vec<f64>,
    /// First-plateau force of the reference.
    pub plateau: f64,
    /// The errors of the graded force.
    pub errors: ForceErrors,
    /// The errors of the other force measure, where the scheme has both (the penalty schemes).
    pub other_errors: Option<ForceErrors>,
    /// `|impulse - exact|/exact` of the momentum delivered.
    pub impulse_error: f64,
    /// Energy of the real masses (kinetic + strain) at the end over the initial energy; `None`
    /// when it is undefined ([`ENERGY_RATIO_UNDEFINED`]).
    pub energy_ratio: Option<f64>,
    /// Central difference's conserved energy of the real masses at the end,
    /// `1/2 v^{n-1/2} M v^{n+1/2} + 1/2 u^n K u^n` (Hughes 1987, §9.1), over the initial energy:
    /// once the bodies have separated, the energy the run left in them, without the step-scale
    /// oscillation that inflates `energy_ratio` near the critical step. `None` for a run that
    /// diverged: above the critical step the staggered kinetic term is not positive and the
    /// ratio means nothing (the status says how the run ended).
    pub energy_ratio_conserved: Option<f64>,
    /// Wall time of the run.
    pub wall_time: Duration,
}

/// Why a contact case has no `plateau_deviation`.
pub const PLATEAU_UNDEFINED: &str = "undefined: no recorded force sample lies inside the first plateau (10 % to 90 % of it): the history ends before it, or its sampling misses it";

/// Why a contact case has no `duration_error`.
pub const DURATION_UNDEFINED: &str = "undefined: no recorded force sample reached half the smallest plateau (the contact opened before, or the sampling, history_every, missed it)";

/// Sample intervals on either side of a jump of the exact force left out of
/// `force_l1_off_jumps` (steps, when every step is recorded: `history_every = 1`), and the
/// open-contact samples in a row ([`OPEN_FORCE`]) that count as an opening for
/// `separation_error`.
pub const JUMP_EXCLUSION_SAMPLES: usize = 5;

/// Why a contact case has no `separation_error`.
pub const SEPARATION_UNDEFINED: &str = "undefined: the recorded force never reached half the first plateau and then stayed zero for a few samples (no opening seen)";

/// Why a contact case has no `energy_ratio`.
pub const ENERGY_RATIO_UNDEFINED: &str =
    "undefined: no energy at the first sample, or a non-finite energy at the last (a diverged run)";

impl ContactResult {
    /// The errors of the force `measure` (`None` for the penalty force of the Lagrange
    /// multiplier method, which has none).
    pub fn errors_of(&self, measure: ForceMeasure) -> Option<&ForceErrors> {
        if measure == self.measure {
            Some(&self.errors)
        } else {
            self.other_errors.as_ref()
        }
    }
}

/// Compare a contact record with the analytic force of 1D wave theory, grading the force
/// `measure`.
pub fn compare_contact(
    record: ContactRecord,
    reference: &dyn ContactHistory,
    measure: ForceMeasure,
) -> ContactResult {
    let ContactRecord {
        case,
        penalty,
        mut run,
        diverged,
        wall_time,
    } = record;
    if diverged.is_some() {
        // A diverged run's record ends where its values stop being numbers: the guard stops it
        // at the step its energy overflows, and that step's sample may hold infinities.
        let finite = |s: &ContactSample| {
            [
                s.time,
                s.force,
                s.penalty_force,
                s.gap,
                s.impulse,
                s.kinetic,
                s.kinetic_staggered,
                s.strain,
                s.penalty_spring,
                s.penalty_kinetic,
                s.total,
            ]
            .iter()
            .all(|x| x.is_finite())
        };
        let end = run.history.iter().position(|s| !finite(s));
        run.history.truncate(end.unwrap_or(run.history.len()));
    }
    let exact: Vec<f64> = run
        .history
        .iter()
        .map(|s| reference.contact_force(s.time))
        .collect();
    let errors = ForceErrors::of(measure, &run.history, &exact, reference);
    let other = match measure {
        ForceMeasure::PenaltyForce => ForceMeasure::TransferredMomentum,
        ForceMeasure::TransferredMomentum => ForceMeasure::PenaltyForce,
    };
    let other_errors = (ForceMeasure::for_scheme(other, &run.scheme) == other)
        .then(|| ForceErrors::of(other, &run.history, &exact, reference));
    let impulse_error =
        (run.impulse - reference.contact_impulse()).abs() / reference.contact_impulse();
    let energy = |s: &ContactSample| s.kinetic + s.strain;
    let conserved = |s: &ContactSample| s.kinetic_staggered + s.strain;
    let ratio = |end: f64, start: f64| Some(end / start).filter(|r| r.is_finite());
    let (energy_ratio, energy_ratio_conserved) = match (run.history.first(), run.history.last()) {
        (Some(a), Some(b)) if energy(a) > 0.0 => (
            ratio(energy(b), energy(a)),
            diverged
                .is_none()
                .then(|| ratio(conserved(b), energy(a)))
                .flatten(),
        ),
        _ => (None, None),
    };
    ContactResult {
        case,
        penalty,
        run,
        diverged,
        measure,
        reference: exact,
        plateau: reference.first_plateau_force(),
        errors,
        other_errors,
        impulse_error,
        energy_ratio,
        energy_ratio_conserved,
        wall_time,
    }
}

/// The force history: `t, force, reference, transferred_force, gap, active, impulse, kinetic,
/// strain, penalty_spring, penalty_kinetic, total`. `force` is the graded force
/// ([`ForceMeasure`](super::contact::ForceMeasure): the seed's `eps_s x penetration` for the
/// penalty schemes, momentum/dt for the Lagrange multiplier), `transferred_force` the momentum
/// delivered to the real masses at the level over the span of its velocity update.
pub fn force_table(r: &ContactResult) -> Table {
    let mut table = Table::new(&[
        "t",
        "force",
        "reference",
        "transferred_force",
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
            r.measure.force(s).into(),
            (*reference).into(),
            s.force.into(),
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
        "force_measure",
        "plateau",
        "plateau_deviation",
        "impulse_error",
        "duration_error",
        "force_l1_error",
        "energy_ratio",
        "energy_ratio_conserved",
        "max_force",
        "max_transferred_force",
        "status",
        "note",
        "wall_time_s",
    ]);
    for r in results {
        let status = match &r.diverged {
            None => "completed".to_string(),
            Some(d) => format!("diverged at step {}", d.step),
        };
        // A diverged run's figures may have overflowed: those are empty cells (its note says
        // so). A completed run's figures are finite.
        let figure = |x: f64| -> Cell {
            if r.diverged.is_some() && !x.is_finite() {
                Cell::Empty
            } else {
                Cell::Num(x)
            }
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
            r.measure.label().into(),
            r.plateau.into(),
            r.errors.plateau_deviation.map_or(Cell::Empty, figure),
            figure(r.impulse_error),
            r.errors.duration_error.map_or(Cell::Empty, figure),
            figure(r.errors.force_l1_error),
            r.energy_ratio.into(),
            r.energy_ratio_conserved.into(),
            figure(r.errors.max_force),
            figure(r.run.max_force),
            status.into(),
            contact_note(r).into(),
            r.wall_time.as_secs_f64().into(),
        ]);
    }
    table
}

/// What a contact row's numbers need said: chatter (a plateau deviation near 1 without a
/// plateau), or a diverged run's missing conserved energy.
fn contact_note(r: &ContactResult) -> String {
    let mut notes = Vec::new();
    if r.errors.open_in_plateau == 1.0 {
        notes.push(
            "contact open at every plateau sample: the bars separated before the plateau (plateau deviation 1)"
                .to_string(),
        );
    } else if r.errors.open_in_plateau > 0.0 {
        notes.push(format!(
            "contact open at {:.0} % of the plateau samples (chatter: the plateau deviation is that of a force switching between 0 and its peak)",
            100.0 * r.errors.open_in_plateau
        ));
    }
    if r.errors.plateau_deviation.is_none() {
        notes.push(format!(
            "plateau_deviation {}",
            super::contact::PLATEAU_UNDEFINED
        ));
    }
    if r.errors.duration_error.is_none() {
        notes.push(format!(
            "duration_error {}",
            super::contact::DURATION_UNDEFINED
        ));
    }
    if r.diverged.is_some() {
        notes.push(
            "diverged: no conserved energy above the critical step; energy_ratio is where the guard stopped it (a figure that overflowed is empty)"
                .to_string(),
        );
    }
    notes.join("; ")
}
