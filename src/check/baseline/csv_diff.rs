//! Comparing a fresh CSV with its baseline, cell by cell, under each column's rule: what changed
//! in each column (largest absolute and relative change, cells beyond tolerance, the worst one).

use super::tolerance::{ColumnRule, Tolerances};

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
    /// Cells of a numeric column that differ and are not a number on one side or both (e.g.
    /// `abc` or an empty cell against `1.5`): counted in `beyond`, reported as "not a number".
    pub not_numbers: usize,
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
        } else if self.not_numbers > 0 && self.max_abs == 0.0 {
            format!(
                "{}: {} cell(s) not a number [{}{peak}]",
                self.column,
                self.not_numbers,
                self.rule.label()
            )
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

/// A parsed CSV table: header and data rows.
type Csv = (Vec<String>, Vec<Vec<String>>);

/// A CSV reader's error as "line N: what" (not the csv crate's wording).
fn located(e: &csv::Error) -> String {
    let line = |pos: &Option<csv::Position>| pos.as_ref().map_or(0, csv::Position::line);
    match e.kind() {
        csv::ErrorKind::UnequalLengths {
            pos,
            expected_len,
            len,
        } => format!(
            "line {}: the row has {len} cells, the header {expected_len}",
            line(pos)
        ),
        csv::ErrorKind::Utf8 { pos, .. } => format!("line {}: not UTF-8 text", line(pos)),
        _ => format!("not a CSV table ({e})"),
    }
}

fn parse_csv(text: &str) -> Result<Csv, String> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .from_reader(text.as_bytes());
    let header = reader
        .headers()
        .map_err(|e| located(&e))?
        .iter()
        .map(str::to_string)
        .collect();
    let rows = reader
        .records()
        .map(|r| {
            r.map(|r| r.iter().map(str::to_string).collect())
                .map_err(|e| located(&e))
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
        not_numbers: 0,
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
                    change.not_numbers += 1;
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
        change.not_numbers = 0;
    }
    change
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::baseline::scene_diff::FileComparison;
    use crate::check::baseline::tolerance::tolerance_value;

    fn columns(outcome: &FileOutcome) -> &[ColumnChange] {
        match outcome {
            FileOutcome::Compared { columns, .. } => columns,
            other => panic!("not compared: {other:?}"),
        }
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

    #[test]
    fn a_corrupted_baseline_is_named_at_its_line() {
        let outcome = compare_csv("a,b\n1,2\n", "a,b\n1,2\n3\n", &Tolerances::default());
        assert_eq!(
            outcome,
            FileOutcome::Unreadable(
                "baseline file: line 3: the row has 1 cells, the header 2".into()
            )
        );
    }
}
