//! Source of truth: the seed's Figs. 3 and 5 as built-in scenes (`scenes/fig3.toml`,
//! `scenes/fig5.toml`, `scenes/contact_wall.toml`, `scenes/contact_unequal.toml`) with their
//! expectations from 1D wave theory and the closed-form bipenalty stability (methods.md §7).
//!
//! ```text
//!   v0 --> |== striker ==|  |======= target =======|        o--o--o~~k_s~~|// wall
//! ```
//!
//! Proves: every expectation of the contact scenes holds when run through the scene pipeline
//! (the same path as `courant run`), the Fig. 3 sweep matches the closed form to 1e-8, and bad
//! contact input is refused naming the key.

use courant::builtin::builtin_scene;
use courant::{Scene, run_scene};

#[test]
fn contact_scenes_meet_every_expectation() {
    for name in ["fig3", "fig5", "contact_wall", "contact_unequal"] {
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
    let base = courant::builtin::builtin_text("contact_wall").unwrap();
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
    ];
    for (from, to, key) in cases {
        assert!(base.contains(from), "{from}");
        let err = Scene::parse("bad", "bad.toml", &base.replacen(from, to, 1)).expect_err(to);
        assert_eq!(err.key, key, "{err}");
    }
}
