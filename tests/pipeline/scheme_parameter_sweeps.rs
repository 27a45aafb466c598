//! Source of truth: the scene rules of docs/guide/scenes.md ( a scheme parameter given as a
//! list is a sweep, one case per value) and methods.md §6 (Park's theta = 0 is central
//! difference).
//!
//! ```text
//!   [integrator]                                 cases
//!   scheme = ["cd", "park-lts"]                  cd-co1, cd-co0.5, ...
//!   theta = [0, 0.5]                             park-lts-theta0-co1, park-lts-theta0.5-co1, ...
//!   park_variant = ["free", "incremental"]       park-lts-free-theta0-co1, ...
//! ```
//!
//! Proves: a listed parameter gives one case per value (cartesian product over listed keys, in
//! file order), named by a token (`theta0.5`, or the word itself), only for the schemes that
//! declare it; each case runs the scheme built with its value and records it; empty lists, lists
//! of tables and duplicates are refused naming line and key; a list counts against the case
//! budget; and on the Fig. 2 bar the theta = 0
//! case equals central difference to round-off (the built-in `fig2_theta` scene's expectation).

use courant::pipeline::evaluate_scene;
use courant::scene::Scene;
use courant::scene::builtin::{builtin_text, resolve};
use courant_solver::integrator::ParameterValue;

/// The built-in fig1 scene without its expectations, its scheme line replaced by `integrator`.
fn scene(integrator: &str) -> Result<Scene, courant::scene::SceneError> {
    let mut text = builtin_text("fig1").unwrap().to_string();
    text.truncate(text.find("[[expect]]").unwrap());
    let text = text.replacen("mass = \"lumped\"\n", "", 1).replacen(
        "scheme = \"central-difference\"\n",
        &format!("{integrator}\n"),
        1,
    );
    Scene::parse("sweep", "sweep.toml", &text)
}

fn names(s: &Scene) -> Vec<&str> {
    s.cases.iter().map(|c| c.name.as_str()).collect()
}

#[test]
fn a_listed_parameter_gives_one_case_per_value_named_by_its_token() {
    let s = scene("scheme = \"park-lts\"\ntheta = [0, 0.25, 1]").unwrap();
    assert_eq!(
        names(&s),
        [
            "theta0-co1",
            "theta0-co0.5",
            "theta0-co0.1",
            "theta0.25-co1",
            "theta0.25-co0.5",
            "theta0.25-co0.1",
            "theta1-co1",
            "theta1-co0.5",
            "theta1-co0.1"
        ]
    );
    let labels: Vec<String> = s
        .cases
        .iter()
        .map(|c| c.integrator.scheme.label())
        .collect();
    assert_eq!(labels[0], "park-lts-free theta=0");
    assert_eq!(labels[3], "park-lts-free theta=0.25");
    assert_eq!(labels[8], "park-lts-free theta=1");
    assert_eq!(
        s.cases[3].swept,
        [("theta".to_string(), ParameterValue::Number(0.25))]
    );
    // A single value is no sweep: no token, nothing recorded.
    let s = scene("scheme = \"park-lts\"\ntheta = 0.25").unwrap();
    assert_eq!(names(&s), ["co1", "co0.5", "co0.1"]);
    assert!(s.cases.iter().all(|c| c.swept.is_empty()));
}

#[test]
fn lists_multiply_and_apply_only_to_the_schemes_that_declare_them() {
    let s = scene(
        "scheme = [\"cd\", \"park-lts\"]\ntheta = [0, 0.5]\npark_variant = [\"free\", \"incremental\"]",
    )
    .unwrap();
    let n = names(&s);
    assert_eq!(n.len(), 3 + 2 * 2 * 3, "{n:?}");
    assert_eq!(&n[..3], ["cd-co1", "cd-co0.5", "cd-co0.1"]);
    // Keys in file order: theta before park_variant.
    assert!(n.contains(&"park-lts-theta0.5-incremental-co0.1"), "{n:?}");
    let case = s
        .cases
        .iter()
        .find(|c| c.name == "park-lts-theta0-incremental-co1")
        .unwrap();
    assert_eq!(
        case.integrator.scheme.label(),
        "park-lts-incremental theta=0"
    );
    assert!(s.cases[0].swept.is_empty(), "cd takes no theta");
}

#[test]
fn bad_lists_are_refused_naming_line_and_key() {
    for (integrator, key, says) in [
        (
            "scheme = \"park-lts\"\ntheta = []",
            "integrator.theta",
            "empty",
        ),
        (
            "scheme = \"park-lts\"\ntheta = [{ a = 1 }]",
            "integrator.theta",
            "numbers or words",
        ),
        (
            "scheme = \"park-lts\"\ntheta = [0.5, 2.0]",
            "integrator.theta",
            "[0, 1]",
        ),
        (
            "scheme = \"park-lts\"\ntheta = [0.5, 0.5]",
            "integrator.courant",
            "appears twice",
        ),
        (
            "scheme = \"cd\"\ntheta = [0, 0.5]",
            "integrator.theta",
            "unknown field",
        ),
    ] {
        let e = scene(integrator).unwrap_err();
        let text = e.to_string();
        assert_eq!(e.key, key, "{integrator}: {text}");
        assert!(e.line > 0, "{integrator}: no line in {text}");
        assert!(text.contains(says), "{integrator}: {text}");
    }
}

#[test]
fn a_long_list_counts_against_the_case_budget_before_any_case_is_built() {
    // fig1 has three Courant numbers: 20 001 theta values would be 60 003 cases, over the
    // 10 000 a scene may have (src/scene/budget.rs), refused before any bisection runs.
    let values: Vec<String> = (0..=20_000)
        .map(|i| format!("{}", i as f64 / 20_000.0))
        .collect();
    let e = scene(&format!(
        "scheme = \"park-lts\"\ntheta = [{}]",
        values.join(", ")
    ))
    .unwrap_err();
    let text = e.to_string();
    assert!(text.contains("60003 cases"), "{text}");
    assert!(text.contains("10000"), "{text}");
}

#[test]
fn theta_zero_equals_central_difference_on_the_fig2_bar() {
    let scene = resolve("fig2_theta").unwrap();
    let outcome = evaluate_scene(&scene).unwrap();
    let cd = outcome
        .results
        .iter()
        .find(|r| r.run.case == "cd-co0.5")
        .unwrap();
    for name in ["park-lts-theta0-co0.5", "park-global-theta0-co0.5"] {
        let park = outcome.results.iter().find(|r| r.run.case == name).unwrap();
        assert_eq!(park.run.steps, cd.run.steps, "{name}: same plan");
        for (a, b) in park.profiles.iter().zip(&cd.profiles) {
            let peak = b.stress.iter().fold(0.0_f64, |m, s| m.max(s.abs()));
            let worst = a
                .stress
                .iter()
                .zip(&b.stress)
                .fold(0.0_f64, |m, (s, r)| m.max((s - r).abs()));
            assert!(worst <= 1e-12 * peak, "{name} t = {}: {worst:e}", a.time);
        }
    }
    let verdicts: Vec<_> = outcome
        .verdicts
        .iter()
        .filter(|v| v.metric.name() == "stress_difference")
        .collect();
    assert_eq!(verdicts.len(), 2);
    assert!(verdicts.iter().all(|v| v.pass));
}
