//! Source of truth: the production Park kernel ([`crate::kernels::park::ParkStep`], itself
//! tested against the element-by-element formulas of methods.md §6). Proves: without contact,
//! the combined stepper's Park path is Park's scheme (same `u`, `v`, `a` to round-off) on a
//! layered bar, for both variants, with and without local stepping.

use super::bulk::BulkScheme;
use super::stepper::{CombinedStepper, ContactMode};
use crate::contact::problem::ContactProblem;
use crate::contact::scheme::ContactScheme;
use crate::kernels::park::{ParkOptions, ParkStep, ParkVariant};
use crate::model::{Bar, End, Field, Mesh};

#[test]
fn without_contact_the_park_path_is_the_park_kernel() {
    let n = 24;
    let e: Vec<f64> = (0..n)
        .map(|k| if k < n / 2 { 1.0 } else { 256.0 })
        .collect();
    let bar = Bar::new(
        Mesh::uniform(1.0, n).unwrap(),
        &Field::PerElement(e),
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )
    .unwrap();
    let problem = ContactProblem::wall_impact(bar, End::Right, 1.0, 0.0).unwrap();
    let model = &problem.bodies()[0];
    let dt = 0.7 * problem.stiffest_transit();
    for variant in [ParkVariant::Free, ParkVariant::Incremental] {
        for local_stepping in [true, false] {
            let options = ParkOptions {
                theta: 0.5,
                variant,
                local_stepping,
            };
            let mut kernel = ParkStep::new(model, dt, options).unwrap();
            kernel.start(model);
            let mut combined = CombinedStepper::allowing_unstable(
                &problem,
                BulkScheme::Park(options),
                ContactScheme::LagrangeMultiplier,
                ContactMode::Off,
                dt,
            )
            .unwrap();
            for step in 0..40 {
                kernel.step(model, step as f64 * dt);
                combined.step();
                let [u, v, a] = combined.state();
                for (mine, theirs) in [
                    (u, kernel.displacement()),
                    (v, kernel.velocity()),
                    (a, kernel.acceleration()),
                ] {
                    let scale = theirs.iter().fold(1e-300_f64, |m, x| m.max(x.abs()));
                    for (i, (x, y)) in mine.iter().zip(theirs).enumerate() {
                        assert!(
                            (x - y).abs() <= 1e-12 * scale,
                            "{options:?} step {step} node {i}: {x} vs {y}"
                        );
                    }
                }
            }
        }
    }
}
