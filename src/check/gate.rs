//! Running the checks: every scene run and compared (in parallel, in argument order), its
//! expectation verdicts, and its files against a baseline when one is given.

use super::baseline::csv_diff::FileOutcome;
use super::baseline::kind::BaselineKind;
use super::baseline::scene_diff::{FileComparison, compare_scene};
use super::baseline::tolerance::Tolerances;
use crate::compare::files::scene_files;
use crate::compare::verdict::Verdict;
use crate::io::clock::date;
use crate::io::parallel::in_order;
use crate::pipeline::studies::run_convergence;
use crate::pipeline::{EvaluateError, evaluate_scene};
use crate::scene::cases::Scene;
use crate::scene::studies::convergence::ConvergenceStudy;
use rayon::prelude::*;
use std::path::{Path, PathBuf};

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
    /// Wall time of each case's run, in seconds, by case name.
    pub case_times: Vec<(String, f64)>,
}

impl SceneCheck {
    /// The wall time of the run a verdict judges (0 when it judges no single run).
    pub fn time_of(&self, case: &str) -> f64 {
        self.case_times
            .iter()
            .find(|(c, _)| c == case)
            .map_or(0.0, |(_, t)| *t)
    }

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
) -> Result<SceneCheck, EvaluateError> {
    let started = date();
    let clock = std::time::Instant::now();
    let outcome = evaluate_scene(scene)?;
    let files = scene_files(&outcome);
    let baseline = baseline
        .map(|(root, kind)| compare_scene(&files, &root.join(&scene.name), kind, tolerances));
    let case_times = outcome
        .results
        .iter()
        .map(|r| (r.run.case.clone(), r.run.wall_time.as_secs_f64()))
        .chain(
            outcome
                .contact
                .iter()
                .map(|r| (r.case.clone(), r.wall_time.as_secs_f64())),
        )
        .chain(
            outcome
                .spectra
                .iter()
                .map(|r| (r.case.clone(), r.wall_time.as_secs_f64())),
        )
        .collect();
    Ok(SceneCheck {
        case_times,
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

/// The checks of a convergence study: its order verdicts, as a scene of its own named
/// `convergence:<study>` (no files, no baseline).
pub fn check_study(study: &ConvergenceStudy) -> Result<SceneCheck, String> {
    let started = date();
    let clock = std::time::Instant::now();
    let result = run_convergence(study)?;
    Ok(SceneCheck {
        name: format!("convergence:{}", study.name),
        description: study.title.to_string(),
        source: study.expected.to_string(),
        verdicts: result.order_verdicts(),
        files: Vec::new(),
        baseline: None,
        started,
        wall_time: clock.elapsed().as_secs_f64(),
        case_times: Vec::new(),
    })
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
    /// Verdicts that pass as stated findings (disagreements with stability theory or with a
    /// claim of the seed).
    pub findings: usize,
    /// Checks skipped (files a report baseline does not keep).
    pub skipped: usize,
}

impl CheckReport {
    /// Check every scene and convergence study, in parallel (rayon; the results keep the
    /// argument order and do not depend on the thread count). The baseline's kind is detected
    /// ([`BaselineKind::detect`]). When scenes cannot run, the error of the first one in
    /// argument order is returned.
    pub fn run(
        scenes: &[Scene],
        studies: &[ConvergenceStudy],
        baseline: Option<&Path>,
        tolerances: Tolerances,
    ) -> Result<CheckReport, (String, String)> {
        let clock = std::time::Instant::now();
        let baseline = baseline.map(|root| (root.to_path_buf(), BaselineKind::detect(root)));
        let base = baseline
            .as_ref()
            .map(|(root, kind)| (root.as_path(), *kind));
        // Progress on stderr: indicatif draws only on a terminal and is silent otherwise (CI,
        // a pipe, a file), so the output a program reads never changes.
        let progress = indicatif::ProgressBar::new((scenes.len() + studies.len()) as u64);
        progress.set_style(
            indicatif::ProgressStyle::with_template("checking {bar:40} {pos}/{len} {msg}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        let done = |name: &str| {
            progress.set_message(name.to_string());
            progress.inc(1);
        };
        let checked = in_order(
            scenes
                .par_iter()
                .map(|s| {
                    let checked = check_scene(s, base, &tolerances)
                        .map_err(|e| (s.name.clone(), e.to_string()));
                    done(&s.name);
                    checked
                })
                .collect(),
        );
        let studied = checked.and_then(|mut scenes| {
            scenes.extend(in_order(
                studies
                    .par_iter()
                    .map(|s| {
                        let checked =
                            check_study(s).map_err(|e| (format!("convergence:{}", s.name), e));
                        done(s.name);
                        checked
                    })
                    .collect(),
            )?);
            Ok(scenes)
        });
        progress.finish_and_clear();
        let scenes = studied?;
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
            failed: all.clone().filter(|v| !v.pass).count(),
            findings: all.filter(|v| v.finding).count(),
            skipped: 0,
        }
    }

    /// Baseline file comparisons: (total, failed).
    pub fn baseline_counts(&self) -> Counts {
        let all = self.scenes.iter().flat_map(|s| s.baseline.iter().flatten());
        Counts {
            total: all.clone().count(),
            failed: all.clone().filter(|f| !f.passed()).count(),
            findings: 0,
            skipped: all.filter(|f| f.skipped()).count(),
        }
    }
}
