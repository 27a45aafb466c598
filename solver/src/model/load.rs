//! Loads: nodal forces and end tractions, each scaled by a time function.
//!
//! A traction `sigma(t)` on an end becomes a nodal force on the end node with the outward normal:
//! `F = -sigma A` at the left end (normal `-x`) and `F = +sigma A` at the right end (methods.md
//! §2).

use crate::error::InputError;

/// Time dependence of a load, `f(t)`, multiplying its magnitude.
#[derive(Debug, Clone, PartialEq)]
pub enum TimeFunction {
    /// Heaviside step `H(t - start)`, with `H(0) = value_at_start`. `value_at_start = 1` is the
    /// convention that makes lumped CD at Co = 1 exact (methods.md §2); `1/2` is what a naive
    /// three-level start needs instead.
    Step {
        /// Time the step switches on.
        start: f64,
        /// Value at exactly `t = start`.
        value_at_start: f64,
    },
    /// Linear ramp from 0 at `start` to 1 at `start + rise`, then held at 1.
    Ramp {
        /// Time the ramp begins.
        start: f64,
        /// Rise time, positive.
        rise: f64,
    },
    /// Rectangular pulse, `H(t - start) - H(t - start - duration)` with `H(0) = 1`: 1 on
    /// `[start, start + duration)`, 0 elsewhere.
    Pulse {
        /// Time the pulse switches on.
        start: f64,
        /// Duration, positive.
        duration: f64,
    },
    /// Piecewise-linear table `(t_i, f_i)`, times strictly increasing; held constant before the
    /// first and after the last point.
    Table {
        /// Times, strictly increasing.
        times: Vec<f64>,
        /// Values at those times.
        values: Vec<f64>,
    },
}

impl TimeFunction {
    /// The Heaviside step at `t = 0` with `H(0) = 1`.
    pub const HEAVISIDE: TimeFunction = TimeFunction::Step {
        start: 0.0,
        value_at_start: 1.0,
    };

    /// Evaluate `f(t)`.
    pub fn value(&self, t: f64) -> f64 {
        match self {
            TimeFunction::Step {
                start,
                value_at_start,
            } => {
                if t > *start {
                    1.0
                } else if t == *start {
                    *value_at_start
                } else {
                    0.0
                }
            }
            TimeFunction::Ramp { start, rise } => ((t - start) / rise).clamp(0.0, 1.0),
            TimeFunction::Pulse { start, duration } => {
                if t >= *start && t < start + duration {
                    1.0
                } else {
                    0.0
                }
            }
            TimeFunction::Table { times, values } => {
                let i = times.partition_point(|&ti| ti <= t);
                if i == 0 {
                    values[0]
                } else if i == times.len() {
                    values[times.len() - 1]
                } else {
                    let s = (t - times[i - 1]) / (times[i] - times[i - 1]);
                    values[i - 1] + s * (values[i] - values[i - 1])
                }
            }
        }
    }

    /// Check the parameters: finite times, positive durations, a strictly increasing table.
    pub fn validate(&self) -> Result<(), InputError> {
        let finite = |field, value: f64| {
            if value.is_finite() {
                Ok(())
            } else {
                Err(InputError::Parameter {
                    field,
                    value,
                    rule: "must be finite",
                })
            }
        };
        match self {
            TimeFunction::Step {
                start,
                value_at_start,
            } => {
                finite("start", *start)?;
                finite("value_at_start", *value_at_start)
            }
            TimeFunction::Ramp { start, rise } => {
                finite("start", *start)?;
                crate::model::mesh::positive("rise", *rise)
            }
            TimeFunction::Pulse { start, duration } => {
                finite("start", *start)?;
                crate::model::mesh::positive("duration", *duration)
            }
            TimeFunction::Table { times, values } => {
                if times.is_empty() || times.len() != values.len() {
                    return Err(InputError::LoadTableShape {
                        times: times.len(),
                        values: values.len(),
                    });
                }
                for (i, (&t, &v)) in times.iter().zip(values).enumerate() {
                    finite("table time", t)?;
                    finite("table value", v)?;
                    if i > 0 && t <= times[i - 1] {
                        return Err(InputError::Parameter {
                            field: "table time",
                            value: t,
                            rule: "must be greater than the previous table time",
                        });
                    }
                }
                Ok(())
            }
        }
    }
}

/// Which end of the bar.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// The end at node 0.
    Left,
    /// The end at node N.
    Right,
}

/// A load as the user states it.
#[derive(Debug, Clone, PartialEq)]
pub enum Load {
    /// Nodal force `F(t) = magnitude * f(t)` on one node (positive along +x).
    Force {
        /// Node index.
        node: usize,
        /// Force magnitude.
        magnitude: f64,
        /// Time function `f(t)`.
        time: TimeFunction,
    },
    /// End traction `sigma(end, t) = stress * f(t)` (positive in tension).
    Traction {
        /// Which end.
        end: End,
        /// Stress magnitude.
        stress: f64,
        /// Time function `f(t)`.
        time: TimeFunction,
    },
}

/// A load resolved to one node: `F(t) = magnitude * time.value(t)`.
#[derive(Debug, Clone, PartialEq)]
pub struct NodalLoad {
    /// Node index.
    pub node: usize,
    /// Force magnitude (along +x).
    pub magnitude: f64,
    /// Time function.
    pub time: TimeFunction,
}

impl NodalLoad {
    /// The force at time `t`.
    pub fn force(&self, t: f64) -> f64 {
        self.magnitude * self.time.value(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heaviside_is_one_at_zero_and_pulse_is_right_open() {
        assert_eq!(TimeFunction::HEAVISIDE.value(0.0), 1.0);
        assert_eq!(TimeFunction::HEAVISIDE.value(-1e-300), 0.0);
        let p = TimeFunction::Pulse {
            start: 0.0,
            duration: 0.5,
        };
        assert_eq!(p.value(0.0), 1.0);
        assert_eq!(p.value(0.5), 0.0);
    }

    #[test]
    fn ramp_and_table_interpolate_linearly() {
        let r = TimeFunction::Ramp {
            start: 1.0,
            rise: 2.0,
        };
        assert_eq!(r.value(2.0), 0.5);
        assert_eq!(r.value(5.0), 1.0);
        let t = TimeFunction::Table {
            times: vec![0.0, 1.0, 3.0],
            values: vec![0.0, 2.0, -2.0],
        };
        assert_eq!(t.value(0.5), 1.0);
        assert_eq!(t.value(2.0), 0.0);
        assert_eq!(t.value(9.0), -2.0);
        assert_eq!(t.value(-9.0), 0.0);
    }

    #[test]
    fn a_table_that_goes_back_in_time_is_refused() {
        let t = TimeFunction::Table {
            times: vec![0.0, 1.0, 1.0],
            values: vec![0.0; 3],
        };
        assert!(
            t.validate()
                .unwrap_err()
                .to_string()
                .contains("greater than the previous")
        );
    }
}
