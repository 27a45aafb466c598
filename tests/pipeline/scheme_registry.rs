//! Source of truth: the scheme registry of `courant_solver::schemes::REGISTRY` and the scene
//! rules of docs/guide/scenes.md ( schemes by their registry names, scheme parameters as the
//! keys each scheme declares, unknown keys refused naming line and key).
//!
//! ```text
//!   [integrator]                      (the fig1 scene, its scheme line replaced)
//!   scheme = ["cd", "park-lts", "noh-bathe"]   -> cd-co1 ... park-lts-co1 ... noh-bathe-co0.1
//!   theta = 0.25                               -> park-lts (declared by Park)
//!   p = 0.6                                    -> noh-bathe (declared by Noh-Bathe)
//! ```
//!
//! Proves: every registry name and alias builds its scheme with the declared parameters (and
//! their defaults); a scene mixing schemes gets each its own keys and the case names of the
//! existing rule; a key no listed scheme declares, a value breaking its rule, a misspelt scheme,
//! a mass or start a scheme does not take are refused naming the line, the key and the rule;
//! `courant list --schemes` lists every scheme with its parameters and source.

use courant::scene::Scene;
use courant::scene::builtin::builtin_text;
use courant_solver::schemes::REGISTRY;
use rstest::rstest;
use std::process::Command;

/// The built-in fig1 scene (without its expectations and its `mass = "lumped"`, the default) with
/// its `scheme = "central-difference"` line replaced by `integrator`.
fn scene(integrator: &str) -> Result<Scene, courant::scene::SceneError> {
    let mut text = builtin_text("fig1").unwrap().to_string();
    text.truncate(text.find("[[expect]]").unwrap());
    let (line, mass) = ("scheme = \"central-difference\"\n", "mass = \"lumped\"\n");
    assert!(text.contains(line) && text.contains(mass));
    let text = text
        .replacen(mass, "", 1)
        .replacen(line, &format!("{integrator}\n"), 1);
    Scene::parse("registry", "registry.toml", &text)
}

/// The line of fig1's `scheme` key, where the lines under test start.
fn scheme_line() -> usize {
    let text = builtin_text("fig1").unwrap();
    text[..text.find("scheme = \"central-difference\"").unwrap()]
        .lines()
        .count()
        + 1
}

#[test]
fn every_registry_name_builds_its_scheme_with_its_defaults() {
    for entry in REGISTRY {
        for name in std::iter::once(&entry.name).chain(entry.aliases) {
            let s = scene(&format!("scheme = \"{name}\"")).unwrap();
            assert_eq!(s.cases.len(), 3);
            assert_eq!(s.cases[1].name, "co0.5");
            assert_eq!(s.cases[0].integrator.scheme.name(), entry.name);
        }
    }
    let s = scene("scheme = \"noh-bathe\"").unwrap();
    assert_eq!(s.cases[0].integrator.scheme.label(), "noh-bathe p=0.54");
    assert_eq!(s.cases[0].limit.name(), "Omega_crit(p)/omega_max");
    let s = scene("scheme = \"park-global\"").unwrap();
    assert_eq!(
        s.cases[0].integrator.scheme.label(),
        "park-global-free theta=0.5"
    );
}

#[test]
fn mixed_schemes_each_take_their_own_keys() {
    let s = scene(
        "scheme = [\"cd\", \"park-lts\", \"noh-bathe\"]\ntheta = 0.25\npark_variant = \"incremental\"\np = 0.6",
    )
    .unwrap();
    let names: Vec<&str> = s.cases.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "cd-co1",
            "cd-co0.5",
            "cd-co0.1",
            "park-lts-co1",
            "park-lts-co0.5",
            "park-lts-co0.1",
            "noh-bathe-co1",
            "noh-bathe-co0.5",
            "noh-bathe-co0.1"
        ]
    );
    let labels: Vec<String> = s
        .cases
        .iter()
        .step_by(3)
        .map(|c| c.integrator.scheme.label())
        .collect();
    assert_eq!(
        labels,
        ["cd", "park-lts-incremental theta=0.25", "noh-bathe p=0.6"]
    );
    assert_eq!(s.cases[8].integrator.scheme.force_evaluations(), 2);
    assert_eq!(s.cases[0].integrator.scheme.force_evaluations(), 1);
}

/// `offset`: the line of the error below the `scheme` line.
#[rstest]
#[case::parameter_out_of_its_range(
    "scheme = \"noh-bathe\"\np = 0.4",
    1,
    "integrator.p",
    "0.4 must lie in [0.5, 0.75]"
)]
#[case::parameter_no_listed_scheme_declares(
    "scheme = \"cd\"\np = 0.54",
    1,
    "integrator.p",
    "unknown field `p`: neither a key of [integrator] nor a parameter of its schemes (cd takes none)"
)]
#[case::misspelt_parameter(
    "scheme = \"park-lts\"\nthetta = 0.5",
    1,
    "integrator.thetta",
    "park-lts: theta, park_variant"
)]
#[case::word_where_a_number_goes(
    "scheme = \"noh-bathe\"\np = \"half\"",
    1,
    "integrator.p",
    "must be a number"
)]
#[case::unknown_choice(
    "scheme = \"park-lts\"\npark_variant = \"fast\"",
    1,
    "integrator.park_variant",
    "\"fast\" must be one of free, incremental"
)]
#[case::unknown_scheme(
    "scheme = [\"cd\", \"nb\"]",
    0,
    "integrator.scheme",
    "\"nb\" is not one of cd (central-difference), park-lts, park-global, noh-bathe, park-printed"
)]
#[case::mass_the_scheme_does_not_take(
    "scheme = \"park-lts\"\nmass = \"cmm\"",
    0,
    "integrator.scheme",
    "Park's scheme runs with the lumped mass only"
)]
#[case::start_the_scheme_does_not_take(
    "scheme = \"noh-bathe\"\nstart = \"three-level\"",
    0,
    "integrator.scheme",
    "the three-level start is central difference's"
)]
#[case::table_as_a_parameter(
    "scheme = \"noh-bathe\"\np = { value = 0.5 }",
    1,
    "integrator.p",
    "a number, a word in quotes, or a list of them"
)]
fn bad_scheme_input_names_line_key_and_rule(
    #[case] integrator: &str,
    #[case] offset: usize,
    #[case] key: &str,
    #[case] rule: &str,
) {
    let e = scene(integrator).unwrap_err();
    assert_eq!(
        (e.line, e.key.as_str()),
        (scheme_line() + offset, key),
        "{e}"
    );
    assert!(e.message.contains(rule), "{e}");
}

#[test]
fn list_schemes_names_every_scheme_its_parameters_and_source() {
    let out = Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(["list", "--schemes"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for entry in REGISTRY {
        assert!(
            text.contains(&format!("\n{}", entry.name)),
            "{}",
            entry.name
        );
        assert!(text.contains(entry.source), "{}", entry.name);
        for p in entry.parameters {
            assert!(text.contains(&format!("  {} = ", p.key)), "{}", p.key);
        }
    }
    for name in [
        "cd-penalty",
        "cd-bipenalty",
        "predictor-corrector",
        "lagrange-multiplier",
    ] {
        assert!(text.contains(&format!("\n{name}\n")), "{name}");
    }
}
