//! How the report shows numbers: one format per table column (every row of a column reads
//! alike), four significant digits, never a bare 0 for a value that is not zero (round-off shows
//! as what it is, e.g. `8.971e-14`), and never a round number for a value near it that is not (a
//! step ratio `0.99997` is not shown as `1.000`). The CSV files beside the report keep every
//! number at full round-trip precision.
//!
//! A format is either fixed with one number of decimals for the whole column (`0.99997`,
//! `1.00000`, `0.50000` in one column: the digits line up and tell the values apart) or
//! scientific with four significant digits (`8.971e-14`, `1.000e6`). Columns compared within a
//! row share one format: an expectation's `measured`, `min`, `max`, `equals` and a check's
//! `bound` ([`format_group`]).

use crate::results::table::{Cell, Table};
use std::collections::BTreeMap;

/// Significant digits shown.
const DIGITS: i32 = 4;

/// Most decimals a fixed column shows.
const MAX_DECIMALS: usize = 9;

/// A value within this relative distance of an integer is that integer to round-off (below the
/// marginal band 1e-9 of the stability table, `compare::stability`): no extra digits for it.
const ROUND_OFF: f64 = 1e-9;

/// Widest fixed column, in digits before and after the point together; wider columns are
/// scientific.
const MAX_FIXED_DIGITS: usize = 8;

/// The notation of one column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Notation {
    /// Fixed notation with this many decimals for every value of the column (`0.07440`,
    /// `1.00000`, `1235`).
    Fixed(usize),
    /// Four significant digits in scientific notation (`8.971e-14`, `1.000e6`).
    Scientific,
}

/// The name whose format a column takes: the columns an expectation or check compares within a
/// row (`measured`, `min`, `max`, `equals`, `bound`) share one.
pub fn format_group(column: &str) -> &str {
    match column {
        "measured" | "min" | "max" | "equals" | "bound" => "measured",
        other => other,
    }
}

/// Decimal exponent of `x` once rounded to [`DIGITS`] significant digits (`0.99997` -> 0).
fn rounded_exponent(x: f64) -> i32 {
    let sci = format!("{:.*e}", (DIGITS - 1) as usize, x);
    sci.split('e')
        .nth(1)
        .and_then(|e| e.parse().ok())
        .unwrap_or(0)
}

/// Decimals `x` needs in fixed notation: four significant digits, and enough to tell it from the
/// integer next to it (`0.99997` needs 5: `1.0000` would read as 1).
fn decimals_needed(x: f64) -> usize {
    let mut d = (DIGITS - 1 - rounded_exponent(x)).max(0) as usize;
    let n = x.round();
    let off = (x - n).abs();
    if n != 0.0 && off > ROUND_OFF * n.abs() {
        while d < MAX_DECIMALS && format!("{x:.d$}") == format!("{n:.d$}") {
            d += 1;
        }
    }
    d
}

/// The notation of a column of these cells: fixed when every finite nonzero number lies in
/// `[1e-2, 1e5)` and the column, at the decimals its values need, stays within
/// [`MAX_FIXED_DIGITS`] digits; else scientific (a column never mixes `562300` with `1.000e6`).
pub fn column_notation<'a>(cells: impl Iterator<Item = &'a Cell>) -> Notation {
    let values: Vec<f64> = cells
        .filter_map(|c| match c {
            Cell::Num(x) if x.is_finite() && *x != 0.0 => Some(x.abs()),
            _ => None,
        })
        .collect();
    if !values.iter().all(|x| (1e-2..1e5).contains(x)) {
        return Notation::Scientific;
    }
    let decimals = values
        .iter()
        .map(|&x| decimals_needed(x))
        .max()
        .unwrap_or(0);
    let integer_digits = values
        .iter()
        .map(|&x| {
            format!("{x:.decimals$}")
                .split('.')
                .next()
                .map_or(1, str::len)
        })
        .max()
        .unwrap_or(1);
    if decimals > 0 && integer_digits + decimals > MAX_FIXED_DIGITS {
        Notation::Scientific
    } else {
        Notation::Fixed(decimals)
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
        Notation::Fixed(decimals) => format!("{x:.decimals$}"),
    }
}

/// The notation of every column name of some tables: each [`format_group`] decided over every
/// table given that has it (the report decides each table on its own, [`shown`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Formats(BTreeMap<String, Notation>);

impl Formats {
    /// The formats of these tables.
    pub fn of_tables<'a>(tables: impl Iterator<Item = &'a Table>) -> Self {
        let mut cells: BTreeMap<String, Vec<&Cell>> = BTreeMap::new();
        for table in tables {
            for (c, column) in table.columns.iter().enumerate() {
                let group = cells.entry(format_group(column).to_string()).or_default();
                group.extend(table.rows.iter().map(|r| &r[c]));
            }
        }
        Self(
            cells
                .into_iter()
                .map(|(name, cells)| (name, column_notation(cells.into_iter())))
                .collect(),
        )
    }

    /// The notation of `column` (fixed without decimals for a column not seen).
    pub fn notation(&self, column: &str) -> Notation {
        self.0
            .get(format_group(column))
            .copied()
            .unwrap_or(Notation::Fixed(0))
    }
}

/// Every cell of a table as shown in `formats`: numbers in their column's notation, integers
/// exactly, empty cells as `-`.
pub fn shown_in(table: &Table, formats: &Formats) -> Vec<Vec<String>> {
    let notations: Vec<Notation> = table.columns.iter().map(|c| formats.notation(c)).collect();
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

/// Every cell of one table as shown on its own (its columns' formats decided over it alone).
pub fn shown(table: &Table) -> Vec<Vec<String>> {
    shown_in(table, &Formats::of_tables(std::iter::once(table)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Source of truth: the report's number rules above. Proves: four significant digits, one
    /// number of decimals per fixed column, a column is all fixed or all scientific, round-off is
    /// never shown as 0, and no value near 1 is shown as 1.
    #[test]
    fn one_format_per_column_and_no_false_zeros_or_ones() {
        let column = |xs: &[f64]| {
            let cells: Vec<Cell> = xs.iter().map(|&x| Cell::Num(x)).collect();
            let n = column_notation(cells.iter());
            xs.iter().map(|&x| format(x, n)).collect::<Vec<_>>()
        };
        assert_eq!(column(&[0.0744001]), ["0.07440"]);
        assert_eq!(column(&[1.0, 1234.6]), ["1.000", "1234.600"]);
        assert_eq!(column(&[8.9706e-14]), ["8.971e-14"]);
        assert_eq!(column(&[0.0, 0.5]), ["0", "0.5000"]);
        assert_eq!(column(&[562300.0, 1e6]), ["5.623e5", "1.000e6"]);
        assert_eq!(column(&[0.5, 2e-14]), ["5.000e-1", "2.000e-14"]);
        // A step ratio a hair below its limit beside the limit itself: told apart, one
        // number of decimals for the column (not `1.0000` beside `1.000`).
        assert_eq!(
            column(&[0.99997, 1.0, 0.5, 1.01]),
            ["0.99997", "1.00000", "0.50000", "1.01000"]
        );
        // Round-off is the integer it rounds to.
        assert_eq!(column(&[1.0 + 1e-15, 0.99]), ["1.0000", "0.9900"]);
        // 0.09988 needs 5 decimals; 0.1 rounded to 4 digits is not `0.10000` beside `0.2500`.
        assert_eq!(column(&[0.1, 0.25]), ["0.1000", "0.2500"]);
        // Too wide at one number of decimals: scientific.
        assert_eq!(column(&[0.0125, 15614.0]), ["1.250e-2", "1.561e4"]);
    }

    /// Source of truth: the rule "one format per column; the values a row compares share
    /// one". Proves: a column takes the format its values need over the tables it is decided
    /// on, and an expectation's measured value and its bounds share one (no `1.103e0` beside a
    /// `1.050`).
    #[test]
    fn a_column_reads_alike_and_a_measured_value_like_its_bounds() {
        let mut a = Table::new(&["l1", "measured", "min"]);
        a.push(vec![Cell::Num(0.0744), Cell::Num(1.103), Cell::Num(1.05)]);
        let mut b = Table::new(&["l1", "bound"]);
        b.push(vec![Cell::Num(8.97e-14), Cell::Num(1e-12)]);
        let formats = Formats::of_tables([&a, &b].into_iter());
        assert_eq!(shown_in(&a, &formats), [["7.440e-2", "1.103e0", "1.050e0"]]);
        let alone = shown(&a);
        assert_eq!(alone, [["0.07440", "1.103", "1.050"]]);
        let mut c = Table::new(&["measured", "min"]);
        c.push(vec![Cell::Num(1.103), Cell::Num(1.05)]);
        c.push(vec![Cell::Num(8.97e-14), Cell::Empty]);
        assert_eq!(shown(&c), [["1.103e0", "1.050e0"], ["8.970e-14", "-"]]);
    }
}
