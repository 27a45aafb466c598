//! Running a contact-impact case (seed Figs. 4-5) with courant's solver: the lumped
//! central-difference contact stepper, or a combined bulk (`contact::combined`).

use crate::results::contact::ContactRecord;
use crate::scene::contact::ContactCase;
use courant_solver::contact::combined::CombinedIntegrator;
use courant_solver::contact::combined::amplification::AmplificationError;
use courant_solver::contact::{ContactError, ContactRequest};
use std::time::Instant;

/// Run one contact case. A divergence (allowed unstable runs only) is recorded, not an error.
///
/// # Errors
/// The solver refuses the case (input, or a step beyond the stability limit).
pub fn run_contact(case: &ContactCase) -> Result<ContactRecord, ContactRunError> {
    let started = Instant::now();
    let request = ContactRequest {
        history_every: case.history_every,
        profile_steps: Vec::new(),
    };
    // A combined bulk runs through `contact::combined`; the lumped CD bulk keeps its stepper.
    let result = match &case.bulk {
        None => case.integrator.run(&case.problem, case.steps, &request),
        Some(bulk) => {
            let integrator = CombinedIntegrator {
                dt: case.integrator.dt,
                bulk: bulk.scheme,
                scheme: case.integrator.scheme,
                stability: case.integrator.stability,
            };
            // A limit not measured at validation is measured here, before the first step.
            let critical = match bulk.critical {
                Some(critical) => critical,
                None => CombinedIntegrator::measured_critical(
                    &case.problem,
                    bulk.scheme,
                    case.integrator.scheme,
                )
                .map_err(ContactRunError::Limit)?,
            };
            integrator.run(&case.problem, case.steps, &request, critical)
        }
    };
    let (run, diverged) = match result {
        Ok(run) => (run, None),
        Err(ContactError::Diverged { error, partial }) => (*partial, Some(error)),
        Err(refused) => return Err(refused.into()),
    };
    Ok(ContactRecord {
        case: case.name.clone(),
        penalty: case.penalty,
        run,
        diverged,
        wall_time: started.elapsed(),
    })
}

/// Why a contact case did not run.
#[derive(Debug, thiserror::Error)]
pub enum ContactRunError {
    /// The solver refused the case (input, or a step above the applicable limit).
    #[error(transparent)]
    Refused(#[from] ContactError),
    /// The combined bulk's step limit could not be measured.
    #[error("measuring the step limit of the combined bulk: {0}")]
    Limit(#[from] AmplificationError),
}
