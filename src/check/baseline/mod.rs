//! Comparing fresh result CSVs with a baseline, column by column, the way MOOSE's CSVDiff does.
//!
//! A baseline is either a previous run's output directory, laid out as `courant run --out DIR`
//! writes it (`DIR/<scene>/<file>.csv`), or a previous *report* (`courant report --out DIR`:
//! `DIR/index.md` beside `DIR/<scene>/`), which keeps only each scene's deterministic tables
//! ([`REPORT_TABLES`](crate::compare::files::REPORT_TABLES): the summary without wall times, norms, expectations, dispersion and contact
//! stability tables) and not the per-case profiles, histories, energy logs and spectra
//! ([`BaselineKind`](kind::BaselineKind)).
//! Every fresh file of a scene is compared with the baseline file of the same name, cell by cell,
//! under the rule [`Tolerances::rule_for`](tolerance::Tolerances::rule_for) picks for its column; columns are matched by name (in
//! any order), and ignored columns (wall times) may be present on one side only. A file missing
//! on either side (except a fresh file a report does not keep, which is reported as not
//! compared), a changed header, a changed row count or a cell beyond its tolerance fails the
//! file. The report keeps the largest change of every column (absolute and relative) so that a
//! passing comparison still says how close it came.
//!
//! - [`kind`]: a run's output or a report; [`tolerance`]: the rule of each column;
//!   [`csv_diff`]: the comparison of one file; [`scene_diff`]: of a scene's files.

pub mod csv_diff;
pub mod kind;
pub mod scene_diff;
pub mod tolerance;
