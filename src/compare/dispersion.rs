//! A dispersion record beside the fully discrete dispersion relation of central difference,
//! `sin(omega_hat dt/2) = (Co/2) Omega(kh)` (methods.md §5), evaluated by `courant-references`.

use super::spectrum::closed_form_kind;
use crate::results::dispersion::{DispersionRecord, ModeMeasurement};
use crate::results::table::{Cell, Table};
use crate::scene::dispersion::DispersionCase;
use courant_solver::MassKind;

/// One row of a dispersion case: a mode, its closed-form and measured phase-speed ratios.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DispersionRow {
    /// Mode number.
    pub mode: usize,
    /// The measurement.
    pub measured: ModeMeasurement,
    /// `sin(omega_hat dt/2) = (Co/2) Omega(kh)` evaluated by `courant-references`.
    pub closed_form: f64,
}

/// The rows of a dispersion case.
#[derive(Debug, Clone, PartialEq)]
pub struct DispersionResult {
    /// The case.
    pub case: DispersionCase,
    /// One row per mode.
    pub rows: Vec<DispersionRow>,
}

impl DispersionResult {
    /// Largest `|measured - closed form|` of the phase-speed ratio.
    pub fn deviation(&self) -> f64 {
        self.rows
            .iter()
            .map(|r| (r.measured.phase_speed_ratio - r.closed_form).abs())
            .fold(0.0, f64::max)
    }

    /// Observed order of the phase error between each mode `n` and `2n` present in the list:
    /// `log2(|e(2n)| / |e(n)|)`, `e = ratio - 1`, for row `i` (the `2n` row), else `None`.
    pub fn observed_order(&self, i: usize) -> Option<f64> {
        let row = &self.rows[i];
        let half = self.rows.iter().find(|r| 2 * r.mode == row.mode)?;
        let (fine, coarse) = (
            (half.measured.phase_speed_ratio - 1.0).abs(),
            (row.measured.phase_speed_ratio - 1.0).abs(),
        );
        (fine > 0.0 && coarse > 0.0).then(|| (coarse / fine).log2())
    }

    /// Smallest observed order over the mode pairs.
    pub fn min_order(&self) -> Option<f64> {
        (0..self.rows.len())
            .filter_map(|i| self.observed_order(i))
            .reduce(f64::min)
    }
}

/// Compare the measured modes of a case with the closed-form phase-speed ratio.
pub fn compare_dispersion(record: DispersionRecord, case: &DispersionCase) -> DispersionResult {
    let kind = closed_form_kind(case.mass);
    let rows = record
        .modes
        .into_iter()
        .map(|(mode, measured)| DispersionRow {
            mode,
            measured,
            closed_form: courant_references::spectra::phase_speed_ratio(
                kind,
                measured.kh,
                case.courant,
            )
            .unwrap_or(f64::NAN),
        })
        .collect();
    DispersionResult {
        case: case.clone(),
        rows,
    }
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
