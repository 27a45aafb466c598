//! Reading a file courant was given (a result file, a baseline, a query file, a scene) without
//! letting it block, exhaust memory or flood a message.
//!
//! Only a regular file (or a symbolic link to one) is read: a FIFO would block until a writer
//! comes, a device such as `/dev/zero` never ends, a directory is not a file. The kind is checked
//! before opening (without following into the object), the file is opened non-blocking and
//! checked again on the open handle (a FIFO swapped in between is still refused), its size is
//! capped and every line is capped while reading, so a one-line file of hundreds of megabytes
//! stops at the cap instead of being held and echoed. The text must be UTF-8; a bad byte is
//! located by line and byte.

use std::io::Read;
use std::path::Path;
use thiserror::Error;

/// Largest data file read: result files, baselines and query files (docs/guide/running.md, "Limits").
pub const DATA_CAP: u64 = 1 << 30;
/// Largest small text file read: scenes, `results.toml`, manifests (docs/guide/running.md, "Limits").
pub const TEXT_CAP: u64 = 1 << 20;
/// Longest line of any file read, in bytes (docs/guide/running.md, "Limits").
pub const LINE_CAP: usize = 1 << 16;

/// Why a file was not read. Messages do not repeat the path: the caller names it once.
#[derive(Debug, Error)]
pub enum ReadError {
    /// Nothing at the path (a dangling symbolic link included).
    #[error("does not exist{}", if *.dangling { " (a symbolic link to nothing)" } else { "" })]
    Missing {
        /// The path is a symbolic link whose target is missing.
        dangling: bool,
    },
    /// A directory, FIFO, device or socket: refused without opening it.
    #[error("is a {0}, not a regular file (refused without reading it)")]
    NotRegular(&'static str),
    /// Larger than the cap.
    #[error("is {size} bytes, over the limit of {cap} bytes for this file")]
    TooLarge {
        /// Size on disk.
        size: u64,
        /// The cap.
        cap: u64,
    },
    /// A line longer than [`LINE_CAP`].
    #[error("the line is longer than {cap} bytes (the limit of a line)")]
    LineTooLong {
        /// 1-based line.
        line: usize,
        /// The cap.
        cap: usize,
    },
    /// Not UTF-8 at `line`, `byte` (1-based byte within the line).
    #[error("not valid UTF-8 at this byte (files are UTF-8 text)")]
    NotUtf8 {
        /// 1-based line.
        line: usize,
        /// 1-based byte of the line.
        byte: usize,
    },
    /// Any other I/O error.
    #[error("cannot read: {0}")]
    Io(#[from] std::io::Error),
}

impl ReadError {
    /// The 1-based (line, column) the error is at, (0, 0) for the whole file.
    pub fn location(&self) -> (usize, usize) {
        match self {
            Self::LineTooLong { line, .. } => (*line, 1),
            Self::NotUtf8 { line, byte } => (*line, *byte),
            _ => (0, 0),
        }
    }

    /// The message with its location ("line 2, byte 9: ...") for callers that do not show
    /// the location themselves.
    pub fn located(&self) -> String {
        match self.location() {
            (0, _) => self.to_string(),
            (line, byte) => format!("line {line}, byte {byte}: {self}"),
        }
    }

    /// Nothing is at the path.
    pub fn is_missing(&self) -> bool {
        matches!(self, Self::Missing { .. })
    }
}

/// Read `path` as UTF-8 text of at most `cap` bytes and lines of at most [`LINE_CAP`] bytes.
///
/// # Errors
/// [`ReadError`]: missing, not a regular file, too large, a line too long, not UTF-8, or I/O.
pub fn read_text(path: &Path, cap: u64) -> Result<String, ReadError> {
    let meta = match std::fs::metadata(path) {
        Ok(meta) => meta,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            let dangling = std::fs::symlink_metadata(path).is_ok();
            return Err(ReadError::Missing { dangling });
        }
        Err(e) => return Err(e.into()),
    };
    if !meta.is_file() {
        return Err(ReadError::NotRegular(super::file_kind::kind_of(&meta)));
    }
    let file = open_nonblocking(path)?;
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Err(ReadError::NotRegular(super::file_kind::kind_of(&meta)));
    }
    if meta.len() > cap {
        return Err(ReadError::TooLarge {
            size: meta.len(),
            cap,
        });
    }
    let bytes = read_lines_capped(file.take(cap.saturating_add(1)), cap)?;
    String::from_utf8(bytes).map_err(|e| {
        let bytes = e.as_bytes();
        let at = e.utf8_error().valid_up_to();
        let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
        let start = bytes[..at]
            .iter()
            .rposition(|&b| b == b'\n')
            .map_or(0, |i| i + 1);
        ReadError::NotUtf8 {
            line,
            byte: at - start + 1,
        }
    })
}

/// Open for reading without blocking on a FIFO swapped in after the kind was checked.
fn open_nonblocking(path: &Path) -> std::io::Result<std::fs::File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path)
}

/// Every byte of `reader`, stopping at the first line longer than [`LINE_CAP`] or past `cap`
/// bytes (a file that grew while read).
fn read_lines_capped(mut reader: impl Read, cap: u64) -> Result<Vec<u8>, ReadError> {
    let mut bytes = Vec::new();
    let mut chunk = vec![0u8; 1 << 16];
    let (mut line, mut line_len) = (1usize, 0usize);
    loop {
        let n = match reader.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e.into()),
        };
        for &b in &chunk[..n] {
            if b == b'\n' {
                line += 1;
                line_len = 0;
            } else {
                line_len += 1;
                if line_len > LINE_CAP {
                    return Err(ReadError::LineTooLong {
                        line,
                        cap: LINE_CAP,
                    });
                }
            }
        }
        bytes.extend_from_slice(&chunk[..n]);
        if bytes.len() as u64 > cap {
            return Err(ReadError::TooLarge {
                size: bytes.len() as u64,
                cap,
            });
        }
    }
    Ok(bytes)
}

/// `text` cut to at most `max` characters, with "…" and the count of what was cut: for echoing
/// a value in a message.
pub fn shortened(text: &str, max: usize) -> String {
    match text.char_indices().nth(max) {
        None => text.to_string(),
        Some((end, _)) => format!("{}… ({} more bytes)", &text[..end], text.len() - end),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!(
            "courant-bounded-read-{name}-{}",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn regular_files_read_and_everything_else_is_named() {
        let dir = scratch("kinds");
        let file = dir.join("a.csv");
        std::fs::write(&file, "t,x\n1,2\n").unwrap();
        assert_eq!(read_text(&file, DATA_CAP).unwrap(), "t,x\n1,2\n");
        assert!(matches!(
            read_text(&dir, DATA_CAP),
            Err(ReadError::NotRegular("directory"))
        ));
        assert!(
            read_text(&dir.join("none"), DATA_CAP)
                .unwrap_err()
                .is_missing()
        );
        #[cfg(unix)]
        {
            let zero = dir.join("zero.csv");
            std::os::unix::fs::symlink("/dev/zero", &zero).unwrap();
            assert!(matches!(
                read_text(&zero, DATA_CAP),
                Err(ReadError::NotRegular("device"))
            ));
            let dangling = dir.join("dangling.csv");
            std::os::unix::fs::symlink(dir.join("nothing"), &dangling).unwrap();
            let e = read_text(&dangling, DATA_CAP).unwrap_err();
            assert!(e.to_string().contains("symbolic link to nothing"), "{e}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn caps_and_bad_bytes_are_located() {
        let dir = scratch("caps");
        let file = dir.join("a.csv");
        std::fs::write(&file, "t,x\n1,\u{e9}\n").unwrap();
        assert!(matches!(
            read_text(&file, 4),
            Err(ReadError::TooLarge { cap: 4, .. })
        ));
        std::fs::write(&file, b"t,x\n1,\xff2\n").unwrap();
        let e = read_text(&file, DATA_CAP).unwrap_err();
        assert_eq!(e.location(), (2, 3), "{e}");
        let mut long = b"t,x\n".to_vec();
        long.extend(std::iter::repeat_n(b'x', LINE_CAP + 1));
        std::fs::write(&file, &long).unwrap();
        let e = read_text(&file, DATA_CAP).unwrap_err();
        assert_eq!(e.location(), (2, 1), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn shortened_cuts_long_values_only() {
        assert_eq!(shortened("abc", 5), "abc");
        assert_eq!(shortened("abcdef", 3), "abc… (3 more bytes)");
    }
}
