//! The solver's own tests: the integrator contract seen from outside, each scheme's amplification,
//! convergence and stability, contact against dense references, the blocked time loop.
//!
//! One test binary; each module opens with its source of truth and what it proves.

#[path = "../common/mod.rs"]
mod common;

mod blocked_time_loop_equals_single_steps;
mod contact_combined_run;
mod contact_graded_impact_convergence;
mod contact_local_stepping_and_reciprocal_mass;
mod contact_momentum_and_outputs;
mod contact_schemes_match_dense_reference;
mod critical_step_against_dense_eigen;
mod integrator_interface_external_scheme;
mod matrix_mass_thread_bit_identity;
mod noh_bathe_amplification;
mod noh_bathe_convergence_and_stability;
mod noh_bathe_step_loaded_bar;
mod park_printed_misprints;
