//! The contact run: stability check against the critical steps of the scheme, the time loop over
//! a [`ContactStepper`], histories, profiles and the blow-up guard.

use super::error::{ContactError, ContactUnstableError};
use super::output::{ContactRequest, ContactRun};
use super::problem::ContactProblem;
use super::scheme::ContactScheme;
use super::stability::ContactCriticalStep;
use super::stepper::ContactStepper;
use crate::error::{DivergenceError, InputError};
use crate::integrator::StabilityPolicy;
use crate::model::Model;

/// Contact integrator: step, scheme and stability policy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactIntegrator {
    /// Time step.
    pub dt: f64,
    /// Contact scheme.
    pub scheme: ContactScheme,
    /// Refusal above the critical step (`allow_unstable`) and blow-up guard ratio.
    pub stability: StabilityPolicy,
}

impl ContactIntegrator {
    /// `scheme` with step `dt` and the default stability policy.
    pub fn new(dt: f64, scheme: ContactScheme) -> Self {
        Self {
            dt,
            scheme,
            stability: StabilityPolicy::default(),
        }
    }

    /// The critical steps, and an error if `dt` exceeds the applicable one (with the time plan's
    /// relative allowance [`crate::analysis::ROUNDING_SLACK`]) and unstable runs are not
    /// allowed.
    ///
    /// # Errors
    /// [`ContactError::Input`] for bad parameters, [`ContactError::Unstable`] above the limit.
    pub fn check_stability(
        &self,
        problem: &ContactProblem,
    ) -> Result<ContactCriticalStep, ContactError> {
        crate::model::mesh::positive("dt", self.dt)?;
        self.scheme.validate()?;
        let critical = ContactCriticalStep::of(problem, &self.scheme).map_err(InputError::from)?;
        refuse_above(
            self.dt,
            &self.scheme,
            &critical,
            self.stability.allow_unstable,
        )?;
        Ok(critical)
    }

    /// Integrate `steps` steps from the problem's initial state.
    ///
    /// # Errors
    /// [`ContactError::Input`] for bad parameters or a problem nothing excites,
    /// [`ContactError::Unstable`] above the critical step (unless allowed),
    /// [`ContactError::Diverged`] when an allowed unstable run blows up: the energy of the real
    /// masses, `kinetic + strain`, exceeds `blowup_energy_ratio` times the largest of its initial
    /// value, the external work and the loads' one-step impulse energy (as the shared time loop's
    /// guard ([`crate::integrator`])). Contact is passive: a stable scheme can only keep or
    /// dissipate energy, so on an impact a ratio of ten already detects an unstable one. The
    /// penalty terms are left out: the spring energy of a first-step penetration `k_s (dt v0)^2/2`
    /// grows without bound with `k_s` even when the run is stable.
    pub fn run(
        &self,
        problem: &ContactProblem,
        steps: usize,
        request: &ContactRequest,
    ) -> Result<ContactRun, ContactError> {
        check_request(problem, steps, request)?;
        let critical = self.check_stability(problem)?;
        let mut stepper = ContactStepper::new(problem, self.dt, self.scheme)?;
        let mut profile_steps = request.profile_steps.clone();
        profile_steps.sort_unstable();
        profile_steps.dedup();
        let mut next_profile = profile_steps.into_iter().peekable();
        let first = stepper.sample();
        let mut run = ContactRun {
            scheme: self.scheme,
            dt: self.dt,
            steps: 0,
            courant: critical.courant(self.dt),
            critical,
            history: vec![first],
            profiles: Vec::new(),
            impulse: first.impulse,
            initial_momentum: (0..problem.bodies().len())
                .map(|b| initial_momentum(&problem.bodies()[b]))
                .collect(),
            final_momentum: Vec::new(),
            max_force: first.force.abs(),
        };
        let mut profile = |stepper: &ContactStepper, run: &mut ContactRun, step: usize| {
            if next_profile.peek() == Some(&step) {
                next_profile.next();
                run.profiles.push(stepper.profile());
            }
        };
        profile(&stepper, &mut run, 0);
        let ratio = self.stability.blowup_energy_ratio;
        for step in 1..=steps {
            let sample = stepper.step();
            run.steps = step;
            run.impulse = sample.impulse;
            run.max_force = run.max_force.max(sample.force.abs());
            let reference = stepper.energy_reference();
            let mechanical = sample.kinetic + sample.strain;
            // NaN (a non-finite state) counts as diverged.
            let diverged = mechanical.is_nan() || mechanical > ratio * reference;
            if diverged || step.is_multiple_of(request.history_every) || step == steps {
                run.history.push(sample);
            }
            profile(&stepper, &mut run, step);
            if diverged {
                run.final_momentum = stepper.momenta();
                let node = stepper.largest_displacement_node();
                return Err(diverged_at(
                    run,
                    step,
                    sample.time,
                    node,
                    mechanical / reference,
                ));
            }
        }
        run.final_momentum = stepper.momenta();
        Ok(run)
    }
}

/// The checks every contact run makes before stepping: a recording interval of at least one
/// step, profile steps the run reaches, and something that sets the problem in motion.
pub(crate) fn check_request(
    problem: &ContactProblem,
    steps: usize,
    request: &ContactRequest,
) -> Result<(), ContactError> {
    if request.history_every == 0 {
        return Err(InputError::EveryIsZero {
            field: "history_every",
        }
        .into());
    }
    if let Some(&step) = request.profile_steps.iter().find(|&&s| s > steps) {
        return Err(InputError::ProfileAfterLastStep { step, last: steps }.into());
    }
    if !problem.is_excited() {
        return Err(InputError::NothingExcites {
            what: "the contact problem",
        }
        .into());
    }
    Ok(())
}

/// Refuse `dt` above `critical.applicable` (with the time plan's relative allowance
/// [`crate::analysis::ROUNDING_SLACK`]) unless unstable runs are allowed.
pub(crate) fn refuse_above(
    dt: f64,
    scheme: &ContactScheme,
    critical: &ContactCriticalStep,
    allow_unstable: bool,
) -> Result<(), ContactError> {
    if dt > critical.applicable * (1.0 + crate::analysis::time_step::ROUNDING_SLACK)
        && !allow_unstable
    {
        return Err(ContactUnstableError {
            scheme: scheme.label(),
            dt,
            dt_crit: critical.applicable,
            courant: critical.courant(dt),
            critical_courant: critical.critical_courant(),
            limit: critical.binding,
        }
        .into());
    }
    Ok(())
}

/// The blow-up guard's stop: `run` so far (its `final_momentum` set) with where it diverged;
/// `energy_ratio` is the energy of the real masses over the guard's reference (infinite for a
/// non-finite state).
pub(crate) fn diverged_at(
    run: ContactRun,
    step: usize,
    time: f64,
    node: usize,
    energy_ratio: f64,
) -> ContactError {
    let error = DivergenceError {
        step,
        time,
        node,
        energy_ratio: if energy_ratio.is_finite() {
            energy_ratio
        } else {
            f64::INFINITY
        },
        courant: run.courant,
    };
    ContactError::Diverged {
        error,
        partial: Box::new(run),
    }
}

fn initial_momentum(model: &Model) -> f64 {
    model
        .nodal_mass()
        .iter()
        .zip(model.initial_velocity())
        .map(|(m, v)| m * v)
        .sum()
}
