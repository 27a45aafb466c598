//! The mark of a courant output directory, and the rule for replacing one.
//!
//! Every directory courant writes whole ([`super::atomic::write_dir_atomically`]) carries a
//! manifest, [`MANIFEST`], listing every file written with it (relative paths, sorted, one a
//! line; no sizes or dates, so two writes of the same content are identical files). A directory
//! is replaced only when it is
//!
//! - absent, or empty, or
//! - a courant output: it holds the manifest and nothing the manifest does not list (a file a
//!   user added to an output directory would be lost with it, so it makes the directory foreign).
//!
//! Anything else (a user's directory, a file, a symbolic link, `.` or `/`) is refused with a
//! [`Refusal`] naming the path and the first entry courant did not write, and nothing is
//! touched. Outputs written before courant marked them have no manifest and are refused too:
//! remove them by hand once.
//!
//! The manifest also names the command that wrote the directory (`# written by: courant run`)
//! when the command set it ([`set_writer`]). `run` writes a scene's profiles, histories and
//! energy logs; `reference` and `score --out` write a handful of exchange files or tables to the
//! same `DIR/<scene>`: one command's output is not replaced by another's unless it was told to
//! (`--force`), and the refusal says what is there.

use super::bounded_read::{ReadError, TEXT_CAP, read_text};
use super::file_kind::kind_of;
use std::collections::BTreeSet;
use std::io;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// File name of the manifest inside every directory courant writes whole.
pub const MANIFEST: &str = ".courant-manifest";

/// First line of every manifest: what the directory is.
const HEADER: &str = "# courant output: written whole by courant; its next write replaces the whole directory. Files written:";

/// Start of the manifest line naming the command that wrote the directory.
const WRITER_PREFIX: &str = "# written by: ";

/// The command of this process and whether it may replace another command's output.
static WRITER: std::sync::OnceLock<(&'static str, bool)> = std::sync::OnceLock::new();

/// Name the command of this process (e.g. "courant run") in the manifests it writes, and let it
/// replace another command's output only with `force`. Set once, at start-up; later calls are
/// ignored.
pub fn set_writer(command: &'static str, force: bool) {
    let _ = WRITER.set((command, force));
}

/// Why a directory may not be replaced.
#[derive(Debug, Error)]
pub enum Refusal {
    /// The path exists and is not a directory (a file, a symbolic link, a device, a FIFO).
    #[error(
        "{}: is a {what}, not a directory courant wrote; nothing was written (choose another output directory)",
        .path.display()
    )]
    NotADirectory {
        /// The path.
        path: PathBuf,
        /// What it is instead.
        what: &'static str,
    },
    /// The path has no last component to replace (`.`, `..`, `/`).
    #[error(
        "{}: names no directory courant could replace (give a directory name such as `results`)",
        .0.display()
    )]
    NoName(PathBuf),
    /// The directory holds an entry courant did not write.
    #[error(
        "{}: refusing to replace it: it holds `{entry}`, which courant did not write ({why}); courant replaces only an empty directory or one it wrote itself (with its {MANIFEST}). Nothing was written: choose another output directory, or move the files away",
        .dir.display()
    )]
    Foreign {
        /// The directory.
        dir: PathBuf,
        /// The first foreign entry, relative to `dir`.
        entry: String,
        /// Whether the directory has no manifest at all or the entry is not listed in it.
        why: &'static str,
    },
    /// Another command's output (its manifest names it).
    #[error(
        "{}: holds the output of `{by}` ({files} files); `{this}` would replace it with its own. Nothing was written: choose another output directory, or give --force to replace it",
        .dir.display()
    )]
    OtherCommand {
        /// The directory.
        dir: PathBuf,
        /// The command that wrote it.
        by: String,
        /// How many files it holds.
        files: usize,
        /// The command that would replace it.
        this: &'static str,
    },
    /// The directory cannot be read.
    #[error("{}: cannot read it to check what it holds: {source}", .path.display())]
    Unreadable {
        /// The path.
        path: PathBuf,
        /// The I/O error.
        source: io::Error,
    },
}

/// The manifest of a directory holding exactly `files` (relative paths).
pub fn manifest_text<'a>(files: impl IntoIterator<Item = &'a str>) -> String {
    let listed: BTreeSet<&str> = files.into_iter().collect();
    let mut text = String::from(HEADER);
    text.push('\n');
    if let Some((command, _)) = WRITER.get() {
        text.push_str(WRITER_PREFIX);
        text.push_str(command);
        text.push('\n');
    }
    for file in listed {
        text.push_str(file);
        text.push('\n');
    }
    text
}

/// The files a manifest lists.
fn listed(text: &str) -> BTreeSet<String> {
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(str::to_string)
        .collect()
}

/// Whether `dir` may be replaced by a courant write (module docs). Reads only; touches nothing.
///
/// # Errors
/// [`Refusal`] naming the path and, for a foreign directory, the first entry courant did not
/// write.
pub fn check_replaceable(dir: &Path) -> Result<(), Refusal> {
    if dir.file_name().is_none() {
        return Err(Refusal::NoName(dir.to_path_buf()));
    }
    let meta = match std::fs::symlink_metadata(dir) {
        Ok(m) => m,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(()),
        Err(source) => {
            return Err(Refusal::Unreadable {
                path: dir.to_path_buf(),
                source,
            });
        }
    };
    if !meta.is_dir() {
        return Err(Refusal::NotADirectory {
            path: dir.to_path_buf(),
            what: kind_of(&meta),
        });
    }
    let unreadable = |source| Refusal::Unreadable {
        path: dir.to_path_buf(),
        source,
    };
    let manifest = match read_text(&dir.join(MANIFEST), TEXT_CAP) {
        Ok(text) => {
            let by = text.lines().find_map(|l| l.strip_prefix(WRITER_PREFIX));
            if let (Some(by), Some(&(this, false))) = (by, WRITER.get())
                && by != this
            {
                return Err(Refusal::OtherCommand {
                    dir: dir.to_path_buf(),
                    by: by.to_string(),
                    files: listed(&text).len(),
                    this,
                });
            }
            Some(listed(&text))
        }
        Err(ReadError::Missing { dangling: false }) => None,
        Err(ReadError::Io(e)) => return Err(unreadable(e)),
        Err(e) => return Err(unreadable(io::Error::other(format!("{MANIFEST} {e}")))),
    };
    let (allowed, why) = match &manifest {
        Some(files) => (files.clone(), "its manifest does not list it"),
        None => (
            BTreeSet::new(),
            "the directory has no manifest; an output of a courant older than the manifest has none either: remove it by hand once",
        ),
    };
    // Directories that hold listed files are courant's too.
    let parents: BTreeSet<String> = allowed
        .iter()
        .flat_map(|f| {
            f.match_indices('/')
                .map(|(i, _)| f[..i].to_string())
                .collect::<Vec<_>>()
        })
        .collect();
    match first_foreign(dir, "", &allowed, &parents).map_err(unreadable)? {
        None => Ok(()),
        Some(entry) => Err(Refusal::Foreign {
            dir: dir.to_path_buf(),
            entry,
            why,
        }),
    }
}

/// The first entry under `dir` (depth first, sorted) that is neither the manifest, a listed
/// file nor a directory of listed files.
fn first_foreign(
    root: &Path,
    prefix: &str,
    files: &BTreeSet<String>,
    parents: &BTreeSet<String>,
) -> io::Result<Option<String>> {
    let mut entries: Vec<(String, std::fs::FileType)> = std::fs::read_dir(root.join(prefix))?
        .map(|e| e.and_then(|e| Ok((e.file_name().to_string_lossy().into_owned(), e.file_type()?))))
        .collect::<io::Result<_>>()?;
    entries.sort_by(|a, b| a.0.cmp(&b.0));
    for (name, kind) in entries {
        let path = if prefix.is_empty() {
            name.clone()
        } else {
            format!("{prefix}/{name}")
        };
        if kind.is_dir() && parents.contains(&path) {
            if let Some(found) = first_foreign(root, &path, files, parents)? {
                return Ok(Some(found));
            }
        } else if !(kind.is_file() && (files.contains(&path) || path == MANIFEST)) {
            return Ok(Some(path));
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(test: &str) -> PathBuf {
        let base =
            std::env::temp_dir().join(format!("courant-manifest-{test}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&base);
        std::fs::create_dir_all(&base).unwrap();
        base
    }

    #[test]
    fn the_manifest_lists_files_sorted_once() {
        let text = manifest_text(["b/x.csv", "a.csv", "a.csv"]);
        assert_eq!(
            listed(&text),
            BTreeSet::from(["a.csv".to_string(), "b/x.csv".to_string()])
        );
        assert!(text.starts_with("# courant output"));
        assert!(text.ends_with("a.csv\nb/x.csv\n"));
    }

    #[test]
    fn absent_empty_and_listed_directories_may_be_replaced() {
        let base = scratch("allowed");
        let dir = base.join("out");
        check_replaceable(&dir).unwrap();
        std::fs::create_dir_all(&dir).unwrap();
        check_replaceable(&dir).unwrap();
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        std::fs::write(dir.join("sub/a.csv"), "1").unwrap();
        std::fs::write(dir.join(MANIFEST), manifest_text(["sub/a.csv", "b.csv"])).unwrap();
        check_replaceable(&dir).unwrap();
        std::fs::remove_dir_all(&base).unwrap();
    }

    #[test]
    fn a_users_file_or_an_unmarked_directory_is_refused_by_name() {
        let base = scratch("refused");
        let dir = base.join("out");
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        std::fs::write(dir.join("sub/data.csv"), "x").unwrap();
        std::fs::write(dir.join("thesis.tex"), "x").unwrap();
        let e = check_replaceable(&dir).unwrap_err().to_string();
        assert!(e.contains("`sub`") && e.contains("has no manifest"), "{e}");
        std::fs::write(dir.join(MANIFEST), manifest_text(["sub/data.csv"])).unwrap();
        let e = check_replaceable(&dir).unwrap_err().to_string();
        assert!(
            e.contains("`thesis.tex`") && e.contains("does not list it"),
            "{e}"
        );
        let file = dir.join("thesis.tex");
        assert!(matches!(
            check_replaceable(&file),
            Err(Refusal::NotADirectory { what: "file", .. })
        ));
        assert!(matches!(
            check_replaceable(Path::new(".")),
            Err(Refusal::NoName(_))
        ));
        std::fs::remove_dir_all(&base).unwrap();
    }
}
