//! # courant
//!
//! Verification benchmarks and reference solutions for explicit finite-element dynamics of bars.
//! This crate reads declarative scene files ([`scene`]), runs their cases with
//! `courant-solver` ([`run`]), compares them with the analytic references of
//! `courant-references` ([`reference`](mod@reference), [`metrics`]), checks their expectations ([`expect`]) and
//! writes named CSV tables ([`results`], [`table`], [`write`](mod@write)).

pub mod baseline;
pub mod bench_table;
pub mod builtin;
pub mod check;
pub mod clock;
pub mod contact_study;
pub mod dispersion;
pub mod document;
pub mod expect;
pub mod junit;
pub mod metrics;
pub mod plot;
pub mod reference;
pub mod report;
pub mod report_figures;
pub mod results;
pub mod run;
pub mod scene;
pub mod spectra;
pub mod stability_table;
pub mod table;
pub mod work_precision;
pub mod write;

pub use run::{CaseResult, SceneOutcome, Status, run_case, run_scene};
pub use scene::{Case, Scene, SceneError};
