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
//! stopped by the divergence guard long before their planned end, with the step and node.

use courant::report::builtin_scenes;
use courant::run::run_scene;
use courant::stability_table::{StabilityRow, stability_table};

#[test]
fn stability_extremes_rows_agree_with_the_critical_step() {
    let scene = builtin_scenes()
        .unwrap()
        .into_iter()
        .find(|s| s.name == "stability_extremes")
        .expect("built-in scene");
    let outcome = run_scene(&scene).unwrap();
    let rows: Vec<StabilityRow> = outcome
        .results
        .iter()
        .map(|r| StabilityRow::new(&scene.name, r))
        .collect();
    assert_eq!(rows.len(), 12);
    let unstable: Vec<&StabilityRow> = rows.iter().filter(|r| r.predicted == "unstable").collect();
    let stable = rows.iter().filter(|r| r.predicted == "stable").count();
    assert_eq!((unstable.len(), stable), (4, 8));
    for row in &rows {
        assert!(row.agrees(), "{row:?}");
    }
    for (row, r) in rows.iter().zip(&outcome.results) {
        if row.predicted == "unstable" {
            assert!(row.ratio > 1.009 && row.ratio < 1.011, "{row:?}");
            assert!(
                r.steps < r.steps_planned / 10,
                "{}: caught at {} of {}",
                row.case,
                r.steps,
                r.steps_planned
            );
        } else {
            assert_eq!(r.steps, r.steps_planned, "{}", row.case);
        }
    }
    let csv = stability_table(&rows).to_csv(courant::table::Precision::RoundTrip);
    assert_eq!(csv.lines().filter(|l| l.ends_with(",yes")).count(), 12);
}
