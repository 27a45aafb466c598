//! Named tables rendered as CSV, at full (round-trip) precision for result files or rounded to
//! fixed significant digits for snapshots.

/// One cell.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A real number.
    Num(f64),
    /// An integer (printed exactly at every precision).
    Int(u64),
    /// Text.
    Text(String),
    /// No value (e.g. no reference).
    Empty,
}

impl From<f64> for Cell {
    fn from(x: f64) -> Self {
        Cell::Num(x)
    }
}

impl From<usize> for Cell {
    fn from(x: usize) -> Self {
        Cell::Int(x as u64)
    }
}

impl From<&str> for Cell {
    fn from(s: &str) -> Self {
        Cell::Text(s.to_string())
    }
}

impl From<String> for Cell {
    fn from(s: String) -> Self {
        Cell::Text(s)
    }
}

impl<T: Into<Cell>> From<Option<T>> for Cell {
    fn from(x: Option<T>) -> Self {
        x.map_or(Cell::Empty, Into::into)
    }
}

/// How numbers are printed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Precision {
    /// Shortest representation that reads back to the same f64 (scientific below 1e-5 and
    /// from 1e16 on).
    RoundTrip,
    /// `digits` significant digits; magnitudes below `floor` print as 0 (round-off noise such as
    /// a 1e-16 error must not make a snapshot platform-dependent).
    Significant {
        /// Significant digits.
        digits: usize,
        /// Absolute floor.
        floor: f64,
    },
}

impl Precision {
    /// The snapshot convention: 6 significant digits, values below 1e-10 are 0.
    pub const SNAPSHOT: Precision = Precision::Significant {
        digits: 6,
        floor: 1e-10,
    };

    /// Format one number.
    pub fn format(self, x: f64) -> String {
        match self {
            Precision::RoundTrip
                if x == 0.0 || !x.is_finite() || (1e-5..1e16).contains(&x.abs()) =>
            {
                format!("{x}")
            }
            Precision::RoundTrip => format!("{x:e}"),
            Precision::Significant { digits, floor } => significant(x, digits, floor),
        }
    }
}

fn significant(x: f64, digits: usize, floor: f64) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x.abs() < floor || x == 0.0 {
        return "0".to_string();
    }
    let digits = digits.max(1);
    // Correct rounding first, in scientific form; then choose the layout from the exponent.
    let sci = format!("{:.*e}", digits - 1, x);
    let exponent: i32 = sci
        .split('e')
        .nth(1)
        .and_then(|e| e.parse().ok())
        .unwrap_or(0);
    if (-4..6).contains(&exponent) {
        let rounded: f64 = sci.parse().unwrap_or(x);
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        format!("{rounded:.decimals$}")
    } else {
        sci
    }
}

/// A table with named columns.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Column names.
    pub columns: Vec<String>,
    /// Rows, each as long as `columns`.
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    /// An empty table with these columns.
    pub fn new(columns: &[&str]) -> Self {
        Self {
            columns: columns.iter().map(|c| c.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// Append a row.
    pub fn push(&mut self, row: Vec<Cell>) {
        debug_assert_eq!(
            row.len(),
            self.columns.len(),
            "row length must match the columns"
        );
        self.rows.push(row);
    }

    /// Render as CSV with a header row.
    pub fn to_csv(&self, precision: Precision) -> String {
        csv_text(&self.columns, self.rows.iter().cloned(), precision)
    }
}

/// CSV with a header row from `columns` and rows produced one at a time (so a table of
/// millions of rows need not be held as cells: only its text is), rendered as
/// [`Table::to_csv`] renders the same rows.
pub fn csv_text<C: AsRef<str>>(
    columns: &[C],
    rows: impl Iterator<Item = Vec<Cell>>,
    precision: Precision,
) -> String {
    let mut text = Vec::new();
    write_csv(&mut text, columns, rows, precision).expect("writing CSV to memory cannot fail");
    String::from_utf8(text).expect("CSV of UTF-8 fields is UTF-8")
}

/// [`csv_text`] written into `out` row by row, never held whole (`courant run` streams a
/// profile file of 10^7 rows into its staged file this way): the same bytes.
///
/// # Errors
/// Any I/O error of `out`.
pub fn write_csv<C: AsRef<str>>(
    out: &mut dyn std::io::Write,
    columns: &[C],
    rows: impl Iterator<Item = Vec<Cell>>,
    precision: Precision,
) -> std::io::Result<()> {
    let mut writer = csv::Writer::from_writer(out);
    writer.write_record(columns.iter().map(|c| c.as_ref()))?;
    let mut fields = Vec::new();
    for row in rows {
        fields.clear();
        fields.extend(row.into_iter().map(|c| match c {
            Cell::Num(x) => precision.format(x),
            Cell::Int(i) => i.to_string(),
            Cell::Text(s) => s,
            Cell::Empty => String::new(),
        }));
        writer.write_record(&fields)?;
    }
    writer.flush()
}

impl Table {
    /// Render as a Markdown table (numbers at `precision`; empty cells as `-`).
    pub fn to_markdown(&self, precision: Precision) -> String {
        let mut out = String::new();
        out += &format!("| {} |\n", self.columns.join(" | "));
        out += &format!("|{}\n", "---|".repeat(self.columns.len()));
        for row in &self.rows {
            let cells: Vec<String> = row
                .iter()
                .map(|c| match c {
                    Cell::Num(x) => precision.format(*x),
                    Cell::Int(i) => i.to_string(),
                    Cell::Text(s) => s.replace('|', "\\|"),
                    Cell::Empty => "-".to_string(),
                })
                .collect();
            out += &format!("| {} |\n", cells.join(" | "));
        }
        out
    }

    /// A copy without the named columns (e.g. timings, kept out of deterministic content).
    pub fn without(&self, drop: &[&str]) -> Table {
        let keep: Vec<usize> = (0..self.columns.len())
            .filter(|&i| !drop.contains(&self.columns[i].as_str()))
            .collect();
        Table {
            columns: keep.iter().map(|&i| self.columns[i].clone()).collect(),
            rows: self
                .rows
                .iter()
                .map(|r| keep.iter().map(|&i| r[i].clone()).collect())
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits_round_correctly_and_floor_noise() {
        let p = Precision::SNAPSHOT;
        assert_eq!(p.format(-0.9999996), "-1.00000");
        assert_eq!(p.format(0.5), "0.500000");
        assert_eq!(p.format(1.2743210), "1.27432");
        assert_eq!(p.format(3.4e-14), "0");
        assert_eq!(p.format(-1.2e-7), "-1.20000e-7");
        assert_eq!(p.format(123456789.0), "1.23457e8");
        assert_eq!(p.format(0.0), "0");
    }

    #[test]
    fn round_trip_precision_reads_back_exactly() {
        let x = 0.1 + 0.2;
        for x in [x, 2.6867397195928788e-14, -1.5e20, 123.0] {
            assert_eq!(Precision::RoundTrip.format(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(Precision::RoundTrip.format(2.5e-14), "2.5e-14");
    }

    #[test]
    fn markdown_has_a_header_rule_and_dashes_for_empty_cells() {
        let mut t = Table::new(&["a", "b", "wall_time_s"]);
        t.push(vec![Cell::Num(0.123456789), Cell::Empty, Cell::Num(1.0)]);
        let md = t
            .without(&["wall_time_s"])
            .to_markdown(Precision::Significant {
                digits: 4,
                floor: 1e-14,
            });
        assert_eq!(md, "| a | b |\n|---|---|\n| 0.1235 | - |\n");
    }

    #[test]
    fn csv_has_a_header_and_empty_cells() {
        let mut t = Table::new(&["a", "b"]);
        t.push(vec![Cell::Int(3), Cell::Empty]);
        assert_eq!(t.to_csv(Precision::RoundTrip), "a,b\n3,\n");
    }
}
