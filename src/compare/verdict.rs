//! The verdict of one expectation on one case: what was measured, the bound, pass or fail, and
//! the source of truth.

use crate::results::table::Cell;
use crate::scene::contact::ForceMeasure;
use crate::scene::expectation::{Bound, Metric};
use crate::scene::mass::mass_name;
use courant_solver::MassKind;

/// What was measured for an expectation.
#[derive(Debug, Clone, PartialEq)]
pub enum Measured {
    /// A number.
    Value(f64),
    /// A yes/no outcome.
    Flag(bool),
    /// What a run did (the stability verdict), e.g. `energy growth x5.300`.
    Text(String),
    /// Nothing could be measured (e.g. the run diverged before the profile time).
    Missing(String),
}

impl std::fmt::Display for Measured {
    /// Numbers with 4 significant digits in scientific form.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Measured::Value(x) => write!(f, "{x:.4e}"),
            Measured::Flag(b) => write!(f, "{b}"),
            Measured::Text(t) => write!(f, "{t}"),
            Measured::Missing(why) => write!(f, "missing ({why})"),
        }
    }
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
    /// The case the value is relative to, if any.
    pub relative_to: Option<String>,
    /// `mass_deviation`: the mass kind compared and the one it is compared against.
    pub masses: Option<(MassKind, MassKind)>,
    /// Contact force metrics: the force measured, when not the scene's.
    pub force: Option<ForceMeasure>,
    /// Measured value.
    pub measured: Measured,
    /// Bound.
    pub bound: Bound,
    /// Whether the bound holds (a stated finding passes).
    pub pass: bool,
    /// A stability verdict where theory and run disagree as the scene states (`[[finding]]`), or
    /// a row stated as a finding (`finding = true`) whose bound holds:
    /// it passes, and is counted apart from the agreements.
    pub finding: bool,
    /// Source of truth of the bound (of the finding, for a finding).
    pub source: String,
}

impl Verdict {
    /// The metric as measured: `l1`, `l1 / co0.5` (a ratio to another case),
    /// `force_history_difference vs <case>`, `stress_difference vs <case>`,
    /// `mass_deviation rmm0.5 vs amm0.5`.
    pub fn metric_label(&self) -> String {
        let name = match self.force {
            Some(force) => format!("{} ({})", self.metric.name(), force.label()),
            None => self.metric.name().to_string(),
        };
        match (&self.relative_to, self.masses) {
            (_, Some((a, b))) => format!("{name} {} vs {}", mass_name(a), mass_name(b)),
            (Some(other), _) if self.metric.compares_cases() => {
                format!("{name} vs {other}")
            }
            (Some(other), _) => format!("{name} / {other}"),
            (None, None) => name,
        }
    }

    /// `(min, max, equals)` cells for tables.
    pub fn bound_cells(&self) -> (Cell, Cell, Cell) {
        match self.bound {
            Bound::Range { min, max } => (min.into(), max.into(), Cell::Empty),
            Bound::Equals(b) => (Cell::Empty, Cell::Empty, Cell::Text(b.to_string())),
            Bound::Theory(p) => (Cell::Empty, Cell::Empty, Cell::Text(p.to_string())),
        }
    }

    /// `pass`, `FAIL`, or `finding` (a stated disagreement with theory).
    pub fn word(&self) -> &'static str {
        match (self.pass, self.finding) {
            (true, true) => "finding",
            (true, false) => "pass",
            (false, _) => "FAIL",
        }
    }

    /// How far a verdict is from its bound, in words: `1.20e-3 above the max 1e-3 (+20 %)`,
    /// `false, expected true`, `observed energy growth x5.300, theory predicts stable`.
    pub fn excess(&self) -> String {
        match (&self.measured, self.bound) {
            (Measured::Value(x), _) if !x.is_finite() => format!("{x} is not a finite number"),
            (Measured::Value(x), Bound::Range { min, max }) => {
                let past = |edge: f64, side: &str| {
                    let relative = if edge != 0.0 {
                        format!(" ({:+.3} %)", 100.0 * (x - edge) / edge.abs())
                    } else {
                        String::new()
                    };
                    format!("{x:.4e} is {side} {edge:e}{relative}")
                };
                match (min, max) {
                    (Some(lo), _) if *x < lo => past(lo, "below the min"),
                    (_, Some(hi)) if *x > hi => past(hi, "above the max"),
                    _ => format!("{x:.4e} is within the bound"),
                }
            }
            (Measured::Flag(b), Bound::Equals(want)) => format!("{b}, expected {want}"),
            (Measured::Text(t), Bound::Theory(p)) => {
                format!("observed {t}, theory predicts {p}")
            }
            (Measured::Missing(why), _) => format!("not measured: {why}"),
            (measured, bound) => format!("measured {measured}, bound {bound}"),
        }
    }

    /// One line for the terminal.
    pub fn describe(&self) -> String {
        let at = self.at.map(|t| format!(" at t = {t}")).unwrap_or_default();
        format!(
            "{:7}  {} {}{at} = {} {}  [{}]",
            self.word(),
            self.case,
            self.metric_label(),
            self.measured,
            self.bound,
            self.source
        )
    }
}
