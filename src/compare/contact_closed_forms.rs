//! The closed-form critical Courant numbers of contact with a rigid wall at large beta_s, each
//! beside its large-beta_s limit and the leading term of the difference (`courant-references`,
//! methods.md §7): a check of the closed forms themselves, free of cancellation up to 1e12.

use crate::results::table::Table;

/// The text above the table of [`contact_closed_form_table`].
pub const CONTACT_CLOSED_FORMS_TEXT: &str = "Closed-form critical Courant numbers of contact with a rigid \
     wall (semi-infinite uniform lumped bar, central difference; `courant-references`, methods.md §7) at large \
     beta_s, each beside its large-beta_s limit: sqrt(2/beta_s) for penalty only (r = -), 1/sqrt(r) for bipenalty \
     with r > 1, 1 for r <= 1. scaled_difference = beta_s (Cr/limit - 1) stands beside scaled_first_order, \
     beta_s times the leading term of that difference in 1/beta_s: -1/2 for penalty only, r(1 - s)/(1 + s) \
     with s = 1/(sqrt(r) + sqrt(r - 1))^2 for r > 1, 0 for r <= 1. They agree up to beta_s = 1e12, where the \
     difference itself is below 1e-11: the closed forms stay accurate there, free of cancellation.";

/// The penalty stiffnesses of [`contact_closed_form_table`].
const CLOSED_FORM_BETAS: [f64; 4] = [1e6, 1e8, 1e10, 1e12];

/// The penalty ratios of [`contact_closed_form_table`] (`None`: penalty only).
const CLOSED_FORM_RATIOS: [Option<f64>; 4] = [None, Some(0.25), Some(1.0), Some(4.0)];

/// One row of [`contact_closed_form_table`], unrounded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosedFormRow {
    /// Penalty stiffness `beta_s`.
    pub beta_s: f64,
    /// Penalty ratio; `None`: penalty only.
    pub r: Option<f64>,
    /// The closed-form critical Courant number.
    pub cr: f64,
    /// Its limit as beta_s -> inf at fixed r.
    pub limit: f64,
    /// The leading term of `cr/limit - 1` in 1/beta_s.
    pub first_order: f64,
}

/// The closed-form contact critical Courant numbers of `courant-references` at beta_s = 1e6 …
/// 1e12, penalty only and bipenalty r = 1/4, 1, 4, beside their large-beta_s limits.
pub fn contact_closed_form_rows() -> Result<Vec<ClosedFormRow>, courant_references::ReferenceError>
{
    use courant_references::contact::{
        signorini_critical_courant_penalty, signorini_critical_courant_ratio,
    };
    let mut rows = Vec::new();
    for r in CLOSED_FORM_RATIOS {
        for beta_s in CLOSED_FORM_BETAS {
            let row = match r {
                None => ClosedFormRow {
                    beta_s,
                    r,
                    cr: signorini_critical_courant_penalty(beta_s)?,
                    limit: (2.0 / beta_s).sqrt(),
                    first_order: -1.0 / (2.0 * beta_s),
                },
                Some(r) if r > 1.0 => {
                    let s = 1.0 / (r.sqrt() + (r - 1.0).sqrt()).powi(2);
                    ClosedFormRow {
                        beta_s,
                        r: Some(r),
                        cr: signorini_critical_courant_ratio(beta_s, r)?,
                        limit: 1.0 / r.sqrt(),
                        first_order: r / beta_s * (1.0 - s) / (1.0 + s),
                    }
                }
                Some(r) => ClosedFormRow {
                    beta_s,
                    r: Some(r),
                    cr: signorini_critical_courant_ratio(beta_s, r)?,
                    limit: 1.0,
                    first_order: 0.0,
                },
            };
            rows.push(row);
        }
    }
    Ok(rows)
}

/// The table of [`contact_closed_form_rows`]: `beta_s, r, cr_closed_form, cr_limit,
/// scaled_difference, scaled_first_order`, the differences times beta_s (O(1) numbers: the
/// differences themselves fall below the report's display floor for round-off).
///
/// # Errors
/// A closed form refuses its parameters (it cannot for these fixed, valid values).
pub fn contact_closed_form_table() -> Result<Table, courant_references::ReferenceError> {
    let mut table = Table::new(&[
        "beta_s",
        "r",
        "cr_closed_form",
        "cr_limit",
        "scaled_difference",
        "scaled_first_order",
    ]);
    for row in contact_closed_form_rows()? {
        table.push(vec![
            row.beta_s.into(),
            row.r.into(),
            row.cr.into(),
            row.limit.into(),
            (row.beta_s * (row.cr / row.limit - 1.0)).into(),
            (row.beta_s * row.first_order).into(),
        ]);
    }
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::results::table::Precision;

    /// The precision of the report's CSV tables.
    const STORED: Precision = Precision::Significant {
        digits: 10,
        floor: 1e-12,
    };

    #[test]
    fn closed_forms_approach_their_limits_at_the_first_order_rate_up_to_1e12() {
        let rows = contact_closed_form_rows().unwrap();
        assert_eq!(rows.len(), 16);
        for row in &rows {
            let difference = row.cr / row.limit - 1.0;
            if row.r.is_some_and(|r| r <= 1.0) {
                assert_eq!(row.cr, 1.0, "{row:?}: no localized mode for r <= 1");
            } else {
                assert!(
                    (difference - row.first_order).abs() <= 1e-3 * row.first_order.abs(),
                    "{row:?}: Cr/limit - 1 = {difference:e}"
                );
            }
        }
        let last = rows
            .iter()
            .find(|r| r.beta_s == 1e12 && r.r.is_none())
            .unwrap();
        assert!((last.cr / 2e-12_f64.sqrt() - 1.0).abs() < 1e-12, "{last:?}");
    }

    #[test]
    fn table_lists_every_beta_and_ratio_with_readable_differences() {
        let table = contact_closed_form_table().unwrap();
        assert_eq!(table.rows.len(), 16);
        let csv = table.to_csv(STORED);
        assert!(csv.starts_with(
            "beta_s,r,cr_closed_form,cr_limit,scaled_difference,scaled_first_order\n"
        ));
        // Penalty only at beta_s = 1e12: beta_s (Cr/limit - 1) -> -1/2; the difference (5e-13)
        // carries round-off of about 1e-16/5e-13, so only three digits are asserted.
        let row = csv
            .lines()
            .find(|l| l.starts_with("1.000000000e12,,"))
            .expect("penalty row at 1e12");
        let cells: Vec<&str> = row.split(',').collect();
        assert_eq!(cells[5], "-0.5000000000", "{row}");
        let scaled: f64 = cells[4].parse().unwrap();
        assert!((scaled + 0.5).abs() < 1e-3, "{row}");
        assert!(
            csv.contains("\n1.000000000e12,0.2500000000,1.000000000,1.000000000,0,0\n"),
            "{csv}"
        );
    }
}
