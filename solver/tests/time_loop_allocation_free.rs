//! Source of truth: the project's cost rule ("a lumped-mass run stays diagonal and O(N) per step,
//! with no dense or global matrices in a time loop") and its companion, "the element loop does
//! no allocation": every per-step kernel is set up once and then steps without touching the heap.
//!
//! ```text
//!   new(model, dt)  --allocates-->  [ step  step  step ... ]  --0 allocations-->
//! ```
//!
//! Proves: one step of lumped CD (and a block of its steps on one thread; on two threads a
//! block allocates a fixed few buffers and its thread, never per step), of CD with each
//! non-diagonal mass (CMM, AMM: partitioned tridiagonal solve, and windows on a long bar; RMM:
//! product with M^-1; with a node's acceleration and T* recomputed from the mass; on a bar of two
//! chunks, none on one thread, and on two none after the first step has started the worker
//! thread kept for the kernel's life), of
//! Park's scheme (global and local stepping,
//! both variants), and of the Noh-Bathe stepper with every mass (the lumped one in its one-sweep
//! step over chunks of the bar, several chunks here; stepped through the public `Integrator`
//! interface, as the shared time loop steps it; the matrix masses also on a bar long enough for
//! their windowed solves) performs exactly zero heap allocations, counted
//! by a global allocator wrapper.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use courant_solver::bench::LumpedStep;
use courant_solver::bench::ParkStep;
use courant_solver::bench::graded_seed_bar;
use courant_solver::bench::{MAX_BLOCK_STEPS, StepBlock, TILE, TWO_THREADS_FROM_NODES};
use courant_solver::bench::{MatrixMassStep, StartState};
use courant_solver::integrator::{InitialState, Integrator};
use courant_solver::schemes::noh_bathe::NohBatheStepper;
use courant_solver::{MassKind, MassOperator, ParkOptions, ParkVariant, Start};

/// The system allocator, counting allocations and reallocations.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is forwarded unchanged to the system allocator.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

/// Most allocations a block of steps on two threads may make: the pipeline's three vectors and
/// what `std::thread::scope` and one spawned thread allocate.
const PIPELINE_ALLOCATIONS: usize = 16;

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Heap allocations made by `steps` calls of `step`.
fn allocations_during(steps: usize, mut step: impl FnMut()) -> usize {
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    for _ in 0..steps {
        step();
    }
    ALLOCATIONS.load(Ordering::SeqCst) - before
}

// All kernels are checked in one function run by `main` (`harness = false` in Cargo.toml): the
// counter is process-wide, so no other thread may run meanwhile (libtest's main thread and its
// other tests would be counted too).
fn main() {
    every_time_stepping_kernel_steps_without_allocating();
    println!("test every_time_stepping_kernel_steps_without_allocating ... ok");
}

fn every_time_stepping_kernel_steps_without_allocating() {
    // 1000 elements: large enough for the partitioned mass solve to use its 8 blocks.
    let n = 1000;
    let model = graded_seed_bar(n).unwrap();
    let element_dt = model.bar().stiffest_element().1;
    let forces = [(0usize, -1.0f64)];

    let v_half = vec![0.0; n + 1];
    let mut lumped = LumpedStep::new(&model, 0.5 * element_dt, &v_half, &v_half);
    assert_eq!(
        allocations_during(200, || {
            std::hint::black_box(lumped.step_with_energy(&forces));
        }),
        0,
        "lumped CD"
    );

    // Blocks of steps (temporal blocking): none on one thread; on two, only the pipeline's
    // counters and the threads, a fixed few per block of up to 1024 steps (not per step).
    let mut block = StepBlock::new(&[0], &[3, 4], &[4]);
    block.forces.fill(-1.0);
    assert_eq!(
        allocations_during(5, || lumped
            .advance_block::<true>(&mut block, MAX_BLOCK_STEPS)),
        0,
        "lumped CD, blocks of steps on one thread"
    );
    let wide = graded_seed_bar(6 * TILE).unwrap();
    let zeros = vec![0.0; 6 * TILE + 1];
    let mut lumped = LumpedStep::new(&wide, 0.5 * element_dt, &zeros, &zeros);
    lumped.set_threads(2);
    lumped.advance_block::<true>(&mut block, MAX_BLOCK_STEPS);
    let per_block = allocations_during(5, || {
        lumped.advance_block::<true>(&mut block, MAX_BLOCK_STEPS)
    }) / 5;
    assert!(
        (1..=PIPELINE_ALLOCATIONS).contains(&per_block),
        "{per_block} allocations per block on two threads"
    );

    // CMM, AMM and RMM on the 1000-element bar (CMM and AMM: the global factor; RMM's `C` too),
    // and on a bar long enough for windows (two groups of 12 windows of 520 rows; RMM's `C` in
    // windows for its mass check), with the mass check (`staggered_kinetic_from_mass`) and one
    // node's acceleration as a time loop asks for them.
    let long = graded_seed_bar(2 * 12 * 512).unwrap();
    for (model, kind) in [
        (&model, MassKind::Consistent),
        (&model, MassKind::Averaged { beta: 0.5 }),
        (&model, MassKind::Reciprocal { beta: 0.5 }),
        (&long, MassKind::Consistent),
        (&long, MassKind::Averaged { beta: 0.5 }),
        (&long, MassKind::Reciprocal { beta: 0.5 }),
    ] {
        let n = model.bar().element_count();
        let element_dt = model.bar().stiffest_element().1;
        let zeros = vec![0.0; n + 1];
        let start = StartState {
            displacement: &zeros,
            half_step_velocity: &zeros,
            acceleration: &zeros,
            residual: &zeros,
            kinetic_staggered: 0.0,
        };
        let operator = MassOperator::new(model, kind).unwrap();
        let dt = 0.5 * kind.critical_courant() * element_dt;
        let windows = operator
            .windows()
            .or(operator.reciprocal_windows())
            .is_some();
        assert_eq!(
            windows,
            n > 1000,
            "{}: windows on the long bar only",
            kind.label()
        );
        let mut kernel = MatrixMassStep::new(dt, model.stiffness(), operator, &start);
        assert_eq!(
            allocations_during(200, || {
                std::hint::black_box(kernel.step_with_energy(&forces));
                std::hint::black_box(kernel.acceleration_at(n / 2));
            }),
            0,
            "{}, {n} elements",
            kind.label()
        );
        assert_eq!(
            allocations_during(3, || {
                std::hint::black_box(kernel.staggered_kinetic_from_mass());
            }),
            0,
            "{}, {n} elements: T* from the mass",
            kind.label()
        );
        assert!(kernel.displacement().iter().all(|u| u.is_finite()));
    }

    // A bar long enough for the matrix-mass step to run in two fixed chunks on two threads: none
    // on one thread; on two, the first step starts the worker (a few allocations, once), then
    // none per step.
    let chunked = graded_seed_bar(TWO_THREADS_FROM_NODES).unwrap();
    let element_dt = chunked.bar().stiffest_element().1;
    for kind in [MassKind::Consistent, MassKind::Reciprocal { beta: 0.5 }] {
        let zeros = vec![0.0; TWO_THREADS_FROM_NODES + 1];
        let start = StartState {
            displacement: &zeros,
            half_step_velocity: &zeros,
            acceleration: &zeros,
            residual: &zeros,
            kinetic_staggered: 0.0,
        };
        let operator = MassOperator::new(&chunked, kind).unwrap();
        let dt = 0.5 * kind.critical_courant() * element_dt;
        let mut kernel = MatrixMassStep::new(dt, chunked.stiffness(), operator, &start);
        assert_eq!(
            allocations_during(20, || {
                std::hint::black_box(kernel.step_with_energy(&forces));
            }),
            0,
            "{}, two chunks on one thread",
            kind.label()
        );
        kernel.set_threads(2);
        let start = allocations_during(1, || {
            std::hint::black_box(kernel.step_with_energy(&forces));
        });
        assert!(
            (1..=PIPELINE_ALLOCATIONS).contains(&start),
            "{}: {start} allocations to start the worker",
            kind.label()
        );
        assert_eq!(
            allocations_during(20, || {
                std::hint::black_box(kernel.step_with_energy(&forces));
            }),
            0,
            "{}, two chunks on two threads after the first step",
            kind.label()
        );
    }

    for local_stepping in [false, true] {
        for variant in [ParkVariant::Free, ParkVariant::Incremental] {
            let options = ParkOptions {
                local_stepping,
                variant,
                ..ParkOptions::default()
            };
            let dt = 0.5 * element_dt;
            let mut park = ParkStep::new(&model, dt, options).unwrap();
            park.start(&model);
            let mut t = 0.0;
            assert_eq!(
                allocations_during(200, || {
                    std::hint::black_box(park.step(&model, t));
                    t += dt;
                }),
                0,
                "{}",
                options.label()
            );
            assert!(park.displacement().iter().all(|u| u.is_finite()));
        }
    }

    // Every mass on the 1000-element bar, and the matrix masses on the long bar too, where
    // their solves run in windows.
    for (model, kind) in [
        (&model, MassKind::Lumped),
        (&model, MassKind::Consistent),
        (&model, MassKind::Averaged { beta: 0.5 }),
        (&model, MassKind::Reciprocal { beta: 0.5 }),
        (&long, MassKind::Consistent),
        (&long, MassKind::Averaged { beta: 0.5 }),
        (&long, MassKind::Reciprocal { beta: 0.5 }),
    ] {
        let n = model.bar().element_count();
        let element_dt = model.bar().stiffest_element().1;
        let zeros = vec![0.0; n + 1];
        let dt = 0.5 * kind.critical_courant() * element_dt;
        let state = InitialState {
            model,
            dt,
            displacement: &zeros,
            velocity: &zeros,
            acceleration: &zeros,
            residual: &zeros,
            kinetic: 0.0,
            start: Start::HalfStep,
            allow_unstable: false,
            mass: MassOperator::new(model, kind).unwrap(),
            threads: 1,
        };
        let mut stepper = NohBatheStepper::start(&0.54, state).unwrap();
        let mut t = 0.0;
        assert_eq!(
            allocations_during(200, || {
                std::hint::black_box(stepper.step(model, t, &forces));
                t += dt;
            }),
            0,
            "noh-bathe {}, {n} elements",
            kind.label()
        );
        assert!(stepper.displacement().iter().all(|u| u.is_finite()));
    }
}
