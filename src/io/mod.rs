//! The bottom of the pipeline: what every stage may use and that knows no stage.
//!
//! - [`atomic`]: files and directories written whole or not at all (staged, then renamed or
//!   exchanged into place), with recovery of interrupted writes.
//! - [`manifest`]: the mark of a courant output directory (a manifest of what was written) and
//!   the rule that only an absent, empty or marked directory is replaced.
//! - [`bounded_read`]: reading a file courant was given: regular files only, sizes and lines
//!   capped, bad UTF-8 located.
//! - [`owned_file`]: one output file replaced only when absent or written by the same command.
//! - [`file_kind`]: what a path is (file, directory, FIFO, device), without opening it.
//! - [`clock`]: ISO 8601 UTC dates for reports and JUnit timestamps.
//! - [`parallel`]: collecting parallel work in input order, so that the first error (and every
//!   result) does not depend on the thread count.
//!
//! Enters: paths, file contents, results of parallel maps. Leaves: files on disk, dates. Must
//! not know: scenes, solvers, records, verdicts.

pub mod atomic;
pub mod bounded_read;
pub mod clock;
pub mod file_kind;
pub mod manifest;
pub mod owned_file;
pub mod parallel;
