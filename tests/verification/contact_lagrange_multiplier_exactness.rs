//! Source of truth: the exact contact force of 1D impact (`courant_references::contact::
//! ImpactForce`, wave tracking; methods.md §7) and methods.md §4: lumped central difference at
//! Co = 1 is exact for piecewise-constant layers with interfaces at nodes. While the forward
//! increment Lagrange multiplier method (Carpenter, Taylor and Katona 1991) holds the gap at 0,
//! the two contact half-nodes move as one node of the welded chain, which is such a layered bar.
//!
//! ```text
//!   equal impedance (seed Fig. 4):  striker L1 = 1, E = rho = 1  |  target L2 = 2, E = rho = 1
//!   staircase:                       striker L1 = 3, E = rho = 1  |  target L2 = 1, E = rho = 4
//!   (equal wave speeds c = 1 and equal h: both bars at Co = 1 with one dt; Z2 = 4 Z1)
//! ```
//!
//! Proves, at Co = 1:
//! - equal impedance: the force is Z v0/2 at every level of the contact, the level on the jump
//!   at 2 L1/c carries the mean Z v0/4 of its two sides (the discrete force is the exact one
//!   averaged with a hat function over [t^{n-1}, t^{n+1}]; the start level spans [0, dt/2]),
//!   zero after, all to round-off; the impulse is rho A L1 v0 to round-off and equals the
//!   target's momentum gain; the ends touch at zero force until 2 L2/c and only then part;
//! - unequal impedance: the staircase F = 0.8, 0.48, 0.288 (Z1 v0 = 1) on [0, 2), [2, 4),
//!   [4, 6) is reproduced to round-off at every level, interior jumps included, except the
//!   release level: the forward increment method cannot anticipate the release, so the level
//!   on which the exact force drops to zero delivers nothing instead of the mean half plateau,
//!   and the impulse falls short by exactly F_last dt/2 (an O(h) deficit).

use courant_references::contact::{ImpactBar, ImpactForce};
use courant_solver::contact::{
    ContactIntegrator, ContactProblem, ContactRequest, ContactRun, ContactScheme,
};
use courant_solver::{Bar, Mesh};

/// Per-unit-length element count; dt = h/c = 1/N.
const N: usize = 20;

fn bar(length: f64, modulus_and_density: f64) -> Bar {
    let elements = (length * N as f64).round() as usize;
    Bar::homogeneous(
        Mesh::uniform(length, elements).unwrap(),
        modulus_and_density,
        modulus_and_density,
        1.0,
    )
    .unwrap()
}

fn exact(l1: f64, rho1: f64, l2: f64, rho2: f64) -> ImpactForce {
    let b = |l, rho| ImpactBar::from_material(rho, rho, 1.0, l).unwrap();
    ImpactForce::new(b(l1, rho1), b(l2, rho2), 1.0).unwrap()
}

fn run(l1: f64, rho1: f64, l2: f64, rho2: f64, end: f64) -> ContactRun {
    let problem = ContactProblem::bar_impact(bar(l1, rho1), bar(l2, rho2), 1.0, 0.0).unwrap();
    let dt = 1.0 / N as f64;
    ContactIntegrator::new(dt, ContactScheme::LagrangeMultiplier)
        .run(
            &problem,
            (end / dt).round() as usize,
            &ContactRequest::default(),
        )
        .unwrap()
}

/// The exact force averaged with the level's hat: `F(0+)` at the start, else the mean of the
/// two sides (plateau boundaries fall on levels at Co = 1).
fn hat_mean(exact: &ImpactForce, step: usize, t: f64) -> f64 {
    let dt = 1.0 / N as f64;
    let after = exact.force(t + 1e-6 * dt);
    if step == 0 {
        after
    } else {
        0.5 * (exact.force(t - 1e-6 * dt) + after)
    }
}

#[test]
fn equal_impedance_force_and_impulse_are_exact_at_courant_one() {
    let exact = exact(1.0, 1.0, 2.0, 1.0);
    let run = run(1.0, 1.0, 2.0, 1.0, 5.0);
    assert!((run.courant - 1.0).abs() < 1e-12);
    for s in &run.history {
        let expected = hat_mean(&exact, s.step, s.time);
        assert!(
            (s.force - expected).abs() < 1e-12,
            "t = {}: {} vs {expected}",
            s.time,
            s.force
        );
        // Touching (gap 0 to round-off) until the target's pulse returns at 2 L2/c = 4.
        if s.time <= 4.0 + 1e-9 {
            assert!(s.gap.abs() < 1e-13, "t = {}: gap {}", s.time, s.gap);
        } else {
            assert!(s.gap > 0.0);
        }
    }
    let level = |t: f64| run.history[(t * N as f64).round() as usize].force;
    for (t, f) in [(0.0, 0.5), (1.0, 0.5), (2.0, 0.25), (3.0, 0.0)] {
        assert!((level(t) - f).abs() < 1e-12, "t = {t}: {}", level(t));
    }
    assert!(
        (run.impulse - exact.impulse()).abs() < 1e-13,
        "{}",
        run.impulse
    );
    let gain = run.final_momentum[1] - run.initial_momentum[1];
    assert!((gain - run.impulse).abs() < 1e-14);
    assert!(exact.separation_time() == 4.0);
}

#[test]
fn unequal_impedance_staircase_is_exact_at_courant_one_except_the_release_level() {
    let exact = exact(3.0, 1.0, 1.0, 4.0);
    let plateaus: Vec<(f64, f64, f64)> = exact
        .plateaus()
        .iter()
        .map(|p| (p.start, p.end, p.force))
        .collect();
    assert_eq!(
        plateaus,
        vec![(0.0, 2.0, 0.8), (2.0, 4.0, 0.48), (4.0, 6.0, 0.288)],
        "Z1 Z2 v0/(Z1 + Z2), then x (Z2 - Z1)/(Z1 + Z2) per round trip in the target"
    );
    let run = run(3.0, 1.0, 1.0, 4.0, 8.0);
    let release = (exact.duration() * N as f64).round() as usize;
    for s in &run.history {
        let expected = if s.step == release {
            0.0
        } else {
            hat_mean(&exact, s.step, s.time)
        };
        assert!(
            (s.force - expected).abs() < 1e-12,
            "t = {}: {} vs {expected}",
            s.time,
            s.force
        );
    }
    let deficit = 0.5 * 0.288 / N as f64;
    assert!(
        (run.impulse - (exact.impulse() - deficit)).abs() < 1e-12,
        "impulse {} vs {} - {deficit}",
        run.impulse,
        exact.impulse()
    );
    let gain = run.final_momentum[1] - run.initial_momentum[1];
    assert!((gain - run.impulse).abs() < 1e-13);
}
