//! Verification against the references: exactness, convergence orders, invariants, spectra and
//! stability limits, each module naming its source of truth.
//!
//! One test binary; each module opens with its source of truth and what it proves.

#[path = "../common/mod.rs"]
mod common;
#[path = "../common/xml.rs"]
mod xml;

mod airy_front_convergence;
mod contact_critical_courant;
mod contact_fig5_central_difference;
mod contact_fig5_predictor_corrector;
mod contact_fig5_snapshots;
mod contact_lagrange_multiplier_exactness;
mod dalembert_courant_one_exactness;
mod dispersion_single_mode_runs;
mod energy_balance_invariant;
mod equal_transit_layered_and_graded;
mod fig1_profile_snapshots;
mod fig2_graded_bar_contrast;
mod impact_graded_reference;
mod impact_layered_combined_convergence;
mod impact_layered_convergence;
mod mass_matrix_spectra_and_limits;
mod park_amplification_analysis;
mod park_local_stepping;
mod si_units_normalisation;
mod stability_at_the_extremes;
mod stability_extremes_table;
mod stability_guard;
mod stability_marginal_growth_law;
mod work_precision_combination;
mod work_precision_contact;
