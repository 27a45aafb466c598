//! Source of truth: 1D wave theory for a step-loaded bar (unit bar, E = rho = A = 1, c = 1,
//! force F0 = 1 at the free end x = 0 from t = 0 with H(0) = 1, fixed at x = 1): the velocity at
//! x = 1/2 is exactly `v = F0/(rho c A) H(t - 1/2)` until the reflection returns at t = 3/2;
//! and an independent numpy implementation of the Noh-Bathe scheme (the same equations, the
//! research note's verify.py §6), which gave max v = 1.1136 and min v (t > 0.6) = 0.9996 at
//! c dt/h = 1.85, p = 0.54, N = 100, 65 steps.
//!
//! ```text
//!   F0 H(t) --> o---o---o--- ... o(x = 1/2) ... ---o //
//!   v(1/2, t) = H(t - 1/2)          (front at t = 1/2; reflection back at t = 3/2)
//! ```
//!
//! Proves: lumped central difference at c dt/h = 1 is exact at x = 1/2 (to 1e-13) and rings at
//! 0.5; Noh-Bathe near its bifurcation (c dt/h = 1.85: the highest mode at Omega = 3.70, close
//! to 2/p where it is damped most) leaves one overshoot of 11 % and no trailing oscillation
//! (v stays within [0.9995, 1.0009] after t = 0.6), and reproduces the independent
//! implementation's numbers to 5e-4; at c dt/h = 1 it still rings (its top mode is barely
//! damped there), so its benefit needs the large step.

use crate::common;

use common::run;
use courant_solver::schemes::noh_bathe::NohBatheScheme;
use courant_solver::{
    Bar, CentralDifference, InitialConditions, Integration, Load, MassKind, Mesh, Model,
    OutputRequest, Supports, TimeFunction,
};
use std::sync::Arc;

const N: usize = 100;
const MID: usize = N / 2;

fn bar() -> Model {
    let bar = Bar::homogeneous(Mesh::uniform(1.0, N).unwrap(), 1.0, 1.0, 1.0).unwrap();
    let load = Load::Force {
        node: 0,
        magnitude: 1.0,
        time: TimeFunction::HEAVISIDE,
    };
    Model::new(
        bar,
        Supports::FREE_FIXED,
        &[load],
        InitialConditions::default(),
    )
    .unwrap()
}

/// `(max v, min v for t > 0.6, total variation)` of the velocity at x = 1/2 up to t = 1.2, and
/// its max for t > 0.6.
fn velocity_at_mid(integration: &Integration) -> (f64, f64, f64, f64) {
    let dt = integration.dt;
    let steps = (1.2 / dt).round() as usize;
    let out = run(integration, &bar(), steps, &[MID]).unwrap();
    let v: Vec<(f64, f64)> = out.histories[0]
        .samples
        .iter()
        .map(|s| (s.time, s.velocity))
        .collect();
    let max = v.iter().map(|s| s.1).fold(f64::MIN, f64::max);
    let min_after = v
        .iter()
        .filter(|s| s.0 > 0.6)
        .map(|s| s.1)
        .fold(f64::MAX, f64::min);
    let max_after = v
        .iter()
        .filter(|s| s.0 > 0.6)
        .map(|s| s.1)
        .fold(f64::MIN, f64::max);
    let variation = v.windows(2).map(|w| (w[1].1 - w[0].1).abs()).sum();
    (max, min_after, variation, max_after)
}

fn at_courant(scheme: Arc<dyn courant_solver::Scheme>, courant: f64) -> Integration {
    Integration::new(courant / N as f64, scheme)
}

#[test]
fn noh_bathe_near_its_bifurcation_leaves_one_overshoot_and_no_trailing_oscillation() {
    let h = 1.0 / N as f64;
    let cd = |co: f64| CentralDifference::new(co * h).integration();
    // Central difference: exact at Co = 1, ringing at 0.5.
    let (max, min, variation, _) = velocity_at_mid(&cd(1.0));
    assert!(
        (max - 1.0).abs() < 1e-13 && (min - 1.0).abs() < 1e-13,
        "{max} {min}"
    );
    assert!((variation - 1.0).abs() < 1e-12);
    let (_, min, variation, _) = velocity_at_mid(&cd(0.5));
    assert!(min < 0.9 && variation > 5.0, "CD at 0.5: {min} {variation}");

    let nb = Arc::new(NohBatheScheme { p: 0.54 });
    let (max, min, variation, max_after) = velocity_at_mid(&at_courant(nb.clone(), 1.85));
    assert!((max - 1.1136).abs() < 5e-4, "max v {max}");
    assert!(
        (min - 0.9996).abs() < 5e-4 && min >= 0.9995,
        "min v after 0.6: {min}"
    );
    assert!(max_after <= 1.0009, "max v after 0.6: {max_after}");
    assert!(variation < 1.3, "total variation {variation}");
    // At Co = 1 its highest mode (Omega = 2) keeps 97 % per step: it rings.
    let (_, min, variation, _) = velocity_at_mid(&at_courant(nb, 1.0));
    assert!(min < 0.95 && variation > 2.5, "NB at 1: {min} {variation}");
}

#[test]
fn the_consistent_mass_runs_to_its_own_limit() {
    // With CMM omega_max = 2 sqrt(3) c/h: the Noh-Bathe limit is c dt/h = 1.8725/sqrt(3) = 1.081.
    let nb = Integration {
        mass: MassKind::Consistent,
        ..Integration::new(1.07 / N as f64, Arc::new(NohBatheScheme { p: 0.54 }))
    };
    let (max, min, _, _) = velocity_at_mid(&nb);
    // The independent implementation: max 1.0267, min (t > 0.6) 0.9798.
    assert!(
        (max - 1.0267).abs() < 5e-4 && (min - 0.9798).abs() < 5e-4,
        "{max} {min}"
    );
    let above = Integration {
        dt: 1.09 / N as f64,
        ..nb
    };
    assert!(above.run(&bar(), 10, &OutputRequest::default()).is_err());
}
