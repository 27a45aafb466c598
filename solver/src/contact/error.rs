//! Typed errors of contact runs.

use thiserror::Error;

use super::output::ContactRun;
use super::stability::StepLimit;
use crate::error::{DivergenceError, InputError};

/// The time step is above the critical step of the contact scheme and unstable runs were not
/// allowed.
#[derive(Debug, Clone, PartialEq, Error)]
#[error(
    "time step dt = {dt:.6e} exceeds the critical step dt_crit = {dt_crit:.6e} of the {scheme} \
     scheme by {:.3e} relative (Courant number {courant:.6} against the critical {critical_courant:.6}, \
     relative to the stiffest element); the limit that binds is {limit}; lower the Courant number, \
     change the penalties or set allow_unstable = true",
    dt / dt_crit - 1.0
)]
pub struct ContactUnstableError {
    /// Scheme label ([`super::ContactScheme::label`]).
    pub scheme: &'static str,
    /// The requested time step.
    pub dt: f64,
    /// The applicable critical step.
    pub dt_crit: f64,
    /// Courant number of `dt`, relative to the stiffest element of all bodies.
    pub courant: f64,
    /// Courant number of `dt_crit`.
    pub critical_courant: f64,
    /// Which limit gives `dt_crit`.
    pub limit: StepLimit,
}

/// Why a contact run did not complete.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ContactError {
    /// Bad parameters; nothing ran.
    #[error(transparent)]
    Input(#[from] InputError),
    /// `dt` above the applicable critical step and unstable runs not allowed; nothing ran.
    #[error(transparent)]
    Unstable(#[from] ContactUnstableError),
    /// An allowed unstable run blew up; `partial` holds everything recorded up to and including
    /// the step at which it was detected. The error's `node` is a global index: the bodies'
    /// nodes numbered one after the other (the target's node 0 is the striker's last + 1).
    #[error("{error}")]
    Diverged {
        /// Where and how it diverged.
        error: DivergenceError,
        /// Outputs up to the divergence.
        partial: Box<ContactRun>,
    },
}
