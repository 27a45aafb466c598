//! Source of truth: the stability limit of central difference, dt_crit = 2/omega_max (seed
//! eq. 5; Hughes, The Finite Element Method, §9.1), with omega_max of the lumped free-fixed bar
//! in closed form, (2c/h) cos(pi/(4N)), so Co_crit = 1/cos(pi/(4N)) slightly above 1.
//!
//! Proves: a step above the critical step is refused before anything runs, with dt, dt_crit and
//! the controlling element in the error; an allowed run at 1.01 x dt_crit blows up and is
//! stopped with a typed error naming the step, the node and the energy ratio, keeping what it
//! recorded; a run at 0.99 x dt_crit stays bounded for 100 transits.

use crate::common;

use common::fig1_model;
use courant_solver::{CentralDifference, CriticalStep, OutputRequest, RunError, TimeFunction};

const N: usize = 100;

fn critical() -> CriticalStep {
    CriticalStep::lumped(&fig1_model(N, TimeFunction::HEAVISIDE)).unwrap()
}

#[test]
fn critical_courant_number_is_the_closed_form() {
    let c = critical();
    let closed_form = 1.0 / (std::f64::consts::PI / (4.0 * N as f64)).cos();
    let h = 1.0 / N as f64;
    assert!(
        (c.exact / h - closed_form).abs() < 1e-13,
        "{} vs {closed_form}",
        c.exact / h
    );
    assert!((c.element - h).abs() < 1e-15 && c.gershgorin <= c.exact && c.element <= c.exact);
}

#[test]
fn a_step_above_the_critical_step_is_refused_with_its_context() {
    let model = fig1_model(N, TimeFunction::HEAVISIDE);
    let dt = 1.001 * critical().exact;
    let err = CentralDifference::new(dt)
        .run(&model, 10, &OutputRequest::default())
        .unwrap_err();
    let RunError::Unstable(e) = &err else {
        panic!("expected a refusal, got {err}")
    };
    assert_eq!(e.dt, dt);
    assert_eq!(e.dt_crit, critical().exact);
    assert!(e.element < N);
    let msg = err.to_string();
    assert!(
        msg.contains("exceeds the critical step") && msg.contains("allow_unstable"),
        "{msg}"
    );
}

#[test]
fn an_allowed_unstable_run_is_stopped_at_the_blow_up_with_step_node_and_energy_ratio() {
    let model = fig1_model(N, TimeFunction::HEAVISIDE);
    let dt = 1.01 * critical().exact;
    let integrator = common::cd_allowing_unstable(dt);
    let request = OutputRequest {
        profile_steps: vec![10, 100_000],
        history_nodes: vec![0],
        ..Default::default()
    };
    let err = integrator.run(&model, 100_000, &request).unwrap_err();
    let RunError::Diverged { error, partial } = err else {
        panic!("expected a divergence")
    };
    assert!(
        error.step > 10 && error.step < 100_000,
        "diverged at step {}",
        error.step
    );
    assert!(
        error.energy_ratio > 1e6,
        "energy ratio {}",
        error.energy_ratio
    );
    assert!(error.node <= N);
    assert!((error.courant - 1.01 * critical().exact * N as f64).abs() < 1e-9);
    // Everything up to the blow-up is kept: the early profile, the history up to that step.
    assert_eq!(partial.steps, error.step);
    assert_eq!(partial.profiles.len(), 1);
    assert_eq!(partial.histories[0].samples.len(), error.step);
    assert!(
        partial.histories[0]
            .samples
            .iter()
            .all(|s| s.displacement.is_finite())
    );
}

#[test]
fn a_run_just_below_the_critical_step_stays_bounded_for_a_hundred_transits() {
    let model = fig1_model(N, TimeFunction::HEAVISIDE);
    let dt = 0.99 * critical().exact;
    let steps = (100.0 / dt) as usize;
    let out = CentralDifference::new(dt)
        .run(
            &model,
            steps,
            &OutputRequest {
                energy_every: 1000,
                ..Default::default()
            },
        )
        .unwrap();
    assert_eq!(out.steps, steps);
    // The work of a step load on this bar stays below 2 |sigma0|^2 A L / E, so does the energy.
    let max_mechanical = out
        .energy
        .samples
        .iter()
        .map(|s| s.kinetic + s.strain)
        .fold(0.0, f64::max);
    assert!(
        max_mechanical <= 2.0 + 1e-9,
        "mechanical energy reached {max_mechanical}"
    );
    assert!(out.energy.relative_balance_error() < 1e-12);
}
