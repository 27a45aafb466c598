//! One output file (`--junit`, `bench --out`) replaced only when it is absent or a regular file
//! the same command wrote before: the file is written to a hidden sibling and renamed into
//! place, and a rename replaces whatever is at the path, so without this check a device node, a
//! FIFO, a symbolic link or a user's notes would be replaced by a regular file (as root,
//! `--junit /dev/null` would have replaced `/dev/null`).
//!
//! A symbolic link is followed to the regular file it names, which is then the file written (the
//! link stays); a link to anything else, or to nothing, is refused.

use super::atomic::write_file_atomically;
use std::io::Read;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// How many leading bytes of an existing file [`Owner::recognises`] looks at.
const HEAD: u64 = 4096;

/// The command an output file belongs to and how its files begin.
#[derive(Debug, Clone, Copy)]
pub struct Owner {
    /// What wrote the file, for messages (e.g. "`courant check --junit`").
    pub what: &'static str,
    /// Whether a file whose first bytes are these (lossy UTF-8) is one this command wrote.
    pub recognises: fn(&str) -> bool,
}

/// Why an output file was not written; nothing at the path was touched.
#[derive(Debug, Error)]
pub enum FileWriteError {
    /// A directory, FIFO, device, socket or dangling link.
    #[error("{}: is a {kind}, not a file {what} wrote; refused (give the path of a new or regular file)", .path.display())]
    NotRegular {
        /// The path given.
        path: PathBuf,
        /// What it is.
        kind: &'static str,
        /// The command.
        what: &'static str,
    },
    /// A regular file that does not look like one this command wrote.
    #[error("{}: exists and is not a file {what} wrote; give another path or remove it", .path.display())]
    NotOurs {
        /// The path given.
        path: PathBuf,
        /// The command.
        what: &'static str,
    },
    /// An I/O error looking at or writing the file.
    #[error("{}: {source}", .path.display())]
    Io {
        /// The path given.
        path: PathBuf,
        /// The error.
        source: std::io::Error,
    },
}

/// The file `path` stands for (a symbolic link followed to its regular file), after checking it
/// may be replaced by `owner`: absent, or a regular file `owner` recognises.
///
/// # Errors
/// [`FileWriteError`], naming the path and what is there.
pub fn check_file_replaceable(path: &Path, owner: Owner) -> Result<PathBuf, FileWriteError> {
    let io = |source| FileWriteError::Io {
        path: path.to_path_buf(),
        source,
    };
    let not_regular = |kind| FileWriteError::NotRegular {
        path: path.to_path_buf(),
        kind,
        what: owner.what,
    };
    let link = match std::fs::symlink_metadata(path) {
        Ok(meta) => meta,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(path.to_path_buf()),
        Err(e) => return Err(io(e)),
    };
    let target = if link.file_type().is_symlink() {
        match std::fs::metadata(path) {
            Ok(meta) if meta.is_file() => std::fs::canonicalize(path).map_err(io)?,
            Ok(meta) => return Err(not_regular(super::file_kind::kind_of(&meta))),
            Err(_) => return Err(not_regular("symbolic link to nothing")),
        }
    } else if link.is_file() {
        path.to_path_buf()
    } else {
        return Err(not_regular(super::file_kind::kind_of(&link)));
    };
    let mut head = Vec::new();
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(&target).map_err(io)?;
    if !file.metadata().map_err(io)?.is_file() {
        return Err(not_regular("special file"));
    }
    file.take(HEAD).read_to_end(&mut head).map_err(io)?;
    if (owner.recognises)(&String::from_utf8_lossy(&head)) {
        Ok(target)
    } else {
        Err(FileWriteError::NotOurs {
            path: path.to_path_buf(),
            what: owner.what,
        })
    }
}

/// Write `text` to `path` atomically ([`write_file_atomically`]) after
/// [`check_file_replaceable`] (checked again here: the path may have changed since validation).
///
/// # Errors
/// As [`check_file_replaceable`], or the I/O error of the write.
pub fn write_owned_file(path: &Path, text: &str, owner: Owner) -> Result<(), FileWriteError> {
    let target = check_file_replaceable(path, owner)?;
    write_file_atomically(&target, text).map_err(|source| FileWriteError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// A JUnit report courant wrote (`courant check --junit`, `courant score --junit`).
pub const JUNIT: Owner = Owner {
    what: "courant's --junit",
    recognises: |head| {
        head.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"courant ")
    },
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_absent_or_own_regular_files_are_replaced() {
        let dir = std::env::temp_dir().join(format!("courant-owned-file-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let junit = dir.join("j.xml");
        let ours =
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"courant check\">\n";
        write_owned_file(&junit, ours, JUNIT).unwrap();
        write_owned_file(&junit, ours, JUNIT).unwrap();
        let notes = dir.join("notes");
        std::fs::write(&notes, "mine").unwrap();
        assert!(matches!(
            write_owned_file(&notes, ours, JUNIT),
            Err(FileWriteError::NotOurs { .. })
        ));
        assert_eq!(std::fs::read_to_string(&notes).unwrap(), "mine");
        assert!(matches!(
            write_owned_file(&dir, ours, JUNIT),
            Err(FileWriteError::NotRegular {
                kind: "directory",
                ..
            })
        ));
        #[cfg(unix)]
        {
            let null = dir.join("null");
            std::os::unix::fs::symlink("/dev/null", &null).unwrap();
            assert!(matches!(
                write_owned_file(&null, ours, JUNIT),
                Err(FileWriteError::NotRegular { kind: "device", .. })
            ));
            assert!(
                std::fs::symlink_metadata(&null)
                    .unwrap()
                    .file_type()
                    .is_symlink()
            );
            let link = dir.join("link.xml");
            std::os::unix::fs::symlink(&junit, &link).unwrap();
            write_owned_file(&link, ours, JUNIT).unwrap();
            assert!(
                std::fs::symlink_metadata(&link)
                    .unwrap()
                    .file_type()
                    .is_symlink()
            );
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
