//! Reading exchange files into records. Every error names the file, the line, the column (the
//! CSV field number) and the column name, and nothing is returned half-read.

use super::columns::{Header, Kind, Want};
use super::error::{ERRORS_PER_FILE, ExchangeError, ExchangeErrors};
use super::record::{CaseData, CaseFile, ForceHistory, Positions, Profile, SpectrumRow};

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
    if raw.is_empty() {
        return Err(fail("the cell is empty".into()));
    }
    if name == "mass" {
        return Ok(Cell::Text(raw.to_string()));
    }
    let x: f64 = raw
        .parse()
        .map_err(|_| fail(format!("`{raw}` is not a number")))?;
    if !x.is_finite() {
        return Err(fail(format!("`{raw}` is not finite")));
    }
    if name == "mode" && !(x >= 0.0 && x.fract() == 0.0 && x <= 1e9) {
        return Err(fail(format!(
            "`{raw}` is not a mode number (a whole number, 0 or more)"
        )));
    }
    Ok(Cell::Number(x))
}

fn csv_error(file: &str, e: &csv::Error) -> ExchangeError {
    match e.kind() {
        csv::ErrorKind::UnequalLengths {
            pos,
            expected_len,
            len,
        } => ExchangeError::at(
            file,
            pos.as_ref().map_or(0, |p| p.line() as usize),
            1,
            "",
            format!("the row has {len} cells, the header {expected_len}"),
        ),
        csv::ErrorKind::Utf8 { pos, .. } => ExchangeError::at(
            file,
            pos.as_ref().map_or(0, |p| p.line() as usize),
            1,
            "",
            "the row is not UTF-8 text",
        ),
        _ => ExchangeError::file(file, e.to_string()),
    }
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
                    right[i], left[i]
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
                    x[i],
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
                    b.unwrap_or(f64::NAN),
                    a.unwrap_or(f64::NAN),
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
mod tests {
    use super::*;

    fn read(text: &str) -> Result<CaseFile, ExchangeError> {
        read_case("d/c.csv", "c", text, Want::Results)
    }

    #[test]
    fn element_profiles_are_grouped_by_time_and_sorted_by_position() {
        let f = read("t,x_left,x_right,stress\n0.5,0.5,1,2\n0.5,0,0.5,1\n1.5,0,1,3\n").unwrap();
        let CaseData::Profiles(p) = f.data else {
            panic!()
        };
        assert_eq!(p.len(), 2);
        assert_eq!(p[0].time, 0.5);
        assert_eq!(p[0].stress, vec![1.0, 2.0]);
        assert_eq!(p[0].lines, vec![3, 2], "lines follow the sorted rows");
        assert_eq!(
            p[1].positions,
            Positions::Elements {
                left: vec![0.0],
                right: vec![1.0]
            }
        );
    }

    #[test]
    fn bad_cells_and_geometry_name_line_and_column() {
        let e = read("t,x_left,x_right,stress\n0.5,0,0.5,abc\n").unwrap_err();
        assert_eq!((e.line, e.column, e.key.as_str()), (2, 4, "stress"), "{e}");
        let e = read("t,x_left,x_right,stress\n0.5,0,0.5,inf\n").unwrap_err();
        assert!(e.message.contains("not finite"), "{e}");
        let e = read("t,x_left,x_right,stress\n0.5,0,0.5,1\n0.4,0,0.5,1\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (3, "t"), "{e}");
        let e = read("t,x_left,x_right,stress\n0.5,0,0.6,1\n0.5,0.5,1,1\n").unwrap_err();
        assert!(e.message.contains("overlaps itself"), "{e}");
        let e = read("t,x_left,x_right,stress\n0.5,0,0.4,1\n0.5,0.5,1,1\n").unwrap_err();
        assert!(e.message.contains("does not cover the bar"), "{e}");
        let e = read("t,x,stress\n0.5,0.2,1\n0.5,0.2,1\n").unwrap_err();
        assert!(e.message.contains("overlap"), "{e}");
        let e = read("t,x,stress\n0.5,0.2\n").unwrap_err();
        assert_eq!(e.line, 2, "{e}");
        let e = read("t,x,stress\n").unwrap_err();
        assert!(e.message.contains("no rows"), "{e}");
        let e = read("t,force\n0,1\n0,2\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (3, "t"), "{e}");
        let e = read("mode,omega\n1.5,2\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (2, "mode"), "{e}");
    }

    #[test]
    fn queries_need_only_the_keys() {
        let q = read_case("q.csv", "q", "t,x\n0.5,0.1\n0.5,0.2\n", Want::Query).unwrap();
        let CaseData::Profiles(p) = q.data else {
            panic!()
        };
        assert!(p[0].stress.is_empty());
        let q = read_case("q.csv", "q", "t\n0\n1\n", Want::Query).unwrap();
        assert!(matches!(q.data, CaseData::Force(_)));
    }
}
