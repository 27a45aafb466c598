//! The terminal report of `courant score`: per result set a line per case (size, step, worst
//! norms or measures), then one table of checks in `courant check`'s layout (the scene's
//! expectations, those skipped with the reason, and the diagnostics of every case), then the
//! convergence studies across sets and a summary line.

use super::render::{render_rows, verdict_row};
use crate::compare::score::outcome::{ScoreOutcome, Scored, ScoredCase, ScoredSet, SkipKind};
use crate::scene::cases::Scene;
use std::fmt::Write as _;

/// Counts of the checks of a score.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ScoreCounts {
    /// Expectation verdicts.
    pub expectations: usize,
    /// Signature rows of a scheme or mass the files do not declare.
    pub not_applicable: usize,
    /// Expectations whose case or time no file supplies, and cases with no file.
    pub not_supplied: usize,
    /// Expectations files cannot answer (energies, divergence).
    pub skipped: usize,
    /// Diagnostics with a verdict.
    pub diagnostics: usize,
    /// Fitted orders with a band.
    pub orders: usize,
    /// Failed checks of all kinds.
    pub failed: usize,
    /// Failures stated as findings of the code (`--stated`).
    pub findings: usize,
}

/// Count the checks of `outcome`.
pub fn counts(outcome: &ScoreOutcome) -> ScoreCounts {
    let mut c = ScoreCounts::default();
    for set in &outcome.sets {
        c.expectations += set.verdicts.len();
        c.failed += set.verdicts.iter().filter(|v| !v.pass).count();
        c.findings += set.verdicts.iter().filter(|v| v.finding).count();
        c.failed += set.stated.iter().filter(|s| !s.holds).count();
        for s in &set.skipped {
            match s.kind {
                SkipKind::NotApplicable => c.not_applicable += 1,
                SkipKind::NotSupplied => c.not_supplied += 1,
                SkipKind::NotMeasurable => c.skipped += 1,
            }
        }
        c.not_supplied += set.missing_cases.len();
        if set.require_all {
            c.failed += set.not_supplied() + set.missing_cases.len();
        }
        for (_, row, stated) in set.diagnostic_rows() {
            if let Some(pass) = row.verdict {
                c.diagnostics += 1;
                if stated {
                    c.findings += 1;
                } else {
                    c.failed += usize::from(!pass);
                }
            }
        }
    }
    for study in &outcome.convergence {
        for v in study.result.verdicts() {
            if let Some(pass) = v.pass {
                c.orders += 1;
                c.failed += usize::from(!pass);
            }
        }
    }
    c
}

fn word(v: Option<bool>) -> &'static str {
    match v {
        Some(true) => "pass",
        Some(false) => "FAIL",
        None => "n/a",
    }
}

/// One line of what a case file measured.
fn case_line(c: &ScoredCase) -> String {
    let dt =
        c.dt.map(|(dt, from)| format!(", dt = {dt:.6e} ({from})"))
            .unwrap_or_default();
    match &c.scored {
        Scored::Profiles { profiles, points } => {
            let n = c.worst_norms();
            let f = |x: Option<f64>| x.map_or("-".to_string(), |x| format!("{x:.3e}"));
            format!(
                "{}: {} {} x {} time(s) read ({} rows){dt}; worst L1 {}, L2 {}, Linf {}, overshoot {}",
                c.case,
                c.read.values,
                if *points { "points" } else { "elements" },
                profiles.len(),
                c.read.rows,
                f(n.map(|n| n.l1)),
                f(n.map(|n| n.l2)),
                f(n.map(|n| n.linf)),
                f(n.map(|n| n.overshoot)),
            )
        }
        Scored::Force(force) => format!(
            "{}: {} samples{dt}; plateau deviation {:.3e}, impulse error {:.3e}, duration error {:.3e}, force L1 error {:.3e}",
            c.case,
            force.time.len(),
            force.errors.plateau_deviation.unwrap_or(f64::NAN),
            force.impulse_error,
            force.errors.duration_error.unwrap_or(f64::NAN),
            force.errors.force_l1_error
        ),
        Scored::Spectrum(s) => format!(
            "{}: {} mode(s); closed-form deviation {:.3e}",
            c.case,
            s.rows.len(),
            s.deviation
        ),
    }
}

/// The check rows of a set: expectation verdicts, skipped expectations, diagnostics (those that
/// do not apply to the kind of file, e.g. every one of a spectrum, left out).
pub fn check_rows(set: &ScoredSet) -> Vec<[String; 6]> {
    let mut rows: Vec<[String; 6]> = set.verdicts.iter().map(verdict_row).collect();
    for s in &set.skipped {
        let at = s.at.map(|t| format!(" at {t}")).unwrap_or_default();
        let word = if set.require_all && s.kind == SkipKind::NotSupplied {
            "FAIL"
        } else {
            s.kind.word()
        };
        rows.push([
            word.into(),
            s.case.clone(),
            format!("{}{at}", s.label),
            "-".into(),
            "-".into(),
            format!("{} [{}]", s.reason, s.source),
        ]);
    }
    for (case, row, stated) in set.diagnostic_rows() {
        if row.note.starts_with("not applicable") {
            continue;
        }
        rows.push([
            if stated { "finding" } else { word(row.verdict) }.into(),
            case.to_string(),
            row.name.into(),
            row.measured,
            row.expected.into(),
            row.note,
        ]);
    }
    for s in set.stated.iter().filter(|s| !s.holds) {
        rows.push([
            "FAIL".into(),
            s.stated.case.clone(),
            s.stated.check.clone(),
            "passes".into(),
            "stated to fail".into(),
            format!(
                "stated as a finding, but it does not fail: {}",
                s.stated.finding
            ),
        ]);
    }
    for missing in &set.missing_cases {
        rows.push([
            if set.require_all { "FAIL" } else { "missing" }.into(),
            missing.clone(),
            "file".into(),
            "-".into(),
            format!("{missing}.csv"),
            "not supplied: the set has no file for this case of the scene".into(),
        ]);
    }
    rows
}

/// The terminal report.
pub fn terminal(scene: &Scene, outcome: &ScoreOutcome) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}: {}", scene.name, scene.description);
    let _ = writeln!(out, "  source: {}", scene.source);
    for set in &outcome.sets {
        let _ = writeln!(
            out,
            "\n  results {} ({} {}), {} case file(s):",
            set.label,
            set.code,
            set.version,
            set.cases.len()
        );
        for c in &set.cases {
            let _ = writeln!(out, "    {}", case_line(c));
            let scene_n = scene
                .cases
                .iter()
                .find(|s| s.name == c.case)
                .map(|s| s.model.bar().element_count());
            if let (Some(n), Some(e)) = (scene_n, c.elements)
                && n != e
            {
                let _ = writeln!(
                    out,
                    "      (the scene's case has {n} elements: bounds measured on its mesh may not hold on this one)"
                );
            }
        }
        render_rows(&mut out, &check_rows(set));
    }
    for study in &outcome.convergence {
        let levels: Vec<String> = study
            .result
            .levels
            .iter()
            .map(|l| l.elements.to_string())
            .collect();
        let _ = writeln!(
            out,
            "\n  convergence of {} (N = {}; band: {}):",
            study.case,
            levels.join(", "),
            study.note.as_deref().unwrap_or(study.result.study.name)
        );
        for v in study.result.verdicts() {
            let _ = writeln!(
                out,
                "    {:4}  {} fitted order {}, expected {}",
                word(v.pass),
                v.norm,
                v.fitted.map_or("-".into(), |p| format!("{p:.3}")),
                v.expected
            );
        }
    }
    let c = counts(outcome);
    let _ = writeln!(
        out,
        "\nscore: {}, {} set(s): {} expectation verdict(s), {} diagnostic(s), {} fitted order(s), {} stated finding(s), {} failed: {}; no verdict: {} not applicable, {} not supplied{}, {} not measurable from files",
        scene.name,
        outcome.sets.len(),
        c.expectations,
        c.diagnostics,
        c.orders,
        c.findings,
        c.failed,
        if c.failed > 0 {
            "FAIL"
        } else if outcome.sets.iter().any(ScoredSet::nothing_checked) {
            "FAIL (nothing could be checked on a set)"
        } else {
            "pass"
        },
        c.not_applicable,
        c.not_supplied,
        if outcome.sets.iter().any(|s| s.require_all) {
            " (failed: --require-all)"
        } else {
            ""
        },
        c.skipped,
    );
    out
}
