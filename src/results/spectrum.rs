//! The record of a spectrum case.

use courant_solver::MassKind;
use std::time::Duration;

/// Computed frequencies of one bar for several mass kinds.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumRecord {
    /// Case name.
    pub case: String,
    /// Mass kinds, one spectrum each.
    pub masses: Vec<MassKind>,
    /// Computed angular frequencies per mass kind (dense eigen-solution), ascending.
    pub computed: Vec<Vec<f64>>,
    /// Wall time of the eigen-solutions.
    pub wall_time: Duration,
}
