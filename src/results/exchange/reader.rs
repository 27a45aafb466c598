//! Reading exchange files into records. Every error names the file, the line, the column (the
//! CSV field number) and the column name, and nothing is returned half-read.

use super::columns::{Header, Kind, Want};
use super::error::{
    ERRORS_PER_FILE, ExchangeError, ExchangeErrors, SHOWN, csv_error, short_number,
    unterminated_quote,
};
use super::record::{CaseData, CaseFile, ForceHistory, Positions, Profile, SpectrumRow};
use crate::io::bounded_read::shortened;

/// Name of the optional metadata file of a result set.
pub const META_FILE: &str = "results.toml";

/// Relative tolerance (of a profile's extent) within which neighbouring elements touch and two
/// points coincide.
pub const TOUCH: f64 = 1e-9;

/// One parsed row: its line and its cells by column name.
struct Row {
    line: usize,
    cells: Vec<(&'static str, Cell)>,
}

enum Cell {
    Number(f64),
    Text(String),
}

impl Row {
    fn number(&self, column: &str) -> Option<f64> {
        self.cells.iter().find_map(|(name, cell)| match cell {
            Cell::Number(x) if *name == column => Some(*x),
            _ => None,
        })
    }

    fn text(&self, column: &str) -> Option<String> {
        self.cells.iter().find_map(|(name, cell)| match cell {
            Cell::Text(s) if *name == column => Some(s.clone()),
            _ => None,
        })
    }
}

/// Read one case file. `case` is its name (the file stem), `file` its path for messages.
///
/// # Errors
/// A header the format does not know ([`Header::recognise`]), a row of the wrong length, an
/// empty, non-numeric or non-finite cell, times that decrease, elements that overlap or leave a
/// gap, a point given twice, a mode given twice, no rows.
pub fn read_case(
    file: &str,
    case: &str,
    text: &str,
    want: Want,
) -> Result<CaseFile, ExchangeError> {
    read_case_whole(file, case, text, want).map_err(|mut e| e.0.swap_remove(0))
}

/// [`read_case`], reporting every bad cell (up to [`ERRORS_PER_FILE`]) rather than the first.
///
/// # Errors
/// As [`read_case`], all of them.
pub fn read_case_whole(
    file: &str,
    case: &str,
    text: &str,
    want: Want,
) -> Result<CaseFile, ExchangeErrors> {
    if let Some(e) = unterminated_quote(file, text) {
        return Err(e.into());
    }
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let names: Vec<String> = reader
        .headers()
        .map_err(|e| csv_error(file, &e))?
        .iter()
        .map(str::to_string)
        .collect();
    if names.iter().all(|n| n.trim().is_empty()) {
        return Err(ExchangeError::at(file, 1, 1, "", "no header line: the file is empty").into());
    }
    let header = Header::recognise(file, &names, want)?;
    let wanted: Vec<&'static str> = match want {
        Want::Results => header.kind.columns(),
        Want::Query => header.kind.keys().to_vec(),
    };
    let mut rows = Vec::new();
    let mut errors = Vec::new();
    let mut more = 0usize;
    let mut note = |e: ExchangeError, errors: &mut Vec<ExchangeError>| {
        if errors.len() < ERRORS_PER_FILE {
            errors.push(e);
        } else {
            more += 1;
        }
    };
    for record in reader.records() {
        let record = match record {
            Ok(r) => r,
            Err(e) => {
                note(csv_error(file, &e), &mut errors);
                continue;
            }
        };
        let line = record.position().map_or(0, |p| p.line() as usize);
        let mut cells = Vec::new();
        for &column in &wanted {
            let Some(i) = header.field(column) else {
                continue;
            };
            let raw = record.get(i).unwrap_or_default();
            match cell(file, line, i + 1, column, raw) {
                Ok(c) => cells.push((column, c)),
                Err(e) => note(e, &mut errors),
            }
        }
        rows.push(Row { line, cells });
    }
    if more > 0 {
        errors.push(ExchangeError::file(
            file,
            format!("and {more} more bad cell(s) not listed"),
        ));
    }
    if !errors.is_empty() {
        return Err(ExchangeErrors(errors));
    }
    if rows.is_empty() {
        return Err(ExchangeError::at(file, 1, 1, "", "no rows after the header").into());
    }
    let column_of = |name: &str| header.field(name).map_or(1, |i| i + 1);
    let data = match header.kind {
        Kind::Elements | Kind::Points => {
            CaseData::Profiles(profiles(file, header.kind, &rows, &column_of)?)
        }
        Kind::Force => CaseData::Force(force_history(file, &rows, &column_of)?),
        Kind::Spectrum => CaseData::Spectrum(spectrum(file, &rows, &column_of)?),
    };
    Ok(CaseFile {
        case: case.to_string(),
        file: file.to_string(),
        columns: header.fields.iter().map(|&(n, i)| (n, i + 1)).collect(),
        data,
        reference: None,
    })
}

/// Parse one cell: a mass label stays text, every other column is a finite number (`mode` a
/// whole number).
fn cell(
    file: &str,
    line: usize,
    column: usize,
    name: &str,
    raw: &str,
) -> Result<Cell, ExchangeError> {
    let fail = |message: String| ExchangeError::at(file, line, column, name, message);
    let shown = shortened(raw, SHOWN);
    if raw.is_empty() {
        return Err(fail("the cell is empty".into()));
    }
    if name == "mass" {
        return Ok(Cell::Text(raw.to_string()));
    }
    let x: f64 = raw
        .parse()
        .map_err(|_| fail(format!("`{shown}` is not a number")))?;
    if !x.is_finite() {
        return Err(fail(format!("`{shown}` is not finite")));
    }
    if name == "mode" && !(x >= 0.0 && x.fract() == 0.0 && x <= 1e9) {
        return Err(fail(format!(
            "`{shown}` is not a mode number (a whole number, 0 or more)"
        )));
    }
    Ok(Cell::Number(x))
}

/// Group profile rows by time (times never decreasing), sort each group by position and check
/// that elements neither overlap nor leave a gap and that points are distinct.
fn profiles(
    file: &str,
    kind: Kind,
    rows: &[Row],
    column_of: &dyn Fn(&str) -> usize,
) -> Result<Vec<Profile>, ExchangeError> {
    let mut groups: Vec<(f64, Vec<&Row>)> = Vec::new();
    for row in rows {
        let t = row.number("t").unwrap_or(f64::NAN);
        match groups.last_mut() {
            Some((time, group)) if *time == t => group.push(row),
            Some((time, group)) if t < *time => {
                return Err(ExchangeError::at(
                    file,
                    row.line,
                    column_of("t"),
                    "t",
                    format!(
                        "t = {t} after t = {time} (line {}): rows are grouped by time, times never decrease",
                        group.last().map_or(0, |r| r.line)
                    ),
                ));
            }
            _ => groups.push((t, vec![row])),
        }
    }
    groups
        .into_iter()
        .map(|(time, mut group)| {
            let key = if kind == Kind::Elements {
                "x_left"
            } else {
                "x"
            };
            group.sort_by(|a, b| {
                a.number(key)
                    .unwrap_or(0.0)
                    .total_cmp(&b.number(key).unwrap_or(0.0))
            });
            let lines: Vec<usize> = group.iter().map(|r| r.line).collect();
            let stress: Vec<f64> = group.iter().filter_map(|r| r.number("stress")).collect();
            let positions = if kind == Kind::Elements {
                let left: Vec<f64> = group
                    .iter()
                    .map(|r| r.number("x_left").unwrap_or(0.0))
                    .collect();
                let right: Vec<f64> = group
                    .iter()
                    .map(|r| r.number("x_right").unwrap_or(0.0))
                    .collect();
                check_elements(file, &left, &right, &lines, column_of)?;
                Positions::Elements { left, right }
            } else {
                let x: Vec<f64> = group.iter().map(|r| r.number("x").unwrap_or(0.0)).collect();
                check_points(file, &x, &lines, column_of)?;
                Positions::Points(x)
            };
            Ok(Profile {
                time,
                positions,
                stress,
                lines,
            })
        })
        .collect()
}

/// Elements of one time, sorted by left end: each has `left < right`, and each starts where the
/// previous one ends (within [`TOUCH`] of the profile's extent).
fn check_elements(
    file: &str,
    left: &[f64],
    right: &[f64],
    lines: &[usize],
    column_of: &dyn Fn(&str) -> usize,
) -> Result<(), ExchangeError> {
    let extent = right.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b)) - left[0];
    let tol = TOUCH * extent.abs();
    for i in 0..left.len() {
        if left[i] >= right[i] {
            return Err(ExchangeError::at(
                file,
                lines[i],
                column_of("x_right"),
                "x_right",
                format!(
                    "x_right = {} is not above x_left = {}: an element has a positive length",
                    short_number(right[i]),
                    short_number(left[i])
                ),
            ));
        }
        if i == 0 {
            continue;
        }
        let (end, start) = (right[i - 1], left[i]);
        if start < end - tol {
            return Err(ExchangeError::at(
                file,
                lines[i],
                column_of("x_left"),
                "x_left",
                format!(
                    "the mesh overlaps itself: element [{start}, {}] starts inside [{}, {end}] (line {})",
                    right[i],
                    left[i - 1],
                    lines[i - 1]
                ),
            ));
        }
        if start > end + tol {
            return Err(ExchangeError::at(
                file,
                lines[i],
                column_of("x_left"),
                "x_left",
                format!(
                    "the mesh does not cover the bar: a gap between x = {end} (line {}) and x = {start}",
                    lines[i - 1]
                ),
            ));
        }
    }
    Ok(())
}

/// Points of one time, sorted: no two within [`TOUCH`] of the profile's extent.
fn check_points(
    file: &str,
    x: &[f64],
    lines: &[usize],
    column_of: &dyn Fn(&str) -> usize,
) -> Result<(), ExchangeError> {
    let tol = TOUCH * (x[x.len() - 1] - x[0]).abs();
    for i in 1..x.len() {
        if x[i] - x[i - 1] <= tol {
            return Err(ExchangeError::at(
                file,
                lines[i],
                column_of("x"),
                "x",
                format!(
                    "the points overlap: x = {} is given twice at one time (line {})",
                    short_number(x[i]),
                    lines[i - 1]
                ),
            ));
        }
    }
    Ok(())
}

fn force_history(
    file: &str,
    rows: &[Row],
    column_of: &dyn Fn(&str) -> usize,
) -> Result<ForceHistory, ExchangeError> {
    for pair in rows.windows(2) {
        let (a, b) = (pair[0].number("t"), pair[1].number("t"));
        if b <= a {
            return Err(ExchangeError::at(
                file,
                pair[1].line,
                column_of("t"),
                "t",
                format!(
                    "t = {} after t = {} (line {}): the times of a force history increase",
                    short_number(b.unwrap_or(f64::NAN)),
                    short_number(a.unwrap_or(f64::NAN)),
                    pair[0].line
                ),
            ));
        }
    }
    let column = |name: &str| -> Option<Vec<f64>> { rows.iter().map(|r| r.number(name)).collect() };
    Ok(ForceHistory {
        time: column("t").unwrap_or_default(),
        force: column("force").unwrap_or_default(),
        penetration: column("penetration"),
        gap: column("gap"),
        lines: rows.iter().map(|r| r.line).collect(),
    })
}

fn spectrum(
    file: &str,
    rows: &[Row],
    column_of: &dyn Fn(&str) -> usize,
) -> Result<Vec<SpectrumRow>, ExchangeError> {
    let mut out: Vec<SpectrumRow> = Vec::new();
    for row in rows {
        let spectrum_row = SpectrumRow {
            mode: row.number("mode").unwrap_or(0.0) as usize,
            omega: row.number("omega").unwrap_or(f64::NAN),
            mass: row.text("mass"),
            line: row.line,
        };
        if let Some(twin) = out
            .iter()
            .find(|r| r.mode == spectrum_row.mode && r.mass == spectrum_row.mass)
        {
            return Err(ExchangeError::at(
                file,
                row.line,
                column_of("mode"),
                "mode",
                format!(
                    "mode {} is given twice{} (line {})",
                    spectrum_row.mode,
                    spectrum_row
                        .mass
                        .as_ref()
                        .map(|m| format!(" for mass {m}"))
                        .unwrap_or_default(),
                    twin.line
                ),
            ));
        }
        out.push(spectrum_row);
    }
    Ok(out)
}

#[cfg(test)]
#[path = "reader_tests.rs"]
mod tests;
