//! The central-difference step with a non-diagonal mass (CMM, AMM: a pre-factored tridiagonal
//! solve, in overlapping windows for long bars ([`crate::mass::windows`]) and with the global
//! partitioned factor otherwise ([`crate::mass::partitioned_ldl`]); RMM: a tridiagonal product with
//! the assembled `M^-1`, no solve), O(N) per step, no dense matrix, no allocation; the passes
//! run in cache blocks ([`MatrixMassStep::step_with_energy`]).
//!
//! ```text
//!   u^{n+1}   = u^n + dt v^{n+1/2}
//!   r^{n+1}   = F^{n+1} - K u^{n+1}              (element forces, branch-free)
//!   a^{n+1}   = M^-1 r^{n+1}                      (solve, or product with M^-1)
//!   v^{n+3/2} = v^{n+1/2} + dt a^{n+1}
//! ```
//!
//! Energies per step without applying `M` (since `M a = r` on the free nodes):
//!
//! ```text
//!   T*^{n+1} = T*^n + 1/2 dt v^{n+1/2} . (r^n + r^{n+1})     (T* = 1/2 v^{n+1/2} M v^{n+3/2})
//!   T^{n+1}  = T*^{n+1} + dt^2/8 a^{n+1} . r^{n+1}           (full-step kinetic energy)
//! ```
//!
//! and, at sampled steps, `T*` from `M` itself ([`MatrixMassStep::staggered_kinetic_from_mass`]),
//! which checks the mass operator against the update.
//!
//! What a step streams (8-byte words per node): every mass reads and writes `u`, `v` and the
//! residual (overwritten in place, `r^n` read just before: the increment needs both) and reads
//! `k`. RMM adds the two diagonals of `M^-1` (9 words against the lumped step's 7: `u`, `v`
//! read and written, `k`, `dt/m`, `m`); `a` is formed in the velocity sweep and never stored (a
//! history forms `(M^-1 r^n)_i` at its node). CMM and AMM with windows add the windows' factors
//! (2 words and the halo's share, 7 % for CMM) and keep the group's residual and solve in cache
//! (about 9.3 words; `a` not stored either); with the global factor they also copy the residual
//! out, run the factor's two sweeps over it and a separate velocity pass (about 18 words).
//! Measured ratios to the lumped step: benches/RESULTS.md, "2026-11-28, AMD: matrix-mass steps
//! against the lumped step".

use crate::kernels::energy::StepEnergy;
use crate::kernels::lumped::kernel::PARALLEL_FROM_NODES;
use crate::kernels::matrix_mass::chunks::{self, Chunks, seam_of};
use crate::kernels::matrix_mass::pair::Pair;
#[cfg(test)]
use crate::kernels::matrix_mass::passes::lane_sums;
use crate::kernels::matrix_mass::passes::{
    BLOCK, EnergyLanes, ResidualFront, constant_blocks, inverse_row, reciprocal_velocity,
    velocity_lanes,
};
use crate::kernels::matrix_mass::placed_arrays::PlacedArrays;
use crate::mass::MassOperator;
use crate::mass::windows::GroupBuffers;
use crate::simd::{LANES, has_avx2};

/// The state a run starts from, after the start procedure.
#[derive(Debug, Clone, Copy)]
pub struct StartState<'a> {
    /// `u^0`.
    pub displacement: &'a [f64],
    /// `v^{1/2}`.
    pub half_step_velocity: &'a [f64],
    /// `a^0 = M^-1 r^0`.
    pub acceleration: &'a [f64],
    /// `r^0 = F^0 - K u^0`.
    pub residual: &'a [f64],
    /// `1/2 v^{-1/2} M v^{1/2}`.
    pub kinetic_staggered: f64,
}

/// Where `u`, `v` and `r^n` are in [`MatrixMassStep`]'s state (the padded
/// stiffnesses are the fourth array).
const U: usize = 0;
const V: usize = 1;
const R: usize = 2;

/// The page offsets (bytes modulo 4096) of `u`, `v`, `r^n` and the stiffnesses ([`PlacedArrays`]),
/// chosen by measurement (ns per node-step, RMM / CMM steps; benches/RESULTS.md, heading "... the
/// run's start, the mass check, where the state lives ..."): with all four at one offset (what
/// fresh mappings give) 0.733 / 0.945 at N = 1e5 and 1.22 / 1.24 at 1e6; a quarter page apart
/// 0.57-0.66 / 0.84-0.88 at 1e5 but 0.87-1.11 for RMM at 1e6; these 0.61-0.63 / 0.84-0.87 at 1e5
/// and 0.68-0.81 / 1.07-1.22 at 1e6 (of 16 placements tried, the fastest at both sizes; RMM runs of
/// 300 steps at 1e6 took 271-287 ms against 322-323 a quarter page apart).
const PLACEMENT: [usize; 4] = [2624, 1216, 3200, 384];

/// Central difference with a tridiagonal mass or inverse mass.
#[derive(Debug, Clone)]
pub struct MatrixMassStep {
    dt: f64,
    /// The arrays every step streams, placed apart in their pages ([`PlacedArrays`]): `u`, `v`,
    /// `r^n` (the residual of the last step) and the element stiffnesses padded with a zero at
    /// both ends (length N + 2 for N elements), at [`U`], [`V`], [`R`] and 3.
    state: PlacedArrays<4>,
    mass: MassOperator,
    a: Vec<f64>,
    /// Scratch of the whole-pass reference step (the blocked step overwrites `r^n` in place).
    #[cfg(test)]
    r: Vec<f64>,
    /// CMM/AMM with windows: one group's work arrays (empty otherwise).
    group: GroupBuffers,
    /// RMM: per block of [`BLOCK`] rows, `M^-1`'s coefficients where they are constant over
    /// the block ([`constant_blocks`]; empty otherwise).
    constant: Vec<Option<[f64; 2]>>,
    scratch: Vec<f64>,
    staggered: f64,
    /// Whether the CPU has AVX2 (the blocked step then runs its AVX2-compiled copy).
    avx2: bool,
    /// Where a long bar is cut into two chunks of nodes ([`chunks`]; fixed by the bar and the
    /// mass, not by the thread count), with the second chunk's group buffers and its loads.
    seam: Option<Chunks>,
    /// Threads the chunks run on (1 or 2: the same bits).
    threads: usize,
    /// The calling thread and the worker that runs chunk 1 on two threads, started at the
    /// first such step and kept for the kernel's life ([`Pair`]).
    pair: Pair,
    /// Nodes from which the chunks take a second thread when `threads` allows
    /// ([`TWO_THREADS_FROM_NODES`]; below, both on the calling thread: the same bits).
    threads_from: usize,
}

/// Nodes from which a matrix-mass step in two chunks runs them on two threads (when its run
/// has two): every bar with a seam (from [`PARALLEL_FROM_NODES`], 1e5). The second chunk runs on
/// a worker kept for the kernel's life (two handshakes per step, no thread start), so a step of
/// 0.1 ms is long enough: on idle cores, one thread / two = 1.55-1.86 at 1e5 nodes, 1.40-1.76 at
/// 3e5, 1.62-1.78 at 1e6, against 0.57-0.77, 0.95-1.22 and 1.51-1.56 when each step spawned its
/// thread (benches/RESULTS.md, heading "2026-11-28 17:52 UTC, AMD, idle cores: the matrix
/// masses' second chunk on a worker kept for the kernel's life"). On a machine whose other core
/// is busy two threads are slower than one (0.83-0.85 at 1e6), as for lumped CD's pipeline.
pub const TWO_THREADS_FROM_NODES: usize = PARALLEL_FROM_NODES;

impl MatrixMassStep {
    /// Set up with element stiffnesses, the mass operator, `u^0`, `v^{1/2}`, `a^0`, the residual
    /// `r^0 = F^0 - K u^0` and the staggered kinetic energy `1/2 v^{-1/2} M v^{1/2}`. With the
    /// reciprocal mass or a windowed solve `a^0` is not kept: [`Self::acceleration_at`] forms
    /// `(M^-1 r^0)_i`, which is the time loop's `a^0` (`MassOperator::apply_inverse` of `r^0`,
    /// the same operations).
    pub fn new(dt: f64, stiffness: &[f64], mass: MassOperator, start: &StartState) -> Self {
        let StartState {
            displacement: u0,
            half_step_velocity: v_half,
            acceleration: a0,
            residual: r0,
            kinetic_staggered: staggered0,
        } = *start;
        let n = u0.len();
        let reciprocal = matches!(mass, MassOperator::Reciprocal { .. });
        let windows = mass.windows().is_some();
        // u, v, r^n, and the stiffnesses padded with a zero at both ends (written in place).
        let mut state = PlacedArrays::zeroed([n, n, n, n + 1], PLACEMENT);
        let [u, v, r, k] = state.split_mut();
        u.copy_from_slice(u0);
        v.copy_from_slice(v_half);
        r.copy_from_slice(r0);
        k[1..n].copy_from_slice(stiffness);
        let group = (mass.windows().or(mass.reciprocal_windows()))
            .map_or_else(GroupBuffers::default, |t| t.buffers());
        let constant = match &mass {
            MassOperator::Reciprocal { inverse, .. } => {
                constant_blocks(&inverse.diag, &inverse.off)
            }
            _ => Vec::new(),
        };
        Self {
            dt,
            state,
            mass,
            a: if reciprocal || windows {
                Vec::new()
            } else {
                a0.to_vec()
            },
            #[cfg(test)]
            r: Vec::new(),
            group,
            constant,
            scratch: vec![0.0; n],
            staggered: staggered0,
            avx2: has_avx2(),
            seam: None,
            threads: 1,
            pair: Pair::default(),
            threads_from: TWO_THREADS_FROM_NODES,
        }
        .with_chunks_from(PARALLEL_FROM_NODES)
    }

    /// Cut the bar into two chunks ([`chunks`]) if it has `from_nodes` nodes or more and its mass
    /// has a seam (CMM/AMM with windows, RMM); one chunk otherwise.
    pub(crate) fn with_chunks_from(mut self, from_nodes: usize) -> Self {
        let n = self.state.get(U).len();
        self.seam = seam_of(&self.mass, n, from_nodes).map(|seam| {
            let buffers = self
                .mass
                .windows()
                .map_or_else(GroupBuffers::default, |t| t.buffers());
            (seam, buffers, Vec::with_capacity(16))
        });
        self
    }

    /// Run the chunks of a long bar on `threads` threads (at most 2 are used; the same bits
    /// whatever the count).
    pub fn set_threads(&mut self, threads: usize) {
        self.threads = threads.max(1);
    }

    /// Time step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// `u^n`.
    pub fn displacement(&self) -> &[f64] {
        self.state.get(U)
    }

    /// `v^{n+1/2}`.
    pub fn half_step_velocity(&self) -> &[f64] {
        self.state.get(V)
    }

    /// `a^n` at node `i`: the kept solve for CMM and AMM; with windows, whose step does not
    /// store `a` (one stream less), the solve of node `i`'s window
    /// ([`crate::mass::windows::HaloTiles::solution_at`]); for RMM row `i` of `M^-1 r^n` from the
    /// kept residual. Each formed as the step formed it (same operations, same order), so
    /// bit-identical to the step's `a`.
    pub fn acceleration_at(&self, i: usize) -> f64 {
        match &self.mass {
            MassOperator::Reciprocal { inverse, .. } => {
                inverse_row(&inverse.diag, &inverse.off, self.state.get(R), i)
            }
            mass => match mass.windows() {
                Some(tiles) => tiles.solution_at(i, self.state.get(R)),
                None => self.a[i],
            },
        }
    }

    /// Advance one step; `forces` lists `(node, F^{n+1})`, sorted, each node once.
    ///
    /// Every pass is a straight sweep; the energy sums run in `LANES` (8) independent partial
    /// sums (node or element `i` adds to lane `i % LANES`, a fixed order, so the result is
    /// deterministic) so that no pass waits on the latency of one long chain of additions.
    pub fn step_with_energy(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: `avx2` is set only when the running CPU reports AVX2 support.
            return unsafe { self.blocked_step_avx2(forces) };
        }
        self.blocked_step::<false>(forces)
    }

    /// The step as whole passes over the arrays (any mass operator): the reference the blocked
    /// step is tested against.
    #[cfg(test)]
    fn whole_pass_step(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        let dt = self.dt;
        let [u, v, r_previous, k] = self.state.split_mut();
        let n = u.len();
        self.r.resize(n, 0.0);
        self.a.resize(n, 0.0);
        // Element forces padded with a zero at both ends (length N + 2).
        let mut element_force = vec![0.0; n + 1];
        for (u, v) in u.iter_mut().zip(v.iter()) {
            *u += dt * v;
        }
        // Element forces N_e = k_e (u_{e+1} - u_e) at padded index e + 1 (ghosts stay 0).
        let [strain] = lane_sums(
            &mut element_force[1..n],
            (&k[1..n], &u[..]),
            |e, force, (k, u)| {
                let du = u[e + 1] - u[e];
                *force = k[e] * du;
                [*force * du]
            },
        );
        // r_i = N_i - N_{i-1} + F_i.
        for (r, pair) in self.r.iter_mut().zip(element_force.windows(2)) {
            *r = pair[1] - pair[0];
        }
        for &(node, f) in forces {
            self.r[node] += f;
        }
        self.mass.apply_inverse(&self.r, &mut self.a);
        let [increment, impulse] = lane_sums(
            v,
            (&self.a[..], (&r_previous[..], &self.r[..])),
            |i, v, (a, (r_previous, r))| {
                let terms = [*v * (r_previous[i] + r[i]), a[i] * r[i]];
                *v += dt * a[i];
                terms
            },
        );
        self.staggered += 0.5 * dt * increment;
        r_previous.copy_from_slice(&self.r);
        StepEnergy {
            kinetic_staggered: self.staggered,
            kinetic: self.staggered + 0.125 * dt * dt * impulse,
            strain: 0.5 * strain,
        }
    }

    /// [`Self::step_with_energy`] in blocks of [`BLOCK`] nodes: each pass advanced just as far
    /// as the next one reads (`u` one node ahead of the residual, whose element forces are
    /// formed in registers, not stored; for the reciprocal mass, whose `M^-1` is a tridiagonal
    /// product (a stencil), the residual one node ahead of `a = M^-1 r` and the velocity update
    /// in the same block, the residual overwriting `r^n` in place), so a block's data are still
    /// in L1 when the next pass reads them; CMM and AMM with windows solve each group of windows
    /// just behind the residual and update `v` tile by tile, with the global factor they solve
    /// the whole residual after the blocks. Every value is computed by the same operations as
    /// in whole passes, and each pass's blocks start at multiples of [`LANES`], so every energy
    /// term goes to the same lane in the same order: bit-identical to the whole-pass step
    /// (tested).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn blocked_step_avx2(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        self.blocked_step::<true>(forces)
    }

    #[inline(always)]
    fn blocked_step<const AVX2: bool>(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        let mut lanes = EnergyLanes::default();
        if self.seam.is_some() {
            self.chunked_step::<AVX2>(forces, &mut lanes);
        } else if matches!(self.mass, MassOperator::Reciprocal { .. }) {
            self.reciprocal_blocks::<AVX2>(forces, &mut lanes);
        } else {
            self.solved_step::<AVX2>(forces, &mut lanes);
        }
        let total = |lanes: [f64; LANES]| lanes.iter().sum::<f64>();
        let dt = self.dt;
        self.staggered += 0.5 * dt * total(lanes.increment);
        StepEnergy {
            kinetic_staggered: self.staggered,
            kinetic: self.staggered + 0.125 * dt * dt * total(lanes.impulse),
            strain: 0.5 * total(lanes.strain),
        }
    }

    /// The step of a bar in two chunks ([`chunks`]).
    #[inline(always)]
    fn chunked_step<const AVX2: bool>(&mut self, forces: &[(usize, f64)], lanes: &mut EnergyLanes) {
        let Self {
            dt,
            state,
            mass,
            group,
            constant,
            seam: Some((seam, group1, local)),
            threads,
            pair,
            threads_from,
            ..
        } = self
        else {
            return;
        };
        let n = state.get(U).len();
        let at = (*seam, pair, n >= *threads_from && *threads > 1);
        match mass {
            MassOperator::Reciprocal { inverse, .. } => {
                let matrix = (*dt, &inverse.diag[..], &inverse.off[..], &constant[..]);
                chunks::reciprocal::<AVX2>(at, matrix, state.split_mut(), forces, local, lanes);
            }
            mass => {
                let Some(tiles) = mass.windows() else {
                    return;
                };
                let buffers = [group, group1];
                let arrays = state.split_mut();
                chunks::windowed::<AVX2>(at, (*dt, tiles), arrays, forces, local, buffers, lanes);
            }
        }
    }

    /// The reciprocal-mass step in blocks: per block, `u` one node ahead of the residual, the
    /// residual (overwriting `r^n` in place, with the strain and increment lanes) one node ahead
    /// of `a = M^-1 r` (a stencil), and the velocity with the impulse lanes.
    #[inline(always)]
    fn reciprocal_blocks<const AVX2: bool>(
        &mut self,
        forces: &[(usize, f64)],
        lanes: &mut EnergyLanes,
    ) {
        let Self {
            dt,
            state,
            mass: MassOperator::Reciprocal { inverse, .. },
            constant,
            ..
        } = self
        else {
            return;
        };
        let [u, v, r, k] = state.split_mut();
        let k = &*k;
        let (dt, n, diag, off) = (*dt, u.len(), &inverse.diag[..], &inverse.off[..]);
        // `a = M^-1 r` is formed in the velocity sweep, not stored (`Self::acceleration_at`
        // forms it from `r`); the residual runs one row ahead (the product reads it).
        let mut front = ResidualFront::default();
        let mut v_done = 0;
        while v_done < n {
            let v_to = (v_done + BLOCK).min(n);
            front.advance::<AVX2>(v_to + 1, (dt, k), (u, v), r, forces, lanes);
            let rows = (dt, (v_done, v_to));
            let coefficients = (diag, off, constant[v_done / BLOCK]);
            reciprocal_velocity::<AVX2>(coefficients, r, v, rows, &mut lanes.impulse);
            v_done = v_to;
        }
    }

    /// The CMM and AMM step: `u` and the residual in blocks (the residual overwriting `r^n` in
    /// place, the strain and increment lanes summed while the rows are in L1), then
    /// `a = M^-1 r` and `v` with the impulse `a r`. With windows
    /// ([`crate::mass::windows::HaloTiles`]) the residual runs just ahead of each group of
    /// windows, which is solved while its rows are in cache, and `v` follows tile by tile
    /// (`a` is not stored); otherwise the right-hand side is copied out, the global factor
    /// solves it, and `v` is one more pass.
    #[inline(always)]
    fn solved_step<const AVX2: bool>(&mut self, forces: &[(usize, f64)], lanes: &mut EnergyLanes) {
        let Self {
            dt,
            state,
            mass,
            a,
            group,
            ..
        } = self;
        let [u, v, r, k] = state.split_mut();
        let (dt, k) = (*dt, &*k);
        let mut front = ResidualFront::default();
        if let Some(tiles) = mass.windows() {
            for g in 0..tiles.groups() {
                let to = tiles.rows_read(g);
                front.advance::<AVX2>(to, (dt, k), (u, v), r, forces, lanes);
                tiles.solve_group(g, r, group);
                for (c, rows) in tiles.group_tiles(g) {
                    let solution = tiles.tile_solution(g, c, &rows, group);
                    let (v, r) = (&mut v[rows.clone()], &r[rows]);
                    velocity_lanes::<AVX2>(v, solution, r, dt, &mut lanes.impulse);
                }
            }
            return;
        }
        front.advance::<AVX2>(u.len(), (dt, k), (u, v), r, forces, lanes);
        // a = M^-1 r as `MassOperator::apply_inverse` forms it: 0 at the fixed nodes.
        a.copy_from_slice(r);
        mass.apply_inverse_in_place(a);
        velocity_lanes::<AVX2>(v, a, r, dt, &mut lanes.impulse);
    }

    /// `1/2 v^{n-1/2} . M v^{n+1/2}` computed with the mass operator itself (one product or
    /// solve): compared with the running `T*` it checks `M^-1` against `M`.
    pub fn staggered_kinetic_from_mass(&mut self) -> f64 {
        let dt = self.dt;
        let (v, r) = (self.state.get(V), self.state.get(R));
        // Sum of (v_i - dt a_i) (M v)_i in increasing i, `a = M^-1 r^n` formed as the step
        // formed it: row by row of `M^-1` (RMM), window by window, or the kept `a`.
        let mut sum = 0.0;
        if let MassOperator::Reciprocal {
            inverse, lumped, ..
        } = &self.mass
        {
            // `M v = A C^-1 A v`: `C^-1 A v` tile by tile with windows (consumed as it comes,
            // no second array), else from the global factor.
            let (diag, off) = (&inverse.diag[..], &inverse.off[..]);
            let mut add = |rows: std::ops::Range<usize>, x: &[f64]| {
                // The running sum in a register (captured, it was stored and reloaded every row),
                // added to in increasing rows.
                let mut running = sum;
                for (i, xi) in rows.zip(x) {
                    running += (v[i] - dt * inverse_row(diag, off, r, i)) * (xi * lumped[i]);
                }
                sum = running;
            };
            let scaled = &mut self.scratch;
            self.mass.lumped_scaled(v, scaled);
            match self.mass.reciprocal_windows() {
                Some(tiles) => tiles.for_each_tile(scaled, &mut self.group, add),
                None => {
                    self.mass.solve_reciprocal_in_place(scaled);
                    add(0..v.len(), scaled);
                }
            }
            return 0.5 * sum;
        }
        self.mass.apply(v, &mut self.scratch);
        let my = &self.scratch;
        let mut add = |rows: std::ops::Range<usize>, a: &[f64]| {
            let mut running = sum;
            for (i, ai) in rows.zip(a) {
                running += (v[i] - dt * ai) * my[i];
            }
            sum = running;
        };
        match self.mass.windows() {
            Some(tiles) => tiles.for_each_tile(r, &mut self.group, add),
            None => add(0..v.len(), &self.a),
        }
        0.5 * sum
    }
}

#[cfg(test)]
mod tests;
