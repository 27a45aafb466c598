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

    /// A directory with an `index.md` is a report, anything else a run's output.
    pub fn detect(root: &Path) -> Self {
        if root.join("index.md").is_file() {
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
