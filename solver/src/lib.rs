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
//! Layers, lowest first: `mesh`, `bar`, `load`, `model` (the problem); `tridiagonal`,
//! `partitioned_ldl`, `halo_tiles` (with `halo_avx2`), `banded`, `mass` (operators);
//! `stability`, `spectrum`, `time_step`;
//! `kernel`, `kernel_tiled` and `kernel_pipeline` (the lumped step, and blocks of it: temporal
//! blocking on one or several threads), `matrix_kernel` (with `matrix_passes`, `matrix_avx2`),
//! `park` (step kernels); `integrator` (the public integrator
//! interface every scheme honours, the shared time loop); `schemes` (central difference, Park,
//! Noh-Bathe, each written against the interface, and the registry scenes name them through);
//! `contact` (contact runs, stepping the bulk with the `cd` stepper); `output`, `error`,
//! `fixtures`.

pub mod banded;
pub mod bar;
pub mod contact;
pub mod error;
pub mod fixtures;
#[cfg(target_arch = "x86_64")]
mod halo_avx2;
pub mod halo_tiles;
pub mod integrator;
pub mod kernel;
#[cfg(target_arch = "x86_64")]
mod kernel_avx2;
mod kernel_pipeline;
pub mod kernel_tiled;
pub mod load;
pub mod mass;
#[cfg(target_arch = "x86_64")]
mod matrix_avx2;
pub mod matrix_kernel;
mod matrix_passes;
pub mod mesh;
pub mod model;
pub mod output;
pub mod park;
pub mod partitioned_ldl;
mod placed_arrays;
pub mod schemes;
pub mod spectrum;
pub mod stability;
pub mod time_step;
mod tridiagonal;

pub use bar::{Bar, Field};
pub use error::{DivergenceError, InputError, NoConvergence, RunError, UnstableStepError};
pub use integrator::{
    Integration, LimitKind, OutputRequest, Scheme, SchemeEntry, SchemeLimit, StabilityPolicy, Start,
};
pub use load::{End, Load, NodalLoad, TimeFunction};
pub use mass::{MassKind, MassOperator};
pub use mesh::Mesh;
pub use model::{InitialConditions, Model, Support, Supports};
pub use output::{EnergyLog, EnergySample, HistorySample, NodeHistory, RunOutput, StressProfile};
pub use park::{ParkOptions, ParkScheme, ParkVariant};
pub use schemes::seed::CentralDifference;
pub use stability::CriticalStep;
pub use time_step::{TimePlan, plan, plan_keeping_step};
