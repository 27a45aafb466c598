//! A spectrum record beside the continuum and the closed-form discrete spectra (the seed's
//! Fig. 6, methods.md §5).

use crate::results::spectrum::SpectrumRecord;
use crate::results::table::{Cell, Table};
use crate::scene::mass::mass_name;
use crate::scene::spectrum::SpectrumCase;
use courant_references::spectra as closed;
use courant_solver::MassKind;
use std::time::Duration;

/// The spectra of one case for each mass kind, beside their references.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumResult {
    /// Case name.
    pub case: String,
    /// Mass kinds, one column each.
    pub masses: Vec<MassKind>,
    /// Mode numbers `n` (free-free from 0, the rigid mode).
    pub modes: Vec<usize>,
    /// Continuum frequencies `c k_n`, when the closed forms apply.
    pub continuum: Option<Vec<f64>>,
    /// Computed frequencies per mass kind (dense eigen-solution), ascending.
    pub computed: Vec<Vec<f64>>,
    /// Closed-form discrete frequencies per mass kind, when they apply.
    pub closed_form: Option<Vec<Vec<f64>>>,
    /// Wall time of the eigen-solutions.
    pub wall_time: Duration,
}

impl SpectrumResult {
    /// Largest `|omega_computed - omega_closed| / omega_closed` over the elastic modes (the rigid
    /// mode, 0 in both, is excluded) and every mass kind.
    pub fn closed_form_deviation(&self) -> Option<f64> {
        let closed = self.closed_form.as_ref()?;
        let mut worst = 0.0_f64;
        for (computed, exact) in self.computed.iter().zip(closed) {
            for (c, e) in computed.iter().zip(exact) {
                if *e > 0.0 {
                    worst = worst.max((c - e).abs() / e);
                }
            }
        }
        Some(worst)
    }
}

/// The closed-form counterpart of a solver mass kind.
pub fn closed_form_kind(kind: MassKind) -> closed::MassKind {
    match kind {
        MassKind::Lumped => closed::MassKind::Lumped,
        MassKind::Consistent => closed::MassKind::Consistent,
        MassKind::Averaged { beta } => closed::MassKind::Averaged { beta },
        MassKind::Reciprocal { beta } => closed::MassKind::Reciprocal { beta },
    }
}

/// Compare the computed spectra of a case with the continuum and the closed forms of its bar
/// (when the bar is uniform and homogeneous with closed-form ends).
pub fn compare_spectrum(record: SpectrumRecord, case: &SpectrumCase) -> SpectrumResult {
    let count = record.computed.first().map_or(0, Vec::len);
    let (modes, continuum, closed_form) = match &case.closed_form {
        Some(bar) => {
            let modes: Vec<usize> = bar.modes().collect();
            let continuum = modes.iter().map(|&n| bar.continuum_frequency(n)).collect();
            let closed = record
                .masses
                .iter()
                .map(|&k| {
                    // Sorted: for RMM with beta > 5/2 Omega(kh) peaks inside the band, so mode
                    // order and frequency order differ; the computed spectrum is sorted.
                    let mut list: Vec<f64> = modes
                        .iter()
                        .map(|&n| bar.discrete_frequency(closed_form_kind(k), n))
                        .collect();
                    list.sort_by(f64::total_cmp);
                    list
                })
                .collect();
            (modes, Some(continuum), Some(closed))
        }
        None => ((1..=count).collect(), None, None),
    };
    SpectrumResult {
        case: record.case,
        masses: record.masses,
        modes,
        continuum,
        computed: record.computed,
        closed_form,
        wall_time: record.wall_time,
    }
}

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
