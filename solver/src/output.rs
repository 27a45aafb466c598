//! What a run records: stress profiles at requested steps, nodal histories, and the energy log.

/// Element stresses at one time level `t^n` (methods.md §2: `sigma_e^n` lives at `t^n`).
#[derive(Debug, Clone, PartialEq)]
pub struct StressProfile {
    /// Step index `n`.
    pub step: usize,
    /// Time `t^n = n dt`.
    pub time: f64,
    /// `sigma_e^n = E_e (u_{e+1}^n - u_e^n)/h_e`, one per element.
    pub stress: Vec<f64>,
}

/// One sample of a nodal history at `t^n`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HistorySample {
    /// Step index `n`.
    pub step: usize,
    /// Time `t^n`.
    pub time: f64,
    /// Displacement `u^n`.
    pub displacement: f64,
    /// Full-step velocity `v^n = (v^{n-1/2} + v^{n+1/2})/2` (seed eq. 4); `v^0` is the initial value.
    pub velocity: f64,
    /// Acceleration `a^n = M^-1 (F^n - K u^n)`.
    pub acceleration: f64,
}

/// The history of one node.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeHistory {
    /// Node index.
    pub node: usize,
    /// Node position.
    pub x: f64,
    /// Samples in time order.
    pub samples: Vec<HistorySample>,
}

/// Energies at one time level `t^n`.
///
/// The balance uses the energy that central difference conserves exactly for linear systems,
/// `E^n = 1/2 v^{n-1/2} M v^{n+1/2} + 1/2 u^n K u^n`, whose increments equal the trapezoidal work
/// `W^{n+1} - W^n = 1/2 (F^n + F^{n+1}) (u^{n+1} - u^n)` (e.g. Hughes, The Finite Element Method
/// (1987), §9.1; derivation in the integrator's doc). `balance_error = E^n - W^n - (E^0 - W^0)`
/// is therefore round-off for every stable Courant number.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnergySample {
    /// Step index `n`.
    pub step: usize,
    /// Time `t^n`.
    pub time: f64,
    /// `1/2 v^n M v^n` with the full-step velocity.
    pub kinetic: f64,
    /// `1/2 v^{n-1/2} M v^{n+1/2}`, the kinetic part of the conserved energy.
    pub kinetic_staggered: f64,
    /// `1/2 u^n K u^n`.
    pub strain: f64,
    /// External work, trapezoidal in time.
    pub work: f64,
    /// `kinetic_staggered + strain - work`, minus its value at step 0.
    pub balance_error: f64,
}

/// The energy log of a run.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct EnergyLog {
    /// Samples at the requested interval (always including step 0 and the last step).
    pub samples: Vec<EnergySample>,
    /// Largest `|balance_error|` over every step, sampled or not.
    pub max_balance_error: f64,
    /// Energy scale: the largest of `|W|`, `kinetic + strain` and the initial energy over every step.
    pub scale: f64,
}

impl EnergyLog {
    /// `max_balance_error / scale` (0 when nothing moved).
    pub fn relative_balance_error(&self) -> f64 {
        if self.scale > 0.0 {
            self.max_balance_error / self.scale
        } else {
            0.0
        }
    }
}

/// Everything a run recorded.
#[derive(Debug, Clone, PartialEq)]
pub struct RunOutput {
    /// The time step.
    pub dt: f64,
    /// Steps taken (fewer than planned when the run diverged).
    pub steps: usize,
    /// Courant number relative to the stiffest element.
    pub courant: f64,
    /// Stress profiles at the requested steps that were reached.
    pub profiles: Vec<StressProfile>,
    /// Nodal histories.
    pub histories: Vec<NodeHistory>,
    /// Energy log.
    pub energy: EnergyLog,
}
