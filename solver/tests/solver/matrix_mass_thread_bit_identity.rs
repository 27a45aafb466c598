//! Source of truth: the project's determinism rule ("the same scene gives bit-identical output
//! whatever the thread count"), for central difference with a matrix mass, whose step on a bar of
//! 1e5 nodes or more runs in two fixed chunks (`kernels::matrix_mass::chunks`: the chunks are
//! fixed by the bar, the threads only run them), on two threads from
//! `TWO_THREADS_FROM_NODES` (1e5) nodes on when the run has two.
//!
//! Proves: on the graded seed bar of 5 10^5 elements (loaded at its free end, fixed at the other)
//! moving from a smooth initial velocity over the whole bar, so every node moves from the first
//! step, CD with CMM and with AMM(1/2) (their windowed solve) and with RMM(1/2) writes the same energies (every step), histories (at the
//! loaded end, on both sides of each mass's seam, beyond it) and profiles on one thread and on
//! two, bit for bit; and the two-thread run does use two threads (`Integration::threads`).

use courant_solver::integrator::OutputRequest;
use courant_solver::{
    CentralDifference, End, InitialConditions, Integration, Load, MassKind, Model, Supports,
    TimeFunction,
};

#[test]
fn cd_with_each_matrix_mass_gives_the_same_bits_on_one_thread_and_on_two() {
    let n = 500_000;
    assert!(n >= courant_solver::bench::TWO_THREADS_FROM_NODES);
    let bar = courant_solver::bench::graded_bar(n).unwrap();
    let load = Load::Traction {
        end: End::Left,
        stress: -1.0,
        time: TimeFunction::HEAVISIDE,
    };
    // sin(pi x) sin(7 pi x): smooth, zero at both ends (the right one fixed).
    let velocity = (0..=n)
        .map(|i| {
            if i == n {
                return 0.0;
            }
            let x = i as f64 / n as f64;
            (std::f64::consts::PI * x).sin() * (7.0 * std::f64::consts::PI * x).sin()
        })
        .collect();
    let initial = InitialConditions {
        displacement: None,
        velocity: Some(velocity),
    };
    let model = Model::new(bar, Supports::FREE_FIXED, &[load], initial).unwrap();
    let element_dt = model.bar().stiffest_element().1;
    let steps = 40;
    let request = OutputRequest {
        profile_steps: vec![steps / 2, steps],
        // Beside each seam: CMM/AMM at the first row of group 20 of 41 (12 tiles of 1024 rows
        // each: 245 760), RMM at n/2 rounded down to a multiple of 512 (249 856).
        history_nodes: vec![0, 245_759, 245_760, 249_855, 249_856, n / 2 + 700, n],
        history_every: 1,
        energy_every: 1,
    };
    for kind in [
        MassKind::Consistent,
        MassKind::Averaged { beta: 0.5 },
        MassKind::Reciprocal { beta: 0.5 },
    ] {
        let run = |threads: usize| {
            let integration = Integration {
                threads: Some(threads),
                ..CentralDifference {
                    mass: kind,
                    ..CentralDifference::new(0.5 * kind.critical_courant() * element_dt)
                }
                .integration()
            };
            assert_eq!(integration.threads(&model), threads, "{kind:?}");
            let out = integration.run(&model, steps, &request).unwrap();
            assert_eq!(out.steps, steps);
            format!("{out:?}")
        };
        let (one, two) = (run(1), run(2));
        assert!(one == two, "{kind:?}: one thread and two differ");
    }
}
