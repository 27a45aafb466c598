//! Comparing records with their references: exact solutions on the record's own mesh and times,
//! error norms, diagnostics, expectation verdicts, observed orders, stability verdicts.
//!
//! ```text
//!   scene ──> run ──> results ──> compare ──> report / check
//!                                 ^^^^^^^
//! ```
//!
//! - [`exact`] evaluates a case's reference (`courant-references`), [`cache`] shares exact
//!   profiles between the cases of a scene, [`norms`] measures a profile against them and
//!   [`front_width`] the width of its dispersed front;
//! - [`case`], [`contact`], [`spectrum`], [`dispersion`], [`sweep`]: each kind of record beside
//!   its reference; [`scene`] compares a whole scene into an [`outcome::SceneOutcome`] and
//!   [`expect`] gives the [`verdict`]s of its expectations, [`stability_verdicts`] those of a
//!   stability scene's cases;
//! - [`convergence`] (observed and fitted orders against the study's band), [`stability`]
//!   (predicted against observed stability, [`growth`] the double-root law at the limit),
//!   [`work_precision`] (cost beside error), [`contact_closed_forms`] (the closed forms against
//!   their asymptotes);
//! - [`tables`], [`files`]: the CSV tables of time-stepping cases (each other study's tables
//!   sit in its own module), the files `courant run` writes and those a report keeps;
//! - [`score`]: another code's results (exchange files) graded against the scene's references
//!   with the same norms and expectations, plus time-level, sign and load diagnostics.
//!
//! Enters: records (`results`, courant's or read from another code's files) and the scene they
//! came from (cases, references, expectations).
//! Leaves: comparisons, verdicts and their tables. Must not know: how records were produced (it
//! never runs a solver), documents, figures, the command line.

pub mod cache;
pub mod case;
pub mod contact;
pub mod contact_closed_forms;
pub mod convergence;
pub mod dispersion;
pub mod exact;
pub mod expect;
pub mod files;
pub mod front_width;
pub mod growth;
pub mod norms;
pub mod outcome;
pub mod scene;
pub mod score;
pub mod spectrum;
pub mod stability;
pub mod stability_verdicts;
pub mod stress_difference;
pub mod sweep;
pub mod tables;
pub mod verdict;
pub mod work_precision;
