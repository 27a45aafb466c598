//! Errors of exchange files: every one names the file, the line, the column and the key (a CSV
//! column name or a `results.toml` key), and the rule broken.

use thiserror::Error;

/// An exchange file that cannot be used, with the position of the offending cell or key.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{file}:{line}:{column}: {}{message}", key_prefix(.key))]
pub struct ExchangeError {
    /// Path of the file.
    pub file: String,
    /// 1-based line (0 when the file itself is missing or unreadable).
    pub line: usize,
    /// 1-based column: the CSV field number, or the character column in `results.toml`.
    pub column: usize,
    /// The CSV column name or the dotted `results.toml` key (empty for the whole file).
    pub key: String,
    /// What is wrong, naming the value and the rule.
    pub message: String,
}

fn key_prefix(key: &str) -> String {
    if key.is_empty() {
        String::new()
    } else {
        format!("`{key}`: ")
    }
}

impl ExchangeError {
    /// An error at `line`, `column` of `file` for `key`.
    pub fn at(
        file: &str,
        line: usize,
        column: usize,
        key: &str,
        message: impl Into<String>,
    ) -> Self {
        Self {
            file: file.to_string(),
            line,
            column,
            key: key.to_string(),
            message: message.into(),
        }
    }

    /// An error about the whole file.
    pub fn file(file: &str, message: impl Into<String>) -> Self {
        Self::at(file, 0, 0, "", message)
    }
}

/// Every error of a result set, in file order: a set is read whole and all of them reported at
/// once, so that one run shows everything to fix.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{}", render(.0))]
pub struct ExchangeErrors(pub Vec<ExchangeError>);

/// At most this many characters of a value or name are echoed in a message (the rest are
/// counted).
pub const SHOWN: usize = 40;

/// `x` for a message: as Rust writes it, or in exponent form when that would take more than a
/// dozen digits (`1e308` rather than 309 of them, `5e-324` rather than 324 zeros).
pub fn short_number(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-4..1e6).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// At most this many errors of one file are reported (the rest are counted).
pub const ERRORS_PER_FILE: usize = 20;

fn render(errors: &[ExchangeError]) -> String {
    match errors {
        [one] => one.to_string(),
        many => {
            let lines: Vec<String> = many.iter().map(ToString::to_string).collect();
            format!("{} errors:\n  {}", many.len(), lines.join("\n  "))
        }
    }
}

impl From<ExchangeError> for ExchangeErrors {
    fn from(e: ExchangeError) -> Self {
        Self(vec![e])
    }
}

impl ExchangeErrors {
    /// The first error (in file order).
    pub fn first(&self) -> &ExchangeError {
        &self.0[0]
    }
}

/// 1-based (line, column) of a byte offset of `text`.
pub fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before
        .rfind('\n')
        .map_or(before.len(), |i| before.len() - i - 1)
        + 1;
    (line, column)
}

/// The first line with an unterminated quote (an odd number of `"`): the CSV reader would
/// swallow the rest of the file into one cell, and the damage would surface far away (e.g. as a
/// gap in the mesh), so it is named at its line.
pub fn unterminated_quote(file: &str, text: &str) -> Option<ExchangeError> {
    let (i, line) = text
        .lines()
        .enumerate()
        .find(|(_, l)| l.matches('"').count() % 2 == 1)?;
    let column = line[..line.find('"').unwrap_or(0)].matches(',').count() + 1;
    Some(ExchangeError::at(
        file,
        i + 1,
        column,
        "",
        "an unterminated quote (`\"`): cells of this format are not quoted across lines",
    ))
}

/// A CSV reader's error, located.
pub fn csv_error(file: &str, e: &csv::Error) -> ExchangeError {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_message_names_file_line_column_and_key() {
        let e = ExchangeError::at("r/co1.csv", 3, 4, "stress", "`x` is not a number");
        assert_eq!(
            e.to_string(),
            "r/co1.csv:3:4: `stress`: `x` is not a number"
        );
        assert_eq!(line_column("a\nbc\nd", 4), (2, 3));
    }

    #[test]
    fn numbers_in_messages_are_short() {
        assert_eq!(short_number(1e308), "1e308");
        assert_eq!(short_number(5e-324), "5e-324");
        assert_eq!(short_number(0.25), "0.25");
        assert_eq!(short_number(-12.5), "-12.5");
    }
}
