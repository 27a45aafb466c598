//! The matrix-mass step of a long bar in two chunks of nodes, on one thread or two: the same
//! values of `u`, `v` and the residual whatever the thread count, and the same energies.
//!
//! ```text
//!   nodes   0 ............ s-1 | s ............. n-1        s: the seam (fixed by the bar)
//!   phase 1 chunk 0: its rows but s-1      chunk 1: its rows but s    (in parallel)
//!   phase 2 the seam rows s-1 and s, the windows (or M^-1 rows) that read across the seam
//! ```
//!
//! Phase 1 runs each chunk's blocked passes ([`crate::kernels::matrix_mass::kernel`]) on its own
//! nodes only: `u` of all its nodes, the residual of its rows but the one next to the seam (row
//! `s - 1` needs `u_s`, row `s` needs `u_{s-1}`), and for CMM/AMM with windows every group of
//! windows that reads none of the seam rows (solved, and its tiles' `v` updated, just behind
//! the residual as in one chunk), for RMM the velocity rows whose `M^-1` row reads none. Phase
//! 2, on the calling thread after both, forms the two seam rows and the rest (for CMM/AMM the
//! last group of chunk 0 and the first of chunk 1, whose windows overlap the seam; for RMM rows
//! `s - 2 .. s + 2`). Every value is formed by the same operations as in one chunk, so `u`, `v`
//! and the residual are bit-identical to the one-chunk step. The energy sums run in three sets
//! of lanes (chunk 0, chunk 1, phase 2), lane `l` added as `(chunk 0 + chunk 1) + phase 2`: a
//! fixed order whatever the thread count (the chunks are fixed by the bar, not by the threads),
//! so a run's energies are the same bits on one thread and on two; they differ from the
//! one-chunk sums by round-off. The seam is a multiple of [`BLOCK`] (RMM) or a group edge
//! (windows, a multiple of the tile), so each chunk's lanes are the global ones (`i % LANES`).
//!
//! On two threads chunk 1 runs on the kernel's worker ([`Pair`]: one thread started at the
//! first such step and kept for the kernel's life, handed each step's chunk and waited for
//! before phase 2, two handshakes on atomics per step instead of a thread start), chunk 0 on the
//! calling thread; on one, both on the calling thread, chunk 0 first. A panic in a chunk is
//! resumed on the calling thread once both chunks are done.

use crate::kernels::matrix_mass::pair::Pair;
use crate::kernels::matrix_mass::passes::{
    BLOCK, EnergyLanes, ResidualFront, reciprocal_velocity, residual_rows, velocity_lanes,
};
use crate::mass::MassOperator;
use crate::mass::windows::{GroupBuffers, HaloTiles};
use crate::simd::LANES;

/// Where the bar is cut into two chunks: chunk 1 starts at node `node`; with windows, group
/// `split` is chunk 1's first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Seam {
    pub(crate) node: usize,
    split: usize,
}

/// A seam with what the second chunk needs of its own: its group buffers (windows) and its
/// loads numbered from the seam (capacity kept from step to step).
pub(crate) type Chunks = (Seam, GroupBuffers, Vec<(usize, f64)>);

/// The seam of a bar of `n` nodes with `mass`, from `from_nodes` nodes on (below, one chunk):
/// CMM/AMM with windows and at least four groups, at the first row of group `groups / 2`; RMM
/// at `n / 2` rounded down to a multiple of [`BLOCK`]; none for the other solves.
pub(crate) fn seam_of(mass: &MassOperator, n: usize, from_nodes: usize) -> Option<Seam> {
    if n < from_nodes.max(8 * BLOCK) {
        return None;
    }
    if let Some(tiles) = mass.windows() {
        let split = tiles.groups() / 2;
        if tiles.groups() < 4 {
            return None;
        }
        let (_, rows) = tiles.group_tiles(split).next()?;
        return Some(Seam {
            node: rows.start,
            split,
        });
    }
    matches!(mass, MassOperator::Reciprocal { .. }).then(|| Seam {
        node: n / 2 / BLOCK * BLOCK,
        split: 0,
    })
}

/// Loads `(node, F)`, sorted by node.
type Loads<'f> = &'f [(usize, f64)];

/// RMM's `M^-1` for a step: `dt`, its diagonal and coupling, its constant blocks.
pub(crate) type InverseMass<'a> = (f64, &'a [f64], &'a [f64], &'a [Option<[f64; 2]>]);

/// The step's arrays: `u`, `v`, the residual (`r^n` in, `r^{n+1}` out) and the padded
/// stiffnesses (`k[i + 1]` of element `i`).
pub(crate) type Arrays<'a> = [&'a mut [f64]; 4];

/// The loads of each part: `(chunk 0's rows, the seam rows, chunk 1's rows numbered from the
/// seam)`; `local` holds chunk 1's (its capacity is kept from step to step).
fn split_loads<'f>(
    forces: &'f [(usize, f64)],
    seam: usize,
    local: &'f mut Vec<(usize, f64)>,
) -> (Loads<'f>, Loads<'f>, Loads<'f>) {
    let below = forces.partition_point(|f| f.0 < seam - 1);
    let at = forces.partition_point(|f| f.0 <= seam);
    local.clear();
    local.extend(forces[at..].iter().map(|&(i, f)| (i - seam, f)));
    (&forces[..below], &forces[below..at], &local[..])
}

/// Lane `l` of `into` becomes `(a_l + b_l) + c_l`, for each of the three sums.
fn combine(into: &mut EnergyLanes, [a, b, c]: [&EnergyLanes; 3]) {
    for l in 0..LANES {
        into.strain[l] = (a.strain[l] + b.strain[l]) + c.strain[l];
        into.increment[l] = (a.increment[l] + b.increment[l]) + c.increment[l];
        into.impulse[l] = (a.impulse[l] + b.impulse[l]) + c.impulse[l];
    }
}

/// The CMM/AMM step with windows in two chunks (module docs).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(crate) fn windowed<const AVX2: bool>(
    (seam, pair, two): (Seam, &mut Pair, bool),
    (dt, tiles): (f64, &HaloTiles),
    [u, v, r, k]: Arrays<'_>,
    forces: &[(usize, f64)],
    local: &mut Vec<(usize, f64)>,
    [buffers0, buffers1]: [&mut GroupBuffers; 2],
    lanes: &mut EnergyLanes,
) {
    let (s, n) = (seam.node, u.len());
    let (loads0, seam_loads, loads1) = split_loads(forces, s, local);
    let [mut lanes0, mut lanes1, mut lanes2] = [(); 3].map(|_| EnergyLanes::default());
    let (l0, l1) = (&mut lanes0, &mut lanes1);
    let groups = tiles.groups();
    let first_phase = |g: usize| {
        if g < seam.split {
            tiles.rows_read(g) < s
        } else {
            tiles.first_row_read(g) > s
        }
    };
    {
        let (u0, u1) = u.split_at_mut(s);
        let (v0, v1) = v.split_at_mut(s);
        let (r0, r1) = r.split_at_mut(s);
        let (k0, k1) = (&k[..=s], &k[s..]);
        let buffers0 = &mut *buffers0;
        // Each chunk sums into lanes of its own stack, stored once at its end (no cache line
        // shared between the threads while they run).
        let chunk0 = move || {
            let (mut front, mut mine) = (ResidualFront::default(), EnergyLanes::default());
            let l = &mut mine;
            for g in (0..seam.split).filter(|&g| first_phase(g)) {
                front.advance::<AVX2>(tiles.rows_read(g), (dt, k0), (u0, v0), r0, loads0, l);
                tiles.solve_group(g, r0, buffers0);
                for (c, rows) in tiles.group_tiles(g) {
                    let solution = tiles.tile_solution(g, c, &rows, buffers0);
                    let (v, r) = (&mut v0[rows.clone()], &r0[rows]);
                    velocity_lanes::<AVX2>(v, solution, r, dt, &mut l.impulse);
                }
            }
            front.advance::<AVX2>(s - 1, (dt, k0), (u0, v0), r0, loads0, l);
            *l0 = mine;
        };
        let chunk1 = move || {
            let (mut front, mut mine) = (ResidualFront::from_row(1), EnergyLanes::default());
            let l = &mut mine;
            for g in (seam.split..groups).filter(|&g| first_phase(g)) {
                let to = tiles.rows_read(g) - s;
                front.advance::<AVX2>(to, (dt, k1), (u1, v1), r1, loads1, l);
                tiles.solve_group_at(g, r1, s, buffers1);
                for (c, rows) in tiles.group_tiles(g) {
                    let solution = tiles.tile_solution(g, c, &rows, buffers1);
                    let local = rows.start - s..rows.end - s;
                    let (v, r) = (&mut v1[local.clone()], &r1[local]);
                    velocity_lanes::<AVX2>(v, solution, r, dt, &mut l.impulse);
                }
            }
            front.advance::<AVX2>(n - s, (dt, k1), (u1, v1), r1, loads1, l);
            *l1 = mine;
        };
        pair.run(two, chunk0, chunk1);
    }
    residual_rows::<AVX2>((&*k, &*u, &*v), r, (s - 1, s + 1), seam_loads, &mut lanes2);
    for g in (0..groups).filter(|&g| !first_phase(g)) {
        tiles.solve_group(g, r, buffers0);
        for (c, rows) in tiles.group_tiles(g) {
            let solution = tiles.tile_solution(g, c, &rows, buffers0);
            let (v, r) = (&mut v[rows.clone()], &r[rows]);
            velocity_lanes::<AVX2>(v, solution, r, dt, &mut lanes2.impulse);
        }
    }
    combine(lanes, [&lanes0, &lanes1, &lanes2]);
}

/// The RMM step in two chunks (module docs): `M^-1 = (diag, off)`, `constant` its constant
/// blocks.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(crate) fn reciprocal<const AVX2: bool>(
    (seam, pair, two): (Seam, &mut Pair, bool),
    (dt, diag, off, constant): InverseMass<'_>,
    [u, v, r, k]: Arrays<'_>,
    forces: &[(usize, f64)],
    local: &mut Vec<(usize, f64)>,
    lanes: &mut EnergyLanes,
) {
    let (s, n) = (seam.node, u.len());
    let (loads0, seam_loads, loads1) = split_loads(forces, s, local);
    let [mut lanes0, mut lanes1, mut lanes2] = [(); 3].map(|_| EnergyLanes::default());
    let (l0, l1) = (&mut lanes0, &mut lanes1);
    {
        let (u0, u1) = u.split_at_mut(s);
        let (v0, v1) = v.split_at_mut(s);
        let (r0, r1) = r.split_at_mut(s);
        let (k0, k1) = (&k[..=s], &k[s..]);
        let (diag0, diag1) = diag.split_at(s);
        let (off0, off1) = (&off[..s], &off[s..]);
        // Velocity rows up to s - 2 (row s - 2 reads the seam row s - 1), the residual one
        // row ahead.
        let chunk0 = move || {
            let (mut front, mut v_done) = (ResidualFront::default(), 0);
            let mut mine = EnergyLanes::default();
            let l = &mut mine;
            while v_done < s - 2 {
                let v_to = (v_done + BLOCK).min(s - 2);
                front.advance::<AVX2>(v_to + 1, (dt, k0), (u0, v0), r0, loads0, l);
                let coefficients = (diag0, off0, constant[v_done / BLOCK]);
                let rows = (dt, (v_done, v_to));
                reciprocal_velocity::<AVX2>(coefficients, r0, v0, rows, &mut l.impulse);
                v_done = v_to;
            }
            *l0 = mine;
        };
        // From row s + 2 (row s + 1 reads the seam row s), in the global blocks.
        let chunk1 = move || {
            let (mut front, mut v_done) = (ResidualFront::from_row(1), 2);
            let mut mine = EnergyLanes::default();
            let l = &mut mine;
            while v_done < n - s {
                let v_to = ((v_done / BLOCK + 1) * BLOCK).min(n - s);
                front.advance::<AVX2>(v_to + 1, (dt, k1), (u1, v1), r1, loads1, l);
                let coefficients = (diag1, off1, constant[(s + v_done) / BLOCK]);
                let rows = (dt, (v_done, v_to));
                reciprocal_velocity::<AVX2>(coefficients, r1, v1, rows, &mut l.impulse);
                v_done = v_to;
            }
            *l1 = mine;
        };
        pair.run(two, chunk0, chunk1);
    }
    residual_rows::<AVX2>((&*k, &*u, &*v), r, (s - 1, s + 1), seam_loads, &mut lanes2);
    for (from, to) in [(s - 2, s), (s, s + 2)] {
        let coefficients = (diag, off, constant[from / BLOCK]);
        reciprocal_velocity::<AVX2>(coefficients, r, v, (dt, (from, to)), &mut lanes2.impulse);
    }
    combine(lanes, [&lanes0, &lanes1, &lanes2]);
}
