//! Scene errors: every one names the file, the line and column, the key, and the rule broken.

use std::ops::Range;
use thiserror::Error;
use toml::Spanned;

/// A scene file that cannot be used, with the position of the offending key.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{file}{}: {}{message}{}", position(*.line, *.column), key_prefix(.key), more(.also))]
pub struct SceneError {
    /// Path (or built-in name) of the scene file.
    pub file: String,
    /// 1-based line (0 for an error about the file as a whole: it is not shown then).
    pub line: usize,
    /// 1-based column.
    pub column: usize,
    /// Dotted key, e.g. `material.modulus` (empty when the file does not parse at all).
    pub key: String,
    /// What is wrong, naming the value and the rule.
    pub message: String,
    /// Further errors of the same file found in the same pass (shown on lines of their own).
    pub also: Vec<SceneError>,
}

/// The further errors, one `error: ...` line each.
fn more(also: &[SceneError]) -> String {
    also.iter().map(|e| format!("\nerror: {e}")).collect()
}

/// Every value, or every error (the first with the others attached): independent tables of a
/// file (each `[[expect]]`, each `[[finding]]`) are all checked, not only up to the first bad one.
pub fn collect_all<T>(
    results: impl IntoIterator<Item = Result<T, SceneError>>,
) -> Result<Vec<T>, SceneError> {
    let (mut values, mut errors) = (Vec::new(), Vec::new());
    for r in results {
        match r {
            Ok(v) => values.push(v),
            Err(e) => errors.push(e),
        }
    }
    match SceneError::all(errors) {
        None => Ok(values),
        Some(e) => Err(e),
    }
}

impl SceneError {
    /// The first error with the others attached, or `None` for no error.
    pub fn all(mut errors: Vec<SceneError>) -> Option<SceneError> {
        if errors.is_empty() {
            return None;
        }
        let mut first = errors.remove(0);
        first.also.extend(errors);
        Some(first)
    }
}

/// A value as an error echoes it: at most 40 characters, then how many more bytes.
fn echo(value: &str) -> String {
    match value.char_indices().nth(40) {
        None => value.to_string(),
        Some((cut, _)) => format!("{}… ({} more bytes)", &value[..cut], value.len() - cut),
    }
}

/// toml's "unknown field `X`, expected one of `a`, `b`" with the nearest known field named
/// first: "unknown field `profile_tims` (did you mean `profile_times`?), expected one of ...".
fn with_suggestion(message: &str) -> String {
    let Some(rest) = message.strip_prefix("unknown field `") else {
        return message.to_string();
    };
    let Some((field, expected)) = rest.split_once('`') else {
        return message.to_string();
    };
    let known: Vec<&str> = expected.split('`').skip(1).step_by(2).collect();
    match super::spelling::closest(field, &known) {
        Some(near) => format!("unknown field `{field}` (did you mean `{near}`?){expected}"),
        None => message.to_string(),
    }
}

/// `:line:column`, or nothing for an error that has no place in a file (line 0).
fn position(line: usize, column: usize) -> String {
    if line == 0 {
        String::new()
    } else {
        format!(":{line}:{column}")
    }
}

fn key_prefix(key: &str) -> String {
    if key.is_empty() {
        String::new()
    } else {
        format!("`{key}`: ")
    }
}

/// Source text of a scene file with the helpers that turn byte spans into positions.
#[derive(Debug, Clone)]
pub struct Source<'a> {
    /// Path or name shown in errors.
    pub file: &'a str,
    /// The TOML text.
    pub text: &'a str,
    /// The limits it is validated against.
    pub limits: super::limits::Limits,
}

impl Source<'_> {
    /// An error at `span` for `key`.
    pub fn error(
        &self,
        span: Option<Range<usize>>,
        key: &str,
        message: impl Into<String>,
    ) -> SceneError {
        let (line, column) = span
            .map(|s| self.position(s.start))
            .or_else(|| self.table_header(key))
            .unwrap_or((1, 1));
        SceneError {
            file: self.file.to_string(),
            line,
            column,
            key: key.to_string(),
            message: message.into(),
            also: Vec::new(),
        }
    }

    /// The (line, 1) of the header of the table `key` is in (`[material]` for `material` or
    /// `material.modulus`, the first `[[expect]]` for `expect`): where an error about a key
    /// that is missing from the table points, rather than the file's first line.
    fn table_header(&self, key: &str) -> Option<(usize, usize)> {
        let table = key.split(['.', '[']).next().filter(|t| !t.is_empty())?;
        self.text.lines().enumerate().find_map(|(i, line)| {
            let name = line
                .trim()
                .trim_start_matches('[')
                .split([']', '.'])
                .next()?
                .trim()
                .trim_matches('"');
            (line.trim_start().starts_with('[') && name == table).then_some((i + 1, 1))
        })
    }

    /// Convert a TOML deserialisation error, recovering the dotted key from the text at its span.
    pub fn from_toml(&self, err: &toml::de::Error) -> SceneError {
        let mut key = err.span().map(|s| self.key_at(s.start)).unwrap_or_default();
        // A missing key is named by the message; at the top level the span is the whole file,
        // whose first line may be a comment, not a key.
        if let Some(field) = err
            .message()
            .strip_prefix("missing field `")
            .and_then(|m| m.split('`').next())
        {
            // toml gives an empty span at 0 for a key missing at the top level.
            let top_level = err.span().is_none_or(|s| s.is_empty() && s.start == 0);
            if top_level {
                return SceneError {
                    file: self.file.to_string(),
                    line: 0,
                    column: 0,
                    key: field.to_string(),
                    message: format!(
                        "missing: the file has no `[{field}]` table, which every scene of this kind needs"
                    ),
                    also: Vec::new(),
                };
            }
            key = if key.is_empty() {
                field.to_string()
            } else {
                format!("{key}.{field}")
            };
        }
        let message = err
            .message()
            .trim()
            .replace('\n', "; ")
            .replace(
                "data did not match any variant of untagged enum RawField",
                "expected a number or `{ linear = [left, right] }`",
            )
            .replace(
                "data did not match any variant of untagged enum OneOrManyInts",
                "expected a whole number or a list of whole numbers",
            )
            .replace(
                "data did not match any variant of untagged enum OneOrManyStrings",
                "expected a string or a list of strings",
            )
            .replace(
                "data did not match any variant of untagged enum OneOrMany",
                "expected a positive number or a list of positive numbers",
            );
        let message = with_suggestion(&message);
        // The value given, when the message does not show it already (`elements = "100"`:
        // `"100"`), so every rule broken is seen beside what broke it.
        let given = err
            .span()
            .filter(|s| !s.is_empty() && s.end <= self.text.len())
            .and_then(|s| self.text.get(s))
            .map(str::trim)
            .filter(|v| !v.is_empty() && !v.contains('\n') && !message.contains(*v));
        let message = match given {
            Some(v) if !message.starts_with("unknown field") => {
                format!("{}: {message}", echo(v))
            }
            _ => message,
        };
        self.error(err.span(), &key, message)
    }

    /// The span of the value of `key = value` on a line of its own in the table that starts
    /// at `table` (a table's span: its header, for an array of tables), up to the next table
    /// header, for keys deserialised without a span of their own; `table` when there is none.
    pub fn value_span(&self, table: Range<usize>, key: &str) -> Range<usize> {
        let start = table.start.min(self.text.len());
        let mut offset = start;
        for (i, line) in self.text[start..].split_inclusive('\n').enumerate() {
            let trimmed = line.trim_start();
            if i > 0 && trimmed.starts_with('[') {
                break;
            }
            if let Some(rest) = trimmed.strip_prefix(key)
                && let Some(value) = rest.trim_start().strip_prefix('=')
            {
                let start = offset + (line.len() - value.trim_start().len());
                return start..start + value.trim().len();
            }
            offset += line.len();
        }
        table
    }

    /// 1-based (line, column) of a byte offset.
    pub fn position(&self, offset: usize) -> (usize, usize) {
        let before = &self.text[..offset.min(self.text.len())];
        let line = before.matches('\n').count() + 1;
        let column = before
            .rfind('\n')
            .map_or(before.len(), |i| before.len() - i - 1)
            + 1;
        (line, column)
    }

    /// The dotted key whose line holds `offset`: the table header above it plus the text before
    /// `=` on that line (or the header itself when the offset is on a header line).
    pub fn key_at(&self, offset: usize) -> String {
        let offset = offset.min(self.text.len());
        let line_start = self.text[..offset].rfind('\n').map_or(0, |i| i + 1);
        let line_end = self.text[offset..]
            .find('\n')
            .map_or(self.text.len(), |i| offset + i);
        let line = self.text[line_start..line_end].trim();
        let header = |l: &str| {
            l.starts_with('[')
                .then(|| l.trim_matches(|c| c == '[' || c == ']').trim().to_string())
        };
        if let Some(h) = header(line) {
            return h;
        }
        if line.starts_with('#') {
            return String::new();
        }
        let table = self.text[..line_start]
            .lines()
            .rev()
            .find_map(|l| header(l.trim()));
        let local = line.split('=').next().unwrap_or("").trim();
        match (table, local.is_empty()) {
            (Some(t), false) => format!("{t}.{local}"),
            (Some(t), true) => t,
            (None, _) => local.to_string(),
        }
    }
}

/// A number that must be positive and finite, or the error naming `key` at the value's span.
pub fn positive(src: &Source, v: &Spanned<f64>, key: &str) -> Result<f64, SceneError> {
    let x = *v.get_ref();
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(src.error(
            Some(v.span()),
            key,
            format!("{x} must be positive and finite"),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn key_and_position_come_from_the_text() {
        let text = "[scene]\ndescription = \"x\"\n\n[material]\nmodulus = -1\n";
        let src = Source {
            file: "a.toml",
            text,
            limits: Default::default(),
        };
        let offset = text.find("-1").unwrap();
        assert_eq!(src.position(offset), (5, 11));
        assert_eq!(src.key_at(offset), "material.modulus");
        let e = src.error(
            Some(offset..offset + 2),
            "material.modulus",
            "must be positive",
        );
        assert_eq!(
            e.to_string(),
            "a.toml:5:11: `material.modulus`: must be positive"
        );
    }
}
