//! Source of truth: Park's step costs two internal-force evaluations per element (the element
//! predictions and the step's own `K u`, methods.md §6), central difference one; Park's rule
//! alpha_e <= 1 and the penalty's exact contact-active limit (methods.md §7); the exact force of
//! the layered impact (courant-references `LayeredImpact`; Graff 1975, ch. 2).
//!
//! Proves: the `impact_combined` work-precision study runs Park-LTS + bipenalty at 0.9 of Park's
//! rule and CD-LMM + penalty at 0.9 of its exact limit on every mesh, counts two element force
//! evaluations per step for Park and one for CD, and the report's sentence states the saving at
//! equal error computed from these points (the ratios of the cheapest runs within the common
//! error), not typed in.

use courant::compare::work_precision::{WorkPoint, equal_error_saving};
use courant::pipeline::studies::run_work_precision as run;
use courant::report::document::Block;
use courant::report::work_precision::study_page;
use courant::scene::studies::work_precision::{
    COMBINATION_FAST, COMBINATION_SLOW, COMBINATION_STUDY, WORK_PRECISION_STUDIES,
};

#[test]
fn park_lts_and_the_penalty_run_at_their_limits_and_the_saving_is_computed_from_the_rows() {
    let study = WORK_PRECISION_STUDIES
        .iter()
        .find(|s| s.name == COMBINATION_STUDY)
        .unwrap();
    let points = run(study).unwrap();
    let of = |method: &str| -> Vec<&WorkPoint> {
        points.iter().filter(|p| p.method == method).collect()
    };
    let meshes = study.contact_meshes.len();
    let park = of(COMBINATION_FAST);
    assert_eq!(park.len(), meshes);
    for p in &park {
        assert_eq!(p.force_evaluations, 2, "{p:?}");
        assert_eq!(p.element_force_evaluations(), 2 * p.elements * p.steps);
        assert!(
            (p.courant - 0.9).abs() < 1e-9 && p.courant < p.critical_courant,
            "{p:?}"
        );
    }
    for slow in COMBINATION_SLOW {
        let penalty = of(slow);
        assert_eq!(penalty.len(), meshes, "{slow}");
        for p in &penalty {
            assert_eq!(p.force_evaluations, 1, "{p:?}");
            assert!((p.courant / p.critical_courant - 0.9).abs() < 1e-9, "{p:?}");
        }
        let s = equal_error_saving(&points, COMBINATION_FAST, slow).unwrap();
        assert!(s.fast.l1 <= s.error && s.slow.l1 <= s.error);
        let stated: String = format!(
            "{:.0} times the steps and {:.0} times the element force evaluations",
            s.step_ratio(),
            s.evaluation_ratio()
        );
        let page = study_page(study, &points);
        let said = page
            .blocks
            .iter()
            .any(|b| matches!(b, Block::Paragraph(t) if t.contains(&stated)));
        assert!(said, "{stated} not in the page");
        eprintln!("{slow}: {stated} (error {:.3})", s.error);
    }
}
