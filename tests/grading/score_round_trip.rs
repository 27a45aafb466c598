//! Source of truth: the norms of `courant run` (docs/guide/running.md; `compare::norms`) and
//! the references of `courant-references` (d'Alembert, the graded and layered bars, 1D wave
//! theory of impact, closed-form discrete spectra).
//!
//! ```text
//!   courant run --exchange ──> files ──> courant score   ==  the run's own norms (1e-12)
//!   courant reference     ──> files ──> courant score   ==  0 (the exact answers graded)
//!   one case at N = 200, 400, 800 ──> courant score DIR1 DIR2 DIR3  ==  the report study's orders
//! ```
//!
//! Proves: a result set exported from `courant run` and read back from files scores identically
//! to the run itself: every stress profile norm of fig1, fig1_masses, fig2 (graded) and layered
//! to 1e-12, the force errors of contact_wall exactly (the graded force is exported) and its
//! impulse error to 1e-12 where the graded force is the momentum delivered, the closed-form deviation
//! of fig6 exactly, and the same verdict on every expectation both can measure; the exact
//! answers of `courant reference` (at the scene's mesh, and at a query of points or elements)
//! score zero against the same references; several sets of one case at different N give the
//! observed and fitted orders of `compare::convergence` for courant's own levels, judged against
//! the band of the report's study of that case.

use crate::exchange;

use courant::compare::convergence::{ConvergenceResult, Level};
use courant::compare::score::answers::exact_set;
use courant::compare::score::outcome::Scored;
use courant::compare::score::set::{score, score_set};
use courant::results::exchange::columns::Want;
use courant::results::exchange::reader::read_case;
use courant::scene::contact::ForceMeasure;
use exchange::{courant_set, derived, scene, scratch, through_files};

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs().max(1e-300) || (a - b).abs() <= 1e-12
}

#[test]
fn an_exported_run_scores_as_the_run_itself() {
    for name in ["fig1", "fig1_masses", "fig2", "layered"] {
        let s = scene(name);
        let (outcome, set) = courant_set(&s);
        let dir = scratch(&format!("export-{name}"));
        let scored = score_set(&s, &through_files(&set, &dir)).unwrap();
        for r in &outcome.results {
            let c = scored.cases.iter().find(|c| c.case == r.run.case).unwrap();
            let Scored::Profiles { profiles, points } = &c.scored else {
                panic!()
            };
            assert!(!points);
            assert_eq!(profiles.len(), r.profiles.len(), "{name} {}", r.run.case);
            for (p, q) in profiles.iter().zip(&r.profiles) {
                let own = q.norms.unwrap();
                assert_eq!(p.time, q.time);
                for (a, b) in [
                    (p.norms.l1, own.l1),
                    (p.norms.l2, own.l2),
                    (p.norms.linf, own.linf),
                    (p.norms.overshoot, own.overshoot),
                ] {
                    assert!(
                        close(a, b, 1e-12),
                        "{name} {} t = {}: {a} vs {b}",
                        r.run.case,
                        q.time
                    );
                }
                // Undefined (no variation of the exact profile) in both or in neither.
                match (p.norms.tv_ratio, own.tv_ratio) {
                    (Some(a), Some(b)) => {
                        assert!(close(a, b, 1e-12), "{name} {}: tv_ratio", r.run.case)
                    }
                    (a, b) => assert_eq!(a, b, "{name} {}: tv_ratio defined", r.run.case),
                }
            }
        }
        for v in &scored.verdicts {
            let own = outcome
                .verdicts
                .iter()
                .find(|o| o.case == v.case && o.metric == v.metric && o.at == v.at)
                .unwrap();
            assert_eq!(v.pass, own.pass, "{name}: {}", v.describe());
        }
        assert!(!scored.verdicts.is_empty(), "{name}: expectations measured");
    }
}

#[test]
fn exported_contact_histories_and_spectra_score_as_the_run() {
    let s = scene("contact_wall");
    let (outcome, set) = courant_set(&s);
    let scored = score_set(&s, &through_files(&set, &scratch("export-contact"))).unwrap();
    for r in &outcome.contact {
        let c = scored.cases.iter().find(|c| c.case == r.case).unwrap();
        let Scored::Force(f) = &c.scored else {
            panic!()
        };
        assert_eq!(f.errors, r.errors, "{}: the graded force's errors", r.case);
        if r.measure == ForceMeasure::TransferredMomentum {
            // Every step is sampled and the force ends at 0: the trapezoid rule over the momenta
            // per step is the run's sum of momenta, up to the order of additions.
            assert!(
                close(f.impulse_error, r.impulse_error, 1e-12),
                "{}: {} vs {}",
                r.case,
                f.impulse_error,
                r.impulse_error
            );
        }
    }
    let s = scene("fig6");
    let (outcome, set) = courant_set(&s);
    let scored = score_set(&s, &through_files(&set, &scratch("export-fig6"))).unwrap();
    for r in &outcome.spectra {
        let c = scored.cases.iter().find(|c| c.case == r.case).unwrap();
        let Scored::Spectrum(sp) = &c.scored else {
            panic!()
        };
        assert_eq!(Some(sp.deviation), r.closed_form_deviation(), "{}", r.case);
    }
    assert!(scored.passed());
}

#[test]
fn the_exact_answers_score_zero() {
    for name in ["fig1", "fig2", "layered", "contact_wall", "fig6"] {
        let s = scene(name);
        let set = exact_set(&s, None, name).unwrap();
        assert!(
            set.cases.iter().all(|c| c.reference.is_some()),
            "{name}: reference column"
        );
        let scored =
            score_set(&s, &through_files(&set, &scratch(&format!("exact-{name}")))).unwrap();
        for c in &scored.cases {
            match &c.scored {
                Scored::Profiles { profiles, .. } => {
                    for p in profiles {
                        assert!(
                            p.norms.linf <= 1e-15,
                            "{name} {} t = {}: {:?}",
                            c.case,
                            p.time,
                            p.norms
                        );
                    }
                }
                Scored::Force(f) => assert_eq!(f.errors.force_l1_error, 0.0, "{name} {}", c.case),
                Scored::Spectrum(sp) => assert_eq!(sp.deviation, 0.0, "{name} {}", c.case),
            }
        }
    }
}

#[test]
fn the_exact_answers_at_a_query_of_points_or_elements_score_zero() {
    let s = scene("fig1");
    for (query, points) in [
        (
            "t,x\n0.25,0\n0.25,0.1\n0.25,0.4\n0.25,1\n0.75,0.5\n0.75,0.9\n",
            true,
        ),
        (
            "t,x_left,x_right\n0.5,0,0.3\n0.5,0.3,0.55\n0.5,0.55,1\n",
            false,
        ),
    ] {
        let q = read_case("q.csv", "query", query, Want::Query).unwrap();
        let set = exact_set(&s, Some(&q), "fig1").unwrap();
        let dir = scratch(if points {
            "query-points"
        } else {
            "query-elements"
        });
        let scored = score_set(&s, &through_files(&set, &dir)).unwrap();
        for c in &scored.cases {
            let Scored::Profiles {
                profiles,
                points: p,
            } = &c.scored
            else {
                panic!()
            };
            assert_eq!(*p, points);
            assert_eq!(profiles.len(), if points { 2 } else { 1 });
            for p in profiles {
                assert_eq!(p.norms.linf, 0.0, "{}: {:?}", c.case, p.norms);
            }
        }
    }
    // d'Alembert at t = 0.25: -1 behind the front at x = 0.25, 0 ahead.
    let q = read_case("q.csv", "query", "t,x\n0.25,0.1\n0.25,0.4\n", Want::Query).unwrap();
    let set = exact_set(&s, Some(&q), "fig1").unwrap();
    let courant::results::exchange::record::CaseData::Profiles(p) = &set.cases[0].data else {
        panic!()
    };
    assert_eq!(p[0].stress, vec![-1.0, 0.0]);
}

#[test]
fn several_meshes_give_the_orders_of_the_report_study() {
    let sizes = [200, 400, 800];
    let mut sets = Vec::new();
    let mut own = Vec::new();
    for n in sizes {
        let s = derived("fig1", "elements = 100", &format!("elements = {n}"));
        let (outcome, set) = courant_set(&s);
        sets.push(through_files(&set, &scratch(&format!("mesh{n}"))));
        let r = outcome
            .results
            .iter()
            .find(|r| r.run.case == "co0.5")
            .unwrap();
        let first = r.profiles[0].norms.unwrap();
        own.push(Level {
            elements: n,
            dt: r.run.dt,
            steps: r.profiles[0].step,
            l1: first.l1,
            l2: first.l2,
            linf: first.linf,
            wall_time: 0.0,
        });
    }
    let outcome = score(&scene("fig1"), &sets).unwrap();
    let co = outcome
        .convergence
        .iter()
        .find(|c| c.case == "co0.5")
        .unwrap();
    assert_eq!(
        co.result.study.name, "fig1_co0.5",
        "the report's study of lumped CD at Co = 0.5"
    );
    let expected = ConvergenceResult {
        study: co.result.study.clone(),
        levels: own,
    };
    assert_eq!(co.result.levels.len(), 3);
    for (a, b) in co.result.verdicts().iter().zip(expected.verdicts()) {
        let (fa, fb) = (a.fitted.unwrap(), b.fitted.unwrap());
        assert!((fa - fb).abs() < 1e-12, "{}: {fa} vs {fb}", a.norm);
        assert_eq!(
            a.pass,
            Some(true),
            "{} order {fa} in {}",
            a.norm,
            a.expected
        );
    }
    let exact = outcome
        .convergence
        .iter()
        .find(|c| c.case == "co1")
        .unwrap();
    assert_eq!(exact.result.study.name, "fig1_co1");
    assert!(exact.passed(), "Co = 1 is exact on every mesh");
    let measured = outcome
        .convergence
        .iter()
        .find(|c| c.case == "co0.1")
        .unwrap();
    assert!(
        measured.note.is_some(),
        "no report study runs Co = 0.1: measured only"
    );
    // The scene's bounds hold on its mesh (N = 100); some it measured there do not hold on
    // these meshes (fig1's overshoot ratio of co0.1 to co0.5), the orders and the diagnostics do.
    for set in &outcome.sets {
        for c in &set.cases {
            assert!(
                c.diagnostics
                    .verdicts()
                    .iter()
                    .all(|v| v.verdict != Some(false)),
                "{}",
                c.case
            );
        }
    }
    assert!(outcome.convergence.iter().all(|c| c.passed()));
}
