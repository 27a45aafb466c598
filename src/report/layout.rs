//! How a table is laid out for reading (Markdown and HTML alike; the CSV beside it keeps the
//! data's own column order): the verdict or status first, so that no error is read without the
//! word that says whether the run completed or the check held, and long texts (`source`, `note`)
//! last, where they can wrap; long tables keep their non-passing rows in view and fold the rest.

use crate::results::table::Table;

/// Columns that say whether a row holds, in the order they lead a table.
pub const STATUS_COLUMNS: [&str; 3] = ["verdict", "status", "agrees"];

/// Columns of free text, moved to the end of a table.
const TEXT_COLUMNS: [&str; 2] = ["source", "note"];

/// Verdict and status words that need no second look: a row made only of these may fold.
const PASSING: [&str; 4] = ["pass", "yes", "completed", "-"];

/// True for a column that states a verdict or a run's status.
pub fn is_status(column: &str) -> bool {
    STATUS_COLUMNS.contains(&column)
}

/// The order columns are shown in: status columns first (in [`STATUS_COLUMNS`] order), free
/// text last, the rest as the data has them.
pub fn column_order(columns: &[String]) -> Vec<usize> {
    let status = STATUS_COLUMNS
        .iter()
        .filter_map(|s| columns.iter().position(|c| c == s));
    let middle = (0..columns.len())
        .filter(|&i| !is_status(&columns[i]) && !TEXT_COLUMNS.contains(&columns[i].as_str()));
    let text = (0..columns.len()).filter(|&i| TEXT_COLUMNS.contains(&columns[i].as_str()));
    status.chain(middle).chain(text).collect()
}

/// `items` in the order of `order`.
pub fn reordered<T: Clone>(items: &[T], order: &[usize]) -> Vec<T> {
    order.iter().map(|&i| items[i].clone()).collect()
}

/// True when a shown row needs a look: one of its status cells is not a passing word
/// (`FAIL`, `finding`, `no`, `diverged at step 1`, `not predicted`, ...).
pub fn needs_a_look(columns: &[String], row: &[String]) -> bool {
    columns
        .iter()
        .zip(row)
        .any(|(c, v)| is_status(c) && !PASSING.contains(&v.as_str()))
}

/// True when a table states a verdict or status in some column.
pub fn has_status(table: &Table) -> bool {
    table.columns.iter().any(|c| is_status(c))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Source of truth: the report's reading order (a verdict is read before the numbers it
    /// judges). Proves: verdict and status lead, free text trails, the rest keeps its order, and
    /// a row needs a look exactly when a status cell is not a passing word.
    #[test]
    fn status_first_text_last() {
        let columns: Vec<String> = ["case", "source", "l1", "status", "verdict", "note"]
            .map(String::from)
            .to_vec();
        let order = column_order(&columns);
        assert_eq!(
            reordered(&columns, &order),
            ["verdict", "status", "case", "l1", "source", "note"]
        );
        let row = |s: &str, v: &str| -> Vec<String> {
            ["c", "src", "0.1", s, v, ""].map(String::from).to_vec()
        };
        assert!(!needs_a_look(&columns, &row("completed", "pass")));
        assert!(needs_a_look(&columns, &row("diverged at step 1", "pass")));
        assert!(needs_a_look(&columns, &row("completed", "finding")));
        assert!(needs_a_look(&columns, &row("completed", "FAIL")));
    }
}
