//! Result sets and query files read from disk: a directory's `*.csv` and `results.toml`
//! ([`read_dir`], or [`read_dir_partial`] keeping what reads), a query file of
//! `courant reference --at` ([`read_query`]). What the files hold is read by `super::reader`.

use super::columns::Want;
use super::error::{ExchangeError, ExchangeErrors};
use super::reader::{META_FILE, read_case};
use super::record::{CaseFile, ExchangeSet};
use super::set::read_set_partial;
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
        if path.is_file() && (name.ends_with(".csv") || name == META_FILE) {
            match std::fs::read_to_string(&path) {
                Ok(text) => files.push((name, text)),
                Err(e) => errors.push(ExchangeError::file(
                    &path.display().to_string(),
                    format!("cannot read: {e}"),
                )),
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
    let text = std::fs::read_to_string(path)
        .map_err(|e| ExchangeError::file(&shown, format!("cannot read: {e}")))?;
    read_case(&shown, "query", &text, Want::Query)
}
