//! `results.toml`: what a result set knows of itself. Every key is optional; unknown keys are
//! errors naming line and key, as in scene files.
//!
//! ```toml
//! format = 2                 # the exchange format's version (default 1; 2 adds `parameters`)
//! code = "sfepy"             # the producing code
//! version = "2026.3"         # its version
//!
//! [cases."co0.5"]            # one table per case file (co0.5.csv), every key optional
//! scheme = "central-difference"  # a name of `courant list --schemes` (or a contact scheme)
//! parameters = { }           # the scheme's parameters, e.g. { p = 0.54 } for noh-bathe
//! mass = "lumped"            # lmm/lumped, cmm/consistent, amm(beta), rmm(beta)
//! dt = 0.005                 # the time step (time-level offsets are counted in steps of it)
//! elements = 100             # the number of elements
//! wall_s = 0.0123            # the code's own time for the run, s (format 2; median of >= 3 runs)
//! steps = 300                # the time steps the run took (format 2)
//! ```
//!
//! `scheme`, `parameters` and `mass` say which of the scene's signature rows apply to the case
//! (`compare::score::applies`): those of a case run with the same scheme, parameters and mass.

use super::FORMAT;
use super::error::{ExchangeError, line_column};
use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

/// A scheme parameter's value in `results.toml`.
#[derive(Debug, Clone, PartialEq)]
pub enum MetaValue {
    /// A number.
    Number(f64),
    /// A word.
    Text(String),
}

/// A key of `results.toml` with its value and its (line, column).
#[derive(Debug, Clone, PartialEq)]
pub struct Located<T> {
    /// The value.
    pub value: T,
    /// 1-based line.
    pub line: usize,
    /// 1-based column.
    pub column: usize,
}

impl<T> Located<T> {
    /// A value with no position (a set built in memory).
    pub fn unplaced(value: T) -> Self {
        Self {
            value,
            line: 0,
            column: 0,
        }
    }
}

/// What `results.toml` says of one case.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CaseMeta {
    /// Time-stepping (or contact) scheme, as the registry names it.
    pub scheme: Option<String>,
    /// Where `scheme` is (line, column), for messages.
    pub scheme_at: (usize, usize),
    /// The scheme's parameters, in file order (keys sorted by TOML).
    pub parameters: Vec<(String, Located<MetaValue>)>,
    /// Mass kind, as written, with its (line, column) (checked against the scene's vocabulary
    /// by `compare::score`).
    pub mass: Option<(String, usize, usize)>,
    /// Time step.
    pub dt: Option<f64>,
    /// Number of elements, with its line.
    pub elements: Option<(usize, usize)>,
    /// The producing code's own wall time for the run, in seconds, measured by its driver
    /// around its time loop (format 2). Machine-specific: compared only as a ratio.
    pub wall_s: Option<f64>,
    /// The time steps the run took (format 2).
    pub steps: Option<usize>,
    /// Line of the case's table header.
    pub line: usize,
}

/// `results.toml`.
#[derive(Debug, Clone, PartialEq)]
pub struct ResultsMeta {
    /// Path of the file, for messages.
    pub file: String,
    /// Format version.
    pub format: u32,
    /// Producing code.
    pub code: Option<String>,
    /// Its version.
    pub version: Option<String>,
    /// Per case, by case name (sorted).
    pub cases: BTreeMap<String, CaseMeta>,
}

impl ResultsMeta {
    /// What is known of `case` (nothing when the file has no table for it).
    pub fn case(&self, case: &str) -> Option<&CaseMeta> {
        self.cases.get(case)
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMeta {
    format: Option<Spanned<i64>>,
    code: Option<String>,
    version: Option<String>,
    #[serde(default)]
    cases: BTreeMap<String, Spanned<RawCaseMeta>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCaseMeta {
    scheme: Option<Spanned<String>>,
    parameters: Option<BTreeMap<String, Spanned<toml::Value>>>,
    mass: Option<Spanned<String>>,
    dt: Option<Spanned<toml::Value>>,
    elements: Option<Spanned<i64>>,
    wall_s: Option<Spanned<toml::Value>>,
    steps: Option<Spanned<toml::Value>>,
}

/// Read `results.toml` (`file` names it in messages).
///
/// # Errors
/// TOML that does not parse, an unknown key, a format newer than this courant reads, a `dt`
/// or `wall_s` that is not a positive finite number, `elements` below 1, `steps` that is not a
/// positive integer, a format-2 key (`parameters`, `wall_s`, `steps`) in a file that says
/// format 1; each naming line, column and key.
pub fn parse(file: &str, text: &str) -> Result<ResultsMeta, ExchangeError> {
    let at = |offset: usize, key: &str, message: String| {
        let (line, column) = line_column(text, offset);
        ExchangeError::at(file, line, column, key, message)
    };
    let raw: RawMeta = toml::from_str(text).map_err(|e| {
        let offset = e.span().map_or(0, |s| s.start);
        let message = e.message().trim().replace('\n', "; ");
        // serde names an unknown key between backticks: `unknown field `x`, expected ...`.
        let key = message
            .strip_prefix("unknown field `")
            .and_then(|rest| rest.split('`').next())
            .map_or_else(|| key_at(text, offset), str::to_string);
        at(offset, &key, message)
    })?;
    let format = match raw.format {
        None => FORMAT,
        Some(f) => match u32::try_from(*f.get_ref()) {
            Ok(v) if (1..=FORMAT).contains(&v) => v,
            _ => {
                return Err(at(
                    f.span().start,
                    "format",
                    format!(
                        "{} is not a format this courant reads (1 to {FORMAT}); a newer format needs a newer courant",
                        f.get_ref()
                    ),
                ));
            }
        },
    };
    let mut cases = BTreeMap::new();
    for (name, spanned) in raw.cases {
        let key = |k: &str| format!("cases.\"{name}\".{k}");
        let header = line_column(text, spanned.span().start).0;
        let raw = spanned.into_inner();
        let dt = match raw.dt {
            None => None,
            Some(v) => {
                let value = match v.get_ref() {
                    toml::Value::Float(x) => Some(*x),
                    toml::Value::Integer(i) => Some(*i as f64),
                    _ => None,
                };
                match value {
                    Some(x) if x.is_finite() && x > 0.0 => Some(x),
                    _ => {
                        return Err(at(
                            v.span().start,
                            &key("dt"),
                            format!("{} must be a positive finite number", v.get_ref()),
                        ));
                    }
                }
            }
        };
        let elements = match raw.elements {
            None => None,
            Some(e) if *e.get_ref() >= 1 => {
                Some((*e.get_ref() as usize, line_column(text, e.span().start).0))
            }
            Some(e) => {
                return Err(at(
                    e.span().start,
                    &key("elements"),
                    format!("{} must be at least 1", e.get_ref()),
                ));
            }
        };
        let format_2 = |k: &str, offset: usize| {
            at(
                offset,
                &key(k),
                format!(
                    "`{k}` is a key of format 2; this file says format = {format} (write format = 2)"
                ),
            )
        };
        let wall_s = match raw.wall_s {
            None => None,
            Some(v) if format < 2 => return Err(format_2("wall_s", v.span().start)),
            Some(v) => match v.get_ref() {
                toml::Value::Float(x) if x.is_finite() && *x > 0.0 => Some(*x),
                toml::Value::Integer(i) if *i > 0 => Some(*i as f64),
                other => {
                    return Err(at(
                        v.span().start,
                        &key("wall_s"),
                        format!("{other} must be a positive finite number of seconds"),
                    ));
                }
            },
        };
        let steps = match raw.steps {
            None => None,
            Some(v) if format < 2 => return Err(format_2("steps", v.span().start)),
            Some(v) => match v.get_ref() {
                toml::Value::Integer(i) if *i >= 1 => Some(*i as usize),
                other => {
                    return Err(at(
                        v.span().start,
                        &key("steps"),
                        format!("{other} must be a whole number of steps, at least 1"),
                    ));
                }
            },
        };
        let mass = raw.mass.map(|m| {
            let (line, column) = line_column(text, m.span().start);
            (m.into_inner(), line, column)
        });
        let mut parameters = Vec::new();
        for (k, v) in raw.parameters.unwrap_or_default() {
            if format < 2 {
                return Err(at(
                    v.span().start,
                    &format!("cases.\"{name}\".parameters.{k}"),
                    format!(
                        "`parameters` is a key of format 2; this file says format = {format} (write format = 2)"
                    ),
                ));
            }
            let (line, column) = line_column(text, v.span().start);
            let value = match v.get_ref() {
                toml::Value::Float(x) if x.is_finite() => MetaValue::Number(*x),
                toml::Value::Integer(i) => MetaValue::Number(*i as f64),
                toml::Value::String(word) => MetaValue::Text(word.clone()),
                other => {
                    return Err(at(
                        v.span().start,
                        &format!("cases.\"{name}\".parameters.{k}"),
                        format!("{other} is not a finite number or a word in quotes"),
                    ));
                }
            };
            parameters.push((
                k,
                Located {
                    value,
                    line,
                    column,
                },
            ));
        }
        let (scheme, scheme_at) = match raw.scheme {
            Some(s) => {
                let at = line_column(text, s.span().start);
                (Some(s.into_inner()), at)
            }
            None => (None, (0, 0)),
        };
        cases.insert(
            name,
            CaseMeta {
                scheme,
                scheme_at,
                parameters,
                mass,
                dt,
                elements,
                wall_s,
                steps,
                line: header,
            },
        );
    }
    Ok(ResultsMeta {
        file: file.to_string(),
        format,
        code: raw.code,
        version: raw.version,
        cases,
    })
}

/// The dotted key whose value starts at byte `offset` (`cases."co1".elements`): the text before
/// `=` on its line, under the last table header above it; empty when there is none.
fn key_at(text: &str, offset: usize) -> String {
    let offset = offset.min(text.len());
    let line_start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let line = &text[line_start..];
    let line = &line[..line.find('\n').unwrap_or(line.len())];
    let Some((key, _)) = line.split_once('=') else {
        return String::new();
    };
    let key = key.trim();
    let table = text[..line_start]
        .lines()
        .rev()
        .map(str::trim)
        .find(|l| l.starts_with('[') && l.ends_with(']'))
        .map(|l| l.trim_matches(|c| c == '[' || c == ']').trim());
    match table {
        Some(t) if !t.is_empty() => format!("{t}.{key}"),
        _ => key.to_string(),
    }
}

/// A TOML basic string (quoted and escaped).
fn quoted(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

/// The text of a `results.toml` (format [`FORMAT`]): `code`, `version`, then one table per case
/// in the order given. `dt` is written at round-trip precision.
pub fn render(code: &str, version: &str, cases: &[(String, CaseMeta)]) -> String {
    let mut out = format!(
        "format = {FORMAT}\ncode = {}\nversion = {}\n",
        quoted(code),
        quoted(version)
    );
    for (name, meta) in cases {
        out += &format!("\n[cases.{}]\n", quoted(name));
        if let Some(s) = &meta.scheme {
            out += &format!("scheme = {}\n", quoted(s));
        }
        if !meta.parameters.is_empty() {
            let items: Vec<String> = meta
                .parameters
                .iter()
                .map(|(k, v)| match &v.value {
                    MetaValue::Number(x) => format!("{k} = {x:?}"),
                    MetaValue::Text(word) => format!("{k} = {}", quoted(word)),
                })
                .collect();
            out += &format!("parameters = {{ {} }}\n", items.join(", "));
        }
        if let Some((m, ..)) = &meta.mass {
            out += &format!("mass = {}\n", quoted(m));
        }
        if let Some(dt) = meta.dt {
            out += &format!("dt = {dt:?}\n");
        }
        if let Some((n, _)) = meta.elements {
            out += &format!("elements = {n}\n");
        }
        if let Some(w) = meta.wall_s {
            out += &format!("wall_s = {w:?}\n");
        }
        if let Some(n) = meta.steps {
            out += &format!("steps = {n}\n");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_written_file_reads_back() {
        let case = CaseMeta {
            scheme: Some("noh-bathe".into()),
            parameters: vec![("p".into(), Located::unplaced(MetaValue::Number(0.54)))],
            mass: Some(("rmm(0.5)".into(), 0, 0)),
            dt: Some(0.1 + 0.2),
            elements: Some((100, 0)),
            wall_s: Some(0.0125),
            steps: Some(300),
            ..CaseMeta::default()
        };
        let text = render("courant", "0.1.0", &[("co0.5".into(), case)]);
        let meta = parse("r.toml", &text).unwrap();
        assert_eq!(meta.format, FORMAT);
        assert_eq!(meta.code.as_deref(), Some("courant"));
        let c = meta.case("co0.5").unwrap();
        assert_eq!(c.dt, Some(0.1 + 0.2));
        assert_eq!(c.elements.map(|e| e.0), Some(100));
        assert_eq!(c.mass.as_ref().map(|m| m.0.as_str()), Some("rmm(0.5)"));
        assert_eq!(c.scheme.as_deref(), Some("noh-bathe"));
        assert_eq!((c.wall_s, c.steps), (Some(0.0125), Some(300)));
        assert_eq!(c.parameters[0].0, "p");
        assert_eq!(c.parameters[0].1.value, MetaValue::Number(0.54));
        assert_eq!(c.parameters[0].1.line, 7, "{text}");
    }

    #[test]
    fn unknown_keys_and_bad_values_name_line_and_key() {
        let e = parse("r.toml", "code = \"x\"\n[cases.a]\nsheme = \"cd\"\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (3, "sheme"), "{e}");
        let e = parse("r.toml", "[cases.a]\ndt = -1\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (2, "cases.\"a\".dt"), "{e}");
        let e = parse("r.toml", "format = 3\n").unwrap_err();
        assert!(e.message.contains("newer courant"), "{e}");
        let e = parse(
            "r.toml",
            "format = 1\n[cases.a]\nscheme = \"cd\"\nparameters = { p = 1 }\n",
        )
        .unwrap_err();
        assert_eq!(
            (e.line, e.key.as_str()),
            (4, "cases.\"a\".parameters.p"),
            "{e}"
        );
        let e = parse("r.toml", "[cases.a]\nelements = 0\n").unwrap_err();
        assert_eq!(e.line, 2);
        // A value of the wrong type names its key.
        let e = parse(
            "r.toml",
            "code = \"x\"\n[cases.\"co1\"]\nelements = \"1\"\n",
        )
        .unwrap_err();
        assert_eq!(
            (e.line, e.key.as_str()),
            (3, "cases.\"co1\".elements"),
            "{e}"
        );
        let e = parse("r.toml", "format = \"1\"\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (1, "format"), "{e}");
    }

    /// The cost keys of format 2 (README, "Results exchange format"): `wall_s` a positive finite
    /// number, `steps` a positive integer, both refused in a format-1 file; each error names its
    /// line and key.
    #[test]
    fn wall_time_and_steps_are_checked_and_located() {
        let ok = parse(
            "r.toml",
            "format = 2\n[cases.a]\nwall_s = 0.5\nsteps = 3\n[cases.b]\n",
        )
        .unwrap();
        assert_eq!(
            ok.case("a").map(|c| (c.wall_s, c.steps)),
            Some((Some(0.5), Some(3)))
        );
        assert_eq!(
            ok.case("b").map(|c| (c.wall_s, c.steps)),
            Some((None, None))
        );
        for (text, line, key, words) in [
            (
                "format = 2\n[cases.a]\nwall_s = 0.0\n",
                3,
                "wall_s",
                "positive finite",
            ),
            (
                "format = 2\n[cases.a]\nwall_s = -1\n",
                3,
                "wall_s",
                "positive finite",
            ),
            (
                "format = 2\n[cases.a]\nwall_s = nan\n",
                3,
                "wall_s",
                "positive finite",
            ),
            (
                "format = 2\n[cases.a]\nwall_s = inf\n",
                3,
                "wall_s",
                "positive finite",
            ),
            (
                "format = 2\n[cases.a]\nwall_s = \"1 s\"\n",
                3,
                "wall_s",
                "positive finite",
            ),
            (
                "format = 2\n[cases.a]\n\nsteps = 0\n",
                4,
                "steps",
                "whole number",
            ),
            (
                "format = 2\n[cases.a]\nsteps = 2.5\n",
                3,
                "steps",
                "whole number",
            ),
            ("format = 1\n[cases.a]\nsteps = 2\n", 3, "steps", "format 2"),
            (
                "format = 1\n[cases.a]\nwall_s = 2\n",
                3,
                "wall_s",
                "format 2",
            ),
        ] {
            let e = parse("r.toml", text).unwrap_err();
            assert_eq!(
                (e.line, e.key.as_str()),
                (line, format!("cases.\"a\".{key}").as_str()),
                "{text}: {e}"
            );
            assert!(e.message.contains(words), "{text}: {e}");
        }
    }
}
