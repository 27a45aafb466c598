//! The layered impact with the combined schemes measured (benches/RESULTS.md, heading "Contact
//! with local stepping and the reciprocal mass"): a striker of length 1 (layers [0, 0.5] E = 1,
//! [0.5, 1] E = 256) at v0 = 1 onto a target of length 2 ([0, 0.5] E = 16, [0.5, 1.5] E = 1,
//! [1.5, 2] E = 256), rho = A = 1, gap 0, `EPL` elements per unit length.
//!
//! Prints (1) the step limits measured from the amplification matrix (8 elements per unit
//! length) and (2) a work-precision table: the force error against the CD-LMM + Lagrange
//! multiplier run on a 256-per-unit-length mesh (L1 over [0, 3] of the cumulative impulse of the
//! reported force, divided by the reference's; force = delivered momentum over the level's
//! span: the ringing of the stiff layers makes a pointwise force error O(1)), steps, element force
//! evaluations (elements x evaluations per step x steps) and wall time, for Park-LTS + bipenalty
//! and for the global step (CD-LMM) + penalty.
//!
//! ```text
//! cargo run --release -p courant-solver --example impact_combined
//! ```

use courant_solver::contact::combined::amplification::{measured_limit, spectral_radius};
use courant_solver::contact::combined::{BulkScheme, CombinedStepper, ContactMode};
use courant_solver::contact::{ContactProblem, ContactScheme, MassPenalty};
use courant_solver::{Bar, Field, Mesh, ParkOptions, ParkVariant};
use std::time::Instant;

fn layered(length: f64, epl: usize, layers: &[(f64, f64)]) -> Bar {
    let n = (length * epl as f64).round() as usize;
    let e: Vec<f64> = (0..n)
        .map(|k| {
            let x = (k as f64 + 0.5) * length / n as f64;
            layers.iter().find(|(end, _)| x < *end).expect("layer").1
        })
        .collect();
    Bar::new(
        Mesh::uniform(length, n).expect("mesh"),
        &Field::PerElement(e),
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )
    .expect("bar")
}

fn impact(epl: usize) -> ContactProblem {
    ContactProblem::bar_impact(
        layered(1.0, epl, &[(0.5, 1.0), (1.0, 256.0)]),
        layered(2.0, epl, &[(0.5, 16.0), (1.5, 1.0), (2.0, 256.0)]),
        1.0,
        0.0,
    )
    .expect("problem")
}

fn park(variant: ParkVariant, local_stepping: bool) -> BulkScheme {
    BulkScheme::Park(ParkOptions {
        theta: 0.5,
        variant,
        local_stepping,
    })
}

/// `(times, forces, steps, seconds)` to t = 3.
fn run(
    problem: &ContactProblem,
    bulk: BulkScheme,
    scheme: ContactScheme,
    dt: f64,
) -> (Vec<(f64, f64)>, usize, f64) {
    let start = Instant::now();
    let mut stepper = CombinedStepper::new(problem, bulk, scheme, dt).expect("stepper");
    let steps = (3.0 / dt).ceil() as usize;
    let mut history = Vec::with_capacity(steps + 1);
    let first = stepper.level();
    history.push((first.time, first.force));
    for _ in 0..steps {
        let l = stepper.step();
        history.push((l.time, l.force));
    }
    (history, steps, start.elapsed().as_secs_f64())
}

/// The cumulative impulse `I(t^n) = sum_k (F^k + F^{k+1}) dt/2` (the target's momentum, exact
/// for the discrete scheme) at each level.
fn impulse(history: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut total = 0.0;
    let mut out = vec![(history[0].0, 0.0)];
    for w in history.windows(2) {
        total += 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0);
        out.push((w[1].0, total));
    }
    out
}

/// L1 over [0, 3] of `I - I_ref` (the reference linear between its levels) over the L1 of
/// `I_ref`: the force error in the norm that a ringing force does not dominate.
fn force_error(history: &[(f64, f64)], reference: &[(f64, f64)]) -> f64 {
    let (history, reference) = (impulse(history), impulse(reference));
    let at = |t: f64| {
        let k = reference
            .partition_point(|&(s, _)| s <= t)
            .clamp(1, reference.len() - 1);
        let ((t0, f0), (t1, f1)) = (reference[k - 1], reference[k]);
        f0 + (f1 - f0) * (t - t0) / (t1 - t0)
    };
    let dt = history[1].0 - history[0].0;
    let num: f64 = history.iter().map(|&(t, f)| (f - at(t)).abs() * dt).sum();
    let rdt = reference[1].0 - reference[0].0;
    let den: f64 = reference.iter().map(|&(_, f)| f.abs() * rdt).sum();
    num / den
}

fn main() {
    let small = impact(8);
    let transit = small.stiffest_transit();
    let lm = ContactScheme::LagrangeMultiplier;
    println!("Step limits / stiffest element's transit time, 8 elements per unit length:");
    for bulk in [
        park(ParkVariant::Free, true),
        park(ParkVariant::Free, false),
        park(ParkVariant::Incremental, true),
        park(ParkVariant::Incremental, false),
        BulkScheme::CentralDifference,
        BulkScheme::Reciprocal { beta: 0.5 },
    ] {
        let free = measured_limit(&small, bulk, lm, ContactMode::Off).expect("limit") / transit;
        let mut row = format!("{:22} contact-free {free:.6}", bulk.label());
        for beta_s in [1.0, 1e4, 1e8] {
            let p = small
                .penalty(beta_s, MassPenalty::Ratio(1.0))
                .expect("penalty");
            for (name, scheme) in [
                (
                    "pen",
                    ContactScheme::Penalty {
                        stiffness: p.stiffness,
                    },
                ),
                ("bip", ContactScheme::Bipenalty(p)),
                ("pc", ContactScheme::PredictorCorrector(p)),
            ] {
                let l =
                    measured_limit(&small, bulk, scheme, ContactMode::Bilateral).expect("limit");
                row += &format!(" {name}({beta_s:e}) {:.6}", l / transit);
            }
        }
        let l = measured_limit(&small, bulk, lm, ContactMode::Bilateral).expect("limit");
        println!("{row} lm {:.6}", l / transit);
    }
    for f in [0.1, 0.3, 0.5, 0.7, 0.8, 0.9] {
        let r = spectral_radius(
            &small,
            park(ParkVariant::Free, true),
            lm,
            ContactMode::Off,
            f * transit,
        )
        .expect("rho");
        println!(
            "park-lts-free contact-free alpha_max {f}: rho - 1 = {:.3e}",
            r - 1.0
        );
    }

    let fine = impact(256);
    let (reference, _, _) = run(
        &fine,
        BulkScheme::CentralDifference,
        lm,
        0.9 * fine.stiffest_transit(),
    );
    println!("\nWork precision (reference: CD-LMM + LM, 256 elements per unit length, Co 0.9):");
    println!(
        "{:>4} {:38} {:>10} {:>8} {:>12} {:>9}",
        "EPL", "case", "error", "steps", "elem evals", "ms"
    );
    for epl in [8, 16, 32, 64] {
        let problem = impact(epl);
        let transit = problem.stiffest_transit();
        let elements = 3 * epl;
        let p4 = problem
            .penalty(1e4, MassPenalty::Ratio(1.0))
            .expect("penalty");
        let mut cases = vec![(
            "park-lts-incremental + bipenalty 1e4".to_string(),
            park(ParkVariant::Incremental, true),
            ContactScheme::Bipenalty(p4),
            0.9 * transit,
        )];
        cases.push((
            "cd-lmm + bipenalty 1e4".to_string(),
            BulkScheme::CentralDifference,
            ContactScheme::Bipenalty(p4),
            0.9 * transit,
        ));
        cases.push((
            "cd-lmm + lagrange multiplier".to_string(),
            BulkScheme::CentralDifference,
            lm,
            0.9 * transit,
        ));
        for beta_s in [1e2, 1e3, 1e4] {
            let p = problem.penalty(beta_s, MassPenalty::None).expect("penalty");
            let scheme = ContactScheme::Penalty {
                stiffness: p.stiffness,
            };
            let limit = courant_solver::contact::ContactCriticalStep::of(&problem, &scheme)
                .expect("limit")
                .applicable;
            cases.push((
                format!("cd-lmm + penalty {beta_s:e}"),
                BulkScheme::CentralDifference,
                scheme,
                0.9 * limit.min(transit),
            ));
        }
        for (name, bulk, scheme, dt) in cases {
            let (history, steps, seconds) = run(&problem, bulk, scheme, dt);
            println!(
                "{epl:>4} {name:38} {:>10.3e} {steps:>8} {:>12} {:>9.2}",
                force_error(&history, &reference),
                elements * bulk.force_evaluations() * steps,
                1e3 * seconds
            );
        }
    }
}
