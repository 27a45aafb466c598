//! The passes of the blocked matrix-mass step ([`crate::kernels::matrix_mass::kernel`]), each over
//! a range of nodes so that the step can run them block by block: the displacement update, the
//! residual rows `r = F - K u` with the strain and increment lanes, the rows of the reciprocal
//! mass's product `a = M^-1 r`, and the velocity update with the impulse lanes. Each forms its
//! values with the same operations in the same order as the whole-pass step (tested there), so
//! blocking changes no bit.

use crate::simd::LANES;

/// Nodes per block of the blocked step (a multiple of [`LANES`]).
pub(crate) const BLOCK: usize = 512;

/// The whole chunks of [`LANES`] rows from a multiple of [`LANES`] within `lo..hi` (empty, at
/// `hi`, when there is none): the rows an AVX2 sweep takes, the rest run one by one.
#[inline(always)]
fn lane_chunks(lo: usize, hi: usize) -> std::ops::Range<usize> {
    let chunks = lo.next_multiple_of(LANES)..hi / LANES * LANES;
    if chunks.start < chunks.end {
        chunks
    } else {
        hi.max(lo)..hi.max(lo)
    }
}

/// `v^{n+3/2} = v^{n+1/2} + dt a^{n+1}` for the nodes of `v` (starting at a multiple of [`LANES`]),
/// adding `a r` to the impulse lanes; `a` and `r` hold the same nodes as `v` (and may be longer).
/// `AVX2`: the whole chunks of [`LANES`] nodes run
/// [`crate::kernels::matrix_mass::avx2::velocity_lanes`] (only an AVX2-compiled caller may ask for
/// it).
#[inline(always)]
pub(crate) fn velocity_lanes<const AVX2: bool>(
    v: &mut [f64],
    a: &[f64],
    r: &[f64],
    dt: f64,
    impulse: &mut [f64; LANES],
) {
    let len = v.len();
    let (a, r) = (&a[..len], &r[..len]);
    #[cfg(target_arch = "x86_64")]
    let done = if AVX2 {
        // SAFETY: `AVX2` is true only in the step compiled for AVX2, run when the CPU has it.
        unsafe { crate::kernels::matrix_mass::avx2::velocity_lanes(v, a, r, dt, impulse) }
    } else {
        0
    };
    #[cfg(not(target_arch = "x86_64"))]
    let done = 0;
    let mut product = *impulse;
    for i in done..len {
        product[i % LANES] += a[i] * r[i];
        v[i] += dt * a[i];
    }
    *impulse = product;
}

/// `r_i = N_i - N_{i-1} + F_i` for rows `from..to`, overwriting `r^n` in place, with the element
/// forces `N` of padded index `i + 1` formed as `k[i + 1] (u[i + 1] - u[i])` (`k` the padded
/// stiffness, length `n + 1`), the ghost forces 0 and the load `F_i` of `loads` (the rows' loads,
/// sorted) added last: the whole-pass step's `element_force[i + 1] - element_force[i]`, then
/// `+= F_i`, operation for operation. Each row also adds its right element's `N_e du_e` (element
/// `e = i`, all rows but the last) to strain lane `e % LANES` and `v_i (r^n_i + r^{n+1}_i)` to
/// increment lane `i % LANES`, in increasing rows. `AVX2`: the whole chunks of [`LANES`] unloaded
/// interior rows run [`crate::kernels::matrix_mass::avx2::residual_rows`].
#[inline(always)]
pub(crate) fn residual_rows<const AVX2: bool>(
    (k, u, v): (&[f64], &[f64], &[f64]),
    r: &mut [f64],
    (from, to): (usize, usize),
    loads: &[(usize, f64)],
    lanes: &mut EnergyLanes,
) {
    let n = u.len();
    if from >= to {
        return;
    }
    let (mut strain, mut increment) = (lanes.strain, lanes.increment);
    let force = |i: usize| k[i + 1] * (u[i + 1] - u[i]);
    // Row `i` with its value `N_i - N_{i-1}` and load: the new residual and its increment.
    let set =
        |i: usize, value: f64, load: Option<f64>, r: &mut [f64], increment: &mut [f64; LANES]| {
            let new = load.map_or(value, |f| value + f);
            increment[i % LANES] += v[i] * (r[i] + new);
            r[i] = new;
        };
    // An interior row (1 <= i <= n - 2).
    let interior = |i: usize, load: Option<f64>, r: &mut [f64], lanes: [&mut [f64; LANES]; 2]| {
        let du = u[i + 1] - u[i];
        let right = k[i + 1] * du;
        lanes[0][i % LANES] += right * du;
        set(i, right - k[i] * (u[i] - u[i - 1]), load, r, lanes[1]);
    };
    // The loads in row order: `load_at(i)` takes row i's, if it has one.
    let mut loads = loads.iter().peekable();
    let load_at = |loads: &mut std::iter::Peekable<std::slice::Iter<(usize, f64)>>, i: usize| {
        loads.next_if(|f| f.0 == i).map(|f| f.1)
    };
    if n == 1 {
        // One node, no element: both ghost forces, `0 - 0 = +0`.
        set(0, 0.0, load_at(&mut loads, 0), r, &mut increment);
        (lanes.strain, lanes.increment) = (strain, increment);
        return;
    }
    if from == 0 {
        let du = u[1] - u[0];
        let right = k[1] * du;
        strain[0] += right * du;
        set(0, right - 0.0, load_at(&mut loads, 0), r, &mut increment);
    }
    let (lo, hi) = (from.max(1), to.min(n - 1));
    let mut row = lo;
    while row < hi {
        // Unloaded rows up to the next loaded one: whole chunks of LANES rows from a multiple of
        // LANES with the intrinsics, the rest one by one.
        let end = loads.peek().map_or(hi, |f| f.0.min(hi));
        let chunks = lane_chunks(row, end);
        for i in row..chunks.start {
            interior(i, None, r, [&mut strain, &mut increment]);
        }
        #[cfg(target_arch = "x86_64")]
        let done = if AVX2 && !chunks.is_empty() {
            // SAFETY: `AVX2` is true only in the step compiled for AVX2, run when the CPU has it.
            unsafe {
                crate::kernels::matrix_mass::avx2::residual_rows(
                    (k, u, v),
                    r,
                    chunks.clone(),
                    [&mut strain, &mut increment],
                )
            }
        } else {
            chunks.start
        };
        #[cfg(not(target_arch = "x86_64"))]
        let done = chunks.start;
        for i in done..end {
            interior(i, None, r, [&mut strain, &mut increment]);
        }
        if end < hi {
            interior(
                end,
                load_at(&mut loads, end),
                r,
                [&mut strain, &mut increment],
            );
            row = end + 1;
        } else {
            row = hi;
        }
    }
    if to == n {
        set(
            n - 1,
            0.0 - force(n - 2),
            load_at(&mut loads, n - 1),
            r,
            &mut increment,
        );
    }
    (lanes.strain, lanes.increment) = (strain, increment);
}

/// Per block of [`BLOCK`] rows (block `b` is rows `b BLOCK..(b + 1) BLOCK`), the coefficients
/// `[diag, off]` of the symmetric tridiagonal `(diag, off)` where the block's rows read only
/// those two values, bit for bit (`diag_i` of every row, `off_{i-1}` and `off_i` of every
/// interior row): a bar of uniform element mass `rho A h` has them away from its ends and fixed
/// nodes. The sweep then broadcasts them instead of streaming two arrays (the same values enter
/// the same operations: the same bits).
pub(crate) fn constant_blocks(diag: &[f64], off: &[f64]) -> Vec<Option<[f64; 2]>> {
    let n = diag.len();
    let equal = |x: &[f64]| x.iter().all(|v| v.to_bits() == x[0].to_bits());
    (0..n.div_ceil(BLOCK))
        .map(|b| {
            let (from, to) = (b * BLOCK, ((b + 1) * BLOCK).min(n));
            // The couplings the rows read: off[from - 1] (row from > 0) to off[to - 1] (row to - 1
            // < n - 1).
            let couplings = &off[from.saturating_sub(1)..to.min(n - 1)];
            let constant = !couplings.is_empty() && equal(&diag[from..to]) && equal(couplings);
            constant.then(|| [diag[from], couplings[0]])
        })
        .collect()
}

/// The reciprocal mass's velocity rows `from..to` (`from` a multiple of [`LANES`]):
/// `a_i = (M^-1 r)_i` formed as [`inverse_row`] forms it, `a_i r_i` added to impulse lane
/// `i % LANES`, then `v_i += dt a_i` (`a` is never stored). `AVX2`: the whole chunks of
/// [`LANES`] interior rows run [`crate::kernels::matrix_mass::avx2::reciprocal_velocity`] (the same
/// operations), with the coefficients broadcast where `constant` gives them (the rows' entries
/// of `diag` and `off`, from [`constant_blocks`]).
#[inline(always)]
pub(crate) fn reciprocal_velocity<const AVX2: bool>(
    (diag, off, constant): (&[f64], &[f64], Option<[f64; 2]>),
    r: &[f64],
    v: &mut [f64],
    (dt, (from, to)): (f64, (usize, usize)),
    impulse: &mut [f64; LANES],
) {
    let n = diag.len();
    let mut product = *impulse;
    let row = |i: usize, v: &mut [f64], product: &mut [f64; LANES]| {
        let a = inverse_row(diag, off, r, i);
        product[i % LANES] += a * r[i];
        v[i] += dt * a;
    };
    // Interior rows (1..n - 1) in whole chunks with the intrinsics; the rest one by one.
    let chunks = lane_chunks(from.max(1), to.min(n.saturating_sub(1)));
    (from..chunks.start).for_each(|i| row(i, v, &mut product));
    #[cfg(target_arch = "x86_64")]
    let done = if AVX2 && !chunks.is_empty() {
        // SAFETY: `AVX2` is true only in the step compiled for AVX2, run when the CPU has it.
        unsafe {
            let rows = (dt, chunks.clone());
            let coefficients = (diag, off);
            match constant {
                Some(c) => crate::kernels::matrix_mass::avx2::reciprocal_velocity::<true>(
                    (coefficients, c),
                    r,
                    v,
                    rows,
                    &mut product,
                ),
                None => crate::kernels::matrix_mass::avx2::reciprocal_velocity::<false>(
                    (coefficients, [0.0; 2]),
                    r,
                    v,
                    rows,
                    &mut product,
                ),
            }
        }
    } else {
        chunks.start
    };
    #[cfg(not(target_arch = "x86_64"))]
    let done = chunks.start;
    (done..to).for_each(|i| row(i, v, &mut product));
    *impulse = product;
}

/// `(M^-1 r)_i`, row `i` of the symmetric tridiagonal `M^-1` (`diag`, `off`) times `r`, formed
/// as [`crate::mass::tridiagonal::Tridiagonal::apply`] forms it (same operations, same order).
#[inline(always)]
pub(crate) fn inverse_row(diag: &[f64], off: &[f64], r: &[f64], i: usize) -> f64 {
    let n = diag.len();
    if n == 1 {
        diag[0] * r[0]
    } else if i == 0 {
        diag[0] * r[0] + off[0] * r[1]
    } else if i == n - 1 {
        off[n - 2] * r[n - 2] + diag[n - 1] * r[n - 1]
    } else {
        off[i - 1] * r[i - 1] + diag[i] * r[i] + off[i] * r[i + 1]
    }
}

/// The energy lanes of one step: strain `N_e du_e`, increment `v^{n+1/2} (r^n + r^{n+1})`,
/// impulse `a^{n+1} r^{n+1}`.
#[derive(Debug, Default)]
pub(crate) struct EnergyLanes {
    pub(crate) strain: [f64; LANES],
    pub(crate) increment: [f64; LANES],
    pub(crate) impulse: [f64; LANES],
}

/// How far a matrix-mass step's first passes have got: `u` advanced to `u_done`, the residual
/// (with its loads up to `next_load` and the strain and increment lanes) to row `r_done`.
#[derive(Debug, Default)]
pub(crate) struct ResidualFront {
    u_done: usize,
    r_done: usize,
    next_load: usize,
}

impl ResidualFront {
    /// A front whose residual starts at row `row` (`u` at node 0): a chunk of the bar whose
    /// rows before `row` are formed elsewhere ([`crate::kernels::matrix_mass::chunks`]).
    pub(crate) fn from_row(row: usize) -> Self {
        Self {
            u_done: 0,
            r_done: row,
            next_load: 0,
        }
    }

    /// Advance the residual to row `to` (or the end) in blocks of at most [`BLOCK`] rows, `u`
    /// one node ahead of it (its element forces are formed in registers). Where the blocks
    /// end changes no bit: every row is formed alike and adds to its own lanes in row order.
    #[inline(always)]
    pub(crate) fn advance<const AVX2: bool>(
        &mut self,
        to: usize,
        (dt, k): (f64, &[f64]),
        (u, v): (&mut [f64], &[f64]),
        r: &mut [f64],
        loads: &[(usize, f64)],
        lanes: &mut EnergyLanes,
    ) {
        let n = u.len();
        while self.r_done < to.min(n) {
            let (from, r_to) = (self.r_done, (self.r_done + BLOCK).min(to).min(n));
            advance(dt, u, v, &mut self.u_done, (r_to + 1).min(n));
            let block_loads = rows_loads(loads, &mut self.next_load, r_to);
            residual_rows::<AVX2>((k, u, v), r, (from, r_to), block_loads, lanes);
            self.r_done = r_to;
        }
    }
}

/// The loads from `*next` on whose nodes are below `to` (`loads` sorted); `*next` moves past them.
#[inline(always)]
fn rows_loads<'f>(loads: &'f [(usize, f64)], next: &mut usize, to: usize) -> &'f [(usize, f64)] {
    let from = *next;
    *next += loads[from..].partition_point(|f| f.0 < to);
    &loads[from..*next]
}

/// `u^{n+1} = u^n + dt v^{n+1/2}` for nodes `*u_done..u_to`; the counter advances.
#[inline(always)]
fn advance(dt: f64, u: &mut [f64], v: &[f64], u_done: &mut usize, u_to: usize) {
    for (ui, vi) in u[*u_done..u_to].iter_mut().zip(&v[*u_done..u_to]) {
        *ui += dt * vi;
    }
    *u_done = u_to.max(*u_done);
}

/// Update every `x[i]` with `f(i, &mut x[i], data)` and sum each of the `K` terms it returns in
/// [`LANES`] partial sums (index `i` adds to lane `i % LANES`), added up in a fixed order at the
/// end: the whole-pass step's sums, which the blocked step's lanes reproduce.
#[cfg(test)]
pub(crate) fn lane_sums<const K: usize, D: Copy>(
    x: &mut [f64],
    data: D,
    f: impl Fn(usize, &mut f64, D) -> [f64; K],
) -> [f64; K] {
    let mut lanes = [[0.0; LANES]; K];
    for (i, xi) in x.iter_mut().enumerate() {
        for (lane, term) in lanes.iter_mut().zip(f(i, xi, data)) {
            lane[i % LANES] += term;
        }
    }
    lanes.map(|lane| lane.iter().sum())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_blocks_are_those_whose_rows_read_one_diagonal_and_one_coupling() {
        // Uniform interior, half-weight end rows (as an assembled bar's), one odd coupling.
        let n = 4 * BLOCK + 10;
        let assembled = |odd: usize| {
            let mut diag = vec![2.0; n];
            (diag[0], diag[n - 1]) = (1.0, 1.0);
            let mut off = vec![0.5; n - 1];
            off[odd] = 0.25;
            (diag, off)
        };
        let uniform = Some([2.0, 0.5]);
        // Block 0 holds row 0, the last block row n - 1; the odd coupling inside block 1.
        let (diag, off) = assembled(BLOCK + 7);
        assert_eq!(
            constant_blocks(&diag, &off),
            [None, None, uniform, uniform, None]
        );
        // A coupling read across a block edge: off[2 BLOCK - 1] is row 2 BLOCK - 1's right
        // coupling and row 2 BLOCK's left one.
        let (diag, off) = assembled(2 * BLOCK - 1);
        assert_eq!(
            constant_blocks(&diag, &off),
            [None, None, None, uniform, None]
        );
        // One node: nothing to broadcast.
        assert_eq!(constant_blocks(&[1.0], &[]), [None]);
    }
}
