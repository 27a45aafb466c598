//! What a run is told besides its step: the start procedure, the stability policy and what to
//! record (validated against the model in [`super::record`]).

/// How the first half-step velocity is formed from `u^0`, `v^0` and `a^0 = M^-1 (F(0) - K u^0)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Start {
    /// `v^{1/2} = v^0 + dt/2 a^0`: the predictor-corrector start of seed eqs. 2-4. With the
    /// Heaviside convention H(0) = 1 it is exact at Co = 1 (methods.md §2).
    #[default]
    HalfStep,
    /// The naive three-level start `u^{-1} = u^0 - dt v^0`, `u^1 = 2u^0 - u^{-1} + dt^2 a^0`,
    /// i.e. `v^{1/2} = v^0 + dt a^0`. Exact only when `F(0)` is half the step load; with the full
    /// load it injects a spurious one-element pulse (methods.md §2).
    ThreeLevel,
}

/// What to do about the stability limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StabilityPolicy {
    /// Run even when `dt` exceeds the exact critical step (for Park's scheme also
    /// `alpha_e > 1`, run with the true `alpha_e`:
    /// [`ParkStep::allowing_unstable`](crate::kernels::park::ParkStep::allowing_unstable)).
    pub allow_unstable: bool,
    /// A run stops as diverged when `kinetic + strain` exceeds this multiple of its energy
    /// reference (largest of the initial energy and the external work so far).
    pub blowup_energy_ratio: f64,
}

impl Default for StabilityPolicy {
    fn default() -> Self {
        Self {
            allow_unstable: false,
            blowup_energy_ratio: 1e6,
        }
    }
}

/// What a run records.
#[derive(Debug, Clone, PartialEq)]
pub struct OutputRequest {
    /// Steps at which to record element stress profiles.
    pub profile_steps: Vec<usize>,
    /// Nodes whose `u, v, a` histories to record.
    pub history_nodes: Vec<usize>,
    /// Record histories every this many steps (>= 1).
    pub history_every: usize,
    /// Keep an energy sample every this many steps (>= 1); the balance is checked every step.
    pub energy_every: usize,
}

impl Default for OutputRequest {
    fn default() -> Self {
        Self {
            profile_steps: Vec::new(),
            history_nodes: Vec::new(),
            history_every: 1,
            energy_every: 1,
        }
    }
}
