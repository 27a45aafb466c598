//! The tables of compared spectrum, dispersion and contact cases: per case its spectrum or force
//! history (`<case>.csv`), per scene `summary.csv`, `dispersion.csv` or `stability.csv`.

use super::contact::ContactResult;
use super::dispersion::DispersionResult;
use super::spectrum::SpectrumResult;
use super::sweep::SweepResult;
use crate::results::table::{Cell, Table};
use crate::scene::mass::mass_name;
use courant_solver::MassKind;

/// One row per spectrum case: `case, N, masses, closed_form_deviation, wall_time_s`.
pub fn spectrum_summary_table(spectra: &[SpectrumResult]) -> Table {
    let mut table = Table::new(&[
        "case",
        "modes",
        "masses",
        "closed_form_deviation",
        "wall_time_s",
    ]);
    for s in spectra {
        let masses: Vec<String> = s.masses.iter().map(|m| m.label()).collect();
        table.push(vec![
            s.case.as_str().into(),
            s.modes.len().into(),
            masses.join(" ").into(),
            s.closed_form_deviation().into(),
            s.wall_time.as_secs_f64().into(),
        ]);
    }
    table
}

/// `mode, exact`, then per mass kind its frequency, its closed form and its relative error
/// against the continuum (`exact` and the error are empty where there is no continuum
/// reference or for the rigid mode).
pub fn spectrum_table(r: &SpectrumResult) -> Table {
    let names: Vec<String> = r.masses.iter().map(|&m| mass_name(m)).collect();
    let mut columns = vec!["mode".to_string(), "exact".to_string()];
    columns.extend(names.iter().cloned());
    columns.extend(names.iter().map(|n| format!("{n}_closed_form")));
    columns.extend(names.iter().map(|n| format!("{n}_rel_error")));
    let mut table = Table {
        columns,
        rows: Vec::new(),
    };
    for (i, &mode) in r.modes.iter().enumerate() {
        let exact = r.continuum.as_ref().map(|c| c[i]);
        let mut row: Vec<Cell> = vec![mode.into(), exact.into()];
        row.extend(r.computed.iter().map(|c| Cell::from(c.get(i).copied())));
        row.extend(
            (0..r.masses.len()).map(|m| Cell::from(r.closed_form.as_ref().map(|c| c[m][i]))),
        );
        row.extend(r.computed.iter().map(|c| match (exact, c.get(i)) {
            (Some(e), Some(v)) if e > 0.0 => Cell::Num((v - e) / e),
            _ => Cell::Empty,
        }));
        table.rows.push(row);
    }
    table
}

/// `case, mass, beta, fourth_order, Co, mode, kh, closed_form, measured, difference, phase_error,
/// observed_order` (order between mode `n/2` and `n`, when both are listed).
pub fn dispersion_table(results: &[DispersionResult]) -> Table {
    let mut table = Table::new(&[
        "case",
        "mass",
        "beta",
        "fourth_order",
        "Co",
        "mode",
        "kh",
        "closed_form",
        "measured",
        "difference",
        "phase_error",
        "observed_order",
    ]);
    for r in results {
        let beta = match r.case.mass {
            MassKind::Averaged { beta } | MassKind::Reciprocal { beta } => Some(beta),
            _ => None,
        };
        for (i, row) in r.rows.iter().enumerate() {
            let m = row.measured;
            table.push(vec![
                r.case.name.as_str().into(),
                r.case.mass.label().into(),
                beta.into(),
                r.case.fourth_order.to_string().into(),
                r.case.courant.into(),
                row.mode.into(),
                m.kh.into(),
                row.closed_form.into(),
                m.phase_speed_ratio.into(),
                (m.phase_speed_ratio - row.closed_form).into(),
                (m.phase_speed_ratio - 1.0).into(),
                Cell::from(r.observed_order(i)),
            ]);
        }
    }
    table
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
