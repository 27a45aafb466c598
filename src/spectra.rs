//! Running spectrum cases and tabulating them (the seed's Fig. 6).

use crate::scene::spectrum::SpectrumCase;
use crate::table::{Cell, Table};
use courant_references::spectra as closed;
use courant_solver::{InputError, MassKind};
use std::time::{Duration, Instant};

/// The spectra of one case for each mass kind.
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

/// Compute the spectra of a case.
pub fn run_spectrum(case: &SpectrumCase) -> Result<SpectrumResult, InputError> {
    let started = Instant::now();
    let computed = case
        .masses
        .iter()
        .map(|&kind| courant_solver::spectrum::angular_frequencies(&case.model, kind))
        .collect::<Result<Vec<_>, _>>()?;
    let wall_time = started.elapsed();
    let count = computed.first().map_or(0, Vec::len);
    let (modes, continuum, closed_form) = match &case.closed_form {
        Some(bar) => {
            let modes: Vec<usize> = bar.modes().collect();
            let continuum = modes.iter().map(|&n| bar.continuum_frequency(n)).collect();
            let closed = case
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
    Ok(SpectrumResult {
        case: case.name.clone(),
        masses: case.masses.clone(),
        modes,
        continuum,
        computed,
        closed_form,
        wall_time,
    })
}

/// `mode, exact`, then per mass kind its frequency, its closed form and its relative error
/// against the continuum (`exact` and the error are empty where there is no continuum
/// reference or for the rigid mode).
pub fn spectrum_table(r: &SpectrumResult) -> Table {
    let names: Vec<String> = r
        .masses
        .iter()
        .map(|&m| crate::scene::mass_name(m))
        .collect();
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
