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

#[cfg(test)]
mod tests {
    use super::{ContactRunError, run_contact};
    use crate::scene::cases::Scene;
    use courant_solver::contact::ContactError;

    /// Source of truth: the measured limit of a combined bulk (`contact::combined`, `rho(G) <=
    /// 1`; RMM(1/2) with contact measured at 0.83 of the stiffest transit on two bars of this
    /// kind). Proves: a `cd-rmm` case whose steps count in the stiffest element's transit is not
    /// measured at validation, and the run measures it and refuses a step above it before the
    /// first step, naming the limit; below it the case runs.
    #[test]
    fn a_limit_left_to_the_run_is_measured_and_enforced_there() {
        let text = |courant: f64| {
            format!(
                "[scene]\ndescription = \"d\"\nsource = \"s\"\n\n[contact]\nproblem = \"two-bars\"\n\
                 striker = {{ length = 1.0, elements = 4 }}\n\
                 target = {{ length = 1.0, elements = 4, modulus = 4.0 }}\n\
                 velocity = 1.0\nschemes = [\"lagrange-multiplier\"]\nbulk = \"cd-rmm\"\n\
                 courant = {courant}\nend_time = 1.0\n"
            )
        };
        let above = Scene::parse("t", "t.toml", &text(0.99)).unwrap();
        let case = &above.contact[0];
        assert!(case.bulk.unwrap().critical.is_none());
        match run_contact(case) {
            Err(ContactRunError::Refused(ContactError::Unstable(e))) => {
                assert!(e.dt > e.dt_crit, "{e}");
            }
            other => panic!("expected a refusal, got {:?}", other.map(|r| r.case)),
        }
        let below = Scene::parse("t", "t.toml", &text(0.5)).unwrap();
        assert!(run_contact(&below.contact[0]).is_ok());
    }
}
