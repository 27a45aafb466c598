//! A result set from its files' contents: every `<case>.csv` read as a case, `results.toml` as
//! its metadata, every error of every file reported at once.

use super::columns::Want;
use super::error::{ExchangeError, ExchangeErrors};
use super::meta::{ResultsMeta, parse};
use super::reader::{META_FILE, read_case_whole};
use super::record::ExchangeSet;

/// Read a result set from in-memory files (`(file name, text)`; `dir` prefixes the names in
/// messages): every `<case>.csv` is a case, `results.toml` its metadata; other files are
/// ignored. Cases are sorted by name.
///
/// # Errors
/// Every bad file in name order (every bad cell of each, up to [`ERRORS_PER_FILE`]); no case
/// file at all; a `results.toml` table naming a case that has no file.
pub fn read_set(
    label: &str,
    dir: &str,
    files: &[(String, String)],
) -> Result<ExchangeSet, ExchangeErrors> {
    match read_set_partial(label, dir, files) {
        (Some(set), errors) if errors.is_empty() => Ok(set),
        (_, errors) => Err(ExchangeErrors(errors)),
    }
}

/// [`read_set`], keeping what reads: the set of the good files (with `results.toml` if it
/// reads; `None` when no case file reads) and every error.
pub fn read_set_partial(
    label: &str,
    dir: &str,
    files: &[(String, String)],
) -> (Option<ExchangeSet>, Vec<ExchangeError>) {
    let path = |name: &str| format!("{}/{name}", dir.trim_end_matches('/'));
    let mut names: Vec<&(String, String)> = files.iter().collect();
    names.sort_by(|a, b| a.0.cmp(&b.0));
    let mut cases = Vec::new();
    let mut errors = Vec::new();
    for (name, text) in &names {
        if let Some(stem) = name.strip_suffix(".csv") {
            match read_case_whole(&path(name), stem, text, Want::Results) {
                Ok(case) => cases.push(case),
                Err(e) => errors.extend(e.0),
            }
        }
    }
    if cases.is_empty() && errors.is_empty() {
        let none = "no case files: a result set holds one <case>.csv per case";
        return (None, vec![ExchangeError::file(dir, none)]);
    }
    let meta: Option<ResultsMeta> = match names.iter().find(|(name, _)| name == META_FILE) {
        None => None,
        Some((name, text)) => match parse(&path(name), text) {
            Ok(meta) => Some(meta),
            Err(e) => {
                errors.push(e);
                None
            }
        },
    };
    if let Some(meta) = &meta {
        // A table for a case whose file failed to read is not reported twice.
        let failed: Vec<String> = errors.iter().map(|e| e.file.clone()).collect();
        for (name, m) in &meta.cases {
            if !cases.iter().any(|c| &c.case == name)
                && !failed.contains(&path(&format!("{name}.csv")))
            {
                errors.push(ExchangeError::at(
                    &meta.file,
                    m.line,
                    1,
                    &format!("cases.\"{name}\""),
                    format!("there is no file {name}.csv in this set"),
                ));
            }
        }
    }
    let set = (!cases.is_empty()).then(|| ExchangeSet {
        label: label.to_string(),
        cases,
        meta,
    });
    (set, errors)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_set_refuses_metadata_for_a_missing_case() {
        let files = vec![
            ("a.csv".to_string(), "t,force\n0,1\n".to_string()),
            (
                "results.toml".to_string(),
                "[cases.b]\ndt = 1.0\n".to_string(),
            ),
        ];
        let e = read_set("d", "d", &files).unwrap_err();
        assert_eq!(
            (e.first().file.as_str(), e.first().line),
            ("d/results.toml", 1),
            "{e}"
        );
        assert!(read_set("d", "d", &files[..1]).is_ok());
    }

    #[test]
    fn a_set_is_read_whole_and_every_bad_file_and_cell_reported() {
        let files = vec![
            (
                "a.csv".to_string(),
                "t,force
0,x
1,y
"
                .to_string(),
            ),
            (
                "b.csv".to_string(),
                "t,force
0,1
0,2
"
                .to_string(),
            ),
            (
                "c.csv".to_string(),
                "t,force
0,1
"
                .to_string(),
            ),
            (
                "results.toml".to_string(),
                "[cases.c]\nsheme = 1\n".to_string(),
            ),
        ];
        let e = read_set("d", "d", &files).unwrap_err();
        let at: Vec<(&str, usize)> = e.0.iter().map(|e| (e.file.as_str(), e.line)).collect();
        assert_eq!(
            at,
            vec![
                ("d/a.csv", 2),
                ("d/a.csv", 3),
                ("d/b.csv", 3),
                ("d/results.toml", 2)
            ],
            "{e}"
        );
        assert!(e.to_string().starts_with("4 errors:"), "{e}");
    }
}
