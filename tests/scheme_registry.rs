//! Source of truth: the scheme registry of `courant_solver::schemes::REGISTRY` and the scene
//! rules of the README ("Scene files": schemes by their registry names, scheme parameters as the
//! keys each scheme declares, unknown keys refused naming line and key).
//!
//! ```text
//!   [integrator]
//!   scheme = ["cd", "park-lts", "noh-bathe"]   -> cd-co0.5, park-lts-co0.5, noh-bathe-co0.5
//!   theta = 0.5                                -> park-lts (declared by Park)
//!   p = 0.6                                    -> noh-bathe (declared by Noh-Bathe)
//! ```
//!
//! Proves: every registry name and alias builds its scheme with the declared parameters (and
//! their defaults); a scene mixing schemes gets each its own keys and the case names of the
//! existing rule; a key no listed scheme declares, a value breaking its rule, a misspelt scheme,
//! a mass or start a scheme does not take are refused naming the line, the key and the rule;
//! `courant list --schemes` lists every scheme with its parameters and source.

use courant::scene::Scene;
use courant_solver::schemes::REGISTRY;
use rstest::rstest;
use std::process::Command;

/// A minimal scene; `{integrator}` is replaced by the lines under test (line 17 on).
const SCENE: &str = r#"[scene]
description = "registry"
source = "the registry"

[material]
modulus = 1.0

[mesh]
elements = 10

[[load]]
kind = "traction"
end = "left"
value = -1.0

[integrator]
{integrator}
courant = 0.5

[output]
profile_times = [0.5]
"#;

fn scene(integrator: &str) -> Result<Scene, courant::scene::SceneError> {
    Scene::parse(
        "registry",
        "registry.toml",
        &SCENE.replace("{integrator}", integrator),
    )
}

#[test]
fn every_registry_name_builds_its_scheme_with_its_defaults() {
    for entry in REGISTRY {
        for name in std::iter::once(&entry.name).chain(entry.aliases) {
            let s = scene(&format!("scheme = \"{name}\"")).unwrap();
            assert_eq!(s.cases.len(), 1);
            assert_eq!(s.cases[0].name, "co0.5");
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
    assert_eq!(names, ["cd-co0.5", "park-lts-co0.5", "noh-bathe-co0.5"]);
    let labels: Vec<String> = s
        .cases
        .iter()
        .map(|c| c.integrator.scheme.label())
        .collect();
    assert_eq!(
        labels,
        ["cd", "park-lts-incremental theta=0.25", "noh-bathe p=0.6"]
    );
    assert_eq!(s.cases[2].integrator.scheme.force_evaluations(), 2);
    assert_eq!(s.cases[0].integrator.scheme.force_evaluations(), 1);
}

#[rstest]
#[case::parameter_out_of_its_range(
    "scheme = \"noh-bathe\"\np = 0.4",
    18,
    "integrator.p",
    "0.4 must lie in [0.5, 0.75]"
)]
#[case::parameter_no_listed_scheme_declares(
    "scheme = \"cd\"\np = 0.54",
    18,
    "integrator.p",
    "unknown field `p`: neither a key of [integrator] nor a parameter of its schemes (cd takes none)"
)]
#[case::misspelt_parameter(
    "scheme = \"park-lts\"\nthetta = 0.5",
    18,
    "integrator.thetta",
    "park-lts: theta, park_variant"
)]
#[case::word_where_a_number_goes(
    "scheme = \"noh-bathe\"\np = \"half\"",
    18,
    "integrator.p",
    "must be a number"
)]
#[case::unknown_choice(
    "scheme = \"park-lts\"\npark_variant = \"fast\"",
    18,
    "integrator.park_variant",
    "\"fast\" must be one of free, incremental"
)]
#[case::unknown_scheme(
    "scheme = [\"cd\", \"nb\"]",
    17,
    "integrator.scheme",
    "\"nb\" is not one of cd (central-difference), park-lts, park-global, noh-bathe"
)]
#[case::mass_the_scheme_does_not_take(
    "scheme = \"park-lts\"\nmass = \"cmm\"",
    17,
    "integrator.scheme",
    "Park's scheme runs with the lumped mass only"
)]
#[case::start_the_scheme_does_not_take(
    "scheme = \"noh-bathe\"\nstart = \"three-level\"",
    17,
    "integrator.scheme",
    "the three-level start is central difference's"
)]
#[case::table_as_a_parameter(
    "scheme = \"noh-bathe\"\np = [0.5]",
    18,
    "integrator.p",
    "a number or a word in quotes"
)]
fn bad_scheme_input_names_line_key_and_rule(
    #[case] integrator: &str,
    #[case] line: usize,
    #[case] key: &str,
    #[case] rule: &str,
) {
    let e = scene(integrator).unwrap_err();
    assert_eq!((e.line, e.key.as_str()), (line, key), "{e}");
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
