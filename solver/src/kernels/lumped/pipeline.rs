//! Blocks of lumped central-difference steps on one or several threads: the tiles of
//! [`crate::kernels::lumped::tiled`] cut into one contiguous region per thread, run as a pipeline.
//!
//! ```text
//!   region:      0          1          2
//!   sub-block 0  [A0] ----> [B0] ----> [C0]        --> : continues the lanes and edge slots
//!   sub-block 1  [A1] ----> [B1] ----> [C1]            of the region on the left
//!                  ^--- waits for B0's first tile (which rewrites the nodes A1 ends on)
//! ```
//!
//! Region `q` runs sub-block `b` when region `q - 1` has finished `b` (its energy lanes and edge
//! slots are the start of region `q`'s, exactly as one thread would carry them from tile to
//! tile) and region `q + 1` has finished its first tile of `b - 1`. Each node-step is computed
//! by one thread with the operands one thread would use, and each step's lanes receive the nodes
//! in increasing order: the states, energies and probes are bit-identical whatever the thread
//! count (unit test below and `solver/tests`). With `P` threads and `B` sub-blocks per call the
//! pipeline keeps every thread busy but for `P - 1` sub-blocks: a speed-up of at most
//! `P B / (B + P - 1)` (1.88 for two threads and 16 sub-blocks).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};

use crate::kernels::energy::StepEnergy;
use crate::kernels::lumped::kernel::{Lanes, LumpedStep};
use crate::kernels::lumped::tiled::{
    BarView, DEPTH, MAX_BLOCK_STEPS, Plan, StepBlock, TILE, Worker, tile, tile_count,
};

/// What a region hands to the next at the end of a sub-block.
#[derive(Debug)]
struct Seam {
    lanes: [Lanes; DEPTH],
    edge: [f64; DEPTH],
}

/// The pipeline's counters and seams (one per region).
struct Pipeline {
    /// `done[q]`: sub-blocks region `q` has finished.
    done: Vec<AtomicUsize>,
    /// `first[q]`: sub-blocks whose first tile region `q` has finished.
    first: Vec<AtomicUsize>,
    seams: Vec<Mutex<Seam>>,
    /// Set when a region's thread panicked: the others stop waiting for it (and panic too, so
    /// the block fails instead of hanging).
    failed: AtomicBool,
}

/// Marks the pipeline failed if its thread unwinds.
struct FailOnPanic<'a>(&'a AtomicBool);

impl Drop for FailOnPanic<'_> {
    fn drop(&mut self) {
        if std::thread::panicking() {
            self.0.store(true, Ordering::Release);
        }
    }
}

/// Wait until `counter >= value` (spin briefly, then yield: the machine may be shared).
///
/// # Panics
/// When another region's thread panicked (`failed`): the block cannot complete.
fn wait_for(counter: &AtomicUsize, value: usize, failed: &AtomicBool) {
    let mut spins = 0u32;
    while counter.load(Ordering::Acquire) < value {
        assert!(
            !failed.load(Ordering::Acquire),
            "another thread of the block of steps panicked"
        );
        if spins < 1 << 12 {
            spins += 1;
            std::hint::spin_loop();
        } else {
            std::thread::yield_now();
        }
    }
}

impl LumpedStep {
    /// Advance `steps` steps (1..=[`MAX_BLOCK_STEPS`]) with the loads in `block.forces`,
    /// recording the probes and (with `ENERGY`) the energies of every step, on
    /// [`Self::threads`] threads: bit-identical to `steps` calls of [`Self::step`] /
    /// [`Self::step_with_energy`] whatever the thread count.
    ///
    /// # Panics
    /// When `steps` is 0 or above [`MAX_BLOCK_STEPS`], or a load or probe of `block` is not a
    /// node of the bar (a caller's bug, not user input).
    pub fn advance_block<const ENERGY: bool>(&mut self, block: &mut StepBlock, steps: usize) {
        assert!(
            (1..=MAX_BLOCK_STEPS).contains(&steps),
            "block of {steps} steps"
        );
        let bar = BarView {
            u: self.u.as_mut_ptr(),
            v: self.v.as_mut_ptr(),
            k: self.k.as_ptr(),
            dt_inverse_mass: self.dt_inverse_mass.as_ptr(),
            mass: self.mass.as_ptr(),
            len: self.u.len(),
            dt: self.dt,
        };
        let nodes = bar.len - 2;
        let in_range = |nodes_of: &[usize]| nodes_of.last().is_none_or(|&last| last < nodes);
        assert!(
            in_range(&block.load_nodes) && in_range(&block.u_probes) && in_range(&block.v_probes),
            "a block's loads and probes must be nodes of the bar (0..{nodes})"
        );
        let tiles = tile_count(bar.len);
        // One thread per region of at least one tile, and no more threads than sub-blocks (a
        // pipeline of one sub-block runs its regions one after the other).
        let threads = self.threads.clamp(1, tiles.min(steps.div_ceil(DEPTH)));
        block.prepare_workers(threads, steps);
        let StepBlock {
            load_nodes,
            u_probes,
            v_probes,
            forces,
            energies,
            workers,
            ..
        } = block;
        let plan = Plan {
            load_nodes,
            forces,
            u_probes,
            v_probes,
        };
        let avx2 = self.avx2;
        let energies = &mut energies[..steps];
        if threads == 1 {
            run_region::<ENERGY>(
                avx2,
                bar,
                plan,
                &mut workers[0],
                None,
                (0, tiles),
                steps,
                Some(energies),
            );
        } else {
            let pipeline = Pipeline {
                done: (0..threads).map(|_| AtomicUsize::new(0)).collect(),
                first: (0..threads).map(|_| AtomicUsize::new(0)).collect(),
                seams: (0..threads)
                    .map(|_| {
                        Mutex::new(Seam {
                            lanes: [Lanes::default(); DEPTH],
                            edge: [0.0; DEPTH],
                        })
                    })
                    .collect(),
                failed: AtomicBool::new(false),
            };
            let pipeline = &pipeline;
            let mut energies = Some(energies);
            std::thread::scope(|scope| {
                let mut regions = workers[..threads].iter_mut().enumerate();
                let (_, first_worker) = regions.next().expect("at least one worker");
                for (q, worker) in regions {
                    let region = (tiles * q / threads, tiles * (q + 1) / threads);
                    // The last region's lanes are the step's energies.
                    let out = if q + 1 == threads {
                        energies.take()
                    } else {
                        None
                    };
                    scope.spawn(move || {
                        run_region::<ENERGY>(
                            avx2,
                            bar,
                            plan,
                            worker,
                            Some((q, pipeline)),
                            region,
                            steps,
                            out,
                        );
                    });
                }
                let region = (0, tiles / threads);
                run_region::<ENERGY>(
                    avx2,
                    bar,
                    plan,
                    first_worker,
                    Some((0, pipeline)),
                    region,
                    steps,
                    None,
                );
            });
        }
        block.collect_probes(threads, steps);
    }
}

/// Run region `tiles.0..tiles.1` of every sub-block (the AVX2-compiled copy where the CPU has
/// it). `pipeline`: this region's index and the pipeline, `None` for one thread.
#[allow(clippy::too_many_arguments)]
fn run_region<const ENERGY: bool>(
    avx2: bool,
    bar: BarView,
    plan: Plan<'_>,
    worker: &mut Worker,
    pipeline: Option<(usize, &Pipeline)>,
    tiles: (usize, usize),
    steps: usize,
    energies: Option<&mut [StepEnergy]>,
) {
    #[cfg(target_arch = "x86_64")]
    if avx2 {
        // SAFETY: `avx2` is set only when the running CPU reports AVX2 support; the arrays
        // outlive the call (`advance_block` borrows the kernel until the threads join).
        unsafe { region_avx2::<ENERGY>(bar, plan, worker, pipeline, tiles, steps, energies) };
        return;
    }
    let _ = avx2;
    // SAFETY: as above.
    unsafe { region::<ENERGY, false>(bar, plan, worker, pipeline, tiles, steps, energies) };
}

/// [`region`] compiled with AVX2.
///
/// # Safety
/// The CPU must have AVX2; the contract of [`region`].
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[allow(clippy::too_many_arguments)]
unsafe fn region_avx2<const ENERGY: bool>(
    bar: BarView,
    plan: Plan<'_>,
    worker: &mut Worker,
    pipeline: Option<(usize, &Pipeline)>,
    tiles: (usize, usize),
    steps: usize,
    energies: Option<&mut [StepEnergy]>,
) {
    // SAFETY: the caller's contract.
    unsafe { region::<ENERGY, true>(bar, plan, worker, pipeline, tiles, steps, energies) };
}

/// The sub-blocks of one region, with the pipeline's waits and hand-overs (module docs).
///
/// # Safety
/// `bar` points to the kernel's live arrays; the regions of one call partition the tiles.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn region<const ENERGY: bool, const AVX2: bool>(
    bar: BarView,
    plan: Plan<'_>,
    worker: &mut Worker,
    pipeline: Option<(usize, &Pipeline)>,
    (t0, t1): (usize, usize),
    steps: usize,
    mut energies: Option<&mut [StepEnergy]>,
) {
    let (q, threads) = pipeline.map_or((0, 1), |(q, p)| (q, p.done.len()));
    let _fail_on_panic = pipeline.map(|(_, p)| FailOnPanic(&p.failed));
    let last_tile = tile_count(bar.len) - 1;
    for b in 0..steps.div_ceil(DEPTH) {
        let row0 = b * DEPTH;
        let depth = DEPTH.min(steps - row0);
        match pipeline {
            Some((q, p)) if q > 0 => {
                wait_for(&p.done[q - 1], b + 1, &p.failed);
                let seam = p.seams[q - 1]
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner);
                worker.lanes[..depth].copy_from_slice(&seam.lanes[..depth]);
                worker.edge[..depth].copy_from_slice(&seam.edge[..depth]);
            }
            _ => {
                if ENERGY {
                    worker.lanes[..depth].fill(Lanes::default());
                }
            }
        }
        if let Some((_, p)) = pipeline.filter(|_| q + 1 < threads) {
            wait_for(&p.first[q + 1], b, &p.failed);
        }
        for t in t0..t1 {
            let left = 1 + t * TILE;
            let right = if t == last_tile {
                usize::MAX
            } else {
                left + TILE
            };
            // SAFETY: the pipeline's waits give this thread the tile's nodes (module docs).
            unsafe { tile::<ENERGY, AVX2>(bar, plan, worker, row0, depth, left, right) };
            if let Some((_, p)) = pipeline.filter(|_| t == t0) {
                p.first[q].store(b + 1, Ordering::Release);
            }
        }
        match pipeline {
            Some((_, p)) if q + 1 < threads => {
                let mut seam = p.seams[q].lock().unwrap_or_else(PoisonError::into_inner);
                seam.lanes[..depth].copy_from_slice(&worker.lanes[..depth]);
                seam.edge[..depth].copy_from_slice(&worker.edge[..depth]);
                drop(seam);
                p.done[q].store(b + 1, Ordering::Release);
            }
            _ => {
                if let (true, Some(out)) = (ENERGY, energies.as_deref_mut()) {
                    for (energy, lanes) in out[row0..row0 + depth].iter_mut().zip(&worker.lanes) {
                        *energy = lanes.energy();
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::fixtures::graded_test_kernel as graded_kernel;

    /// Blocks on 1, 2, 3 and 5 threads against single steps: loads at the first and last node,
    /// inside a tile, on a tile edge and where a region's first velocity update lands on a loaded
    /// node (node `4 TILE - 3` is the first node of region 1's step 3 with three threads);
    /// probes across tile and region edges; blocks of 1, 5, 64, 65 and 1024 steps.
    #[test]
    fn blocks_are_bit_identical_to_single_steps_whatever_the_thread_count() {
        let n = 13 * TILE + 37;
        let load_nodes = [0, 700, TILE - 1, 4 * TILE - 3, 8 * TILE + 5, n];
        let u_probes = [
            0,
            1,
            TILE - 2,
            TILE - 1,
            TILE,
            4 * TILE - 40,
            4 * TILE,
            n - 1,
            n,
        ];
        let v_probes = [0, TILE - 1, 1500, 4 * TILE - 2, 9 * TILE - 30, n];
        let force = |step: usize, l: usize| ((step * 7 + l) as f64 * 0.31).cos();
        let avx2_variants = [false, crate::simd::has_avx2()];
        let cases = [(true, 1), (true, 2), (true, 3), (true, 5), (false, 2)];
        for (avx2, (energy, threads)) in avx2_variants
            .iter()
            .flat_map(|&a| cases.iter().map(move |&c| (a, c)))
        {
            let mut single = graded_kernel(n);
            let mut tiled = graded_kernel(n);
            single.avx2 = avx2;
            tiled.avx2 = avx2;
            tiled.set_threads(threads);
            let mut block = StepBlock::new(&load_nodes, &u_probes, &v_probes);
            assert_eq!(
                (block.u_probes(), block.v_probes()),
                (&u_probes[..], &v_probes[..])
            );
            let mut step = 0;
            for steps in [1, 5, DEPTH, DEPTH + 1, MAX_BLOCK_STEPS] {
                for s in 0..steps {
                    for l in 0..load_nodes.len() {
                        block.forces[s * load_nodes.len() + l] = force(step + s + 1, l);
                    }
                }
                if energy {
                    tiled.advance_block::<true>(&mut block, steps);
                } else {
                    tiled.advance_block::<false>(&mut block, steps);
                }
                for s in 0..steps {
                    step += 1;
                    let forces: Vec<(usize, f64)> = load_nodes
                        .iter()
                        .enumerate()
                        .map(|(l, &node)| (node, force(step, l)))
                        .collect();
                    let e = single.step_with_energy(&forces);
                    let context = format!("threads {threads}, avx2 {avx2}, step {step}");
                    if energy {
                        assert_eq!(block.energies[s], e, "{context}");
                    }
                    let u = single.displacement();
                    let v = single.half_step_velocity();
                    for (p, &node) in u_probes.iter().enumerate() {
                        let got = block.u_values[s * u_probes.len() + p];
                        assert_eq!(got.to_bits(), u[node].to_bits(), "u{node}, {context}");
                    }
                    for (p, &node) in v_probes.iter().enumerate() {
                        let got = block.v_values[s * v_probes.len() + p];
                        assert_eq!(got.to_bits(), v[node].to_bits(), "v{node}, {context}");
                    }
                }
                let bits = |x: &[f64]| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&tiled.u), bits(&single.u), "u after step {step}");
                assert_eq!(bits(&tiled.v), bits(&single.v), "v after step {step}");
            }
        }
    }

    #[test]
    fn a_bar_shorter_than_one_tile_is_one_tile_on_one_thread() {
        let n = 100;
        let mut single = graded_kernel(n);
        let mut tiled = graded_kernel(n);
        tiled.set_threads(4);
        let mut block = StepBlock::new(&[0], &[], &[]);
        block.forces[..DEPTH].fill(1.0);
        tiled.advance_block::<true>(&mut block, DEPTH);
        for s in 0..DEPTH {
            assert_eq!(single.step_with_energy(&[(0, 1.0)]), block.energies[s]);
        }
        assert_eq!(tiled.u, single.u);
        assert_eq!(tiled.v, single.v);
        assert_eq!(block.workers.len(), 1, "one tile runs on one thread");
    }
}
