//! A spectrum of a file beside the closed-form discrete spectra (methods.md §5), mode by mode.

use super::bind::Bound;
use super::diagnostics::Diagnostics;
use super::outcome::{Read, Scored, ScoredCase, ScoredSpectrum};
use crate::compare::spectrum::closed_form_kind;
use crate::results::exchange::record::SpectrumRow;
use crate::scene::spectrum::SpectrumCase;
use courant_solver::MassKind;

/// The closed-form frequency of mode `n` for `kind`: the closed forms of the bar's modes sorted
/// ascending, as `courant run` pairs them with the computed (ascending) spectrum; `None` without
/// closed forms or for a mode the bar does not have.
pub fn closed_form(case: &SpectrumCase, kind: MassKind, n: usize) -> Option<f64> {
    let bar = case.closed_form.as_ref()?;
    let modes = bar.modes();
    if !modes.contains(&n) {
        return None;
    }
    let mut list: Vec<f64> = modes
        .clone()
        .map(|m| bar.discrete_frequency(closed_form_kind(kind), m))
        .collect();
    list.sort_by(f64::total_cmp);
    Some(list[n - modes.start()])
}

/// Score a spectrum file (rows bound to their mass kinds) against the closed forms.
pub fn score_spectrum(bound: &Bound, case: &SpectrumCase, rows: &[SpectrumRow]) -> ScoredCase {
    let scored: Vec<(String, usize, f64, f64)> = rows
        .iter()
        .zip(&bound.row_masses)
        .map(|(r, &kind)| {
            let closed = closed_form(case, kind, r.mode).unwrap_or(f64::NAN);
            (kind.label(), r.mode, r.omega, closed)
        })
        .collect();
    let deviation = scored
        .iter()
        .filter(|r| r.3 > 0.0)
        .map(|r| (r.2 - r.3).abs() / r.3)
        .fold(0.0, f64::max);
    ScoredCase {
        case: bound.file.case.clone(),
        file: bound.file.file.clone(),
        scheme: bound.meta.and_then(|m| m.scheme.clone()),
        applies: bound.applies.clone(),
        mass: bound.mass.map(|m| m.label()),
        elements: Some(case.model.bar().element_count()),
        read: Read {
            values: rows.len(),
            times: 1,
            rows: rows.len(),
        },
        dt: None,
        reference: "closed-form",
        scored: Scored::Spectrum(ScoredSpectrum {
            rows: scored,
            deviation,
        }),
        diagnostics: Diagnostics::none("not applicable: a spectrum has no time levels or load"),
    }
}
