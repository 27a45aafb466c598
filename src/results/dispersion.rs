//! The record of a dispersion case: the measured phase of single standing modes.

/// A single-mode measurement (see `run::dispersion` for how it is taken).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeMeasurement {
    /// `kh = n pi / N`.
    pub kh: f64,
    /// Phase per step `theta = omega_hat dt`.
    pub phase_per_step: f64,
    /// `omega_hat / (c k)`.
    pub phase_speed_ratio: f64,
    /// Steps run.
    pub steps: usize,
    /// Largest `|u_j^s - cos(s theta) u_j^0|` over nodes and steps: how single the mode stayed.
    pub mode_leak: f64,
}

/// The measured modes of one dispersion case.
#[derive(Debug, Clone, PartialEq)]
pub struct DispersionRecord {
    /// Case name.
    pub case: String,
    /// `(mode number, measurement)`, in the case's mode order.
    pub modes: Vec<(usize, ModeMeasurement)>,
}
