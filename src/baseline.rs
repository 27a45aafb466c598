//! Comparing fresh result CSVs with a baseline, column by column, the way MOOSE's CSVDiff does.
//!
//! A baseline is either a previous run's output directory, laid out as `courant run --out DIR`
//! writes it (`DIR/<scene>/<file>.csv`), or a previous *report* (`courant report --out DIR`:
//! `DIR/index.md` beside `DIR/<scene>/`), which keeps only each scene's deterministic tables
//! ([`REPORT_TABLES`]: the summary without wall times, norms, expectations, dispersion and contact
//! stability tables) and not the per-case profiles, histories, energy logs and spectra
//! ([`BaselineKind`]).
//! Every fresh file of a scene is compared with the baseline file of the same name, cell by cell,
//! under the rule [`Tolerances::rule_for`] picks for its column; columns are matched by name (in
//! any order), and ignored columns (wall times) may be present on one side only. A file missing
//! on either side (except a fresh file a report does not keep, which is reported as not
//! compared), a changed header, a changed row count or a cell beyond its tolerance fails the
//! file. The report keeps the largest change of every column (absolute and relative) so that a
//! passing comparison still says how close it came.

use std::path::Path;
use thiserror::Error;

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

/// The names of the scene tables a report keeps: `courant report` writes each scene's
/// deterministic tables under these names (and no others), and a report baseline compares them.
pub mod report_tables {
    /// Cases (wall times dropped), or the spectra of a spectrum scene, or the contact runs.
    pub const SUMMARY: &str = "summary.csv";
    /// Norms per case and profile time.
    pub const NORMS: &str = "norms.csv";
    /// Phase speeds of a dispersion scene.
    pub const DISPERSION: &str = "dispersion.csv";
    /// A contact stability sweep.
    pub const STABILITY: &str = "stability.csv";
    /// The expectation verdicts.
    pub const EXPECTATIONS: &str = "expectations.csv";
}

/// Every name of [`report_tables`]; a fresh file of another name is not kept by a report
/// baseline.
pub const REPORT_TABLES: &[&str] = &[
    report_tables::SUMMARY,
    report_tables::NORMS,
    report_tables::DISPERSION,
    report_tables::STABILITY,
    report_tables::EXPECTATIONS,
];

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

/// How the cells of one column are compared. `a` is the fresh value, `b` the baseline's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ColumnRule {
    /// Numbers pass when `|a - b| <= max(abs, rel * |b|)`: relative, with an absolute floor for
    /// values near zero.
    Relative {
        /// Relative tolerance.
        rel: f64,
        /// Absolute floor.
        abs: f64,
    },
    /// Numbers pass when `|a - b| <= max(abs, rel * peak)`, `peak = max |b|` over the baseline
    /// column: for wave fronts, where a cell next to the front is small but its error is judged
    /// against the jump, not against itself.
    PeakRelative {
        /// Relative tolerance (relative to the column's peak).
        rel: f64,
        /// Absolute floor.
        abs: f64,
    },
    /// Numbers must be equal (integer columns).
    Exact,
    /// Not compared (wall times).
    Ignored,
    /// Reported for a column that turned out to hold no numbers (case names, statuses): every
    /// cell must be the same text. [`Tolerances::rule_for`] never returns it; the comparison
    /// finds it.
    Text,
}

impl ColumnRule {
    /// Short name for reports.
    pub fn label(self) -> String {
        match self {
            ColumnRule::Relative { rel, abs } => format!("relative (rel {rel:e}, abs {abs:e})"),
            ColumnRule::PeakRelative { rel, abs } => {
                format!("peak-relative (rel {rel:e} of the peak, abs {abs:e})")
            }
            ColumnRule::Exact => "exact".into(),
            ColumnRule::Ignored => "ignored".into(),
            ColumnRule::Text => "text, exact".into(),
        }
    }
}

/// A tolerance given on the command line that breaks its rule: the flag, the value as given and
/// the rule, e.g. `--rel "-1": must be a finite number >= 0`.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{flag} {value:?}: {rule}")]
pub struct ToleranceError {
    /// The flag (`--rel`, `--column`, ...).
    pub flag: &'static str,
    /// The value as given.
    pub value: String,
    /// The rule it breaks.
    pub rule: &'static str,
}

/// A tolerance value: finite and not negative.
pub fn tolerance_value(flag: &'static str, value: f64) -> Result<f64, ToleranceError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(ToleranceError {
            flag,
            value: value.to_string(),
            rule: "must be a finite number >= 0",
        })
    }
}

impl ColumnRule {
    /// The grammar of a per-column rule on the command line.
    pub const GRAMMAR: &'static str = "must be COLUMN=RULE with RULE one of ignore, exact, rel:REL[:ABS], peak:REL[:ABS] (REL, ABS finite numbers >= 0)";

    /// Parse `COLUMN=RULE` (`courant check --column`): `ignore`, `exact`, `rel:REL[:ABS]`
    /// (`|a - b| <= max(ABS, REL |b|)`, `ABS` defaulting to `default_abs`) or `peak:REL[:ABS]`
    /// (`|a - b| <= max(ABS, REL peak)`, `ABS` defaulting to `default_peak_abs`).
    pub fn parse_override(
        spec: &str,
        default_abs: f64,
        default_peak_abs: f64,
    ) -> Result<(String, ColumnRule), ToleranceError> {
        let bad = || ToleranceError {
            flag: "--column",
            value: spec.to_string(),
            rule: Self::GRAMMAR,
        };
        let (column, rule) = spec.split_once('=').ok_or_else(bad)?;
        let column = column.trim();
        if column.is_empty() {
            return Err(bad());
        }
        let mut parts = rule.trim().split(':');
        let kind = parts.next().unwrap_or_default();
        let numbers = parts
            .map(|x| {
                x.trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite() && *v >= 0.0)
                    .ok_or_else(bad)
            })
            .collect::<Result<Vec<f64>, _>>()?;
        let rule = match (kind, numbers.as_slice()) {
            ("ignore", []) => ColumnRule::Ignored,
            ("exact", []) => ColumnRule::Exact,
            ("rel", [rel]) => ColumnRule::Relative {
                rel: *rel,
                abs: default_abs,
            },
            ("rel", [rel, abs]) => ColumnRule::Relative {
                rel: *rel,
                abs: *abs,
            },
            ("peak", [rel]) => ColumnRule::PeakRelative {
                rel: *rel,
                abs: default_peak_abs,
            },
            ("peak", [rel, abs]) => ColumnRule::PeakRelative {
                rel: *rel,
                abs: *abs,
            },
            _ => return Err(bad()),
        };
        Ok((column.to_string(), rule))
    }
}

/// The tolerance rules of a baseline comparison, in one place.
///
/// For the column named `c` of a file, the first rule that applies wins:
///
/// 0. the rule given for `c` in [`overrides`](Self::overrides) (`courant check --column
///    c=RULE`, see [`ColumnRule::parse_override`]);
/// 1. **ignored** when `c` is in [`ignored_columns`](Self::ignored_columns) (`wall_time_s`) or
///    ends in one of [`ignored_suffixes`](Self::ignored_suffixes) (`_time_s`: times in seconds;
///    `beta_s` and other `_s` names are compared);
/// 2. **exact** when `c` is in [`exact_columns`](Self::exact_columns) (the integer columns
///    `element, node, step, steps, N, mode, active`);
/// 3. **peak-relative** when the file is a stress profile (`<case>.csv`: its header has every
///    one of [`peak_columns`](Self::peak_columns), `stress, reference, error`) and `c` is one of
///    them: `|a - b| <= max(peak_abs, peak_rel * peak)` with `peak = max |b|` over the baseline
///    column (defaults `peak_rel = 1e-9`, `peak_abs = 1e-12`);
/// 4. **relative** otherwise: `|a - b| <= max(abs, rel * |b|)` (defaults `rel = 1e-9`,
///    `abs = 1e-12`).
///
/// Whatever the rule, a cell that is not a number on both sides (text such as a case name or a
/// status, or an empty cell) must be the same text (a column of such cells is reported as
/// [`ColumnRule::Text`]); two non-finite numbers must be the same
/// (`NaN` equals `NaN`, `inf` equals `inf`).
#[derive(Debug, Clone, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance of ordinary numeric columns.
    pub rel: f64,
    /// Absolute floor of ordinary numeric columns.
    pub abs: f64,
    /// Relative tolerance of peak-relative columns (relative to the column's peak |value|).
    pub peak_rel: f64,
    /// Absolute floor of peak-relative columns.
    pub peak_abs: f64,
    /// Columns compared relative to their peak; a file whose header has all of them is a stress
    /// profile.
    pub peak_columns: Vec<String>,
    /// Integer-valued columns, compared exactly.
    pub exact_columns: Vec<String>,
    /// Columns never compared.
    pub ignored_columns: Vec<String>,
    /// Columns whose name ends in one of these are never compared.
    pub ignored_suffixes: Vec<String>,
    /// Per-column rules that take precedence over everything else, by column name.
    pub overrides: Vec<(String, ColumnRule)>,
}

impl Default for Tolerances {
    fn default() -> Self {
        let strings = |names: &[&str]| names.iter().map(|s| s.to_string()).collect();
        Self {
            rel: 1e-9,
            abs: 1e-12,
            peak_rel: 1e-9,
            peak_abs: 1e-12,
            peak_columns: strings(&["stress", "reference", "error"]),
            exact_columns: strings(&["element", "node", "step", "steps", "N", "mode", "active"]),
            ignored_columns: strings(&["wall_time_s"]),
            ignored_suffixes: strings(&["_time_s"]),
            overrides: Vec::new(),
        }
    }
}

impl Tolerances {
    /// True when a file with this header is a stress profile (has every peak column).
    pub fn is_profile(&self, header: &[String]) -> bool {
        !self.peak_columns.is_empty() && self.peak_columns.iter().all(|c| header.contains(c))
    }

    /// The rule for `column` of a file (`profile`: the file is a stress profile).
    pub fn rule_for(&self, profile: bool, column: &str) -> ColumnRule {
        if let Some((_, rule)) = self.overrides.iter().rev().find(|(c, _)| c == column) {
            *rule
        } else if self.ignored_columns.iter().any(|c| c == column)
            || self.ignored_suffixes.iter().any(|s| column.ends_with(s))
        {
            ColumnRule::Ignored
        } else if self.exact_columns.iter().any(|c| c == column) {
            ColumnRule::Exact
        } else if profile && self.peak_columns.iter().any(|c| c == column) {
            ColumnRule::PeakRelative {
                rel: self.peak_rel,
                abs: self.peak_abs,
            }
        } else {
            ColumnRule::Relative {
                rel: self.rel,
                abs: self.abs,
            }
        }
    }

    /// One line describing the rules, for reports.
    pub fn describe(&self) -> String {
        let overrides: String = self
            .overrides
            .iter()
            .map(|(c, r)| format!("; {c}: {}", r.label()))
            .collect();
        format!(
            "|a - b| <= max(abs, rel * scale): scale = |b| (rel {:e}, abs {:e}); for {} of stress profiles scale = the column's peak |b| (rel {:e}, abs {:e}); exact: {}; ignored: {} and *{}{overrides}",
            self.rel,
            self.abs,
            self.peak_columns.join("/"),
            self.peak_rel,
            self.peak_abs,
            self.exact_columns.join(", "),
            self.ignored_columns.join(", "),
            self.ignored_suffixes.join(", *"),
        )
    }
}

/// One cell that changed.
#[derive(Debug, Clone, PartialEq)]
pub struct CellChange {
    /// Line of the CSV file (the header is line 1).
    pub line: usize,
    /// Fresh text.
    pub fresh: String,
    /// Baseline text.
    pub baseline: String,
}

/// What changed in one compared column.
#[derive(Debug, Clone, PartialEq)]
pub struct ColumnChange {
    /// Column name.
    pub column: String,
    /// The rule it was compared under.
    pub rule: ColumnRule,
    /// The peak |baseline value| of a peak-relative column.
    pub peak: Option<f64>,
    /// Largest `|a - b|` over the numeric cells.
    pub max_abs: f64,
    /// Largest `|a - b| / scale` (`scale = |b|`, or the peak) over the cells with a nonzero
    /// scale: a cell whose baseline is exactly 0 (e.g. a report's value stored as 0 below its
    /// 1e-12 floor) has no relative change and is judged by the absolute floor alone.
    pub max_rel: f64,
    /// Cells beyond tolerance (including changed text).
    pub beyond: usize,
    /// The worst cell beyond tolerance (largest `|a - b|` over what the rule allows; changed
    /// text counts as worst, the first one is kept).
    pub worst: Option<CellChange>,
}

impl ColumnChange {
    /// True when no cell is beyond tolerance.
    pub fn passed(&self) -> bool {
        self.beyond == 0
    }

    /// True when some cell differs at all.
    pub fn changed(&self) -> bool {
        self.max_abs > 0.0 || self.beyond > 0
    }

    /// One line for reports.
    pub fn describe(&self) -> String {
        let peak = self
            .peak
            .map(|p| format!(", peak {p:.4e}"))
            .unwrap_or_default();
        let mut line = if self.rule == ColumnRule::Text {
            format!("{}: [{}]", self.column, self.rule.label())
        } else {
            format!(
                "{}: max |change| {:.3e}, max relative {:.3e} [{}{peak}]",
                self.column,
                self.max_abs,
                self.max_rel,
                self.rule.label()
            )
        };
        if let Some(w) = &self.worst {
            line.push_str(&format!(
                "; {} cell(s) beyond tolerance, worst at line {}: fresh {} vs baseline {}",
                self.beyond, w.line, w.fresh, w.baseline
            ));
        }
        line
    }
}

/// How a file compared.
#[derive(Debug, Clone, PartialEq)]
pub enum FileOutcome {
    /// Both files read with the same header and row count; every non-ignored column compared.
    Compared {
        /// Data rows.
        rows: usize,
        /// Compared columns, in header order.
        columns: Vec<ColumnChange>,
        /// Columns the rules ignore.
        ignored: Vec<String>,
    },
    /// The fresh run wrote the file but the baseline has none.
    MissingInBaseline,
    /// The baseline has the file but the fresh run did not write it.
    MissingInFresh,
    /// The baseline is a report, which does not keep this file (a per-case profile, history or
    /// energy log): not compared, and not a failure.
    NotKeptByReport,
    /// The headers differ.
    HeaderChanged {
        /// Fresh header.
        fresh: Vec<String>,
        /// Baseline header.
        baseline: Vec<String>,
    },
    /// The row counts differ.
    RowCountChanged {
        /// Fresh data rows.
        fresh: usize,
        /// Baseline data rows.
        baseline: usize,
    },
    /// A file could not be read or is not a well-formed CSV table.
    Unreadable(String),
}

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

/// A parsed CSV table: header and data rows.
type Csv = (Vec<String>, Vec<Vec<String>>);

fn parse_csv(text: &str) -> Result<Csv, String> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .from_reader(text.as_bytes());
    let header = reader
        .headers()
        .map_err(|e| e.to_string())?
        .iter()
        .map(str::to_string)
        .collect();
    let rows = reader
        .records()
        .map(|r| {
            r.map(|r| r.iter().map(str::to_string).collect())
                .map_err(|e| e.to_string())
        })
        .collect::<Result<_, _>>()?;
    Ok((header, rows))
}

/// Compare a fresh CSV text with its baseline text under `tolerances`.
pub fn compare_csv(fresh: &str, baseline: &str, tolerances: &Tolerances) -> FileOutcome {
    let (fresh_header, fresh_rows) = match parse_csv(fresh) {
        Ok(t) => t,
        Err(e) => return FileOutcome::Unreadable(format!("fresh file: {e}")),
    };
    let (base_header, base_rows) = match parse_csv(baseline) {
        Ok(t) => t,
        Err(e) => return FileOutcome::Unreadable(format!("baseline file: {e}")),
    };
    // Columns are matched by name, in any order; ignored columns (wall times) may be on one side
    // only.
    let fresh_profile = tolerances.is_profile(&fresh_header);
    let profile = tolerances.is_profile(&base_header);
    let compared = |header: &[String], profile: bool| -> Vec<String> {
        let mut names: Vec<String> = header
            .iter()
            .filter(|c| tolerances.rule_for(profile, c) != ColumnRule::Ignored)
            .cloned()
            .collect();
        names.sort();
        names
    };
    if compared(&fresh_header, fresh_profile) != compared(&base_header, profile) {
        return FileOutcome::HeaderChanged {
            fresh: fresh_header,
            baseline: base_header,
        };
    }
    if fresh_rows.len() != base_rows.len() {
        return FileOutcome::RowCountChanged {
            fresh: fresh_rows.len(),
            baseline: base_rows.len(),
        };
    }
    let mut columns = Vec::new();
    let mut ignored: Vec<String> = Vec::new();
    for (j, name) in base_header.iter().enumerate() {
        let rule = tolerances.rule_for(profile, name);
        if rule == ColumnRule::Ignored {
            ignored.push(name.clone());
            continue;
        }
        // Present: the compared names are equal on both sides.
        let Some(i) = fresh_header.iter().position(|c| c == name) else {
            continue;
        };
        let cells = fresh_rows
            .iter()
            .zip(&base_rows)
            .map(|(f, b)| (&f[i], &b[j]));
        columns.push(compare_column(name, rule, cells));
    }
    for name in &fresh_header {
        if !ignored.contains(name) && !base_header.contains(name) {
            ignored.push(name.clone());
        }
    }
    FileOutcome::Compared {
        rows: base_rows.len(),
        columns,
        ignored,
    }
}

fn number(cell: &str) -> Option<f64> {
    let cell = cell.trim();
    if cell.is_empty() {
        None
    } else {
        cell.parse().ok()
    }
}

fn compare_column<'a>(
    name: &str,
    rule: ColumnRule,
    cells: impl Iterator<Item = (&'a String, &'a String)> + Clone,
) -> ColumnChange {
    let peak = match rule {
        ColumnRule::PeakRelative { .. } => Some(
            cells
                .clone()
                .filter_map(|(_, b)| number(b))
                .filter(|b| b.is_finite())
                .fold(0.0, |m, b| f64::max(m, b.abs())),
        ),
        _ => None,
    };
    let mut change = ColumnChange {
        column: name.to_string(),
        rule,
        peak,
        max_abs: 0.0,
        max_rel: 0.0,
        beyond: 0,
        worst: None,
    };
    // How far beyond tolerance the worst cell is (|a - b| over what the rule allows).
    let mut worst_excess = 0.0_f64;
    let (mut numbers, mut texts) = (0_usize, 0_usize);
    for (i, (fresh, base)) in cells.enumerate() {
        let cell = || CellChange {
            line: i + 2,
            fresh: fresh.clone(),
            baseline: base.clone(),
        };
        let (a, b) = match (number(fresh), number(base)) {
            (Some(a), Some(b)) => {
                numbers += 1;
                (a, b)
            }
            _ => {
                texts += usize::from(!fresh.trim().is_empty() || !base.trim().is_empty());
                if fresh != base {
                    change.beyond += 1;
                    if worst_excess < f64::INFINITY {
                        worst_excess = f64::INFINITY;
                        change.worst = Some(cell());
                    }
                }
                continue;
            }
        };
        if !a.is_finite() || !b.is_finite() {
            let same = a == b || (a.is_nan() && b.is_nan());
            if !same {
                change.max_abs = f64::INFINITY;
                change.max_rel = f64::INFINITY;
                change.beyond += 1;
                if worst_excess < f64::INFINITY {
                    worst_excess = f64::INFINITY;
                    change.worst = Some(cell());
                }
            }
            continue;
        }
        let diff = (a - b).abs();
        let (scale, allowed) = match rule {
            ColumnRule::Relative { rel, abs } => (b.abs(), abs.max(rel * b.abs())),
            ColumnRule::PeakRelative { rel, abs } => {
                let p = peak.unwrap_or(0.0);
                (p, abs.max(rel * p))
            }
            ColumnRule::Exact | ColumnRule::Ignored | ColumnRule::Text => (b.abs(), 0.0),
        };
        let relative = if scale > 0.0 { diff / scale } else { 0.0 };
        change.max_abs = change.max_abs.max(diff);
        change.max_rel = change.max_rel.max(relative);
        if diff > allowed {
            change.beyond += 1;
            let excess = if allowed > 0.0 {
                diff / allowed
            } else {
                f64::MAX
            };
            if excess > worst_excess {
                worst_excess = excess;
                change.worst = Some(cell());
            }
        }
    }
    if numbers == 0 && texts > 0 {
        change.rule = ColumnRule::Text;
    }
    change
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
                match std::fs::read_to_string(baseline_dir.join(file)) {
                    Ok(base) => compare_csv(text, &base, tolerances),
                    Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                        FileOutcome::MissingInBaseline
                    }
                    Err(e) => FileOutcome::Unreadable(format!("baseline file: {e}")),
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

    fn columns(outcome: &FileOutcome) -> &[ColumnChange] {
        match outcome {
            FileOutcome::Compared { columns, .. } => columns,
            other => panic!("not compared: {other:?}"),
        }
    }

    #[test]
    fn rules_follow_the_documented_precedence() {
        let t = Tolerances::default();
        assert_eq!(t.rule_for(true, "wall_time_s"), ColumnRule::Ignored);
        assert_eq!(t.rule_for(false, "setup_time_s"), ColumnRule::Ignored);
        assert_ne!(t.rule_for(false, "beta_s"), ColumnRule::Ignored);
        assert_eq!(t.rule_for(true, "element"), ColumnRule::Exact);
        assert_eq!(t.rule_for(false, "N"), ColumnRule::Exact);
        assert!(matches!(
            t.rule_for(true, "stress"),
            ColumnRule::PeakRelative { .. }
        ));
        assert!(matches!(
            t.rule_for(false, "reference"),
            ColumnRule::Relative { .. }
        ));
        assert!(matches!(t.rule_for(true, "x"), ColumnRule::Relative { .. }));
    }

    #[test]
    fn relative_with_floor_peak_relative_exact_and_text() {
        let t = Tolerances::default();
        let base = "t,element,stress,reference,error,status,wall_time_s\n\
                    0.5,0,-1,-1.5,0.5,ok,0.1\n0.5,1,1e-6,0,1e-6,ok,0.1\n";
        // stress: 1e-6 -> 1.0002e-6 is 2e-4 relative to itself but 2e-10 of the peak (1): passes.
        // t: 0.5 -> 0.5 + 1e-10 is 2e-10 relative: passes. wall time ignored.
        let fresh = "t,element,stress,reference,error,status,wall_time_s\n\
                     0.5,0,-1,-1.5,0.5,ok,7\n0.5000000001,1,1.0002e-6,0,1.0002e-6,ok,9\n";
        let outcome = compare_csv(fresh, base, &t);
        let cols = columns(&outcome);
        assert!(cols.iter().all(ColumnChange::passed), "{outcome:?}");
        let FileOutcome::Compared { ignored, .. } = &outcome else {
            unreachable!()
        };
        assert_eq!(ignored, &["wall_time_s".to_string()]);
        let stress = cols.iter().find(|c| c.column == "stress").unwrap();
        assert_eq!(stress.peak, Some(1.0));
        assert!((stress.max_abs - 2e-10).abs() < 1e-16);

        // The same change is a failure where the column is relative to itself (not a profile).
        let base2 = base.replace("error", "err");
        let fresh2 = fresh.replace("error", "err");
        let outcome = compare_csv(&fresh2, &base2, &t);
        let stress = columns(&outcome)
            .iter()
            .find(|c| c.column == "stress")
            .unwrap();
        assert_eq!(stress.beyond, 1);
        assert_eq!(stress.worst.as_ref().unwrap().line, 3);

        // Integers exactly, text exactly.
        let fresh3 = fresh
            .replace("0.5,0,-1", "0.5,2,-1")
            .replace(",ok,9", ",KO,9");
        let outcome = compare_csv(&fresh3, base, &t);
        let failing: Vec<&str> = columns(&outcome)
            .iter()
            .filter(|c| !c.passed())
            .map(|c| c.column.as_str())
            .collect();
        assert_eq!(failing, ["element", "status"]);
        let status = columns(&outcome).iter().find(|c| c.column == "status");
        assert_eq!(status.unwrap().rule, ColumnRule::Text);
    }

    #[test]
    fn structure_changes_fail() {
        let t = Tolerances::default();
        let c = |fresh: &str, base: &str| FileComparison {
            file: "f.csv".into(),
            outcome: compare_csv(fresh, base, &t),
        };
        assert!(c("a,b\n1,2\n", "a,b\n1,2\n").passed());
        let header = c("a,c\n1,2\n", "a,b\n1,2\n");
        assert!(matches!(header.outcome, FileOutcome::HeaderChanged { .. }));
        assert!(header.failure_message().unwrap().contains("added: c"));
        let rows = c("a,b\n1,2\n", "a,b\n1,2\n3,4\n");
        assert_eq!(
            rows.outcome,
            FileOutcome::RowCountChanged {
                fresh: 1,
                baseline: 2
            }
        );
        assert!(!c("a,b\n1,nan\n", "a,b\n1,2\n").passed());
        assert!(c("a,b\nNaN,inf\n", "a,b\nNaN,inf\n").passed());
        assert!(!c("a,b\n1,\n", "a,b\n1,0\n").passed());
    }

    /// Overrides come first: a column named on the command line gets its rule whatever its kind.
    #[test]
    fn overrides_win_and_parse_with_named_errors() {
        let mut t = Tolerances::default();
        let (c, r) = ColumnRule::parse_override("stress=rel:1e-6", 1e-12, 1e-12).unwrap();
        assert_eq!(c, "stress");
        assert_eq!(
            r,
            ColumnRule::Relative {
                rel: 1e-6,
                abs: 1e-12
            }
        );
        t.overrides.push((c, r));
        t.overrides
            .push(ColumnRule::parse_override("wall_time_s=exact", 0.0, 0.0).unwrap());
        t.overrides
            .push(ColumnRule::parse_override("x=peak:1e-3:1e-8", 0.0, 0.0).unwrap());
        t.overrides
            .push(ColumnRule::parse_override(" l1 = ignore ", 0.0, 0.0).unwrap());
        assert_eq!(t.rule_for(true, "stress"), r);
        assert_eq!(t.rule_for(false, "wall_time_s"), ColumnRule::Exact);
        assert_eq!(
            t.rule_for(false, "x"),
            ColumnRule::PeakRelative {
                rel: 1e-3,
                abs: 1e-8
            }
        );
        assert_eq!(t.rule_for(false, "l1"), ColumnRule::Ignored);
        // Without its own ABS a peak rule takes the peak floor, a relative rule the plain one.
        assert_eq!(
            ColumnRule::parse_override("s=peak:1e-3", 1e-12, 1e-9)
                .unwrap()
                .1,
            ColumnRule::PeakRelative {
                rel: 1e-3,
                abs: 1e-9
            }
        );
        assert!(t.describe().contains("; l1: ignored"));
        for bad in [
            "stress",
            "=rel:1",
            "stress=rel",
            "stress=rel:-1",
            "stress=rel:1:2:3",
            "stress=exact:1",
            "stress=relative:1",
            "stress=rel:nan",
        ] {
            let e = ColumnRule::parse_override(bad, 0.0, 0.0).unwrap_err();
            assert_eq!(e.flag, "--column");
            assert_eq!(e.value, bad);
            assert!(e.to_string().contains("COLUMN=RULE"), "{e}");
        }
        assert!(tolerance_value("--rel", -1.0).is_err());
        assert!(tolerance_value("--abs", f64::INFINITY).is_err());
        assert_eq!(tolerance_value("--abs", 0.0), Ok(0.0));
    }

    /// Columns are matched by name: a report drops `wall_time_s` from summaries, a run keeps it.
    #[test]
    fn ignored_columns_may_be_on_one_side_only() {
        let t = Tolerances::default();
        let fresh = "case,l1,wall_time_s\na,0.5,3.2\n";
        let report = "case,l1\na,0.5000000001\n";
        let outcome = compare_csv(fresh, report, &t);
        assert_eq!(columns(&outcome).len(), 2);
        assert!(columns(&outcome).iter().all(ColumnChange::passed));
        let FileOutcome::Compared { ignored, .. } = &outcome else {
            unreachable!()
        };
        assert_eq!(ignored, &["wall_time_s".to_string()]);
        // A compared column on one side only still changes the header.
        let outcome = compare_csv("case,l1,l2\na,1,2\n", "case,l1\na,1\n", &t);
        assert!(matches!(outcome, FileOutcome::HeaderChanged { .. }));
        // The same columns in another order are compared by name.
        let outcome = compare_csv("l1,case\n0.5,a\n", "case,l1\na,0.5\n", &t);
        assert!(
            columns(&outcome).iter().all(|c| !c.changed()),
            "{outcome:?}"
        );
    }

    /// A report keeps only its tables: other fresh files are skipped, its tables must match and
    /// must exist; a run's output keeps everything.
    #[test]
    fn a_report_baseline_compares_its_tables_and_skips_per_case_files() {
        let root =
            std::env::temp_dir().join(format!("courant-baseline-kind-{}", std::process::id()));
        let scene = root.join("s");
        std::fs::create_dir_all(&scene).unwrap();
        assert_eq!(BaselineKind::detect(&root), BaselineKind::RunOutput);
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
