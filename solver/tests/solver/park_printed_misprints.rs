//! Source of truth: Park's eqs. 8 and 13 as the seed prints them (seed §3.1) against the
//! corrected forms and their derivation (methods.md §6): the pull-back is the cubic in time
//! through `t^n` and `t^n + dt_e`, whose velocity term at `t^n + dt` is `dt v`; the velocity
//! update is the trapezoidal `dt/2 (a^n + a^{n+1})`.
//!
//! ```text
//!   rigid translation, no load, theta = 1/2:   corrected  u^1 = dt v0
//!                                              eq. 8 as printed  u^1 = (dt + dt_e)/2 v0  (end node)
//! ```
//!
//! Proves: `park-printed` with `misprint = "none"` is `park-lts` (the folded kernel) to
//! round-off; eq. 8 as printed moves a rigidly translating graded bar by `(dt + dt_e)/2 v0` at
//! its end node in one step, not `dt v0` (inconsistent for `alpha < 1`); eq. 13 as printed
//! changes the velocity of a bar under a constant end force by `1/dt` times the corrected change.

use crate::common;

use common::run;
use courant_solver::bench::graded_seed_bar;
use courant_solver::integrator::ParameterValue;
use courant_solver::schemes::find;
use courant_solver::{InitialConditions, Integration, Model, Scheme, Supports};
use std::sync::Arc;

const N: usize = 100;

fn scheme(name: &str, misprint: &str) -> Arc<dyn Scheme> {
    let entry = find(name).unwrap();
    let mut values = vec![("theta".to_string(), ParameterValue::Number(0.5))];
    if name == "park-printed" {
        values.push((
            "misprint".to_string(),
            ParameterValue::Text(misprint.into()),
        ));
    }
    entry.build_with(&values).unwrap()
}

/// The seed's graded bar with every node moving at `v0 = 1`, free at both ends, no load.
fn translating() -> Model {
    let graded = graded_seed_bar(N).unwrap();
    Model::new(
        graded.bar().clone(),
        Supports::default(),
        &[],
        InitialConditions {
            displacement: None,
            velocity: Some(vec![1.0; N + 1]),
        },
    )
    .unwrap()
}

#[test]
fn corrected_equations_run_element_by_element_equal_the_folded_kernel() {
    let model = graded_seed_bar(N).unwrap();
    let dt = 0.5 * model.bar().stiffest_element().1;
    let nodes = [0, N / 4, N / 2];
    let folded = run(
        &Integration::new(dt, scheme("park-lts", "")),
        &model,
        400,
        &nodes,
    )
    .unwrap();
    let printed = run(
        &Integration::new(dt, scheme("park-printed", "none")),
        &model,
        400,
        &nodes,
    )
    .unwrap();
    for (a, b) in folded.histories.iter().zip(&printed.histories) {
        for (x, y) in a.samples.iter().zip(&b.samples) {
            assert!(
                (x.displacement - y.displacement).abs() <= 1e-12 * (1.0 + x.displacement.abs())
            );
            assert!((x.velocity - y.velocity).abs() <= 1e-10 * (1.0 + x.velocity.abs()));
        }
    }
}

#[test]
fn eq8_as_printed_does_not_translate_a_rigid_bar_consistently() {
    let model = translating();
    let bar = model.bar();
    let dt = 0.5 * bar.stiffest_element().1;
    // Node N has one element, the softest: alpha = dt/dt_e well below 1.
    let dt_e = bar.element_transit_time(N - 1);
    assert!(dt / dt_e < 0.5);
    let u1 = |misprint: &str| {
        let out = run(
            &Integration::new(dt, scheme("park-printed", misprint)),
            &model,
            1,
            &[N],
        )
        .unwrap();
        out.histories[0].samples.last().unwrap().displacement
    };
    let corrected = u1("none");
    assert!(
        (corrected - dt).abs() < 1e-14,
        "corrected {corrected} vs dt {dt}"
    );
    let printed = u1("eq8");
    let expected = 0.5 * (dt + dt_e);
    assert!(
        (printed - expected).abs() < 1e-12,
        "printed {printed} vs (dt + dt_e)/2 = {expected}"
    );
}

#[test]
fn eq13_as_printed_scales_the_velocity_update_by_one_over_dt() {
    let model = graded_seed_bar(N).unwrap();
    let dt = 0.5 * model.bar().stiffest_element().1;
    let v1 = |misprint: &str| {
        let out = run(
            &Integration::new(dt, scheme("park-printed", misprint)),
            &model,
            1,
            &[0],
        )
        .unwrap();
        out.histories[0].samples.last().unwrap().velocity
    };
    let (corrected, printed) = (v1("none"), v1("eq13"));
    assert!(corrected.abs() > 0.0);
    let ratio = printed / corrected;
    assert!(
        (ratio * dt - 1.0).abs() < 1e-9,
        "velocity change ratio {ratio} vs 1/dt = {}",
        1.0 / dt
    );
}
