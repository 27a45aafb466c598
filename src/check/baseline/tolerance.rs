//! The tolerance rules of a baseline comparison: per column relative, peak-relative, exact or
//! ignored, with command-line overrides.

use thiserror::Error;

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

#[cfg(test)]
mod tests {
    use super::*;

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
}
