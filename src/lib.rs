//! # courant
//!
//! Verification benchmarks and reference solutions for explicit finite-element dynamics of bars.
//! The crate is laid out as the pipeline it runs (`ARCHITECTURE.md`):
//!
//! ```text
//!   scene ──> run ──> results ──> compare ──> report
//!   (TOML     (solver  (records,   (references,   └──> check
//!    cases)    runs)    plain data) norms, verdicts)
//!
//!   pipeline: run + compare, the only place they meet      cli: the commands
//!   io: atomic writes, clock, ordered parallel collection (used by every stage)
//! ```
//!
//! Dependencies point one way (checked by `tests/architecture/main.rs`): a stage uses only the
//! stages upstream of it and `io`; `compare` never runs a solver, `run` never compares, `report`
//! only renders compared records.

pub mod check;
pub mod cli;
pub mod compare;
pub mod io;
pub mod pipeline;
pub mod report;
pub mod results;
pub mod run;
pub mod scene;
