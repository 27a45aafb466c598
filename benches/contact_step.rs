//! Benchmark: the cost contact adds to a step. Fig. 5 problem (seed section 3.2; striker
//! L1 = 1 onto a bar L2 = 2 at rest, E = rho = A = 1), **1e5 elements per bar** (striker
//! h = 1e-5, target h = 2e-5), Co = 0.5 relative to the striker, r = 1 bipenalty with
//! beta_s = 0.25e4.
//!
//! What it measures (wall time of one step, both bars):
//! - `baseline`: the two bars' lumped kernels (`kernel::LumpedCentralDifference::
//!   step_with_energy`, one zero nodal force each) from the contact run's start state, with no
//!   contact: what a contact-free run of the same bodies costs;
//! - `predictor_corrector`, `cd_bipenalty`, `lagrange_multiplier`: `contact::ContactStepper::
//!   step` of each scheme: the same two kernel steps plus the O(1) contact update (a few nodal
//!   reads, one scalar update, the contact momentum handed to the kernels as a nodal force) and
//!   the sample it returns.
//!
//! The striker starts in contact (the steppers begin at the impact and the contact lasts 2 L1/c
//! = 4e5 steps, far more than criterion runs), so the contact branch is the one timed.
//! Target (issue 5): contact adds at most 5 % to the step; compare the medians.
//!
//! Run:      cargo bench --bench contact_step
//! Numbers:  target/criterion/contact_step/<name>/100000/new/estimates.json
//!           (`median.point_estimate`, ns per step).
//! Duration: about 20 s (warm-up 1 s, 3 s of measurement per function).

use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Duration;

use courant_solver::contact::{ContactProblem, ContactScheme, ContactStepper, MassPenalty};
use courant_solver::kernel::LumpedCentralDifference;
use courant_solver::{Bar, InitialConditions, Mesh, Model, Supports};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

const ELEMENTS: usize = 100_000;

/// The Fig. 5 bars with a smooth background velocity `1e-3 cos(pi x/L)` added to both (the
/// striker's v0 = 1 on top), so that every nodal value stays a normal float: a body at rest
/// ahead of a Co = 0.5 wavefront otherwise carries a band of subnormal values in its dispersive
/// precursor, whose slow arithmetic would be charged to the contact.
fn problem() -> ContactProblem {
    let body = |length: f64, v0: f64| {
        let bar =
            Bar::homogeneous(Mesh::uniform(length, ELEMENTS).unwrap(), 1.0, 1.0, 1.0).unwrap();
        let velocity = (0..=ELEMENTS)
            .map(|i| v0 + 1e-3 * (PI * i as f64 / ELEMENTS as f64).cos())
            .collect();
        let initial = InitialConditions {
            displacement: None,
            velocity: Some(velocity),
        };
        Model::new(bar, Supports::default(), &[], initial).unwrap()
    };
    ContactProblem::pair(body(1.0, 1.0), body(2.0, 0.0), 0.0).unwrap()
}

fn contact_step(c: &mut Criterion) {
    let problem = problem();
    let dt = 0.5 * problem.stiffest_transit();
    let mut group = c.benchmark_group("contact_step");
    group
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3))
        .sample_size(30)
        .throughput(Throughput::Elements(2 * ELEMENTS as u64));

    // Baseline: the same two kernels without contact, from the contact stepper's start state.
    let start = ContactStepper::new(&problem, dt, ContactScheme::LagrangeMultiplier).unwrap();
    let mut kernels: Vec<LumpedCentralDifference> = problem
        .bodies()
        .iter()
        .enumerate()
        .map(|(b, model)| {
            LumpedCentralDifference::new(
                model,
                dt,
                start.displacement(b),
                start.half_step_velocity(b),
            )
        })
        .collect();
    drop(start);
    // One zero nodal force per body, at the contact node, as the contact steps pass.
    let forces = [[(ELEMENTS, 0.0)], [(0, 0.0)]];
    group.bench_function(BenchmarkId::new("baseline", ELEMENTS), |b| {
        b.iter(|| {
            let mut energy = 0.0;
            for (kernel, f) in kernels.iter_mut().zip(&forces) {
                energy += kernel.step_with_energy(black_box(f)).kinetic;
            }
            energy
        })
    });

    let penalty = problem.penalty(0.25e4, MassPenalty::Ratio(1.0)).unwrap();
    for (name, scheme) in [
        (
            "predictor_corrector",
            ContactScheme::PredictorCorrector(penalty),
        ),
        ("cd_bipenalty", ContactScheme::Bipenalty(penalty)),
        ("lagrange_multiplier", ContactScheme::LagrangeMultiplier),
    ] {
        let mut stepper = ContactStepper::new(&problem, dt, scheme).unwrap();
        group.bench_function(BenchmarkId::new(name, ELEMENTS), |b| {
            b.iter(|| black_box(stepper.step()))
        });
        let sample = stepper.sample();
        assert!(
            sample.total.is_finite() && sample.impulse > 0.0,
            "{name}: the benchmark state left the contact or blew up: {sample:?}"
        );
    }
    group.finish();
}

criterion_group!(benches, contact_step);
criterion_main!(benches);
