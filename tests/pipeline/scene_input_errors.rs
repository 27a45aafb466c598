//! Source of truth: courant's scene rules (docs/guide/scenes.md): unknown keys, wrong types and
//! values that break a physical or numerical rule are refused before anything runs.
//!
//! Proves: every class of bad input gives an error naming the file, the line, the key and the
//! rule, and `courant run` exits with status 2 writing nothing.

use courant::scene::Scene;
use rstest::rstest;
use std::process::Command;

/// A valid minimal scene; each case below breaks one line of it.
const VALID: &str = r#"[scene]
description = "minimal"
source = "d'Alembert"

[material]
modulus = 1.0

[mesh]
elements = 10

[[load]]
kind = "traction"
end = "left"
value = -1.0

[integrator]
courant = 0.5

[output]
profile_times = [0.5]

[reference]
kind = "dalembert"
"#;

fn broken(find: &str, replace: &str) -> String {
    assert!(
        VALID.contains(find),
        "test set-up: {find:?} not in the scene"
    );
    VALID.replacen(find, replace, 1)
}

#[test]
fn the_minimal_scene_is_valid_and_uses_the_documented_defaults() {
    let scene = Scene::parse("minimal", "minimal.toml", VALID).unwrap();
    assert_eq!(scene.cases.len(), 1);
    let case = &scene.cases[0];
    assert_eq!(case.name, "co0.5");
    assert_eq!(case.model.bar().mesh().length(), 1.0);
    assert_eq!(case.model.bar().area()[0], 1.0);
    assert_eq!(case.model.bar().density()[0], 1.0);
    assert!(
        case.model.is_fixed(10) && !case.model.is_fixed(0),
        "default supports are free-fixed"
    );
    assert_eq!(case.plan.steps, 10);
}

#[rstest]
#[case::syntax_error("elements = 10", "elements = = 10", 9, "mesh.elements", "extra `=`")]
#[case::unknown_key(
    "elements = 10",
    "elements = 10\nelemnts = 3",
    10,
    "mesh.elemnts",
    "unknown field `elemnts`"
)]
#[case::unknown_table(
    "[reference]",
    "[referense]",
    22,
    "referense",
    "unknown field `referense`"
)]
#[case::wrong_type(
    "elements = 10",
    "elements = \"ten\"",
    9,
    "mesh.elements",
    "expected a whole number"
)]
#[case::negative_modulus(
    "modulus = 1.0",
    "modulus = -1.0",
    6,
    "material.modulus",
    "must be positive and finite"
)]
#[case::zero_density(
    "modulus = 1.0",
    "modulus = 1.0\ndensity = 0.0",
    7,
    "material.density",
    "must be positive and finite"
)]
#[case::negative_length(
    "[material]",
    "[bar]\nlength = -2.0\n\n[material]",
    6,
    "bar.length",
    "-2 must be positive and finite"
)]
#[case::zero_area(
    "[material]",
    "[bar]\narea = 0.0\n\n[material]",
    6,
    "bar.area",
    "0 must be positive and finite"
)]
#[case::zero_elements(
    "elements = 10",
    "elements = 0",
    9,
    "mesh.elements",
    "0 must lie in 1..=500000"
)]
#[case::too_many_elements(
    "elements = 10",
    "elements = 1000000000000",
    9,
    "mesh.elements",
    "must lie in 1..=500000 (elements of one bar)"
)]
#[case::extreme_grading(
    "elements = 10",
    "elements = 2000\ngrading = 1.5",
    10,
    "mesh.grading",
    "smallest element"
)]
#[case::field_of_wrong_shape(
    "modulus = 1.0",
    "modulus = { linear = 3 }",
    6,
    "material.modulus",
    "a number or `{ linear = [left, right] }`"
)]
#[case::too_many_steps(
    "courant = 0.5",
    "courant = 1e-9",
    17,
    "integrator.courant",
    "at most 100000000"
)]
#[case::too_much_work(
    "elements = 10",
    "elements = 400000",
    17,
    "integrator.courant",
    "node-steps"
)]
#[case::zero_courant(
    "courant = 0.5",
    "courant = 0.0",
    17,
    "integrator.courant",
    "0 must be positive and finite"
)]
#[case::negative_courant_in_a_list(
    "courant = 0.5",
    "courant = [0.5, -1.0]",
    17,
    "integrator.courant",
    "-1 must be positive"
)]
#[case::courant_and_dt(
    "courant = 0.5",
    "courant = 0.5\ndt = 0.01",
    17,
    "integrator",
    "either `courant` or `dt`"
)]
#[case::unstable_courant(
    "courant = 0.5",
    "courant = 1.5",
    17,
    "integrator.courant",
    "asked courant = 1.5; shrunk to hit the output times, the step is dt = 1.250000e-1: Courant number 1.250000"
)]
#[case::profile_after_end(
    "profile_times = [0.5]",
    "profile_times = [0.5, 2.0]\nend_time = 1.0",
    20,
    "output.profile_times",
    "after the end time"
)]
#[case::history_outside_bar(
    "profile_times = [0.5]",
    "profile_times = [0.5]\nhistory_points = [1.5]",
    21,
    "output.history_points",
    "outside the bar"
)]
#[case::nothing_excites_the_bar(
    "value = -1.0",
    "value = 0.0",
    11,
    "load",
    "nothing excites the bar"
)]
#[case::traction_without_end("end = \"left\"", "node = 0", 11, "load", "needs `end`")]
#[case::force_on_a_fixed_node(
    "kind = \"traction\"\nend = \"left\"",
    "kind = \"force\"\nnode = 10",
    11,
    "load",
    "which is fixed"
)]
#[case::reference_does_not_apply(
    "[mesh]",
    "[supports]\nleft = \"free\"\nright = \"free\"\n\n[mesh]",
    27,
    "reference.kind",
    "solves a homogeneous bar"
)]
#[case::unknown_metric(
    "kind = \"dalembert\"",
    "kind = \"dalembert\"\n\n[[expect]]\nmetric = \"l3\"\nmax = 1.0\nsource = \"x\"",
    26,
    "expect.metric",
    "is not one of"
)]
#[case::bound_min_above_max(
    "kind = \"dalembert\"",
    "kind = \"dalembert\"\n\n[[expect]]\nmetric = \"l1\"\nmin = 2.0\nmax = 1.0\nsource = \"x\"",
    25,
    "expect",
    "above max"
)]
#[case::park_above_alpha_one(
    "courant = 0.5",
    "scheme = \"park-lts\"\ncourant = 1.002\nkeep_step = true",
    18,
    "integrator.courant",
    "with park-lts-free theta=0.5 (dt_crit = 1.000000e-1, alpha_e <= 1)"
)]
fn bad_input_names_line_key_and_rule(
    #[case] find: &str,
    #[case] replace: &str,
    #[case] line: usize,
    #[case] key: &str,
    #[case] message: &str,
) {
    let text = broken(find, replace);
    let err = Scene::parse("bad", "bad.toml", &text).expect_err("the scene must be refused");
    assert_eq!(err.file, "bad.toml");
    assert_eq!((err.line, err.key.as_str()), (line, key), "{err}");
    assert!(
        err.message.contains(message),
        "message {:?} lacks {message:?}",
        err.message
    );
    assert!(
        err.to_string().starts_with(&format!("bad.toml:{line}:")),
        "{err}"
    );
}

#[test]
fn courant_run_exits_2_and_writes_nothing_on_bad_input() {
    let dir = std::env::temp_dir().join(format!("courant-bad-input-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, broken("modulus = 1.0", "modulus = -1.0")).unwrap();
    let out = dir.join("out");
    // A good scene before the bad one must not be written either: validation comes first.
    let status = Command::new(env!("CARGO_BIN_EXE_courant"))
        .args([
            "run",
            "fig1",
            bad.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(status.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&status.stderr);
    assert!(
        stderr.contains("bad.toml:6:") && stderr.contains("material.modulus"),
        "{stderr}"
    );
    assert!(!out.exists(), "nothing may be written on bad input");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The minimal scene with a bar of `elements` and a profile time short enough for the node-step
/// limit (which `--large` keeps).
fn with_elements(elements: u64) -> String {
    broken("elements = 10", &format!("elements = {elements}"))
        .replace("profile_times = [0.5]", "profile_times = [0.001]")
}

/// Source of truth: `scene::limits` (docs/guide/running.md, "Large runs"). Proves: a bar beyond the default
/// 5e5 elements is refused naming the key, the value, the rule and the opt-in; with the opt-in
/// (`Limits::LARGE`) it validates; beyond the large bound (the solver's 1e7 mesh cap) it is
/// refused again, with no opt-in left to suggest.
#[test]
fn large_bars_are_an_explicit_opt_in() {
    use courant::scene::limits::Limits;
    let big = with_elements(600_000);
    let err = Scene::parse("big", "big.toml", &big).expect_err("refused by default");
    let message = err.to_string();
    for part in ["mesh.elements", "600000", "1..=500000", "--large"] {
        assert!(message.contains(part), "{part:?} missing: {message}");
    }
    let scene = Scene::parse_within("big", "big.toml", &big, Limits::LARGE)
        .expect("a bar of 6e5 elements validates with the opt-in");
    assert_eq!(scene.cases[0].model.bar().element_count(), 600_000);
    let huge = with_elements(10_000_001);
    let err = Scene::parse_within("huge", "huge.toml", &huge, Limits::LARGE)
        .expect_err("refused beyond the large bound");
    let message = err.to_string();
    assert!(
        message.contains("1..=10000000") && !message.contains("--large"),
        "{message}"
    );
}

/// Proves: `courant run --large` passes the opt-in to validation (a bar beyond the large bound
/// is refused with the large bound, before anything runs), and `courant run` without it refuses
/// a bar beyond the default and tells the user about `--large`; nothing is written either way.
#[test]
fn courant_run_large_flag_reaches_validation() {
    let dir = std::env::temp_dir().join(format!("courant-large-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("out");
    for (elements, large, expected) in [
        (600_000, false, "--large"),
        (10_000_001, true, "1..=10000000"),
    ] {
        let scene = dir.join("big.toml");
        std::fs::write(&scene, with_elements(elements)).unwrap();
        let mut args = vec![
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ];
        if large {
            args.push("--large");
        }
        let output = Command::new(env!("CARGO_BIN_EXE_courant"))
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(output.status.code(), Some(2));
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.contains("mesh.elements") && stderr.contains(expected),
            "{stderr}"
        );
        assert!(!out.exists(), "nothing may be written on refused input");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
