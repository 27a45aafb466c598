//! The time loop every scheme runs (generic over its [`Integrator`], compiled once per stepper):
//! the common start, the steps, the loads and their work, the energy balance, the blow-up guard
//! and the recording.
//!
//! The balance checks the scheme's balance energy `E^n = T*^n + U^n` (module docs of
//! [`super`]) against the trapezoidal work `W^{n+1} - W^n = 1/2 (F^n + F^{n+1}) (u^{n+1} - u^n)`
//! at the loaded nodes. For central difference the identity is exact (linear system, any mass,
//! any `dt`): with `E^n = 1/2 v^{n-1/2} M v^{n+1/2} + 1/2 u^n K u^n` and
//! `v^{n+3/2} - v^{n-1/2} = dt (a^n + a^{n+1}) = dt M^-1 (F^n + F^{n+1} - K (u^n + u^{n+1}))`,
//!
//! ```text
//!   E^{n+1} - E^n = 1/2 dt v^{n+1/2} (F^n + F^{n+1}) - 1/2 (u^{n+1} - u^n) K (u^{n+1} + u^n)
//!                   + 1/2 (u^{n+1} K u^{n+1} - u^n K u^n)
//!                 = 1/2 (F^n + F^{n+1}) (u^{n+1} - u^n),
//! ```
//!
//! the trapezoidal work increment, exactly. So `E^n - W^n` is constant to round-off; for a
//! dissipative scheme its drift is the energy the scheme removed.

use super::contract::{InitialState, Integrator};
use super::guard::{BlowUpGuard, impulse_energy};
use super::record::record;
use super::scheme::RunSetup;
use crate::error::{DivergenceError, RunError};
use crate::output::{EnergyLog, EnergySample, NodeHistory, RunOutput};

/// Run `setup.steps` steps of the scheme whose stepper is `I`, with its `parameters`. The caller
/// ([`super::Integration::run`]) has validated the request and the step.
///
/// # Errors
/// [`RunError::Input`] when the stepper refuses its parameters, [`RunError::Diverged`] with the
/// partial output when the guard stops the run.
pub fn run<I: Integrator>(
    parameters: &I::Parameters,
    setup: RunSetup<'_>,
) -> Result<RunOutput, RunError> {
    let RunSetup {
        model,
        dt,
        start,
        stability,
        mass: operator,
        steps,
        request,
    } = setup;
    let nodes = model.bar().node_count();

    // Loads: unique sorted nodes, each load mapped to its node's slot.
    let mut load_nodes: Vec<usize> = model.loads().iter().map(|l| l.node).collect();
    load_nodes.sort_unstable();
    load_nodes.dedup();
    let slots: Vec<usize> = model
        .loads()
        .iter()
        .map(|l| load_nodes.binary_search(&l.node).unwrap_or(0))
        .collect();
    let mut forces: Vec<(usize, f64)> = load_nodes.iter().map(|&n| (n, 0.0)).collect();
    let eval_forces = |t: f64, forces: &mut Vec<(usize, f64)>| {
        forces.iter_mut().for_each(|f| f.1 = 0.0);
        for (load, &slot) in model.loads().iter().zip(&slots) {
            forces[slot].1 += load.force(t);
        }
    };

    // The common start: r^0 = F(0) - K u^0, a^0 = M^-1 r^0, T^0, U^0.
    let u0 = model.initial_displacement();
    let v0 = model.initial_velocity();
    let r0: Vec<f64> = (0..nodes)
        .map(|i| model.external_force_at(i, 0.0) + model.internal_force_at(u0, i))
        .collect();
    let mut a0 = vec![0.0; nodes];
    operator.apply_inverse(&r0, &mut a0);
    let mut m_times = vec![0.0; nodes];
    operator.apply(v0, &mut m_times);
    let kinetic0 = 0.5 * v0.iter().zip(&m_times).map(|(a, b)| a * b).sum::<f64>();
    // Freed at once: the stepper's start allocates its own state next.
    drop(m_times);
    let strain0 = model.strain_energy(u0);
    let mut integrator = I::start(
        parameters,
        InitialState {
            model,
            dt,
            displacement: u0,
            velocity: v0,
            acceleration: &a0,
            residual: &r0,
            kinetic: kinetic0,
            start,
            allow_unstable: stability.allow_unstable,
            mass: operator,
        },
    )?;
    // The start's arrays are not needed by the steps: free them before the loop (16 bytes per
    // node that a long run would otherwise hold).
    drop((r0, a0));
    let kinetic_staggered0 = integrator.start_energy();
    let invariant0 = kinetic_staggered0 + strain0;

    let mut output = RunOutput {
        dt,
        steps: 0,
        courant: model.bar().courant_number(dt),
        profiles: Vec::with_capacity(request.profile_steps.len()),
        histories: request
            .history_nodes
            .iter()
            .map(|&node| NodeHistory {
                node,
                x: model.bar().mesh().nodes()[node],
                samples: Vec::new(),
            })
            .collect(),
        energy: EnergyLog::default(),
    };
    let mut profile_steps: Vec<usize> = request.profile_steps.clone();
    profile_steps.sort_unstable();
    profile_steps.dedup();
    let mut next_profile = profile_steps.iter().peekable();

    output.energy.samples.push(EnergySample {
        step: 0,
        time: 0.0,
        kinetic: kinetic0,
        kinetic_staggered: kinetic_staggered0,
        strain: strain0,
        work: 0.0,
        balance_error: 0.0,
    });
    output.energy.scale = kinetic0 + strain0;
    let mut guard = BlowUpGuard::new(stability.blowup_energy_ratio, kinetic0 + strain0);
    let mut max_work = 0.0_f64;
    record(
        model,
        &integrator,
        0,
        0.0,
        v0,
        request,
        &mut output,
        &mut next_profile,
    );

    eval_forces(0.0, &mut forces);
    guard.admit(impulse_energy(model, dt, &forces));
    let mut previous_forces = forces.clone();
    let mut work = 0.0;
    let mut displaced = vec![0.0; forces.len()];
    for step in 1..=steps {
        let t = step as f64 * dt;
        eval_forces(t, &mut forces);
        // Trapezoidal work: 1/2 (F^n + F^{n+1}) (u^{n+1} - u^n) at the loaded nodes.
        for (slot, f) in displaced.iter_mut().zip(&forces) {
            *slot = integrator.displacement()[f.0];
        }
        let sums = integrator.step(model, t - dt, &forces);
        let u = integrator.displacement();
        work += forces
            .iter()
            .zip(&previous_forces)
            .zip(&displaced)
            .map(|((f, f0), u0)| 0.5 * (f.1 + f0.1) * (u[f.0] - u0))
            .sum::<f64>();
        guard.admit(work.abs());
        guard.admit(impulse_energy(model, dt, &forces));
        std::mem::swap(&mut forces, &mut previous_forces);

        let balance_error = sums.kinetic_staggered + sums.strain - work - invariant0;
        let mechanical = sums.kinetic + sums.strain;
        max_work = max_work.max(work.abs());
        let energy = &mut output.energy;
        energy.max_balance_error = energy.max_balance_error.max(balance_error.abs());
        energy.scale = energy.scale.max(max_work).max(mechanical);
        output.steps = step;
        if let Some(energy_ratio) = guard.tripped(mechanical) {
            let u = integrator.displacement();
            let node = (0..nodes).fold(0, |best, i| {
                if u[i].abs() > u[best].abs() || u[i].is_nan() {
                    i
                } else {
                    best
                }
            });
            let error = DivergenceError {
                step,
                time: t,
                node,
                energy_ratio,
                courant: output.courant,
            };
            return Err(RunError::Diverged {
                error,
                partial: Box::new(output),
            });
        }
        if step.is_multiple_of(request.energy_every) || step == steps {
            // A stepper that carries T* forward by increments recomputes it from M at each
            // sample; any mismatch counts as balance error.
            let balance_error = match integrator.recomputed_balance_kinetic() {
                Some(from_mass) => balance_error + (from_mass - sums.kinetic_staggered),
                None => balance_error,
            };
            energy.max_balance_error = energy.max_balance_error.max(balance_error.abs());
            energy.samples.push(EnergySample {
                step,
                time: t,
                kinetic: sums.kinetic,
                kinetic_staggered: sums.kinetic_staggered,
                strain: sums.strain,
                work,
                balance_error,
            });
        }
        record(
            model,
            &integrator,
            step,
            t,
            &[],
            request,
            &mut output,
            &mut next_profile,
        );
    }
    Ok(output)
}
