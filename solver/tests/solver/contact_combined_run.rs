//! Source of truth: the module docs of `contact::combined` (with the lumped central-difference
//! bulk the combined stepper gives the contact stepper's levels, velocity-Verlet form of the same
//! scheme). Proves: `CombinedIntegrator::run` records the same force, gap and cumulative impulse
//! as `ContactIntegrator::run` at every level of a two-bar impact, for every contact scheme, to
//! round-off; it refuses a step above the limit it is given unless unstable runs are allowed,
//! and its guard stops a run above Park's measured limit.

use courant_solver::contact::combined::{BulkScheme, CombinedIntegrator};
use courant_solver::contact::{
    ContactError, ContactIntegrator, ContactProblem, ContactRequest, ContactScheme, MassPenalty,
};
use courant_solver::{Bar, Field, Mesh, ParkOptions, ParkVariant, StabilityPolicy};

fn bar(length: f64, elements: usize, modulus: f64) -> Bar {
    Bar::new(
        Mesh::uniform(length, elements).unwrap(),
        &Field::Constant(modulus),
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )
    .unwrap()
}

fn problem() -> ContactProblem {
    ContactProblem::bar_impact(bar(1.0, 10, 1.0), bar(2.0, 20, 4.0), 1.0, 0.0).unwrap()
}

#[test]
fn lumped_bulk_run_matches_the_contact_stepper() {
    let problem = problem();
    let penalty = |b| problem.penalty(b, MassPenalty::Ratio(1.0)).unwrap();
    let schemes = [
        ContactScheme::Penalty {
            stiffness: penalty(1.0).stiffness,
        },
        ContactScheme::Bipenalty(penalty(1e4)),
        ContactScheme::PredictorCorrector(penalty(1e4)),
        ContactScheme::LagrangeMultiplier,
    ];
    for scheme in schemes {
        let dt = 0.3 * problem.stiffest_transit();
        let steps = (3.0 / dt) as usize;
        let request = ContactRequest::default();
        let lumped = ContactIntegrator::new(dt, scheme)
            .run(&problem, steps, &request)
            .unwrap();
        let combined = CombinedIntegrator {
            dt,
            bulk: BulkScheme::CentralDifference,
            scheme,
            stability: StabilityPolicy::default(),
        };
        let critical = CombinedIntegrator::measured_critical(&problem, combined.bulk, scheme)
            .expect("31 + 21 nodes");
        let run = combined.run(&problem, steps, &request, critical).unwrap();
        assert_eq!(run.history.len(), lumped.history.len());
        let scale = lumped.max_force.max(1.0);
        for (a, b) in run.history.iter().zip(&lumped.history) {
            let label = format!("{} step {}", scheme.label(), a.step);
            assert_eq!(a.active, b.active, "{label}");
            assert!((a.force - b.force).abs() <= 1e-9 * scale, "{label}");
            assert!((a.gap - b.gap).abs() <= 1e-12, "{label}");
            assert!((a.impulse - b.impulse).abs() <= 1e-10, "{label}");
        }
    }
}

#[test]
fn combined_run_is_checked_against_its_limit_and_guarded() {
    let problem = problem();
    let park = BulkScheme::Park(ParkOptions {
        theta: 0.5,
        variant: ParkVariant::Incremental,
        local_stepping: true,
    });
    let scheme = ContactScheme::LagrangeMultiplier;
    let rule = CombinedIntegrator::park_rule_critical(&problem, scheme).unwrap();
    let run = |dt: f64, allow_unstable: bool| {
        CombinedIntegrator {
            dt,
            bulk: park,
            scheme,
            stability: StabilityPolicy {
                allow_unstable,
                ..StabilityPolicy::default()
            },
        }
        .run(&problem, 20_000, &ContactRequest::default(), rule)
    };
    assert!(matches!(
        run(1.2 * rule.applicable, false),
        Err(ContactError::Unstable(_))
    ));
    assert!(matches!(
        run(1.2 * rule.applicable, true),
        Err(ContactError::Diverged { .. })
    ));
    assert!(run(0.5 * rule.applicable, false).is_ok());
}

/// Source of truth: the combined stepper with the contact off applies no contact impulse and
/// steps the contact nodes with the bulk (`contact::combined::stepper`). Proves: the measured
/// contact-free limit of a bulk is the same, bit for bit, whatever contact scheme it is measured
/// with, so a scene measures it once per bulk (`measured_critical_given_free`), and the split
/// measurement equals `measured_critical`.
#[test]
fn the_contact_free_limit_does_not_depend_on_the_contact_scheme() {
    let problem = problem();
    let penalty = |b| problem.penalty(b, MassPenalty::Ratio(1.0)).unwrap();
    let schemes = [
        ContactScheme::Penalty {
            stiffness: penalty(1e4).stiffness,
        },
        ContactScheme::Bipenalty(penalty(1e4)),
        ContactScheme::PredictorCorrector(penalty(1e4)),
        ContactScheme::LagrangeMultiplier,
    ];
    let park = ParkOptions {
        theta: 0.5,
        variant: ParkVariant::Incremental,
        local_stepping: true,
    };
    for bulk in [
        BulkScheme::CentralDifference,
        BulkScheme::Reciprocal { beta: 0.5 },
        BulkScheme::Park(park),
    ] {
        let free: Vec<f64> = schemes
            .iter()
            .map(|&s| CombinedIntegrator::measured_contact_free(&problem, bulk, s).unwrap())
            .collect();
        assert!(
            free.iter().all(|&f| f == free[0]),
            "{bulk:?}: contact-free limits {free:?}"
        );
        for scheme in schemes {
            let whole = CombinedIntegrator::measured_critical(&problem, bulk, scheme).unwrap();
            let split =
                CombinedIntegrator::measured_critical_given_free(&problem, bulk, scheme, free[0])
                    .unwrap();
            assert_eq!(whole, split, "{bulk:?} {}", scheme.label());
        }
    }
}
