//! Case names: built from the scene's values (`co0.5`, `cd-penalty-bs2500`, `amm0.25-co1`),
//! they become file names (`<case>.csv`, `<case>.history.csv`), so they are bounded and safe
//! before anything runs.

use super::error::{SceneError, Source};
use std::ops::Range;

/// Longest case name, in bytes (file names add at most 12 bytes, `.history.csv`; file systems
/// allow 255).
pub const MAX_CASE_NAME: usize = 100;

/// Longest plain decimal label of a number; longer ones are written in scientific form.
const PLAIN_LABEL: usize = 12;

/// The label of a number in a case name: its shortest round-trip decimal form when that has at
/// most 12 characters (`0.5`, `2500`, `100000000`: every name of the built-in scenes), else the
/// scientific form (`1e300` rather than a 301-digit integer, `1e-40` rather than 42 characters).
pub fn number(x: f64) -> String {
    let plain = format!("{x}");
    if plain.len() <= PLAIN_LABEL {
        plain
    } else {
        format!("{x:e}")
    }
}

/// True for a character a case name may hold.
fn allowed(c: char) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-' | '+')
}

/// Every name at most [`MAX_CASE_NAME`] bytes of `A-Z a-z 0-9 . _ - +`, not starting with `.`
/// or `-` (a hidden file, an option), else the error at `span`/`key` naming the case.
pub fn check(
    src: &Source,
    span: Option<Range<usize>>,
    key: &str,
    names: &[String],
) -> Result<(), SceneError> {
    for name in names {
        let problem = if name.len() > MAX_CASE_NAME {
            Some(format!(
                "is {} bytes long, more than the {MAX_CASE_NAME} a case name (a file name) may have",
                name.len()
            ))
        } else if name.is_empty() || name.starts_with(['.', '-']) {
            Some("must not be empty or start with `.` or `-`".to_string())
        } else {
            name.chars().find(|&c| !allowed(c)).map(|c| {
                format!("holds {c:?}; case names (file names) use only letters, digits and . _ - +")
            })
        };
        if let Some(problem) = problem {
            let shown: String = name.chars().take(60).collect();
            return Err(src.error(
                span,
                key,
                format!(
                    "case name \"{shown}\"{} {problem}",
                    if shown.len() < name.len() { "..." } else { "" }
                ),
            ));
        }
    }
    Ok(())
}

/// The name of `names` nearest to `arg` by edit distance, if it is close: at most 2 edits, and
/// fewer than half of `arg`'s characters.
pub fn closest<'a>(arg: &str, names: &[&'a str]) -> Option<&'a str> {
    let arg = arg.to_lowercase();
    names
        .iter()
        .map(|n| (edit_distance(&arg, n), *n))
        .filter(|&(d, _)| d <= 2 && 2 * d < arg.chars().count())
        .min_by_key(|&(d, _)| d)
        .map(|(_, n)| n)
}

/// Levenshtein distance between two strings (insertions, deletions, substitutions).
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut previous: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut current = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let substitution = previous[j] + usize::from(ca != *cb);
            current.push(substitution.min(previous[j + 1] + 1).min(current[j] + 1));
        }
        previous = current;
    }
    previous[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_stay_short_and_keep_the_built_in_names() {
        assert_eq!(number(0.5), "0.5");
        assert_eq!(number(1.0), "1");
        assert_eq!(number(25_000_000.0), "25000000");
        assert_eq!(number(1e8), "100000000");
        assert_eq!(number(1e300), "1e300");
        assert_eq!(number(1e-300), "1e-300");
        assert_eq!(number(0.123_456_789_012_345_6), "1.234567890123456e-1");
    }

    #[test]
    fn long_or_unsafe_names_are_refused() {
        let src = Source {
            file: "s.toml",
            text: "",
            limits: Default::default(),
        };
        let ok = ["co0.5".to_string(), "cd-penalty-bs1e300".to_string()];
        check(&src, None, "k", &ok).unwrap();
        for bad in [
            "x".repeat(101),
            ".hidden".into(),
            "a/b".into(),
            String::new(),
        ] {
            assert!(
                check(&src, None, "k", std::slice::from_ref(&bad)).is_err(),
                "{bad}"
            );
        }
    }
}
