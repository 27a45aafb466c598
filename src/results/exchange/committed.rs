//! The external result sets committed in this repository (`external/<code>/results/<scene>/`),
//! compiled into the binary like the built-in scenes, so that `courant report` grades them from
//! any directory and its content does not depend on the working directory. A test checks that
//! this list holds every file of those directories.

use super::error::ExchangeError;
use super::reader::read_set;
use super::record::ExchangeSet;

/// One committed result set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CommittedSet {
    /// The producing code.
    pub code: &'static str,
    /// The scene it answers.
    pub scene: &'static str,
    /// Its directory, relative to the repository root.
    pub dir: &'static str,
    /// `(file name, text)` of every file.
    pub files: &'static [(&'static str, &'static str)],
}

impl CommittedSet {
    /// Read the set (labelled by its directory).
    ///
    /// # Errors
    /// A committed file is not valid exchange data (a bug caught by the tests).
    pub fn read(&self) -> Result<ExchangeSet, ExchangeError> {
        let files: Vec<(String, String)> = self
            .files
            .iter()
            .map(|(n, t)| (n.to_string(), t.to_string()))
            .collect();
        read_set(self.dir, self.dir, &files)
    }
}

/// Every committed result set, in report order.
pub const COMMITTED: &[CommittedSet] = &[];
