//! How the report shows numbers: one notation per table column, four significant digits, never
//! a bare 0 for a value that is not zero (round-off shows as what it is, e.g. `8.971e-14`). The
//! CSV files beside the report keep every number at full round-trip precision.

use crate::results::table::{Cell, Table};

/// The notation of one column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Notation {
    /// Four significant digits in fixed notation (`0.07440`, `1.000`, `1235`).
    Fixed,
    /// Four significant digits in scientific notation (`8.971e-14`, `1.000e6`).
    Scientific,
}

/// Fixed when every finite nonzero number of the column lies in `[1e-2, 1e5)`, else scientific:
/// a column never mixes `562300` with `1.000e6`.
pub fn column_notation<'a>(cells: impl Iterator<Item = &'a Cell>) -> Notation {
    let fixed = cells
        .filter_map(|c| match c {
            Cell::Num(x) if x.is_finite() && *x != 0.0 => Some(x.abs()),
            _ => None,
        })
        .all(|x| (1e-2..1e5).contains(&x));
    if fixed {
        Notation::Fixed
    } else {
        Notation::Scientific
    }
}

/// One number in a column's notation: 0 as `0`, non-finite values as `NaN`, `inf`, `-inf`.
pub fn format(x: f64, notation: Notation) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == 0.0 {
        return "0".into();
    }
    match notation {
        Notation::Scientific => format!("{x:.3e}"),
        Notation::Fixed => {
            let exponent = x.abs().log10().floor() as i32;
            let decimals = (3 - exponent).max(0) as usize;
            format!("{x:.decimals$}")
        }
    }
}

/// Every cell of a table as shown: numbers in their column's notation, integers exactly, empty
/// cells as `-`.
pub fn shown(table: &Table) -> Vec<Vec<String>> {
    let notations: Vec<Notation> = (0..table.columns.len())
        .map(|c| column_notation(table.rows.iter().map(|r| &r[c])))
        .collect();
    table
        .rows
        .iter()
        .map(|row| {
            row.iter()
                .zip(&notations)
                .map(|(cell, &n)| match cell {
                    Cell::Num(x) => format(*x, n),
                    Cell::Int(i) => i.to_string(),
                    Cell::Text(s) => s.clone(),
                    Cell::Empty => "-".into(),
                })
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Source of truth: the report's number rules above. Proves: four significant digits, a
    /// column is all fixed or all scientific, round-off is never shown as 0.
    #[test]
    fn one_notation_per_column_and_no_false_zeros() {
        assert_eq!(format(0.0744001, Notation::Fixed), "0.07440");
        assert_eq!(format(1.0, Notation::Fixed), "1.000");
        assert_eq!(format(1234.6, Notation::Fixed), "1235");
        assert_eq!(format(8.9706e-14, Notation::Scientific), "8.971e-14");
        assert_eq!(format(0.0, Notation::Scientific), "0");
        let cells = [Cell::Num(562300.0), Cell::Num(1e6)];
        assert_eq!(column_notation(cells.iter()), Notation::Scientific);
        let cells = [Cell::Num(0.5), Cell::Num(0.0), Cell::Text("x".into())];
        assert_eq!(column_notation(cells.iter()), Notation::Fixed);
        let cells = [Cell::Num(0.5), Cell::Num(2e-14)];
        assert_eq!(column_notation(cells.iter()), Notation::Scientific);
    }
}
