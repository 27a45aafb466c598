//! Benchmark: ONE lumped-mass central-difference step of `courant_solver`'s
//! `kernel::LumpedStep` (`step` and `step_with_energy`), on a GRADED bar.
//!
//! What it measures: the wall time of one step for N = 1e3, 1e5, 1e6 elements. The bar is the
//! unit bar with modulus linear 16 -> 1 (so every element has its own stiffness and every node
//! its own inverse mass), density 1, area 1, free left end loaded by F = 1 on node 0, fixed right
//! end, dt at Courant number 0.5. The state starts from u = 0 and a smooth half-step velocity
//! v = 1e-3 cos(pi x / 2) (zero at the fixed end), so every value is a normal float and the
//! (stable) scheme keeps it bounded however many iterations criterion runs; each benchmark checks
//! at the end that the state is still finite. Throughput is `Elements(N)`: criterion's
//! "elem/s" is element-steps per second; ns per node-step = time per step / (N + 1).
//!
//! Target: as fast as the tight C loop doing the same arithmetic, `benches/c_reference/cd_step.c`
//! compiled with `gcc -O3 -march=native` — the team's figure is about 1.6–1.8 ns per node-step for
//! N <= 1e5 on the 2-core machines. `run.sh` there prints the C loop's own numbers (two-pass, fused
//! and blocked variants); compare with those, measured on the same machine. ISA: the kernel selects
//! an AVX2-compiled copy of the step at run time where the CPU has AVX2 (bit-identical results; see
//! `kernels::lumped::kernel`), so a default `cargo bench` is comparable with the C loop at
//! `-march=native`. `step_with_energy` adds three energy sums, kept in 8 independent lanes so they
//! vectorise.
//!
//! Also: `run_loop`, a whole 1000-step run through the public time loop (N = 1e4; lumped CD, CMM,
//! Park, Noh-Bathe): what the loop adds around the kernels; `noh_bathe_step`, one Noh-Bathe step
//! (LMM, CMM) beside CD's, both through the `Integrator` interface; `memory_triad`, the STREAM
//! triad at the same sizes (and 4e6), the machine's bandwidth the report compares each step's model
//! bandwidth with.
//!
//! Run:      cargo bench --bench cd_step
//!           (one function only: cargo bench --bench cd_step -- 'lumped_cd_step/step/')
//!           C reference: bash benches/c_reference/run.sh
//! Numbers:  target/criterion/lumped_cd_step/<step|step_with_energy>/<N>/new/estimates.json
//!           (i.e. target/criterion/*/*/*/new/estimates.json; `median.point_estimate` is in ns
//!           per step), HTML report in target/criterion/report/index.html.
//! Duration: about a minute (warm-up 1 s and 3 s of measurement per benchmark, 4 s at N = 1e6).

use std::hint::black_box;
use std::time::Duration;

use courant_solver::bench::LumpedStep;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

/// Element counts.
const SIZES: [usize; 3] = [1_000, 100_000, 1_000_000];

/// Noh-Bathe's splitting parameter in the benches (the registry's default).
const NB_P: f64 = 0.54;

/// Noh-Bathe's critical step over central difference's on the same mass:
/// `Omega_crit(p) / 2` (`NohBatheScheme::critical_omega`; 1.8725 at p = 0.54).
fn noh_bathe_step_ratio() -> f64 {
    courant_solver::schemes::noh_bathe::NohBatheScheme::critical_omega(NB_P) / 2.0
}

use courant_solver::bench::smooth_half_velocity;

/// The graded, loaded, free-fixed bar of `n` elements and its kernel at Courant number 0.5.
fn graded_kernel(n: usize) -> LumpedStep {
    let model = courant_solver::bench::graded_seed_bar(n).unwrap();
    let dt = 0.5 * model.bar().stiffest_element().1;
    let u0 = vec![0.0; n + 1];
    let v_half = smooth_half_velocity(n);
    LumpedStep::new(&model, dt, &u0, &v_half)
}

fn assert_finite(kernel: &LumpedStep) {
    assert!(
        kernel
            .displacement()
            .iter()
            .chain(kernel.half_step_velocity())
            .all(|x| x.is_finite()),
        "the benchmark state blew up"
    );
}

fn lumped_cd_step(c: &mut Criterion) {
    let forces = [(0usize, 1.0f64)];
    let mut group = c.benchmark_group("lumped_cd_step");
    group.warm_up_time(Duration::from_secs(1));
    for n in SIZES {
        if n >= 1_000_000 {
            group
                .sample_size(20)
                .measurement_time(Duration::from_secs(4));
        } else {
            group
                .sample_size(50)
                .measurement_time(Duration::from_secs(3));
        }
        group.throughput(Throughput::Elements(n as u64));

        let mut kernel = graded_kernel(n);
        group.bench_with_input(BenchmarkId::new("step", n), &n, |b, _| {
            b.iter(|| kernel.step(black_box(&forces)));
        });
        assert_finite(&kernel);

        let mut kernel = graded_kernel(n);
        group.bench_with_input(BenchmarkId::new("step_with_energy", n), &n, |b, _| {
            b.iter(|| kernel.step_with_energy(black_box(&forces)));
        });
        assert_finite(&kernel);
    }
    group.finish();
}

/// Temporal blocking: blocks of 1024 lumped steps (`advance_block`: tiles of 1024 nodes,
/// sub-blocks of 64 steps) on one and on two threads, bare and with the energy sums, per
/// node-step (throughput `1024 N`). Bit-identical to single steps whatever the thread count
/// (unit tests of `kernels::lumped::pipeline`). Target: 0.54 ns at N = 1e6 on one core, 1.7x on
/// two (benches/RESULTS.md, "2026-11-25, Intel: blocks of steps (temporal blocking) and both
/// cores").
fn lumped_cd_block(c: &mut Criterion) {
    use courant_solver::bench::{MAX_BLOCK_STEPS, StepBlock};
    let steps = MAX_BLOCK_STEPS;
    let mut group = c.benchmark_group("lumped_cd_block");
    group
        .warm_up_time(Duration::from_secs(1))
        .sample_size(10)
        .measurement_time(Duration::from_secs(4));
    for n in SIZES {
        group.throughput(Throughput::Elements((n * steps) as u64));
        let mut block = StepBlock::new(&[0], &[], &[]);
        block.forces.fill(1.0);
        for threads in [1, 2] {
            let mut kernel = graded_kernel(n);
            kernel.set_threads(threads);
            group.bench_with_input(
                BenchmarkId::new(format!("step_t{threads}"), n),
                &n,
                |b, _| {
                    b.iter(|| kernel.advance_block::<false>(black_box(&mut block), steps));
                },
            );
            assert_finite(&kernel);
            let mut kernel = graded_kernel(n);
            kernel.set_threads(threads);
            group.bench_with_input(
                BenchmarkId::new(format!("step_with_energy_t{threads}"), n),
                &n,
                |b, _| {
                    b.iter(|| kernel.advance_block::<true>(black_box(&mut block), steps));
                },
            );
            assert_finite(&kernel);
        }
    }
    group.finish();
}

/// One run step (with energies, as runs take it) per mass kind on the graded bar, N = 1e3, 1e5,
/// 1e6, at half of each kind's critical Courant number, and CMM on a bar of graded density too
/// (each window with its own factors). Targets: RMM within 2x of LMM, CMM and AMM within 3x (when
/// the matrix masses were added), then each within 1.5x at N = 1e5 and 1e6 (benches/RESULTS.md,
/// "2026-11-28, AMD: matrix-mass steps against the lumped step").
fn mass_kind_step(c: &mut Criterion) {
    use courant_solver::MassKind;
    let forces = [(0usize, 1.0f64)];
    let mut group = c.benchmark_group("mass_kind_step");
    group
        .warm_up_time(Duration::from_secs(1))
        .sample_size(20)
        .measurement_time(Duration::from_secs(3));
    for n in SIZES {
        let model = courant_solver::bench::graded_seed_bar(n).unwrap();
        group.throughput(Throughput::Elements(n as u64));
        let mut lumped = graded_kernel(n);
        group.bench_function(BenchmarkId::new("lmm", n), |b| {
            b.iter(|| lumped.step_with_energy(black_box(&forces)))
        });
        assert_finite(&lumped);
        // CMM also on the bar with its density graded too (4 to 1): every window's rows differ,
        // so each keeps its own factors (`mass::windows`), streamed every step.
        let graded_density = courant_solver::Model::unloaded(
            courant_solver::Bar::new(
                courant_solver::Mesh::uniform(1.0, n).unwrap(),
                &courant_solver::Field::Linear {
                    left: 16.0,
                    right: 1.0,
                },
                &courant_solver::Field::Linear {
                    left: 4.0,
                    right: 1.0,
                },
                &courant_solver::Field::Constant(1.0),
            )
            .unwrap(),
            courant_solver::Supports::FREE_FIXED,
        );
        for (name, model, kind) in [
            ("cmm", &model, MassKind::Consistent),
            ("amm0.5", &model, MassKind::Averaged { beta: 0.5 }),
            ("rmm0.5", &model, MassKind::Reciprocal { beta: 0.5 }),
            ("cmm-graded-density", &graded_density, MassKind::Consistent),
        ] {
            let mut kernel = courant_solver::bench::matrix_step(model, kind).unwrap();
            group.bench_function(BenchmarkId::new(name, n), |b| {
                b.iter(|| kernel.step_with_energy(black_box(&forces)))
            });
            assert!(
                kernel.displacement().iter().all(|x| x.is_finite()),
                "{kind:?} blew up"
            );
        }
    }
    group.finish();
}

/// Dense spectra of a 200-element fixed-free bar per mass kind (target: well under a second).
fn spectrum_dense(c: &mut Criterion) {
    use courant_solver::{Bar, MassKind, Mesh, Model, Support, Supports};
    let bar = Bar::homogeneous(Mesh::uniform(1.0, 200).unwrap(), 1.0, 1.0, 1.0).unwrap();
    let model = Model::unloaded(
        bar,
        Supports {
            left: Support::Fixed,
            right: Support::Free,
        },
    );
    let mut group = c.benchmark_group("spectrum_dense");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(3));
    for kind in [
        MassKind::Lumped,
        MassKind::Consistent,
        MassKind::Averaged { beta: 0.5 },
        MassKind::Reciprocal { beta: 0.5 },
    ] {
        let name = kind.label().replace(['(', ')'], "");
        group.bench_function(BenchmarkId::new(name, 200), |b| {
            b.iter(|| {
                courant_solver::analysis::angular_frequencies(black_box(&model), kind).unwrap()
            })
        });
    }
    group.finish();
}

/// One step of Park's scheme (theta = 1/2, with and without local stepping) against the lumped
/// CD run step on the Fig. 2 graded bar, N = 1e3, 1e5, 1e6, Co = 0.5. Target: within 3x of CD
/// (a Park step evaluates the internal forces twice).
fn park_step(c: &mut Criterion) {
    use courant_solver::ParkOptions;
    use courant_solver::bench::ParkStep;
    let mut group = c.benchmark_group("park_step");
    group
        .warm_up_time(Duration::from_secs(1))
        .sample_size(20)
        .measurement_time(Duration::from_secs(3));
    for n in SIZES {
        let model = courant_solver::bench::graded_seed_bar(n).unwrap();
        let dt = 0.5 * model.bar().stiffest_element().1;
        group.throughput(Throughput::Elements(n as u64));
        let forces = [(0usize, 1.0f64)];
        let mut cd = graded_kernel(n);
        group.bench_function(BenchmarkId::new("cd", n), |b| {
            b.iter(|| cd.step_with_energy(black_box(&forces)))
        });
        for local_stepping in [false, true] {
            let options = ParkOptions {
                local_stepping,
                ..ParkOptions::default()
            };
            let mut park = ParkStep::new(&model, dt, options).unwrap();
            park.start(&model);
            let mut t = 0.0;
            group.bench_function(BenchmarkId::new(options.label(), n), |b| {
                b.iter(|| {
                    let e = park.step(black_box(&model), t);
                    t += dt;
                    e
                })
            });
            assert!(park.displacement().iter().all(|x| x.is_finite()));
        }
    }
    group.finish();
}

/// One step of the Noh-Bathe scheme (p = 0.54, lumped and consistent mass) against central
/// difference, both stepped through the public `Integrator` interface as the shared time loop
/// steps them, on the Fig. 2 graded bar at 0.5 of each one's critical Courant number, N = 1e3,
/// 1e5, 1e6. Noh-Bathe does two K u products and two mass solves per step.
fn noh_bathe_step(c: &mut Criterion) {
    use courant_solver::integrator::{InitialState, Integrator};
    use courant_solver::schemes::central_difference::{LumpedStepper, MatrixStepper};
    use courant_solver::schemes::noh_bathe::NohBatheStepper;
    use courant_solver::{MassKind, MassOperator, Model, Start};
    /// The start state of `model` from rest with the smooth velocity of the other benchmarks.
    fn stepper<I: Integrator>(model: &Model, kind: MassKind, dt: f64, p: &I::Parameters) -> I {
        let n = model.bar().node_count() - 1;
        let (zeros, v) = (vec![0.0; n + 1], smooth_half_velocity(n));
        let state = InitialState {
            model,
            dt,
            displacement: &zeros,
            velocity: &v,
            acceleration: &zeros,
            residual: &zeros,
            kinetic: 0.0,
            start: Start::HalfStep,
            allow_unstable: false,
            mass: MassOperator::new(model, kind).unwrap(),
            threads: 1,
        };
        I::start(p, state).unwrap()
    }
    fn bench<I: Integrator>(
        group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
        name: &str,
        model: &Model,
        mut stepper: I,
    ) {
        let n = model.bar().element_count();
        let forces = [(0usize, 1.0f64)];
        let dt = stepper.dt();
        let mut t = 0.0;
        group.bench_function(BenchmarkId::new(name, n), |b| {
            b.iter(|| {
                let e = stepper.step(black_box(model), t, black_box(&forces));
                t += dt;
                e
            })
        });
        assert!(
            stepper.displacement().iter().all(|x| x.is_finite()),
            "{name}"
        );
    }
    let mut group = c.benchmark_group("noh_bathe_step");
    group
        .warm_up_time(Duration::from_secs(1))
        .sample_size(20)
        .measurement_time(Duration::from_secs(3));
    for n in SIZES {
        let model = courant_solver::bench::graded_seed_bar(n).unwrap();
        let element_dt = model.bar().stiffest_element().1;
        group.throughput(Throughput::Elements(n as u64));
        let lumped = 0.5 * element_dt;
        let consistent = 0.5 * MassKind::Consistent.critical_courant() * element_dt;
        bench(
            &mut group,
            "cd-lmm",
            &model,
            stepper::<LumpedStepper>(&model, MassKind::Lumped, lumped, &()),
        );
        bench(
            &mut group,
            "noh-bathe-lmm",
            &model,
            stepper::<NohBatheStepper>(
                &model,
                MassKind::Lumped,
                noh_bathe_step_ratio() * lumped,
                &NB_P,
            ),
        );
        bench(
            &mut group,
            "cd-cmm",
            &model,
            stepper::<MatrixStepper>(&model, MassKind::Consistent, consistent, &()),
        );
        bench(
            &mut group,
            "noh-bathe-cmm",
            &model,
            stepper::<NohBatheStepper>(
                &model,
                MassKind::Consistent,
                noh_bathe_step_ratio() * consistent,
                &NB_P,
            ),
        );
    }
    group.finish();
}

/// The machine's reach: the STREAM triad `a[i] = b[i] + s c[i]` (McCalpin, "Memory bandwidth and
/// machine balance", 1995) over N = 1e3, 1e5, 1e6 and 4e6 elements, 24 bytes per element as
/// STREAM counts them (write-allocate traffic not counted). The report's benchmark table divides
/// each step's model bandwidth by the triad's at the same N: how close to this machine's limit
/// the step runs. 4e6 (96 MB) is beyond every cache: main-memory bandwidth.
fn memory_triad(c: &mut Criterion) {
    let mut group = c.benchmark_group("memory_triad");
    group
        .warm_up_time(Duration::from_secs(1))
        .sample_size(20)
        .measurement_time(Duration::from_secs(3));
    for n in [1_000, 100_000, 1_000_000, 4_000_000] {
        let b: Vec<f64> = (0..n).map(|i| i as f64).collect();
        let c_in: Vec<f64> = (0..n).map(|i| 1.0 / (1.0 + i as f64)).collect();
        let mut a = vec![0.0; n];
        group.throughput(Throughput::Bytes(24 * n as u64));
        group.bench_function(BenchmarkId::new("triad", n), |bench| {
            bench.iter(|| {
                let s = black_box(3.0);
                for ((a, b), c) in a.iter_mut().zip(&b).zip(&c_in) {
                    *a = b + s * c;
                }
                black_box(&mut a);
            })
        });
        assert!(a.iter().all(|x| x.is_finite()));
    }
    group.finish();
}

/// A whole run through the public time loop (`Integration::run`: start, stability check, steps
/// with the energy balance, the guard and the work of the loads), 1000 steps on the graded bar of
/// N = 1e4 elements at Co = 0.5 (Park: its own Co = 0.5, CMM: half its critical Courant number,
/// Noh-Bathe: half its own limit), no profiles, no histories, one energy sample at the end. Time
/// per run; per step divide by 1000. It measures what the loop adds around the kernels.
fn run_loop(c: &mut Criterion) {
    use courant_solver::{CentralDifference, MassKind, OutputRequest, ParkOptions};
    let mut group = c.benchmark_group("run_loop");
    group
        .warm_up_time(Duration::from_secs(1))
        .sample_size(20)
        .measurement_time(Duration::from_secs(4));
    let (n, steps) = (10_000, 1_000);
    let model = courant_solver::bench::graded_seed_bar(n).unwrap();
    let element_dt = model.bar().stiffest_element().1;
    let request = OutputRequest {
        energy_every: steps,
        history_every: steps,
        ..OutputRequest::default()
    };
    group.throughput(Throughput::Elements((n * steps) as u64));
    for (name, integrator) in [
        ("lmm", CentralDifference::new(0.5 * element_dt)),
        (
            "cmm",
            CentralDifference {
                mass: MassKind::Consistent,
                ..CentralDifference::new(0.5 * MassKind::Consistent.critical_courant() * element_dt)
            },
        ),
        (
            "park-lts",
            CentralDifference {
                park: Some(ParkOptions::default()),
                ..CentralDifference::new(0.5 * element_dt)
            },
        ),
    ]
    .map(|(name, settings)| (name, settings.integration()))
    .into_iter()
    .chain([(
        "noh-bathe",
        courant_solver::Integration::new(
            0.5 * noh_bathe_step_ratio() * element_dt,
            std::sync::Arc::new(courant_solver::schemes::noh_bathe::NohBatheScheme { p: NB_P }),
        ),
    )]) {
        group.bench_function(BenchmarkId::new(name, n), |b| {
            b.iter(|| {
                let out = integrator.run(black_box(&model), steps, &request).unwrap();
                assert_eq!(out.steps, steps);
                out.energy.max_balance_error
            })
        });
    }
    group.finish();
}

/// The run loop at scale (benches/RESULTS.md, "2026-11-25, Intel: the run loop against the
/// bare kernel; memory per element"):
/// `Scheme::run` (the shared time loop: the start, the steps with the energy balance checked every
/// step, the blow-up guard, the work of the loads, an energy sample at every step as a scene takes
/// them for runs of up to 10^4 steps (with `T*` recomputed from the mass at every 64th:
/// `MASS_CHECK_EVERY`), no profiles or histories) on the graded bar of N = 1e5 (1000 steps) and 1e6
/// (300 steps) elements, for lumped CD (compare with `lumped_cd_step/step`, the bare kernel), CMM,
/// AMM(1/2), RMM(1/2) (with `mass_kind_step`, their own step) and Park with local stepping (with
/// `park_step`), each at half its critical Courant number. The mass is assembled and factored
/// outside the timing (`iter_batched`); the start is inside. Time per run; ns per node-step = time
/// / (steps (N + 1)).
fn run_loop_large(c: &mut Criterion) {
    use courant_solver::integrator::OutputRequest;
    use courant_solver::{CentralDifference, MassKind, MassOperator, ParkOptions};
    let mut group = c.benchmark_group("run_loop_large");
    group
        .warm_up_time(Duration::from_secs(1))
        .sample_size(10)
        .measurement_time(Duration::from_secs(3));
    for (n, steps) in [(100_000, 1_000), (1_000_000, 300)] {
        let model = courant_solver::bench::graded_seed_bar(n).unwrap();
        let element_dt = model.bar().stiffest_element().1;
        let request = OutputRequest {
            energy_every: 1,
            history_every: steps,
            ..OutputRequest::default()
        };
        group.throughput(Throughput::Elements((n * steps) as u64));
        let matrix = |mass: MassKind| CentralDifference {
            mass,
            ..CentralDifference::new(0.5 * mass.critical_courant() * element_dt)
        };
        for (name, settings) in [
            ("lmm", CentralDifference::new(0.5 * element_dt)),
            ("cmm", matrix(MassKind::Consistent)),
            ("amm0.5", matrix(MassKind::Averaged { beta: 0.5 })),
            ("rmm0.5", matrix(MassKind::Reciprocal { beta: 0.5 })),
            (
                "park-lts",
                CentralDifference {
                    park: Some(ParkOptions::default()),
                    ..CentralDifference::new(0.5 * element_dt)
                },
            ),
        ] {
            let integration = settings.integration();
            group.bench_function(BenchmarkId::new(name, n), |b| {
                b.iter_batched(
                    || MassOperator::new(&model, integration.mass).unwrap(),
                    |mass| {
                        let out = integration
                            .run_assembled(black_box(&model), steps, &request, mass)
                            .unwrap();
                        assert_eq!(out.steps, steps);
                        out.energy.max_balance_error
                    },
                    criterion::BatchSize::LargeInput,
                )
            });
        }
    }
    group.finish();
}

criterion_group!(
    benches,
    run_loop,
    run_loop_large,
    lumped_cd_step,
    lumped_cd_block,
    mass_kind_step,
    spectrum_dense,
    park_step,
    noh_bathe_step,
    memory_triad
);
criterion_main!(benches);
