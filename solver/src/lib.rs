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
//! Folders, lowest first (each uses only those before it; `tests/architecture.rs` checks it):
//! `simd` (lane width and CPU features), `error`, `output`; `model/` (the discrete bar);
//! `mass/` (mass operators, their factors and windowed solves); `analysis/` (critical steps,
//! spectra, step plans); `kernels/` (the step arithmetic: `lumped/`, `matrix_mass/`, `park/`);
//! `integrator/` (the public integrator interface every scheme honours, the shared time loop);
//! `schemes/` (central difference, Park, Noh-Bathe, each written against the interface, and
//! the registry scenes name them through); `contact/` (contact runs, stepping the bulk with the
//! `cd` stepper); `fixtures` (bars for tests, benches and examples).

pub mod analysis;
pub mod contact;
pub mod error;
pub mod fixtures;
pub mod integrator;
pub mod kernels;
pub mod mass;
pub mod model;
pub mod output;
pub mod schemes;
mod simd;

pub use analysis::{CriticalStep, TimePlan, plan, plan_keeping_step};
pub use error::{DivergenceError, InputError, NoConvergence, RunError, UnstableStepError};
pub use integrator::{
    Integration, LimitKind, OutputRequest, Scheme, SchemeEntry, SchemeLimit, StabilityPolicy, Start,
};
pub use kernels::park::{ParkOptions, ParkScheme, ParkVariant};
pub use mass::{MassKind, MassOperator};
pub use model::bar::{Bar, Field};
pub use model::load::{End, Load, NodalLoad, TimeFunction};
pub use model::mesh::Mesh;
pub use model::{InitialConditions, Model, Support, Supports};
pub use output::{EnergyLog, EnergySample, HistorySample, NodeHistory, RunOutput, StressProfile};
pub use schemes::seed::CentralDifference;
