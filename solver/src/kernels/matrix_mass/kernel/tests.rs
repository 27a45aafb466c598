//! Tests of the blocked matrix-mass step against its whole passes, and of the mass check.

use super::*;
use crate::mass::MassKind;
use crate::mass::windows::{MAX_TILE, WINDOWS_PER_GROUP, tile_rows};
use crate::model::{Bar, Field, Mesh, Model, Support, Supports};

/// The step of `fixtures::matrix_step` (built here from the layers below the kernels): the graded
/// seed bar of `n` elements (modulus 16 to 1) with the given supports, at half the mass's
/// critical Courant number, at rest in `u` and `r` with `v^{1/2} = 1e-3 cos(pi x / 2)` (0 at the
/// last node, `fixtures::smooth_half_velocity`).
fn matrix_kernel(n: usize, kind: MassKind, supports: Supports) -> MatrixMassStep {
    let modulus = Field::Linear {
        left: 16.0,
        right: 1.0,
    };
    let one = Field::Constant(1.0);
    let bar = Bar::new(Mesh::uniform(1.0, n).unwrap(), &modulus, &one, &one).unwrap();
    let model = Model::unloaded(bar, supports);
    let dt = 0.5 * kind.critical_courant() * model.bar().stiffest_element().1;
    let mass = MassOperator::new(&model, kind).unwrap();
    let v_half: Vec<f64> = (0..=n)
        .map(|i| {
            let x = i as f64 / n as f64;
            if i == n {
                0.0
            } else {
                1e-3 * (std::f64::consts::FRAC_PI_2 * x).cos()
            }
        })
        .collect();
    let zeros = vec![0.0; n + 1];
    let start = StartState {
        displacement: &zeros,
        half_step_velocity: &v_half,
        acceleration: &zeros,
        residual: &zeros,
        kinetic_staggered: 0.0,
    };
    MatrixMassStep::new(dt, model.stiffness(), mass, &start)
}

#[test]
fn blocked_step_is_bit_identical_to_whole_passes_for_every_matrix_mass() {
    // Several blocks, loads inside a block, at a block edge and at the last node; and a
    // mesh shorter than a block. The lumped (diagonal) operator too: the kernel accepts any
    // mass (a step with it once did nothing at all).
    let windowed = 2 * WINDOWS_PER_GROUP * MAX_TILE + 333;
    // Its tiles: three groups of 696 rows.
    let tile = tile_rows(windowed + 1);
    assert_eq!(tile, 696);
    for (n, forces) in [
        (
            3 * BLOCK + 37,
            vec![
                (0, 1.0),
                (1, 0.125),
                (7, 0.5),
                (8, -0.5),
                (BLOCK - 1, 0.25),
                (700, -0.25),
                (2 * BLOCK, 0.5),
                (3 * BLOCK + 36, 1.5),
                (3 * BLOCK + 37, 2.0), // the last node
            ],
        ),
        (5, vec![(0, 1.0)]),
        // One and two elements: no interior row, one.
        (1, vec![(0, 1.0), (1, 0.5)]),
        (2, vec![(0, 1.0), (1, 0.5), (2, -1.0)]),
        // n elements, n + 1 nodes: the last node alone in the last block.
        (2 * BLOCK, vec![(0, 1.0)]),
        // CMM and AMM solve in windows ([`crate::mass::windows`]): two groups and a shorter
        // one, loads on a tile edge, a group edge, inside the last group and at the last
        // two nodes (in its short last tile).
        (
            windowed,
            vec![
                (0, 1.0),
                (tile - 1, -0.5),
                (tile, 0.5),
                (WINDOWS_PER_GROUP * tile, -1.0),
                (2 * WINDOWS_PER_GROUP * tile + 300, 2.0),
                (windowed - 1, 0.25),
                (windowed, 1.0), // the last node
            ],
        ),
    ] {
        let steps = if n == windowed { 40 } else { 200 };
        let both_fixed = Supports {
            left: Support::Fixed,
            right: Support::Fixed,
        };
        let supports = [Supports::FREE_FIXED, Supports::default(), both_fixed];
        for (kind, avx2, supports) in [
            MassKind::Reciprocal { beta: 0.5 },
            MassKind::Consistent,
            MassKind::Averaged { beta: 0.5 },
            MassKind::Lumped,
        ]
        .into_iter()
        .flat_map(|kind| [(kind, false), (kind, has_avx2())])
        .flat_map(|(kind, avx2)| supports.map(|s| (kind, avx2, s)))
        {
            let mut blocked = matrix_kernel(n, kind, supports);
            blocked.avx2 = avx2;
            let mut whole = matrix_kernel(n, kind, supports);
            for _ in 0..steps {
                let a = blocked.step_with_energy(&forces);
                let b = whole.whole_pass_step(&forces);
                assert_eq!(a, b, "{kind:?}, n = {n}, {supports:?}");
            }
            for a in [U, V, R] {
                assert_eq!(blocked.state.get(a), whole.state.get(a), "u, v and r^n");
            }
            assert!(
                blocked.displacement().iter().any(|&u| u != 0.0),
                "{kind:?}: the bar moved"
            );
            // Every node; with windows (each node's own solve) every 7th and the tile edges.
            let check = |i: usize| n != windowed || i.is_multiple_of(7) || i % tile < 2;
            for i in (0..=n).filter(|&i| check(i)) {
                assert_eq!(blocked.acceleration_at(i), whole.a[i], "node {i}");
            }
        }
    }
}

#[test]
fn reciprocal_mass_check_is_the_operator_product_and_matches_t_star() {
    // RMM's `M v = A C^-1 A v` solves `C` in windows on a bar long enough for them: the
    // check consumes each tile as it comes and equals, bit for bit, the sum over the
    // operator's own product (the same windows); and it agrees with the running `T*`.
    // A short bar too: `C` solved by the global factor, the same sum.
    let both_fixed = Supports {
        left: Support::Fixed,
        right: Support::Fixed,
    };
    let (long, short) = (2 * WINDOWS_PER_GROUP * MAX_TILE + 333, 50);
    for (n, supports) in [long, short]
        .into_iter()
        .flat_map(|n| [(n, Supports::FREE_FIXED), (n, both_fixed)])
    {
        let kind = MassKind::Reciprocal { beta: 0.5 };
        let mut kernel = matrix_kernel(n, kind, supports);
        assert_eq!(kernel.mass.reciprocal_windows().is_some(), n == long);
        // A consistent start: at rest at the fixed nodes, `T* = 1/2 v M v` (`a^0 = 0`, the
        // fixture's `r^0` is 0).
        let [_, v, ..] = kernel.state.split_mut();
        v[n] = 0.0;
        if supports.left == Support::Fixed {
            v[0] = 0.0;
        }
        kernel.staggered = kernel.staggered_kinetic_from_mass();
        for _ in 0..20 {
            kernel.step_with_energy(&[(1, 1.0), (n / 2, -0.5)]);
        }
        let mut my = vec![0.0; n + 1];
        kernel.mass.apply(kernel.half_step_velocity(), &mut my);
        let MassOperator::Reciprocal { inverse, .. } = &kernel.mass else {
            unreachable!()
        };
        let (dt, v, r) = (kernel.dt, kernel.state.get(V), kernel.state.get(R));
        let expected = 0.5
            * (0..=n).fold(0.0, |sum, i| {
                let a = inverse_row(&inverse.diag, &inverse.off, r, i);
                sum + (v[i] - dt * a) * my[i]
            });
        let checked = kernel.staggered_kinetic_from_mass();
        assert_eq!(checked.to_bits(), expected.to_bits(), "{supports:?}");
        let running = kernel.staggered;
        assert!(
            (checked - running).abs() <= 1e-12 * running.abs(),
            "{supports:?}: {checked} vs {running}"
        );
    }
}

/// The step of a long bar in two fixed chunks (`kernels::matrix_mass::chunks`, its module docs
/// the statement): on one thread and on two the same bits of `u`, `v`, `r^n` and every energy;
/// `u`, `v` and `r^n` the bits of the one-chunk step, its energies equal to that step's sums to
/// round-off (a sum of about 5e4 terms in another order: a relative 1e-9 is a wide margin).
/// CMM and AMM (five groups of windows) and RMM, loads on both sides of the seam and on it,
/// free and fixed ends, with and without the intrinsics.
#[test]
fn chunked_step_gives_the_same_bits_on_one_thread_and_on_two() {
    let n = 4 * WINDOWS_PER_GROUP * MAX_TILE + 333;
    let both_fixed = Supports {
        left: Support::Fixed,
        right: Support::Fixed,
    };
    for (kind, supports, avx2) in [
        MassKind::Consistent,
        MassKind::Averaged { beta: 0.5 },
        MassKind::Reciprocal { beta: 0.5 },
    ]
    .into_iter()
    .flat_map(|kind| [(kind, Supports::FREE_FIXED), (kind, both_fixed)])
    .flat_map(|(kind, s)| [(kind, s, false), (kind, s, has_avx2())])
    {
        let mut single = matrix_kernel(n, kind, supports);
        single.avx2 = avx2;
        assert!(
            single.seam.is_none(),
            "below PARALLEL_FROM_NODES: one chunk"
        );
        let mut chunked = single.clone().with_chunks_from(0);
        let mut threaded = single.clone().with_chunks_from(0);
        threaded.set_threads(2);
        threaded.threads_from = 0;
        let seam = chunked.seam.as_ref().expect("a seam").0.node;
        assert!(seam > n / 4 && seam < 3 * n / 4, "{kind:?}: seam {seam}");
        let forces = [
            (1, 1.0),
            (seam - 2, 0.5),
            (seam - 1, -0.25),
            (seam, 0.75),
            (seam + 1, -1.0),
            (n - 1, 0.125),
        ];
        for step in 0..30 {
            let a = single.step_with_energy(&forces);
            let b = chunked.step_with_energy(&forces);
            let c = threaded.step_with_energy(&forces);
            assert_eq!(b, c, "{kind:?}, step {step}: one thread and two");
            let scale = 1e-9 * (a.kinetic.abs() + a.strain.abs());
            for (x, y) in [
                (a.kinetic, b.kinetic),
                (a.kinetic_staggered, b.kinetic_staggered),
                (a.strain, b.strain),
            ] {
                assert!((x - y).abs() <= scale, "{kind:?}, step {step}: {x} vs {y}");
            }
        }
        for array in [U, V, R] {
            assert_eq!(
                single.state.get(array),
                chunked.state.get(array),
                "{kind:?}"
            );
            assert_eq!(
                single.state.get(array),
                threaded.state.get(array),
                "{kind:?}"
            );
        }
        assert!(
            chunked.displacement()[seam] != 0.0,
            "{kind:?}: the seam moved"
        );
        for i in [0, seam - 1, seam, seam + 1, n] {
            assert_eq!(single.acceleration_at(i), threaded.acceleration_at(i));
        }
    }
}
