//! [`CentralDifference`]: the integrator, its stability check and the time loop (start, steps,
//! energy balance, blow-up guard, recording).
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

use super::guard::{BlowUpGuard, impulse_energy};
use super::limit::SchemeLimit;
use super::record::{record, validate_request};
use super::settings::{OutputRequest, StabilityPolicy, Start};
use super::step_kernel::Kernel;
use crate::error::{DivergenceError, InputError, UnstableStepError};
use crate::kernel::LumpedCentralDifference;
use crate::mass::{MassKind, MassOperator};
use crate::matrix_kernel::{MatrixCentralDifference, StartState};
use crate::model::Model;
use crate::output::{EnergyLog, EnergySample, NodeHistory, RunOutput};
use crate::park::{ParkOptions, ParkScheme};
use crate::stability::CriticalStep;
use thiserror::Error;

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
        self.check_stability_with(model, &operator)
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
    ) -> Result<CriticalStep, RunError> {
        let critical = CriticalStep::of(model, self.mass, operator).map_err(InputError::from)?;
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
            }
            .into());
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
