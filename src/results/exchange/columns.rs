//! The kinds of exchange file and their columns, and how a header is recognised: by its column
//! names, each of which must belong to the format.

use super::error::{ExchangeError, SHOWN};
use crate::io::bounded_read::shortened;

/// The kind of data a file holds, recognised from its columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Stress profiles as element averages: `t, x_left, x_right, stress`.
    Elements,
    /// Stress profiles as point values: `t, x, stress`.
    Points,
    /// A contact force history: `t, force` (+ `penetration`, `gap`).
    Force,
    /// A spectrum: `mode, omega` (+ `mass`).
    Spectrum,
}

/// Whether a file holds results (values required) or is a query of positions and times
/// (`courant reference --at`: values, if present, are ignored).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Want {
    /// A result file: key and value columns.
    Results,
    /// A query file: key columns.
    Query,
}

/// The text column that says which reference produced a value; accepted and ignored on reading.
pub const REFERENCE: &str = "reference";

const KINDS: [Kind; 4] = [Kind::Elements, Kind::Points, Kind::Force, Kind::Spectrum];

impl Kind {
    /// What the kind is, for messages.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Elements => "stress profile (element averages)",
            Kind::Points => "stress profile (point values)",
            Kind::Force => "contact force history",
            Kind::Spectrum => "spectrum",
        }
    }

    /// The columns that locate a value: time and position, or the mode.
    pub fn keys(self) -> &'static [&'static str] {
        match self {
            Kind::Elements => &["t", "x_left", "x_right"],
            Kind::Points => &["t", "x"],
            Kind::Force => &["t"],
            Kind::Spectrum => &["mode"],
        }
    }

    /// The value columns.
    pub fn values(self) -> &'static [&'static str] {
        match self {
            Kind::Elements | Kind::Points => &["stress"],
            Kind::Force => &["force"],
            Kind::Spectrum => &["omega"],
        }
    }

    /// Optional columns.
    pub fn optional(self) -> &'static [&'static str] {
        match self {
            Kind::Force => &["penetration", "gap"],
            Kind::Spectrum => &["mass"],
            _ => &[],
        }
    }

    /// Columns only this kind has: one of them present identifies the kind.
    fn identifying(self) -> &'static [&'static str] {
        match self {
            Kind::Elements => &["x_left", "x_right"],
            Kind::Points => &["x"],
            Kind::Force => &["force", "penetration", "gap"],
            Kind::Spectrum => &["mode", "omega", "mass"],
        }
    }

    /// Every column of the kind.
    pub fn columns(self) -> Vec<&'static str> {
        let mut all = self.keys().to_vec();
        all.extend(self.values());
        all.extend(self.optional());
        all
    }

    /// `t, x_left, x_right, stress` (optional columns in brackets).
    pub fn header(self) -> String {
        let mut text = [self.keys(), self.values()].concat().join(", ");
        for o in self.optional() {
            text += &format!(" [, {o}]");
        }
        text
    }
}

/// Every kind with its header, for messages.
fn kinds_described() -> String {
    KINDS
        .iter()
        .map(|k| format!("{}: {}", k.name(), k.header()))
        .collect::<Vec<_>>()
        .join("; ")
}

/// A recognised header: the kind and the field index of each column present.
#[derive(Debug, Clone, PartialEq)]
pub struct Header {
    /// The kind of file.
    pub kind: Kind,
    /// `(column name, field index)` of every column present (the `reference` column excluded).
    pub fields: Vec<(&'static str, usize)>,
}

impl Header {
    /// Field index of `column`, if present.
    pub fn field(&self, column: &str) -> Option<usize> {
        self.fields
            .iter()
            .find(|(name, _)| *name == column)
            .map(|&(_, i)| i)
    }

    /// Recognise `names` (the header line of `file`). Every name must be a column of the format,
    /// none twice; the names must identify one kind; its key columns (and, for results, its
    /// value columns) must all be present.
    ///
    /// # Errors
    /// An unknown or repeated column (line 1, its field number), a header that matches no kind
    /// or several, a missing column.
    pub fn recognise(file: &str, names: &[String], want: Want) -> Result<Header, ExchangeError> {
        let all: Vec<&'static str> = KINDS.iter().flat_map(|k| k.columns()).collect();
        let mut present: Vec<(&'static str, usize)> = Vec::new();
        for (i, raw) in names.iter().enumerate() {
            let name = raw.trim();
            if name == REFERENCE {
                continue;
            }
            let Some(&known) = all.iter().find(|c| **c == name) else {
                // The nearest known name within two edits, if any (a name far longer than any
                // known one is not compared: the distance would cost its length squared).
                let hint = all
                    .iter()
                    .chain([&REFERENCE])
                    .filter(|c| name.len() <= c.len() + 2)
                    .map(|c| (edit_distance(c, name), c))
                    .filter(|(d, _)| *d <= 2)
                    .min_by_key(|(d, _)| *d)
                    .map(|(_, c)| format!(" (did you mean `{c}`?)"))
                    .unwrap_or_default();
                // A name that could not be a column (other text: a file that is no CSV, such as
                // a linked system file) is described, not echoed.
                let name_like = name
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | ' '));
                let key = if name_like {
                    shortened(name, SHOWN)
                } else {
                    String::new()
                };
                let what = if name_like {
                    format!("unknown column{hint}")
                } else {
                    format!(
                        "field {} of the header line is no column name ({} bytes of other text: is this a result file?)",
                        i + 1,
                        name.len()
                    )
                };
                return Err(ExchangeError::at(
                    file,
                    1,
                    i + 1,
                    &key,
                    format!("{what}; the format's files are {}", kinds_described()),
                ));
            };
            if present.iter().any(|(n, _)| *n == known) {
                return Err(ExchangeError::at(
                    file,
                    1,
                    i + 1,
                    &shortened(name, SHOWN),
                    "the column appears twice",
                ));
            }
            present.push((known, i));
        }
        let has = |c: &str| present.iter().any(|(n, _)| *n == c);
        let identified: Vec<Kind> = KINDS
            .into_iter()
            .filter(|k| k.identifying().iter().any(|c| has(c)))
            .collect();
        let kind = match identified.as_slice() {
            [kind] => *kind,
            // A query of times alone asks for contact forces.
            [] if want == Want::Query && has("t") => Kind::Force,
            _ => {
                let header: Vec<&str> = names.iter().map(|n| n.trim()).collect();
                return Err(ExchangeError::at(
                    file,
                    1,
                    1,
                    "",
                    format!(
                        "the header `{}` matches no case kind; the format's files are {}",
                        header.join(", "),
                        kinds_described()
                    ),
                ));
            }
        };
        let required: Vec<&str> = match want {
            Want::Results => [kind.keys(), kind.values()].concat(),
            Want::Query => kind.keys().to_vec(),
        };
        if let Some(missing) = required.iter().find(|c| !has(c)) {
            return Err(ExchangeError::at(
                file,
                1,
                1,
                missing,
                format!(
                    "missing column: a {} has the columns {}",
                    kind.name(),
                    kind.header()
                ),
            ));
        }
        if let Some(&(stray, i)) = present.iter().find(|(n, _)| !kind.columns().contains(n)) {
            return Err(ExchangeError::at(
                file,
                1,
                i + 1,
                stray,
                format!("not a column of a {} ({})", kind.name(), kind.header()),
            ));
        }
        Ok(Header {
            kind,
            fields: present,
        })
    }
}

/// Levenshtein distance (for "did you mean" hints on misspelt columns).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut previous = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let substitution = previous + usize::from(ca != cb);
            previous = row[j + 1];
            row[j + 1] = substitution.min(row[j] + 1).min(previous + 1);
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(s: &str) -> Vec<String> {
        s.split(',').map(str::to_string).collect()
    }

    #[test]
    fn kinds_are_recognised_by_their_columns_in_any_order() {
        let h = Header::recognise("f", &names("stress, x_right,t,x_left"), Want::Results).unwrap();
        assert_eq!(h.kind, Kind::Elements);
        assert_eq!(h.field("t"), Some(2));
        let h = Header::recognise("f", &names("t,x,stress,reference"), Want::Results).unwrap();
        assert_eq!(h.kind, Kind::Points);
        let h = Header::recognise("f", &names("t,force,gap"), Want::Results).unwrap();
        assert_eq!(h.kind, Kind::Force);
        let h = Header::recognise("f", &names("t"), Want::Query).unwrap();
        assert_eq!(h.kind, Kind::Force);
        let h = Header::recognise("f", &names("mode,omega,mass"), Want::Results).unwrap();
        assert_eq!(h.kind, Kind::Spectrum);
    }

    #[test]
    fn bad_headers_name_the_column_and_the_rule() {
        let e =
            Header::recognise("f", &names("t,x_left,x_right,stres"), Want::Results).unwrap_err();
        assert_eq!((e.line, e.column, e.key.as_str()), (1, 4, "stres"));
        assert!(e.message.contains("did you mean `stress`?"), "{e}");
        let e = Header::recognise("f", &names("t,x_left,stress"), Want::Results).unwrap_err();
        assert_eq!(e.key, "x_right");
        let e = Header::recognise("f", &names("t,stress"), Want::Results).unwrap_err();
        assert!(e.message.contains("matches no case kind"), "{e}");
        let e = Header::recognise("f", &names("t,x,force"), Want::Results).unwrap_err();
        assert!(e.message.contains("matches no case kind"), "{e}");
        let e = Header::recognise("f", &names("t,x,stress,x"), Want::Results).unwrap_err();
        assert_eq!(
            (e.column, e.message.as_str()),
            (4, "the column appears twice")
        );
        let e = Header::recognise("f", &names("mode,omega,stress"), Want::Results).unwrap_err();
        assert_eq!((e.column, e.key.as_str()), (3, "stress"));
    }
}
