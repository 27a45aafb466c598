//! The pipeline from scene files to the report: scene rules and their errors, the scheme registry,
//! sweeps, the fuzz of scene files, and the report's tables, figures and SVG.
//!
//! One test binary; each module opens with its source of truth and what it proves.

#[path = "../common/cli.rs"]
mod cli;
#[path = "../common/mutate.rs"]
mod mutate;
#[path = "../common/xml.rs"]
mod xml;

mod contact_scenes;
mod fuzz_scenes;
mod plot_svg;
mod report_figures_split;
mod report_generation;
mod robustness_regressions;
mod scene_input_errors;
mod scheme_parameter_sweeps;
mod scheme_registry;
mod sources_resolve;
