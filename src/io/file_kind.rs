//! What a path is, in words, without opening it (a FIFO opened for reading would block until a
//! writer comes).

use std::path::Path;

/// What the file type of `meta` is, in words: "file", "directory", "symbolic link",
/// "FIFO (named pipe)", "device", "socket" or "special file".
pub fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    let kind = meta.file_type();
    if kind.is_symlink() {
        return "symbolic link";
    }
    if kind.is_file() {
        return "file";
    }
    if kind.is_dir() {
        return "directory";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return "FIFO (named pipe)";
        }
        if kind.is_char_device() || kind.is_block_device() {
            return "device";
        }
        if kind.is_socket() {
            return "socket";
        }
    }
    "special file"
}

/// What `path` is when it exists and is not a regular file (symbolic links followed): `None` for
/// a regular file or a path that does not exist.
pub fn non_regular_kind(path: &Path) -> Option<&'static str> {
    let meta = std::fs::metadata(path).ok()?;
    (!meta.is_file()).then(|| kind_of(&meta))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directories_and_devices_are_named_and_regular_files_are_not() {
        assert_eq!(
            non_regular_kind(Path::new(env!("CARGO_MANIFEST_DIR"))),
            Some("directory")
        );
        assert_eq!(non_regular_kind(Path::new(file!())), None);
        assert_eq!(non_regular_kind(Path::new("no/such/file.toml")), None);
        if cfg!(unix) {
            assert_eq!(non_regular_kind(Path::new("/dev/null")), Some("device"));
        }
    }
}
