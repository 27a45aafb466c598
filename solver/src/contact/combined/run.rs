//! A combined contact run as a [`ContactRun`]: the time loop over a [`CombinedStepper`] with the
//! blow-up guard of [`crate::contact::ContactIntegrator::run`], the levels recorded as
//! [`ContactSample`]s, and the step limits the run is checked and reported against
//! ([`CombinedIntegrator::measured_critical`], [`CombinedIntegrator::park_rule_critical`]).

use super::amplification::{AmplificationError, measured_limit};
use super::bulk::BulkScheme;
use super::stepper::{CombinedStepper, ContactMode};
use crate::contact::error::ContactError;
use crate::contact::output::{ContactRequest, ContactRun, ContactSample};
use crate::contact::problem::ContactProblem;
use crate::contact::run::{check_request, diverged_at, refuse_above};
use crate::contact::scheme::ContactScheme;
use crate::contact::stability::{ContactCriticalStep, StepLimit};
use crate::error::InputError;
use crate::integrator::StabilityPolicy;

/// A combined contact integrator: bulk, contact scheme, step and stability policy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CombinedIntegrator {
    /// Time step.
    pub dt: f64,
    /// What steps the bulk.
    pub bulk: BulkScheme,
    /// Contact scheme.
    pub scheme: ContactScheme,
    /// Refusal above the limit (`allow_unstable`) and the blow-up guard's ratio.
    pub stability: StabilityPolicy,
}

impl CombinedIntegrator {
    /// The measured limits of `bulk` with `scheme` ([`measured_limit`]): `contact_free` with the
    /// contact off, `contact_active` with it always on, `applicable` the smaller, binding
    /// [`StepLimit::Measured`]. The row-sum and nodal estimates are those of the lumped central
    /// difference ([`ContactCriticalStep::of`]), capped at the measured limit.
    ///
    /// # Errors
    /// [`AmplificationError`]: above [`super::amplification::MAX_NODES`] nodes, no convergence,
    /// or no bracket.
    pub fn measured_critical(
        problem: &ContactProblem,
        bulk: BulkScheme,
        scheme: ContactScheme,
    ) -> Result<ContactCriticalStep, AmplificationError> {
        let contact_free = Self::measured_contact_free(problem, bulk, scheme)?;
        Self::measured_critical_given_free(problem, bulk, scheme, contact_free)
    }

    /// The measured limit of `bulk` with the contact off. It does not depend on the contact
    /// scheme (with the contact off no contact impulse acts and the contact nodes step with the
    /// bulk), so cases sharing a bulk may share it ([`Self::measured_critical_given_free`]);
    /// `scheme` is only validated.
    ///
    /// # Errors
    /// As [`Self::measured_critical`].
    pub fn measured_contact_free(
        problem: &ContactProblem,
        bulk: BulkScheme,
        scheme: ContactScheme,
    ) -> Result<f64, AmplificationError> {
        measured_limit(problem, bulk, scheme, ContactMode::Off)
    }

    /// [`Self::measured_critical`] with the contact-free limit already measured by
    /// [`Self::measured_contact_free`] for the same problem and bulk.
    ///
    /// # Errors
    /// As [`Self::measured_critical`].
    pub fn measured_critical_given_free(
        problem: &ContactProblem,
        bulk: BulkScheme,
        scheme: ContactScheme,
        contact_free: f64,
    ) -> Result<ContactCriticalStep, AmplificationError> {
        let lumped = ContactCriticalStep::of(problem, &scheme)?;
        let contact_active = measured_limit(problem, bulk, scheme, ContactMode::Bilateral)?;
        let applicable = contact_free.min(contact_active);
        Ok(ContactCriticalStep {
            contact_free,
            contact_active,
            applicable,
            binding: StepLimit::Measured,
            gershgorin: lumped.gershgorin.min(applicable),
            nodal: lumped.nodal.min(applicable),
            ..lumped
        })
    }

    /// Park's rule `alpha_e <= 1` as a critical step: `min_e dt_e`, the stiffest element's
    /// transit time (with and without local stepping), binding [`StepLimit::ParkRule`].
    ///
    /// # Errors
    /// As [`ContactCriticalStep::of`].
    pub fn park_rule_critical(
        problem: &ContactProblem,
        scheme: ContactScheme,
    ) -> Result<ContactCriticalStep, InputError> {
        let lumped = ContactCriticalStep::of(problem, &scheme)?;
        let rule = problem.stiffest_transit();
        Ok(ContactCriticalStep {
            contact_free: rule,
            contact_active: rule,
            applicable: rule,
            binding: StepLimit::ParkRule,
            gershgorin: lumped.gershgorin.min(rule),
            nodal: lumped.nodal.min(rule),
            ..lumped
        })
    }

    /// Integrate `steps` steps from the problem's initial state, checked and reported against
    /// `critical` (from [`Self::measured_critical`] or [`Self::park_rule_critical`]).
    ///
    /// # Errors
    /// [`ContactError::Input`] for bad parameters (Park's `alpha_e > 1` unless unstable runs are
    /// allowed), [`ContactError::Unstable`] above `critical.applicable` unless allowed,
    /// [`ContactError::Diverged`] when `kinetic + strain` of the real masses exceeds the policy's
    /// ratio times its initial value (contact is passive; no loads act on a contact problem's
    /// bodies here).
    pub fn run(
        &self,
        problem: &ContactProblem,
        steps: usize,
        request: &ContactRequest,
        critical: ContactCriticalStep,
    ) -> Result<ContactRun, ContactError> {
        check_request(problem, steps, request)?;
        let allow = self.stability.allow_unstable;
        refuse_above(self.dt, &self.scheme, &critical, allow)?;
        let mut stepper = if allow {
            CombinedStepper::allowing_unstable(
                problem,
                self.bulk,
                self.scheme,
                ContactMode::Unilateral,
                self.dt,
            )?
        } else {
            CombinedStepper::new(problem, self.bulk, self.scheme, self.dt)?
        };
        let first = sample(&mut stepper, &self.scheme);
        let initial = (first.kinetic + first.strain).max(f64::MIN_POSITIVE);
        let mut run = ContactRun {
            scheme: self.scheme,
            dt: self.dt,
            steps: 0,
            courant: critical.courant(self.dt),
            critical,
            history: vec![first],
            profiles: Vec::new(),
            impulse: first.impulse,
            initial_momentum: stepper.momenta(),
            final_momentum: Vec::new(),
            max_force: first.force.abs(),
        };
        let ratio = self.stability.blowup_energy_ratio;
        for step in 1..=steps {
            stepper.step();
            let s = sample(&mut stepper, &self.scheme);
            run.steps = step;
            run.impulse = s.impulse;
            run.max_force = run.max_force.max(s.force.abs());
            let mechanical = s.kinetic + s.strain;
            let diverged = mechanical.is_nan() || mechanical > ratio * initial;
            if diverged || step.is_multiple_of(request.history_every) || step == steps {
                run.history.push(s);
            }
            if diverged {
                run.final_momentum = stepper.momenta();
                let [u, _, _] = stepper.state();
                let node = largest(u);
                return Err(diverged_at(run, step, s.time, node, mechanical / initial));
            }
        }
        run.final_momentum = stepper.momenta();
        Ok(run)
    }
}

/// The current level as a [`ContactSample`] (`penalty_kinetic`: `1/2 m_p (N^T v^n)^2` of the
/// bipenalty while active).
fn sample(stepper: &mut CombinedStepper<'_>, scheme: &ContactScheme) -> ContactSample {
    let level = stepper.level();
    let energy = stepper.energy();
    let penalty = scheme.penalty();
    let [_, v, _] = stepper.state();
    let penalty_kinetic = match scheme {
        ContactScheme::Bipenalty(p) if level.active => {
            0.5 * p.mass * stepper.direction().project(v).powi(2)
        }
        _ => 0.0,
    };
    let penalty_force = match scheme {
        ContactScheme::LagrangeMultiplier => 0.0,
        _ => penalty.stiffness * (-level.gap).max(0.0),
    };
    ContactSample {
        step: level.step,
        time: level.time,
        force: level.force,
        penalty_force,
        gap: level.gap,
        active: level.active,
        impulse: stepper.impulse(),
        kinetic: energy.kinetic,
        kinetic_staggered: energy.kinetic_staggered,
        strain: energy.strain,
        penalty_spring: energy.penalty_spring,
        penalty_kinetic,
        total: energy.kinetic + energy.strain + energy.penalty_spring + penalty_kinetic,
    }
}

/// Index of the largest `|u|`, NaN first.
fn largest(u: &[f64]) -> usize {
    let mut best = (0, -1.0_f64);
    for (i, &x) in u.iter().enumerate() {
        let size = if x.is_nan() { f64::INFINITY } else { x.abs() };
        if size > best.1 {
            best = (i, size);
        }
    }
    best.0
}
