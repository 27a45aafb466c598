//! Source of truth: the central-difference step itself (seed eqs. 2-4, methods.md §2): a block of
//! steps (temporal blocking, `kernels::lumped::tiled` / `kernels::lumped::pipeline`) must be the
//! same arithmetic as the steps one at a time, so the shared time loop must give the same run
//! either way.
//!
//! ```text
//!   allow_unstable = false  ->  blocks of up to 1024 steps  ┐  every profile, history sample,
//!   allow_unstable = true   ->  one step at a time          ┘  energy sample and error equal
//! ```
//!
//! Proves: (1) the whole `RunOutput` (profiles, histories, energy log, balance, scale) of the
//! blocked loop equals the single-step loop's, bit for bit, on bars of 1 to 3000 elements, free or
//! fixed, with loads at the ends, on adjacent nodes and across a tile edge (1023/1024), histories
//! at both ends and mid-bar, every `history_every` / `energy_every`, profiles at steps 1, 2, the
//! middle and the end, runs of 1 to 2100 steps; (2) a guard trip inside a block (a stable run with
//! a small `blowup_energy_ratio`) reports the same step, time, energy ratio, node and partial
//! output as single steps; (3) the thread count a scene plans with (`Integration::threads`) is the
//! kernel's, on both sides of the 1e5-node threshold.

use courant_solver::integrator::OutputRequest;
use courant_solver::{
    Bar, CentralDifference, Field, InitialConditions, Load, Mesh, Model, RunError, RunOutput,
    Support, Supports, TimeFunction,
};

const FREE: Supports = Supports {
    left: Support::Free,
    right: Support::Free,
};

/// A graded bar (E from 16 to 1) of `n` elements with forces on `loads` (ramps and pulses) and a
/// small smooth initial velocity.
fn graded_model(n: usize, loads: &[usize], supports: Supports) -> Model {
    let modulus = Field::Linear {
        left: 16.0,
        right: 1.0,
    };
    let bar = Bar::new(
        Mesh::uniform(1.0, n).unwrap(),
        &modulus,
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )
    .unwrap();
    let loads: Vec<Load> = loads
        .iter()
        .enumerate()
        .map(|(k, &node)| Load::Force {
            node,
            magnitude: 1.0 + k as f64 * 0.37,
            time: if k % 2 == 0 {
                TimeFunction::Ramp {
                    start: 0.0,
                    rise: 0.01,
                }
            } else {
                TimeFunction::Pulse {
                    start: 0.001,
                    duration: 0.003,
                }
            },
        })
        .collect();
    let fixed_right = supports.right == Support::Fixed;
    let velocity: Vec<f64> = (0..=n)
        .map(|i| {
            if i == n && fixed_right {
                0.0
            } else {
                (i as f64 * 0.37).sin() * 1e-3
            }
        })
        .collect();
    let initial = InitialConditions {
        displacement: None,
        velocity: Some(velocity),
    };
    Model::new(bar, supports, &loads, initial).unwrap()
}

/// Lumped CD at 0.9 of the stiffest element's step; `single`: allow unstable runs, which makes
/// the loop step one step at a time (the same arithmetic, no blocks).
fn run(
    model: &Model,
    steps: usize,
    request: &OutputRequest,
    single: bool,
    ratio: Option<f64>,
) -> Result<RunOutput, RunError> {
    let dt = 0.9 * model.bar().stiffest_element().1;
    let mut cd = CentralDifference::new(dt).integration();
    cd.stability.allow_unstable = single;
    if let Some(ratio) = ratio {
        cd.stability.blowup_energy_ratio = ratio;
    }
    cd.run(model, steps, request)
}

#[test]
fn the_blocked_loop_gives_the_single_step_run_bit_for_bit() {
    let cases = [
        (1usize, vec![0usize], Supports::FREE_FIXED),
        (2, vec![0, 1, 2], FREE),
        (3, vec![2, 3], FREE),
        (1023, vec![0, 1022, 1023], FREE),
        (2047, vec![1022, 1023, 1024, 2046], Supports::FREE_FIXED),
        (3000, vec![0, 1500, 1501, 2999, 3000], FREE),
    ];
    let mut compared = 0;
    for (n, loads, supports) in cases {
        let model = graded_model(n, &loads, supports);
        for steps in [1usize, 2, 3, 64, 1025, 2100] {
            for (history_every, energy_every) in [(1, 1), (3, 5), (7, 1000)] {
                let mut profile_steps = vec![1, 2, steps / 2, steps - 1, steps];
                profile_steps.retain(|&p| (1..=steps).contains(&p));
                let request = OutputRequest {
                    profile_steps,
                    history_nodes: vec![0, n / 2, n, n - 1],
                    history_every,
                    energy_every,
                };
                let blocked = run(&model, steps, &request, false, None).unwrap();
                let single = run(&model, steps, &request, true, None).unwrap();
                assert!(!blocked.profiles.is_empty() && !blocked.energy.samples.is_empty());
                // `{:?}` of f64 is its shortest round-trip text: equal texts are equal bits.
                assert_eq!(
                    format!("{blocked:?}"),
                    format!("{single:?}"),
                    "n {n}, steps {steps}, history_every {history_every}, energy_every {energy_every}"
                );
                compared += 1;
            }
        }
    }
    assert_eq!(compared, 6 * 6 * 3);
}

#[test]
fn a_guard_trip_inside_a_block_names_the_node_of_its_own_step() {
    // A uniform free-free bar pushed at node 0 by a pulse: the wave front carries the largest
    // |u| forward, so the node at the trip step and 1000 steps later differ.
    let n = 3000;
    let bar = Bar::new(
        Mesh::uniform(1.0, n).unwrap(),
        &Field::Constant(1.0),
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )
    .unwrap();
    let load = Load::Force {
        node: 0,
        magnitude: 1.0,
        time: TimeFunction::Pulse {
            start: 0.0,
            duration: 0.02,
        },
    };
    let model = Model::new(bar, FREE, &[load], InitialConditions::default()).unwrap();
    let request = OutputRequest {
        history_nodes: vec![0, 10],
        ..OutputRequest::default()
    };
    for ratio in [1.000_000_1, 1.001] {
        let outcome = |single| run(&model, 3000, &request, single, Some(ratio));
        match (outcome(false), outcome(true)) {
            (
                Err(RunError::Diverged {
                    error: blocked,
                    partial: blocked_partial,
                }),
                Err(RunError::Diverged {
                    error: single,
                    partial: single_partial,
                }),
            ) => {
                assert!(blocked.step % 1024 != 0, "the trip is inside a block");
                assert_eq!(
                    format!("{blocked:?}"),
                    format!("{single:?}"),
                    "ratio {ratio}"
                );
                assert_eq!(
                    format!("{blocked_partial:?}"),
                    format!("{single_partial:?}")
                );
            }
            (a, b) => panic!(
                "ratio {ratio}: both runs must trip the guard: {:?} / {:?}",
                a.map(|o| o.steps),
                b.map(|o| o.steps)
            ),
        }
    }
}

/// The thread count is a setting of the run: a lumped run that must stay stable, and a
/// matrix-mass run (its step in two fixed chunks, `kernels::matrix_mass::chunks`), use
/// `Integration::threads` from 1e5 nodes on and one thread below; a lumped run that steps
/// singly (unstable runs allowed) uses one whatever the setting.
#[test]
fn a_run_takes_its_thread_count_from_its_integration() {
    for elements in [99_998usize, 99_999] {
        let model = courant_solver::bench::graded_seed_bar(elements).unwrap();
        let dt = 0.5 * model.bar().stiffest_element().1;
        let two = |seed: CentralDifference| courant_solver::Integration {
            threads: Some(2),
            ..seed.integration()
        };
        let expected = if elements + 1 >= 100_000 { 2 } else { 1 };
        let lumped = two(CentralDifference::new(dt));
        assert_eq!(lumped.threads(&model), expected, "{} nodes", elements + 1);
        let mut unstable = CentralDifference::new(dt);
        unstable.stability.allow_unstable = true;
        let consistent = CentralDifference {
            mass: courant_solver::MassKind::Consistent,
            ..CentralDifference::new(dt)
        };
        assert_eq!(two(unstable).threads(&model), 1, "{unstable:?}");
        assert_eq!(two(consistent).threads(&model), expected, "{consistent:?}");
    }
}
