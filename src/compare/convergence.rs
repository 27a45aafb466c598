//! Observed orders of an h-refinement study: the order between successive meshes, the order
//! fitted by least squares on the finest meshes, and its verdict against the band theory allows
//! (deal.II's convergence tables; the bands are the study's, `scene::studies::convergence`).

use super::verdict::{Measured, Verdict};
use crate::results::table::{Cell, Table};
use crate::scene::expectation::{Bound, Metric};
use crate::scene::studies::convergence::{ConvergenceStudy, FIT_LEVELS, OrderBand};

/// What a convergence study's fitted order says of one norm.
#[derive(Debug, Clone, PartialEq)]
pub struct OrderVerdict {
    /// `l1`, `l2` or `linf`.
    pub norm: &'static str,
    /// Order fitted on the finest [`FIT_LEVELS`] meshes (`None` at round-off).
    pub fitted: Option<f64>,
    /// What theory allows, as text (`-` where it gives nothing).
    pub expected: String,
    /// `None` for a norm with no band (measured only).
    pub pass: Option<bool>,
}

/// Picks one error norm of a mesh level.
type NormOf = fn(&Level) -> f64;

/// One mesh of a convergence study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Level {
    /// Elements.
    pub elements: usize,
    /// Time step.
    pub dt: f64,
    /// Steps.
    pub steps: usize,
    /// Normalised L1, L2 and max errors.
    pub l1: f64,
    /// L2 error.
    pub l2: f64,
    /// Max error.
    pub linf: f64,
    /// Wall time of the run, in seconds.
    pub wall_time: f64,
}

/// Errors against the exact solution on each mesh of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct ConvergenceResult {
    /// The study.
    pub study: ConvergenceStudy,
    /// One entry per mesh, coarse to fine.
    pub levels: Vec<Level>,
}

impl ConvergenceResult {
    /// Observed order between level `i - 1` and `i` of the norm picked by `pick`.
    fn order(&self, i: usize, pick: fn(&Level) -> f64) -> Option<f64> {
        let (a, b) = (&self.levels[i - 1], &self.levels[i]);
        let (ea, eb) = (pick(a), pick(b));
        (ea > 1e-12 && eb > 1e-12)
            .then(|| (ea / eb).ln() / (b.elements as f64 / a.elements as f64).ln())
    }

    /// True when the error decreases strictly from mesh to mesh on the finest [`FIT_LEVELS`]
    /// meshes.
    pub fn decreasing(&self, pick: fn(&Level) -> f64) -> bool {
        let finest = &self.levels[self.levels.len().saturating_sub(FIT_LEVELS)..];
        finest.len() >= 2 && finest.windows(2).all(|w| pick(&w[1]) < pick(&w[0]))
    }

    /// Least-squares order on the finest [`FIT_LEVELS`] meshes, `-slope` of `ln e` against
    /// `ln N`; `None` when an error there is at round-off level (below 1e-12).
    pub fn fitted_order(&self, pick: fn(&Level) -> f64) -> Option<f64> {
        let finest = &self.levels[self.levels.len().saturating_sub(FIT_LEVELS)..];
        if finest.len() < 2 || finest.iter().any(|l| pick(l) <= 1e-12) {
            return None;
        }
        let points: Vec<(f64, f64)> = finest
            .iter()
            .map(|l| ((l.elements as f64).ln(), pick(l).ln()))
            .collect();
        let count = points.len() as f64;
        let (mx, my) = points
            .iter()
            .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / count, b + y / count));
        let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
            (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
        });
        Some(-sxy / sxx)
    }

    /// One verdict per norm (L1, L2, max).
    pub fn verdicts(&self) -> Vec<OrderVerdict> {
        let picks: [(&str, NormOf); 3] = [("l1", |l| l.l1), ("l2", |l| l.l2), ("linf", |l| l.linf)];
        picks
            .iter()
            .zip(self.study.bands)
            .map(|(&(norm, pick), band)| {
                // Under an exactness band the errors are round-off: a slope fitted to them is
                // noise, not an order, and is left out.
                let fitted = match band {
                    Some(OrderBand::Exact { .. }) => None,
                    _ => self.fitted_order(pick),
                };
                let (expected, pass) = match band {
                    None => ("-".to_string(), None),
                    Some(OrderBand::Order { min, max }) => (
                        format!("order in [{min}, {max}]"),
                        Some(fitted.is_some_and(|p| (min..=max).contains(&p))),
                    ),
                    Some(OrderBand::Exact { max_error }) => (
                        format!("error <= {max_error:e} on every mesh"),
                        Some(self.levels.iter().all(|l| pick(l) <= max_error)),
                    ),
                    Some(OrderBand::Converges { min }) => (
                        format!("decreasing on the finest {FIT_LEVELS} meshes, order >= {min}"),
                        Some(self.decreasing(pick) && fitted.is_some_and(|p| p >= min)),
                    ),
                };
                OrderVerdict {
                    norm,
                    fitted,
                    expected,
                    pass,
                }
            })
            .collect()
    }

    /// The verdicts of the norms with a band, as verdicts beside the scenes' (case
    /// `<study> <norm>`): the fitted order against an order band, or the largest error over the
    /// meshes against an exactness band.
    pub fn order_verdicts(&self) -> Vec<Verdict> {
        let picks: [NormOf; 3] = [|l| l.l1, |l| l.l2, |l| l.linf];
        self.verdicts()
            .into_iter()
            .zip(self.study.bands)
            .zip(picks)
            .filter_map(|((v, band), pick)| {
                let pass = v.pass?;
                let (metric, measured, bound) = match band? {
                    OrderBand::Order { min, max } => (
                        Metric::FittedOrder,
                        v.fitted.map_or(
                            Measured::Missing("an error at round-off on the finest meshes".into()),
                            Measured::Value,
                        ),
                        Bound::Range {
                            min: Some(min),
                            max: Some(max),
                        },
                    ),
                    OrderBand::Exact { max_error } => (
                        Metric::MaxError,
                        Measured::Value(self.levels.iter().map(pick).fold(0.0, f64::max)),
                        Bound::Range {
                            min: None,
                            max: Some(max_error),
                        },
                    ),
                    // A non-decreasing error fails even with a positive fitted order: `pass`
                    // carries both.
                    OrderBand::Converges { min } => (
                        Metric::FittedOrder,
                        v.fitted.map_or(
                            Measured::Missing("an error at round-off on the finest meshes".into()),
                            Measured::Value,
                        ),
                        Bound::Range {
                            min: Some(min),
                            max: None,
                        },
                    ),
                };
                Some(Verdict {
                    case: format!("{} {}", self.study.name, v.norm),
                    metric,
                    at: None,
                    relative_to: None,
                    masses: None,
                    force: None,
                    measured,
                    bound,
                    pass,
                    finding: false,
                    source: self.study.expected.to_string(),
                })
            })
            .collect()
    }

    /// `norm, fitted_order, expected, verdict` (fitted on the finest [`FIT_LEVELS`] meshes).
    pub fn verdict_table(&self) -> Table {
        let mut t = Table::new(&["norm", "fitted_order", "expected", "verdict"]);
        for v in self.verdicts() {
            t.push(vec![
                v.norm.into(),
                v.fitted.into(),
                v.expected.into(),
                match v.pass {
                    None => "measured",
                    Some(true) => "pass",
                    Some(false) => "FAIL",
                }
                .into(),
            ]);
        }
        t
    }

    /// `N, dt, steps, l1, order_l1, l2, order_l2, linf, order_linf` (orders between successive
    /// meshes; empty where an error is at round-off level).
    pub fn table(&self) -> Table {
        let mut t = Table::new(&[
            "N",
            "dt",
            "steps",
            "l1",
            "order_l1",
            "l2",
            "order_l2",
            "linf",
            "order_linf",
        ]);
        for (i, level) in self.levels.iter().enumerate() {
            let order = |pick| {
                if i == 0 {
                    Cell::Empty
                } else {
                    self.order(i, pick).into()
                }
            };
            t.push(vec![
                level.elements.into(),
                level.dt.into(),
                level.steps.into(),
                level.l1.into(),
                order(|l| l.l1),
                level.l2.into(),
                order(|l| l.l2),
                level.linf.into(),
                order(|l| l.linf),
            ]);
        }
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::studies::convergence::{AIRY_FRONT, CONVERGENCE_STUDIES};

    fn study_with(errors: &[(usize, f64)], bands: [Option<OrderBand>; 3]) -> ConvergenceResult {
        ConvergenceResult {
            study: ConvergenceStudy {
                bands,
                ..CONVERGENCE_STUDIES[0]
            },
            levels: errors
                .iter()
                .map(|&(elements, e)| Level {
                    elements,
                    dt: 1.0 / elements as f64,
                    steps: elements,
                    l1: e,
                    l2: e,
                    linf: 0.3,
                    wall_time: 0.0,
                })
                .collect(),
        }
    }

    #[test]
    fn fitted_order_is_the_least_squares_slope_of_the_finest_meshes() {
        // e = 2 N^(-1/2) on the finest three meshes; the coarse one is off the line and ignored.
        let c = study_with(
            &[
                (50, 1.0),
                (100, 2.0 / 10.0),
                (200, 2.0 / 200f64.sqrt()),
                (400, 2.0 / 20.0),
            ],
            AIRY_FRONT,
        );
        assert!((c.fitted_order(|l| l.l1).unwrap() - 0.5).abs() < 1e-12);
        let verdicts = c.verdicts();
        assert_eq!(
            verdicts[0].pass,
            Some(true),
            "L1 order 1/2 is in [0.42, 0.56]"
        );
        assert_eq!(
            verdicts[1].pass,
            Some(false),
            "L2 order 1/2 is outside [0.30, 0.37]"
        );
        assert_eq!(
            verdicts[2].pass,
            Some(true),
            "a constant max error has order 0"
        );
        let exact = study_with(
            &[(50, 0.0), (100, 1e-15)],
            [Some(OrderBand::Exact { max_error: 1e-10 }), None, None],
        );
        assert_eq!(exact.fitted_order(|l| l.l1), None, "round-off has no order");
        assert_eq!(exact.verdicts()[0].pass, Some(true));
        assert_eq!(exact.verdicts()[1].pass, None, "no band: measured only");
    }
}
