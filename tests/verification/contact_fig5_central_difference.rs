//! Source of truth: the seed's Fig. 5 problem (Kolman et al., section 3.2: "the results of the
//! central difference method for higher value of beta_s shown significant spurious
//! oscillations of contact forces"); the closed-form critical Courant numbers of two equal bars
//! with a relative (bi)penalty link, `Cr_two(beta_s) = Cr_wall(2 beta_s)`
//! (`courant_references::contact`, methods.md §7); the exact impact force (`ImpactForce`).
//!
//! ```text
//!   striker L1 = 1, v0 = 1 ->       target L2 = 2, at rest
//!   o--o--o-- ... --o--a | b--o--o--o-- ... --o--o--o      E = rho = A = 1, h = 0.01
//!                     k_s, m_p (relative)                  Co = 0.5
//! ```
//!
//! Proves:
//! - CD with penalty only at Co = 0.5 is refused for beta_s >= 25, as the closed form says
//!   (Cr_two(25) = 0.1980 < 0.5), and accepted at beta_s = 0.25 (Cr_two = 0.9718);
//! - allowed anyway, it pumps energy into the bodies at every contact (the impact leaves them
//!   with about 100 times the striker's kinetic energy at beta_s = 25): the guard, set to the
//!   ratio 10 that no passive contact can reach, stops the run and keeps the history up to it;
//!   on a persistent contact (a bar pressed on a wall) the default guard (1e6) trips too;
//! - CD with bipenalty r = 1 is accepted at Co = 0.5 for every beta_s (the contact-free limit
//!   binds) and stays bounded on the impact: kinetic + strain energy within 4 % of the input
//!   (measured +3.3 %), impulse within 0.5 % (1.5 % for the soft beta_s = 0.25, whose contact
//!   lasts longer; measured 0.43 % and 1.0 %) and the force's plateau mean within 0.5 % of
//!   Z v0/2 (measured -0.32 %) — but for beta_s >= 25 the contact chatters: the force jumps
//!   between 0 (gap open, 40 % of the levels) and about 1.87 times the plateau in a cycle of
//!   about five steps. These figures do not depend on beta_s from 25 to 2.5e7: with r = 1 the
//!   penalty pair is a spring-mass of frequency sqrt(k_s/m_p) = 2c/h, so the penetration stays
//!   about 1.35 h and eps_s x penetration (about 1.35 beta_s Z v0) is no measure of the force.
//!   At beta_s = 0.25 the plateau is clean (within 0.02 %);
//! - a documented weakness: CD bipenalty with r = 1 gains energy on a persistent chattering
//!   contact although its (linear, persistent-contact) limit holds: switching H(g) on and off is
//!   not energy-neutral. Bar pressed on a wall, beta_s = 25, Co = 0.5: kinetic + strain energy
//!   goes from 2.25 to above 20 within 100 L/c (beta_s = 0.25 only dissipates).

use courant_references::contact::{ImpactBar, ImpactForce, two_bar_critical_courant};
use courant_solver::StabilityPolicy;
use courant_solver::contact::{
    ContactError, ContactIntegrator, ContactProblem, ContactRequest, ContactRun, ContactScheme,
    MassPenalty, StepLimit,
};

const DT: f64 = 0.005;

fn fig5() -> ContactProblem {
    ContactProblem::fig5(100, 1.0).unwrap()
}

fn penalty_only(beta_s: f64) -> ContactScheme {
    let p = fig5().penalty(beta_s, MassPenalty::None).unwrap();
    ContactScheme::Penalty {
        stiffness: p.stiffness,
    }
}

fn bipenalty(beta_s: f64) -> ContactScheme {
    ContactScheme::Bipenalty(fig5().penalty(beta_s, MassPenalty::Ratio(1.0)).unwrap())
}

fn allowed(scheme: ContactScheme, blowup_energy_ratio: f64) -> ContactIntegrator {
    ContactIntegrator {
        stability: StabilityPolicy {
            allow_unstable: true,
            blowup_energy_ratio,
        },
        ..ContactIntegrator::new(DT, scheme)
    }
}

#[test]
fn cd_penalty_at_courant_half_is_refused_from_beta_s_25_as_the_closed_form_says() {
    let problem = fig5();
    for beta_s in [0.25e2, 0.25e4, 0.25e8] {
        let closed = two_bar_critical_courant(beta_s, 0.0).unwrap();
        assert!(closed < 0.5, "beta_s = {beta_s}: Cr = {closed}");
        let error = ContactIntegrator::new(DT, penalty_only(beta_s))
            .run(&problem, 600, &ContactRequest::default())
            .unwrap_err();
        let ContactError::Unstable(e) = &error else {
            panic!("beta_s = {beta_s}: {error}")
        };
        assert_eq!(e.limit, StepLimit::ContactActive);
        assert!(
            (e.critical_courant / closed - 1.0).abs() < 1e-8,
            "{e:?} vs {closed}"
        );
        assert!((e.courant - 0.5).abs() < 1e-12);
    }
    assert!((two_bar_critical_courant(25.0, 0.0).unwrap() - 0.19801).abs() < 1e-5);
    // beta_s = 0.25: Cr_two = Cr_wall(0.5) = 0.9718 > 0.5, accepted.
    let soft = ContactIntegrator::new(DT, penalty_only(0.25));
    assert!(soft.check_stability(&problem).is_ok());
}

#[test]
fn allowed_cd_penalty_pumps_energy_and_the_guard_stops_it_keeping_the_history() {
    let problem = fig5();
    let input = 0.5; // striker kinetic energy rho A L1 v0^2/2
    // Default guard: the impact ends, with the bodies carrying ~100x the input energy.
    let run = allowed(penalty_only(25.0), 1e6)
        .run(&problem, 600, &ContactRequest::default())
        .unwrap();
    let last = run.history.last().unwrap();
    assert!(last.kinetic + last.strain > 100.0 * input, "{last:?}");
    // Guard at 10: stopped, history kept up to and including the step that tripped it.
    let error = allowed(penalty_only(25.0), 10.0)
        .run(&problem, 600, &ContactRequest::default())
        .unwrap_err();
    let ContactError::Diverged { error, partial } = error else {
        panic!("expected a divergence")
    };
    assert!(error.energy_ratio > 10.0 && error.step < 600, "{error}");
    assert_eq!(partial.steps, error.step);
    assert_eq!(partial.history.len(), error.step + 1);
    let tripped = partial.history.last().unwrap();
    assert!(tripped.kinetic + tripped.strain > 10.0 * input);
    assert!(
        error.to_string().starts_with("run diverged at step"),
        "{error}"
    );
    // Persistent contact under a load: the default guard trips.
    let wall = courant_solver::bench::loaded_wall(100, 0.0).unwrap();
    let penalty = wall.penalty(25.0, MassPenalty::None).unwrap();
    let error = allowed(
        ContactScheme::Penalty {
            stiffness: penalty.stiffness,
        },
        1e6,
    )
    .run(&wall, 4000, &ContactRequest::default())
    .unwrap_err();
    assert!(
        matches!(error, ContactError::Diverged { .. }),
        "expected a divergence, got {error}"
    );
}

/// Mean force over 0.2 <= t <= 1.8 and the fraction of those levels with the contact open.
fn plateau_mean_and_open_fraction(run: &ContactRun) -> (f64, f64) {
    let window: Vec<_> = run
        .history
        .iter()
        .filter(|s| (0.2..=1.8).contains(&s.time))
        .collect();
    let mean = window.iter().map(|s| s.force).sum::<f64>() / window.len() as f64;
    let open = window.iter().filter(|s| !s.active).count() as f64 / window.len() as f64;
    (mean, open)
}

#[test]
fn cd_bipenalty_with_ratio_one_is_accepted_and_bounded_but_chatters_at_large_beta_s() {
    let exact = {
        let bar = |length| ImpactBar::from_material(1.0, 1.0, 1.0, length).unwrap();
        ImpactForce::new(bar(1.0), bar(2.0), 1.0).unwrap()
    };
    let plateau = exact.first_plateau();
    for beta_s in [0.25, 0.25e2, 0.25e4, 0.25e8] {
        let run = ContactIntegrator::new(DT, bipenalty(beta_s))
            .run(&fig5(), 600, &ContactRequest::default())
            .unwrap();
        assert_eq!(run.critical.binding, StepLimit::ContactFree);
        let (mean, open) = plateau_mean_and_open_fraction(&run);
        let max_energy = run
            .history
            .iter()
            .map(|s| s.kinetic + s.strain)
            .fold(0.0, f64::max);
        let max_penalty = run
            .history
            .iter()
            .map(|s| s.penalty_force)
            .fold(0.0, f64::max);
        let in_window = run.history.iter().filter(|s| (0.2..=1.8).contains(&s.time));
        let (lo, hi) = in_window.fold((f64::INFINITY, 0.0_f64), |(lo, hi), s| {
            (lo.min(s.force), hi.max(s.force))
        });
        println!(
            "beta_s = {beta_s:e}: plateau mean {mean:.5}, force in [{lo:.4}, {hi:.4}], open \
             {:.0} % of levels, impulse {:.5}, max K+U {max_energy:.5}, max eps_s x \
             penetration {max_penalty:.4e}",
            100.0 * open,
            run.impulse
        );
        assert!(max_energy < 1.04 * 0.5, "beta_s = {beta_s}: {max_energy}");
        let impulse_bound = if beta_s < 1.0 { 1.5e-2 } else { 5e-3 };
        assert!(
            (run.impulse - exact.impulse()).abs() < impulse_bound,
            "beta_s = {beta_s}: impulse {}",
            run.impulse
        );
        assert!(
            (mean / plateau - 1.0).abs() < 5e-3,
            "beta_s = {beta_s}: mean {mean}"
        );
        if beta_s < 1.0 {
            let deviation = (hi - plateau).max(plateau - lo);
            assert!(deviation < 2e-4 * plateau && open == 0.0, "[{lo}, {hi}]");
        } else {
            // Chatter: about two levels in five open, the force up to ~2x the plateau.
            assert!(
                open > 0.3 && lo == 0.0 && hi > 1.8 * plateau,
                "{open} [{lo}, {hi}]"
            );
            assert!(max_penalty > 0.9 * beta_s * hi, "{max_penalty}");
        }
    }
}

#[test]
fn cd_bipenalty_gains_energy_on_a_chattering_persistent_contact_though_its_limit_holds() {
    let problem = courant_solver::bench::loaded_wall(100, 0.0).unwrap();
    let peak = |beta_s: f64| {
        let scheme =
            ContactScheme::Bipenalty(problem.penalty(beta_s, MassPenalty::Ratio(1.0)).unwrap());
        let run = ContactIntegrator::new(DT, scheme)
            .run(&problem, 20_000, &ContactRequest::default())
            .unwrap();
        assert_eq!(run.critical.binding, StepLimit::ContactFree);
        let tail = &run.history[15_000..];
        tail.iter()
            .map(|s| s.kinetic + s.strain)
            .fold(0.0, f64::max)
    };
    let (soft, stiff) = (peak(0.25), peak(25.0));
    println!("last quarter of 100 L/c, peak K + U: beta_s 0.25: {soft:.3}, beta_s 25: {stiff:.3}");
    // A stable scheme stays at or below the sudden-load peak 2 F^2 L/(E A) = 2.
    assert!(soft <= 2.0, "{soft}");
    assert!(stiff > 20.0, "{stiff}");
}
