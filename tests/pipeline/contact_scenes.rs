//! Source of truth: the seed's Figs. 3 and 5 as built-in scenes (`scenes/fig3.toml`,
//! `scenes/fig5.toml`, `scenes/contact_wall.toml`, `scenes/contact_unequal.toml`,
//! `scenes/contact_courant_sweep.toml`, `scenes/contact_extremes.toml`,
//! `scenes/contact_impact_stability.toml`) with their expectations from 1D wave theory and the
//! exact (bi)penalty stability limits (methods.md §7).
//!
//! ```text
//!   v0 --> |== striker ==|  |======= target =======|        o--o--o~~k_s~~|// wall
//! ```
//!
//! Proves: every expectation of the contact scenes holds when run through the scene pipeline
//! (the same path as `courant run`), the Fig. 3 sweep matches the closed form to 1e-8, Courant
//! numbers in units of each case's exact critical step give exactly that step, and bad contact
//! input is refused naming the key.

use courant::pipeline::evaluate_scene as run_scene;
use courant::scene::Scene;
use courant::scene::builtin::builtin_scene;

#[test]
fn contact_scenes_meet_every_expectation() {
    for name in [
        "fig3",
        "fig5",
        "contact_wall",
        "contact_unequal",
        "contact_courant_sweep",
        "contact_extremes",
        "contact_impact_stability",
    ] {
        let scene = builtin_scene(name).unwrap().unwrap();
        let outcome = run_scene(&scene).unwrap();
        assert!(!outcome.verdicts.is_empty(), "{name} has expectations");
        for v in &outcome.verdicts {
            assert!(v.pass, "{name}: {}", v.describe());
        }
        if name == "fig3" {
            assert_eq!(outcome.sweeps[0].rows.len(), 41 * 6);
            assert!(outcome.sweeps[0].deviation() < 1e-8);
        }
    }
}

#[test]
fn bad_contact_input_names_the_key() {
    let base = courant::scene::builtin::builtin_text("contact_wall").unwrap();
    let cases = [
        ("problem = \"wall\"", "problem = \"wal\"", "contact.problem"),
        (
            "problem = \"wall\"",
            "problem = \"two-bars\"",
            "contact.target",
        ),
        (
            "schemes = [\"predictor-corrector\", \"lagrange-multiplier\"]",
            "schemes = [\"penalty\"]",
            "contact.schemes",
        ),
        ("beta_s = [25.0, 2.5e7]\n", "", "contact.beta_s"),
        ("velocity = 1.0", "velocity = -1.0", "contact.velocity"),
        ("courant = 0.5", "courant = 0.8", "contact.courant"),
        ("courant = 0.5", "courant = [0.5, -1.0]", "contact.courant"),
        ("courant = 0.5", "courant = []", "contact.courant"),
        (
            "courant = 0.5",
            "courant = 0.5\ncourant_unit = \"transit\"",
            "contact.courant_unit",
        ),
    ];
    for (from, to, key) in cases {
        assert!(base.contains(from), "{from}");
        let err = Scene::parse("bad", "bad.toml", &base.replacen(from, to, 1)).expect_err(to);
        assert_eq!(err.key, key, "{err}");
    }
}

/// `courant_unit = "critical"`: each case's step is the given multiple of its scheme's exact
/// critical step (`ContactCriticalStep::applicable`, methods.md §7), one case per value, named
/// `-co<value>`; a step above it is refused unless unstable runs are allowed.
#[test]
fn critical_courant_unit_scales_each_cases_exact_limit() {
    let base = courant::scene::builtin::builtin_text("contact_wall").unwrap();
    let text = base.replacen(
        "courant = 0.5",
        "courant = [0.5, 0.99]\ncourant_unit = \"critical\"",
        1,
    );
    let scene = Scene::parse("critical", "critical.toml", &text).unwrap();
    assert_eq!(scene.contact.len(), 2 * 2 + 2);
    for case in &scene.contact {
        let critical = case.integrator.check_stability(&case.problem).unwrap();
        let fraction = if case.name.ends_with("-co0.5") {
            0.5
        } else {
            assert!(case.name.ends_with("-co0.99"), "{}", case.name);
            0.99
        };
        let ratio = case.integrator.dt / critical.applicable;
        assert!((ratio - fraction).abs() < 1e-15, "{}: {ratio}", case.name);
    }
    let above = base.replacen(
        "courant = 0.5",
        "courant = 1.01\ncourant_unit = \"critical\"",
        1,
    );
    let err = Scene::parse("above", "above.toml", &above).expect_err("above the limit");
    assert_eq!(err.key, "contact.courant", "{err}");
}
