//! The bound of an `[[expect]]` row (a range, a flag, or the stability prediction of a
//! stability scene's case) and how it is shown; re-exported by [`super::expectation`].

/// The bound of an expectation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    /// `min <= value <= max` (either side optional).
    Range {
        /// Lower bound.
        min: Option<f64>,
        /// Upper bound.
        max: Option<f64>,
    },
    /// A boolean metric equals this.
    Equals(bool),
    /// The stability verdict of a stability scene's case: the run does what theory predicts
    /// (`stable`, `marginal`, `unstable`, `contact-unstable`).
    Theory(&'static str),
}

impl std::fmt::Display for Bound {
    /// `<= max`, `>= min`, `in [min, max]`, `== flag`, `as predicted: stable`; numbers in their
    /// shortest round-trip form (scientific below 1e-4 and from 1e6).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let num = |x: f64| {
            if x != 0.0 && !(1e-4..1e6).contains(&x.abs()) {
                format!("{x:e}")
            } else {
                format!("{x}")
            }
        };
        match *self {
            Bound::Range {
                min: Some(lo),
                max: Some(hi),
            } => write!(f, "in [{}, {}]", num(lo), num(hi)),
            Bound::Range {
                min: Some(lo),
                max: None,
            } => write!(f, ">= {}", num(lo)),
            Bound::Range {
                min: None,
                max: Some(hi),
            } => write!(f, "<= {}", num(hi)),
            Bound::Range {
                min: None,
                max: None,
            } => write!(f, "unbounded"),
            Bound::Equals(b) => write!(f, "== {b}"),
            Bound::Theory(predicted) => write!(f, "as predicted: {predicted}"),
        }
    }
}
