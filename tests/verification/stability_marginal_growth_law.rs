//! Source of truth: the double-root law at the stability limit (methods.md §2, "At the limit"):
//! at `dt = dt_crit = 2/omega_max` lumped central difference's critical mode has the double
//! eigenvalue `-1`, so the energy grows at most like `n^2`; above it an eigenvalue of modulus
//! above 1 grows exponentially. omega_max of the lumped free-fixed bar is computed exactly
//! (Sturm bisection, Hughes 2000, §9.3).
//!
//! Proves: a step-loaded free-fixed bar (N = 100) run exactly at `2/omega_max` for 20 000 steps,
//! its energy logged every step, has a growth exponent over its last doubling of at most 2 and
//! is within the law; the same bar at 1.001 `dt_crit` grows exponentially, is stopped by the
//! guard and is beyond the law.

use crate::common;

use common::fig1_model;
use courant::compare::growth::time_stepping_growth;
use courant_solver::{CriticalStep, OutputRequest, RunError, TimeFunction};

const N: usize = 100;
const STEPS: usize = 20_000;

fn run(ratio: f64) -> Result<courant_solver::RunOutput, RunError> {
    let model = fig1_model(N, TimeFunction::HEAVISIDE);
    let dt = ratio * CriticalStep::lumped(&model).unwrap().exact;
    let integrator = common::cd_allowing_unstable(dt);
    let request = OutputRequest {
        energy_every: 1,
        ..Default::default()
    };
    integrator.run(&model, STEPS, &request)
}

#[test]
fn at_the_limit_the_energy_grows_within_the_double_root_law() {
    let out = run(1.0).expect("a run at the limit completes");
    assert_eq!(out.steps, STEPS);
    let growth = time_stepping_growth(&out.energy, None).unwrap();
    let (p, max) = growth.exponent.expect("20 000 samples measure an exponent");
    assert!(p <= 2.0, "p = {p}");
    // The law's closed form at n = 20 000, k = 1 (methods.md §2):
    // log2(1 + (60 002 / 19 998)^2) = 3.32227...
    assert!((max - 3.322_27).abs() < 1e-5, "law {max}");
    assert!(growth.within_law(), "{growth:?}");
}

#[test]
fn above_the_limit_the_energy_grows_beyond_the_double_root_law() {
    let Err(RunError::Diverged { error, partial }) = run(1.001) else {
        panic!("1.001 dt_crit is stopped by the guard")
    };
    let growth =
        time_stepping_growth(&partial.energy, Some((error.step, error.energy_ratio))).unwrap();
    assert!(
        !growth.within_law(),
        "{growth:?}, caught at step {}",
        error.step
    );
    let (p, max) = growth.exponent.expect("every step logged");
    assert!(
        p > 2.0 * max,
        "p = {p}: exponential growth, far beyond the law {max}"
    );
}
