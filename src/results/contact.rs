//! The record of a contact-impact case.

use courant_solver::DivergenceError;
use courant_solver::contact::ContactRun;
use std::time::Duration;

/// What a contact run produced: its force and energy history (partial when it diverged).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRecord {
    /// Case name.
    pub case: String,
    /// `(beta_s, beta_m)` for the penalty schemes.
    pub penalty: Option<(f64, f64)>,
    /// The run (partial when it diverged).
    pub run: ContactRun,
    /// How it diverged, if it did.
    pub diverged: Option<DivergenceError>,
    /// Wall time of the run.
    pub wall_time: Duration,
}
