//! # courant-solver
//!
//! A compact explicit finite-element solver for 1D elastic bars: two-node linear elements with
//! per-element modulus, density and area; lumped (row-sum) mass; central difference in the
//! half-step velocity form, equivalent to the predictor-corrector eqs. 2-4 of Kolman et al.,
//! "Recent progress in numerical methods for explicit finite element analysis" (the seed paper);
//! critical-step estimates and a stability guard. No I/O: the `courant` crate reads scenes and
//! writes results.
//!
//! Conventions (time levels, load convention H(0) = 1, Courant number relative to the stiffest
//! element) follow courant's `methods.md` §1-2.
//!
//! **Enters:** bars and models built in code ([`Mesh`], [`Bar`], [`Model`], loads, supports,
//! initial conditions), a step and run settings. **Leaves:** run outputs ([`RunOutput`],
//! [`contact::ContactRun`]), critical steps, spectra and typed errors. It must not know files,
//! scenes, reports or the analytic references (`courant-references` is compared with it by the
//! `courant` crate), and it does no I/O.
//!
//! Folders, lowest first (each uses only those before it; `tests/architecture/main.rs` checks it):
//! `simd` (lane width and CPU features), `output`, `error`; `model/` (the discrete bar);
//! `mass/` (mass operators, their factors and windowed solves); `analysis/` (critical steps,
//! spectra, step plans); `kernels/` (the step arithmetic: `lumped/`, `matrix_mass/`, `park/`);
//! `integrator/` (the public integrator interface every scheme honours, the shared time loop);
//! `schemes/` (central difference, Park, Noh-Bathe, each written against the interface, and
//! the registry scenes name them through); `contact/` (contact runs, stepping the bulk with the
//! `cd` stepper); `fixtures` (bars for tests, benches and examples).
//!
//! Public surface: the types re-exported here, and the modules `model`, `mass`, `analysis`
//! (their public items only; their files are private), `integrator` (the contract a scheme
//! honours, with the [`integrator::StepEnergy`] and [`integrator::StepBlock`] it exchanges with
//! the loop), `schemes` and `contact`. The step kernels, the fixtures and the kernels' constants
//! are private; what benches, timing examples and kernel-level tests need of them is gathered in
//! the hidden `bench` module, which is not a stable interface.

#![warn(missing_docs)]

pub mod analysis;
#[doc(hidden)]
pub mod bench;
pub mod contact;
mod error;
mod fixtures;
pub mod integrator;
mod kernels;
pub mod mass;
pub mod model;
mod output;
pub mod schemes;
mod simd;

pub use analysis::{CriticalStep, TimePlan, plan, plan_keeping_step};
pub use error::{DivergenceError, InputError, NoConvergence, RunError, UnstableStepError};
pub use integrator::{
    Integration, LimitKind, OutputRequest, Scheme, SchemeEntry, SchemeLimit, StabilityPolicy, Start,
};
pub use kernels::park::{ParkOptions, ParkVariant};
pub use mass::{MassKind, MassOperator, MassWork};
pub use model::{
    Bar, End, Field, InitialConditions, Load, Mesh, Model, NodalLoad, Support, Supports,
    TimeFunction,
};
pub use output::{EnergyLog, EnergySample, HistorySample, NodeHistory, RunOutput, StressProfile};
pub use schemes::seed::CentralDifference;
