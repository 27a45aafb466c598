//! The seed's schemes as plain settings ([`CentralDifference`]): central difference with a mass,
//! or Park's scheme, as tests and benchmarks write them. A shorthand for an [`Integration`] whose
//! scheme is the registry's `cd` or a Park entry: it runs through the same interface and loop.

use super::central_difference::CentralDifferenceScheme;
use super::park::ParkScheme;
use crate::analysis::stability::CriticalStep;
use crate::error::RunError;
use crate::integrator::{Integration, OutputRequest, Scheme, SchemeLimit, StabilityPolicy, Start};
use crate::kernels::park::ParkOptions;
use crate::mass::MassKind;
use crate::model::Model;
use crate::output::RunOutput;
use std::sync::Arc;

/// The seed's schemes as plain settings: central difference with a mass, or Park's scheme in
/// place of the CD predictor (`park`, lumped mass only). A shorthand for an [`Integration`]
/// whose scheme is the `cd` or a Park entry: it runs through the same interface and loop.
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
    /// Park's scheme instead of central difference (`theta = 0` is CD). Default `None`.
    pub park: Option<ParkOptions>,
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

    /// The same settings as an [`Integration`].
    pub fn integration(&self) -> Integration {
        let scheme: Arc<dyn Scheme> = match self.park {
            None => Arc::new(CentralDifferenceScheme),
            Some(options) => Arc::new(ParkScheme { options }),
        };
        Integration {
            dt: self.dt,
            mass: self.mass,
            start: self.start,
            stability: self.stability,
            scheme,
            threads: None,
        }
    }

    /// [`Integration::check_stability`].
    ///
    /// # Errors
    /// As there.
    pub fn check_stability(&self, model: &Model) -> Result<CriticalStep, RunError> {
        self.integration().check_stability(model)
    }

    /// [`Integration::limit`].
    pub fn limit(&self, model: &Model, critical: &CriticalStep) -> SchemeLimit {
        self.integration().limit(model, critical)
    }

    /// [`Integration::run`].
    ///
    /// # Errors
    /// As there.
    pub fn run(
        &self,
        model: &Model,
        steps: usize,
        request: &OutputRequest,
    ) -> Result<RunOutput, RunError> {
        self.integration().run(model, steps, request)
    }
}
