//! Source of truth: the dispersion theory of lumped central difference at Co < 1 for a step
//! front (methods.md §3): the front spreads into an Airy profile of width ~ (h^2 t)^(1/3), so the
//! L1 error decays like h^(1/2), the L2 error like h^(1/3), the max error does not converge,
//! and the overshoot behind the front tends to max_x int_{-inf}^x Ai = 1.2743..., i.e. 27.4 %
//! of the jump.
//!
//! ```text
//!   exact      ____________                 numerical   _/\/\__________
//!                          |                                     \
//!                          |____                                  \_/\____
//! ```
//!
//! Proves: the observed orders over N = 800 ... 6400 at Co = 0.5 fall in the bands of
//! `data/airy_front_convergence.csv` (theory order +- the pre-asymptotic drift seen at these N:
//! observed L1 0.44-0.50, L2 0.33-0.34), before (t = 0.5 T) and after (t = 1.5 T) the
//! reflection, and the overshoot is 27.4 % +- 1 %, measured directly and by the scene
//! pipeline's `overshoot` metric.

use crate::common;

use common::*;
use courant::pipeline::evaluate_case as run_case;
use courant::scene::Scene;
use courant_solver::{Start, TimeFunction};

const MESHES: [usize; 4] = [800, 1600, 3200, 6400];
const TIMES: [f64; 2] = [0.5, 1.5];

struct Band {
    metric: String,
    min_order: f64,
    max_order: f64,
}

fn bands() -> Vec<Band> {
    let mut reader = csv::Reader::from_path(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/airy_front_convergence.csv"
    ))
    .unwrap();
    reader
        .records()
        .map(|r| {
            let r = r.unwrap();
            Band {
                metric: r[0].to_string(),
                min_order: r[2].parse().unwrap(),
                max_order: r[3].parse().unwrap(),
            }
        })
        .collect()
}

/// Errors of one profile: (l1, l2, linf) and the overshoot.
type ProfileErrors = ((f64, f64, f64), f64);

/// Errors per mesh (outer) and time (inner).
fn errors() -> Vec<Vec<ProfileErrors>> {
    MESHES
        .iter()
        .map(|&n| {
            let out = run_fig1(
                n,
                0.5,
                &TIMES,
                Start::HalfStep,
                TimeFunction::HEAVISIDE,
                &[],
            );
            out.profiles
                .iter()
                .map(|p| {
                    let exact = exact_averages(n, p.time);
                    // |sigma| beyond the largest exact |sigma| behind the front (sigma0 = -1, and
                    // the plateau behind every front is -1 at 0.5 T, -2 at 1.5 T).
                    let plateau = if p.time < 1.0 { 1.0 } else { 2.0 };
                    let overshoot = p
                        .stress
                        .iter()
                        .map(|s| -s - plateau)
                        .fold(f64::NEG_INFINITY, f64::max);
                    (error_norms(&p.stress, &exact), overshoot)
                })
                .collect()
        })
        .collect()
}

#[test]
fn observed_orders_of_the_dispersive_front_match_theory() {
    let errors = errors();
    let bands = bands();
    for (ti, t) in TIMES.iter().enumerate() {
        for pair in 0..MESHES.len() - 1 {
            let (coarse, fine) = (errors[pair][ti].0, errors[pair + 1][ti].0);
            let ratio = (MESHES[pair + 1] / MESHES[pair]) as f64;
            let order = |a: f64, b: f64| (a / b).ln() / ratio.ln();
            for band in &bands {
                let observed = match band.metric.as_str() {
                    "l1" => order(coarse.0, fine.0),
                    "l2" => order(coarse.1, fine.1),
                    "linf" => order(coarse.2, fine.2),
                    other => panic!("unknown metric {other} in the data file"),
                };
                assert!(
                    (band.min_order..=band.max_order).contains(&observed),
                    "t = {t}, N = {} -> {}: {} order {observed:.3} outside [{}, {}]",
                    MESHES[pair],
                    MESHES[pair + 1],
                    band.metric,
                    band.min_order,
                    band.max_order
                );
            }
        }
    }
}

#[test]
fn overshoot_behind_the_front_tends_to_the_airy_value() {
    let airy_overshoot = 0.2743; // max_x int_{-inf}^x Ai(s) ds - 1, at the first zero of Ai
    let errors = errors();
    for (mi, &n) in MESHES.iter().enumerate().skip(2) {
        for (ti, t) in TIMES.iter().enumerate() {
            let overshoot = errors[mi][ti].1;
            assert!(
                (overshoot - airy_overshoot).abs() < 0.01,
                "N = {n}, t = {t}: overshoot {overshoot:.4} vs {airy_overshoot}"
            );
        }
    }
}

#[test]
fn the_scene_overshoot_metric_measures_the_airy_overshoot() {
    // Fig. 1 at N = 3200, Co = 0.5, without its expectations (they name the other cases).
    let fig1 = courant::scene::builtin::builtin_text("fig1").unwrap();
    let text = fig1[..fig1.find("[[expect]]").unwrap()]
        .replace("elements = 100", "elements = 3200")
        .replace("courant = [1.0, 0.5, 0.1]", "courant = 0.5");
    let scene = Scene::parse("fig1_fine", "fig1_fine.toml", &text).unwrap();
    let result = run_case(&scene.cases[0]).unwrap();
    for p in &result.profiles {
        let overshoot = p.norms.unwrap().overshoot;
        assert!(
            (overshoot - 0.2743).abs() < 0.01,
            "t = {}: scene overshoot {overshoot:.4}",
            p.time
        );
    }
}
