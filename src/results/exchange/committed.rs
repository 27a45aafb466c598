//! The external result sets committed in this repository (`external/<code>/results/<scene>/`),
//! compiled into the binary like the built-in scenes, so that `courant report` grades them from
//! any directory and its content does not depend on the working directory. `build.rs` lists
//! them; a test checks that the list holds every file of those directories.

use super::error::ExchangeErrors;
use super::record::ExchangeSet;
use super::set::read_set;

/// One committed result set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CommittedSet {
    /// The producing code.
    pub code: &'static str,
    /// The code and the variant the set shows (`opensees central-difference-as-it-comes`), or
    /// the code alone.
    pub label: &'static str,
    /// The scene it answers.
    pub scene: &'static str,
    /// Its directory, relative to the repository root.
    pub dir: &'static str,
    /// `(file name, text)` of every file.
    pub files: &'static [(&'static str, &'static str)],
    /// `stated.toml`: the findings stated for the set, if any (`compare::score::stated`).
    pub stated: Option<&'static str>,
}

impl CommittedSet {
    /// Read the set (labelled by its directory).
    ///
    /// # Errors
    /// A committed file is not valid exchange data (a bug caught by the tests).
    pub fn read(&self) -> Result<ExchangeSet, ExchangeErrors> {
        let files: Vec<(String, String)> = self
            .files
            .iter()
            .map(|(n, t)| (n.to_string(), t.to_string()))
            .collect();
        read_set(self.dir, self.dir, &files)
    }
}

/// Every committed result set, in report order (codes alphabetically, then their directories):
/// listed by `build.rs` from `external/<code>/results/`, every file of each directory included.
pub const COMMITTED: &[CommittedSet] = include!(concat!(env!("OUT_DIR"), "/committed_sets.rs"));

/// courant's times on the cases another code ran (`external/<code>/courant_times.csv`: per
/// scene and case, the steps and courant's wall time, measured by that code's driver right after
/// its own, whose times are the `wall_s` of its sets), as `(code, text)`.
pub const COURANT_TIMES: &[(&str, &str)] =
    include!(concat!(env!("OUT_DIR"), "/committed_courant_times.rs"));

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_file_of_the_committed_directories_is_listed_and_reads() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        for set in COMMITTED {
            let mut on_disk: Vec<String> = std::fs::read_dir(root.join(set.dir))
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect();
            on_disk.retain(|f| f != "stated.toml");
            on_disk.sort();
            let listed: Vec<&str> = set.files.iter().map(|f| f.0).collect();
            assert_eq!(on_disk, listed, "{}: add every file to COMMITTED", set.dir);
            let read = set.read().unwrap();
            assert_eq!(read.code(), set.code);
        }
    }
}
