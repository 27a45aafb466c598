//! `courant score` as JUnit XML: one test suite per result set (properties: scene, code,
//! version, directory), one test case per expectation verdict (skipped ones as `<skipped>`) and
//! per diagnostic (not measurable ones as `<skipped>`); one suite for the convergence studies,
//! one test case per fitted order.

use super::junit::{Failure, TestCase, TestSuite, render};
use super::junit_report::verdict_case;
use crate::compare::score::outcome::{ScoreOutcome, SkipKind};
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
            let name = format!("{} {}{at}", s.case, s.label);
            // What is not supplied fails under --require-all; the rest is skipped.
            let failure = (set.require_all && s.kind == SkipKind::NotSupplied).then(|| Failure {
                message: format!("{name}: {}", s.reason),
                kind: "not supplied".into(),
                details: s.reason.clone(),
            });
            let skipped = failure.is_none().then(|| s.reason.clone());
            cases.push(case(name, failure, s.source.clone(), skipped));
        }
        for c in &set.cases {
            for row in c.diagnostics.verdicts() {
                if row.note.starts_with("not applicable") {
                    continue;
                }
                let what = format!("{}; {}", row.measured, row.note);
                let failure = (row.verdict == Some(false)).then(|| Failure {
                    message: format!("{} {}: {what}", c.case, row.name),
                    kind: "diagnostic".into(),
                    details: what.clone(),
                });
                let skipped = row.verdict.is_none().then(|| row.note.clone());
                cases.push(case(
                    format!("{} {}", c.case, row.name),
                    failure,
                    what,
                    skipped,
                ));
            }
        }
        if set.require_all {
            for missing in &set.missing_cases {
                let why = format!("not supplied: no {missing}.csv in this set");
                cases.push(case(
                    format!("{missing} file"),
                    Some(Failure {
                        message: why.clone(),
                        kind: "not supplied".into(),
                        details: why.clone(),
                    }),
                    why,
                    None,
                ));
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
