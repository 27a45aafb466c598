//! `courant check`: run scenes, gate on their expectations and, optionally, on a baseline.
//!
//! Every expectation verdict of every scene is a check; with a baseline directory every result
//! file of every scene is one more (compared by [`crate::baseline`]). The report renders as a
//! terminal table ([`CheckReport::render`]) and as JUnit XML ([`CheckReport::junit`]), one
//! test suite per scene, one test case per check.

use crate::baseline::{BaselineKind, FileComparison, FileOutcome, Tolerances, compare_scene};
use crate::expect::{Measured, Verdict};
use crate::junit::{Failure, TestCase, TestSuite};
use crate::scene::{Bound, Scene, SceneError};
use courant_solver::RunError;
use rayon::prelude::*;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Resolve every argument like `courant run` does (built-in names or `.toml` paths; every
/// built-in scene when there is none). Every bad argument is reported, not just the first.
pub fn resolve_scenes(args: &[String]) -> Result<Vec<Scene>, Vec<SceneError>> {
    let names: Vec<String> = if args.is_empty() {
        crate::builtin::BUILTIN_SCENES
            .iter()
            .map(|(n, _)| n.to_string())
            .collect()
    } else {
        args.to_vec()
    };
    let (mut scenes, mut errors) = (Vec::new(), Vec::new());
    for name in &names {
        match crate::builtin::resolve(name) {
            Ok(scene) => scenes.push(scene),
            Err(e) => errors.push(e),
        }
    }
    if errors.is_empty() {
        Ok(scenes)
    } else {
        Err(errors)
    }
}

/// The checks of one scene.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneCheck {
    /// Scene name (its output directory).
    pub name: String,
    /// One-line description.
    pub description: String,
    /// Source of truth of the scene.
    pub source: String,
    /// Expectation verdicts.
    pub verdicts: Vec<Verdict>,
    /// The scene's result files (name, CSV text), as `courant run` writes them.
    pub files: Vec<(String, String)>,
    /// The baseline comparison of every file, when a baseline was given.
    pub baseline: Option<Vec<FileComparison>>,
    /// When the scene started running, ISO 8601 UTC.
    pub started: String,
    /// Wall time of running and comparing the scene, in seconds.
    pub wall_time: f64,
}

impl SceneCheck {
    /// True when every expectation holds and every file matches its baseline.
    pub fn passed(&self) -> bool {
        self.verdicts.iter().all(|v| v.pass)
            && self
                .baseline
                .as_ref()
                .is_none_or(|files| files.iter().all(FileComparison::passed))
    }
}

/// Run a scene, evaluate its expectations and compare its files with `baseline` (the baseline
/// root `DIR` and what it holds; the scene's files are under `DIR/<scene>/`).
pub fn check_scene(
    scene: &Scene,
    baseline: Option<(&Path, BaselineKind)>,
    tolerances: &Tolerances,
) -> Result<SceneCheck, RunError> {
    let started = crate::clock::date();
    let clock = std::time::Instant::now();
    let outcome = crate::run_scene(scene)?;
    let files = crate::results::scene_files(&outcome);
    let baseline = baseline
        .map(|(root, kind)| compare_scene(&files, &root.join(&scene.name), kind, tolerances));
    Ok(SceneCheck {
        started,
        wall_time: clock.elapsed().as_secs_f64(),
        name: scene.name.clone(),
        description: scene.description.clone(),
        source: scene.source.clone(),
        verdicts: outcome.verdicts,
        files,
        baseline,
    })
}

/// The test-case name of a verdict: `<case> <metric>`, plus ` at <t>` when it names a time.
pub fn testcase_name(v: &Verdict) -> String {
    let at = v.at.map(|t| format!(" at {t}")).unwrap_or_default();
    format!("{} {}{at}", v.case, v.metric.name())
}

/// The measured value of a verdict, for reports.
pub fn format_measured(measured: &Measured) -> String {
    match measured {
        Measured::Value(x) => format!("{x:.4e}"),
        Measured::Flag(b) => b.to_string(),
        Measured::Missing(why) => format!("missing ({why})"),
    }
}

/// The bound of a verdict, for reports: `<= max`, `>= min`, `in [min, max]`, `== flag`.
pub fn format_bound(bound: &Bound) -> String {
    let num = |x: f64| crate::table::Precision::RoundTrip.format(x);
    match *bound {
        Bound::Range {
            min: Some(lo),
            max: Some(hi),
        } => format!("in [{}, {}]", num(lo), num(hi)),
        Bound::Range {
            min: Some(lo),
            max: None,
        } => format!(">= {}", num(lo)),
        Bound::Range {
            min: None,
            max: Some(hi),
        } => format!("<= {}", num(hi)),
        Bound::Range {
            min: None,
            max: None,
        } => "unbounded".into(),
        Bound::Equals(b) => format!("== {b}"),
    }
}

fn verdict_word(pass: bool) -> &'static str {
    if pass { "pass" } else { "FAIL" }
}

/// Everything `courant check` found.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckReport {
    /// Per scene, in argument order.
    pub scenes: Vec<SceneCheck>,
    /// The baseline root and what it holds, if any.
    pub baseline: Option<(PathBuf, BaselineKind)>,
    /// The tolerance rules of the baseline comparison.
    pub tolerances: Tolerances,
    /// Wall time of the whole check (scenes run in parallel), in seconds.
    pub wall_time: f64,
}

/// Counts of checks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Counts {
    /// Checks made (including skipped ones).
    pub total: usize,
    /// Checks failed.
    pub failed: usize,
    /// Checks skipped (files a report baseline does not keep).
    pub skipped: usize,
}

impl CheckReport {
    /// Check every scene, in parallel (rayon; the results keep the argument order and do not
    /// depend on the thread count). The baseline's kind is detected ([`BaselineKind::detect`]).
    /// When scenes cannot run, the error of the first one in argument order is returned.
    pub fn run(
        scenes: &[Scene],
        baseline: Option<&Path>,
        tolerances: Tolerances,
    ) -> Result<CheckReport, (String, RunError)> {
        let clock = std::time::Instant::now();
        let baseline = baseline.map(|root| (root.to_path_buf(), BaselineKind::detect(root)));
        let base = baseline
            .as_ref()
            .map(|(root, kind)| (root.as_path(), *kind));
        let scenes = crate::run::in_order(
            scenes
                .par_iter()
                .map(|s| check_scene(s, base, &tolerances).map_err(|e| (s.name.clone(), e)))
                .collect(),
        )?;
        Ok(CheckReport {
            scenes,
            baseline,
            tolerances,
            wall_time: clock.elapsed().as_secs_f64(),
        })
    }

    /// The `--column` overrides whose column appears in no compared file (a misspelt name
    /// loosens nothing and must not pass silently).
    pub fn unmatched_overrides(&self) -> Vec<&str> {
        let seen = |name: &str| {
            self.scenes
                .iter()
                .flat_map(|s| s.baseline.iter().flatten())
                .any(|f| match &f.outcome {
                    FileOutcome::Compared {
                        columns, ignored, ..
                    } => {
                        columns.iter().any(|c| c.column == name)
                            || ignored.iter().any(|c| c == name)
                    }
                    _ => false,
                })
        };
        self.tolerances
            .overrides
            .iter()
            .map(|(c, _)| c.as_str())
            .filter(|c| !seen(c))
            .collect()
    }

    /// True when every check holds.
    pub fn passed(&self) -> bool {
        self.scenes.iter().all(SceneCheck::passed)
    }

    /// Expectation verdicts: (total, failed).
    pub fn expectation_counts(&self) -> Counts {
        let all = self.scenes.iter().flat_map(|s| &s.verdicts);
        Counts {
            total: all.clone().count(),
            failed: all.filter(|v| !v.pass).count(),
            skipped: 0,
        }
    }

    /// Baseline file comparisons: (total, failed).
    pub fn baseline_counts(&self) -> Counts {
        let all = self.scenes.iter().flat_map(|s| s.baseline.iter().flatten());
        Counts {
            total: all.clone().count(),
            failed: all.clone().filter(|f| !f.passed()).count(),
            skipped: all.filter(|f| f.skipped()).count(),
        }
    }

    /// The terminal report: per scene a table of its expectations (verdict, case, metric,
    /// measured value, bound, source), then its baseline files with the largest change of each
    /// changed column; a summary line at the end.
    pub fn render(&self) -> String {
        let mut out = String::new();
        for scene in &self.scenes {
            let _ = writeln!(out, "{}: {}", scene.name, scene.description);
            let _ = writeln!(out, "  source: {}", scene.source);
            render_verdicts(&mut out, &scene.verdicts);
            if let (Some((root, kind)), Some(files)) = (&self.baseline, &scene.baseline) {
                let _ = writeln!(
                    out,
                    "  baseline {} ({}):",
                    root.join(&scene.name).display(),
                    kind.label()
                );
                render_baseline(&mut out, files);
            }
            out.push('\n');
        }
        if self.baseline.is_some() {
            let _ = writeln!(out, "baseline tolerances: {}", self.tolerances.describe());
        }
        let e = self.expectation_counts();
        let _ = write!(
            out,
            "check: {} scene(s), {} expectation(s), {} failed",
            self.scenes.len(),
            e.total,
            e.failed
        );
        if self.baseline.is_some() {
            let b = self.baseline_counts();
            let _ = write!(
                out,
                "; baseline: {} file(s), {} failed, {} not kept by the baseline",
                b.total, b.failed, b.skipped
            );
        }
        let _ = writeln!(out, ": {}", verdict_word(self.passed()));
        out
    }

    /// The JUnit test suites: one per scene (properties: description, source, baseline
    /// directory), one test case per expectation verdict (classname = scene, name =
    /// [`testcase_name`]) and per baseline file (name = `baseline <file>`).
    pub fn junit_suites(&self) -> Vec<TestSuite> {
        self.scenes
            .iter()
            .map(|scene| {
                let mut properties = vec![
                    ("description".to_string(), scene.description.clone()),
                    ("source".to_string(), scene.source.clone()),
                ];
                if let Some((root, kind)) = &self.baseline {
                    properties.push((
                        "baseline".into(),
                        root.join(&scene.name).display().to_string(),
                    ));
                    properties.push(("baseline_kind".into(), kind.label().into()));
                    properties.push(("tolerances".into(), self.tolerances.describe()));
                }
                let mut cases: Vec<TestCase> = scene
                    .verdicts
                    .iter()
                    .map(|v| {
                        let name = testcase_name(v);
                        let what = format!(
                            "measured {}, bound {}; source: {}",
                            format_measured(&v.measured),
                            format_bound(&v.bound),
                            v.source
                        );
                        TestCase {
                            classname: scene.name.clone(),
                            failure: (!v.pass).then(|| Failure {
                                message: format!("{name}: {what}"),
                                kind: "expectation".into(),
                                details: v.describe(),
                            }),
                            name,
                            output: Some(what),
                            skipped: None,
                        }
                    })
                    .collect();
                for file in scene.baseline.iter().flatten() {
                    cases.push(TestCase {
                        classname: scene.name.clone(),
                        name: format!("baseline {}", file.file),
                        failure: file.failure_message().map(|m| Failure {
                            message: m.lines().next().unwrap_or_default().to_string(),
                            kind: "baseline".into(),
                            details: m,
                        }),
                        output: Some(file_details(file)),
                        skipped: file.skipped().then(|| file.summary()),
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
            .collect()
    }

    /// The JUnit XML document.
    pub fn junit(&self) -> String {
        crate::junit::render("courant check", &self.junit_suites(), self.wall_time)
    }
}

fn render_verdicts(out: &mut String, verdicts: &[Verdict]) {
    if verdicts.is_empty() {
        out.push_str("  (no expectations)\n");
        return;
    }
    let rows: Vec<[String; 6]> = verdicts
        .iter()
        .map(|v| {
            let at = v.at.map(|t| format!(" at {t}")).unwrap_or_default();
            [
                verdict_word(v.pass).to_string(),
                v.case.clone(),
                format!("{}{at}", v.metric.name()),
                format_measured(&v.measured),
                format_bound(&v.bound),
                v.source.clone(),
            ]
        })
        .collect();
    let header = ["verdict", "case", "metric", "measured", "bound", "source"].map(String::from);
    let mut widths = [0; 6];
    for row in std::iter::once(&header).chain(&rows) {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    for row in std::iter::once(&header).chain(&rows) {
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
