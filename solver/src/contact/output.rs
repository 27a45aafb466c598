//! What a contact run is asked to record and what it returns: samples of every level (force,
//! gap, impulse, energies), stress profiles, and the run's summary (momenta, largest force).

use super::scheme::ContactScheme;
use super::stability::ContactCriticalStep;

/// One level `t^n` of a contact run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactSample {
    /// Step index n.
    pub step: usize,
    /// `t^n = n dt`.
    pub time: f64,
    /// Contact force, compression positive: the momentum `J^n` delivered to the real masses at
    /// level n over the span of the level's velocity update (`dt`, or `dt/2` at n = 0),
    /// stamped `t^n` (methods.md §7).
    pub force: f64,
    /// `eps_s x penetration = k_s max(0, -g^n)` (0 for the Lagrange multiplier method). Not the
    /// contact force once a mass penalty acts, nor for the predictor-corrector scheme.
    pub penalty_force: f64,
    /// Gap `g^n = N^T u^n + g0`.
    pub gap: f64,
    /// Whether the scheme applied contact at level n (CD: `g^n < 0`; predictor-corrector and
    /// Lagrange multiplier: predicted `g^{n+1} < 0`).
    pub active: bool,
    /// Cumulative contact impulse `sum_{k <= n} J^k`.
    pub impulse: f64,
    /// Kinetic energy `1/2 v^n M v^n`, `v^n = (v^{n-1/2} + v^{n+1/2})/2` (`v^0` at n = 0).
    pub kinetic: f64,
    /// Central difference's staggered kinetic term `1/2 v^{n-1/2} M v^{n+1/2}` (`kinetic` at
    /// n = 0, where `v^{-1/2}` does not exist). With `strain` it is the energy CD conserves
    /// exactly for free bodies (`1/2 v^{n-1/2} M v^{n+1/2} + 1/2 u^n K u^n`, Hughes 1987, §9.1),
    /// positive definite below the critical step; unlike `kinetic` it does not count the
    /// step-scale oscillation of a mode near the limit as energy.
    pub kinetic_staggered: f64,
    /// Strain energy `1/2 u^n K u^n`.
    pub strain: f64,
    /// Penalty spring energy `1/2 k_s min(g^n, 0)^2`.
    pub penalty_spring: f64,
    /// Penalty-mass kinetic energy `1/2 m_p (N^T v^n)^2` while active, for CD bipenalty (the
    /// only scheme in which the penalty mass carries a state; the predictor-corrector scheme
    /// only weights its correction with it). It appears when the contact switches on with a
    /// nonzero relative velocity: a property of the bipenalty functional, not energy gained by
    /// the bodies.
    pub penalty_kinetic: f64,
    /// `kinetic + strain + penalty_spring + penalty_kinetic`.
    pub total: f64,
}

/// Element stresses of every body at one level.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactProfile {
    /// Step index n.
    pub step: usize,
    /// `t^n`.
    pub time: f64,
    /// `sigma_e^n` per body ([`Model::element_stress`](crate::model::Model::element_stress)).
    pub stress: Vec<Vec<f64>>,
}

/// What a contact run records.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRequest {
    /// Keep a [`ContactSample`] every this many steps (>= 1); step 0 and the last step always.
    pub history_every: usize,
    /// Steps at which to record stress profiles.
    pub profile_steps: Vec<usize>,
}

impl Default for ContactRequest {
    fn default() -> Self {
        Self {
            history_every: 1,
            profile_steps: Vec::new(),
        }
    }
}

/// Everything a contact run recorded.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRun {
    /// The scheme.
    pub scheme: ContactScheme,
    /// Time step.
    pub dt: f64,
    /// Steps taken (fewer than planned when the run diverged).
    pub steps: usize,
    /// Courant number relative to the stiffest element.
    pub courant: f64,
    /// The critical steps of the problem under the scheme.
    pub critical: ContactCriticalStep,
    /// Samples at the requested interval.
    pub history: Vec<ContactSample>,
    /// Stress profiles at the requested steps that were reached.
    pub profiles: Vec<ContactProfile>,
    /// Total contact impulse.
    pub impulse: f64,
    /// Momentum `sum_i m_i v_i^0` of each body at the start.
    pub initial_momentum: Vec<f64>,
    /// Momentum `sum_i m_i v_i^{n+1/2}` of each body after the last step n.
    pub final_momentum: Vec<f64>,
    /// Largest `|force|` over every step.
    pub max_force: f64,
}
