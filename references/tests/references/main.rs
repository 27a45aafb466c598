//! Self-tests of the analytic references: each against a second, independent route.
//!
//! One test binary; each module opens with its source of truth and what it proves.

mod contact_critical_courant_closed_forms;
mod contact_critical_courant_eigenvalues;
mod contact_impact_against_lattice;
mod contact_layered_impact;
mod dalembert_self_tests;
mod graded_bar_two_routes;
mod graded_layered_waves;
mod spectra_closed_forms;
mod spectra_error_ratios;
