//! Source of truth: momentum conservation of the contact update (methods.md §7: every contact
//! momentum acts along N, and the relative mass penalty `M_p = m_p [[1,-1],[-1,1]]` has
//! `1^T M_p = 0`), the hand result of a bar bouncing off a rigid wall (elastic, impulse
//! `2 m v0`, force `Z v0` for `2L/c`; methods.md §7), and the input rules of `courant_solver::contact`.
//!
//! ```text
//!   striker  o--o--o--a  |  b--o--o--o--o  target        bar  o--o--o--c |//  wall
//!            v0 ->                at rest                     v0 ->
//! ```
//!
//! Proves: (1) for two bodies the cumulative contact impulse equals the target's momentum gain
//! and the striker's loss to round-off, for all four schemes; (2) the Lagrange multiplier
//! scheme at Co = 1 holds a bar on a wall exactly (force `Z v0` at every level of the contact
//! `[0, 2L/c)`); the release level carries 0 instead of the mean `Z v0/2`, so the impulse is
//! `2 m v0 - Z v0 dt/2` (the method cannot anticipate a release); (2b) once the bodies have
//! separated, `kinetic_staggered + strain` is central difference's conserved energy of the free
//! bars (Hughes 1987, §9.1): constant to round-off, while the full-step `kinetic + strain`
//! oscillates; (3) outputs (histories, profiles) are
//! recorded as requested; (4) bad input is refused with a typed error naming the rule, and a
//! step above the applicable limit is refused naming dt, dt_crit and the limit that binds.

use courant_solver::contact::{
    ContactError, ContactIntegrator, ContactProblem, ContactRequest, ContactScheme, MassPenalty,
    Penalty, StepLimit,
};
use courant_solver::{Bar, End, InitialConditions, Mesh, Model, StabilityPolicy, Supports};

fn fig5(n: usize) -> ContactProblem {
    ContactProblem::fig5(n, 1.0).unwrap()
}

fn schemes(problem: &ContactProblem) -> Vec<ContactScheme> {
    let bipenalty = problem.penalty(25.0, MassPenalty::Ratio(1.0)).unwrap();
    let penalty = problem.penalty(0.25, MassPenalty::None).unwrap();
    vec![
        ContactScheme::Penalty {
            stiffness: penalty.stiffness,
        },
        ContactScheme::Bipenalty(bipenalty),
        ContactScheme::PredictorCorrector(bipenalty),
        ContactScheme::LagrangeMultiplier,
    ]
}

#[test]
fn two_body_contact_impulse_equals_the_target_momentum_gain_for_every_scheme() {
    let problem = fig5(20);
    for scheme in schemes(&problem) {
        let dt = 0.5 / 20.0;
        let run = ContactIntegrator::new(dt, scheme)
            .run(&problem, 200, &ContactRequest::default())
            .unwrap();
        let gain = run.final_momentum[1] - run.initial_momentum[1];
        let loss = run.initial_momentum[0] - run.final_momentum[0];
        assert!(
            run.impulse > 0.5,
            "{}: impulse {}",
            scheme.label(),
            run.impulse
        );
        for (what, value) in [("target gain", gain), ("striker loss", loss)] {
            assert!(
                (value - run.impulse).abs() <= 1e-14 * run.impulse,
                "{}: {what} {value} vs impulse {}",
                scheme.label(),
                run.impulse
            );
        }
        let last = run.history.last().unwrap();
        assert_eq!(last.impulse, run.impulse);
    }
}

#[test]
fn after_separation_the_staggered_energy_is_conserved_and_the_full_step_one_is_not() {
    let problem = fig5(40);
    for scheme in schemes(&problem) {
        // Co = 0.5: below every scheme's limit (as in the impulse test above).
        let dt = 0.5 / 40.0;
        let run = ContactIntegrator::new(dt, scheme)
            .run(&problem, 800, &ContactRequest::default())
            .unwrap();
        // The last contact level, then free flight.
        let last_active = run.history.iter().rposition(|s| s.active).unwrap();
        let free = &run.history[last_active + 2..];
        assert!(
            free.len() > 100,
            "{}: too short a free flight",
            scheme.label()
        );
        let conserved = |s: &courant_solver::contact::ContactSample| s.kinetic_staggered + s.strain;
        let full = |s: &courant_solver::contact::ContactSample| s.kinetic + s.strain;
        let spread = |f: &dyn Fn(&courant_solver::contact::ContactSample) -> f64| {
            let (lo, hi) = free
                .iter()
                .map(f)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), e| {
                    (lo.min(e), hi.max(e))
                });
            (hi - lo) / hi
        };
        let label = scheme.label();
        assert!(
            spread(&conserved) < 1e-13,
            "{label}: conserved energy varies {:e}",
            spread(&conserved)
        );
        assert!(
            spread(&full) > 1e-6,
            "{label}: full-step energy constant {:e}",
            spread(&full)
        );
    }
}

#[test]
fn lagrange_multiplier_holds_a_bar_on_a_wall_exactly_at_courant_one() {
    let n = 50;
    let bar = Bar::homogeneous(Mesh::uniform(1.0, n).unwrap(), 1.0, 1.0, 1.0).unwrap();
    let problem = ContactProblem::wall_impact(bar, End::Right, 1.0, 0.0).unwrap();
    let dt = 1.0 / n as f64;
    let run = ContactIntegrator::new(dt, ContactScheme::LagrangeMultiplier)
        .run(&problem, 3 * n, &ContactRequest::default())
        .unwrap();
    // Z v0 = 1 at every level of [0, 2L/c) (the start level spans [0, dt/2]); at 2L/c, where
    // the exact force drops to 0, the held node needs no impulse, and the forward increment
    // method cannot anticipate the release: that level delivers 0, not the mean 1/2.
    for s in &run.history {
        let expected = if s.step < 2 * n { 1.0 } else { 0.0 };
        assert!(
            (s.force - expected).abs() < 1e-12,
            "level {}: {} vs {expected}",
            s.step,
            s.force
        );
    }
    // Hence the impulse falls short of the elastic bounce 2 m v0 by Z v0 dt/2 (O(h)).
    let expected = 2.0 - 0.5 * dt;
    assert!(
        (run.impulse - expected).abs() < 1e-12,
        "impulse {}",
        run.impulse
    );
    assert!((run.final_momentum[0] - (1.0 - expected)).abs() < 1e-12);
}

#[test]
fn histories_and_profiles_are_recorded_as_requested() {
    let problem = fig5(10);
    let request = ContactRequest {
        history_every: 7,
        profile_steps: vec![10, 0, 10, 5],
    };
    let run = ContactIntegrator::new(0.1, ContactScheme::LagrangeMultiplier)
        .run(&problem, 50, &request)
        .unwrap();
    let steps: Vec<usize> = run.history.iter().map(|s| s.step).collect();
    assert_eq!(steps, vec![0, 7, 14, 21, 28, 35, 42, 49, 50]);
    let profile_steps: Vec<usize> = run.profiles.iter().map(|p| p.step).collect();
    assert_eq!(profile_steps, vec![0, 5, 10]);
    assert_eq!(run.profiles[2].stress.len(), 2);
    assert_eq!(run.profiles[2].stress[0].len(), 10);
    assert_eq!(run.profiles[2].stress[1].len(), 20);
    // Co = 1: at t = 1 the compressive pulse -Z v0/2 has just crossed the whole striker
    // (length 1) and half of the target, exactly.
    let striker = &run.profiles[2].stress[0];
    let target = &run.profiles[2].stress[1];
    assert!(
        target[..10].iter().all(|&s| (s + 0.5).abs() < 1e-12),
        "{target:?}"
    );
    assert!(target[10..].iter().all(|&s| s.abs() < 1e-12), "{target:?}");
    assert!(
        striker.iter().all(|&s| (s + 0.5).abs() < 1e-12),
        "{striker:?}"
    );
    for s in &run.history {
        let sum = s.kinetic + s.strain + s.penalty_spring + s.penalty_kinetic;
        assert!((s.total - sum).abs() <= 1e-15 * s.total.max(1.0));
        assert_eq!(s.penalty_spring, 0.0);
    }
}

#[test]
fn bad_contact_input_is_refused_with_the_rule() {
    let problem = fig5(10);
    let err = |scheme: ContactScheme, dt: f64, request: &ContactRequest| {
        ContactIntegrator::new(dt, scheme)
            .run(&problem, 10, request)
            .unwrap_err()
            .to_string()
    };
    let ok = ContactRequest::default();
    assert_eq!(
        err(ContactScheme::LagrangeMultiplier, -1.0, &ok),
        "dt = -1 must be positive and finite"
    );
    assert_eq!(
        err(ContactScheme::Penalty { stiffness: 0.0 }, 0.01, &ok),
        "penalty stiffness k_s = 0 must be positive and finite"
    );
    let negative_mass = ContactScheme::Bipenalty(Penalty {
        stiffness: 1.0,
        mass: -1.0,
    });
    assert_eq!(
        err(negative_mass, 0.01, &ok),
        "penalty mass m_p = -1 must be finite and not negative"
    );
    let late = ContactRequest {
        profile_steps: vec![11],
        ..Default::default()
    };
    assert_eq!(
        err(ContactScheme::LagrangeMultiplier, 0.01, &late),
        "profile step 11 is after the last step 10"
    );
    // Nothing moves: refused.
    let bar = || Bar::homogeneous(Mesh::uniform(1.0, 4).unwrap(), 1.0, 1.0, 1.0).unwrap();
    let free = Supports::default();
    let idle = ContactProblem::pair(
        Model::unloaded(bar(), free),
        Model::unloaded(bar(), free),
        0.1,
    )
    .unwrap();
    let e = ContactIntegrator::new(0.1, ContactScheme::LagrangeMultiplier)
        .run(&idle, 5, &ok)
        .unwrap_err();
    assert!(e.to_string().starts_with("nothing excites"), "{e}");
    // Initial penetration through the initial displacement: refused.
    let pushed = Model::new(
        bar(),
        free,
        &[],
        InitialConditions {
            displacement: Some(vec![0.0, 0.0, 0.0, 0.0, 0.2]),
            velocity: None,
        },
    )
    .unwrap();
    let e = ContactProblem::pair(pushed, Model::unloaded(bar(), free), 0.1).unwrap_err();
    assert!(e.to_string().contains("initial penetration"), "{e}");
}

#[test]
fn a_step_above_the_limit_is_refused_naming_dt_dt_crit_and_the_binding_limit() {
    let problem = fig5(100);
    let pc = ContactScheme::PredictorCorrector(
        problem.penalty(0.25e4, MassPenalty::Ratio(1.0)).unwrap(),
    );
    let error = ContactIntegrator::new(0.51 * 0.01, pc)
        .run(&problem, 10, &ContactRequest::default())
        .unwrap_err();
    let ContactError::Unstable(unstable) = &error else {
        panic!("expected a refusal, got {error}");
    };
    assert_eq!(unstable.limit, StepLimit::PredictorCorrector);
    assert_eq!(unstable.scheme, "predictor-corrector");
    // sqrt((m_red + m_p)/k_s) = sqrt((1/4 + 2500/4) m/(2500 k)) h/c: Co = 0.5 sqrt(2501/2500).
    let expected = 0.5 * (2501.0_f64 / 2500.0).sqrt();
    assert!((unstable.critical_courant - expected).abs() < 1e-12);
    let text = error.to_string();
    for part in [
        "dt = 5.100000e-3",
        "dt_crit = 5.001000e-3",
        "predictor-corrector limit k_s dt^2/(m_c + m_p) <= 1",
        "allow_unstable",
    ] {
        assert!(text.contains(part), "missing {part:?} in {text}");
    }
    // The Lagrange multiplier scheme at Co = 1 on free-free bars is exactly at its limit and
    // accepted; just above it is refused by the contact-free bulk.
    let lm = ContactIntegrator::new(0.01, ContactScheme::LagrangeMultiplier);
    assert!(lm.check_stability(&problem).is_ok());
    let above = ContactIntegrator::new(0.0101, ContactScheme::LagrangeMultiplier);
    let Err(ContactError::Unstable(e)) = above.check_stability(&problem) else {
        panic!("expected a refusal");
    };
    assert_eq!(e.limit, StepLimit::ContactFree);
    // Allowed, the same step runs.
    let allowed = ContactIntegrator {
        stability: StabilityPolicy {
            allow_unstable: true,
            ..Default::default()
        },
        ..above
    };
    assert!(allowed.check_stability(&problem).is_ok());
}
