//! The verdict of one expectation on one case: what was measured, the bound, pass or fail, and
//! the source of truth.

use crate::results::table::Cell;
use crate::scene::expectation::{Bound, Metric};

/// What was measured for an expectation.
#[derive(Debug, Clone, PartialEq)]
pub enum Measured {
    /// A number.
    Value(f64),
    /// A yes/no outcome.
    Flag(bool),
    /// Nothing could be measured (e.g. the run diverged before the profile time).
    Missing(String),
}

/// The verdict of one expectation on one case.
#[derive(Debug, Clone, PartialEq)]
pub struct Verdict {
    /// Case name.
    pub case: String,
    /// Metric.
    pub metric: Metric,
    /// Profile time, if the expectation names one.
    pub at: Option<f64>,
    /// Measured value.
    pub measured: Measured,
    /// Bound.
    pub bound: Bound,
    /// Whether the bound holds.
    pub pass: bool,
    /// Source of truth of the bound.
    pub source: String,
}

impl Verdict {
    /// `(min, max, equals)` cells for tables.
    pub fn bound_cells(&self) -> (Cell, Cell, Cell) {
        match self.bound {
            Bound::Range { min, max } => (min.into(), max.into(), Cell::Empty),
            Bound::Equals(b) => (Cell::Empty, Cell::Empty, Cell::Text(b.to_string())),
        }
    }

    /// One line for the terminal.
    pub fn describe(&self) -> String {
        let measured = match &self.measured {
            Measured::Value(x) => format!("{x:.4e}"),
            Measured::Flag(b) => b.to_string(),
            Measured::Missing(why) => format!("missing ({why})"),
        };
        let bound = match self.bound {
            Bound::Range {
                min: Some(lo),
                max: Some(hi),
            } => format!("in [{lo:e}, {hi:e}]"),
            Bound::Range {
                min: Some(lo),
                max: None,
            } => format!(">= {lo:e}"),
            Bound::Range {
                min: None,
                max: Some(hi),
            } => format!("<= {hi:e}"),
            Bound::Range {
                min: None,
                max: None,
            } => "unbounded".into(),
            Bound::Equals(b) => format!("== {b}"),
        };
        let at = self.at.map(|t| format!(" at t = {t}")).unwrap_or_default();
        let verdict = if self.pass { "pass" } else { "FAIL" };
        format!(
            "{verdict:4}  {} {}{at} = {measured} {bound}  [{}]",
            self.case,
            self.metric.name(),
            self.source
        )
    }
}
