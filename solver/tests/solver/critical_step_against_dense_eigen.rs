//! Source of truth: the generalized eigenproblem K u = omega^2 M u of the lumped bar (seed
//! eq. 5), solved densely by nalgebra's symmetric eigen-decomposition of M^-1/2 K M^-1/2 — an
//! independent route to omega_max.
//!
//! Proves: the bisection omega_max equals the dense eigen solution (1e-12 lumped, 1e-9 every mass
//! kind with beta from 0 to 3 and SI-scale data) on
//! graded, geometric and random meshes with every support combination, and the element
//! (Fried) and Gershgorin estimates are conservative on all of them.

use courant_solver::{
    Bar, CriticalStep, Field, InitialConditions, Load, Mesh, Model, Support, Supports, TimeFunction,
};
use nalgebra::DMatrix;

fn dense_omega_max(model: &Model) -> f64 {
    let n = model.bar().node_count();
    let free: Vec<usize> = (0..n).filter(|&i| !model.is_fixed(i)).collect();
    let mut s = DMatrix::<f64>::zeros(free.len(), free.len());
    let k = model.stiffness();
    let m = model.nodal_mass();
    let index = |i: usize| free.iter().position(|&f| f == i);
    for (e, &ke) in k.iter().enumerate() {
        for (a, b, sign) in [
            (e, e, 1.0),
            (e + 1, e + 1, 1.0),
            (e, e + 1, -1.0),
            (e + 1, e, -1.0),
        ] {
            if let (Some(i), Some(j)) = (index(a), index(b)) {
                s[(i, j)] += sign * ke / (m[a] * m[b]).sqrt();
            }
        }
    }
    s.symmetric_eigenvalues().max().sqrt()
}

/// A deterministic pseudo-random sequence in (0.5, 1.5) (no RNG dependency needed).
fn wobble(n: usize, seed: u64) -> Vec<f64> {
    let mut x = seed;
    (0..n)
        .map(|_| {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            0.5 + (x >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

fn bars() -> Vec<(String, Bar)> {
    let graded = Bar::new(
        Mesh::uniform(1.0, 120).unwrap(),
        &Field::Linear {
            left: 16.0,
            right: 1.0,
        },
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )
    .unwrap();
    let geometric =
        Bar::homogeneous(Mesh::geometric(2.0, 80, 1.03).unwrap(), 3.0, 2.0, 0.5).unwrap();
    let n = 150;
    let mut x = vec![0.0];
    for w in wobble(n, 7) {
        x.push(x.last().unwrap() + w);
    }
    let random = Bar::new(
        Mesh::from_nodes(x).unwrap(),
        &Field::PerElement(wobble(n, 11).iter().map(|w| 1e4 * w).collect()),
        &Field::PerElement(wobble(n, 13)),
        &Field::PerElement(wobble(n, 17)),
    )
    .unwrap();
    vec![
        ("graded".into(), graded),
        ("geometric".into(), geometric),
        ("random".into(), random),
    ]
}

#[test]
fn sturm_bisection_equals_dense_eigen_and_estimates_are_conservative() {
    let supports = [
        (Support::Free, Support::Fixed),
        (Support::Fixed, Support::Free),
        (Support::Free, Support::Free),
        (Support::Fixed, Support::Fixed),
    ];
    for (name, bar) in bars() {
        for (left, right) in supports {
            let load = Load::Force {
                node: bar.node_count() / 2,
                magnitude: 1.0,
                time: TimeFunction::HEAVISIDE,
            };
            let model = Model::new(
                bar.clone(),
                Supports { left, right },
                &[load],
                InitialConditions::default(),
            )
            .unwrap();
            let c = CriticalStep::lumped(&model).unwrap();
            let dense = dense_omega_max(&model);
            assert!(
                (c.omega_max - dense).abs() <= 1e-12 * dense,
                "{name} {left:?}-{right:?}: {} vs {dense}",
                c.omega_max
            );
            assert!(
                c.element <= c.exact && c.gershgorin <= c.exact,
                "{name} {left:?}-{right:?}: {c:?}"
            );
        }
    }
}

/// Every mass kind, beta well outside [0, 1], heavy and light densities, SI-like scales: the
/// bisection's omega_max equals the dense eigen-solution (an independent route, `spectrum`), and
/// Gershgorin (all kinds) and Fried (assembled masses) are conservative against the dense value.
#[test]
fn every_mass_kind_matches_dense_eigen_and_estimates_are_conservative() {
    use courant_solver::analysis::angular_frequencies;
    use courant_solver::{MassKind, MassOperator};
    let mut kinds = vec![MassKind::Lumped, MassKind::Consistent];
    for beta in [0.0, 0.5, 1.0, 1.5, 3.0] {
        kinds.push(MassKind::Averaged { beta });
        kinds.push(MassKind::Reciprocal { beta });
    }
    let bars = [
        Bar::new(
            Mesh::uniform(10.0, 10).unwrap(),
            &Field::Constant(2.1e11),
            &Field::Constant(7850.0),
            &Field::Constant(0.01),
        )
        .unwrap(),
        Bar::new(
            Mesh::uniform(1.0, 1).unwrap(),
            &Field::Constant(1.0),
            &Field::Constant(100.0),
            &Field::Constant(1.0),
        )
        .unwrap(),
        Bar::new(
            Mesh::uniform(1.0, 2).unwrap(),
            &Field::Constant(1.0),
            &Field::Constant(1.0),
            &Field::Constant(1.0),
        )
        .unwrap(),
        Bar::new(
            Mesh::geometric(1.0, 30, 1.1).unwrap(),
            &Field::Linear {
                left: 16.0,
                right: 1.0,
            },
            &Field::Linear {
                left: 1.0,
                right: 30.0,
            },
            &Field::Constant(1.0),
        )
        .unwrap(),
    ];
    for (b, bar) in bars.iter().enumerate() {
        for (left, right) in [
            (Support::Free, Support::Fixed),
            (Support::Free, Support::Free),
            (Support::Fixed, Support::Free),
        ] {
            let model = Model::unloaded(bar.clone(), Supports { left, right });
            for &kind in &kinds {
                let op = MassOperator::new(&model, kind).unwrap();
                let c = CriticalStep::of(&model, kind, &op).unwrap();
                let dense = *angular_frequencies(&model, kind).unwrap().last().unwrap();
                assert!(
                    (c.omega_max - dense).abs() <= 1e-9 * dense,
                    "bar {b} {left:?}-{right:?} {kind:?}: bisection {} vs dense {dense}",
                    c.omega_max
                );
                let dt_dense = 2.0 / dense;
                assert!(
                    c.gershgorin <= dt_dense * (1.0 + 1e-12),
                    "bar {b} {kind:?}: Gershgorin {} > {dt_dense}",
                    c.gershgorin
                );
                if kind.element_bound_holds() {
                    assert!(
                        c.element <= dt_dense * (1.0 + 1e-12),
                        "bar {b} {kind:?}: element {} > {dt_dense}",
                        c.element
                    );
                }
            }
        }
    }
}
