//! What a run records: the request checked against the model, and the stress profiles and node
//! histories of each level.

use super::contract::Integrator;
use super::settings::OutputRequest;
use crate::error::InputError;
use crate::model::Model;
use crate::output::{HistorySample, RunOutput, StressProfile};

/// Check the request: history nodes on the bar, profile steps within the run, intervals >= 1.
pub(super) fn validate_request(
    model: &Model,
    steps: usize,
    request: &OutputRequest,
) -> Result<(), InputError> {
    let last = model.bar().node_count() - 1;
    if let Some(&node) = request.history_nodes.iter().find(|&&n| n > last) {
        return Err(InputError::NodeIndex {
            field: "history node",
            node,
            last,
        });
    }
    if let Some(&step) = request.profile_steps.iter().find(|&&s| s > steps) {
        return Err(InputError::ProfileAfterLastStep { step, last: steps });
    }
    if request.history_every == 0 || request.energy_every == 0 {
        return Err(InputError::EveryIsZero {
            field: "history_every and energy_every",
        });
    }
    Ok(())
}

/// Record profiles and histories at step `n` (the stepper's current level).
#[allow(clippy::too_many_arguments)]
pub(super) fn record<'a, I: Integrator>(
    model: &Model,
    kernel: &I,
    step: usize,
    time: f64,
    initial_velocity: &[f64],
    request: &OutputRequest,
    output: &mut RunOutput,
    next_profile: &mut std::iter::Peekable<std::slice::Iter<'a, usize>>,
) {
    let u = kernel.displacement();
    record_profile(model, u, step, time, output, next_profile);
    if step.is_multiple_of(request.history_every) && !output.histories.is_empty() {
        for history in &mut output.histories {
            let i = history.node;
            let (velocity, acceleration) = kernel.velocity_and_acceleration_at(model, i, time);
            // At n = 0 the state's own v^0.
            let velocity = if step == 0 {
                initial_velocity[i]
            } else {
                velocity
            };
            history.samples.push(HistorySample {
                step,
                time,
                displacement: u[i],
                velocity,
                acceleration,
            });
        }
    }
}

/// Record the stress profile of displacements `u` at step `n` when `n` is the next profile step.
pub(super) fn record_profile<'a>(
    model: &Model,
    u: &[f64],
    step: usize,
    time: f64,
    output: &mut RunOutput,
    next_profile: &mut std::iter::Peekable<std::slice::Iter<'a, usize>>,
) {
    if next_profile.peek() == Some(&&step) {
        next_profile.next();
        output.profiles.push(StressProfile {
            step,
            time,
            stress: model.element_stress(u),
        });
    }
}
