//! `courant check` as JUnit XML: one test suite per scene that checked something (properties:
//! description, source, baseline directory), one test case per expectation verdict and per
//! compared baseline file. The files a report baseline does not keep are one property of their
//! suite, not hundreds of `<skipped>` cases; a scene or study with nothing checked has no suite.

use super::baseline::csv_diff::FileOutcome;
use super::baseline::scene_diff::FileComparison;
use super::gate::CheckReport;
use super::junit::{Failure, TestCase, TestSuite, render};
use crate::compare::verdict::Verdict;
use std::fmt::Write as _;

/// The test-case name of a verdict: `<case> <metric>`, plus ` at <t>` when it names a time.
pub fn testcase_name(v: &Verdict) -> String {
    let at = v.at.map(|t| format!(" at {t}")).unwrap_or_default();
    format!("{} {}{at}", v.case, v.metric_label())
}

/// The test case of a verdict (`classname`, name [`testcase_name`], `time` in seconds): a
/// failure says once how far the value is past its bound, its body the source; a passing case
/// says what was measured against which bound.
pub fn verdict_case(classname: &str, v: &Verdict, time: f64) -> TestCase {
    let failure = (!v.pass).then(|| Failure {
        message: v.excess(),
        kind: "expectation".into(),
        details: format!("bound {}; source: {}", v.bound, v.source),
    });
    let output = v.pass.then(|| {
        let finding = if v.finding {
            " (a stated finding: theory and run disagree)"
        } else {
            ""
        };
        format!(
            "measured {}, bound {}{finding}; source: {}",
            v.measured, v.bound, v.source
        )
    });
    TestCase {
        classname: classname.to_string(),
        name: testcase_name(v),
        failure,
        output,
        skipped: None,
        time,
    }
}

/// The JUnit test suites: one per scene with a check (properties: description, source,
/// baseline directory, the files the baseline does not keep), one test case per expectation
/// verdict (classname = scene, name = [`testcase_name`]) and per compared baseline file (name =
/// `baseline <file>`).
pub fn suites(report: &CheckReport) -> Vec<TestSuite> {
    report
        .scenes
        .iter()
        .map(|scene| {
            let mut properties = vec![
                ("description".to_string(), scene.description.clone()),
                ("source".to_string(), scene.source.clone()),
            ];
            if let Some((root, kind)) = &report.baseline {
                properties.push((
                    "baseline".into(),
                    root.join(&scene.name).display().to_string(),
                ));
                properties.push(("baseline_kind".into(), kind.label().into()));
                properties.push(("tolerances".into(), report.tolerances.describe()));
            }
            let mut cases: Vec<TestCase> = scene
                .verdicts
                .iter()
                .map(|v| verdict_case(&scene.name, v, scene.time_of(&v.case)))
                .collect();
            let not_kept: Vec<&str> = scene
                .baseline
                .iter()
                .flatten()
                .filter(|f| f.skipped())
                .map(|f| f.file.as_str())
                .collect();
            if !not_kept.is_empty() {
                properties.push((
                    "baseline_not_compared".into(),
                    format!(
                        "{} file(s) a report baseline does not keep: {}",
                        not_kept.len(),
                        not_kept.join(", ")
                    ),
                ));
            }
            for file in scene.baseline.iter().flatten().filter(|f| !f.skipped()) {
                cases.push(TestCase {
                    classname: scene.name.clone(),
                    name: format!("baseline {}", file.file),
                    failure: file.failure_message().map(|m| Failure {
                        message: m.lines().next().unwrap_or_default().to_string(),
                        kind: "baseline".into(),
                        details: m,
                    }),
                    output: Some(file_details(file)),
                    skipped: None,
                    time: 0.0,
                });
            }
            TestSuite {
                name: scene.name.clone(),
                timestamp: scene.started.clone(),
                time: scene.wall_time,
                properties,
                cases,
            }
        })
        .filter(|suite| !suite.cases.is_empty())
        .collect()
}

/// The JUnit XML document.
pub fn xml(report: &CheckReport) -> String {
    render("courant check", &suites(report), report.wall_time)
}

/// Every column of a compared file with its largest change, for the JUnit `<system-out>`.
fn file_details(file: &FileComparison) -> String {
    let mut text = format!("{}: {}", file.file, file.summary());
    if let FileOutcome::Compared {
        columns, ignored, ..
    } = &file.outcome
    {
        for column in columns {
            let _ = write!(text, "\n  {}", column.describe());
        }
        if !ignored.is_empty() {
            let _ = write!(text, "\n  ignored: {}", ignored.join(", "));
        }
    }
    text
}
