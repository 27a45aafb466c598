//! Source of truth: the closed-form discrete spectra Omega(kh) of the lumped (LMM), consistent
//! (CMM), averaged (AMM) and reciprocal (RMM) masses on a uniform bar, and the critical Courant
//! numbers 2/max Omega of central difference (methods.md §5; Fried 1972 for the element bound;
//! González et al. 2018 and Tkachuk & Bischoff 2015 for RMM), evaluated by `courant-references`
//! independently of the solver.
//!
//! ```text
//!   free-free    o---o---o--- ... ---o        fixed-free   //o---o---o--- ... ---o
//!   omega_n = (c/h) Omega(k_n h),  k_n = n pi/L  |  (2n - 1) pi/(2L)
//! ```
//!
//! Proves: the solver's spectra (dense eigen-solutions) equal the closed forms to 1e-10 for every
//! kind, both end conditions and beta in {0, 1/2, 1}; LMM lies below the continuum and CMM above
//! for every mode; AMM(1/2) is fourth order; the solver's exact critical step reproduces the
//! closed-form critical Courant numbers; runs at 1.01 dt_crit blow up and are caught, runs at
//! 0.99 dt_crit stay bounded, for every kind; the element (Fried) and Gershgorin estimates are
//! conservative where theory says so, and Fried's fails for RMM (beta = 3) on a uniform mesh.

use courant_references::spectra::{self as closed, BarEnds, UniformBar};
use courant_solver::analysis::angular_frequencies;
use courant_solver::bench::seed_bar;
use courant_solver::{
    Bar, CentralDifference, CriticalStep, Field, MassKind, MassOperator, Mesh, Model,
    OutputRequest, RunError, StabilityPolicy, Support, Supports, TimeFunction,
};

fn kinds() -> Vec<MassKind> {
    let mut kinds = vec![MassKind::Lumped, MassKind::Consistent];
    for beta in [0.0, 0.5, 1.0] {
        kinds.push(MassKind::Averaged { beta });
        kinds.push(MassKind::Reciprocal { beta });
    }
    kinds
}

fn closed_kind(kind: MassKind) -> closed::MassKind {
    courant::compare::spectrum::closed_form_kind(kind)
}

fn uniform(n: usize, ends: BarEnds) -> (Model, UniformBar) {
    let supports = match ends {
        BarEnds::FreeFree => Supports {
            left: Support::Free,
            right: Support::Free,
        },
        BarEnds::FixedFree => Supports {
            left: Support::Fixed,
            right: Support::Free,
        },
    };
    let bar = Bar::homogeneous(Mesh::uniform(1.0, n).unwrap(), 4.0, 1.0, 1.0).unwrap(); // c = 2
    (
        Model::unloaded(bar, supports),
        UniformBar::new(1.0, 2.0, n, ends).unwrap(),
    )
}

#[test]
fn solver_spectra_equal_the_closed_forms_for_every_kind_and_end_condition() {
    for ends in [BarEnds::FreeFree, BarEnds::FixedFree] {
        for n in [10, 50] {
            let (model, bar) = uniform(n, ends);
            for kind in kinds() {
                let computed = angular_frequencies(&model, kind).unwrap();
                let exact = bar.discrete_frequencies(closed_kind(kind));
                assert_eq!(
                    computed.len(),
                    exact.len(),
                    "{ends:?} N = {n} {kind:?}: mode count"
                );
                let omega_max = exact.iter().copied().fold(0.0, f64::max);
                for (i, (c, e)) in computed.iter().zip(&exact).enumerate() {
                    if *e > 0.0 {
                        assert!(
                            (c - e).abs() <= 1e-10 * e,
                            "{ends:?} N = {n} {kind:?} mode {i}: {c} vs {e}"
                        );
                    } else {
                        // The rigid mode: omega^2 is zero to round-off relative to omega_max^2.
                        assert!(
                            c * c <= 1e-12 * omega_max * omega_max,
                            "{ends:?} N = {n} {kind:?}: rigid mode {c}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn lumped_frequencies_lie_below_the_continuum_and_consistent_ones_above() {
    for ends in [BarEnds::FreeFree, BarEnds::FixedFree] {
        let (model, bar) = uniform(40, ends);
        let continuum = bar.continuum_frequencies();
        let lmm = angular_frequencies(&model, MassKind::Lumped).unwrap();
        let cmm = angular_frequencies(&model, MassKind::Consistent).unwrap();
        for i in 0..continuum.len() {
            if continuum[i] == 0.0 {
                continue; // the rigid mode of the free-free bar
            }
            assert!(
                lmm[i] < continuum[i] && cmm[i] > continuum[i],
                "{ends:?} mode {i}"
            );
        }
    }
}

#[test]
fn averaged_mass_with_beta_one_half_is_fourth_order() {
    // Relative error of the first three fixed-free modes when N doubles: ratio ~16 (AMM(1/2)),
    // ~4 (LMM, CMM: second order).
    let kinds = [
        (MassKind::Averaged { beta: 0.5 }, 15.0, 17.0),
        (MassKind::Lumped, 3.8, 4.2),
        (MassKind::Consistent, 3.8, 4.2),
    ];
    for (kind, lo, hi) in kinds {
        let error = |n: usize| {
            let (model, bar) = uniform(n, BarEnds::FixedFree);
            let omega = angular_frequencies(&model, kind).unwrap();
            (0..3)
                .map(|i| (omega[i] / bar.continuum_frequency(i + 1) - 1.0).abs())
                .collect::<Vec<_>>()
        };
        let (coarse, fine) = (error(40), error(80));
        for i in 0..3 {
            let ratio = coarse[i] / fine[i];
            assert!(
                (lo..=hi).contains(&ratio),
                "{kind:?} mode {}: error ratio {ratio}",
                i + 1
            );
        }
    }
}

#[test]
fn exact_critical_courant_numbers_are_the_closed_forms() {
    // The free-free uniform bar carries the kh = pi saw-tooth mode, so its exact critical
    // Courant number is exactly the infinite-mesh value 2/max Omega.
    let (model, _) = uniform(64, BarEnds::FreeFree);
    let h_over_c = 1.0 / 64.0 / 2.0;
    let expected = |k: MassKind| match k {
        MassKind::Lumped => 1.0,
        MassKind::Consistent => 1.0 / 3.0_f64.sqrt(),
        MassKind::Averaged { beta } | MassKind::Reciprocal { beta } => {
            ((1.0 + 2.0 * beta) / 3.0).sqrt()
        }
    };
    for kind in kinds() {
        let op = MassOperator::new(&model, kind).unwrap();
        let c = CriticalStep::of(&model, kind, &op).unwrap();
        let co = c.exact / h_over_c;
        assert!(
            (co - expected(kind)).abs() < 1e-12,
            "{kind:?}: Co_crit {co}"
        );
        assert!((co - closed::critical_courant(closed_kind(kind))).abs() < 1e-12);
    }
}

#[test]
fn runs_just_above_the_critical_step_blow_up_and_just_below_stay_bounded() {
    let model = seed_bar(50, Field::Constant(1.0), TimeFunction::HEAVISIDE).unwrap();
    for kind in kinds() {
        let op = MassOperator::new(&model, kind).unwrap();
        let dt_crit = CriticalStep::of(&model, kind, &op).unwrap().exact;
        let steps = (200.0 / dt_crit) as usize; // ~ 200 transits at the largest step
        let unstable = CentralDifference {
            mass: kind,
            stability: StabilityPolicy {
                allow_unstable: true,
                ..Default::default()
            },
            ..CentralDifference::new(1.01 * dt_crit)
        };
        match unstable.run(
            &model,
            steps,
            &OutputRequest {
                energy_every: 1000,
                ..Default::default()
            },
        ) {
            Err(RunError::Diverged { error, .. }) => {
                assert!(error.energy_ratio > 1e6, "{kind:?}: {error}")
            }
            other => panic!(
                "{kind:?}: 1.01 dt_crit must diverge, got {:?}",
                other.map(|o| o.steps)
            ),
        }
        let refused = CentralDifference {
            mass: kind,
            ..CentralDifference::new(1.01 * dt_crit)
        };
        assert!(
            matches!(
                refused.run(&model, 10, &OutputRequest::default()),
                Err(RunError::Unstable(_))
            ),
            "{kind:?}"
        );
        let stable = CentralDifference {
            mass: kind,
            ..CentralDifference::new(0.99 * dt_crit)
        };
        let out = stable
            .run(
                &model,
                steps,
                &OutputRequest {
                    energy_every: 1000,
                    ..Default::default()
                },
            )
            .unwrap();
        let worst = out
            .energy
            .samples
            .iter()
            .map(|s| s.kinetic + s.strain)
            .fold(0.0, f64::max);
        assert!(
            worst <= 3.0,
            "{kind:?}: mechanical energy {worst} (work of the step load stays below 2)"
        );
        assert!(
            out.energy.relative_balance_error() < 1e-11,
            "{kind:?}: balance {:e}",
            out.energy.relative_balance_error()
        );
    }
}

#[test]
fn estimators_are_conservative_where_theory_says_and_fried_fails_for_rmm() {
    // Graded and geometric meshes, every support pair: Gershgorin is always conservative, the
    // element (Fried) estimate for the assembled masses.
    let graded = courant_solver::bench::graded_bar(40).unwrap();
    let geometric = Bar::new(
        Mesh::geometric(1.0, 40, 1.1).unwrap(),
        &Field::Constant(3.0),
        &Field::Linear {
            left: 1.0,
            right: 5.0,
        },
        &Field::Constant(1.0),
    )
    .unwrap();
    for bar in [graded, geometric] {
        for (left, right) in [
            (Support::Free, Support::Free),
            (Support::Free, Support::Fixed),
            (Support::Fixed, Support::Fixed),
        ] {
            let model = Model::unloaded(bar.clone(), Supports { left, right });
            for kind in kinds() {
                let op = MassOperator::new(&model, kind).unwrap();
                let c = CriticalStep::of(&model, kind, &op).unwrap();
                assert!(
                    c.gershgorin <= c.exact * (1.0 + 1e-12),
                    "{kind:?}: Gershgorin {} > exact {}",
                    c.gershgorin,
                    c.exact
                );
                if kind.element_bound_holds() {
                    assert!(
                        c.element <= c.exact * (1.0 + 1e-12),
                        "{kind:?}: element {} > exact {}",
                        c.element,
                        c.exact
                    );
                }
            }
        }
    }
    // RMM with beta = 3 (positive definite, gamma = -4/7): the assembled spectrum peaks inside
    // the band at Omega_max = 1/sqrt(-gamma), so the element estimate sqrt((1 + 2 beta)/3) h/c
    // exceeds the exact critical step: Fried's bound does not hold for a reciprocal mass.
    let kind = MassKind::Reciprocal { beta: 3.0 };
    let (model, _) = uniform(50, BarEnds::FixedFree);
    let op = MassOperator::new(&model, kind).unwrap();
    let c = CriticalStep::of(&model, kind, &op).unwrap();
    assert!(
        c.element > c.exact * 1.005,
        "Fried's estimate {} must exceed the exact {}",
        c.element,
        c.exact
    );
    assert!(c.gershgorin <= c.exact);
    assert!(
        (c.infinite_mesh / c.exact - 1.0).abs() < 1e-3,
        "infinite-mesh {} vs exact {}",
        c.infinite_mesh,
        c.exact
    );
}
