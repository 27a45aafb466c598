//! Source of truth: the seed's Fig. 5 (Kolman et al., section 3.2): contact force histories of
//! a striker (L1 = 1, v0 = 1) hitting a bar at rest (L2 = 2), E = rho = A = 1, 100 elements per
//! unit length, Co = 0.5, bipenalty ratio r = 1; reference: the exact impact force
//! (`courant_references::contact::ImpactForce`, F = Z v0/2 for 0 <= t < 2, right-continuous).
//!
//! ```text
//!   o--o-- ... --o--a | b--o--o-- ... --o--o      force at the pair (a, b), compression > 0
//!   striker, v0 ->       target at rest
//! ```
//!
//! Proves: the representative force histories do not change unnoticed. Each is a rounded CSV
//! (`t, force, reference`; 6 significant digits, |values| < 1e-10 shown as 0): the
//! predictor-corrector scheme at the soft beta_s = 0.25 and at beta_s = 0.25e8 (where it is
//! the Lagrange multiplier method to 4e-8), both every 10th step to t = 3; the Lagrange
//! multiplier reference, every 10th step; and CD bipenalty at beta_s = 0.25e4 every step on
//! 0.9 <= t <= 1.0, to show its chatter (sampling every 10th step would alias its ~5-step
//! cycle). Review changes with `cargo insta review`; in CI (CI=true) a mismatch fails.

use courant::results::table::{Cell, Precision, Table};
use courant_references::contact::{ImpactBar, ImpactForce};
use courant_solver::contact::{
    ContactIntegrator, ContactProblem, ContactRequest, ContactScheme, MassPenalty,
};

const DT: f64 = 0.005;

fn history_csv(scheme: ContactScheme, end: f64, keep: impl Fn(usize, f64) -> bool) -> String {
    let problem = ContactProblem::fig5(100, 1.0).unwrap();
    let bar = |length| ImpactBar::from_material(1.0, 1.0, 1.0, length).unwrap();
    let exact = ImpactForce::new(bar(1.0), bar(2.0), 1.0).unwrap();
    let run = ContactIntegrator::new(DT, scheme)
        .run(
            &problem,
            (end / DT).round() as usize,
            &ContactRequest::default(),
        )
        .unwrap();
    let mut table = Table::new(&["t", "force", "reference"]);
    for s in run.history.iter().filter(|s| keep(s.step, s.time)) {
        table.push(vec![
            Cell::Num(s.time),
            Cell::Num(s.force),
            Cell::Num(exact.force(s.time)),
        ]);
    }
    table.to_csv(Precision::SNAPSHOT)
}

fn penalty(beta_s: f64) -> courant_solver::contact::Penalty {
    ContactProblem::fig5(100, 1.0)
        .unwrap()
        .penalty(beta_s, MassPenalty::Ratio(1.0))
        .unwrap()
}

#[test]
fn fig5_force_histories_are_locked_per_scheme() {
    let every_tenth = |step: usize, _: f64| step.is_multiple_of(10);
    for (name, scheme) in [
        (
            "fig5_pc_beta0.25",
            ContactScheme::PredictorCorrector(penalty(0.25)),
        ),
        (
            "fig5_pc_beta0.25e8",
            ContactScheme::PredictorCorrector(penalty(0.25e8)),
        ),
        ("fig5_lm", ContactScheme::LagrangeMultiplier),
    ] {
        insta::assert_snapshot!(name, history_csv(scheme, 3.0, every_tenth));
    }
    insta::assert_snapshot!(
        "fig5_cd_bipenalty_beta0.25e4_chatter",
        history_csv(ContactScheme::Bipenalty(penalty(0.25e4)), 1.0, |_, t| t
            >= 0.9 - 1e-9)
    );
}
