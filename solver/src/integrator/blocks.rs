//! What the time loop needs to take blocks of steps (temporal blocking,
//! [`crate::kernels::lumped::tiled`]): where the next block ends, and the buffers of a block with
//! the probes that give the loop each step's loads' displacements and history samples.

use super::settings::OutputRequest;
use crate::kernels::lumped::tiled::{MAX_BLOCK_STEPS, StepBlock};
use crate::model::Model;
use crate::output::{HistorySample, RunOutput};

/// A [`BlockStepper::probed_velocity_and_acceleration`](super::contract::BlockStepper):
/// `(v^n, a^n)` at a node from the three displacements and the half-step velocity a block recorded.
pub(super) type Probe<I> = fn(&I, &Model, usize, f64, [f64; 3], f64) -> (f64, f64);

/// The steps of the next block: up to [`MAX_BLOCK_STEPS`], ending at the last step and at the
/// next profile step (a profile needs the whole bar at its level).
pub(super) fn block_depth(step: usize, steps: usize, next_profile: Option<usize>) -> usize {
    let mut end = (step + MAX_BLOCK_STEPS).min(steps);
    if let Some(profile) = next_profile.filter(|&p| p > step) {
        end = end.min(profile);
    }
    end - step
}

/// The buffers of blocks of steps: the [`StepBlock`] with the loaded nodes, and every history
/// node with its neighbours as displacement probes and itself as a velocity probe.
pub(super) struct BlockBuffers {
    pub(super) block: StepBlock,
    /// Probe index of each loaded node (in the loop's load order).
    load_probe: Vec<usize>,
    /// Probe indices `[i-1, i, i+1]` and the velocity probe of each history.
    history_probes: Vec<([usize; 3], usize)>,
}

impl BlockBuffers {
    pub(super) fn new(model: &Model, load_nodes: &[usize], request: &OutputRequest) -> Self {
        let last = model.bar().node_count() - 1;
        let neighbours = |i: usize| [i.saturating_sub(1), i, (i + 1).min(last)];
        let mut u_probes: Vec<usize> = load_nodes.to_vec();
        for &i in &request.history_nodes {
            u_probes.extend(neighbours(i));
        }
        let block = StepBlock::new(load_nodes, &u_probes, &request.history_nodes);
        // The loop's loads are sorted and unique too: the block's force rows are in its order.
        debug_assert_eq!(block.load_nodes(), load_nodes);
        let index = |probes: &[usize], node: usize| probes.binary_search(&node).unwrap_or(0);
        let load_probe = load_nodes
            .iter()
            .map(|&n| index(block.u_probes(), n))
            .collect();
        let history_probes = request
            .history_nodes
            .iter()
            .map(|&i| {
                (
                    neighbours(i).map(|n| index(block.u_probes(), n)),
                    index(block.v_probes(), i),
                )
            })
            .collect();
        Self {
            block,
            load_probe,
            history_probes,
        }
    }

    /// The displacements of the loaded nodes after block row `s` (in the loop's load order).
    pub(super) fn load_displacements(&self, s: usize, out: &mut [f64]) {
        let u = self.block.u_row(s);
        for (value, &p) in out.iter_mut().zip(&self.load_probe) {
            *value = u[p];
        }
    }

    /// The history samples of block row `s` (step `step`, time `t`), as
    /// [`super::record::record`] takes them from the state.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn record_histories<I>(
        &self,
        model: &Model,
        integrator: &I,
        probe: Probe<I>,
        s: usize,
        step: usize,
        t: f64,
        output: &mut RunOutput,
    ) {
        let (u, v) = (self.block.u_row(s), self.block.v_row(s));
        for (history, (around, at)) in output.histories.iter_mut().zip(&self.history_probes) {
            let i = history.node;
            let three = around.map(|p| u[p]);
            let (velocity, acceleration) = probe(integrator, model, i, t, three, v[*at]);
            history.samples.push(HistorySample {
                step,
                time: t,
                displacement: three[1],
                velocity,
                acceleration,
            });
        }
    }
}
