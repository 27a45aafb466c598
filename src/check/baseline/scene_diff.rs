//! Comparing a scene's fresh files with a baseline directory: each file with the baseline file
//! of the same name, files the baseline does not keep skipped, missing files failed.

use super::csv_diff::{ColumnChange, FileOutcome, compare_csv};
use super::kind::BaselineKind;
use super::tolerance::Tolerances;
use crate::io::bounded_read::{DATA_CAP, ReadError, read_text};
use std::path::Path;

/// The comparison of one file.
#[derive(Debug, Clone, PartialEq)]
pub struct FileComparison {
    /// File name inside the scene directory.
    pub file: String,
    /// Outcome.
    pub outcome: FileOutcome,
}

impl FileComparison {
    /// True when the file was not compared because a report baseline does not keep it.
    pub fn skipped(&self) -> bool {
        self.outcome == FileOutcome::NotKeptByReport
    }

    /// True when the file matches its baseline within tolerance (or was skipped).
    pub fn passed(&self) -> bool {
        match &self.outcome {
            FileOutcome::Compared { columns, .. } => columns.iter().all(ColumnChange::passed),
            FileOutcome::NotKeptByReport => true,
            _ => false,
        }
    }

    /// The column with the largest change: one beyond tolerance first, then the largest
    /// relative change, then the largest absolute change. `None` when nothing changed.
    pub fn largest_change(&self) -> Option<&ColumnChange> {
        let FileOutcome::Compared { columns, .. } = &self.outcome else {
            return None;
        };
        columns.iter().filter(|c| c.changed()).max_by(|x, y| {
            (x.beyond > 0)
                .cmp(&(y.beyond > 0))
                .then(x.max_rel.total_cmp(&y.max_rel))
                .then(x.max_abs.total_cmp(&y.max_abs))
        })
    }

    /// One line: the verdict's reason and the largest change.
    pub fn summary(&self) -> String {
        match &self.outcome {
            FileOutcome::Compared { rows, columns, .. } => {
                let what = match self.largest_change() {
                    None => "identical".to_string(),
                    Some(c) if c.not_numbers > 0 && c.max_abs == 0.0 => format!(
                        "largest change in {}: {} cell(s) not a number{}",
                        c.column,
                        c.not_numbers,
                        c.worst
                            .as_ref()
                            .map(|w| format!(
                                " (line {}: fresh {:?} vs baseline {:?})",
                                w.line, w.fresh, w.baseline
                            ))
                            .unwrap_or_default()
                    ),
                    Some(c) => format!(
                        "largest change in {}: |change| {:.3e}, relative {:.3e}",
                        c.column, c.max_abs, c.max_rel
                    ),
                };
                let failing: Vec<&str> = columns
                    .iter()
                    .filter(|c| !c.passed())
                    .map(|c| c.column.as_str())
                    .collect();
                if failing.is_empty() {
                    format!("{rows} rows, {} columns compared; {what}", columns.len())
                } else {
                    format!("column(s) {} beyond tolerance; {what}", failing.join(", "))
                }
            }
            FileOutcome::MissingInBaseline => "missing from the baseline".into(),
            FileOutcome::NotKeptByReport => {
                "not compared: a report baseline does not keep it".into()
            }
            FileOutcome::MissingInFresh => {
                "in the baseline but not written by the fresh run".into()
            }
            FileOutcome::HeaderChanged { fresh, baseline } => {
                let added: Vec<&str> = fresh
                    .iter()
                    .filter(|c| !baseline.contains(c))
                    .map(String::as_str)
                    .collect();
                let removed: Vec<&str> = baseline
                    .iter()
                    .filter(|c| !fresh.contains(c))
                    .map(String::as_str)
                    .collect();
                format!(
                    "header changed: baseline `{}`, fresh `{}` (added: {}; removed: {})",
                    baseline.join(","),
                    fresh.join(","),
                    if added.is_empty() {
                        "-".into()
                    } else {
                        added.join(", ")
                    },
                    if removed.is_empty() {
                        "-".into()
                    } else {
                        removed.join(", ")
                    },
                )
            }
            FileOutcome::RowCountChanged { fresh, baseline } => {
                format!("row count changed: baseline {baseline}, fresh {fresh}")
            }
            FileOutcome::Unreadable(why) => format!("unreadable: {why}"),
        }
    }

    /// Why the file fails, naming the file and every failing column; `None` when it passes.
    pub fn failure_message(&self) -> Option<String> {
        if self.passed() {
            return None;
        }
        let mut message = format!("{}: {}", self.file, self.summary());
        if let FileOutcome::Compared { columns, .. } = &self.outcome {
            for c in columns.iter().filter(|c| !c.passed()) {
                message.push_str("\n  ");
                message.push_str(&c.describe());
            }
        }
        Some(message)
    }
}

/// Compare the fresh files of a scene (name, CSV text) with `baseline_dir` (the scene's
/// directory of a previous run or report, `DIR/<scene>`): every fresh file in order, then every
/// `.csv` file the baseline has and the fresh run did not write. A missing `baseline_dir` makes
/// every file missing from the baseline, whatever its kind; a fresh file a report does not keep
/// ([`BaselineKind::keeps`]) is [`FileOutcome::NotKeptByReport`] and not read.
pub fn compare_scene(
    fresh: &[(String, String)],
    baseline_dir: &Path,
    kind: BaselineKind,
    tolerances: &Tolerances,
) -> Vec<FileComparison> {
    let mut comparisons: Vec<FileComparison> = fresh
        .iter()
        .map(|(file, text)| {
            let outcome = if kind.keeps(file) {
                // A FIFO, a device or a huge file in the baseline fails that file unread.
                match read_text(&baseline_dir.join(file), DATA_CAP) {
                    Ok(base) => compare_csv(text, &base, tolerances),
                    Err(ReadError::Missing { dangling: false }) => FileOutcome::MissingInBaseline,
                    Err(e) => FileOutcome::Unreadable(format!("baseline file: {}", e.located())),
                }
            } else {
                FileOutcome::NotKeptByReport
            };
            FileComparison {
                file: file.clone(),
                outcome,
            }
        })
        .collect();
    let mut extra: Vec<String> = std::fs::read_dir(baseline_dir)
        .into_iter()
        .flatten()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .filter_map(|e| e.file_name().to_str().map(str::to_string))
        .filter(|name| name.ends_with(".csv") && !fresh.iter().any(|(f, _)| f == name))
        .collect();
    extra.sort();
    comparisons.extend(extra.into_iter().map(|file| FileComparison {
        file,
        outcome: FileOutcome::MissingInFresh,
    }));
    comparisons
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A report keeps only its tables: other fresh files are skipped, its tables must match and
    /// must exist; a run's output keeps everything.
    #[test]
    fn a_report_baseline_compares_its_tables_and_skips_per_case_files() {
        let root =
            std::env::temp_dir().join(format!("courant-baseline-kind-{}", std::process::id()));
        let scene = root.join("s");
        std::fs::create_dir_all(&scene).unwrap();
        assert_eq!(BaselineKind::detect(&root), BaselineKind::RunOutput);
        // Scene folders copied out of a report (its tables only) are a report too.
        std::fs::write(scene.join("summary.csv"), "case,l1\na,1\n").unwrap();
        assert_eq!(BaselineKind::detect(&root), BaselineKind::Report);
        std::fs::write(scene.join("a.csv"), "t,stress\n0,1\n").unwrap();
        assert_eq!(BaselineKind::detect(&root), BaselineKind::RunOutput);
        std::fs::remove_file(scene.join("a.csv")).unwrap();
        std::fs::write(root.join("index.md"), "# report\n").unwrap();
        assert_eq!(BaselineKind::detect(&root), BaselineKind::Report);
        std::fs::write(scene.join("summary.csv"), "case,l1\na,1\n").unwrap();
        let fresh = [
            ("a.csv".to_string(), "t,stress\n0,1\n".to_string()),
            (
                "summary.csv".to_string(),
                "case,l1,wall_time_s\na,1,0.1\n".to_string(),
            ),
            ("norms.csv".to_string(), "case,l1\na,1\n".to_string()),
        ];
        let t = Tolerances::default();
        let outcomes = compare_scene(&fresh, &scene, BaselineKind::Report, &t);
        assert!(outcomes[0].skipped() && outcomes[0].passed());
        assert!(outcomes[1].passed() && !outcomes[1].skipped());
        assert_eq!(outcomes[2].outcome, FileOutcome::MissingInBaseline);
        let outcomes = compare_scene(&fresh, &scene, BaselineKind::RunOutput, &t);
        assert_eq!(outcomes[0].outcome, FileOutcome::MissingInBaseline);
        std::fs::remove_dir_all(&root).unwrap();
    }
}
