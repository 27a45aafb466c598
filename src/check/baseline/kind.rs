//! What a baseline directory holds: a run's output (every file) or a report (each scene's
//! deterministic tables only).

use crate::compare::files::REPORT_TABLES;
use std::path::Path;

/// What a baseline directory holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BaselineKind {
    /// A `courant run --out DIR` (or `courant check --out DIR`) directory: every result file of
    /// every scene. A fresh file without a baseline file fails.
    RunOutput,
    /// A `courant report --out DIR` directory (it has an `index.md`): each scene's deterministic
    /// tables only. A fresh file the report does not keep (a profile, history or energy log) is
    /// listed as not compared; every table the report keeps must still be written and match.
    Report,
}

impl BaselineKind {
    /// True when a baseline of this kind keeps a scene file of this name: a run's output keeps
    /// every file, a report its [`REPORT_TABLES`].
    pub fn keeps(self, file: &str) -> bool {
        match self {
            BaselineKind::RunOutput => true,
            BaselineKind::Report => REPORT_TABLES.contains(&file),
        }
    }

    /// A directory with an `index.md` is a report; so is one whose scene folders hold only what
    /// a report keeps (its tables and SVG figures: scene folders copied out of a report);
    /// anything else is a run's output.
    pub fn detect(root: &Path) -> Self {
        if root.join("index.md").is_file() || holds_only_report_tables(root) {
            BaselineKind::Report
        } else {
            BaselineKind::RunOutput
        }
    }

    /// Short name for reports.
    pub fn label(self) -> &'static str {
        match self {
            BaselineKind::RunOutput => "run output",
            BaselineKind::Report => "report",
        }
    }
}

/// True when `root` has scene folders and every file in them is a report table or an SVG figure.
fn holds_only_report_tables(root: &Path) -> bool {
    let Ok(entries) = std::fs::read_dir(root) else {
        return false;
    };
    let mut files_seen = 0;
    for dir in entries.flatten().filter(|e| e.path().is_dir()) {
        let Ok(files) = std::fs::read_dir(dir.path()) else {
            return false;
        };
        for f in files.flatten() {
            let name = f.file_name().to_string_lossy().to_string();
            let kept = REPORT_TABLES.contains(&name.as_str()) || name.ends_with(".svg");
            if !kept || f.path().is_dir() {
                return false;
            }
            files_seen += 1;
        }
    }
    files_seen > 0
}
