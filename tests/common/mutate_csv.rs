//! Mutations of CSV text (exchange case files, `--at` query files, baseline tables) for the
//! fuzz harness of the readers (`tests/grading/fuzz_exchange.rs`): cells replaced by extremes, junk or
//! nothing, header names misspelt, quotes left open, lines deleted, duplicated or swapped, the
//! text truncated or a line made very long.
#![allow(dead_code)]

use proptest::prelude::*;

/// What a cell becomes: magnitudes around every limit, non-numbers and non-finite spellings.
pub const CELLS: &[&str] = &[
    "0",
    "-0",
    "1e308",
    "-1e308",
    "1e-320",
    "5e-324",
    "1e50",
    "1.0000001e50",
    "1e51",
    "1e200",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "",
    " ",
    "x",
    "1e",
    "0x10",
    "999",
    "1000",
    "1e6",
    "1e300",
    "-1",
    "0.5",
    "\"",
    "\"1\"",
    "1,2",
    "t",
    "stress",
    "é",
];

/// What a header name becomes.
pub const NAMES: &[&str] = &[
    "t",
    "x",
    "x_left",
    "x_right",
    "stress",
    "force",
    "mode",
    "omega",
    "mass",
    "reference",
    "Stress",
    "strss",
    "",
    "t ",
    "penetration",
    "gap",
];

/// One edit of a CSV text.
#[derive(Debug, Clone)]
pub enum CsvMutation {
    /// The `at`-th cell (all lines, left to right) becomes `CELLS[value]`.
    Cell { at: usize, value: usize },
    /// The `at`-th header name becomes `NAMES[name]`.
    Header { at: usize, name: usize },
    /// The `at`-th line is deleted.
    DeleteLine { at: usize },
    /// The `at`-th line is written twice.
    DuplicateLine { at: usize },
    /// Lines `at` and `at + 1` change places.
    SwapLines { at: usize },
    /// The text ends after `at` of every 1000 of its characters.
    Truncate { at: usize },
    /// The `at`-th line gets `count` thousand `x` appended.
    LongLine { at: usize, count: usize },
}

/// A mutation with indices in useful ranges (the edit reduces them modulo what exists).
pub fn csv_mutation() -> impl Strategy<Value = CsvMutation> {
    prop_oneof![
        6 => (0..256usize, 0..CELLS.len()).prop_map(|(at, value)| CsvMutation::Cell { at, value }),
        2 => (0..8usize, 0..NAMES.len()).prop_map(|(at, name)| CsvMutation::Header { at, name }),
        2 => (0..64usize).prop_map(|at| CsvMutation::DeleteLine { at }),
        1 => (0..64usize).prop_map(|at| CsvMutation::DuplicateLine { at }),
        2 => (0..64usize).prop_map(|at| CsvMutation::SwapLines { at }),
        1 => (0..1000usize).prop_map(|at| CsvMutation::Truncate { at }),
        1 => (0..64usize, 1..80usize).prop_map(|(at, count)| CsvMutation::LongLine { at, count }),
    ]
}

/// `text` with `mutation` applied.
pub fn apply_csv(text: &str, mutation: &CsvMutation) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    if lines.is_empty() {
        return text.to_string();
    }
    let n = lines.len();
    match *mutation {
        CsvMutation::Cell { at, value } => {
            let cells: usize = lines.iter().map(|l| l.split(',').count()).sum();
            let mut k = at % cells.max(1);
            for line in &mut lines {
                let mut parts: Vec<String> = line.split(',').map(str::to_string).collect();
                if k < parts.len() {
                    parts[k] = CELLS[value].to_string();
                    *line = parts.join(",");
                    break;
                }
                k -= parts.len();
            }
        }
        CsvMutation::Header { at, name } => {
            let mut parts: Vec<String> = lines[0].split(',').map(str::to_string).collect();
            let i = at % parts.len();
            parts[i] = NAMES[name].to_string();
            lines[0] = parts.join(",");
        }
        CsvMutation::DeleteLine { at } => {
            lines.remove(at % n);
        }
        CsvMutation::DuplicateLine { at } => {
            let line = lines[at % n].clone();
            lines.insert(at % n, line);
        }
        CsvMutation::SwapLines { at } => {
            if n > 1 {
                lines.swap(at % (n - 1), at % (n - 1) + 1);
            }
        }
        CsvMutation::Truncate { at } => {
            let joined = lines.join("\n");
            let end = joined.len() * at / 1000;
            let end = (0..=end)
                .rev()
                .find(|&i| joined.is_char_boundary(i))
                .unwrap_or(0);
            return joined[..end].to_string();
        }
        CsvMutation::LongLine { at, count } => {
            lines[at % n].push_str(&"x".repeat(count * 1000));
        }
    }
    let mut out = lines.join("\n");
    out.push('\n');
    out
}
