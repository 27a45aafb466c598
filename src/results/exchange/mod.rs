//! The results exchange format: how another code's results (or courant's own, or the exact
//! answers of `courant reference`) are written to files and read back as records, so that
//! courant's solver is one producer among others.
//!
//! ```text
//!   another code ─┐
//!   courant run ──┼──> DIR/<case>.csv (+ results.toml) ──> exchange records ──> compare::score
//!   courant reference ┘
//! ```
//!
//! **Format 2** (docs/guide/grading.md has a complete example; format 2 adds
//! `parameters` to `results.toml`'s case tables, and a format-1 set reads as before):
//!
//! - a directory per scene; one CSV file per case, `<case>.csv`, the stem naming a case of the
//!   scene; columns matched by name, in any order; one header line; numbers in any notation Rust
//!   parses (`0.5`, `5e-1`), finite; an optional `reference` column (text) is ignored on reading;
//! - the columns say what a file holds ([`columns::Kind`]):
//!   - stress profiles as element averages, `t, x_left, x_right, stress` (one row per element and
//!     output time);
//!   - stress profiles as point values, `t, x, stress`;
//!   - a contact force history, `t, force` (compression positive), optionally `penetration` and
//!     `gap`;
//!   - a spectrum, `mode, omega` (angular frequencies), optionally `mass` (a mass label per row
//!     when one file holds several mass kinds);
//! - profile rows are grouped by time, times never decreasing; within a time the rows may come
//!   in any order (they are sorted by position) but must not overlap; force-history times
//!   increase strictly;
//! - an optional `results.toml` ([`meta`]): `format` (default 1), `code`, `version`, and per case
//!   `[cases."<case>"]` with `scheme`, `parameters`, `mass`, `dt`, `elements`, `wall_s` and
//!   `steps` (the code's own time for the run and its steps); unknown keys are errors.
//!
//! Versioning: `results.toml`'s `format` is the version (absent: 1). A reader refuses a format
//! newer than [`FORMAT`]; any change a format-1 reader would not read correctly (a new column or
//! key included, since unknown ones are errors) makes a new number.
//!
//! - [`record`]: the records read from files; [`columns`]: the kinds of file and their columns;
//!   [`reader`]: a file to records with errors naming file, line, column and key, every error of
//!   a set at once ([`error`]); [`set`]: a set from its files' contents; [`files`]: which files
//!   of a directory are read, each bounded;
//!   [`meta`]: `results.toml`; [`writer`]: records to files; [`committed`]: the external result
//!   sets committed in this repository and compiled into the binary.
//!
//! Enters: file contents. Leaves: records, or every located [`error::ExchangeError`]. Must not know:
//! scenes, references, norms (a record is checked against its scene by `compare::score`).

pub mod columns;
pub mod committed;
pub mod error;
pub mod files;
pub mod meta;
pub mod reader;
pub mod record;
pub mod set;
pub mod writer;

/// The format version this courant reads and writes.
pub const FORMAT: u32 = 2;
