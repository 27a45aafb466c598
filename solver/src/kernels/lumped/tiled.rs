//! Several lumped central-difference steps per pass over the bar (temporal blocking), on one or
//! several threads: the steps of [`crate::kernels::lumped::kernel`], bit for bit, with each array
//! streamed from memory once per [`DEPTH`] steps instead of once per step.
//!
//! **Tiles.** A sub-block of `S <= DEPTH` steps sweeps the bar in tiles of [`TILE`] nodes; a
//! tile runs all `S` steps before the next tile starts, so its `u`, `v`, `k`, `dt/m` stay in
//! cache. Step `s` (1-based) of the tile starting at padded node `L` updates
//!
//! ```text
//!   u^s       = u^{s-1} + dt v^{s-1/2}          on U_s = [L - s + 1, L + TILE - s + 1)
//!   v^{s+1/2} = v^{s-1/2} + dt/m (F - K u^s)    on V_s = [L - s,     L + TILE - s)
//! ```
//!
//! (a parallelogram in the node-step plane leaning left; the first tile starts at node 1, the
//! last runs to the last real node). Every read is at the right level: `U_s` is `V_{s-1}`, and
//! `V_s` reads `u^s` at `j - 1, j, j + 1`, all made by this tile's `U_s` or the left tile's,
//! except the leftmost neighbour `L - s - 1`, which the left tile already advanced to `u^{s+1}`:
//! that tile saved its `u^s` in an edge slot, and the first node of `V_s` reads the slot. Each
//! node computes the operations of the one-step kernel on the same operands: the states are
//! bit-identical.
//!
//! **Energy sums.** Step `s` keeps its own 8 lanes across tiles; nodes reach them in increasing
//! order, node `j` of a segment starting at `a` (after a loaded node) adding to lane
//! `(j - a) % 8` as in the one-step kernel (lanes rotated where a sweep starts mid-segment).
//!
//! **Threads** (`pipeline.rs`,
//! [`crate::kernels::lumped::kernel::LumpedStep::advance_block`]): the tiles are cut into one
//! contiguous region per thread. Region `q` runs sub-block `b` once region `q - 1` has finished
//! it (it continues that region's lanes and edge slots) and once region `q + 1` has finished the
//! first tile of sub-block `b - 1` (whose nodes it overwrites): a pipeline, the same operations
//! in the same order whatever the thread count, so the results are bit-identical to one thread.

use crate::kernels::energy::StepEnergy;
use crate::kernels::lumped::kernel::{Lanes, sweep_nodes, update_one_node};
use crate::simd::LANES;

/// Nodes per tile. A tile's arrays (`u`, `v`, `k`, `dt/m`, `m`: 40 B per node) take 40 KB,
/// inside the 48 KB L1 of the machine measured (benches/RESULTS.md).
pub const TILE: usize = 1024;

/// Steps per sub-block (the depth of a tile's parallelogram; below [`TILE`]).
pub const DEPTH: usize = 64;

/// Most steps one call takes (16 sub-blocks: the pipeline of the threads fills once per call).
pub const MAX_BLOCK_STEPS: usize = 16 * DEPTH;

/// The kernel's arrays (padded layout of [`crate::kernels::lumped::kernel`]) as raw pointers,
/// shared by the threads of a block. Each thread touches only the nodes of its tiles at each step;
/// the pipeline's waits order every write before any read of another thread.
#[derive(Clone, Copy)]
pub(crate) struct BarView {
    pub(crate) u: *mut f64,
    pub(crate) v: *mut f64,
    pub(crate) k: *const f64,
    pub(crate) dt_inverse_mass: *const f64,
    pub(crate) mass: *const f64,
    /// Padded length of `u`, `v`, `dt/m`, `m` (`k` is one shorter).
    pub(crate) len: usize,
    pub(crate) dt: f64,
}

// SAFETY: the pointers stay valid for the whole block (the kernel is borrowed mutably by
// `advance_block` until every thread has joined) and the threads' accesses are ordered by the
// pipeline (module docs): no two threads touch a node's `u` or `v` concurrently.
unsafe impl Send for BarView {}
unsafe impl Sync for BarView {}

/// What a block of steps takes and gives: the loads of each step, the nodes whose `u^s` and
/// `v^{s+1/2}` the caller wants after every step, and the energies. All buffers are sized once
/// ([`StepBlock::new`]); a block on one thread allocates nothing, a block on several allocates
/// its threads and the pipeline's counters (a fixed few per block, none per step).
#[derive(Debug, Clone)]
pub struct StepBlock {
    /// Loaded real nodes, sorted, each once.
    pub(crate) load_nodes: Vec<usize>,
    /// Real nodes whose displacement is recorded after every step, sorted, each once.
    pub(crate) u_probes: Vec<usize>,
    /// Real nodes whose half-step velocity is recorded after every step, sorted, each once.
    pub(crate) v_probes: Vec<usize>,
    /// `forces[s * loads + l]`: the force at `load_nodes[l]` for step `s + 1` of the block
    /// (`F^{n+s+1}`), filled by the caller.
    pub forces: Vec<f64>,
    /// Energies at the level after each step.
    pub energies: Vec<StepEnergy>,
    /// `u_values[s * u_probes + p]`: `u^{n+s+1}` at `u_probes[p]`.
    pub u_values: Vec<f64>,
    /// `v_values[s * v_probes + p]`: `v^{n+s+3/2}` at `v_probes[p]`.
    pub v_values: Vec<f64>,
    /// One per thread (grown when a kernel asks for more threads).
    pub(crate) workers: Vec<Worker>,
}

/// A thread's own buffers: the lanes and edge slots of the sub-block it is in, and the probe
/// values of its nodes (marked, so the block can collect them).
#[derive(Debug, Clone)]
pub(crate) struct Worker {
    pub(crate) lanes: Vec<Lanes>,
    /// `edge[s - 1]`: `u^s` of the node left of the next tile's first velocity update.
    pub(crate) edge: Vec<f64>,
    pub(crate) u_values: Vec<f64>,
    pub(crate) u_mine: Vec<bool>,
    pub(crate) v_values: Vec<f64>,
    pub(crate) v_mine: Vec<bool>,
}

impl Worker {
    fn new(u_probes: usize, v_probes: usize) -> Self {
        Self {
            lanes: vec![Lanes::default(); DEPTH],
            edge: vec![0.0; DEPTH],
            u_values: vec![0.0; MAX_BLOCK_STEPS * u_probes],
            u_mine: vec![false; MAX_BLOCK_STEPS * u_probes],
            v_values: vec![0.0; MAX_BLOCK_STEPS * v_probes],
            v_mine: vec![false; MAX_BLOCK_STEPS * v_probes],
        }
    }
}

/// Sorted, deduplicated copy.
fn sorted(nodes: &[usize]) -> Vec<usize> {
    let mut nodes = nodes.to_vec();
    nodes.sort_unstable();
    nodes.dedup();
    nodes
}

impl StepBlock {
    /// Buffers for blocks of up to [`MAX_BLOCK_STEPS`] steps with these loaded nodes and probes
    /// (real node indices; sorted and deduplicated here).
    pub fn new(load_nodes: &[usize], u_probes: &[usize], v_probes: &[usize]) -> Self {
        let (load_nodes, u_probes, v_probes) =
            (sorted(load_nodes), sorted(u_probes), sorted(v_probes));
        Self {
            forces: vec![0.0; MAX_BLOCK_STEPS * load_nodes.len()],
            energies: vec![StepEnergy::default(); MAX_BLOCK_STEPS],
            u_values: vec![0.0; MAX_BLOCK_STEPS * u_probes.len()],
            v_values: vec![0.0; MAX_BLOCK_STEPS * v_probes.len()],
            workers: vec![Worker::new(u_probes.len(), v_probes.len())],
            load_nodes,
            u_probes,
            v_probes,
        }
    }

    /// The loaded nodes (sorted): the order of each step's row of [`Self::forces`].
    pub fn load_nodes(&self) -> &[usize] {
        &self.load_nodes
    }

    /// The displacement probes (sorted): the order of each step's row of [`Self::u_values`].
    pub fn u_probes(&self) -> &[usize] {
        &self.u_probes
    }

    /// The velocity probes (sorted): the order of each step's row of [`Self::v_values`].
    pub fn v_probes(&self) -> &[usize] {
        &self.v_probes
    }

    /// Row `s` of [`Self::forces`]: the loads of step `s + 1` of the block.
    pub fn forces_row_mut(&mut self, s: usize) -> &mut [f64] {
        let loads = self.load_nodes.len();
        &mut self.forces[s * loads..(s + 1) * loads]
    }

    /// Row `s` of [`Self::forces`].
    pub fn forces_row(&self, s: usize) -> &[f64] {
        let loads = self.load_nodes.len();
        &self.forces[s * loads..(s + 1) * loads]
    }

    /// Row `s` of [`Self::u_values`]: `u` at the displacement probes after step `s + 1`.
    pub fn u_row(&self, s: usize) -> &[f64] {
        let width = self.u_probes.len();
        &self.u_values[s * width..(s + 1) * width]
    }

    /// Row `s` of [`Self::v_values`]: the half-step velocity at the velocity probes after step
    /// `s + 1`.
    pub fn v_row(&self, s: usize) -> &[f64] {
        let width = self.v_probes.len();
        &self.v_values[s * width..(s + 1) * width]
    }

    /// Workers for `threads` threads, their marks cleared for `steps` rows.
    pub(crate) fn prepare_workers(&mut self, threads: usize, steps: usize) {
        let (nu, nv) = (self.u_probes.len(), self.v_probes.len());
        self.workers.resize_with(threads, || Worker::new(nu, nv));
        for worker in &mut self.workers[..threads] {
            worker.u_mine[..steps * nu].fill(false);
            worker.v_mine[..steps * nv].fill(false);
        }
    }

    /// Collect the probe values each worker recorded into [`Self::u_values`] and
    /// [`Self::v_values`].
    pub(crate) fn collect_probes(&mut self, threads: usize, steps: usize) {
        let (nu, nv) = (self.u_probes.len(), self.v_probes.len());
        for worker in &self.workers[..threads] {
            for i in 0..steps * nu {
                if worker.u_mine[i] {
                    self.u_values[i] = worker.u_values[i];
                }
            }
            for i in 0..steps * nv {
                if worker.v_mine[i] {
                    self.v_values[i] = worker.v_values[i];
                }
            }
        }
    }
}

/// The loads and probes every thread reads.
#[derive(Clone, Copy)]
pub(crate) struct Plan<'a> {
    pub(crate) load_nodes: &'a [usize],
    pub(crate) forces: &'a [f64],
    pub(crate) u_probes: &'a [usize],
    pub(crate) v_probes: &'a [usize],
}

/// Record `values[p]` (and mark it) for the probes in padded `from..to` (padded = node + 1).
#[inline(always)]
fn record_probes(
    probes: &[usize],
    array: *const f64,
    (from, to): (usize, usize),
    values: &mut [f64],
    mine: &mut [bool],
) {
    let first = probes.partition_point(|&node| node + 1 < from);
    for (p, &node) in probes.iter().enumerate().skip(first) {
        if node + 1 >= to {
            break;
        }
        // SAFETY: from <= node + 1 < to <= the padded length; this thread owns the node now.
        values[p] = unsafe { *array.add(node + 1) };
        mine[p] = true;
    }
}

/// Sub-block steps `1..=steps` (rows `row0..row0 + steps` of the call) of the tile of padded
/// nodes `left..right` (`left = 1`: the bar's first tile; `right = usize::MAX`: its last).
///
/// # Safety
/// `bar` points to live arrays of the kernel, `worker.edge` holds the left tile's edge slots
/// (unless `left = 1`), and no other thread touches the nodes this tile touches (module docs).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn tile<const ENERGY: bool, const AVX2: bool>(
    bar: BarView,
    plan: Plan<'_>,
    worker: &mut Worker,
    row0: usize,
    steps: usize,
    left: usize,
    right: usize,
) {
    let end = bar.len - 1; // padded index after the last real node
    let first = left == 1;
    let loads = plan.load_nodes.len();
    let (nu, nv) = (plan.u_probes.len(), plan.v_probes.len());
    for s in 1..=steps {
        let row = row0 + s - 1;
        // u^s on U_s.
        let u_from = if first { 1 } else { left + 1 - s };
        let u_to = right.saturating_sub(s - 1).min(end);
        // SAFETY: 1 <= u_from <= u_to <= end < len; the nodes are this tile's at step s.
        let (u, v) = unsafe {
            (
                std::slice::from_raw_parts_mut(bar.u.add(u_from), u_to - u_from),
                std::slice::from_raw_parts(bar.v.add(u_from), u_to - u_from),
            )
        };
        for (u, v) in u.iter_mut().zip(v) {
            *u += bar.dt * v;
        }
        record_probes(
            plan.u_probes,
            bar.u,
            (u_from, u_to),
            &mut worker.u_values[row * nu..(row + 1) * nu],
            &mut worker.u_mine[row * nu..(row + 1) * nu],
        );

        // v^{s+1/2} on V_s: segments between loaded nodes; `start` is the padded node after
        // the last loaded node left of `v_from` (1 if none), where lanes count from.
        let v_from = if first { 1 } else { left - s };
        let v_to = right.saturating_sub(s).min(end);
        let mut lanes = if ENERGY {
            worker.lanes[s - 1]
        } else {
            Lanes::default()
        };
        let forces = &plan.forces[row * loads..(row + 1) * loads];
        let mut loaded = plan.load_nodes.partition_point(|&node| node + 1 < v_from);
        let mut start = if loaded == 0 {
            1
        } else {
            plan.load_nodes[loaded - 1] + 2
        };
        let mut from = v_from;
        if !first {
            // The first node reads its left neighbour's u^s from the edge slot.
            let p = v_from;
            let is_loaded = plan.load_nodes.get(loaded) == Some(&(p - 1));
            let force = is_loaded.then(|| forces[loaded]);
            let lane = if is_loaded { 0 } else { (p - start) % LANES };
            // SAFETY: 1 <= p - 1 and p + 1 <= end; p is this tile's node at step s.
            unsafe {
                let u = [worker.edge[s - 1], *bar.u.add(p), *bar.u.add(p + 1)];
                let k = [*bar.k.add(p - 1), *bar.k.add(p)];
                let dm = [*bar.dt_inverse_mass.add(p), *bar.mass.add(p)];
                update_one_node::<ENERGY>(u, k, force, &mut *bar.v.add(p), dm, &mut lanes, lane);
            }
            if is_loaded {
                loaded += 1;
                start = p + 1;
            }
            from = p + 1;
        }
        for (&node, &force) in plan.load_nodes[loaded..].iter().zip(&forces[loaded..]) {
            let p = node + 1;
            if p >= v_to {
                break;
            }
            // SAFETY: the tile's nodes at step s (`rotated_sweep`'s contract).
            unsafe {
                rotated_sweep::<ENERGY, AVX2>(bar, from, p, start, &mut lanes);
                let u = [*bar.u.add(p - 1), *bar.u.add(p), *bar.u.add(p + 1)];
                let k = [*bar.k.add(p - 1), *bar.k.add(p)];
                let dm = [*bar.dt_inverse_mass.add(p), *bar.mass.add(p)];
                let v = &mut *bar.v.add(p);
                update_one_node::<ENERGY>(u, k, Some(force), v, dm, &mut lanes, 0);
            }
            from = p + 1;
            start = p + 1;
        }
        // SAFETY: as above.
        unsafe { rotated_sweep::<ENERGY, AVX2>(bar, from, v_to, start, &mut lanes) };
        if ENERGY {
            worker.lanes[s - 1] = lanes;
        }
        record_probes(
            plan.v_probes,
            bar.v,
            (v_from, v_to),
            &mut worker.v_values[row * nv..(row + 1) * nv],
            &mut worker.v_mine[row * nv..(row + 1) * nv],
        );
        // The next tile's first velocity update (node right - s) reads u^s of node
        // right - s - 1, which this tile's step s + 1 overwrites.
        if right != usize::MAX {
            // SAFETY: right - s - 1 is in U_s of this tile.
            worker.edge[s - 1] = unsafe { *bar.u.add(right - s - 1) };
        }
    }
}

/// [`sweep_nodes`] of padded nodes `from..to` in a segment starting at `start`, each node
/// adding to lane `(node - start) % LANES`.
///
/// # Safety
/// `1 <= from`, `to <= end`, and the calling thread owns `v` of `from..to` and reads `u` of
/// `from - 1..=to` at step `s` without another thread writing them.
#[inline(always)]
unsafe fn rotated_sweep<const ENERGY: bool, const AVX2: bool>(
    bar: BarView,
    from: usize,
    to: usize,
    start: usize,
    lanes: &mut Lanes,
) {
    if from >= to {
        return;
    }
    let n = to - from;
    // SAFETY: the caller's contract; u: from-1..=to, k: from-1..to, v, dt/m, m: from..to.
    let (u, k, v, s, m) = unsafe {
        (
            std::slice::from_raw_parts(bar.u.add(from - 1), n + 2),
            std::slice::from_raw_parts(bar.k.add(from - 1), n + 1),
            std::slice::from_raw_parts_mut(bar.v.add(from), n),
            std::slice::from_raw_parts(bar.dt_inverse_mass.add(from), n),
            std::slice::from_raw_parts(bar.mass.add(from), n),
        )
    };
    let offset = (from - start) % LANES;
    if ENERGY && offset != 0 {
        lanes.rotate_left(offset);
        sweep_nodes::<ENERGY, AVX2>(u, k, v, s, m, lanes);
        lanes.rotate_right(offset);
    } else {
        sweep_nodes::<ENERGY, AVX2>(u, k, v, s, m, lanes);
    }
}

/// The number of tiles of a bar with padded length `len` (tile `t` starts at padded node
/// `1 + t TILE`; the last runs to the end).
pub(crate) fn tile_count(len: usize) -> usize {
    (len - 2).div_ceil(TILE).max(1)
}
