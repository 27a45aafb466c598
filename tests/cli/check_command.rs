//! Source of truth: the guide's CI-gating contract (docs/guide/ci.md, "Gating CI") and the issue behind it:
//! `courant check [SCENES...] [--junit FILE] [--baseline DIR] [--out DIR]` runs the scenes'
//! expectations, prints each with its measured value, bound, verdict and source, and exits 0
//! when all hold, 1 when any fails, 2 on bad input (nothing written); `--junit` writes JUnit XML
//! (one testsuite per scene, one testcase per expectation, a `<failure>` for each failed one);
//! `--baseline` compares the fresh CSVs with a previous report (`courant report --out DIR`, e.g.
//! the committed `reports/`) or a previous `courant run --out DIR` under per-column tolerances
//! (relative with an absolute floor, peak-relative for stress profiles, exact integers, ignored
//! wall times; each settable with `--rel`, `--abs`, `--peak-rel`, `--peak-abs`, `--column`) and
//! fails naming the file and column that moved.
//!
//! Proves, with the built binary on the fig1 scene (milliseconds per run): the committed
//! expectations pass; a deliberately broken expectation exits 1 and appears as a `<failure>` in
//! a well-formed JUnit file (checked by the shared XML parser `tests/common/xml.rs`: balanced tags, quoted
//! attributes, valid entities, `testsuites/testsuite/testcase/failure` nesting, consistent
//! counts); a baseline from a fresh run passes, survives round-off-sized edits and wall-time
//! changes, and fails on a stress change beyond tolerance or a missing file, naming them; the
//! committed report is a baseline that passes (per-case files it does not keep are JUnit
//! `<skipped>`), a changed report column fails until `--column` loosens that column (a misspelt
//! column and `--out` over a report baseline are refused); a
//! bad scene or a bad tolerance exits 2 and writes neither the JUnit file nor the output
//! directories.

use std::path::Path;
use std::process::Output;

fn text(out: &Output) -> String {
    format!(
        "stdout:\n{}\nstderr:\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

// The XML checker shared by the integration tests (its own test is in report_generation.rs).
use crate::xml;
use xml::{Element, parse_xml};

use crate::cli;
use cli::{courant, scratch};

/// Parse a JUnit file and check its nesting and counts; returns the root.
fn junit(path: &Path) -> Element {
    let doc = std::fs::read_to_string(path).unwrap();
    let root = parse_xml(&doc).unwrap_or_else(|e| panic!("not well-formed XML: {e}\n{doc}"));
    assert_eq!(root.name, "testsuites");
    let (mut tests, mut failures, mut skips) = (0, 0, 0);
    for suite in &root.children {
        assert_eq!(suite.name, "testsuite");
        let (mut cases, mut failed, mut skipped) = (0, 0, 0);
        for child in &suite.children {
            match child.name.as_str() {
                "properties" => assert!(child.children.iter().all(|p| p.name == "property")),
                "testcase" => {
                    cases += 1;
                    assert_eq!(child.value("classname"), suite.value("name"));
                    for grandchild in &child.children {
                        assert!(
                            ["failure", "skipped", "system-out"]
                                .contains(&grandchild.name.as_str()),
                            "unexpected <{}> in a testcase",
                            grandchild.name
                        );
                        assert!(grandchild.children.is_empty());
                    }
                    failed += usize::from(child.child("failure").is_some());
                    skipped += usize::from(child.child("skipped").is_some());
                    assert!(
                        !(child.child("failure").is_some() && child.child("skipped").is_some())
                    );
                }
                other => panic!("unexpected <{other}> in a testsuite"),
            }
        }
        assert_eq!(suite.value("tests"), cases.to_string());
        assert_eq!(suite.value("failures"), failed.to_string());
        assert_eq!(suite.value("errors"), "0");
        assert_eq!(suite.value("skipped"), skipped.to_string());
        // Ant schema: time in seconds, timestamp ISO 8601 without a zone, a hostname.
        let time: f64 = suite.value("time").parse().expect("time is a number");
        assert!(time >= 0.0);
        let stamp = suite.value("timestamp");
        let shape: String = stamp
            .chars()
            .map(|c| if c.is_ascii_digit() { '9' } else { c })
            .collect();
        assert_eq!(shape, "9999-99-99T99:99:99", "timestamp {stamp}");
        assert!(!suite.value("hostname").is_empty());
        tests += cases;
        failures += failed;
        skips += skipped;
    }
    assert_eq!(root.value("tests"), tests.to_string());
    assert_eq!(root.value("failures"), failures.to_string());
    assert_eq!(root.value("skipped"), skips.to_string());
    root
}

fn testcases(root: &Element) -> Vec<&Element> {
    root.children
        .iter()
        .flat_map(|s| &s.children)
        .filter(|c| c.name == "testcase")
        .collect()
}

/// The lines of `courant check`'s table whose verdict is FAIL.
fn failed_lines(stdout: &str) -> Vec<&str> {
    stdout
        .lines()
        .filter(|l| l.trim_start().starts_with("FAIL"))
        .collect()
}

#[test]
fn check_fig1_passes_on_the_committed_expectations() {
    let dir = scratch("pass");
    let report = dir.join("junit").join("fig1.xml");
    let out = courant(&["check", "fig1", "--junit", s(&report), "--verbose"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let stdout = String::from_utf8(out.stdout).unwrap();
    for column in ["verdict", "case", "metric", "measured", "bound", "source"] {
        assert!(stdout.contains(column), "table lacks {column}: {stdout}");
    }
    assert!(!stdout.contains("FAIL"), "{stdout}");
    let scene = courant::scene::builtin::builtin_scene("fig1")
        .unwrap()
        .unwrap();
    for e in &scene.expectations {
        assert!(stdout.contains(&e.source), "source not shown: {}", e.source);
    }
    // One testcase per verdict, none failed, every one named "<case> <metric>".
    let verdicts = courant::pipeline::evaluate_scene(&scene).unwrap().verdicts;
    let root = junit(&report);
    let cases = testcases(&root);
    assert_eq!(cases.len(), verdicts.len());
    assert_eq!(root.children[0].value("name"), "fig1");
    for v in &verdicts {
        let name = courant::check::junit_report::testcase_name(v);
        assert!(
            cases.iter().any(|c| c.value("name") == name),
            "no testcase {name}"
        );
    }
    assert!(cases.iter().all(|c| c.child("failure").is_none()));
    assert_eq!(
        std::fs::read_dir(dir.join("junit")).unwrap().count(),
        1,
        "only the report, no temporary file, is left"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_broken_expectation_exits_1_with_a_junit_failure_for_that_testcase() {
    let dir = scratch("strict");
    let text_in = courant::scene::builtin::builtin_text("fig1")
        .unwrap()
        .replace("max = 1e-10", "max = 1e-30");
    let path = dir.join("strict.toml");
    std::fs::write(&path, text_in).unwrap();
    let report = dir.join("report.xml");
    let results = dir.join("out");
    let out = courant(&[
        "check",
        "--verbose",
        s(&path),
        "--junit",
        s(&report),
        "--out",
        s(&results),
    ]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let stdout = String::from_utf8(out.stdout).unwrap();
    let failed: Vec<&str> = stdout.lines().filter(|l| l.contains("FAIL")).collect();
    assert_eq!(
        failed.len(),
        2,
        "the co1 linf row and the summary: {stdout}"
    );
    assert!(failed[0].contains("co1") && failed[0].contains("linf"));
    assert!(failed[0].contains("<= 1e-30") && failed[0].contains("methods.md §3"));

    let root = junit(&report);
    assert_eq!(root.value("failures"), "1");
    assert_eq!(root.children[0].value("name"), "strict");
    for case in testcases(&root) {
        let failure = case.child("failure");
        if case.value("name") == "co1 linf" {
            // The message says once how far past the bound; the body gives bound and source.
            let failure = failure.expect("co1 linf must fail");
            let message = failure.value("message");
            assert!(
                message.contains("8.9706e-14 > 1e-30: 9e16 x the bound"),
                "{message}"
            );
            assert!(failure.text.contains("bound <= 1e-30"), "{}", failure.text);
            assert!(failure.text.contains("methods.md §3"), "names its source");
            assert!(
                case.child("system-out").is_none(),
                "said once, in the failure"
            );
        } else {
            assert!(failure.is_none(), "{} must pass", case.value("name"));
        }
    }
    // Escaping round-trips: a source with '<' reads back intact.
    assert!(
        testcases(&root)
            .iter()
            .filter_map(|c| c.child("system-out"))
            .any(|o| o.text.contains("Co < 1 cannot look exact"))
    );
    // --out writes the result directory like `run` does, failure recorded.
    let expectations =
        std::fs::read_to_string(results.join("strict").join("expectations.csv")).unwrap();
    assert!(expectations.contains("FAIL"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Replace the `column`-th field of CSV line `line` (1-based, header = 1) by `edit(value)`.
fn edit_cell(path: &Path, line: usize, column: usize, edit: impl Fn(f64) -> f64) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let mut fields: Vec<String> = lines[line - 1].split(',').map(str::to_string).collect();
    fields[column] = format!("{:?}", edit(fields[column].parse().unwrap()));
    lines[line - 1] = fields.join(",");
    std::fs::write(path, lines.join("\n") + "\n").unwrap();
}

#[test]
fn baseline_of_a_fresh_run_passes_and_a_changed_number_fails_naming_file_and_column() {
    let dir = scratch("baseline");
    let base = dir.join("base");
    let run = courant(&["run", "fig1", "--out", s(&base)]);
    assert!(run.status.success(), "{}", text(&run));
    let check = |report: &Path| {
        courant(&[
            "check",
            "--verbose",
            "fig1",
            "--baseline",
            s(&base),
            "--junit",
            s(report),
        ])
    };

    let out = check(&dir.join("same.xml"));
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    assert!(String::from_utf8_lossy(&out.stdout).contains("; baseline: 12 file(s), 0 failed"));
    let root = junit(&dir.join("same.xml"));
    assert!(
        testcases(&root)
            .iter()
            .any(|c| c.value("name") == "baseline co0.5.csv")
    );

    // Within tolerance: a 1e-10 relative change of a stress and a different wall time pass.
    let profile = base.join("fig1").join("co0.5.csv");
    assert_eq!(
        std::fs::read_to_string(&profile).unwrap().lines().next(),
        Some("t,element,x,stress,reference,error")
    );
    let original = std::fs::read_to_string(&profile).unwrap();
    edit_cell(&profile, 52, 3, |x| x * (1.0 + 1e-10));
    edit_cell(&base.join("fig1").join("summary.csv"), 2, 19, |_| 999.0);
    let out = check(&dir.join("close.xml"));
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));

    // Beyond tolerance: 1e-6 on a stress whose column peaks near 1 (allowed: 1e-9 of the peak).
    std::fs::write(&profile, &original).unwrap();
    edit_cell(&profile, 52, 3, |x| x + 1e-6);
    let out = check(&dir.join("changed.xml"));
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let stdout = String::from_utf8(out.stdout).unwrap();
    let failed = failed_lines(&stdout);
    assert_eq!(failed.len(), 1, "only the edited file fails: {stdout}");
    assert!(failed[0].contains("co0.5.csv") && failed[0].contains("stress"));
    assert!(stdout.contains("line 52"), "names the line: {stdout}");
    let root = junit(&dir.join("changed.xml"));
    let case = testcases(&root)
        .into_iter()
        .find(|c| c.value("name") == "baseline co0.5.csv")
        .unwrap();
    let failure = case.child("failure").expect("the edited file fails");
    assert!(failure.value("message").contains("co0.5.csv"));
    assert!(failure.value("message").contains("stress"));
    assert_eq!(root.value("failures"), "1");

    // A file missing from the baseline fails too.
    std::fs::write(&profile, &original).unwrap();
    std::fs::remove_file(base.join("fig1").join("norms.csv")).unwrap();
    let out = check(&dir.join("missing.xml"));
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout
            .lines()
            .any(|l| l.contains("FAIL") && l.contains("norms.csv") && l.contains("missing")),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The committed report (`reports/`, regenerated by CI) as a baseline: its tables are compared,
/// the per-case files it does not keep are named once per suite (no `<skipped>` case each); a copy with one `l1` cell moved by 1e-6
/// relative fails naming `summary.csv` and `l1`, and passes again once `--column l1=rel:1e-5`
/// allows exactly that.
#[test]
fn the_committed_report_is_a_baseline_and_a_moved_report_column_fails_until_allowed() {
    let dir = scratch("report-baseline");
    let committed = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    let junit_file = dir.join("report.xml");
    let out = courant(&[
        "check",
        "--verbose",
        "fig1",
        "fig6",
        "contact_wall",
        "--baseline",
        s(&committed),
        "--junit",
        s(&junit_file),
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("(report):"), "{stdout}");
    let root = junit(&junit_file);
    let cases = testcases(&root);
    let named = |name: &str| {
        cases
            .iter()
            .copied()
            .find(|c| c.value("classname") == "fig1" && c.value("name") == name)
            .unwrap_or_else(|| panic!("no testcase {name}"))
    };
    // The files a report does not keep are one property of the suite, not a skipped case each.
    assert!(
        !cases
            .iter()
            .any(|c| c.value("name") == "baseline co0.5.csv"),
        "a file not compared is no testcase"
    );
    assert_eq!(root.value("skipped"), "0", "no skipped noise");
    let fig1 = root
        .children
        .iter()
        .find(|suite| suite.value("name") == "fig1")
        .unwrap();
    let properties = fig1.child("properties").unwrap();
    let not_compared = properties
        .children
        .iter()
        .find(|p| p.value("name") == "baseline_not_compared")
        .expect("the files not compared are named once");
    assert!(
        not_compared.value("value").contains("co0.5.csv"),
        "{}",
        not_compared.value("value")
    );
    // Real times: a verdict's case carries the wall time of the run it judges (microseconds).
    let time: f64 = named("co1 linf").value("time").parse().unwrap();
    assert!(time > 0.0, "a real time, not 0.000");
    for table in ["summary.csv", "norms.csv", "expectations.csv"] {
        let case = named(&format!("baseline {table}"));
        assert!(case.child("skipped").is_none() && case.child("failure").is_none());
    }

    // A report-shaped copy of fig1 with one l1 cell moved by 1e-6 relative.
    let copy = dir.join("report");
    std::fs::create_dir_all(copy.join("fig1")).unwrap();
    std::fs::copy(committed.join("index.md"), copy.join("index.md")).unwrap();
    for table in ["summary.csv", "norms.csv", "expectations.csv"] {
        std::fs::copy(
            committed.join("fig1").join(table),
            copy.join("fig1").join(table),
        )
        .unwrap();
    }
    let summary = copy.join("fig1").join("summary.csv");
    let header = std::fs::read_to_string(&summary).unwrap();
    let l1 = header
        .lines()
        .next()
        .unwrap()
        .split(',')
        .position(|c| c == "l1")
        .unwrap();
    edit_cell(&summary, 3, l1, |x| x * (1.0 + 1e-6));
    let check_copy = |extra: &[&str]| {
        let mut args = vec!["check", "fig1", "--verbose", "--baseline", s(&copy)];
        args.extend_from_slice(extra);
        courant(&args)
    };
    let out = check_copy(&[]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let stdout = String::from_utf8(out.stdout).unwrap();
    let failed = failed_lines(&stdout);
    assert_eq!(failed.len(), 1, "{stdout}");
    assert!(failed[0].contains("summary.csv") && failed[0].contains("l1"));
    let out = check_copy(&["--column", "l1=rel:1e-5"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    assert!(String::from_utf8_lossy(&out.stdout).contains("l1: relative (rel 1e-5"));
    // A misspelt column loosens nothing: refused, not passed silently.
    let out = check_copy(&["--column", "l1x=rel:1e-5"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(String::from_utf8_lossy(&out.stderr).contains("l1x"));
    // Run output is never written over a report baseline.
    let before = std::fs::read_dir(copy.join("fig1")).unwrap().count();
    let out = check_copy(&["--out", s(&copy)]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert_eq!(
        std::fs::read_dir(copy.join("fig1")).unwrap().count(),
        before
    );
    // A table the report keeps but the copy lost fails.
    std::fs::remove_file(copy.join("fig1").join("norms.csv")).unwrap();
    let out = check_copy(&["--rel", "1e-3"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_exits_2_and_writes_nothing() {
    let dir = scratch("bad");
    let bad = dir.join("bad.toml");
    let text_in = courant::scene::builtin::builtin_text("fig1")
        .unwrap()
        .replace("elements = 100", "elements = 100\nbogus = 1");
    std::fs::write(&bad, text_in).unwrap();
    let (report, results) = (dir.join("report.xml"), dir.join("out"));
    let nowhere = dir.join("nowhere");
    let here = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    let attempts: [&[&str]; 6] = [
        // a scene that does not parse, after a good one
        &["check", "fig1", s(&bad)],
        // no such scene
        &["check", "no_such_scene"],
        // a baseline that is not a directory
        &["check", "fig1", "--baseline", s(&nowhere)],
        // a negative tolerance, a malformed column rule, a tolerance without a baseline
        &["check", "fig1", "--baseline", s(&here), "--rel", "-1"],
        &[
            "check",
            "--verbose",
            "fig1",
            "--baseline",
            s(&here),
            "--column",
            "l1=rel",
        ],
        &["check", "fig1", "--abs", "1e-9"],
    ];
    for args in attempts {
        let mut args = args.to_vec();
        args.extend(["--junit", s(&report), "--out", s(&results)]);
        let out = courant(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", text(&out));
        assert!(!String::from_utf8_lossy(&out.stderr).is_empty());
        assert!(!report.exists(), "{args:?} wrote the JUnit file");
        assert!(!results.exists(), "{args:?} wrote results");
    }
    let out = courant(&["check", "fig1", "--baseline", s(&here), "--rel", "-1"]);
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(
        stderr.contains("--rel") && stderr.contains("-1") && stderr.contains(">= 0"),
        "names the flag, the value and the rule: {stderr}"
    );
    let out = courant(&["check", s(&bad)]);
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(
        stderr.contains("bad.toml") && stderr.contains("bogus"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
