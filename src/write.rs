//! Writing a scene's output directory whole or not at all.
//!
//! Files go to a hidden sibling directory first; only when every file is written is it renamed
//! into place (an existing directory is moved aside, then removed). An interrupted run leaves
//! the previous results intact.

use std::io;
use std::path::Path;

/// Replace `dir` with a directory holding exactly `files` (relative path, contents; parent
/// directories are created).
pub fn write_dir_atomically(dir: &Path, files: &[(String, String)]) -> io::Result<()> {
    let parent = dir
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    std::fs::create_dir_all(parent)?;
    let name = dir.file_name().and_then(|n| n.to_str()).unwrap_or("out");
    let pid = std::process::id();
    let staging = parent.join(format!(".{name}.partial-{pid}"));
    let retired = parent.join(format!(".{name}.old-{pid}"));
    let _ = std::fs::remove_dir_all(&staging);
    std::fs::create_dir_all(&staging)?;
    let written = files.iter().try_for_each(|(file, text)| {
        let path = staging.join(file);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        std::fs::write(path, text)
    });
    if let Err(e) = written {
        let _ = std::fs::remove_dir_all(&staging);
        return Err(e);
    }
    if dir.exists() {
        std::fs::rename(dir, &retired)?;
    }
    std::fs::rename(&staging, dir)?;
    if retired.exists() {
        std::fs::remove_dir_all(&retired)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replaces_the_old_directory_whole() {
        let base = std::env::temp_dir().join(format!("courant-write-test-{}", std::process::id()));
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
        let leftovers: Vec<_> = std::fs::read_dir(&base)
            .unwrap()
            .filter_map(|e| e.ok())
            .filter(|e| e.file_name() != "scene")
            .collect();
        assert!(leftovers.is_empty(), "no staging directories left behind");
        std::fs::remove_dir_all(&base).unwrap();
    }
}
