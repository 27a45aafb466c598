//! Benchmark: the cost contact adds to a step. Fig. 5 problem (seed section 3.2; striker
//! L1 = 1 onto a bar L2 = 2 at rest, E = rho = A = 1), **N = 1e3, 1e5, 1e6 elements per bar**
//! (striker h = 1/N, target h = 2/N), Co = 0.5 relative to the striker, r = 1 bipenalty with
//! beta_s = 0.25e4.
//!
//! What it measures (wall time of one step, both bars):
//! - `baseline`: the two bars' lumped kernels (`LumpedStep::step_with_energy`, one zero nodal
//!   force each) from the contact run's start state, with no
//!   contact: what a contact-free run of the same bodies costs;
//! - `predictor_corrector`, `cd_bipenalty`, `lagrange_multiplier`: `contact::ContactStepper::
//!   step` of each scheme: the same two kernel steps plus the O(1) contact update (a few nodal
//!   reads, one scalar update, the contact momentum handed to the kernels as a nodal force) and
//!   the sample it returns.
//!
//! The striker starts in contact (the steppers begin at the impact and the contact lasts 2 L1/c = 4
//! N steps). Every timed stretch restarts from a clone of the start state after at most min(N,
//! 2000) steps (the clone is not timed), so the contact branch is the one timed at every N. Target:
//! contact adds at most 5 % to the step; compare the medians.
//!
//! Run:      cargo bench --bench contact_step
//! Numbers:  target/criterion/contact_step/<name>/<N>/new/estimates.json
//!           (`median.point_estimate`, ns per step of both bars, 2 (N + 1) nodes).
//! Duration: about 1 min (warm-up 1 s, 3 s of measurement per function and size).

use std::f64::consts::PI;
use std::hint::black_box;
use std::time::{Duration, Instant};

use courant_solver::bench::LumpedStep;
use courant_solver::contact::{ContactProblem, ContactScheme, ContactStepper, MassPenalty};
use courant_solver::{Bar, InitialConditions, Mesh, Model, Supports};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

/// Elements per bar.
const SIZES: [usize; 3] = [1_000, 100_000, 1_000_000];

/// Time `iters` calls of `step` on clones of `start`, restarting from a fresh clone (untimed)
/// every `restart` calls so that the state stays in contact.
fn timed_from<S: Clone>(
    start: &S,
    iters: u64,
    restart: u64,
    mut step: impl FnMut(&mut S),
) -> Duration {
    let mut total = Duration::ZERO;
    let mut left = iters;
    while left > 0 {
        let chunk = left.min(restart);
        let mut state = start.clone();
        let began = Instant::now();
        for _ in 0..chunk {
            step(&mut state);
        }
        total += began.elapsed();
        left -= chunk;
    }
    total
}

/// The Fig. 5 bars with a smooth background velocity `1e-3 cos(pi x/L)` added to both (the
/// striker's v0 = 1 on top), so that every nodal value stays a normal float: a body at rest
/// ahead of a Co = 0.5 wavefront otherwise carries a band of subnormal values in its dispersive
/// precursor, whose slow arithmetic would be charged to the contact.
fn problem(elements: usize) -> ContactProblem {
    let body = |length: f64, v0: f64| {
        let bar =
            Bar::homogeneous(Mesh::uniform(length, elements).unwrap(), 1.0, 1.0, 1.0).unwrap();
        let velocity = (0..=elements)
            .map(|i| v0 + 1e-3 * (PI * i as f64 / elements as f64).cos())
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
    let mut group = c.benchmark_group("contact_step");
    group
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3))
        .sample_size(30);
    for elements in SIZES {
        let problem = problem(elements);
        let dt = 0.5 * problem.stiffest_transit();
        let restart = elements.min(2_000) as u64;
        group.throughput(Throughput::Elements(2 * elements as u64));

        // Baseline: the same two kernels without contact, from the contact stepper's start state.
        let start = ContactStepper::new(&problem, dt, ContactScheme::LagrangeMultiplier).unwrap();
        let kernels: Vec<LumpedStep> = problem
            .bodies()
            .iter()
            .enumerate()
            .map(|(b, model)| {
                LumpedStep::new(
                    model,
                    dt,
                    start.displacement(b),
                    start.half_step_velocity(b),
                )
            })
            .collect();
        drop(start);
        // One zero nodal force per body, at the contact node, as the contact steps pass.
        let forces = [[(elements, 0.0)], [(0, 0.0)]];
        group.bench_function(BenchmarkId::new("baseline", elements), |b| {
            b.iter_custom(|iters| {
                timed_from(&kernels, iters, restart, |kernels| {
                    let mut energy = 0.0;
                    for (kernel, f) in kernels.iter_mut().zip(&forces) {
                        energy += kernel.step_with_energy(black_box(f)).kinetic;
                    }
                    black_box(energy);
                })
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
            let start = ContactStepper::new(&problem, dt, scheme).unwrap();
            let mut probe = start.clone();
            for _ in 0..restart {
                probe.step();
            }
            let sample = probe.sample();
            assert!(
                sample.total.is_finite() && sample.active,
                "{name}: after {restart} steps the benchmark state left the contact or blew up: {sample:?}"
            );
            group.bench_function(BenchmarkId::new(name, elements), |b| {
                b.iter_custom(|iters| {
                    timed_from(&start, iters, restart, |stepper| {
                        black_box(stepper.step());
                    })
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, contact_step);
criterion_main!(benches);
