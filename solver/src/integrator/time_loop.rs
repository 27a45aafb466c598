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
//!
//! **Blocks of steps.** A stepper with temporal blocking ([`BlockStepper`], run by
//! [`run_in_blocks`]: lumped central difference, `kernels::lumped::tiled`) takes up to
//! [`crate::kernels::lumped::tiled::MAX_BLOCK_STEPS`] steps per call when the run must stay stable
//! (`allow_unstable` off); a block ends at the last step and at every profile step. The stepper
//! returns every step's energies and the displacements of the loaded nodes and of each history node
//! and its neighbours (with its half-step velocity), so the loop does exactly the per-step work
//! above on exactly the same numbers: the work, the balance, the guard, the energy samples and the
//! histories of every step are bit-identical to single steps. If the guard trips inside a block (a
//! stable run can trip it: the guard's ratio is the scene's `blowup_energy_ratio`, any positive
//! value), the step, time and energy ratio are the step's, but the state is past it; the run is
//! then repeated by single steps (it is deterministic: the same trip, the same partial output), so
//! the error names the node of largest `|u|` at its own step. That second run is the only cost, and
//! only on failure. A run allowed to be unstable steps singly from the start.

use super::blocks::{BlockBuffers, Probe, block_depth};
use super::contract::{BlockStepper, InitialState, Integrator};
use super::guard::{BlowUpGuard, impulse_energy};
use super::record::{record, record_profile};
use super::scheme::RunSetup;
use super::settings::OutputRequest;
use crate::error::{DivergenceError, RunError};
use crate::kernels::energy::StepEnergy;
use crate::kernels::lumped::tiled::StepBlock;
use crate::model::Model;
use crate::output::{EnergyLog, EnergySample, NodeHistory, RunOutput};

/// Run `setup.steps` steps of the scheme whose stepper is `I`, with its `parameters`, by single
/// steps. The caller ([`super::Integration::run`]) has validated the request and the step.
///
/// # Errors
/// [`RunError::Input`] when the stepper refuses its parameters, [`RunError::Diverged`] with the
/// partial output when the guard stops the run.
pub fn run<I: Integrator>(
    parameters: &I::Parameters,
    setup: RunSetup<'_>,
) -> Result<RunOutput, RunError> {
    run_with::<I>(parameters, setup, None)
}

/// [`run`] for a stepper that takes blocks of steps ([`BlockStepper`]): blocks when the run must
/// stay stable ([`takes_blocks`]), single steps otherwise; the same outputs either way.
///
/// # Errors
/// As [`run`].
pub fn run_in_blocks<I: BlockStepper>(
    parameters: &I::Parameters,
    setup: RunSetup<'_>,
) -> Result<RunOutput, RunError> {
    let blocks = Blocks {
        step: I::step_block,
        probe: I::probed_velocity_and_acceleration,
    };
    run_with(parameters, setup, Some(blocks))
}

/// The block capability of a [`BlockStepper`], as the loop calls it (once per block, and once per
/// history sample of a block): the loop itself is compiled once per stepper for both kinds.
struct Blocks<I> {
    step: fn(&mut I, &mut StepBlock, usize),
    probe: Probe<I>,
}

impl<I> Clone for Blocks<I> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<I> Copy for Blocks<I> {}

/// The run, repeated by single steps if the guard trips inside a block.
fn run_with<I: Integrator>(
    parameters: &I::Parameters,
    setup: RunSetup<'_>,
    blocks: Option<Blocks<I>>,
) -> Result<RunOutput, RunError> {
    // Kept to repeat the run by single steps if the guard trips inside a block (only a run
    // that takes blocks can; its mass is diagonal and shared, so the copy is cheap).
    let single_steps =
        takes_blocks(blocks.is_some(), setup.stability.allow_unstable).then(|| setup.clone());
    match run_steps::<I>(parameters, setup, blocks) {
        Stop::Finished(result) => result,
        Stop::TrippedInsideBlock(error) => match single_steps {
            Some(setup) => match run_steps::<I>(parameters, setup, None) {
                Stop::Finished(result) => result,
                Stop::TrippedInsideBlock(error) => Err(error),
            },
            None => Err(error),
        },
    }
}

/// Whether a run steps in blocks of steps: its stepper has them (`stepper_has_blocks`: a
/// [`BlockStepper`], as lumped central difference's) and the run must stay stable (an allowed
/// unstable run steps singly, so a divergence names the node of its own step). The one statement of
/// the rule: the loop, and [`crate::integrator::Scheme::takes_blocks`] (blocks are what run on
/// several threads), ask it.
pub fn takes_blocks(stepper_has_blocks: bool, allow_unstable: bool) -> bool {
    stepper_has_blocks && !allow_unstable
}

/// How [`run_steps`] ended: with the run's result, or with a guard trip inside a block of
/// steps, whose state is then past the trip step (the divergence's node would be read from a
/// later level).
enum Stop {
    Finished(Result<RunOutput, RunError>),
    TrippedInsideBlock(RunError),
}

/// The loop of [`run`]; `blocks`: the stepper's blocks of steps, if it has them and may take them.
fn run_steps<I: Integrator>(
    parameters: &I::Parameters,
    setup: RunSetup<'_>,
    blocks: Option<Blocks<I>>,
) -> Stop {
    match run_steps_result::<I>(parameters, setup, blocks) {
        Ok(output) => Stop::Finished(Ok(output)),
        Err(Tripped::InsideBlock(error)) => Stop::TrippedInsideBlock(error),
        Err(Tripped::No(error)) => Stop::Finished(Err(error)),
    }
}

/// An error of [`run_steps_result`]: a guard trip inside a block, or any other end.
enum Tripped {
    InsideBlock(RunError),
    No(RunError),
}

fn run_steps_result<I: Integrator>(
    parameters: &I::Parameters,
    setup: RunSetup<'_>,
    block_steps: Option<Blocks<I>>,
) -> Result<RunOutput, Tripped> {
    let RunSetup {
        model,
        dt,
        start,
        stability,
        mass: operator,
        steps,
        request,
        threads,
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
            threads,
        },
    )
    .map_err(|e| Tripped::No(e.into()))?;
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
    let mut ledger = Ledger {
        model,
        dt,
        previous_forces: forces.clone(),
        work: 0.0,
        max_work: 0.0,
        invariant0,
        guard,
    };
    let mut displaced = vec![0.0; forces.len()];
    let mut after = vec![0.0; forces.len()];
    // Temporal blocking where the stepper has it, for runs that must stay stable (an allowed
    // unstable run steps singly, so a divergence names the node of its own step).
    let mut blocks = block_steps
        .filter(|_| takes_blocks(true, stability.allow_unstable))
        .map(|ops| (ops, BlockBuffers::new(model, &load_nodes, request)));
    let mut step = 0;
    while step < steps {
        let depth = match &blocks {
            Some(_) => block_depth(step, steps, next_profile.peek().copied().copied()),
            None => 1,
        };
        if let (Some((ops, buffers)), true) = (&mut blocks, depth >= 2) {
            for (slot, f) in displaced.iter_mut().zip(&forces) {
                *slot = integrator.displacement()[f.0];
            }
            // The loads of every step of the block, evaluated once: the stepper reads them and
            // the accounting below takes them back.
            for s in 0..depth {
                eval_forces((step + s + 1) as f64 * dt, &mut forces);
                for (cell, f) in buffers.block.forces_row_mut(s).iter_mut().zip(&forces) {
                    *cell = f.1;
                }
            }
            (ops.step)(&mut integrator, &mut buffers.block, depth);
            for s in 0..depth {
                step += 1;
                let t = step as f64 * dt;
                for (f, &value) in forces.iter_mut().zip(buffers.block.forces_row(s)) {
                    f.1 = value;
                }
                buffers.load_displacements(s, &mut after);
                let sums = buffers.block.energies[s];
                let tripped =
                    ledger.after_step(step, &mut forces, &displaced, &after, sums, &mut output);
                if let Some(energy_ratio) = tripped {
                    let error = diverged(&integrator, step, t, energy_ratio, output);
                    // The state is at the block's end: at the trip step only if it is the last.
                    return Err(if s + 1 == depth {
                        Tripped::No(error)
                    } else {
                        Tripped::InsideBlock(error)
                    });
                }
                sample_energy(&ledger, step, steps, t, sums, request, &mut output, || None);
                if step.is_multiple_of(request.history_every) {
                    buffers.record_histories(
                        model,
                        &integrator,
                        ops.probe,
                        s,
                        step,
                        t,
                        &mut output,
                    );
                }
                std::mem::swap(&mut displaced, &mut after);
            }
            record_profile(
                model,
                integrator.displacement(),
                step,
                step as f64 * dt,
                &mut output,
                &mut next_profile,
            );
            continue;
        }
        step += 1;
        let t = step as f64 * dt;
        eval_forces(t, &mut forces);
        // Trapezoidal work: 1/2 (F^n + F^{n+1}) (u^{n+1} - u^n) at the loaded nodes.
        for (slot, f) in displaced.iter_mut().zip(&forces) {
            *slot = integrator.displacement()[f.0];
        }
        let sums = integrator.step(model, t - dt, &forces);
        for (slot, f) in after.iter_mut().zip(&forces) {
            *slot = integrator.displacement()[f.0];
        }
        let tripped = ledger.after_step(step, &mut forces, &displaced, &after, sums, &mut output);
        if let Some(energy_ratio) = tripped {
            return Err(Tripped::No(diverged(
                &integrator,
                step,
                t,
                energy_ratio,
                output,
            )));
        }
        // A stepper that carries T* forward by increments recomputes it from M at every
        // MASS_CHECK_EVERY-th sample and the last; any mismatch counts as balance error.
        sample_energy(&ledger, step, steps, t, sums, request, &mut output, || {
            integrator.recomputed_balance_kinetic()
        });
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

/// What the loop carries from step to step: the loads of the last level, the trapezoidal work
/// and the energy reference of the guard (with the model and step the impulse energy needs).
struct Ledger<'a> {
    model: &'a Model,
    dt: f64,
    previous_forces: Vec<(usize, f64)>,
    work: f64,
    max_work: f64,
    invariant0: f64,
    guard: BlowUpGuard,
}

impl Ledger<'_> {
    /// Account for step `step` (loads `forces` = `F^{n+1}`, displacements of the loaded nodes
    /// `before` = `u^n` and `after` = `u^{n+1}`, energies `sums`): the work, the guard, the
    /// balance error and the energy scale; `Some(ratio)` when the guard trips. `forces` is left
    /// holding `F^n`'s buffer (swapped with the kept loads).
    fn after_step(
        &mut self,
        step: usize,
        forces: &mut Vec<(usize, f64)>,
        before: &[f64],
        after: &[f64],
        sums: StepEnergy,
        output: &mut RunOutput,
    ) -> Option<f64> {
        self.work += forces
            .iter()
            .zip(&self.previous_forces)
            .zip(before.iter().zip(after))
            .map(|((f, f0), (u0, u))| 0.5 * (f.1 + f0.1) * (u - u0))
            .sum::<f64>();
        self.guard.admit(self.work.abs());
        self.guard
            .admit(impulse_energy(self.model, self.dt, forces));
        std::mem::swap(forces, &mut self.previous_forces);

        let balance_error = sums.kinetic_staggered + sums.strain - self.work - self.invariant0;
        let mechanical = sums.kinetic + sums.strain;
        self.max_work = self.max_work.max(self.work.abs());
        let energy = &mut output.energy;
        energy.max_balance_error = energy.max_balance_error.max(balance_error.abs());
        energy.scale = energy.scale.max(self.max_work).max(mechanical);
        output.steps = step;
        self.guard.tripped(mechanical)
    }

    /// `T* + U - W - E^0` after a step.
    fn balance_error(&self, sums: StepEnergy) -> f64 {
        sums.kinetic_staggered + sums.strain - self.work - self.invariant0
    }
}

/// Energy samples between two recomputations of `T*` from the mass matrix (a solve or product
/// over the whole bar, a few steps' cost for CMM, AMM and RMM): every 64th sample and the last.
/// The running `T*` is exact per step (its increments are the step's own sums, checked by the
/// balance at every step); the recomputation checks the mass operator against `M^-1`, whose
/// round-off accumulates slowly, so a check every 64 samples bounds it at each check.
pub const MASS_CHECK_EVERY: usize = 64;

/// Whether the energy sample at `step` (a multiple of `energy_every`, or the last step `steps`)
/// recomputes `T*` from the mass: every [`MASS_CHECK_EVERY`]-th sample (step 0 included) and
/// the last.
fn checks_mass(step: usize, steps: usize, energy_every: usize) -> bool {
    step == steps || (step / energy_every).is_multiple_of(MASS_CHECK_EVERY)
}

/// Log the energies of step `step` when it is a sample (every `energy_every` steps and the
/// last); `recomputed` gives `T*` recomputed from the mass for steppers that carry it by
/// increments, asked at every [`MASS_CHECK_EVERY`]-th sample and the last.
#[allow(clippy::too_many_arguments)]
fn sample_energy(
    ledger: &Ledger,
    step: usize,
    steps: usize,
    time: f64,
    sums: StepEnergy,
    request: &OutputRequest,
    output: &mut RunOutput,
    recomputed: impl FnOnce() -> Option<f64>,
) {
    if !(step.is_multiple_of(request.energy_every) || step == steps) {
        return;
    }
    let balance_error = ledger.balance_error(sums);
    let mass_check = checks_mass(step, steps, request.energy_every);
    let balance_error = match mass_check.then(recomputed).flatten() {
        Some(from_mass) => balance_error + (from_mass - sums.kinetic_staggered),
        None => balance_error,
    };
    let energy = &mut output.energy;
    energy.max_balance_error = energy.max_balance_error.max(balance_error.abs());
    energy.samples.push(EnergySample {
        step,
        time,
        kinetic: sums.kinetic,
        kinetic_staggered: sums.kinetic_staggered,
        strain: sums.strain,
        work: ledger.work,
        balance_error,
    });
}

/// The error of a diverged run: the step, its time, the node of largest `|u|` (or the first
/// NaN) in the stepper's state, the energy ratio and the Courant number, with the output so far.
fn diverged<I: Integrator>(
    integrator: &I,
    step: usize,
    time: f64,
    energy_ratio: f64,
    output: RunOutput,
) -> RunError {
    let u = integrator.displacement();
    let node = (0..u.len()).fold(0, |best, i| {
        if u[i].abs() > u[best].abs() || u[i].is_nan() {
            i
        } else {
            best
        }
    });
    let error = DivergenceError {
        step,
        time,
        node,
        energy_ratio,
        courant: output.courant,
    };
    RunError::Diverged {
        error,
        partial: Box::new(output),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_mass_is_checked_at_every_64th_sample_and_the_last() {
        // Samples every step, 200 steps: steps 64, 128, 192 and the last, 200.
        let checked: Vec<usize> = (1..=200).filter(|&s| checks_mass(s, 200, 1)).collect();
        assert_eq!(checked, [64, 128, 192, 200]);
        // Samples every 3 steps: the 64th sample is step 192; a run shorter than 64 samples
        // checks only its last step.
        let checked: Vec<usize> = (3..=400)
            .step_by(3)
            .filter(|&s| checks_mass(s, 400, 3))
            .collect();
        assert_eq!(checked, [192, 384]);
        assert!(checks_mass(400, 400, 3));
        assert_eq!((1..50).filter(|&s| checks_mass(s, 50, 1)).count(), 0);
        assert!(checks_mass(50, 50, 1));
    }
}
