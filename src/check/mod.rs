//! `courant check`: run scenes, gate on their expectations and, optionally, on a baseline.
//!
//! ```text
//!   scene ──> run ──> results ──> compare ──> report / check
//!                                                      ^^^^^
//! ```
//!
//! Every expectation verdict of every scene is a check; with a baseline directory every result
//! file of every scene is one more ([`baseline`], MOOSE CSVDiff style). [`gate`] runs them,
//! [`render`] prints them for a terminal and [`junit_report`] as JUnit XML ([`junit`]), one
//! test suite per scene, one test case per check. `courant score` (another code's files graded
//! by `compare::score`) prints with [`score_render`] and writes JUnit with [`score_junit`].
//!
//! Enters: scenes, a baseline directory, tolerances. Leaves: verdicts, terminal text, JUnit XML.
//! Must not know: how records are produced or compared (it calls `pipeline`), documents.

pub mod baseline;
pub mod gate;
pub mod junit;
pub mod junit_report;
pub mod render;
pub mod score_junit;
pub mod score_render;
