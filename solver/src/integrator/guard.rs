//! The blow-up guard of a run: the energy reference and the test for divergence.

use crate::model::Model;

/// Detects an unstable run: kinetic + strain energy far above every energy that entered the bar.
///
/// A stable central-difference run has `T + U = W + E^0 + dt^2/8 a M a` (full-step kinetic
/// energy `T`), where the last term is at most of the order of the impulse energy
/// `sum_j dt^2 F_j^2/(8 m_j)` of the loads. The reference is the largest of the initial energy,
/// `|W|` and that impulse energy seen so far; the run has diverged when `T + U` exceeds
/// `ratio` times it, or is not finite.
pub(super) struct BlowUpGuard {
    ratio: f64,
    reference: f64,
}

impl BlowUpGuard {
    pub(super) fn new(ratio: f64, initial_energy: f64) -> Self {
        Self {
            ratio,
            reference: initial_energy,
        }
    }

    pub(super) fn admit(&mut self, energy: f64) {
        self.reference = self.reference.max(energy);
    }

    /// `Some(T+U / reference)` when the run has diverged.
    pub(super) fn tripped(&self, mechanical: f64) -> Option<f64> {
        if mechanical <= self.ratio * self.reference {
            None
        } else if mechanical.is_finite() {
            Some(mechanical / self.reference)
        } else {
            Some(f64::INFINITY)
        }
    }
}

/// `sum_j dt^2 F_j^2 / (8 m_j)`: the kinetic energy one step of the loads alone gives the
/// full-step velocity.
pub(super) fn impulse_energy(model: &Model, dt: f64, forces: &[(usize, f64)]) -> f64 {
    forces
        .iter()
        .map(|&(node, f)| 0.125 * dt * dt * f * f * model.inverse_mass()[node])
        .sum()
}
