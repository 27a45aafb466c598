//! Source of truth: the closed-form critical Courant number of CD with penalty only for two equal
//! bars, Cr_two(beta_s) = Cr_wall(2 beta_s), Cr_wall = sqrt(2/(1 + sqrt(1 + beta_s^2)))
//! (methods.md §7, `courant-references`); 1D wave theory of the Fig. 5 impact (methods.md §7);
//! and similarity: at fixed dimensionless beta_s = k_s h/(E A) and Courant number the contact
//! nodes' discrete dynamics in units of h/c are the same on every mesh.
//!
//! Proves: the fig5_contact work-precision study runs CD with penalty at 0.9 of its own exact
//! critical step (below the limit, which equals the closed form) beside the other schemes at
//! Co = 0.5, on every mesh, with about 0.5/0.018 = 28 times their steps; its points are labelled
//! with their Courant setting in the table's Co column, in the three log-log charts (the third
//! against element force evaluations, one per step here) and in the CPU-time
//! chart; its force error is finite, O(1) and mesh-independent (the stiff penalty spring rattles,
//! similarity), far above the converging predictor-corrector and Lagrange-multiplier errors.

use courant::compare::work_precision::WorkPoint;
use courant::pipeline::studies::run_work_precision as run;
use courant::report::work_precision::{cpu_chart, study_page};
use courant::scene::studies::work_precision::WORK_PRECISION_STUDIES;
use courant_references::contact::signorini_critical_courant_penalty;

use crate::xml;

fn svg_texts(svg: &str) -> Vec<String> {
    xml::parse_xml(svg)
        .unwrap_or_else(|e| panic!("{e}"))
        .descendants()
        .into_iter()
        .filter(|e| e.name == "text")
        .map(|e| e.text.trim().to_string())
        .collect()
}

#[test]
fn cd_penalty_runs_at_its_own_stable_step_with_its_courant_number_stated() {
    let study = WORK_PRECISION_STUDIES
        .iter()
        .find(|s| s.name == "fig5_contact")
        .unwrap();
    let points = run(study).unwrap();
    let of = |method: &str| -> Vec<&WorkPoint> {
        points.iter().filter(|p| p.method == method).collect()
    };
    let penalty = of("cd-penalty-bs2500");
    let meshes = study.contact_meshes.len();
    assert_eq!(penalty.len(), meshes, "a penalty point on every mesh");
    let closed = signorini_critical_courant_penalty(2.0 * 2500.0).unwrap();
    for p in &penalty {
        assert_eq!(p.label(), "cd-penalty-bs2500 (Co = 0.9 Co_crit)");
        assert!(
            (p.critical_courant - closed).abs() <= 1e-6 * closed,
            "N = {}: Co_crit {} vs closed form {closed}",
            p.elements,
            p.critical_courant
        );
        assert!(p.courant < p.critical_courant);
        assert!((p.courant / p.critical_courant - 0.9).abs() < 1e-12);
        assert!(p.l1.is_finite() && p.l1 > 0.1 && p.l1 < 3.0, "{p:?}");
    }
    for method in [
        "cd-bipenalty-bs2500",
        "predictor-corrector-bs2500",
        "lagrange-multiplier",
    ] {
        let others = of(method);
        assert_eq!(others.len(), meshes, "{method}");
        for (o, p) in others.iter().zip(&penalty) {
            assert_eq!(o.label(), format!("{method} (Co = 0.5)"));
            assert_eq!(o.elements, p.elements);
            assert!((o.courant - 0.5).abs() < 1e-12 && o.courant < o.critical_courant);
            let ratio = p.steps as f64 / o.steps as f64;
            assert!(
                (27.0..28.5).contains(&ratio),
                "N = {}: penalty takes {ratio} times the steps of {method}",
                o.elements
            );
            assert!(o.l1.is_finite(), "{o:?}");
        }
    }
    // Similarity: the penalty error does not depend on the mesh; the exact-constraint schemes
    // converge and end far below it.
    let (lo, hi) = penalty.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), p| {
        (lo.min(p.l1), hi.max(p.l1))
    });
    assert!(hi / lo < 1.02, "penalty errors {lo}..{hi}");
    let lm = of("lagrange-multiplier");
    assert!(lm.windows(2).all(|w| w[1].l1 < w[0].l1), "LM converges");
    assert!(lm[meshes - 1].l1 * 100.0 < lo, "LM at the finest mesh");

    // The Courant setting is stated in the table, the three work charts and the CPU chart; the
    // table counts one force evaluation per step (central difference on the bulk).
    let page = study_page(study, &points);
    let (report, files) = (page.blocks, page.files);
    let csv = &files
        .iter()
        .find(|f| f.0 == "work_precision/fig5_contact.csv")
        .unwrap()
        .1;
    assert!(csv.starts_with(
        "method,Co,Co_crit,N,steps,node_steps,l1,force_evals_per_step,element_force_evals\n"
    ));
    let row = csv
        .lines()
        .find(|l| l.starts_with("cd-penalty-bs2500,"))
        .unwrap();
    let co: f64 = row.split(',').nth(1).unwrap().parse().unwrap();
    assert!((co - 0.9 * closed).abs() < 1e-6 * closed, "{row}");
    let cells: Vec<&str> = row.split(',').collect();
    assert_eq!(cells[7], "1", "{row}");
    assert_eq!(
        cells[8], cells[5],
        "one K u per step: evaluations = node-steps: {row}"
    );
    let charts: Vec<&(String, String)> = files.iter().filter(|f| f.0.ends_with(".svg")).collect();
    assert_eq!(
        charts.len(),
        3,
        "error against elements x steps, against steps, against force evaluations"
    );
    let cpu = cpu_chart(study, &points).expect("timed points");
    for svg in charts.iter().map(|f| f.1.as_str()).chain([cpu.as_str()]) {
        let texts = svg_texts(svg);
        for label in [
            "cd-penalty-bs2500 (Co = 0.9 Co_crit)",
            "cd-bipenalty-bs2500 (Co = 0.5)",
        ] {
            assert!(texts.iter().any(|t| t == label), "{label} not in {texts:?}");
        }
    }
    assert!(
        report.len() >= 4,
        "heading, three figures and the table: {}",
        report.len()
    );
}
