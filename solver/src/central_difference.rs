//! Central-difference integration of a lumped-mass bar: start, time loop, outputs, energy
//! balance, stability guard.
//!
//! The energy identity the balance relies on (linear system, lumped `M`, any `dt`): with
//! `E^n = 1/2 v^{n-1/2} M v^{n+1/2} + 1/2 u^n K u^n` and
//! `v^{n+3/2} - v^{n-1/2} = dt (a^n + a^{n+1}) = dt M^-1 (F^n + F^{n+1} - K (u^n + u^{n+1}))`,
//!
//! ```text
//!   E^{n+1} - E^n = 1/2 dt v^{n+1/2} (F^n + F^{n+1}) - 1/2 (u^{n+1} - u^n) K (u^{n+1} + u^n)
//!                   + 1/2 (u^{n+1} K u^{n+1} - u^n K u^n)
//!                 = 1/2 (F^n + F^{n+1}) (u^{n+1} - u^n),
//! ```
//!
//! the trapezoidal work increment, exactly. So `E^n - W^n` is constant to round-off.

use crate::error::{DivergenceError, InputError, UnstableStepError};
use crate::kernel::{LumpedCentralDifference, StepEnergy};
use crate::mass::{MassKind, MassOperator};
use crate::matrix_kernel::{MatrixCentralDifference, StartState};
use crate::model::Model;
use crate::output::{
    EnergyLog, EnergySample, HistorySample, NodeHistory, RunOutput, StressProfile,
};
use crate::park::{ParkOptions, ParkScheme};
use crate::stability::CriticalStep;
use thiserror::Error;

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
    /// `alpha_e > 1`, run with the true `alpha_e`: [`ParkScheme::allowing_unstable`]).
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

/// Central difference with lumped mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CentralDifference {
    /// Time step.
    pub dt: f64,
    /// Start procedure.
    pub start: Start,
    /// Stability guard.
    pub stability: StabilityPolicy,
    /// Mass matrix (default lumped).
    pub mass: MassKind,
    /// Replace the CD predictor by Park's pull-back scheme (lumped mass only; `theta = 0` is
    /// CD). Default `None`.
    pub park: Option<ParkOptions>,
}

/// The stability limit of the scheme a [`CentralDifference`] runs: the largest stable step and
/// where it comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SchemeLimit {
    /// Central difference (any mass): `dt <= 2/omega_max` of the assembled `(K, M)`
    /// ([`CriticalStep::exact`]; Hughes, *The Finite Element Method*, 2000, §9.3).
    CentralDifference {
        /// `2/omega_max`.
        dt: f64,
    },
    /// Park's scheme: `alpha_e = dt/dt_e <= 1` in every element (methods.md §6), i.e.
    /// `dt <= min_e dt_e` ([`ParkScheme::limit_step`]). The bound comes from the amplification
    /// analysis of a uniform mesh, whose spectral radius exceeds 1 just above `alpha = 1` at
    /// `kh = pi` (tests/park_amplification_analysis.rs): on a mesh where every element has the
    /// same `dt_e` it is the limit (up to the finite mesh's top mode, a hair below `kh = pi`); on a
    /// graded mesh it is only sufficient (measured: Park's global step on the `graded_1e4` mesh
    /// stays bounded at `alpha = 1.012`).
    Park {
        /// `min_e dt_e`.
        dt: f64,
        /// The element with the smallest `dt_e` (the first whose `alpha_e` exceeds 1).
        element: usize,
        /// True when the elements' `dt_e` differ (relative spread above 1e-12): `alpha_e <= 1`
        /// guarantees stability but above it nothing is predicted.
        sufficient_only: bool,
    },
}

impl SchemeLimit {
    /// The limit of central difference (`park = None`) or of Park's scheme with `park` on
    /// `model`, given the critical steps of its mass: CD's `critical.exact`, or Park's
    /// `alpha_e <= 1` (at or below CD's for the lumped mass: Fried's bound
    /// `omega_max <= max_e 2 c_e/h_e` gives `2/omega_max >= min_e h_e/c_e`).
    pub fn of(park: Option<&ParkOptions>, model: &Model, critical: &CriticalStep) -> Self {
        match park {
            None => SchemeLimit::CentralDifference { dt: critical.exact },
            Some(_) => {
                let bar = model.bar();
                let dt = ParkScheme::limit_step(model);
                let slowest = (0..bar.element_count())
                    .map(|e| bar.element_transit_time(e))
                    .fold(dt, f64::max);
                SchemeLimit::Park {
                    dt,
                    element: bar.stiffest_element().0,
                    sufficient_only: slowest > dt * (1.0 + 1e-12),
                }
            }
        }
    }

    /// The largest stable step.
    pub fn dt(&self) -> f64 {
        match *self {
            SchemeLimit::CentralDifference { dt } | SchemeLimit::Park { dt, .. } => dt,
        }
    }

    /// What the limit is, for tables: `2/omega_max`, `alpha_e <= 1`, or `alpha_e <= 1
    /// (sufficient)` on a graded mesh.
    pub fn name(&self) -> &'static str {
        match self {
            SchemeLimit::CentralDifference { .. } => "2/omega_max",
            SchemeLimit::Park {
                sufficient_only: false,
                ..
            } => "alpha_e <= 1",
            SchemeLimit::Park {
                sufficient_only: true,
                ..
            } => "alpha_e <= 1 (sufficient)",
        }
    }

    /// True when the limit only guarantees stability below it and predicts nothing above.
    pub fn sufficient_only(&self) -> bool {
        matches!(
            self,
            SchemeLimit::Park {
                sufficient_only: true,
                ..
            }
        )
    }
}

/// Why a run did not complete.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RunError {
    /// Bad parameters; nothing ran.
    #[error(transparent)]
    Input(#[from] InputError),
    /// `dt` above the critical step and unstable runs not allowed; nothing ran.
    #[error(transparent)]
    Unstable(#[from] UnstableStepError),
    /// An allowed unstable run blew up; `partial` holds everything recorded before.
    #[error("{error}")]
    Diverged {
        /// Where and how it diverged.
        error: DivergenceError,
        /// Outputs up to the divergence.
        partial: Box<RunOutput>,
    },
}

impl CentralDifference {
    /// Central difference with step `dt`, the half-step start and the default stability guard.
    pub fn new(dt: f64) -> Self {
        Self {
            dt,
            start: Start::HalfStep,
            stability: StabilityPolicy::default(),
            mass: MassKind::Lumped,
            park: None,
        }
    }

    /// Refuse `dt` above the exact critical step, and for Park's scheme above its own limit
    /// `alpha_e <= 1` too ([`SchemeLimit::Park`]), with the relative allowance
    /// [`crate::time_step::ROUNDING_SLACK`] of the time plan (so that Co = 1 on a free-free
    /// uniform bar, where `dt = dt_crit`, is accepted after the plan's rounding).
    pub fn check_stability(&self, model: &Model) -> Result<CriticalStep, RunError> {
        let operator = MassOperator::new(model, self.mass)?;
        Ok(self.check_stability_with(model, &operator)?)
    }

    /// The stability limit of this integrator's scheme on `model`, given the critical steps of
    /// its mass (from [`CentralDifference::check_stability`]): [`SchemeLimit::of`].
    pub fn limit(&self, model: &Model, critical: &CriticalStep) -> SchemeLimit {
        SchemeLimit::of(self.park.as_ref(), model, critical)
    }

    fn check_stability_with(
        &self,
        model: &Model,
        operator: &MassOperator,
    ) -> Result<CriticalStep, UnstableStepError> {
        let critical = CriticalStep::of(model, self.mass, operator);
        if self.stability.allow_unstable {
            return Ok(critical);
        }
        // Park's limit lies at or below CD's (Fried: 2/omega_max >= min_e h_e/c_e), so the
        // scheme's own limit is the one to check.
        let limit = self.limit(model, &critical);
        if self.dt > limit.dt() * (1.0 + crate::time_step::ROUNDING_SLACK) {
            return Err(UnstableStepError {
                dt: self.dt,
                dt_crit: limit.dt(),
                limit: limit.name(),
                courant: model.bar().courant_number(self.dt),
                element: critical.controlling_element,
                element_dt: critical.element_transit,
            });
        }
        Ok(critical)
    }

    /// Integrate `steps` steps from the model's initial state.
    pub fn run(
        &self,
        model: &Model,
        steps: usize,
        request: &OutputRequest,
    ) -> Result<RunOutput, RunError> {
        crate::mesh::positive("dt", self.dt)?;
        validate_request(model, steps, request)?;
        let operator = MassOperator::new(model, self.mass)?;
        self.check_stability_with(model, &operator)?;
        let dt = self.dt;
        let nodes = model.bar().node_count();

        // Loads: unique sorted nodes, each load mapped to its node's slot.
        let mut load_nodes: Vec<usize> = model.loads().iter().map(|l| l.node).collect();
        load_nodes.sort_unstable();
        load_nodes.dedup();
        let slots: Vec<usize> = model
            .loads()
            .iter()
            .map(|l| load_nodes.binary_search(&l.node).unwrap_or(0))
            .collect();
        let mut forces: Vec<(usize, f64)> = load_nodes.iter().map(|&n| (n, 0.0)).collect();
        let eval_forces = |t: f64, forces: &mut Vec<(usize, f64)>| {
            forces.iter_mut().for_each(|f| f.1 = 0.0);
            for (load, &slot) in model.loads().iter().zip(&slots) {
                forces[slot].1 += load.force(t);
            }
        };

        // Start: a^0 = M^-1 (F(0) - K u^0).
        let u0 = model.initial_displacement();
        let v0 = model.initial_velocity();
        let r0: Vec<f64> = (0..nodes)
            .map(|i| model.external_force_at(i, 0.0) + model.internal_force_at(u0, i))
            .collect();
        let mut a0 = vec![0.0; nodes];
        operator.apply_inverse(&r0, &mut a0);
        let start_factor = match self.start {
            Start::HalfStep => 0.5,
            Start::ThreeLevel => 1.0,
        };
        let v_half: Vec<f64> = (0..nodes)
            .map(|i| v0[i] + start_factor * dt * a0[i])
            .collect();
        // v^{-1/2} = v^{1/2} - dt a^0: the recurrence run backwards one step (for the half-step
        // start v^0 is then the mean of the two half steps; for the three-level start
        // v^{-1/2} = v^0, i.e. u^{-1} = u^0 - dt v^0).
        let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(a, b)| a * b).sum::<f64>();
        let mut m_times = vec![0.0; nodes];
        operator.apply(&v_half, &mut m_times);
        let v_before: Vec<f64> = (0..nodes).map(|i| v_half[i] - dt * a0[i]).collect();
        let kinetic_staggered0 = 0.5 * dot(&v_before, &m_times);
        operator.apply(v0, &mut m_times);
        let kinetic0 = 0.5 * dot(v0, &m_times);
        let strain0 = model.strain_energy(u0);
        // For Park's scheme too: its step reports T - dt^2/8 a M a, which is CD's conserved
        // staggered energy when the scheme reduces to CD (theta = 0 or alpha = 1), so the
        // balance then measures only Park's own dissipation.
        let invariant0 = kinetic_staggered0 + strain0;

        let mut kernel = match (self.park, self.mass) {
            (Some(options), MassKind::Lumped) => {
                let mut park = if self.stability.allow_unstable {
                    ParkScheme::allowing_unstable(model, dt, options)?
                } else {
                    ParkScheme::new(model, dt, options)?
                };
                park.start(model);
                Kernel::Park(Box::new(park))
            }
            (Some(_), _) => {
                return Err(InputError::Other(
                    "Park's scheme runs with the lumped mass only".into(),
                )
                .into());
            }
            (None, MassKind::Lumped) => {
                Kernel::Lumped(LumpedCentralDifference::new(model, dt, u0, &v_half))
            }
            (None, _) => Kernel::Matrix(Box::new(MatrixCentralDifference::new(
                dt,
                model.stiffness(),
                operator,
                &StartState {
                    displacement: u0,
                    half_step_velocity: &v_half,
                    acceleration: &a0,
                    residual: &r0,
                    kinetic_staggered: kinetic_staggered0,
                },
            ))),
        };
        let mut output = RunOutput {
            dt,
            steps: 0,
            courant: model.bar().courant_number(dt),
            profiles: Vec::with_capacity(request.profile_steps.len()),
            histories: request
                .history_nodes
                .iter()
                .map(|&node| NodeHistory {
                    node,
                    x: model.bar().mesh().nodes()[node],
                    samples: Vec::new(),
                })
                .collect(),
            energy: EnergyLog::default(),
        };
        let mut profile_steps: Vec<usize> = request.profile_steps.clone();
        profile_steps.sort_unstable();
        profile_steps.dedup();
        let mut next_profile = profile_steps.iter().peekable();

        let first = EnergySample {
            step: 0,
            time: 0.0,
            kinetic: kinetic0,
            kinetic_staggered: kinetic_staggered0,
            strain: strain0,
            work: 0.0,
            balance_error: 0.0,
        };
        output.energy.samples.push(first);
        output.energy.scale = kinetic0 + strain0;
        let mut guard = BlowUpGuard::new(self.stability.blowup_energy_ratio, kinetic0 + strain0);
        let mut max_work = 0.0_f64;
        record(
            model,
            &kernel,
            0,
            0.0,
            v0,
            request,
            &mut output,
            &mut next_profile,
        );

        eval_forces(0.0, &mut forces);
        guard.admit(impulse_energy(model, dt, &forces));
        let mut previous_forces = forces.clone();
        let mut work = 0.0;
        let mut displaced = vec![0.0; forces.len()];
        for step in 1..=steps {
            let t = step as f64 * dt;
            eval_forces(t, &mut forces);
            // Trapezoidal work: 1/2 (F^n + F^{n+1}) (u^{n+1} - u^n) at the loaded nodes.
            for (slot, f) in displaced.iter_mut().zip(&forces) {
                *slot = kernel.displacement()[f.0];
            }
            let sums = kernel.step_with_energy(model, t - dt, &forces);
            let u = kernel.displacement();
            work += forces
                .iter()
                .zip(&previous_forces)
                .zip(&displaced)
                .map(|((f, f0), u0)| 0.5 * (f.1 + f0.1) * (u[f.0] - u0))
                .sum::<f64>();
            guard.admit(work.abs());
            guard.admit(impulse_energy(model, dt, &forces));
            std::mem::swap(&mut forces, &mut previous_forces);

            let balance_error = sums.kinetic_staggered + sums.strain - work - invariant0;
            let mechanical = sums.kinetic + sums.strain;
            max_work = max_work.max(work.abs());
            let energy = &mut output.energy;
            energy.max_balance_error = energy.max_balance_error.max(balance_error.abs());
            energy.scale = energy.scale.max(max_work).max(mechanical);
            output.steps = step;
            if let Some(energy_ratio) = guard.tripped(mechanical) {
                let u = kernel.displacement();
                let node = (0..nodes).fold(0, |best, i| {
                    if u[i].abs() > u[best].abs() || u[i].is_nan() {
                        i
                    } else {
                        best
                    }
                });
                let error = DivergenceError {
                    step,
                    time: t,
                    node,
                    energy_ratio,
                    courant: output.courant,
                };
                return Err(RunError::Diverged {
                    error,
                    partial: Box::new(output),
                });
            }
            if step.is_multiple_of(request.energy_every) || step == steps {
                // A matrix mass carries T* forward by its exact increments; at each sample it is
                // recomputed from M itself, and any mismatch counts as balance error.
                let balance_error = match kernel.staggered_from_mass() {
                    Some(from_mass) => balance_error + (from_mass - sums.kinetic_staggered),
                    None => balance_error,
                };
                energy.max_balance_error = energy.max_balance_error.max(balance_error.abs());
                energy.samples.push(EnergySample {
                    step,
                    time: t,
                    kinetic: sums.kinetic,
                    kinetic_staggered: sums.kinetic_staggered,
                    strain: sums.strain,
                    work,
                    balance_error,
                });
            }
            record(
                model,
                &kernel,
                step,
                t,
                &[],
                request,
                &mut output,
                &mut next_profile,
            );
        }
        Ok(output)
    }
}

/// The step kernel of a run: the fused lumped one, or the one with a matrix mass.
enum Kernel {
    Lumped(LumpedCentralDifference),
    Matrix(Box<MatrixCentralDifference>),
    Park(Box<ParkScheme>),
}

impl Kernel {
    fn dt(&self) -> f64 {
        match self {
            Kernel::Lumped(k) => k.dt(),
            Kernel::Matrix(k) => k.dt(),
            Kernel::Park(k) => k.dt(),
        }
    }

    fn displacement(&self) -> &[f64] {
        match self {
            Kernel::Lumped(k) => k.displacement(),
            Kernel::Matrix(k) => k.displacement(),
            Kernel::Park(k) => k.displacement(),
        }
    }

    /// Advance from `t^n = t`; `forces` are the loads at `t^{n+1}` by node.
    fn step_with_energy(&mut self, model: &Model, t: f64, forces: &[(usize, f64)]) -> StepEnergy {
        match self {
            Kernel::Lumped(k) => k.step_with_energy(forces),
            Kernel::Matrix(k) => k.step_with_energy(forces),
            Kernel::Park(k) => k.step(model, t),
        }
    }

    /// `1/2 v^{n-1/2} M v^{n+1/2}` recomputed from the mass matrix, for kernels that carry it
    /// forward incrementally (`None` for the others).
    fn staggered_from_mass(&mut self) -> Option<f64> {
        match self {
            Kernel::Matrix(k) => Some(k.staggered_kinetic_from_mass()),
            _ => None,
        }
    }

    /// `(v^n, a^n)` at node `i` of the current state (time `t`): for CD `v^n = v^{n+1/2} - dt/2 a^n`,
    /// with `a^n` local for the lumped mass and the kept solve otherwise; Park keeps both.
    fn velocity_and_acceleration_at(&self, model: &Model, i: usize, t: f64) -> (f64, f64) {
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

/// Detects an unstable run: kinetic + strain energy far above every energy that entered the bar.
///
/// A stable central-difference run has `T + U = W + E^0 + dt^2/8 a M a` (full-step kinetic
/// energy `T`), where the last term is at most of the order of the impulse energy
/// `sum_j dt^2 F_j^2/(8 m_j)` of the loads. The reference is the largest of the initial energy,
/// `|W|` and that impulse energy seen so far; the run has diverged when `T + U` exceeds
/// `ratio` times it, or is not finite.
struct BlowUpGuard {
    ratio: f64,
    reference: f64,
}

impl BlowUpGuard {
    fn new(ratio: f64, initial_energy: f64) -> Self {
        Self {
            ratio,
            reference: initial_energy,
        }
    }

    fn admit(&mut self, energy: f64) {
        self.reference = self.reference.max(energy);
    }

    /// `Some(T+U / reference)` when the run has diverged.
    fn tripped(&self, mechanical: f64) -> Option<f64> {
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
fn impulse_energy(model: &Model, dt: f64, forces: &[(usize, f64)]) -> f64 {
    forces
        .iter()
        .map(|&(node, f)| 0.125 * dt * dt * f * f * model.inverse_mass()[node])
        .sum()
}

fn validate_request(
    model: &Model,
    steps: usize,
    request: &OutputRequest,
) -> Result<(), InputError> {
    let last = model.bar().node_count() - 1;
    if let Some(&node) = request.history_nodes.iter().find(|&&n| n > last) {
        return Err(InputError::NodeIndex {
            field: "history node",
            node,
            last,
        });
    }
    if let Some(&step) = request.profile_steps.iter().find(|&&s| s > steps) {
        return Err(InputError::Other(format!(
            "profile step {step} is after the last step {steps}"
        )));
    }
    if request.history_every == 0 || request.energy_every == 0 {
        return Err(InputError::Other(
            "history_every and energy_every must be at least 1".into(),
        ));
    }
    Ok(())
}

/// Record profiles and histories at step `n` (state `u^n`, `v^{n+1/2}` in the kernel).
#[allow(clippy::too_many_arguments)]
fn record<'a>(
    model: &Model,
    kernel: &Kernel,
    step: usize,
    time: f64,
    initial_velocity: &[f64],
    request: &OutputRequest,
    output: &mut RunOutput,
    next_profile: &mut std::iter::Peekable<std::slice::Iter<'a, usize>>,
) {
    let u = kernel.displacement();
    if next_profile.peek() == Some(&&step) {
        next_profile.next();
        output.profiles.push(StressProfile {
            step,
            time,
            stress: model.element_stress(u),
        });
    }
    if step.is_multiple_of(request.history_every) && !output.histories.is_empty() {
        for history in &mut output.histories {
            let i = history.node;
            let (velocity, acceleration) = kernel.velocity_and_acceleration_at(model, i, time);
            // At n = 0 the state's own v^0.
            let velocity = if step == 0 {
                initial_velocity[i]
            } else {
                velocity
            };
            history.samples.push(HistorySample {
                step,
                time,
                displacement: u[i],
                velocity,
                acceleration,
            });
        }
    }
}
