//! [`Integrator`]: what one scheme's time stepper must do for the shared time loop
//! ([`super::time_loop`]), and the [`InitialState`] every stepper is built from.

use super::settings::Start;
use crate::error::InputError;
use crate::kernels::energy::StepEnergy;
use crate::kernels::lumped::tiled::StepBlock;
use crate::mass::MassOperator;
use crate::model::Model;

/// The state every scheme starts from, computed once by the time loop (the same arithmetic for
/// every scheme): `u^0`, `v^0`, the residual `r^0 = F(0) - K u^0` and `a^0 = M^-1 r^0`
/// (0 at fixed nodes), with the assembled mass of the run.
#[derive(Debug)]
pub struct InitialState<'a> {
    /// The model.
    pub model: &'a Model,
    /// The time step.
    pub dt: f64,
    /// `u^0`.
    pub displacement: &'a [f64],
    /// `v^0`.
    pub velocity: &'a [f64],
    /// `a^0 = M^-1 r^0`.
    pub acceleration: &'a [f64],
    /// `r^0 = F(0) - K u^0`.
    pub residual: &'a [f64],
    /// `1/2 v^0 M v^0`.
    pub kinetic: f64,
    /// The start procedure the run was given (central difference's choice; a scheme that has
    /// only one start refuses the other in [`super::Scheme::check_settings`]).
    pub start: Start,
    /// Unstable runs are allowed (a scheme that refuses its own parameters above its limit,
    /// as Park's `alpha_e > 1`, runs them instead).
    pub allow_unstable: bool,
    /// The assembled mass of the run (its to keep: matrix masses are factored once).
    pub mass: MassOperator,
    /// The threads a [`BlockStepper`]'s blocks of steps may use (resolved by
    /// [`super::Integration::threads`]; a stepper without blocks steps on one). The results do
    /// not depend on it.
    pub threads: usize,
}

/// One scheme's time stepper, as the shared time loop drives it (static dispatch: the loop is
/// compiled once per stepper type, so a step costs what the stepper's own code costs).
///
/// The contract:
/// - **Creation** ([`Integrator::start`]): from the scheme's parameters and the
///   [`InitialState`] (model data come with each step): set up everything a step needs. All
///   allocation happens here.
/// - **One step** ([`Integrator::step`]): advance from `t^n = t` to `t^{n+1} = t + dt`, given the
///   external forces `F(t^{n+1})` by node (sorted, each loaded node once); a scheme that needs
///   loads at other times (Park at `t + dt_e`, Noh-Bathe at `t + p dt`) evaluates them from the
///   model. No allocation, O(N) work.
/// - **Outputs**: [`Integrator::displacement`] `u^n` (element stresses are formed from it,
///   `sigma_e = E_e (u_{e+1} - u_e)/h_e`), and [`Integrator::velocity_and_acceleration_at`]
///   `v^n`, `a^n` at a node for histories (the full-step velocity: a staggered scheme averages).
/// - **Energy**: each step returns [`StepEnergy`] at `t^{n+1}`: the full-step kinetic energy
///   `1/2 v M v`, the strain energy `1/2 u K u`, and the kinetic part `T*` of the scheme's
///   *balance energy* (`kinetic_staggered`), and [`Integrator::start_energy`] gives `T*` at
///   `t^0`. The loop checks `T* + U - W` (trapezoidal work `W`) against its start value every
///   step and reports the largest change: round-off for a scheme whose balance energy is
///   conserved (central difference: `1/2 v^{n-1/2} M v^{n+1/2}`), its dissipation otherwise
///   (Park: `T - dt^2/8 a M a`; Noh-Bathe: `T - (p dt)^2/8 a M a`). A scheme without an energy
///   of its own reports `T* = T`: the balance then measures the scheme's energy error. The
///   blow-up guard uses only `T + U`, for every scheme.
pub trait Integrator: Sized {
    /// The scheme's parameters (theta, p, ...), as its registry entry builds them.
    type Parameters;

    /// Set up from the start state.
    ///
    /// # Errors
    /// [`InputError`] naming the parameter and the rule when the parameters do not fit the
    /// model or the step.
    fn start(parameters: &Self::Parameters, state: InitialState<'_>) -> Result<Self, InputError>;

    /// The time step.
    fn dt(&self) -> f64;

    /// Displacements `u^n` of the current level.
    fn displacement(&self) -> &[f64];

    /// `(v^n, a^n)` at node `i` of the current level, time `t = t^n`.
    fn velocity_and_acceleration_at(&self, model: &Model, i: usize, t: f64) -> (f64, f64);

    /// Advance from `t^n = t` to `t^{n+1}`; `forces` are `F(t^{n+1})` by node.
    fn step(&mut self, model: &Model, t: f64, forces: &[(usize, f64)]) -> StepEnergy;

    /// `T*` of the balance energy at `t^0` (what `StepEnergy::kinetic_staggered` reports after
    /// every step).
    fn start_energy(&self) -> f64;

    /// `T*` recomputed from the mass matrix itself at a sampled step, for steppers that carry it
    /// forward by increments (any mismatch counts as balance error); `None` otherwise.
    fn recomputed_balance_kinetic(&mut self) -> Option<f64> {
        None
    }
}

/// A stepper that can also take blocks of steps in one pass over the bar (temporal blocking,
/// [`StepBlock`]): a capability a scheme opts into by implementing this trait for its stepper
/// and running it with [`time_loop::run_in_blocks`](super::time_loop::run_in_blocks). A stepper
/// without it implements [`Integrator`] alone and runs with
/// [`time_loop::run`](super::time_loop::run), by single steps.
///
/// Blocks pay where a step streams the whole bar from memory: a block of `S` steps reads each
/// array once per pass instead of once per step (benches/RESULTS.md, "Blocks of steps (temporal
/// blocking) and both cores"). The loop then needs, for each step of the block, what a single
/// step gives it: the energies, the displacements of the loaded nodes, and the history samples,
/// which a block records as probes.
pub trait BlockStepper: Integrator {
    /// Advance `steps` steps with the loads of `block.forces`, filling the block's energies and
    /// probes: bit-identical to `steps` calls of [`Integrator::step`].
    fn step_block(&mut self, block: &mut StepBlock, steps: usize);

    /// `(v^n, a^n)` at node `i`, time `t = t^n`, from `[u_{i-1}, u_i, u_{i+1}]` and the
    /// half-step velocity `v^{n+1/2}_i` recorded by a block: what
    /// [`Integrator::velocity_and_acceleration_at`] gives at that level.
    fn probed_velocity_and_acceleration(
        &self,
        model: &Model,
        i: usize,
        t: f64,
        u: [f64; 3],
        half_step_velocity: f64,
    ) -> (f64, f64);
}
