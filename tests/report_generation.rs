//! Source of truth: the report contract of the README ("courant report"): every scene's tables
//! and verdicts and the convergence studies in `index.md`, every table also as CSV, timings only
//! in `timing.md`/`timing.csv`, written whole or not at all.
//!
//! Proves: on a reduced set (two scenes, one study) the report has the expected files with CSV
//! headers, its deterministic files are identical from one generation to the next (timings
//! apart), an expectation failure is flagged, and `courant report` replaces the output
//! directory whole.

use courant::builtin::builtin_scene;
use courant::report::{CONVERGENCE_STUDIES, generate};

fn reduced() -> courant::report::Report {
    let scenes = vec![
        builtin_scene("fig1").unwrap().unwrap(),
        builtin_scene("fig6").unwrap().unwrap(),
    ];
    let studies: Vec<_> = CONVERGENCE_STUDIES
        .iter()
        .filter(|s| s.name == "fig1_co1")
        .cloned()
        .collect();
    generate(&scenes, &studies).unwrap()
}

#[test]
fn report_has_sections_tables_and_deterministic_content() {
    let (a, b) = (reduced(), reduced());
    assert!(a.passed);
    let names: Vec<&str> = a.files.iter().map(|f| f.0.as_str()).collect();
    for expected in [
        "index.md",
        "timing.md",
        "timing.csv",
        "fig1/summary.csv",
        "fig1/norms.csv",
        "fig6/summary.csv",
        "convergence/fig1_co1.csv",
        "work_precision/fig5_contact.csv",
        "timing.work_precision.csv",
    ] {
        assert!(
            names.contains(&expected),
            "{expected} missing from {names:?}"
        );
    }
    let index = &a.files.iter().find(|f| f.0 == "index.md").unwrap().1;
    assert!(
        index.contains("## fig1")
            && index.contains("## fig6")
            && index.contains("## Convergence studies")
    );
    assert!(index.contains("pass  co1 linf"), "verdicts listed");
    assert!(!index.contains("wall_time"), "timings stay out of index.md");
    let cpu = &a
        .files
        .iter()
        .find(|f| f.0 == "timing.work_precision.csv")
        .unwrap()
        .1;
    assert!(cpu.starts_with("study,method,N,steps,l1,wall_time_s\n"));
    assert!(
        cpu.contains("fig5_contact,lagrange-multiplier,"),
        "contact schemes timed"
    );
    let html = &a.files.iter().find(|f| f.0 == "index.html").unwrap().1;
    assert!(html.starts_with("<!DOCTYPE html>") && html.trim_end().ends_with("</html>"));
    for tag in ["table", "tr", "ul", "p", "h2", "figure", "svg"] {
        let (open, close) = (
            html.matches(&format!("<{tag}>")).count() + html.matches(&format!("<{tag} ")).count(),
            html.matches(&format!("</{tag}>")).count(),
        );
        assert_eq!(
            open, close,
            "<{tag}> opened {open} times, closed {close} times"
        );
    }
    assert!(
        !html.contains("src=\"http") && !html.contains("href=\"http"),
        "no network resources are loaded"
    );
    assert!(!html.contains("<script"), "no scripts");
    for (name, text) in &a.files {
        if name.ends_with(".csv") {
            let mut reader = csv::Reader::from_reader(text.as_bytes());
            let width = reader.headers().unwrap().len();
            assert!(width >= 2, "{name}");
            assert!(
                reader.records().all(|r| r.unwrap().len() == width),
                "{name}: ragged rows"
            );
        }
        if !name.starts_with("timing") {
            let other = &b.files.iter().find(|f| &f.0 == name).unwrap().1;
            assert_eq!(text, other, "{name} differs between two generations");
        }
    }
}

#[test]
fn courant_report_replaces_the_output_directory_whole() {
    let dir = std::env::temp_dir().join(format!("courant-report-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("old")).unwrap();
    std::fs::write(dir.join("old/stale.txt"), "stale").unwrap();
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(["report", "--out", dir.join("old").to_str().unwrap()])
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(0));
    assert!(dir.join("old/index.md").exists());
    assert!(
        !dir.join("old/stale.txt").exists(),
        "the previous report is replaced whole"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
