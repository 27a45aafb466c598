//! Source of truth: the closed-form critical Courant numbers of the (bi)penalized Signorini
//! problem and of two equal bars (`courant_references::contact`, derived in methods.md §7 after
//! Kopačka et al., IJNME 113 (2018), the seed's ref. [9] and Fig. 3).
//!
//! ```text
//!   wall:  o---o---o--- ... ---o---c |//     k_s, m_p on c       free far end
//!   pair:  o--- ... ---o---a  b---o--- ... ---o   K_p = k_s NN^T, M_p = m_p NN^T, N = [-1, 1]
//! ```
//!
//! Proves: the solver's exact contact-active critical step (bisection on Sturm counts of the
//! tridiagonal pencil `(K + K_p, M + M_p)`) equals the closed form to 1e-8 (measured: 3e-14)
//! over beta_s in [1e-2, 1e8] for penalty only and bipenalty r in {2, 4, 16}; r in {1/4, 1}
//! leaves the contact-free step unchanged for every beta_s and any r > 1 lowers it; Cr tends
//! to 1/sqrt(r); two equal bars obey Cr_two(beta_s) = Cr_wall(2 beta_s); the nodal estimate
//! (k + k_s)/(m_c + m_p) is unconservative and the row-sum (Gershgorin) bound conservative.
//!
//! Mesh size: the closed form is the semi-infinite bar. The localized mode decays like
//! `|q|^j`, so a free far end moves it by O(|q|^(2N)); N is chosen per case with
//! `|q|^(2N) < 1e-12` (up to ~2800 elements near beta_s = 1e-2, where |q| -> 1). A free far end
//! keeps the contact-free top of the spectrum at exactly Lambda = 4 (Cr = 1).
//!
//! Round-off at huge beta_s: the assembled contact diagonal `k + k_s` carries an absolute error
//! of about `eps k_s`, i.e. a relative error `eps beta_s` in the contact row's pivot
//! `(k + k_s) - x (m_c + m_p)`, which is O(k) near the eigenvalue. That does not become an
//! `eps beta_s` error of the eigenvalue: the pivot's slope in the shift x is `m_c + m_p`, so the
//! root moves by `eps k_s/(m_c + m_p)`, which is eps times the contact row's own ratio and so
//! within a factor of two of eps times the eigenvalue (the eigenvalue lies between that ratio
//! and the row sum). The error stays O(eps) uniformly in beta_s, as measured; the 1e-8
//! tolerance asked for is kept, and a second, sharp bound of 1e-12 documents the level reached.

use courant_references::contact::{
    signorini_critical_courant_ratio, signorini_localized_mode, two_bar_critical_courant,
};
use courant_solver::contact::{
    ContactCriticalStep, ContactProblem, ContactScheme, MassPenalty, StepLimit,
};
use courant_solver::{Bar, End, Mesh, Model, Supports};

/// beta_s = 10^(k/4), k = -8..=32: 41 points from 1e-2 to 1e8.
fn beta_grid() -> Vec<f64> {
    (-8..=32).map(|k| 10f64.powf(f64::from(k) / 4.0)).collect()
}

fn mass_penalty(r: f64) -> MassPenalty {
    if r.is_infinite() {
        MassPenalty::None
    } else {
        MassPenalty::Ratio(r)
    }
}

/// Elements for which the localized mode of the wall with `(beta_s, beta_m)` has decayed to
/// `|q|^(2N) < 1e-12` at the far end (at least 50).
fn elements_for(beta_s: f64, beta_m: f64) -> usize {
    match signorini_localized_mode(beta_s, beta_m).unwrap() {
        Some(mode) => {
            let s = -mode.decay_ratio;
            ((1e-12_f64).ln() / (2.0 * s.ln())).ceil().max(50.0) as usize
        }
        None => 200,
    }
}

fn unit_bar(n: usize) -> Bar {
    Bar::homogeneous(Mesh::uniform(1.0, n).unwrap(), 1.0, 1.0, 1.0).unwrap()
}

/// A free-free unit bar against a wall on the right, and its critical steps under
/// (bi)penalty central difference with `beta_s` and ratio `r` (`inf`: penalty only).
fn wall_case(beta_s: f64, r: f64) -> ContactCriticalStep {
    let beta_m = if r.is_infinite() {
        0.0
    } else {
        beta_s / (4.0 * r)
    };
    let n = elements_for(beta_s, beta_m);
    let problem = ContactProblem::wall(
        Model::unloaded(unit_bar(n), Supports::default()),
        End::Right,
        0.0,
    )
    .unwrap();
    let penalty = problem.penalty(beta_s, mass_penalty(r)).unwrap();
    ContactCriticalStep::of(&problem, &ContactScheme::Bipenalty(penalty)).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn exact_contact_courant_number_equals_the_closed_form_for_penalty_and_bipenalty() {
    let mut worst: f64 = 0.0;
    for r in [f64::INFINITY, 2.0, 4.0, 16.0] {
        for beta_s in beta_grid() {
            let step = wall_case(beta_s, r);
            let solver = step.courant(step.contact_active);
            let closed = signorini_critical_courant_ratio(beta_s, r).unwrap();
            let error = rel(solver, closed);
            worst = worst.max(error);
            assert!(
                error < 1e-8,
                "r = {r}, beta_s = {beta_s:e}: solver {solver} vs closed form {closed}"
            );
            assert_eq!(step.binding, StepLimit::ContactActive);
            assert_eq!(step.applicable, step.contact_active);
        }
    }
    assert!(worst < 1e-12, "worst relative difference {worst:e}");
}

#[test]
fn ratio_at_most_one_keeps_the_contact_free_step_and_above_one_lowers_it() {
    for beta_s in beta_grid() {
        for r in [0.25, 1.0] {
            let step = wall_case(beta_s, r);
            assert_eq!(
                step.binding,
                StepLimit::ContactFree,
                "r = {r}, beta_s = {beta_s:e}"
            );
            assert_eq!(step.applicable, step.contact_free);
            assert!(
                step.contact_active >= step.contact_free * (1.0 - 1e-13),
                "r = {r}, beta_s = {beta_s:e}: {} < {}",
                step.contact_active,
                step.contact_free
            );
            // Free-free bar: the contact-free step is Co = 1 exactly.
            assert!((step.critical_courant() - 1.0).abs() < 1e-13);
        }
        for r in [2.0, 4.0, 16.0] {
            let step = wall_case(beta_s, r);
            assert!(
                step.contact_active < step.contact_free,
                "r = {r}, beta_s = {beta_s:e}"
            );
        }
    }
}

#[test]
fn critical_courant_number_tends_to_one_over_sqrt_r_from_above() {
    for r in [2.0, 4.0, 16.0] {
        let limit = 1.0 / f64::sqrt(r);
        let mut previous = f64::INFINITY;
        for beta_s in beta_grid() {
            let step = wall_case(beta_s, r);
            let cr = step.courant(step.contact_active);
            assert!(
                cr > limit && cr <= previous * (1.0 + 1e-13),
                "r = {r}, {beta_s:e}"
            );
            previous = cr;
        }
        assert!(rel(previous, limit) < 1e-6, "r = {r}: Cr(1e8) = {previous}");
    }
}

#[test]
fn two_equal_bars_have_the_wall_courant_number_at_twice_the_penalty() {
    for r in [f64::INFINITY, 2.0, 16.0] {
        for beta_s in [0.05, 1.0, 25.0, 1e4, 1e7] {
            let beta_m = if r.is_infinite() {
                0.0
            } else {
                beta_s / (4.0 * r)
            };
            let n = elements_for(2.0 * beta_s, 2.0 * beta_m);
            let problem = ContactProblem::pair(
                Model::unloaded(unit_bar(n), Supports::default()),
                Model::unloaded(unit_bar(n), Supports::default()),
                0.0,
            )
            .unwrap();
            let penalty = problem.penalty(beta_s, mass_penalty(r)).unwrap();
            let step =
                ContactCriticalStep::of(&problem, &ContactScheme::Bipenalty(penalty)).unwrap();
            let closed = two_bar_critical_courant(beta_s, beta_m).unwrap();
            let solver = step.courant(step.contact_active);
            assert!(
                rel(solver, closed) < 1e-10,
                "r = {r}, beta_s = {beta_s}: solver {solver} vs {closed}"
            );
        }
    }
}

#[test]
fn nodal_estimate_is_unconservative_and_gershgorin_conservative() {
    // Wall, penalty only, beta_s = 10: nodal Co = 2/sqrt(2 (1 + 10)) = 0.42640, exact
    // sqrt(2/(1 + sqrt(101))) = 0.42542, row sum 2/sqrt(2 (2 + 10)) = 0.40825.
    let step = wall_case(10.0, f64::INFINITY);
    let (nodal, exact, row_sum) = (
        step.courant(step.nodal),
        step.courant(step.applicable),
        step.courant(step.gershgorin),
    );
    assert!((nodal - 2.0 / 22.0_f64.sqrt()).abs() < 1e-12, "{nodal}");
    assert!((row_sum - 2.0 / 24.0_f64.sqrt()).abs() < 1e-12, "{row_sum}");
    assert!(
        row_sum < exact && exact < nodal,
        "{row_sum} < {exact} < {nodal}"
    );
    // Two bars with bipenalty r = 2: the same ordering, with the non-diagonal pair block.
    let problem = ContactProblem::fig5(100, 1.0).unwrap();
    for beta_s in [1.0, 1e3, 1e6] {
        let penalty = problem.penalty(beta_s, MassPenalty::Ratio(2.0)).unwrap();
        let step = ContactCriticalStep::of(&problem, &ContactScheme::Bipenalty(penalty)).unwrap();
        assert!(
            step.gershgorin < step.applicable && step.applicable < step.nodal,
            "beta_s = {beta_s}: {step:?}"
        );
    }
}
