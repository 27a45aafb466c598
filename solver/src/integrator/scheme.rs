//! [`Scheme`]: a scheme with its parameters set, as a registry builds it and a run holds it
//! (object-safe: it runs the shared time loop compiled for its own [`super::Integrator`]), and
//! [`Integration`]: everything a run is told (scheme, mass, step, start, stability policy).

use super::limit::SchemeLimit;
use super::record::validate_request;
use super::settings::{OutputRequest, StabilityPolicy, Start};
use crate::analysis::stability::CriticalStep;
use crate::error::{InputError, RunError, UnstableStepError};
use crate::kernels::lumped::PARALLEL_FROM_NODES;
use crate::mass::{MassKind, MassOperator};
use crate::model::Model;
use crate::output::RunOutput;
use std::sync::Arc;

/// What the time loop is given besides the scheme's parameters.
#[derive(Debug, Clone)]
pub struct RunSetup<'a> {
    /// The model.
    pub model: &'a Model,
    /// The time step.
    pub dt: f64,
    /// Start procedure.
    pub start: Start,
    /// Stability policy (the guard's ratio; unstable runs allowed).
    pub stability: StabilityPolicy,
    /// The assembled mass.
    pub mass: MassOperator,
    /// Steps to take.
    pub steps: usize,
    /// What to record.
    pub request: &'a OutputRequest,
    /// The threads a stepper may use ([`Integration::threads`]: blocks of steps, chunks of a
    /// long bar).
    pub threads: usize,
}

/// A scheme with its parameters, ready to run on any model (what a registry entry builds from
/// a scene's keys).
pub trait Scheme: std::fmt::Debug + Send + Sync {
    /// The registry name, e.g. `noh-bathe`.
    fn name(&self) -> &'static str;

    /// The scheme and its parameters as outputs name it, e.g. `noh-bathe p=0.54`.
    fn label(&self) -> String;

    /// Internal-force evaluations `K u` per step (element-level or assembled): the scheme's cost
    /// per step in units of central difference's one.
    fn force_evaluations(&self) -> usize;

    /// Refuse a mass kind or start procedure the scheme does not run with.
    ///
    /// # Errors
    /// [`InputError`] naming the setting and the rule.
    fn check_settings(&self, mass: MassKind, start: Start) -> Result<(), InputError>;

    /// The stability limit on `model`, given the critical steps of its mass.
    fn limit(&self, model: &Model, critical: &CriticalStep) -> SchemeLimit;

    /// Integrate: build the scheme's [`super::Integrator`] and run the shared time loop
    /// ([`super::time_loop::run`]) with it.
    ///
    /// # Errors
    /// As [`Integration::run`].
    fn run(&self, setup: RunSetup<'_>) -> Result<RunOutput, RunError>;

    /// Whether a run of this scheme with `mass` takes blocks of steps
    /// ([`super::time_loop::run_in_blocks`]: lumped central difference, when the run must stay
    /// stable), which may use several threads ([`Integration::threads`]).
    fn takes_blocks(&self, mass: MassKind, allow_unstable: bool) -> bool {
        let _ = (mass, allow_unstable);
        false
    }

    /// Whether a run of this scheme with `mass` may use several threads on a long bar
    /// ([`Integration::threads`]): the runs that take blocks of steps, and any other whose steps
    /// split a long bar into fixed chunks (central difference with a matrix mass).
    fn uses_threads(&self, mass: MassKind, allow_unstable: bool) -> bool {
        self.takes_blocks(mass, allow_unstable)
    }
}

/// Everything a run is told: the scheme (with its parameters), the mass, the step, the start and
/// the stability policy.
#[derive(Debug, Clone)]
pub struct Integration {
    /// Time step.
    pub dt: f64,
    /// Mass matrix.
    pub mass: MassKind,
    /// Start procedure.
    pub start: Start,
    /// Stability guard.
    pub stability: StabilityPolicy,
    /// The scheme.
    pub scheme: Arc<dyn Scheme>,
    /// The threads a run that may use several ([`Scheme::uses_threads`]) uses on a bar of
    /// [`PARALLEL_FROM_NODES`] nodes or more: `None` for every core the process may use
    /// (`std::thread::available_parallelism`). A setting of the run, not of the process: the
    /// `courant` binary resolves `COURANT_THREADS` once and sets it here. The results do not
    /// depend on it (bit-identical whatever the count).
    pub threads: Option<usize>,
}

impl Integration {
    /// `scheme` with step `dt`, the lumped mass, the half-step start and the default guard.
    pub fn new(dt: f64, scheme: Arc<dyn Scheme>) -> Self {
        Self {
            dt,
            mass: MassKind::Lumped,
            start: Start::HalfStep,
            stability: StabilityPolicy::default(),
            scheme,
            threads: None,
        }
    }

    /// Threads a run with these settings uses on `model`: 1 unless it may use several
    /// ([`Scheme::uses_threads`]) on a bar of [`PARALLEL_FROM_NODES`] nodes or more, then
    /// [`Integration::threads`] (every core the process may use if unset). A caller running
    /// several cases at once runs the multi-threaded ones one at a time.
    pub fn threads(&self, model: &Model) -> usize {
        let parallel = self
            .scheme
            .uses_threads(self.mass, self.stability.allow_unstable);
        if !parallel || model.bar().node_count() < PARALLEL_FROM_NODES {
            return 1;
        }
        self.threads
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
            .max(1)
    }

    /// The critical steps of the mass, after refusing `dt` above the scheme's limit
    /// ([`Scheme::limit`]) with the relative allowance
    /// [`crate::analysis::ROUNDING_SLACK`] of the time plan (so that Co = 1 on a
    /// free-free uniform bar, where `dt = dt_crit`, is accepted after the plan's rounding), unless
    /// unstable runs are allowed.
    ///
    /// # Errors
    /// [`RunError::Input`] for settings the scheme does not take, [`RunError::Unstable`] above
    /// the limit.
    pub fn check_stability(&self, model: &Model) -> Result<CriticalStep, RunError> {
        self.scheme.check_settings(self.mass, self.start)?;
        let operator = MassOperator::new(model, self.mass)?;
        self.check_stability_with(model, &operator)
    }

    /// The scheme's limit on `model`, given the critical steps of its mass (from
    /// [`Integration::check_stability`]).
    pub fn limit(&self, model: &Model, critical: &CriticalStep) -> SchemeLimit {
        self.scheme.limit(model, critical)
    }

    /// [`Self::check_stability`] with the critical steps of the mass already computed (what
    /// `check_stability` returned for this model and mass, e.g. for another step): the same
    /// checks without the bisection again.
    ///
    /// # Errors
    /// As [`Self::check_stability`]; [`RunError::Input`] when `critical` is another mass's.
    pub fn check_stability_given(
        &self,
        model: &Model,
        critical: CriticalStep,
    ) -> Result<CriticalStep, RunError> {
        self.scheme.check_settings(self.mass, self.start)?;
        self.check_step(model, critical)
    }

    fn check_stability_with(
        &self,
        model: &Model,
        operator: &MassOperator,
    ) -> Result<CriticalStep, RunError> {
        let critical = CriticalStep::of(model, self.mass, operator).map_err(InputError::from)?;
        self.check_step(model, critical)
    }

    /// Refuse `dt` above the scheme's limit given the mass's critical steps (see
    /// [`Self::check_stability`]).
    fn check_step(&self, model: &Model, critical: CriticalStep) -> Result<CriticalStep, RunError> {
        if critical.mass != self.mass {
            return Err(InputError::CriticalStepsOfAnotherMass {
                given: critical.mass.label(),
                run: self.mass.label(),
            }
            .into());
        }
        if self.stability.allow_unstable {
            return Ok(critical);
        }
        let limit = self.limit(model, &critical);
        if self.dt > limit.dt() * (1.0 + crate::analysis::time_step::ROUNDING_SLACK) {
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
    ///
    /// # Errors
    /// [`RunError::Input`] for bad parameters, [`RunError::Unstable`] above the limit (unless
    /// allowed), [`RunError::Diverged`] (with everything recorded before) when an allowed
    /// unstable run blows up.
    pub fn run(
        &self,
        model: &Model,
        steps: usize,
        request: &OutputRequest,
    ) -> Result<RunOutput, RunError> {
        crate::model::mesh::positive("dt", self.dt)?;
        validate_request(model, steps, request)?;
        self.scheme.check_settings(self.mass, self.start)?;
        let operator = MassOperator::new(model, self.mass)?;
        self.check_stability_with(model, &operator)?;
        self.run_assembled(model, steps, request, operator)
    }

    /// [`Self::run`] with the critical steps of the mass already computed (as
    /// [`Self::check_stability`] returned them for this model and mass; a scene computes them
    /// when it is read): the same checks and run, without the bisection again.
    ///
    /// # Errors
    /// As [`Self::run`]; [`RunError::Input`] when `critical` is another mass's.
    pub fn run_with_critical(
        &self,
        model: &Model,
        steps: usize,
        request: &OutputRequest,
        critical: CriticalStep,
    ) -> Result<RunOutput, RunError> {
        crate::model::mesh::positive("dt", self.dt)?;
        validate_request(model, steps, request)?;
        self.check_stability_given(model, critical)?;
        let operator = MassOperator::new(model, self.mass)?;
        self.run_assembled(model, steps, request, operator)
    }

    /// The time loop of [`Self::run`] with the mass already assembled
    /// (`MassOperator::new(model, self.mass)`) and the request and step already checked: what the
    /// benchmarks time, the assembly and the critical step left out.
    ///
    /// # Errors
    /// As [`Self::run`]'s time loop.
    pub fn run_assembled(
        &self,
        model: &Model,
        steps: usize,
        request: &OutputRequest,
        mass: MassOperator,
    ) -> Result<RunOutput, RunError> {
        self.scheme.run(RunSetup {
            model,
            dt: self.dt,
            start: self.start,
            stability: self.stability,
            mass,
            steps,
            request,
            threads: self.threads(model),
        })
    }
}

/// The error of a scheme that runs with the lumped mass only.
pub fn lumped_only(scheme: &str, mass: MassKind) -> Result<(), InputError> {
    if mass == MassKind::Lumped {
        Ok(())
    } else {
        Err(InputError::LumpedMassOnly {
            scheme: scheme.to_string(),
            mass: mass.label(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CentralDifference, MassKind, RunError};

    /// CMM central difference at `courant` times the element estimate of its limit.
    fn consistent(model: &Model, courant: f64) -> Integration {
        let mass = MassKind::Consistent;
        let element_dt = model.bar().stiffest_element().1;
        CentralDifference {
            mass,
            ..CentralDifference::new(courant * mass.critical_courant() * element_dt)
        }
        .integration()
    }

    #[test]
    fn given_critical_steps_check_and_run_as_the_computed_ones() {
        let model = crate::fixtures::graded_seed_bar(200).unwrap();
        let stable = consistent(&model, 0.5);
        let critical = stable.check_stability(&model).unwrap();
        assert_eq!(
            stable.check_stability_given(&model, critical).unwrap(),
            critical
        );
        let request = OutputRequest::default();
        let run = stable.run(&model, 50, &request).unwrap();
        let given = stable
            .run_with_critical(&model, 50, &request, critical)
            .unwrap();
        assert_eq!(given, run);
        // Above the limit: the same refusal as with the bisection.
        let unstable = consistent(&model, 1.2);
        let computed = unstable.check_stability(&model).unwrap_err();
        let checked = unstable
            .check_stability_given(&model, critical)
            .unwrap_err();
        assert!(matches!(checked, RunError::Unstable(_)));
        assert_eq!(checked.to_string(), computed.to_string());
        // Another mass's critical steps are refused.
        let lumped = CentralDifference::new(stable.dt).integration();
        let refused = lumped.check_stability_given(&model, critical).unwrap_err();
        assert!(matches!(refused, RunError::Input(_)), "{refused}");
        assert_eq!(
            refused.to_string(),
            "critical steps of the cmm mass given for a run with the lmm mass"
        );
    }
}
