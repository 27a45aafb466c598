//! Source of truth: d'Alembert's solution of the free-fixed bar (methods.md §3; Graff, Wave
//! Motion in Elastic Solids, ch. 2) and the theory of lumped central difference at Courant
//! number 1 (the scheme's stencil is the exact characteristic update on a uniform mesh).
//!
//! ```text
//!   sigma0 H(t) ==> o---o---o---o--- ... ---o---o //  fixed
//!                   0   1   2   3          N-1  N
//!   Co = c dt/h = 1: the front crosses exactly one element per step
//! ```
//!
//! Proves: lumped CD at Co = 1 reproduces the exact element stresses and nodal u, v to
//! round-off through any number of reflections; the discrete light cone is sharp; the half-step
//! start with H(0) = 1 is what makes it exact (the naive three-level start is caught, and is exact
//! again with H(0) = 1/2); and the
//! energies equal the exact ones.

use crate::common;

use common::*;
use courant_solver::{Start, TimeFunction};

const TIMES: [f64; 4] = [0.5, 1.5, 2.5, 10.5];

#[test]
fn element_stresses_equal_dalembert_to_round_off_through_ten_reflections() {
    let out = run_fig1(
        100,
        1.0,
        &TIMES,
        Start::HalfStep,
        TimeFunction::HEAVISIDE,
        &[],
    );
    assert_eq!(out.steps, 1050, "dt = h exactly: 10.5 T takes 1050 steps");
    assert_eq!(out.profiles.len(), 4);
    for p in &out.profiles {
        let err = max_abs_diff(&p.stress, &exact_averages(100, p.time));
        assert!(
            err <= 1e-14 * 100.0 * 100.0,
            "t = {}: max stress error {err:e}",
            p.time
        );
    }
}

#[test]
fn exactness_holds_for_every_mesh_with_round_off_growing_like_n_squared() {
    // Even N: every output time (k + 1/2) T is then a whole number of steps at Co = 1.
    for n in [2, 6, 10, 64, 100, 334, 1000, 3000] {
        let out = run_fig1(
            n,
            1.0,
            &TIMES,
            Start::HalfStep,
            TimeFunction::HEAVISIDE,
            &[],
        );
        let tolerance = 1e-14 * (n * n) as f64;
        for p in &out.profiles {
            let err = max_abs_diff(&p.stress, &exact_averages(n, p.time));
            assert!(
                err <= tolerance,
                "N = {n}, t = {}: error {err:e} > {tolerance:e}",
                p.time
            );
        }
    }
}

#[test]
fn nodal_displacement_and_velocity_equal_dalembert_to_round_off() {
    let nodes = [0, 1, 25, 50, 99];
    let out = run_fig1(
        100,
        1.0,
        &[2.5],
        Start::HalfStep,
        TimeFunction::HEAVISIDE,
        &nodes,
    );
    let exact = fig1_exact();
    for h in &out.histories {
        assert_eq!(h.samples.len(), 251);
        // At t = 0 the recorded velocity is the initial state, v^0 = 0, not a mean over the jump.
        for s in h.samples.iter().skip(1) {
            let u_err = (s.displacement - exact.displacement(h.x, s.time)).abs();
            // Where a front sits exactly on the node, v^n is the mean of the one-sided limits.
            let v_err = (s.velocity - exact.velocity_mean(h.x, s.time)).abs();
            assert!(
                u_err <= 1e-12,
                "node {} t = {}: u error {u_err:e}",
                h.node,
                s.time
            );
            assert!(
                v_err <= 1e-10,
                "node {} t = {}: v error {v_err:e}",
                h.node,
                s.time
            );
        }
    }
}

#[test]
fn numerical_light_cone_is_sharp_stress_is_exactly_zero_ahead_of_step_n() {
    let n = 50;
    for steps in [1usize, 2, 17, 49] {
        let t = steps as f64 / n as f64;
        let out = run_fig1(n, 1.0, &[t], Start::HalfStep, TimeFunction::HEAVISIDE, &[]);
        let stress = &out.profiles[0].stress;
        assert_eq!(out.profiles[0].step, steps);
        assert!(
            stress[..steps].iter().all(|&s| s != 0.0),
            "elements behind the cone carry stress"
        );
        assert!(
            stress[steps..].iter().all(|&s| s == 0.0),
            "after {steps} steps elements >= {steps} must be exactly 0"
        );
    }
}

#[test]
fn naive_three_level_start_with_full_step_load_is_caught_and_half_load_start_is_exact() {
    let times = [0.5, 1.5];
    let half_step = run_fig1(
        100,
        1.0,
        &times,
        Start::HalfStep,
        TimeFunction::HEAVISIDE,
        &[],
    );
    let naive = run_fig1(
        100,
        1.0,
        &times,
        Start::ThreeLevel,
        TimeFunction::HEAVISIDE,
        &[],
    );
    let half_load = TimeFunction::Step {
        start: 0.0,
        value_at_start: 0.5,
    };
    let corrected = run_fig1(100, 1.0, &times, Start::ThreeLevel, half_load, &[]);
    for (i, &t) in times.iter().enumerate() {
        let exact = exact_averages(100, t);
        assert!(max_abs_diff(&half_step.profiles[i].stress, &exact) < 1e-10);
        assert!(max_abs_diff(&corrected.profiles[i].stress, &exact) < 1e-10);
        // The full load at t = 0 doubles the first velocity increment of the loaded node. At
        // Co = 1 that extra impulse travels undispersed as a saw-tooth: every stress error is
        // exactly 0 or +-|sigma0|, and half the bar is wrong by |sigma0| (measured: 50 of 100
        // elements at both times).
        let errors: Vec<f64> = naive.profiles[i]
            .stress
            .iter()
            .zip(&exact)
            .map(|(s, e)| s - e)
            .collect();
        assert!(
            errors
                .iter()
                .all(|e| e.abs() < 1e-10 || (e.abs() - 1.0).abs() < 1e-10),
            "t = {t}: {errors:?}"
        );
        let wrong = errors.iter().filter(|e| e.abs() > 0.5).count();
        assert!(wrong >= 25, "t = {t}: only {wrong} elements wrong");
    }
}

#[test]
fn work_and_strain_energy_equal_exact_and_staggered_kinetic_energy_closes_the_balance() {
    let out = run_fig1(
        100,
        1.0,
        &TIMES,
        Start::HalfStep,
        TimeFunction::HEAVISIDE,
        &[],
    );
    let exact = fig1_exact();
    let first = out.energy.samples[0];
    for s in out.energy.samples.iter().skip(1) {
        let e = exact.energies(s.time);
        let scale = out.energy.scale;
        assert!(
            (s.work - e.work).abs() <= 1e-12 * scale,
            "t = {}: work {} vs {}",
            s.time,
            s.work,
            e.work
        );
        assert!(
            (s.strain - e.strain).abs() <= 1e-12 * scale,
            "t = {}: strain {} vs {}",
            s.time,
            s.strain,
            e.strain
        );
        // The conserved CD energy carries the start-up offset 1/2 v^{-1/2} M v^{1/2} = -dt^2/8 a0 M a0.
        let kinetic = s.kinetic_staggered - first.kinetic_staggered;
        assert!(
            (kinetic - e.kinetic).abs() <= 1e-12 * scale,
            "t = {}: kinetic {kinetic} vs {}",
            s.time,
            e.kinetic
        );
    }
    assert!(
        out.energy.relative_balance_error() < 1e-14,
        "balance {:e}",
        out.energy.relative_balance_error()
    );
}
