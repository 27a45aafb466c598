//! `courant score` as JUnit XML: one test suite per result set (properties: scene, code,
//! version, directory), one test case per expectation verdict (skipped ones as `<skipped>`) and
//! per diagnostic (not measurable ones as `<skipped>`); one suite for the convergence studies,
//! one test case per fitted order.

use super::junit::{Failure, TestCase, TestSuite, render};
use super::junit_report::verdict_case;
use crate::compare::score::outcome::ScoreOutcome;
use crate::scene::cases::Scene;

/// The JUnit XML document; `started` is the ISO date the score started, `time` its wall time.
pub fn xml(scene: &Scene, outcome: &ScoreOutcome, started: &str, time: f64) -> String {
    let mut suites = Vec::new();
    for set in &outcome.sets {
        let classname = format!("{} {}", scene.name, set.label);
        let case = |name: String, failure: Option<Failure>, output: String, skipped| TestCase {
            classname: classname.clone(),
            name,
            failure,
            output: Some(output),
            skipped,
            time: 0.0,
        };
        let mut cases: Vec<TestCase> = set
            .verdicts
            .iter()
            .map(|v| verdict_case(&classname, v, 0.0))
            .collect();
        for s in &set.skipped {
            let at = s.at.map(|t| format!(" at {t}")).unwrap_or_default();
            cases.push(case(
                format!("{} {}{at}", s.case, s.label),
                None,
                s.source.clone(),
                Some(s.reason.clone()),
            ));
        }
        for c in &set.cases {
            for (name, verdict, measured, note) in c.diagnostics.verdicts() {
                let what = format!("{measured}; {note}");
                let failure = (verdict == Some(false)).then(|| Failure {
                    message: format!("{} {name}: {what}", c.case),
                    kind: "diagnostic".into(),
                    details: what.clone(),
                });
                let skipped = verdict.is_none().then(|| note.clone());
                cases.push(case(format!("{} {name}", c.case), failure, what, skipped));
            }
        }
        suites.push(TestSuite {
            name: classname.clone(),
            timestamp: started.to_string(),
            time,
            properties: vec![
                ("scene".into(), scene.name.clone()),
                ("code".into(), set.code.clone()),
                ("version".into(), set.version.clone()),
                ("results".into(), set.label.clone()),
            ],
            cases,
        });
    }
    if !outcome.convergence.is_empty() {
        let classname = format!("{} convergence", scene.name);
        let cases = outcome
            .convergence
            .iter()
            .flat_map(|study| {
                study.result.verdicts().into_iter().map(|v| {
                    let name = format!("{} order {}", study.case, v.norm);
                    let what = format!(
                        "fitted {}, expected {}",
                        v.fitted.map_or("-".into(), |p| format!("{p:.3}")),
                        v.expected
                    );
                    TestCase {
                        classname: classname.clone(),
                        failure: (v.pass == Some(false)).then(|| Failure {
                            message: format!("{name}: {what}"),
                            kind: "convergence".into(),
                            details: what.clone(),
                        }),
                        skipped: v
                            .pass
                            .is_none()
                            .then(|| "no band: measured only".to_string()),
                        name,
                        output: Some(what),
                        time: 0.0,
                    }
                })
            })
            .collect();
        suites.push(TestSuite {
            name: classname,
            timestamp: started.to_string(),
            time,
            properties: vec![("scene".into(), scene.name.clone())],
            cases,
        });
    }
    render("courant score", &suites, time)
}
