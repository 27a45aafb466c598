//! A graded striker (E linear from 1 to 16 toward the contact, rho = A = 1, length 1, v0 = 1)
//! onto a graded target (E linear from 16 at the contact to 1, length 2), gap 0: the combined
//! schemes converge to a fine-mesh reference.
//!
//! Source of truth: fine-mesh convergence, stated: no exact solution is known for graded bars in
//! contact, so the reference is central difference with the lumped mass and the Lagrange
//! multiplier (the exact-constraint scheme) on 256 elements per unit length at Co 0.9; the error
//! is the L1 over [0, 3] of the cumulative contact impulse (the target's momentum, exact for
//! the discrete scheme) over the reference's. Proves: Park-LTS with the bipenalty (r = 1,
//! beta_s = 1e4) and CD-RMM(1/2) with the Lagrange multiplier converge to it as the mesh is
//! refined (8 to 64 elements per unit length); and measures the bipenalty's chatter (finding).

use courant_solver::contact::combined::{BulkScheme, CombinedStepper};
use courant_solver::contact::{ContactProblem, ContactScheme, MassPenalty};
use courant_solver::{Bar, Field, Mesh, ParkOptions, ParkVariant};

fn graded(length: f64, elements: usize, left: f64, right: f64) -> Bar {
    Bar::new(
        Mesh::uniform(length, elements).unwrap(),
        &Field::Linear { left, right },
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )
    .unwrap()
}

fn impact(elements_per_length: usize) -> ContactProblem {
    ContactProblem::bar_impact(
        graded(1.0, elements_per_length, 1.0, 16.0),
        graded(2.0, 2 * elements_per_length, 16.0, 1.0),
        1.0,
        0.0,
    )
    .unwrap()
}

/// The cumulative impulse `(t^n, sum_k (F^k + F^{k+1}) dt/2)` to t = 3.
fn impulse(
    problem: &ContactProblem,
    bulk: BulkScheme,
    scheme: ContactScheme,
    dt: f64,
) -> Vec<(f64, f64)> {
    let mut run = CombinedStepper::new(problem, bulk, scheme, dt).unwrap();
    let mut previous = run.level().force;
    let mut total = 0.0;
    let mut out = vec![(0.0, 0.0)];
    for _ in 0..(3.0 / dt).ceil() as usize {
        let level = run.step();
        total += 0.5 * dt * (previous + level.force);
        previous = level.force;
        out.push((level.time, total));
    }
    out
}

fn error(history: &[(f64, f64)], reference: &[(f64, f64)]) -> f64 {
    let at = |t: f64| {
        let k = reference
            .partition_point(|&(s, _)| s <= t)
            .clamp(1, reference.len() - 1);
        let ((t0, f0), (t1, f1)) = (reference[k - 1], reference[k]);
        f0 + (f1 - f0) * (t - t0) / (t1 - t0)
    };
    let dt = history[1].0 - history[0].0;
    let rdt = reference[1].0 - reference[0].0;
    let num: f64 = history.iter().map(|&(t, i)| (i - at(t)).abs() * dt).sum();
    let den: f64 = reference.iter().map(|&(_, i)| i.abs() * rdt).sum();
    num / den
}

fn park_lts() -> BulkScheme {
    BulkScheme::Park(ParkOptions {
        theta: 0.5,
        variant: ParkVariant::Incremental,
        local_stepping: true,
    })
}

#[test]
fn combined_schemes_converge_to_the_fine_mesh_reference() {
    let fine = impact(256);
    let reference = impulse(
        &fine,
        BulkScheme::CentralDifference,
        ContactScheme::LagrangeMultiplier,
        0.9 * fine.stiffest_transit(),
    );
    let rmm = BulkScheme::Reciprocal { beta: 0.5 };
    for (bulk, bipenalty, fraction) in [(park_lts(), true, 0.9), (rmm, false, 0.75)] {
        let errors: Vec<f64> = [8, 16, 32, 64]
            .iter()
            .map(|&epl| {
                let problem = impact(epl);
                let scheme = if bipenalty {
                    ContactScheme::Bipenalty(problem.penalty(1e4, MassPenalty::Ratio(1.0)).unwrap())
                } else {
                    ContactScheme::LagrangeMultiplier
                };
                let dt = fraction * problem.stiffest_transit();
                error(&impulse(&problem, bulk, scheme, dt), &reference)
            })
            .collect();
        // Measured: Park-LTS + bipenalty 0.25, 3.0e-3, 2.0e-3, 8.2e-4 (8 EPL is too coarse for
        // the stiff contact end); RMM + LM 9.6e-3, 6.6e-3, 1.4e-3, 1.4e-3 (the reference's own
        // mesh error is of that order).
        let label = format!("{} {errors:?}", bulk.label());
        assert!(errors[3] < 2e-3 && errors[2] < 0.25 * errors[0], "{label}");
        assert!(errors[1..].windows(2).all(|w| w[1] <= w[0]), "{label}");
    }
}

/// Source: the discrete energy of the real masses, `1/2 v M v + 1/2 u K u`, which a passive
/// contact cannot raise above its initial 1/2. Proves (a finding of
/// `docs/contact_with_local_stepping.md`): the bipenalty (r = 1, beta_s = 1e4) switched on and
/// off by the gap creates energy in every bulk on this graded impact (16 elements per unit
/// length), and with RMM(1/2) at 0.75 of the stiffest transit time, below both its contact-free
/// (0.839) and its persistent-contact (0.846) measured limits, the run blows up.
#[test]
fn bipenalty_chatter_creates_energy_and_blows_up_rmm_below_its_limit() {
    use courant_solver::contact::combined::ContactMode;
    use courant_solver::contact::combined::amplification::measured_limit;
    let problem = impact(16);
    let transit = problem.stiffest_transit();
    let bipenalty =
        ContactScheme::Bipenalty(problem.penalty(1e4, MassPenalty::Ratio(1.0)).unwrap());
    let rmm = BulkScheme::Reciprocal { beta: 0.5 };
    let largest = |bulk, fraction: f64| {
        let dt = fraction * transit;
        let mut run = CombinedStepper::new(&problem, bulk, bipenalty, dt).unwrap();
        let mut largest: f64 = 0.0;
        for _ in 0..(3.0 / dt) as usize {
            run.step();
            let e = run.energy();
            largest = largest.max(e.kinetic + e.strain);
        }
        largest
    };
    let limit = measured_limit(&problem, rmm, bipenalty, ContactMode::Bilateral).unwrap();
    assert!(
        limit > 0.8 * transit,
        "rmm bipenalty limit {}",
        limit / transit
    );
    assert!(largest(rmm, 0.75) > 1e6, "rmm at 0.75");
    for bulk in [BulkScheme::CentralDifference, park_lts(), rmm] {
        assert!(largest(bulk, 0.5) > 0.6, "{}", bulk.label());
    }
}
