//! Source of truth: the semi-discrete solution of a single mode of the uniform fixed-free bar
//! (`u_j(t) = cos(k x_j) cos(omega_h t)`, `omega_h h/c = 2 s` for LMM and
//! `2 s/sqrt(1 - 2 s^2/3)` for CMM, `s = sin(kh/2)`, methods.md §5), the Noh-Bathe stability
//! limit `dt_crit = Omega_crit(p)/omega_max` with `Omega_crit = 2/sqrt((1-p)(3p-1))` and its
//! modified energy (derived for courant; module docs of `courant_solver::schemes::noh_bathe`).
//!
//! ```text
//!   free o---o---o--- ... ---o fixed      u(x, 0) = cos(k x) (one mode) or a rough field
//!   x = 0                    x = 1
//! ```
//!
//! Proves: (1) second order in time for u and v with the lumped and the consistent mass
//! (observed orders in [1.9, 2.1]); (2) on a graded, loaded bar with each mass the run stays
//! bounded for 20000 steps at 0.999 of the limit and the guard catches it at 1.001, and without
//! `allow_unstable` a step above the limit is refused naming `Omega_crit(p)/omega_max`;
//! (3) in free vibration the modified energy never increases, while the physical energy does
//! in some steps, and a single mode's modified energy decays by exactly `det A` per step;
//! (4) the measured critical step of the interface's fallback
//! (`integrator::measure_critical_step`) finds the closed-form limits of Noh-Bathe and central
//! difference to its stated precision.

use crate::common;

use common::{determinant, free_bar, noh_bathe, run};
use courant_solver::bench::graded_seed_bar;
use courant_solver::integrator::{MEASURED_PRECISION, measure_critical_step};
use courant_solver::schemes::central_difference::CentralDifferenceScheme;
use courant_solver::schemes::noh_bathe::NohBatheScheme;
use courant_solver::{CriticalStep, MassKind, MassOperator, Model, RunError, Scheme};
use std::f64::consts::PI;
use std::sync::Arc;

const P: f64 = 0.54;

/// `(exact dt, 2/omega_max)` of `model` with `mass`: Noh-Bathe's limit and central difference's.
fn limits(model: &Model, mass: MassKind) -> (f64, f64) {
    let critical = CriticalStep::of(model, mass, &MassOperator::new(model, mass).unwrap()).unwrap();
    let limit = NohBatheScheme { p: P }.limit(model, &critical);
    (limit.dt(), critical.exact)
}

#[test]
fn second_order_in_displacement_and_velocity_for_lumped_and_consistent_mass() {
    let n = 20;
    let h = 1.0 / n as f64;
    let k = PI / 2.0; // first fixed-free mode: cos(k x), zero at x = 1
    let s = (0.5 * k * h).sin();
    let mode: Vec<f64> = (0..=n).map(|j| (k * j as f64 * h).cos()).collect();
    for (mass, omega) in [
        (MassKind::Lumped, 2.0 * s / h),
        (
            MassKind::Consistent,
            2.0 * s / (1.0 - 2.0 * s * s / 3.0).sqrt() / h,
        ),
    ] {
        let model = free_bar(n, mode.clone());
        // omega t near pi/4 at the end: a phase error shows in both u and v.
        let end = 0.5;
        let mut errors = Vec::new();
        for steps in [20, 40, 80, 160, 320] {
            let dt = end / steps as f64;
            let out = run(&noh_bathe(P, dt, mass, false), &model, steps, &[0]).unwrap();
            let last = out.histories[0].samples.last().unwrap();
            let t = steps as f64 * dt;
            errors.push((
                (last.displacement - (omega * t).cos()).abs(),
                (last.velocity + omega * (omega * t).sin()).abs(),
            ));
        }
        for w in errors.windows(2) {
            let (order_u, order_v) = ((w[0].0 / w[1].0).log2(), (w[0].1 / w[1].1).log2());
            assert!(
                (1.9..=2.1).contains(&order_u),
                "{mass:?}: order u {order_u} ({errors:?})"
            );
            assert!(
                (1.9..=2.1).contains(&order_v),
                "{mass:?}: order v {order_v} ({errors:?})"
            );
        }
    }
}

#[test]
fn bounded_at_0_999_of_the_limit_caught_at_1_001_refused_above_it() {
    let model = graded_seed_bar(20).unwrap();
    for mass in [MassKind::Lumped, MassKind::Consistent] {
        let (dt_crit, cd) = limits(&model, mass);
        assert!((dt_crit / cd - 0.5 * NohBatheScheme::critical_omega(P)).abs() < 1e-12);
        let bounded = run(
            &noh_bathe(P, 0.999 * dt_crit, mass, true),
            &model,
            20_000,
            &[],
        );
        let out = bounded.unwrap_or_else(|e| panic!("{mass:?} at 0.999: {e}"));
        let peak = out
            .energy
            .samples
            .iter()
            .map(|s| s.kinetic + s.strain)
            .fold(0.0, f64::max);
        let work = out
            .energy
            .samples
            .iter()
            .map(|s| s.work.abs())
            .fold(0.0, f64::max);
        assert!(
            peak <= 2.0 * work,
            "{mass:?}: T + U = {peak} against the work {work}"
        );
        match run(
            &noh_bathe(P, 1.001 * dt_crit, mass, true),
            &model,
            20_000,
            &[],
        ) {
            Err(RunError::Diverged { error, .. }) => assert!(error.step < 20_000),
            other => panic!("{mass:?} at 1.001: not caught: {other:?}"),
        }
        match run(&noh_bathe(P, 1.001 * dt_crit, mass, false), &model, 10, &[]) {
            Err(RunError::Unstable(e)) => {
                assert_eq!(e.limit, "Omega_crit(p)/omega_max");
                assert_eq!(e.dt_crit, dt_crit);
            }
            other => panic!("{mass:?}: not refused: {other:?}"),
        }
    }
}

#[test]
fn the_modified_energy_never_increases_in_free_vibration() {
    let n = 50;
    // A rough field (every mode), zero at the fixed node.
    let rough: Vec<f64> = (0..=n)
        .map(|j| {
            if j == n {
                0.0
            } else {
                (0.37 * j as f64).sin() + 0.5 * (1.9 * j as f64).cos()
            }
        })
        .collect();
    let model = free_bar(n, rough);
    for mass in [MassKind::Lumped, MassKind::Consistent] {
        let (_, cd) = limits(&model, mass);
        // E_mod is positive definite below Omega_max = 2/p, i.e. dt < (2/p)/omega_max.
        for fraction in [0.25, 0.5, 0.99] {
            let dt = fraction * (2.0 / P) * (cd / 2.0);
            let out = run(&noh_bathe(P, dt, mass, false), &model, 400, &[]).unwrap();
            let e = &out.energy.samples;
            let modified: Vec<f64> = e.iter().map(|s| s.kinetic_staggered + s.strain).collect();
            let physical: Vec<f64> = e.iter().map(|s| s.kinetic + s.strain).collect();
            for w in modified.windows(2) {
                assert!(
                    w[1] <= w[0] * (1.0 + 1e-13),
                    "{mass:?}, {fraction}: {} -> {}",
                    w[0],
                    w[1]
                );
            }
            assert!(modified[400] < modified[0] && modified[400] > 0.0);
            let rises = physical.windows(2).filter(|w| w[1] > w[0]).count();
            assert!(
                rises > 10,
                "{mass:?}, {fraction}: T + U rose in only {rises} steps"
            );
        }
    }
    // One mode: E_mod(n) = det(A(Omega_h))^n E_mod(0).
    let k = 3.0 * PI / 2.0;
    let h = 1.0 / n as f64;
    let model = free_bar(n, (0..=n).map(|j| (k * j as f64 * h).cos()).collect());
    let omega = 2.0 * (0.5 * k * h).sin() / h;
    let dt = 0.9 * (2.0 / P) / (2.0 / h);
    let out = run(&noh_bathe(P, dt, MassKind::Lumped, false), &model, 100, &[]).unwrap();
    let e = &out.energy.samples;
    let factor = determinant(omega * dt, P);
    for s in e {
        let expected = factor.powi(s.step as i32) * (e[0].kinetic_staggered + e[0].strain);
        let got = s.kinetic_staggered + s.strain;
        assert!(
            (got - expected).abs() <= 1e-10 * expected,
            "step {}: {got} vs {expected}",
            s.step
        );
    }
}

#[test]
fn the_measured_critical_step_finds_the_closed_form_limits() {
    let model = graded_seed_bar(12).unwrap();
    for mass in [MassKind::Lumped, MassKind::Consistent] {
        let (nb, cd) = limits(&model, mass);
        for (scheme, exact) in [
            (Arc::new(NohBatheScheme { p: P }) as Arc<dyn Scheme>, nb),
            (Arc::new(CentralDifferenceScheme) as Arc<dyn Scheme>, cd),
        ] {
            // A guess well below both limits: the search must bracket and bisect to find them.
            let measured = measure_critical_step(&scheme, &model, mass, 0.3 * cd).unwrap();
            let ratio = measured / exact;
            assert!(
                (1.0 - MEASURED_PRECISION..=1.0 + 1e-12).contains(&ratio),
                "{} {mass:?}: measured {measured} vs exact {exact} ({ratio})",
                scheme.label()
            );
        }
    }
}
