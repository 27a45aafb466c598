//! The step kernel a run advances: the fused lumped one, the one with a matrix mass, or Park's
//! scheme, behind one interface.

use crate::kernel::{LumpedCentralDifference, StepEnergy};
use crate::matrix_kernel::MatrixCentralDifference;
use crate::model::Model;
use crate::park::ParkScheme;

/// The step kernel of a run: the fused lumped one, or the one with a matrix mass.
pub(super) enum Kernel {
    Lumped(LumpedCentralDifference),
    Matrix(Box<MatrixCentralDifference>),
    Park(Box<ParkScheme>),
}

impl Kernel {
    pub(super) fn dt(&self) -> f64 {
        match self {
            Kernel::Lumped(k) => k.dt(),
            Kernel::Matrix(k) => k.dt(),
            Kernel::Park(k) => k.dt(),
        }
    }

    pub(super) fn displacement(&self) -> &[f64] {
        match self {
            Kernel::Lumped(k) => k.displacement(),
            Kernel::Matrix(k) => k.displacement(),
            Kernel::Park(k) => k.displacement(),
        }
    }

    /// Advance from `t^n = t`; `forces` are the loads at `t^{n+1}` by node.
    pub(super) fn step_with_energy(
        &mut self,
        model: &Model,
        t: f64,
        forces: &[(usize, f64)],
    ) -> StepEnergy {
        match self {
            Kernel::Lumped(k) => k.step_with_energy(forces),
            Kernel::Matrix(k) => k.step_with_energy(forces),
            Kernel::Park(k) => k.step(model, t),
        }
    }

    /// `1/2 v^{n-1/2} M v^{n+1/2}` recomputed from the mass matrix, for kernels that carry it
    /// forward incrementally (`None` for the others).
    pub(super) fn staggered_from_mass(&mut self) -> Option<f64> {
        match self {
            Kernel::Matrix(k) => Some(k.staggered_kinetic_from_mass()),
            _ => None,
        }
    }

    /// `(v^n, a^n)` at node `i` of the current state (time `t`): for CD `v^n = v^{n+1/2} - dt/2 a^n`,
    /// with `a^n` local for the lumped mass and the kept solve otherwise; Park keeps both.
    pub(super) fn velocity_and_acceleration_at(
        &self,
        model: &Model,
        i: usize,
        t: f64,
    ) -> (f64, f64) {
        let (v_half, a) = match self {
            Kernel::Lumped(k) => (
                k.half_step_velocity()[i],
                model.acceleration_at(k.displacement(), i, t),
            ),
            Kernel::Matrix(k) => (k.half_step_velocity()[i], k.acceleration()[i]),
            Kernel::Park(k) => return (k.velocity()[i], k.acceleration()[i]),
        };
        (v_half - 0.5 * self.dt() * a, a)
    }
}
