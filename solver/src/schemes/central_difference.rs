//! Central difference through the integrator interface: the `cd` registry entry, its steppers (the
//! fused lumped kernel, `kernels::lumped::kernel`; the matrix-mass kernel,
//! `kernels::matrix_mass::kernel`).
//!
//! Half-step form of the seed's predictor-corrector eqs. 2-4 (methods.md §2): from `u^n`,
//! `v^{n+1/2}`, `u^{n+1} = u^n + dt v^{n+1/2}`, `a^{n+1} = M^-1 (F^{n+1} - K u^{n+1})`,
//! `v^{n+3/2} = v^{n+1/2} + dt a^{n+1}`; start `v^{1/2} = v^0 + dt/2 a^0` (or the naive
//! three-level `v^0 + dt a^0`). Balance energy: `1/2 v^{n-1/2} M v^{n+1/2} + 1/2 u K u`,
//! conserved exactly (module docs of [`crate::integrator::time_loop`]). Limit `2/omega_max`.
//! One internal-force evaluation per step.

use crate::analysis::stability::CriticalStep;
use crate::error::{InputError, RunError};
use crate::integrator::{
    BlockStepper, InitialState, Integrator, RunSetup, Scheme, SchemeEntry, SchemeLimit, Start,
    time_loop,
};
use crate::kernels::energy::StepEnergy;
use crate::kernels::lumped::kernel::LumpedStep;
use crate::kernels::lumped::tiled::StepBlock;
use crate::kernels::matrix_mass::kernel::{MatrixMassStep, StartState};
use crate::mass::{MassKind, MassOperator};
use crate::model::Model;
use crate::output::RunOutput;
use std::sync::Arc;

/// The registry entry of central difference.
pub const ENTRY: SchemeEntry = SchemeEntry {
    name: "cd",
    aliases: &["central-difference"],
    summary: "central difference, half-step velocity form (seed eqs. 2-4); 1 K u per step",
    source: "Kolman et al. (seed), eqs. 2-4, methods.md §2; limit 2/omega_max (Hughes 2000, §9.3)",
    masses: "lmm, cmm, amm(beta), rmm(beta)",
    parameters: &[],
    build: |_| Ok(Arc::new(CentralDifferenceScheme)),
};

/// Central difference with any mass (the `cd` entry).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CentralDifferenceScheme;

impl Scheme for CentralDifferenceScheme {
    fn name(&self) -> &'static str {
        ENTRY.name
    }

    fn label(&self) -> String {
        "cd".into()
    }

    fn force_evaluations(&self) -> usize {
        1
    }

    fn check_settings(&self, _mass: MassKind, _start: Start) -> Result<(), InputError> {
        Ok(())
    }

    fn limit(&self, _model: &Model, critical: &CriticalStep) -> SchemeLimit {
        SchemeLimit::central_difference(critical)
    }

    /// The lumped stepper has blocks of steps ([`time_loop::takes_blocks`] says when a run
    /// takes them); the matrix-mass steppers step singly.
    fn takes_blocks(&self, mass: MassKind, allow_unstable: bool) -> bool {
        time_loop::takes_blocks(mass == MassKind::Lumped, allow_unstable)
    }

    /// Lumped: in blocks of steps; a matrix mass: the step of a long bar in two fixed chunks
    /// (`kernels::matrix_mass::chunks`, CMM/AMM with windows and RMM).
    fn uses_threads(&self, mass: MassKind, allow_unstable: bool) -> bool {
        mass != MassKind::Lumped || self.takes_blocks(mass, allow_unstable)
    }

    fn run(&self, setup: RunSetup<'_>) -> Result<RunOutput, RunError> {
        match setup.mass {
            MassOperator::Diagonal { .. } => time_loop::run_in_blocks::<LumpedStepper>(&(), setup),
            _ => time_loop::run::<MatrixStepper>(&(), setup),
        }
    }
}

/// The half-step start of central difference: `v^{1/2} = v^0 + f dt a^0` (`f` = 1/2, or 1 for
/// the three-level start) and `T*^0 = 1/2 v^{-1/2} M v^{1/2}` with `v^{-1/2} = v^{1/2} - dt a^0`
/// (the recurrence run backwards one step: for the half-step start `v^0` is then the mean of the
/// two half steps; for the three-level start `v^{-1/2} = v^0`, i.e. `u^{-1} = u^0 - dt v^0`).
pub(crate) fn half_step_start(state: &InitialState<'_>) -> (Vec<f64>, f64) {
    let (dt, v0, a0) = (state.dt, state.velocity, state.acceleration);
    let start_factor = match state.start {
        Start::HalfStep => 0.5,
        Start::ThreeLevel => 1.0,
    };
    let v_half: Vec<f64> = (0..v0.len())
        .map(|i| v0[i] + start_factor * dt * a0[i])
        .collect();
    let mut m_times = vec![0.0; v0.len()];
    state.mass.apply(&v_half, &mut m_times);
    // `v^{-1/2}_i (M v^{1/2})_i` summed in increasing i, `v^{-1/2}` formed as it is read.
    let staggered = 0.5
        * (v_half.iter().zip(a0))
            .zip(&m_times)
            .map(|((v, a), m)| (v - dt * a) * m)
            .sum::<f64>();
    (v_half, staggered)
}

/// What the shared [`CentralDifferenceStepper`] needs of a central-difference kernel (state
/// `u^n`, `v^{n+1/2}`): how it is built from the half-step start, its step, and `a^n` at a node.
pub trait CentralDifferenceKernel: Sized {
    /// The kernel started with `v^{1/2}` (taken: a kernel may keep its buffer) and `T*^0` (from
    /// `half_step_start`).
    fn build(state: InitialState<'_>, half_step_velocity: Vec<f64>, staggered0: f64) -> Self;
    /// Time step.
    fn dt(&self) -> f64;
    /// `u^n`.
    fn displacement(&self) -> &[f64];
    /// `v^{n+1/2}`.
    fn half_step_velocity(&self) -> &[f64];
    /// `a^n` at node `i`, time `t`.
    fn acceleration_at(&self, model: &Model, i: usize, t: f64) -> f64;
    /// One step with its energies; `forces` are `F^{n+1}` by node.
    fn step_with_energy(&mut self, forces: &[(usize, f64)]) -> StepEnergy;
    /// `T*` recomputed from the mass (matrix masses only).
    fn staggered_from_mass(&mut self) -> Option<f64> {
        None
    }
}

/// A central-difference kernel that also takes blocks of steps (the lumped kernel's temporal
/// blocking, `kernels::lumped::tiled`): its stepper is then a [`BlockStepper`].
pub trait BlockKernel: CentralDifferenceKernel {
    /// `steps` steps with their energies in one pass, bit-identical to single steps.
    fn step_block(&mut self, block: &mut StepBlock, steps: usize);
    /// `a^n` at node `i` from `[u_{i-1}, u_i, u_{i+1}]` recorded by a block, as
    /// [`CentralDifferenceKernel::acceleration_at`] forms it from the state.
    fn probed_acceleration(&self, model: &Model, i: usize, t: f64, u: [f64; 3]) -> f64;
}

impl CentralDifferenceKernel for LumpedStep {
    fn build(state: InitialState<'_>, half_step_velocity: Vec<f64>, _: f64) -> Self {
        let mut kernel = Self::with_half_step_velocity(
            state.model,
            state.dt,
            state.displacement,
            half_step_velocity,
        );
        kernel.set_threads(state.threads);
        kernel
    }
    fn dt(&self) -> f64 {
        self.dt()
    }
    fn displacement(&self) -> &[f64] {
        self.displacement()
    }
    fn half_step_velocity(&self) -> &[f64] {
        self.half_step_velocity()
    }
    /// Local for the lumped mass: `(F_i - (K u)_i)/m_i`.
    fn acceleration_at(&self, model: &Model, i: usize, t: f64) -> f64 {
        model.acceleration_at(self.displacement(), i, t)
    }
    #[inline]
    fn step_with_energy(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        self.step_with_energy(forces)
    }
}

impl BlockKernel for LumpedStep {
    fn step_block(&mut self, block: &mut StepBlock, steps: usize) {
        self.advance_block::<true>(block, steps);
    }
    /// The lumped acceleration, as `acceleration_at` forms it from the state.
    fn probed_acceleration(&self, model: &Model, i: usize, t: f64, u: [f64; 3]) -> f64 {
        model.acceleration_from(i, u, t)
    }
}

impl CentralDifferenceKernel for MatrixMassStep {
    fn build(state: InitialState<'_>, half_step_velocity: Vec<f64>, staggered0: f64) -> Self {
        let start = StartState {
            displacement: state.displacement,
            half_step_velocity: &half_step_velocity,
            acceleration: state.acceleration,
            residual: state.residual,
            kinetic_staggered: staggered0,
        };
        let mut kernel = Self::new(state.dt, state.model.stiffness(), state.mass, &start);
        kernel.set_threads(state.threads);
        kernel
    }
    fn dt(&self) -> f64 {
        self.dt()
    }
    fn displacement(&self) -> &[f64] {
        self.displacement()
    }
    fn half_step_velocity(&self) -> &[f64] {
        self.half_step_velocity()
    }
    /// `a^n = M^-1 r^n` at node `i` (kept by CMM and AMM with the global factor, one window's
    /// solve with windows, one row of `M^-1` for RMM).
    fn acceleration_at(&self, _: &Model, i: usize, _: f64) -> f64 {
        self.acceleration_at(i)
    }
    #[inline]
    fn step_with_energy(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        self.step_with_energy(forces)
    }
    fn staggered_from_mass(&mut self) -> Option<f64> {
        Some(self.staggered_kinetic_from_mass())
    }
}

/// Central difference as a stepper of the time loop, on one of its kernels.
#[derive(Debug, Clone)]
pub struct CentralDifferenceStepper<K> {
    kernel: K,
    staggered0: f64,
}

/// Central difference with the lumped mass: the fused kernel.
pub type LumpedStepper = CentralDifferenceStepper<LumpedStep>;

/// Central difference with a consistent, averaged or reciprocal mass.
pub type MatrixStepper = CentralDifferenceStepper<MatrixMassStep>;

impl<K: CentralDifferenceKernel> CentralDifferenceStepper<K> {
    /// The stepper around a kernel already started (the contact schemes start it with their
    /// level-0 contact impulse, and keep their own energy accounts: `start_energy` is 0).
    pub fn from_kernel(kernel: K) -> Self {
        Self {
            kernel,
            staggered0: 0.0,
        }
    }

    /// Half-step velocities `v^{n+1/2}`.
    pub fn half_step_velocity(&self) -> &[f64] {
        self.kernel.half_step_velocity()
    }
}

impl<K: CentralDifferenceKernel> Integrator for CentralDifferenceStepper<K> {
    type Parameters = ();

    fn start(_: &(), state: InitialState<'_>) -> Result<Self, InputError> {
        let (v_half, staggered0) = half_step_start(&state);
        Ok(Self {
            kernel: K::build(state, v_half, staggered0),
            staggered0,
        })
    }

    fn dt(&self) -> f64 {
        self.kernel.dt()
    }

    fn displacement(&self) -> &[f64] {
        self.kernel.displacement()
    }

    /// `v^n = v^{n+1/2} - dt/2 a^n`.
    fn velocity_and_acceleration_at(&self, model: &Model, i: usize, t: f64) -> (f64, f64) {
        let a = self.kernel.acceleration_at(model, i, t);
        (self.kernel.half_step_velocity()[i] - 0.5 * self.dt() * a, a)
    }

    #[inline]
    fn step(&mut self, _model: &Model, _t: f64, forces: &[(usize, f64)]) -> StepEnergy {
        self.kernel.step_with_energy(forces)
    }

    fn start_energy(&self) -> f64 {
        self.staggered0
    }

    fn recomputed_balance_kinetic(&mut self) -> Option<f64> {
        self.kernel.staggered_from_mass()
    }
}

impl<K: BlockKernel> BlockStepper for CentralDifferenceStepper<K> {
    fn step_block(&mut self, block: &mut StepBlock, steps: usize) {
        self.kernel.step_block(block, steps);
    }

    /// The kernel's `a^n` from the three displacements, `v^n = v^{n+1/2} - dt/2 a^n`: the
    /// operations of [`Integrator::velocity_and_acceleration_at`].
    fn probed_velocity_and_acceleration(
        &self,
        model: &Model,
        i: usize,
        t: f64,
        u: [f64; 3],
        half_step_velocity: f64,
    ) -> (f64, f64) {
        let a = self.kernel.probed_acceleration(model, i, t, u);
        (half_step_velocity - 0.5 * self.dt() * a, a)
    }
}
