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
    /// `mass_deviation`, `mode_error_ratio`: the mass kind compared and the one it is compared against.
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

/// A bound as the terminal shows it: `1e-30`, `3e-1`, and `0` (not `0e0`).
fn edge_text(edge: f64) -> String {
    if edge == 0.0 {
        "0".into()
    } else {
        format!("{edge:e}")
    }
}

/// How far `x` lies past the bound `edge` it broke: `: 9e16 x the bound` beyond a factor 2 either
/// way, `: +20.0 % past the bound` within it, nothing against a bound of 0 (no ratio exists).
fn distance_past(x: f64, edge: f64) -> String {
    if edge == 0.0 {
        return String::new();
    }
    let ratio = x / edge;
    if ratio > 0.0 && !(0.5..=2.0).contains(&ratio) {
        let shown = if (0.01..100.0).contains(&ratio) {
            format!("{ratio:.3}")
        } else {
            format!("{ratio:.0e}")
        };
        format!(": {shown} x the bound")
    } else {
        format!(": {:+.1} % past the bound", 100.0 * (x - edge) / edge.abs())
    }
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

    /// How far a verdict is from its bound, in words: `8.9706e-14 > 1e-30: 9e16 x the bound`,
    /// `1.2000e-3 > 1e-3: +20.0 % past the bound`, `false, expected true`, `observed energy
    /// growth x5.300, theory predicts stable`. A failed bound reads as the relation that broke;
    /// the distance past it is a factor when the value is off by more than 2x, a percentage
    /// otherwise (a percentage of 10^18 says nothing), and none against a bound of 0.
    pub fn excess(&self) -> String {
        match (&self.measured, self.bound) {
            (Measured::Value(x), _) if !x.is_finite() => format!("{x} is not a finite number"),
            (Measured::Value(x), Bound::Range { min, max }) => {
                let past = |edge: f64, relation: &str| {
                    format!(
                        "{x:.4e} {relation} {}{}",
                        edge_text(edge),
                        distance_past(*x, edge)
                    )
                };
                match (min, max) {
                    (Some(lo), _) if *x < lo => past(lo, "<"),
                    (_, Some(hi)) if *x > hi => past(hi, ">"),
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

    /// The bound as the terminal shows it beside the value: the bound itself when it holds
    /// (`<= 1e-10`), the relation that broke when it fails (`> 1e-30`, `< 0.3`).
    fn bound_as_read(&self) -> String {
        match (&self.measured, self.bound) {
            (Measured::Value(x), Bound::Range { min, max }) if !self.pass && x.is_finite() => {
                match (min, max) {
                    (Some(lo), _) if *x < lo => {
                        format!("< {} (bound {})", edge_text(lo), self.bound)
                    }
                    (_, Some(hi)) if *x > hi => {
                        format!("> {} (bound {})", edge_text(hi), self.bound)
                    }
                    _ => self.bound.to_string(),
                }
            }
            _ => self.bound.to_string(),
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
            self.bound_as_read(),
            self.source
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn failed(x: f64, min: Option<f64>, max: Option<f64>) -> Verdict {
        Verdict {
            case: "co1".into(),
            metric: Metric::Linf,
            at: None,
            relative_to: None,
            masses: None,
            force: None,
            measured: Measured::Value(x),
            bound: Bound::Range { min, max },
            pass: false,
            finding: false,
            source: "s".into(),
        }
    }

    /// Source of truth: arithmetic (x / bound). Proves: a failed bound reads as the relation
    /// that broke, far past it as a factor, near it as a percentage, against 0 as neither.
    #[test]
    fn a_failed_bound_reads_as_a_failure() {
        let far = failed(8.9706e-14, None, Some(1e-30));
        assert_eq!(far.excess(), "8.9706e-14 > 1e-30: 9e16 x the bound");
        assert!(
            far.describe()
                .contains("= 8.9706e-14 > 1e-30 (bound <= 1e-30)")
        );
        let near = failed(1.2e-3, None, Some(1e-3));
        assert_eq!(near.excess(), "1.2000e-3 > 1e-3: +20.0 % past the bound");
        let below = failed(0.1, Some(0.3), None);
        assert_eq!(below.excess(), "1.0000e-1 < 3e-1: 0.333 x the bound");
        let zero = failed(1e-3, None, Some(0.0));
        assert_eq!(zero.excess(), "1.0000e-3 > 0");
    }
}
