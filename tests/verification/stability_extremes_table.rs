//! Source of truth: the central-difference stability limit dt_crit = 2/omega_max of the
//! assembled system (seed eq. 5; Hughes, The Finite Element Method, 2000, §9.3), for each mass
//! kind (LMM, CMM, AMM, RMM) of the `stability_extremes` scene.
//!
//! ```text
//!   dt / dt_crit:   0.99        1.00        1.01
//!                  stable      stable*     unstable -> guard stops it
//!   (* Co = 1 of the infinite-mesh value sits just below the finite-mesh dt_crit)
//! ```
//!
//! Proves: every row of the report's "stability at the extremes" table agrees with theory:
//! the 8 runs at or below the critical step complete every planned step, the 4 runs at 1.01 are
//! stopped by the divergence guard long before their planned end, with the step and node; on the
//! graded_1e4 bar Park's alpha_e <= 1 is named a sufficient bound and predicts nothing above it;
//! the Noh-Bathe rows (every mass at 0.99/1.00/1.01 of `Omega_crit(p)/omega_max`) agree: stable,
//! marginal and completed, caught;
//! the contact rows agree except the 4 that gain energy.

use courant::compare::outcome::SceneOutcome;
use courant::compare::stability::{StabilityRow, stability_rows, stability_table};
use courant::pipeline::evaluate_scene as run_scene;
use courant::scene::builtin::all as builtin_scenes;

/// A built-in stability scene's run and the stability rows of its time-stepping cases, with the
/// scene's stated findings.
fn time_stepping_rows(name: &str) -> (SceneOutcome, Vec<StabilityRow>) {
    let scene = courant::scene::builtin::builtin_scene(name)
        .expect("built-in scene")
        .unwrap();
    let outcome = run_scene(&scene).unwrap();
    let rows = stability_rows(&scene, &outcome);
    assert_eq!(rows.len(), outcome.results.len(), "every case has a row");
    (outcome, rows)
}

#[test]
fn stability_extremes_rows_agree_with_the_critical_step() {
    let (outcome, rows) = time_stepping_rows("stability_extremes");
    assert_eq!(rows.len(), 12);
    let unstable: Vec<&StabilityRow> = rows.iter().filter(|r| r.predicted == "unstable").collect();
    let stable = rows.iter().filter(|r| r.predicted == "stable").count();
    assert_eq!((unstable.len(), stable), (4, 8));
    for row in &rows {
        assert_eq!(row.agrees(), Some(true), "{row:?}");
    }
    for (row, r) in rows.iter().zip(&outcome.results) {
        if row.predicted == "unstable" {
            assert!(row.ratio > 1.009 && row.ratio < 1.011, "{row:?}");
            assert!(
                r.run.steps < r.run.steps_planned / 10,
                "{}: caught at {} of {}",
                row.case,
                r.run.steps,
                r.run.steps_planned
            );
        } else {
            assert_eq!(r.run.steps, r.run.steps_planned, "{}", row.case);
        }
    }
    let csv = stability_table(&rows).to_csv(courant::results::table::Precision::RoundTrip);
    assert_eq!(csv.lines().filter(|l| l.ends_with(",yes,pass")).count(), 12);
}

/// Source of truth: the exact critical step of each contact scheme (methods.md §7; seed Fig. 3)
/// and the unilateral nature of contact, for the `contact_extremes` scene (wall impact, CD with
/// penalty, bipenalty r = 4, predictor-corrector; beta_s = 1, 1e4, 1e8).
///
/// ```text
///   dt / dt_crit:  0.99     1.00      1.01 (< dt_free)     1.5 (> dt_free at beta_s = 1)
///                  stable   marginal  contact-unstable     unstable -> guard
///                                     (contact opens: bounded)
/// ```
///
/// Proves: the 9 runs below the limit and the 15 runs between the contact and contact-free
/// limits complete every step, the 3 runs above the contact-free limit are stopped by the guard
/// within a few steps; the penalty runs at 1.5 pump energy (ratio > 10), the predictor-corrector
/// does not. "Stable" means bounded energy (ratio <= 1.5): the 4 predicted-stable runs of CD with
/// (bi)penalty at beta_s >= 1e4 complete but gain energy at each engagement of the contact
/// (conserved-energy ratio 5.30 to 13.06) and are the only rows that disagree with the prediction.
#[test]
fn contact_extremes_rows_agree_with_the_critical_steps() {
    let scene = builtin_scenes()
        .unwrap()
        .into_iter()
        .find(|s| s.name == "contact_extremes")
        .expect("built-in scene");
    let outcome = run_scene(&scene).unwrap();
    let rows = stability_rows(&scene, &outcome);
    assert_eq!(rows.len(), 36);
    let count = |verdict: &str| rows.iter().filter(|r| r.predicted == verdict).count();
    assert_eq!(
        (
            count("stable"),
            count("marginal"),
            count("contact-unstable"),
            count("unstable")
        ),
        (9, 9, 15, 3)
    );
    let growing = [
        "cd-penalty-bs10000-co0.99",
        "cd-penalty-bs100000000-co0.99",
        "cd-bipenalty-bs10000-co0.99",
        "cd-bipenalty-bs100000000-co0.99",
    ];
    for (row, r) in rows.iter().zip(&outcome.contact) {
        if growing.contains(&row.case.as_str()) {
            assert!(
                row.agrees() == Some(false) && row.energy_growth(),
                "{row:?}"
            );
            assert!(row.energy_ratio.unwrap() > 5.0, "{row:?}");
            assert!(row.observed().starts_with("energy growth x"), "{row:?}");
            assert!(
                matches!(row.verdict(), Some((true, true, _))),
                "the scene states the disagreement as a finding: {row:?}"
            );
        } else {
            assert_eq!(row.agrees(), Some(true), "{row:?}");
        }
        if row.predicted == "unstable" {
            assert!(row.case.ends_with("-bs1-co1.5"), "{}", row.case);
            assert!(
                r.run.steps < 20,
                "{}: caught at step {}",
                row.case,
                r.run.steps
            );
        }
        let ratio = row
            .energy_ratio
            .expect("contact rows carry the energy ratio");
        if row.case.starts_with("predictor-corrector") && row.predicted != "unstable" {
            assert!(ratio < 1.2, "{}: energy ratio {ratio}", row.case);
        }
        if row.case.starts_with("cd-") && row.case.ends_with("bs100000000-co1.5") {
            assert!(ratio > 10.0, "{}: energy ratio {ratio}", row.case);
        }
    }
}

/// Source of truth: Park's `alpha_e <= 1` is the kh = pi bound of the uniform-mesh analysis
/// (methods.md §6), only sufficient on a graded mesh; the free variant does not keep a static
/// state static on a heterogeneous mesh (methods.md §6). Proves: on the `graded_1e4` bar the Park
/// rows name the bound as sufficient, predict nothing above it (the global step at 1.01 stays
/// bounded, local stepping diverges; both `not predicted`); below and at it the global step
/// agrees while local stepping (free variant) creates energy under the sustained load, which
/// disagrees with `stable` and `marginal` alike (one rule: energy created is a disagreement at
/// the limit as below it) and passes only as the finding the scene states; the exact limits of CD
/// (`2/omega_max`) and Noh-Bathe (`Omega_crit(p)/omega_max`) keep predictions that hold.
#[test]
fn park_on_a_graded_mesh_is_held_to_a_sufficient_bound_only() {
    let (_, rows) = time_stepping_rows("graded_1e4");
    for row in &rows {
        let above = row.case.ends_with("-co1.01");
        if row.case.starts_with("park") {
            assert_eq!(row.limit, "alpha_e <= 1 (sufficient)", "{row:?}");
            if above {
                assert_eq!(row.predicted, "beyond bound", "{row:?}");
                assert_eq!(row.agrees(), None, "{row:?}");
            } else if row.case.starts_with("park-lts") {
                assert!(row.observed().starts_with("energy created"), "{row:?}");
                assert_eq!(row.agrees(), Some(false), "{row:?}");
                assert!(matches!(row.verdict(), Some((true, true, _))), "{row:?}");
            } else {
                assert_eq!(row.agrees(), Some(true), "{row:?}");
            }
        } else if row.case.starts_with("noh-bathe") {
            assert_eq!(row.limit, "Omega_crit(p)/omega_max", "{row:?}");
            assert_eq!(row.agrees(), Some(true), "{row:?}");
        } else {
            assert_eq!(row.limit, "2/omega_max", "{row:?}");
            assert_eq!(row.agrees(), Some(true), "{row:?}");
        }
    }
    let by_name = |name: &str| rows.iter().find(|r| r.case == name).unwrap();
    assert!(by_name("park-global-co1.01").completed);
    assert!(!by_name("park-lts-co1.01").completed);
}

/// Source of truth: the Noh-Bathe limit `Omega_crit(p)/omega_max`, exact for the linear system
/// (courant_solver::schemes::noh_bathe). Proves: every row of `stability_noh_bathe` names it and
/// agrees with it: 0.99 stable, 1.00 marginal and completed (eigenvalue +1, the other det A < 1),
/// 1.01 stopped by the guard.
#[test]
fn noh_bathe_rows_agree_with_its_exact_limit() {
    let (_, rows) = time_stepping_rows("stability_noh_bathe");
    assert_eq!(rows.len(), 12);
    for row in &rows {
        assert_eq!(row.limit, "Omega_crit(p)/omega_max", "{row:?}");
        assert_eq!(row.agrees(), Some(true), "{row:?}");
        assert_eq!(row.completed, !row.case.ends_with("-co1.01"), "{row:?}");
    }
}
