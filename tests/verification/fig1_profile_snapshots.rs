//! Source of truth: the seed's Fig. 1 (Kolman et al.), reproduced by `scenes/fig1.toml`: lumped
//! CD at Co = 1, 0.5 and 0.1, stress profiles at t = 0.5 T and 1.5 T beside d'Alembert's exact
//! element averages.
//!
//! Proves: the Fig. 1 profiles do not change unnoticed. Each case is locked as a rounded, named
//! CSV (`t, element, x, stress, reference, error`; 6 significant digits, |values| < 1e-10 shown
//! as 0 so that round-off cannot make a snapshot platform-dependent). Review changes with
//! `cargo insta review`; in CI (CI=true) a mismatch fails and nothing is written.

use courant::compare::tables::profile_table;
use courant::pipeline::evaluate_case as run_case;
use courant::results::table::Precision;
use courant::scene::builtin::builtin_scene;

#[test]
fn fig1_profiles_are_locked_per_case() {
    let scene = builtin_scene("fig1")
        .expect("fig1 is built in")
        .expect("fig1 is valid");
    assert_eq!(
        scene
            .cases
            .iter()
            .map(|c| c.name.as_str())
            .collect::<Vec<_>>(),
        ["co1", "co0.5", "co0.1"]
    );
    for case in &scene.cases {
        let result = run_case(case).unwrap();
        let csv = profile_table(&result).to_csv(Precision::SNAPSHOT);
        insta::assert_snapshot!(format!("fig1_{}", case.name), csv);
    }
}

/// Source: the Fig. 1 bar with the reciprocal mass RMM(1/2) at its own critical Courant number
/// sqrt(2/3) (`scenes/fig1_masses.toml`, case `rmm0.5-co1`; methods.md §5). Locks its profile.
#[test]
fn fig1_rmm_profile_is_locked() {
    let scene = builtin_scene("fig1_masses")
        .expect("built in")
        .expect("valid");
    let case = scene
        .cases
        .iter()
        .find(|c| c.name == "rmm0.5-co1")
        .expect("case rmm0.5-co1");
    let result = run_case(case).unwrap();
    insta::assert_snapshot!(
        "fig1_rmm0.5_co1",
        profile_table(&result).to_csv(Precision::SNAPSHOT)
    );
}
