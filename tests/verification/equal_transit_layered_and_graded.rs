//! Source of truth: methods.md §4 — on an equal-transit-time mesh (every element crossed in the
//! same time, E_e = rho (h_e/dt)^2), lumped CD at Co = 1 is the exact layered (Goupillaud) model:
//! exact for piecewise-constant layers with interfaces at nodes, and first-order convergent to the
//! graded solution. References: exact layered wave tracking and the exact graded bar of
//! `courant-references`.
//!
//! ```text
//!   Z = 16, c = 4  | Z = 1, c = 1        element lengths proportional to c:
//!   |----|----|----|-|-|-|-|-|-|-|-|//    every element takes dt to cross
//! ```
//!
//! Proves: on the two-layer bar of `scenes/layered.toml` (impedance ratio 16) CD and Park
//! (alpha = 1) at Co = 1 give the transmitted and reflected stresses to round-off through many
//! reflections; on the Fig. 2 graded bar the equal-transit CD solution converges at first order
//! in L1 (observed order in [0.85, 1.15] over N = 100 ... 400).

use courant::pipeline::evaluate_case as run_case;
use courant::scene::Scene;
use courant::scene::builtin::builtin_text;

fn scene_with(name: &str, replacements: &[(&str, &str)]) -> Scene {
    let mut text = builtin_text(name).unwrap().to_string();
    if let Some(i) = text.find("[[expect]]") {
        text.truncate(i);
    }
    for (from, to) in replacements {
        assert!(text.contains(from), "{from} not in {name}");
        text = text.replace(from, to);
    }
    Scene::parse(name, &format!("{name}.toml"), &text).unwrap()
}

#[test]
fn layered_bar_at_courant_one_is_exact_through_many_reflections() {
    let scene = scene_with(
        "layered",
        &[
            // CD and Park at alpha = 1 (CD); Noh-Bathe is not exact here (the layered scene).
            (
                "scheme = [\"cd\", \"park-lts\", \"noh-bathe\"]",
                "scheme = [\"cd\", \"park-lts\"]",
            ),
            ("courant = [1.0, 0.5]", "courant = 1.0"),
            (
                "profile_times = [0.5, 1.2, 2.6]",
                "profile_times = [0.5, 1.2, 2.6, 7.4, 10.0]",
            ),
        ],
    );
    assert_eq!(scene.cases.len(), 2);
    for case in &scene.cases {
        let result = run_case(case).unwrap();
        assert_eq!(result.profiles.len(), 5);
        for p in &result.profiles {
            let linf = p.norms.unwrap().linf;
            assert!(
                linf < 1e-10,
                "{} t = {}: max error {linf:e} of |sigma0|",
                case.name,
                p.time
            );
        }
    }
}

#[test]
fn equal_transit_cd_converges_at_first_order_to_the_graded_bar() {
    let scene = scene_with(
        "fig2",
        &[
            (
                "elements = 100",
                "elements = [100, 200, 400]\nspacing = \"equal-transit\"",
            ),
            (
                "scheme = [\"cd\", \"park-global\", \"park-lts\", \"noh-bathe\"]",
                "scheme = \"cd\"",
            ),
            ("theta = 0.5\npark_variant = \"free\"\np = 0.54\n", ""),
            ("courant = 0.5", "courant = 1.0"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
    );
    let l1: Vec<f64> = scene
        .cases
        .iter()
        .map(|c| run_case(c).unwrap().profiles[0].norms.unwrap().l1)
        .collect();
    for pair in l1.windows(2) {
        let order = (pair[0] / pair[1]).log2();
        assert!(
            (0.85..=1.15).contains(&order),
            "observed L1 order {order} (errors {l1:?})"
        );
    }
}
