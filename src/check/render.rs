//! The terminal report of `courant check`: per scene a table of its expectations (verdict,
//! case, metric, measured value, bound, source), then its baseline files with the largest change
//! of each changed column; a summary line at the end.

use super::baseline::csv_diff::FileOutcome;
use super::baseline::scene_diff::FileComparison;
use super::gate::CheckReport;
use crate::compare::verdict::Verdict;
use std::fmt::Write as _;

fn verdict_word(pass: bool) -> &'static str {
    if pass { "pass" } else { "FAIL" }
}

/// The terminal report. By default one line per scene (a character per verdict: `.` pass, `f`
/// finding, `F` failed; its baseline files in brief), then every failure again with how far it
/// is past its bound, the findings, and a summary line; `verbose` gives each scene's full
/// table of verdicts and the largest change of every changed baseline column.
pub fn terminal(report: &CheckReport, verbose: bool) -> String {
    let mut out = String::new();
    let width = report
        .scenes
        .iter()
        .map(|s| s.name.chars().count())
        .max()
        .unwrap_or(0);
    for scene in &report.scenes {
        if verbose {
            let _ = writeln!(out, "{}: {}", scene.name, scene.description);
            let _ = writeln!(out, "  source: {}", scene.source);
            render_verdicts(&mut out, &scene.verdicts);
        } else {
            let marks: String = scene
                .verdicts
                .iter()
                .map(|v| match (v.pass, v.finding) {
                    (true, false) => '.',
                    (true, true) => 'f',
                    (false, _) => 'F',
                })
                .collect();
            let failed = scene.verdicts.iter().filter(|v| !v.pass).count();
            let verdict = if failed > 0 {
                format!("{failed} FAILED")
            } else {
                "pass".into()
            };
            let _ = writeln!(
                out,
                "{:<width$}  {verdict:<9} {} verdict(s) {marks}",
                scene.name,
                scene.verdicts.len()
            );
        }
        if let (Some((root, kind)), Some(files)) = (&report.baseline, &scene.baseline) {
            if verbose {
                let _ = writeln!(
                    out,
                    "  baseline {} ({}):",
                    root.join(&scene.name).display(),
                    kind.label()
                );
                render_baseline(&mut out, files);
            } else {
                let failed: Vec<&FileComparison> = files.iter().filter(|f| !f.passed()).collect();
                let _ = writeln!(
                    out,
                    "{:<width$}  baseline: {} file(s), {} failed{}",
                    "",
                    files.len(),
                    failed.len(),
                    failed
                        .iter()
                        .map(|f| format!("; {}: {}", f.file, f.summary()))
                        .collect::<String>()
                );
            }
        }
        if verbose {
            out.push('\n');
        }
    }
    let failures: Vec<(&str, &Verdict)> = report
        .scenes
        .iter()
        .flat_map(|s| {
            s.verdicts
                .iter()
                .filter(|v| !v.pass)
                .map(move |v| (s.name.as_str(), v))
        })
        .collect();
    if !failures.is_empty() && !verbose {
        let _ = writeln!(out, "\nfailures:");
        for (scene, v) in &failures {
            let _ = writeln!(out, "  {scene}: {}", v.describe());
            let _ = writeln!(out, "      {}", v.excess());
        }
    }
    let findings: Vec<(&str, &Verdict)> = report
        .scenes
        .iter()
        .flat_map(|s| {
            s.verdicts
                .iter()
                .filter(|v| v.finding)
                .map(move |v| (s.name.as_str(), v))
        })
        .collect();
    if !findings.is_empty() && !verbose {
        let _ = writeln!(
            out,
            "\nfindings (disagreements with stability theory or with a claim of the seed that the scenes state, with their sources):"
        );
        for (scene, v) in &findings {
            let _ = writeln!(out, "  {scene}/{}: {}", v.case, v.excess());
        }
    }
    if report.baseline.is_some() && verbose {
        let _ = writeln!(out, "baseline tolerances: {}", report.tolerances.describe());
    }
    let e = report.expectation_counts();
    let n_studies = report
        .scenes
        .iter()
        .filter(|s| s.name.starts_with("convergence:"))
        .count();
    let studies = match n_studies {
        0 => String::new(),
        1 => " and 1 convergence study".into(),
        n => format!(" and {n} convergence studies"),
    };
    let _ = write!(
        out,
        "\ncheck: {} scene(s){studies}, {} verdict(s): {} pass, {} finding(s), {} failed",
        report.scenes.len() - n_studies,
        e.total,
        e.total - e.failed - e.findings,
        e.findings,
        e.failed
    );
    if report.baseline.is_some() {
        let b = report.baseline_counts();
        let _ = write!(
            out,
            "; baseline: {} file(s), {} failed, {} not kept by the baseline",
            b.total, b.failed, b.skipped
        );
    }
    let _ = writeln!(out, ": {}", verdict_word(report.passed()));
    if !verbose {
        let _ = writeln!(
            out,
            "(verdicts: the scenes' expectations, the stability verdict of each case of a stability scene{}; the report counts these and the committed results of other codes. --verbose shows every verdict with its bound and source)",
            if studies.is_empty() {
                ""
            } else {
                " and the convergence-order bands"
            }
        );
    }
    out
}

fn render_verdicts(out: &mut String, verdicts: &[Verdict]) {
    if verdicts.is_empty() {
        out.push_str("  (no expectations)\n");
        return;
    }
    let rows: Vec<[String; 6]> = verdicts.iter().map(verdict_row).collect();
    render_rows(out, &rows);
}

/// One verdict as a row: verdict, case, metric (`at t` if it names a time), measured value,
/// bound, source.
pub fn verdict_row(v: &Verdict) -> [String; 6] {
    let at = v.at.map(|t| format!(" at {t}")).unwrap_or_default();
    [
        v.word().to_string(),
        v.case.clone(),
        format!("{}{at}", v.metric_label()),
        v.measured.to_string(),
        v.bound.to_string(),
        v.source.clone(),
    ]
}

/// Rows under the header `verdict, case, metric, measured, bound, source`, columns aligned
/// (measured values on the right), no trailing spaces.
pub fn render_rows(out: &mut String, rows: &[[String; 6]]) {
    let header = ["verdict", "case", "metric", "measured", "bound", "source"].map(String::from);
    let mut widths = [0; 6];
    for row in std::iter::once(&header).chain(rows) {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    for row in std::iter::once(&header).chain(rows) {
        let mut line = String::from(" ");
        for (i, (w, cell)) in widths.iter().zip(row).enumerate() {
            // Measured values line up on the right, the rest on the left; no trailing spaces.
            if i == 5 {
                let _ = write!(line, " {cell}");
            } else if i == 3 {
                let _ = write!(line, " {cell:>w$}");
            } else {
                let _ = write!(line, " {cell:<w$}");
            }
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
}

fn render_baseline(out: &mut String, files: &[FileComparison]) {
    let width = files
        .iter()
        .map(|f| f.file.chars().count())
        .max()
        .unwrap_or(0);
    for file in files {
        let verdict = if file.skipped() {
            "skip"
        } else {
            verdict_word(file.passed())
        };
        let _ = writeln!(
            out,
            "  {:<7} {:<width$}  {}",
            verdict,
            file.file,
            file.summary()
        );
        if let FileOutcome::Compared {
            columns, ignored, ..
        } = &file.outcome
        {
            let unchanged = columns.iter().filter(|c| !c.changed()).count();
            for column in columns.iter().filter(|c| c.changed()) {
                let _ = writeln!(out, "          {}", column.describe());
            }
            if unchanged > 0 && unchanged < columns.len() {
                let _ = writeln!(out, "          {unchanged} other column(s) identical");
            }
            if !ignored.is_empty() {
                let _ = writeln!(out, "          ignored: {}", ignored.join(", "));
            }
        }
    }
}
