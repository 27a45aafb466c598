//! The public integrator interface: what a time-integration scheme must honour to run on every
//! scene, study and table of courant, and the one time loop all schemes share.
//!
//! **Enters:** a [`Model`](crate::Model), a step `dt`, a [`Scheme`] (registry-built, with its
//! parameters) and the run's settings ([`Integration`]: mass, start, stability policy), the
//! number of steps and an [`OutputRequest`]. **Leaves:** a [`RunOutput`](crate::RunOutput) or a
//! [`RunError`](crate::RunError), and the scheme's [`SchemeLimit`]. It must not know scenes, files
//! or the analytic references (no I/O), nor any particular scheme (they live in
//! [`crate::schemes`] and use this module, not the reverse).
//!
//! # The contract
//!
//! A scheme is two things:
//!
//! 1. an [`Integrator`]: the stepper, compiled into the shared [`time_loop::run`] (static
//!    dispatch, so the loop costs what the stepper's own code costs). It is **created** from its
//!    parameters and the common [`InitialState`] (`u^0`, `v^0`, `r^0 = F(0) - K u^0`,
//!    `a^0 = M^-1 r^0`, the assembled mass, the start procedure); it takes **one step** from
//!    `t^n` to `t^{n+1}` given the loads at `t^{n+1}` (loads at other times it evaluates from the
//!    model) without allocating; it exposes **outputs** `u^n` (element stresses follow from it)
//!    and `v^n`, `a^n` at a node; and it reports its **energy**: the full-step kinetic and the
//!    strain energy, and the kinetic part `T*` of its balance energy, whose change the loop
//!    compares with the trapezoidal work at every step (round-off for a conserving scheme, the
//!    dissipated energy otherwise; a scheme without an energy of its own reports `T* = T`).
//!    The blow-up guard needs nothing of the scheme: it stops a run whose `T + U` exceeds
//!    `blowup_energy_ratio` times the largest energy that entered the bar. A stepper that can
//!    also take blocks of steps in one pass over the bar opts into it by implementing
//!    [`BlockStepper`] and running with [`time_loop::run_in_blocks`]; every other stepper
//!    implements [`Integrator`] alone and runs with [`time_loop::run`].
//! 2. a [`Scheme`]: the stepper with its parameter values, object-safe so a registry can hold
//!    it. It names itself and its parameters ([`Scheme::label`]), states its cost in
//!    internal-force evaluations per step ([`Scheme::force_evaluations`]), refuses masses or
//!    starts it does not run with, and gives its **stability limit** on a model
//!    ([`Scheme::limit`], from the exact critical steps of the mass): [`LimitKind::Exact`] (the
//!    largest stable step: unstable above), [`LimitKind::Bound`] (sufficient only: nothing
//!    predicted above) or [`LimitKind::Measured`] (no analysis: [`measure_critical_step`] runs
//!    the scheme and bisects on `dt`). The refusal rule is the same for all three: a step above
//!    the limit is refused unless unstable runs are allowed, and the error names the limit.
//!
//! Its [`SchemeEntry`] in [`crate::schemes::REGISTRY`] declares the name scenes use, the
//! parameters (keys of a scene's `[integrator]`, with defaults, rules and meaning), the masses
//! and the source, and builds the [`Scheme`] from the values.
//!
//! Files: `contract` ([`Integrator`], [`BlockStepper`], [`InitialState`]), `scheme`
//! ([`Scheme`], [`Integration`]), `registry` ([`SchemeEntry`] and parameters), `limit`
//! ([`SchemeLimit`]), `measure` (the measured critical step), `time_loop` (the loop, by single
//! steps or by blocks of steps for a [`BlockStepper`]), `blocks` (a block's end and buffers),
//! `guard` (blow-up detection), `record` (profiles and histories), `settings` (start, stability
//! policy, output request).

mod blocks;
mod contract;
mod guard;
mod limit;
mod measure;
mod record;
mod registry;
mod scheme;
mod settings;
pub mod time_loop;

pub use crate::kernels::energy::StepEnergy;
pub use crate::kernels::lumped::tiled::StepBlock;
pub use contract::{BlockStepper, InitialState, Integrator};
pub use limit::{LimitKind, SchemeLimit};
pub use measure::{MEASURED_PRECISION, measure_critical_step};
pub use registry::{
    Parameter, ParameterDefault, ParameterError, ParameterValue, ParameterValues, SchemeEntry,
};
pub use scheme::{Integration, RunSetup, Scheme, lumped_only};
pub use settings::{OutputRequest, StabilityPolicy, Start};
