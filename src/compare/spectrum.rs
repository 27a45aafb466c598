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

    /// Per mode, [`mode_error_ratio`] of the computed frequencies of `mass` and `against`
    /// against the continuum (`None` for the rigid mode, without a continuum reference, or when
    /// the case lacks one of the two masses).
    pub fn mode_error_ratios(&self, mass: MassKind, against: MassKind) -> Vec<Option<f64>> {
        let column = |kind| self.masses.iter().position(|m| *m == kind);
        let (Some(continuum), Some(a), Some(b)) = (&self.continuum, column(mass), column(against))
        else {
            return vec![None; self.modes.len()];
        };
        (0..self.modes.len())
            .map(|i| {
                let (x, y) = (self.computed[a].get(i)?, self.computed[b].get(i)?);
                mode_error_ratio(*x, *y, continuum[i])
            })
            .collect()
    }

    /// The largest [`mode_error_ratio`] over the elastic modes (`mode_error_ratio` metric):
    /// below 1 when `mass` is closer to the continuum than `against` on every mode; `None`
    /// without a continuum reference or a mass of the two.
    pub fn max_mode_error_ratio(&self, mass: MassKind, against: MassKind) -> Option<f64> {
        self.mode_error_ratios(mass, against)
            .into_iter()
            .flatten()
            .reduce(f64::max)
    }
}

/// `|omega_x/omega - 1| / |omega_y/omega - 1|`: how the relative error of a mode's frequency
/// `omega_x` compares with that of `omega_y`, both against the continuum `omega = c k_n`
/// (methods.md §5, "error ratio"). `None` for the rigid mode (`omega = 0`) or where `omega_y`
/// is exact (no ratio).
pub fn mode_error_ratio(omega_x: f64, omega_y: f64, omega: f64) -> Option<f64> {
    let baseline = (omega_y / omega - 1.0).abs();
    (omega > 0.0 && baseline > 0.0).then(|| (omega_x / omega - 1.0).abs() / baseline)
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

/// The mass kinds of a case other than LMM, when the case has LMM and a continuum reference:
/// those whose error ratio against LMM the tables show.
fn against_lumped(r: &SpectrumResult) -> Vec<MassKind> {
    if r.continuum.is_none() || !r.masses.contains(&MassKind::Lumped) {
        return Vec::new();
    }
    r.masses
        .iter()
        .copied()
        .filter(|m| *m != MassKind::Lumped)
        .collect()
}

/// One row per spectrum case: `case, N, masses, closed_form_deviation`, then for each mass
/// kind X other than LMM (when the scene has LMM and closed forms) `X_error_ratio_vs_lmm`, the
/// largest [`mode_error_ratio`] of X against LMM over the elastic modes (below 1: X closer to
/// the continuum on every mode; methods.md §5), and `wall_time_s`.
pub fn spectrum_summary_table(spectra: &[SpectrumResult]) -> Table {
    let ratios = spectra.first().map(against_lumped).unwrap_or_default();
    let mut columns: Vec<String> = ["case", "modes", "masses", "closed_form_deviation"]
        .iter()
        .map(|c| c.to_string())
        .collect();
    columns.extend(
        ratios
            .iter()
            .map(|m| format!("{}_error_ratio_vs_lmm", mass_name(*m))),
    );
    columns.push("wall_time_s".into());
    let mut table = Table {
        columns,
        rows: Vec::new(),
    };
    for s in spectra {
        let masses: Vec<String> = s.masses.iter().map(|m| m.label()).collect();
        let mut row: Vec<Cell> = vec![
            s.case.as_str().into(),
            s.modes.len().into(),
            masses.join(" ").into(),
            s.closed_form_deviation().into(),
        ];
        row.extend(
            ratios
                .iter()
                .map(|&m| Cell::from(s.max_mode_error_ratio(m, MassKind::Lumped))),
        );
        row.push(s.wall_time.as_secs_f64().into());
        table.rows.push(row);
    }
    table
}

/// `mode, exact`, then per mass kind its frequency, its closed form and its relative error
/// against the continuum (`exact` and the error are empty where there is no continuum
/// reference or for the rigid mode), then per mass kind X other than LMM (when the case has
/// LMM) `X_error_ratio_vs_lmm`, the mode's [`mode_error_ratio`] of X against LMM.
pub fn spectrum_table(r: &SpectrumResult) -> Table {
    let names: Vec<String> = r.masses.iter().map(|&m| mass_name(m)).collect();
    let mut columns = vec!["mode".to_string(), "exact".to_string()];
    columns.extend(names.iter().cloned());
    columns.extend(names.iter().map(|n| format!("{n}_closed_form")));
    columns.extend(names.iter().map(|n| format!("{n}_rel_error")));
    let others = against_lumped(r);
    columns.extend(
        others
            .iter()
            .map(|m| format!("{}_error_ratio_vs_lmm", mass_name(*m))),
    );
    let ratios: Vec<Vec<Option<f64>>> = others
        .iter()
        .map(|&m| r.mode_error_ratios(m, MassKind::Lumped))
        .collect();
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
        row.extend(ratios.iter().map(|r| Cell::from(r[i])));
        table.rows.push(row);
    }
    table
}

#[cfg(test)]
mod tests {
    //! Source of truth: the closed-form spectra of methods.md §5 (`courant_references::spectra`)
    //! stand in for computed ones; the error ratio at `kh = pi` is `(pi - sqrt 6)/(pi - 2)`
    //! for AMM(1/2) and RMM(1/2) (methods.md §5, "error ratio").

    use super::*;
    use courant_references::spectra::{BarEnds, UniformBar};
    use std::f64::consts::PI;

    const MASSES: [MassKind; 3] = [
        MassKind::Lumped,
        MassKind::Averaged { beta: 0.5 },
        MassKind::Reciprocal { beta: 0.5 },
    ];

    /// A free-free bar of `n` elements whose "computed" spectra are the closed forms.
    fn closed_form_result(n: usize) -> SpectrumResult {
        let bar = UniformBar::new(1.0, 1.0, n, BarEnds::FreeFree).unwrap();
        let computed: Vec<Vec<f64>> = MASSES
            .iter()
            .map(|&m| bar.discrete_frequencies(closed_form_kind(m)))
            .collect();
        SpectrumResult {
            case: format!("free-free-n{n}"),
            masses: MASSES.to_vec(),
            modes: bar.modes().collect(),
            continuum: Some(bar.continuum_frequencies()),
            closed_form: Some(computed.clone()),
            computed,
            wall_time: Duration::ZERO,
        }
    }

    #[test]
    fn the_error_ratio_of_a_mode_is_the_ratio_of_the_relative_errors() {
        let r = mode_error_ratio(1.1, 0.8, 1.0).unwrap();
        assert!((r - 0.5).abs() < 1e-15, "{r}");
        assert_eq!(mode_error_ratio(0.0, 0.0, 0.0), None, "rigid mode");
        assert_eq!(mode_error_ratio(1.1, 1.0, 1.0), None, "exact baseline");
    }

    #[test]
    fn the_largest_error_ratio_of_amm_and_rmm_against_lmm_is_reached_at_kh_pi() {
        // Free-free: the top mode has kh = pi exactly (methods.md §5).
        let r = closed_form_result(20);
        let closed = (PI - 6.0_f64.sqrt()) / (PI - 2.0);
        for m in [MASSES[1], MASSES[2]] {
            let ratios = r.mode_error_ratios(m, MassKind::Lumped);
            assert_eq!(ratios[0], None, "the rigid mode is excluded");
            let top = r.max_mode_error_ratio(m, MassKind::Lumped).unwrap();
            assert!((top - closed).abs() < 1e-12, "{}: {top}", m.label());
            assert_eq!(ratios.last().copied().flatten(), Some(top));
        }
        assert_eq!(
            r.max_mode_error_ratio(MassKind::Consistent, MassKind::Lumped),
            None,
            "a mass the case lacks"
        );
    }

    #[test]
    fn the_tables_show_each_mass_against_lmm() {
        let r = closed_form_result(4);
        let summary = spectrum_summary_table(std::slice::from_ref(&r));
        assert!(
            summary
                .columns
                .iter()
                .any(|c| c == "amm0.5_error_ratio_vs_lmm")
        );
        assert!(
            !summary
                .columns
                .iter()
                .any(|c| c == "lmm_error_ratio_vs_lmm")
        );
        let modes = spectrum_table(&r);
        assert_eq!(modes.columns.last().unwrap(), "rmm0.5_error_ratio_vs_lmm");
        assert_eq!(modes.rows[0].last(), Some(&Cell::Empty), "rigid mode");
    }
}
