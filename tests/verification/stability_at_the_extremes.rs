//! Source of truth: the stability limits of the schemes at their exact values — central
//! difference `dt <= 2/omega_max` of the assembled mesh (Hughes 2000, §9.3; methods.md §5) and
//! Park's `alpha_e = dt/dt_e <= 1`, with every theta central difference at `alpha = 1`
//! (methods.md §6) — and the scene rules of `courant_unit = "exact"` and `keep_step = true`.
//!
//! ```text
//!   dt / dt_crit:   0.99       1.00 (to round-off)     1.01
//!   CD, Park:       stable     marginal: completes     unstable -> the guard stops it
//! ```
//!
//! Proves: on a small uniform bar (N = 20) Park with local stepping and with the global step at
//! 0.99, 1.00 and 1.01 of its own limit (the table's `alpha_e <= 1`, not CD's 2/omega_max) reads
//! stable / marginal / unstable, completes / completes as CD (energy balance to round-off) /
//! is stopped by the guard; CD at exactly 1.00 of 2/omega_max reads marginal (|dt/dt_crit - 1|
//! <= 1e-15) for every mass kind and completes; a keep-step run keeps dt bit for bit, snaps its
//! end and profile times to the nearest step and compares with the reference at the step's actual
//! time; bad input for the new keys is refused naming the key and line.

use courant::compare::exact::ExactOnMesh;
use courant::compare::stability::StabilityRow;
use courant::pipeline::evaluate_scene as run_scene;
use courant::results::case::Status;
use courant::scene::Scene;
use courant_solver::{CriticalStep, MassOperator};

/// The Fig. 1 bar with N = 20, unstable runs allowed; `integrator` fills in the scheme lines,
/// `output` the output lines (times in transits).
fn scene(integrator: &str, output: &str) -> String {
    format!(
        r#"[scene]
description = "limit"
source = "methods.md §5, §6"

[material]
modulus = 1.0

[mesh]
elements = 20

[[load]]
kind = "traction"
end = "left"
value = -1.0

[integrator]
{integrator}
allow_unstable = true

[output]
time_unit = "transit"
{output}

[reference]
kind = "dalembert"
"#
    )
}

fn run_rows(text: &str) -> (Vec<StabilityRow>, courant::compare::outcome::SceneOutcome) {
    let scene = Scene::parse("limit", "limit.toml", text).unwrap();
    let outcome = run_scene(&scene).unwrap();
    let rows = outcome
        .results
        .iter()
        .map(|r| StabilityRow::new("limit", r))
        .collect();
    (rows, outcome)
}

#[test]
fn park_at_its_own_limit_is_stable_marginal_then_caught() {
    let text = scene(
        "scheme = [\"park-lts\", \"park-global\"]\ncourant_unit = \"exact\"\ncourant = [0.99, 1.0, 1.01]\nkeep_step = true",
        "end_time = 100.0",
    );
    let (rows, outcome) = run_rows(&text);
    assert_eq!(rows.len(), 6);
    for (row, r) in rows.iter().zip(&outcome.results) {
        assert_eq!(row.limit, "alpha_e <= 1", "{row:?}");
        // Park's limit is the stiffest element's transit time h/c = 0.05, not CD's 2/omega_max
        // (1.0000771 h/c on this mesh).
        assert_eq!(r.run.limit.dt(), r.run.critical.element_transit);
        assert!(r.run.critical.exact > 1.00007 * r.run.limit.dt());
        let fraction = match &row.case[row.case.rfind("-co").unwrap() + 3..] {
            "0.99" => 0.99,
            "1" => 1.0,
            "1.01" => 1.01,
            other => panic!("case {other}"),
        };
        assert!((row.ratio - fraction).abs() <= 1e-15, "{row:?}");
        assert_eq!(row.agrees(), Some(true), "{row:?}");
        match fraction {
            0.99 => {
                assert_eq!(row.predicted, "stable");
                assert_eq!(r.run.steps, r.run.steps_planned);
                assert_eq!(row.observed(), "stable");
            }
            1.0 => {
                assert_eq!(row.predicted, "marginal");
                assert_eq!(r.run.steps, r.run.steps_planned);
                // The double-root law (methods.md §2): bounded energy reads p ~ 0.
                assert!(
                    row.observed()
                        .starts_with("stable; within the n^2 law (p = "),
                    "{row:?}"
                );
                // alpha = 1 in every element: Park is CD, whose discrete energy is conserved.
                assert!(r.energy.relative_balance_error() < 1e-12, "{row:?}");
            }
            _ => {
                assert_eq!(row.predicted, "unstable");
                assert!(matches!(r.run.status, Status::Diverged(_)), "{row:?}");
                assert!(r.run.steps < r.run.steps_planned / 10, "{row:?}");
                assert!(row.caught.as_deref().unwrap().starts_with("step "));
            }
        }
    }
}

#[test]
fn central_difference_at_exactly_its_critical_step_reads_marginal() {
    let text = scene(
        "mass = [\"lmm\", \"cmm\", \"amm\", \"rmm\"]\ncourant_unit = \"exact\"\ncourant = 1.0\nkeep_step = true",
        "end_time = 20.0",
    );
    let (rows, outcome) = run_rows(&text);
    assert_eq!(rows.len(), 4);
    for (row, r) in rows.iter().zip(&outcome.results) {
        assert_eq!(row.limit, "2/omega_max");
        assert!((row.ratio - 1.0).abs() <= 1e-15, "{row:?}");
        assert_eq!(row.predicted, "marginal", "{row:?}");
        assert_eq!(r.run.steps, r.run.steps_planned, "{row:?}");
        assert_eq!(row.agrees(), Some(true));
    }
    // The closed-form unit does not reach the finite mesh's limit; without keep_step the plan
    // shrinks the exact step to land on the end time: neither reads marginal.
    for (unit, keep) in [("critical", "true"), ("exact", "false")] {
        let text = scene(
            &format!("courant_unit = \"{unit}\"\ncourant = 1.0\nkeep_step = {keep}"),
            "end_time = 20.0",
        );
        let (rows, _) = run_rows(&text);
        assert_eq!(rows[0].predicted, "stable", "{unit}, keep_step = {keep}");
        assert!(rows[0].ratio < 1.0 - 1e-6, "{:?}", rows[0]);
    }
}

#[test]
fn a_kept_step_is_exact_and_outputs_sit_at_the_steps_actual_time() {
    let text = scene(
        "courant_unit = \"exact\"\ncourant = 0.99\nkeep_step = true",
        "profile_times = [0.5]\nend_time = 2.0",
    );
    let scene = Scene::parse("keep", "keep.toml", &text).unwrap();
    let case = &scene.cases[0];
    let operator = MassOperator::new(&case.model, case.integrator.mass).unwrap();
    let exact = CriticalStep::of(&case.model, case.integrator.mass, &operator)
        .unwrap()
        .exact;
    let dt = 0.99 * exact;
    assert_eq!(case.integrator.dt.to_bits(), dt.to_bits());
    assert_eq!(case.plan.dt.to_bits(), dt.to_bits());
    let transit = case.transit_time;
    assert_eq!(case.plan.steps, (2.0 * transit / dt).round() as usize);
    let n = (0.5 * transit / dt).round() as usize;
    assert_eq!(case.plan.output_steps, vec![n]);
    let outcome = run_scene(&scene).unwrap();
    let result = &outcome.results[0];
    let profile = &result.profiles[0];
    assert_eq!((profile.step, profile.time), (n, n as f64 * dt));
    assert!(
        profile.time != 0.5 * transit,
        "the step does not land on 0.5 T here"
    );
    // The reference is evaluated at the step's time, not the requested one.
    let reference = case.reference.as_ref().unwrap();
    let mesh = case.model.bar().mesh();
    assert_eq!(
        profile.reference.as_deref(),
        Some(&reference.element_averages(mesh, profile.time)[..])
    );
    assert_ne!(
        profile.reference.as_deref(),
        Some(&reference.element_averages(mesh, 0.5 * transit)[..])
    );
    // An expectation at the requested time finds the profile of the nearest step.
    let with_expect = format!(
        "{text}\n[[expect]]\nmetric = \"l1\"\nat = 0.5\nmax = 0.2\nsource = \"Airy front at Co = 0.99 (methods.md §3)\"\n"
    );
    let scene = Scene::parse("keep", "keep.toml", &with_expect).unwrap();
    let outcome = run_scene(&scene).unwrap();
    assert!(
        outcome.verdicts[0].pass,
        "{}",
        outcome.verdicts[0].describe()
    );
}

#[test]
fn bad_exact_unit_and_keep_step_input_names_the_key_and_line() {
    let cases = [
        (
            scene("dt = 0.01\ncourant_unit = \"exact\"", "end_time = 1.0"),
            "integrator.courant_unit",
            18,
            "applies to `courant` only",
        ),
        (
            scene(
                "courant_unit = \"exact\"\ncourant = 1.0\nkeep_step = true",
                "profile_times = [0.5, 0.51]\nend_time = 1.0",
            ),
            "output.profile_times",
            24,
            "fall on the same step",
        ),
        (
            scene("courant = 1.0\nkeep_step = true", "end_time = 0.01"),
            "output.end_time",
            23,
            "shorter than half a step",
        ),
        (
            scene(
                "courant_unit = \"exactly\"\ncourant = 1.0",
                "end_time = 1.0",
            ),
            "integrator.courant_unit",
            17,
            "unknown variant",
        ),
    ];
    for (text, key, line, message) in cases {
        let err = Scene::parse("bad", "bad.toml", &text).expect_err(key);
        assert_eq!(err.key, key, "{err}");
        assert_eq!(err.line, line, "{err}");
        assert!(err.message.contains(message), "{err}");
    }
}
