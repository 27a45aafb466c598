//! Running a contact-impact case (seed Figs. 4-5) with courant's solver: the lumped
//! central-difference contact stepper, or a combined bulk (`contact::combined`).

use crate::results::contact::ContactRecord;
use crate::scene::contact::ContactCase;
use courant_solver::contact::combined::CombinedIntegrator;
use courant_solver::contact::{ContactError, ContactRequest};
use std::time::Instant;

/// Run one contact case. A divergence (allowed unstable runs only) is recorded, not an error.
///
/// # Errors
/// The solver refuses the case (input, or a step beyond the stability limit).
pub fn run_contact(case: &ContactCase) -> Result<ContactRecord, ContactError> {
    let started = Instant::now();
    let request = ContactRequest {
        history_every: case.history_every,
        profile_steps: Vec::new(),
    };
    // A combined bulk runs through `contact::combined`; the lumped CD bulk keeps its stepper.
    let result = match &case.bulk {
        None => case.integrator.run(&case.problem, case.steps, &request),
        Some(bulk) => CombinedIntegrator {
            dt: case.integrator.dt,
            bulk: bulk.scheme,
            scheme: case.integrator.scheme,
            stability: case.integrator.stability,
        }
        .run(&case.problem, case.steps, &request, bulk.critical),
    };
    let (run, diverged) = match result {
        Ok(run) => (run, None),
        Err(ContactError::Diverged { error, partial }) => (*partial, Some(error)),
        Err(refused) => return Err(refused),
    };
    Ok(ContactRecord {
        case: case.name.clone(),
        penalty: case.penalty,
        run,
        diverged,
        wall_time: started.elapsed(),
    })
}
