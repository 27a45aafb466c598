//! The contact stability sweep (seed Fig. 3) beside the closed forms of `courant-references`
//! (semi-infinite bar against a rigid wall, methods.md §7).

use crate::results::sweep::SweepRecord;
use crate::results::table::Table;
use courant_references::ReferenceError;
use courant_references::contact as closed;
use std::time::Duration;

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

    /// Largest `|courant - 1|` over the bipenalty rows with `r <= 1` (methods.md §7: they keep
    /// the contact-free critical Courant number 1 for every `beta_s`); `None` without such rows.
    pub fn unit_deviation(&self) -> Option<f64> {
        self.rows
            .iter()
            .filter(|r| r.ratio.is_some_and(|ratio| ratio <= 1.0))
            .map(|r| (r.courant - 1.0).abs())
            .reduce(f64::max)
    }

    /// `|courant sqrt(beta_s/2) - 1|` of the penalty-only row with the largest `beta_s`: the
    /// closed form `sqrt(2/(1 + sqrt(1 + beta_s^2)))` tends to `sqrt(2/beta_s)` with relative
    /// error `1/(2 beta_s) + O(beta_s^-2)` (methods.md §7); `None` without penalty-only rows.
    pub fn penalty_asymptote_deviation(&self) -> Option<f64> {
        self.rows
            .iter()
            .filter(|r| r.ratio.is_none())
            .max_by(|a, b| a.beta_s.total_cmp(&b.beta_s))
            .map(|r| (r.courant * (r.beta_s / 2.0).sqrt() - 1.0).abs())
    }
}

/// Put the closed-form critical Courant number beside every point of the sweep.
///
/// # Errors
/// A closed form refuses its parameters (a `beta_s` or ratio it is not defined for).
pub fn compare_sweep(record: SweepRecord) -> Result<SweepResult, ReferenceError> {
    let rows = record
        .points
        .iter()
        .map(|p| {
            let closed_form = match p.ratio {
                None => closed::signorini_critical_courant_penalty(p.beta_s),
                Some(r) => closed::signorini_critical_courant_ratio(p.beta_s, r),
            }?;
            Ok(SweepRow {
                beta_s: p.beta_s,
                ratio: p.ratio,
                courant: p.courant,
                closed_form,
            })
        })
        .collect::<Result<_, ReferenceError>>()?;
    Ok(SweepResult {
        rows,
        wall_time: record.wall_time,
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
