//! Choosing the time step so that every output time is hit exactly (methods.md §1).
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
pub fn plan(nominal_dt: f64, output_times: &[f64], end_time: f64) -> Result<TimePlan, InputError> {
    crate::mesh::positive("dt", nominal_dt)?;
    crate::mesh::positive("end time", end_time)?;
    for &t in output_times {
        if !(t.is_finite() && t >= 0.0) {
            return Err(InputError::Parameter {
                field: "output time",
                value: t,
                rule: "must be finite and not negative",
            });
        }
        if t > end_time * (1.0 + ROUNDING_SLACK) {
            return Err(InputError::Other(format!(
                "output time {t} is after the end time {end_time}"
            )));
        }
    }
    let tol = ROUNDING_SLACK * end_time;
    let tau = output_times
        .iter()
        .filter(|&&t| t > tol)
        .fold(end_time, |g, &t| float_gcd(g, t, tol));
    if tau < nominal_dt * (1.0 - ROUNDING_SLACK) {
        return Err(InputError::Other(format!(
            "the output times and end time {end_time} share no common interval as long as the step \
             dt = {nominal_dt:e} (their largest common interval is {tau:e}); choose times that are \
             multiples of a common interval of at least one step"
        )));
    }
    let per_tau = (tau / nominal_dt * (1.0 - ROUNDING_SLACK)).ceil().max(1.0);
    let dt = tau / per_tau;
    let to_step = |t: f64| (t / dt).round() as usize;
    Ok(TimePlan {
        dt,
        steps: to_step(end_time),
        output_steps: output_times.iter().map(|&t| to_step(t)).collect(),
    })
}

/// Greatest common divisor of two positive reals within an absolute tolerance (Euclid).
fn float_gcd(a: f64, b: f64, tol: f64) -> f64 {
    let (mut a, mut b) = (a.max(b), a.min(b));
    while b > tol {
        let mut r = a % b;
        if b - r <= tol {
            r = 0.0;
        }
        a = b;
        b = r;
    }
    a
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
    fn incommensurable_output_times_are_refused() {
        let err = plan(0.01, &[0.5, 0.501], 1.0).unwrap_err();
        assert!(err.to_string().contains("no common interval"), "{err}");
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
