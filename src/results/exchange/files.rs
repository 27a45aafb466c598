//! Reading result sets and query files from disk: which files of a directory are read (and
//! which are named rather than skipped in silence), each read through
//! [`crate::io::bounded_read`] (regular files only, sizes and lines capped), then parsed by
//! [`super::reader`].

use super::columns::Want;
use super::error::{ExchangeError, ExchangeErrors};
use super::reader::{META_FILE, read_case};
use super::record::{CaseFile, ExchangeSet};
use super::set::read_set_partial;
use crate::io::bounded_read::{DATA_CAP, TEXT_CAP, read_text};
use std::path::Path;

/// Read a result set from a directory (its `*.csv` and `results.toml`; subdirectories and other
/// files are ignored), labelled by the path as given.
///
/// # Errors
/// The directory cannot be read, or as [`read_set`].
pub fn read_dir(dir: &Path) -> Result<ExchangeSet, ExchangeErrors> {
    match read_dir_partial(dir) {
        (Some(set), errors) if errors.is_empty() => Ok(set),
        (_, errors) => Err(ExchangeErrors(errors)),
    }
}

/// [`read_dir`], keeping what reads (as [`read_set_partial`]).
pub fn read_dir_partial(dir: &Path) -> (Option<ExchangeSet>, Vec<ExchangeError>) {
    let shown = dir.display().to_string();
    let unreadable = |e: std::io::Error| {
        ExchangeError::file(&shown, format!("cannot read the results directory: {e}"))
    };
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) => return (None, vec![unreadable(e)]),
    };
    let mut files = Vec::new();
    let mut errors = Vec::new();
    for entry in entries {
        let path = match entry {
            Ok(entry) => entry.path(),
            Err(e) => {
                errors.push(unreadable(e));
                continue;
            }
        };
        let Some(name) = path
            .file_name()
            .and_then(|n| n.to_str())
            .map(str::to_string)
        else {
            continue;
        };
        let lower = name.to_ascii_lowercase();
        let wanted = name.ends_with(".csv") || name == META_FILE;
        if !wanted {
            // A file meant for the set under a name the format does not know is named, not
            // skipped in silence.
            if lower.ends_with(".csv") || lower == META_FILE {
                errors.push(ExchangeError::file(
                    &path.display().to_string(),
                    format!(
                        "not read: names are case-sensitive (`{}` expected)",
                        if lower == META_FILE {
                            META_FILE.to_string()
                        } else {
                            format!("{}.csv", &name[..name.len() - 4])
                        }
                    ),
                ));
            }
            continue;
        }
        let cap = if name == META_FILE {
            TEXT_CAP
        } else {
            DATA_CAP
        };
        match read_text(&path, cap) {
            Ok(text) => files.push((name, text)),
            Err(e) => {
                let (line, column) = e.location();
                errors.push(ExchangeError::at(
                    &path.display().to_string(),
                    line,
                    column,
                    "",
                    e.to_string(),
                ));
            }
        }
    }
    let (set, mut more) = read_set_partial(&shown, &shown, &files);
    if set.is_none() && !errors.is_empty() {
        // "no case files" says nothing when the files are there but unreadable.
        more.retain(|e| e.file != shown);
    }
    errors.extend(more);
    (set, errors)
}

/// Read a query file (`courant reference --at`): the positions and times (or modes) of one
/// kind; value columns, if present, are ignored.
///
/// # Errors
/// The file cannot be read, or as [`read_case`].
pub fn read_query(path: &Path) -> Result<CaseFile, ExchangeError> {
    let shown = path.display().to_string();
    let text = read_text(path, DATA_CAP).map_err(|e| {
        let (line, column) = e.location();
        ExchangeError::at(&shown, line, column, "", e.to_string())
    })?;
    read_case(&shown, "query", &text, Want::Query)
}
