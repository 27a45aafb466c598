//! The record of a contact stability sweep (seed Fig. 3).

use std::time::Duration;

/// One point of the sweep: the critical Courant number of the contact-active system at one
/// penalty stiffness and ratio, from the solver's eigenvalues.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepPoint {
    /// `beta_s`.
    pub beta_s: f64,
    /// Penalty ratio, `None` for penalty only.
    pub ratio: Option<f64>,
    /// Critical Courant number of the contact-active system.
    pub courant: f64,
}

/// The points of a sweep, curve by curve.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRecord {
    /// Points, curve by curve.
    pub points: Vec<SweepPoint>,
    /// Wall time.
    pub wall_time: Duration,
}
