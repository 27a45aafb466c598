//! Choosing the time step so that every output time is hit exactly (methods.md §1), or keeping
//! a given step exactly and snapping the output times to it ([`plan_keeping_step`]).
//!
//! The output times (and the end time) must be integer multiples of a common interval `tau`.
//! With the nominal step `dt_0` (from a Courant number or given directly),
//! `n = ceil(tau/dt_0 (1 - 1e-9))` and `dt = tau/n`: never larger than `dt_0` (rounding to
//! nearest could push Co = 1 above 1), and the relative slack keeps `tau/dt_0 = 50` from becoming
//! 51 through round-off (which would give Co_eff = N/(N+1) and break Co = 1 exactness).

use crate::error::InputError;

/// Relative slack of the step-count rounding (methods.md §1).
pub const ROUNDING_SLACK: f64 = 1e-9;

/// A time-step plan.
#[derive(Debug, Clone, PartialEq)]
pub struct TimePlan {
    /// The step, `dt <= dt_0`.
    pub dt: f64,
    /// Total number of steps to the end time.
    pub steps: usize,
    /// The step index of each output time, in the order given.
    pub output_steps: Vec<usize>,
}

/// Plan a run of nominal step `nominal_dt` to `end_time` that lands exactly on `output_times`
/// (each in `[0, end_time]`).
///
/// The common interval `tau` is the greatest common divisor of the end and output times
/// (Euclid within a tolerance of 1e-9 of the smallest time, so decimal inputs like 0.3 work),
/// snapped so that the end time is an exact multiple of it. Then, as in methods.md §1,
/// `dt = tau / ceil(tau/dt_0 (1 - 1e-9))`: `dt` exceeds `dt_0` by at most the relative slack
/// [`ROUNDING_SLACK`], and only through round-off. Output times that share no common interval
/// give a small `tau`, hence a small step: the plan's `dt` and step count say so, and
/// [`MAX_STEPS`] bounds the run.
pub fn plan(nominal_dt: f64, output_times: &[f64], end_time: f64) -> Result<TimePlan, InputError> {
    validate(nominal_dt, output_times, end_time)?;
    let positive_times = || {
        output_times
            .iter()
            .copied()
            .filter(|&t| t > ROUNDING_SLACK * end_time)
    };
    let smallest = positive_times().fold(end_time, f64::min);
    let tol = (ROUNDING_SLACK * smallest).max(64.0 * f64::EPSILON * end_time);
    let tau = positive_times().try_fold(end_time, |g, t| float_gcd(g, t, tol))?;
    // Snap tau so that the end time is an exact multiple of it.
    let intervals = (end_time / tau).round().max(1.0);
    let per_interval = (end_time / intervals / nominal_dt * (1.0 - ROUNDING_SLACK))
        .ceil()
        .max(1.0);
    let steps_f = intervals * per_interval;
    if steps_f > MAX_STEPS as f64 {
        return Err(InputError::TooManyStepsThroughOutputs {
            steps: steps_f,
            dt: nominal_dt,
            end_time,
            interval: end_time / intervals,
            max: MAX_STEPS,
        });
    }
    let steps = steps_f as usize;
    let dt = end_time / steps_f;
    Ok(TimePlan {
        dt,
        steps,
        output_steps: output_times
            .iter()
            .map(|&t| (t / dt).round() as usize)
            .collect(),
    })
}

/// Plan a run that keeps the step `dt` exactly (no shrinking), for runs whose step is the point,
/// such as a step at exactly 1.00 of a critical step: the run takes `n = round(end_time/dt)`
/// steps and each output time `t` is recorded at its nearest step `round(t/dt)`. The run then
/// ends at `n dt` and each output falls at `round(t/dt) dt`, both within `dt/2` of the time asked
/// for; outputs carry the step's actual time, so references compared with them must be
/// evaluated there (the scene runner does). Refused: an end time shorter than half a step
/// (no step at all), or more than [`MAX_STEPS`] steps.
pub fn plan_keeping_step(
    dt: f64,
    output_times: &[f64],
    end_time: f64,
) -> Result<TimePlan, InputError> {
    validate(dt, output_times, end_time)?;
    let steps_f = (end_time / dt).round();
    if steps_f < 1.0 {
        return Err(InputError::EndBeforeFirstStep { end_time, dt });
    }
    if steps_f > MAX_STEPS as f64 {
        return Err(InputError::TooManySteps {
            steps: steps_f,
            dt,
            end_time,
            max: MAX_STEPS,
        });
    }
    let steps = steps_f as usize;
    Ok(TimePlan {
        dt,
        steps,
        output_steps: output_times
            .iter()
            .map(|&t| ((t / dt).round() as usize).min(steps))
            .collect(),
    })
}

/// The checks every plan makes: `dt` and the end time positive and finite, output times finite,
/// not negative and not after the end time (within the relative slack).
fn validate(dt: f64, output_times: &[f64], end_time: f64) -> Result<(), InputError> {
    crate::model::mesh::positive("dt", dt)?;
    crate::model::mesh::positive("end time", end_time)?;
    for &t in output_times {
        if !(t.is_finite() && t >= 0.0) {
            return Err(InputError::Parameter {
                field: "output time",
                value: t,
                rule: "must be finite and not negative",
            });
        }
        if t > end_time * (1.0 + ROUNDING_SLACK) {
            return Err(InputError::OutputAfterEnd { time: t, end_time });
        }
    }
    Ok(())
}

/// Largest number of steps a plan may have.
pub const MAX_STEPS: usize = 100_000_000;

/// Iteration bound of [`float_gcd`]: Euclid's remainders at least halve every two steps, so
/// from `a` down to the tolerance `tol >= 64 eps a` of [`plan`] takes at most
/// `2 log2(1/(64 eps)) < 94` steps.
const EUCLID_STEPS: usize = 128;

/// Greatest common divisor of two positive reals within an absolute tolerance (Euclid), in at
/// most [`EUCLID_STEPS`] steps.
fn float_gcd(a: f64, b: f64, tol: f64) -> Result<f64, crate::error::NoConvergence> {
    let (mut a, mut b) = (a.max(b), a.min(b));
    for _ in 0..EUCLID_STEPS {
        if b <= tol {
            return Ok(a);
        }
        let mut r = a % b;
        if b - r <= tol {
            r = 0.0;
        }
        a = b;
        b = r;
    }
    Err(crate::error::NoConvergence {
        method: "the common interval of the output times (Euclid's algorithm)",
        iterations: EUCLID_STEPS,
        why: format!("remainder {b:e} still above the tolerance {tol:e}"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn courant_one_on_a_hundred_elements_keeps_dt_exactly() {
        let p = plan(0.01, &[0.5, 1.5, 2.5, 10.5], 10.5).unwrap();
        assert_eq!(p.dt, 0.01);
        assert_eq!(p.output_steps, vec![50, 150, 250, 1050]);
        assert_eq!(p.steps, 1050);
    }

    #[test]
    fn dt_is_shrunk_never_rounded_up() {
        let p = plan(0.3, &[1.0], 1.0).unwrap();
        assert_eq!(p.steps, 4);
        assert_eq!(p.dt, 0.25);
    }

    #[test]
    fn output_times_with_a_short_common_interval_shorten_the_step() {
        let p = plan(0.01, &[0.5, 0.501], 1.0).unwrap();
        assert!((p.dt - 0.001).abs() < 1e-15, "{}", p.dt);
        assert_eq!(p.output_steps, vec![500, 501]);
        let p = plan(0.1, &[0.05], 0.05).unwrap();
        assert_eq!((p.steps, p.dt), (1, 0.05));
    }

    #[test]
    fn long_runs_with_decimal_times_never_exceed_the_nominal_step() {
        for (times, end, dt0) in [
            (vec![0.37, 0.74], 1000.0, 0.01),
            (vec![0.3], 1e4, 0.01),
            (vec![0.3], 1e5, 0.01),
        ] {
            let p = plan(dt0, &times, end).unwrap();
            assert!(
                p.dt <= dt0 * (1.0 + ROUNDING_SLACK),
                "{times:?} to {end}: dt {} > {dt0}",
                p.dt
            );
            assert!(
                p.dt >= 0.99 * dt0,
                "{times:?} to {end}: dt {} needlessly small",
                p.dt
            );
            assert!((p.steps as f64 * p.dt - end).abs() <= 1e-12 * end);
            for (&t, &n) in times.iter().zip(&p.output_steps) {
                assert!(
                    (n as f64 * p.dt - t).abs() <= 1e-12 * end,
                    "{t} missed: {}",
                    n as f64 * p.dt
                );
            }
        }
    }

    #[test]
    fn a_plan_beyond_the_step_limit_is_refused() {
        let err = plan(1e-9, &[], 1.0).unwrap_err();
        assert!(err.to_string().contains("at most 100000000"), "{err}");
    }

    /// Keeping the step: dt is returned bit for bit, the end and output times snap to their
    /// nearest steps (source of truth: the definition, n = round(t/dt)).
    #[test]
    fn keeping_the_step_snaps_times_to_the_nearest_step() {
        let dt = 0.010_000_308_433_064_905; // 2/omega_max of the N = 100 free-fixed bar
        let p = plan_keeping_step(dt, &[0.5, 1.5], 100.0).unwrap();
        assert_eq!(p.dt.to_bits(), dt.to_bits());
        assert_eq!(p.steps, 10_000); // 100/dt = 9999.69
        assert_eq!(p.output_steps, vec![50, 150]); // 49.998, 149.995
        assert!((p.steps as f64 * dt - 100.0).abs() <= 0.5 * dt);
        let p = plan_keeping_step(0.3, &[1.0], 1.0).unwrap();
        assert_eq!((p.dt, p.steps, p.output_steps), (0.3, 3, vec![3]));
    }

    /// An end time below half a step would take no step: refused, saying so.
    #[test]
    fn keeping_the_step_refuses_a_run_without_a_step() {
        let err = plan_keeping_step(1.0, &[], 0.4).unwrap_err();
        assert!(
            err.to_string().contains("shorter than half a step"),
            "{err}"
        );
        assert!(
            plan_keeping_step(1e-9, &[], 1.0)
                .unwrap_err()
                .to_string()
                .contains("at most 100000000")
        );
        assert!(
            plan_keeping_step(0.1, &[2.0], 1.0)
                .unwrap_err()
                .to_string()
                .contains("after the end time")
        );
    }

    #[test]
    fn output_after_the_end_is_refused() {
        assert!(
            plan(0.01, &[2.0], 1.0)
                .unwrap_err()
                .to_string()
                .contains("after the end time")
        );
    }
}
