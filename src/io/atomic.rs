//! Writing an output directory whole or not at all.
//!
//! Files go to a hidden staging sibling `.NAME.partial-PID` first; only when every file is
//! written does it take the place of `NAME`:
//!
//! - on Linux (glibc), by exchanging the two directories atomically
//!   (`renameat2(RENAME_EXCHANGE)`): `NAME` exists at every instant, and the staging name then
//!   holds the previous results, which are removed;
//! - elsewhere, or where the file system cannot exchange, by renaming `NAME` aside to
//!   `.NAME.old-PID`, renaming the staging directory into place and removing the old one. A run
//!   killed between the two renames leaves no `NAME`, only `.NAME.old-PID`.
//!
//! Only a directory that is absent, empty or a courant output (its [`MANIFEST`] lists everything
//! in it) is replaced; anything else is refused before anything is touched
//! ([`super::manifest`]). The manifest is written with the files.
//!
//! Every write first recovers from interrupted runs ([`recover_interrupted`]): if `NAME` is
//! missing and a `.NAME.old-PID` of a process that is not running exists, it is renamed back to
//! `NAME`; the `.NAME.partial-PID` and `.NAME.old-PID` of processes that are no longer running
//! are removed. Whether a process runs is known on Linux (`/proc/PID`); elsewhere such
//! leftovers are kept (but a set-aside `.NAME.old-PID` is still restored when `NAME` is
//! missing). An interrupted run therefore keeps the previous results, or leaves them for the
//! next write to put back, and its leftovers go at the next write. Writers of the same
//! directory must not run concurrently.

use super::manifest::{MANIFEST, Refusal, check_replaceable, manifest_text};
use std::io;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why a directory was not written.
#[derive(Debug, Error)]
pub enum WriteError {
    /// The directory is not one courant may replace; nothing was touched.
    #[error(transparent)]
    Refused(#[from] Refusal),
    /// An I/O error of recovery, writing or renaming; the previous contents are kept.
    #[error(transparent)]
    Io(#[from] io::Error),
}

/// Replace `dir` with a directory holding exactly `files` (relative path, contents; parent
/// directories are created) and its [`MANIFEST`], after recovering from interrupted earlier
/// writes (module docs): [`stage_dir`] then [`Staged::commit`].
///
/// # Errors
/// [`WriteError::Refused`] when `dir` is not absent, empty or a courant output (nothing is
/// touched); any I/O error of recovery, writing or renaming (`dir` then still holds the
/// previous contents, or is absent if it was before).
pub fn write_dir_atomically(dir: &Path, files: &[(String, String)]) -> Result<(), WriteError> {
    stage_dir(dir, files)?.commit()
}

/// A directory written in full to its hidden staging sibling, not yet in place: several can be
/// staged (so that a command writes all of its directories or none, without holding their
/// contents in memory) and then committed. Dropped without [`Staged::commit`], the staging
/// directory is removed and `dir` is untouched.
#[derive(Debug)]
pub struct Staged {
    dir: PathBuf,
    staging: PathBuf,
    retired: PathBuf,
    committed: bool,
}

/// Write `files` (and the [`MANIFEST`]) to the staging sibling of `dir`, after checking that
/// `dir` may be replaced and recovering from interrupted earlier writes; `dir` itself is not
/// touched yet.
///
/// # Errors
/// As [`write_dir_atomically`]; the staging directory is removed.
pub fn stage_dir(dir: &Path, files: &[(String, String)]) -> Result<Staged, WriteError> {
    stage_dir_streamed(dir, files, &[])
}

/// A file written by streaming into it (`courant run`'s profile files, too large to hold as
/// text): its name and what writes its bytes.
pub type Stream<'a> = (String, &'a dyn Fn(&mut dyn io::Write) -> io::Result<()>);

/// [`stage_dir`], with `streamed` files besides `files`, each written into its staged file
/// through a buffer by its writer (never held whole). The staging directory is removed on any
/// error, so a streamed file is never left half-written.
///
/// # Errors
/// As [`write_dir_atomically`]; the staging directory is removed.
pub fn stage_dir_streamed(
    dir: &Path,
    files: &[(String, String)],
    streamed: &[Stream<'_>],
) -> Result<Staged, WriteError> {
    let (parent, name) = parent_and_name(dir);
    check_replaceable(dir)?;
    std::fs::create_dir_all(&parent)?;
    recover_interrupted(dir)?;
    // Recovery may have put a set-aside courant output back: check what is there now.
    check_replaceable(dir)?;
    let pid = std::process::id();
    let staged = Staged {
        dir: dir.to_path_buf(),
        staging: parent.join(format!(".{name}.partial-{pid}")),
        retired: parent.join(format!(".{name}.old-{pid}")),
        committed: false,
    };
    let _ = std::fs::remove_dir_all(&staged.staging);
    std::fs::create_dir_all(&staged.staging)?;
    let manifest = manifest_text(
        files
            .iter()
            .map(|(f, _)| f.as_str())
            .chain(streamed.iter().map(|(f, _)| f.as_str())),
    );
    files
        .iter()
        .chain(std::iter::once(&(MANIFEST.to_string(), manifest)))
        .try_for_each(|(file, text)| {
            let path = staged.staging.join(file);
            if let Some(dir) = path.parent() {
                std::fs::create_dir_all(dir)?;
            }
            std::fs::write(path, text)
        })?;
    for (file, write) in streamed {
        let path = staged.staging.join(file);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        let mut out = io::BufWriter::new(std::fs::File::create(path)?);
        write(&mut out)?;
        io::Write::flush(&mut out)?;
    }
    Ok(staged)
}

impl Staged {
    /// The directory this will replace.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Put the staged directory in the place of `dir` (checked again: it may have changed since
    /// it was staged).
    ///
    /// # Errors
    /// As [`write_dir_atomically`]; the staging directory is removed.
    pub fn commit(mut self) -> Result<(), WriteError> {
        check_replaceable(&self.dir)?;
        replace(&self.staging, &self.dir, &self.retired)?;
        self.committed = true;
        Ok(())
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.staging);
        }
    }
}

/// Write `text` to `path` atomically: to a hidden temporary file beside it, then renamed over
/// it, so a reader never sees a half-written report. Creates the parent directory.
pub fn write_file_atomically(path: &Path, text: &str) -> io::Result<()> {
    let parent = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    std::fs::create_dir_all(parent)?;
    let name = path
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or("junit.xml");
    let staging = parent.join(format!(".{name}.partial-{}", std::process::id()));
    let written = std::fs::write(&staging, text).and_then(|()| std::fs::rename(&staging, path));
    if written.is_err() {
        let _ = std::fs::remove_file(&staging);
    }
    written
}

/// Put the complete `staging` directory in the place of `dir`; the previous `dir` (if any) is
/// removed. Leftovers that cannot be removed carry this process's id and go at a later write.
fn replace(staging: &Path, dir: &Path, retired: &Path) -> io::Result<()> {
    if dir.exists() {
        if exchange(staging, dir).is_ok() {
            // `staging` now holds the previous results.
            let _ = std::fs::remove_dir_all(staging);
            return Ok(());
        }
        std::fs::rename(dir, retired)?;
        if let Err(e) = std::fs::rename(staging, dir) {
            // Put the previous results back rather than leave no `dir`.
            let _ = std::fs::rename(retired, dir);
            return Err(e);
        }
        let _ = std::fs::remove_dir_all(retired);
        Ok(())
    } else {
        std::fs::rename(staging, dir)
    }
}

/// Exchange two existing directories atomically (Linux 3.15+, glibc 2.28+). Fails with the OS
/// error where the file system does not support it (the caller then falls back).
#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn exchange(a: &Path, b: &Path) -> io::Result<()> {
    use std::ffi::CString;
    use std::os::unix::ffi::OsStrExt;
    let a = CString::new(a.as_os_str().as_bytes())?;
    let b = CString::new(b.as_os_str().as_bytes())?;
    // SAFETY: both arguments are NUL-terminated strings that outlive the call, which only reads
    // them; AT_FDCWD makes relative paths relative to the working directory, as `std::fs` does.
    let rc = unsafe {
        libc::renameat2(
            libc::AT_FDCWD,
            a.as_ptr(),
            libc::AT_FDCWD,
            b.as_ptr(),
            libc::RENAME_EXCHANGE,
        )
    };
    if rc == 0 {
        Ok(())
    } else {
        Err(io::Error::last_os_error())
    }
}

/// No atomic exchange on this platform: the caller renames aside instead.
#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn exchange(_: &Path, _: &Path) -> io::Result<()> {
    Err(io::Error::from(io::ErrorKind::Unsupported))
}

/// Recover `dir` from interrupted writes (module docs): restore a set-aside `.NAME.old-PID` if
/// `dir` is missing, then remove the `.NAME.partial-PID` and `.NAME.old-PID` siblings of
/// processes that are no longer running (of this process too: it writes one directory at a
/// time). Other siblings are never touched. Removal is best effort.
///
/// # Errors
/// The parent directory cannot be read, or a set-aside directory cannot be renamed back.
pub fn recover_interrupted(dir: &Path) -> io::Result<()> {
    let (parent, name) = parent_and_name(dir);
    if !parent.is_dir() {
        return Ok(());
    }
    let (partial, old) = (format!(".{name}.partial-"), format!(".{name}.old-"));
    let mut staged = Vec::new();
    let mut set_aside = Vec::new();
    for entry in std::fs::read_dir(&parent)? {
        let entry = entry?;
        let file_name = entry.file_name();
        let Some(file_name) = file_name.to_str() else {
            continue;
        };
        let leftover = |prefix: &str| {
            file_name
                .strip_prefix(prefix)
                .and_then(|pid| pid.parse::<u32>().ok())
                .map(|pid| (entry.path(), owner(pid)))
        };
        if let Some(found) = leftover(&partial) {
            staged.push(found);
        } else if let Some(found) = leftover(&old) {
            set_aside.push(found);
        }
    }
    if std::fs::symlink_metadata(dir).is_err() {
        // The newest set-aside copy is the latest complete result.
        let newest = set_aside
            .iter()
            .enumerate()
            .filter(|(_, (_, owner))| *owner != Owner::Running)
            .max_by_key(|(_, (path, _))| {
                let modified = std::fs::metadata(path).and_then(|m| m.modified()).ok();
                (modified, path.clone())
            })
            .map(|(i, _)| i);
        if let Some(i) = newest {
            let (path, _) = set_aside.remove(i);
            std::fs::rename(path, dir)?;
        }
    }
    for (path, owner) in staged.iter().chain(&set_aside) {
        if *owner == Owner::Gone {
            let _ = std::fs::remove_dir_all(path);
        }
    }
    Ok(())
}

/// Whether the process that left a staging or set-aside directory still runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Owner {
    Running,
    Gone,
    Unknown,
}

fn owner(pid: u32) -> Owner {
    if pid == std::process::id() {
        return Owner::Gone;
    }
    if cfg!(target_os = "linux") && Path::new("/proc/self").exists() {
        if Path::new("/proc").join(pid.to_string()).exists() {
            Owner::Running
        } else {
            Owner::Gone
        }
    } else {
        Owner::Unknown
    }
}

/// The parent directory (`.` for a bare name) and the final component of `dir`.
fn parent_and_name(dir: &Path) -> (PathBuf, String) {
    let parent = dir
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = dir.file_name().and_then(|n| n.to_str()).unwrap_or("out");
    (parent.to_path_buf(), name.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A PID no process can have: above Linux's PID_MAX_LIMIT (2^22).
    const DEAD_PID: u32 = 4_000_000_000;

    fn scratch(test: &str) -> PathBuf {
        let base =
            std::env::temp_dir().join(format!("courant-write-{test}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&base);
        std::fs::create_dir_all(&base).unwrap();
        base
    }

    /// A courant output holding `index.md` (with its manifest).
    fn make(dir: &Path, marker: &str) {
        std::fs::create_dir_all(dir).unwrap();
        std::fs::write(dir.join("index.md"), marker).unwrap();
        std::fs::write(dir.join(MANIFEST), manifest_text(["index.md"])).unwrap();
    }

    fn entries(base: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(base)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn replaces_the_old_directory_whole() {
        let base = scratch("replace");
        let dir = base.join("scene");
        write_dir_atomically(
            &dir,
            &[("a.csv".into(), "1".into()), ("b.csv".into(), "2".into())],
        )
        .unwrap();
        write_dir_atomically(&dir, &[("a.csv".into(), "3".into())]).unwrap();
        assert_eq!(std::fs::read_to_string(dir.join("a.csv")).unwrap(), "3");
        assert!(
            !dir.join("b.csv").exists(),
            "stale files from the previous run must go"
        );
        assert_eq!(
            entries(&base),
            ["scene"],
            "no staging directories left behind"
        );
        std::fs::remove_dir_all(&base).unwrap();
    }

    #[test]
    fn a_staged_directory_dropped_uncommitted_leaves_nothing() {
        let base = scratch("staged");
        let (kept, dropped) = (base.join("kept"), base.join("dropped"));
        make(&kept, "previous");
        let a = stage_dir(&kept, &[("index.md".into(), "new".into())]).unwrap();
        let b = stage_dir(&dropped, &[("index.md".into(), "new".into())]).unwrap();
        assert_eq!(
            std::fs::read_to_string(kept.join("index.md")).unwrap(),
            "previous",
            "staging touches nothing"
        );
        drop(b);
        a.commit().unwrap();
        assert_eq!(
            std::fs::read_to_string(kept.join("index.md")).unwrap(),
            "new"
        );
        assert_eq!(entries(&base), ["kept"], "the dropped staging is gone");
        std::fs::remove_dir_all(&base).unwrap();
    }

    #[test]
    fn a_directory_set_aside_by_a_killed_run_is_restored() {
        // Killed between the two renames: no `scene`, the previous results set aside.
        let base = scratch("restore");
        let dir = base.join("scene");
        make(&base.join(format!(".scene.old-{DEAD_PID}")), "previous");
        recover_interrupted(&dir).unwrap();
        assert_eq!(
            std::fs::read_to_string(dir.join("index.md")).unwrap(),
            "previous"
        );
        assert_eq!(entries(&base), ["scene"]);
        std::fs::remove_dir_all(&base).unwrap();
    }

    #[test]
    fn the_newest_set_aside_directory_is_restored() {
        let base = scratch("newest");
        let dir = base.join("scene");
        let (older, newer) = (
            base.join(format!(".scene.old-{DEAD_PID}")),
            base.join(format!(".scene.old-{}", DEAD_PID + 1)),
        );
        make(&older, "older");
        make(&newer, "newer");
        let past = std::time::SystemTime::now() - std::time::Duration::from_secs(3600);
        std::fs::File::open(&older)
            .unwrap()
            .set_modified(past)
            .unwrap();
        recover_interrupted(&dir).unwrap();
        assert_eq!(
            std::fs::read_to_string(dir.join("index.md")).unwrap(),
            "newer"
        );
        if cfg!(target_os = "linux") {
            assert_eq!(entries(&base), ["scene"], "the other copy is stale");
        }
        std::fs::remove_dir_all(&base).unwrap();
    }

    #[test]
    fn a_write_after_a_killed_run_removes_its_leftovers_and_nothing_else() {
        let base = scratch("stale");
        let dir = base.join("scene");
        make(&dir, "previous");
        make(&base.join(format!(".scene.partial-{DEAD_PID}")), "half");
        make(&base.join(format!(".scene.old-{DEAD_PID}")), "older");
        let unrelated = [
            ".scene.partial-x1",
            ".scenes.old-12",
            ".other.partial-12",
            "scene.old-12",
        ];
        for name in unrelated {
            make(&base.join(name), "keep");
        }
        write_dir_atomically(&dir, &[("index.md".into(), "new".into())]).unwrap();
        assert_eq!(
            std::fs::read_to_string(dir.join("index.md")).unwrap(),
            "new"
        );
        let mut expected: Vec<String> = unrelated.iter().map(|s| s.to_string()).collect();
        expected.push("scene".into());
        if !cfg!(target_os = "linux") {
            // Liveness of the writer is unknown: its leftovers are kept.
            expected.push(format!(".scene.partial-{DEAD_PID}"));
            expected.push(format!(".scene.old-{DEAD_PID}"));
        }
        expected.sort();
        assert_eq!(entries(&base), expected);
        std::fs::remove_dir_all(&base).unwrap();
    }

    #[test]
    fn leftovers_of_a_running_process_are_kept() {
        // PID 1 always runs (on Linux: /proc/1); elsewhere liveness is unknown, also kept.
        let base = scratch("running");
        let dir = base.join("scene");
        make(&dir, "previous");
        make(&base.join(".scene.partial-1"), "in progress");
        recover_interrupted(&dir).unwrap();
        assert_eq!(entries(&base), [".scene.partial-1", "scene"]);
        if cfg!(target_os = "linux") {
            // Nor is a set-aside directory of a running writer taken back: it is mid-swap.
            std::fs::remove_dir_all(&dir).unwrap();
            make(&base.join(".scene.old-1"), "mid-swap");
            recover_interrupted(&dir).unwrap();
            assert_eq!(entries(&base), [".scene.old-1", ".scene.partial-1"]);
        }
        std::fs::remove_dir_all(&base).unwrap();
    }

    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    #[test]
    fn exchange_swaps_two_directories() {
        let base = scratch("exchange");
        let (a, b) = (base.join("a"), base.join("b"));
        make(&a, "first");
        make(&b, "second");
        exchange(&a, &b).unwrap();
        assert_eq!(
            std::fs::read_to_string(a.join("index.md")).unwrap(),
            "second"
        );
        assert_eq!(
            std::fs::read_to_string(b.join("index.md")).unwrap(),
            "first"
        );
        assert!(exchange(&a, &base.join("missing")).is_err());
        std::fs::remove_dir_all(&base).unwrap();
    }
}
