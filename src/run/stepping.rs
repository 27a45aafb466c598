//! Running a time-stepping case with courant's solver.

use crate::results::case::{CaseRecord, RunFacts, Status};
use crate::scene::cases::Case;
use courant_solver::RunError;
use std::time::Instant;

/// Run a case. A divergence (allowed unstable runs only) is a status, not an error: its partial
/// outputs are kept.
///
/// # Errors
/// The solver refuses the case (a step beyond the stability limit without `allow_unstable`, or
/// inconsistent input).
pub fn run_case(case: &Case) -> Result<CaseRecord, RunError> {
    let started = Instant::now();
    // The critical steps were computed when the scene was read.
    let (steps, request) = (case.plan.steps, &case.request);
    let outcome = super::threads::with_setting(&case.integrator).run_with_critical(
        &case.model,
        steps,
        request,
        case.critical,
    );
    let wall_time = started.elapsed();
    let (output, status) = match outcome {
        Ok(output) => (output, Status::Completed),
        Err(RunError::Diverged { error, partial }) => (*partial, Status::Diverged(error)),
        Err(other) => return Err(other),
    };
    let mut profile_steps = case.request.profile_steps.clone();
    profile_steps.sort_unstable();
    profile_steps.dedup();
    Ok(CaseRecord {
        run: RunFacts {
            case: case.name.clone(),
            // The scheme and its parameters: `cd`, `park-lts-free theta=0.5`, `noh-bathe p=0.54`.
            scheme: case.integrator.scheme.label(),
            courant: output.courant,
            dt: output.dt,
            steps_planned: case.plan.steps,
            steps: output.steps,
            critical: case.critical,
            limit: case.limit,
            profiles_requested: profile_steps.len(),
            status,
            wall_time,
        },
        mesh: std::sync::Arc::new(case.model.bar().mesh().clone()),
        profiles: output.profiles,
        histories: output.histories,
        energy: output.energy,
    })
}
