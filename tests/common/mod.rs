//! Shared set-up of the integration tests: the seed's free-fixed bar and its exact solution.
#![allow(dead_code)]

use courant_references::DalembertBar;
use courant_solver::{
    CentralDifference, Model, OutputRequest, RunOutput, StabilityPolicy, Start, TimeFunction,
};

/// The homogeneous unit bar of the seed's Fig. 1 (L = A = rho = E = 1, sigma0 = -1), N elements,
/// loaded by `time` at the free left end, fixed at the right end.
pub fn fig1_model(n: usize, time: TimeFunction) -> Model {
    courant_solver::bench::seed_bar(n, courant_solver::Field::Constant(1.0), time).unwrap()
}

/// Lumped central difference at `dt` with unstable steps allowed (the guard still stops a
/// blow-up): for runs at or above the critical step.
pub fn cd_allowing_unstable(dt: f64) -> CentralDifference {
    CentralDifference {
        stability: StabilityPolicy {
            allow_unstable: true,
            ..Default::default()
        },
        ..CentralDifference::new(dt)
    }
}

/// d'Alembert's solution of that bar.
pub fn fig1_exact() -> DalembertBar {
    DalembertBar::new(1.0, 1.0, 1.0, 1.0, -1.0).unwrap()
}

/// Run lumped CD at Courant number `co` (dt shrunk to hit `times` exactly), recording profiles
/// at `times` and the histories of `history_nodes` at every step.
pub fn run_fig1(
    n: usize,
    co: f64,
    times: &[f64],
    start: Start,
    time: TimeFunction,
    history_nodes: &[usize],
) -> RunOutput {
    let model = fig1_model(n, time);
    let end = times.iter().copied().fold(0.0, f64::max);
    let plan = courant_solver::plan(co / n as f64, times, end).unwrap();
    let integrator = CentralDifference {
        start,
        ..CentralDifference::new(plan.dt)
    };
    let request = OutputRequest {
        profile_steps: plan.output_steps,
        history_nodes: history_nodes.to_vec(),
        ..Default::default()
    };
    integrator.run(&model, plan.steps, &request).unwrap()
}

/// Exact element averages of the stress on the uniform N-element unit mesh at time t.
pub fn exact_averages(n: usize, t: f64) -> Vec<f64> {
    let exact = fig1_exact();
    (0..n)
        .map(|e| exact.stress_average(e as f64 / n as f64, (e + 1) as f64 / n as f64, t))
        .collect()
}

/// max_e |a_e - b_e|.
pub fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// Normalised (L1, L2, Linf) stress errors on the uniform unit mesh (|sigma0| = 1, L = 1).
pub fn error_norms(stress: &[f64], exact: &[f64]) -> (f64, f64, f64) {
    let h = 1.0 / stress.len() as f64;
    let l1 = stress
        .iter()
        .zip(exact)
        .map(|(s, e)| h * (s - e).abs())
        .sum();
    let l2 = stress
        .iter()
        .zip(exact)
        .map(|(s, e)| h * (s - e).powi(2))
        .sum::<f64>()
        .sqrt();
    (l1, l2, max_abs_diff(stress, exact))
}

/// The contact results of a built-in contact scene, refined: `text` with each `(from, to)` of
/// `replacements` applied (each must occur, so a changed scene fails here instead of silently
/// running unrefined), cut before its first `[[expect]]` (bands hold at the scene's own mesh
/// only), then run and compared.
pub fn refined_contact_results(
    name: &str,
    text: &str,
    replacements: &[(&str, String)],
) -> Vec<courant::compare::contact::ContactResult> {
    let mut text = text.to_string();
    for (from, to) in replacements {
        assert!(text.contains(from), "{name}: `{from}` not in the scene");
        text = text.replace(from, to);
    }
    let text = &text[..text.find("[[expect]]").unwrap_or(text.len())];
    let scene = courant::scene::Scene::parse(name, &format!("{name}.toml"), text).unwrap();
    courant::pipeline::evaluate_scene(&scene).unwrap().contact
}
