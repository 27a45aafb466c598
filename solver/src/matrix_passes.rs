//! The passes of the blocked matrix-mass step ([`crate::matrix_kernel`]), each over a range of
//! nodes or elements so that the step can run them block by block: the displacement update's
//! strain lanes, the residual rows `r = F - K u`, the rows of the reciprocal mass's product
//! `a = M^-1 r`, and the velocity update with its energy lanes. Each forms its values with the
//! same operations in the same order as the whole-pass step (tested there), so blocking changes
//! no bit.

use crate::kernel::LANES;

/// Nodes per block of the blocked step (a multiple of [`LANES`]).
pub(crate) const BLOCK: usize = 512;

/// `v^{n+3/2} = v^{n+1/2} + dt a^{n+1}` for the nodes of `v` (starting at a multiple of
/// [`LANES`]), adding `a r` to the impulse lanes and, `INCREMENT`, `v^{n+1/2} (r^n + r^{n+1})`
/// to the increment lanes; `a`, `r_previous` (unused without `INCREMENT`) and `r` hold the same
/// nodes as `v` (and may be longer). `AVX2`: the whole chunks of [`LANES`] nodes run
/// [`crate::matrix_avx2::velocity_lanes`] (only an AVX2-compiled caller may ask for it).
#[inline(always)]
pub(crate) fn velocity_lanes<const AVX2: bool, const INCREMENT: bool>(
    v: &mut [f64],
    a: &[f64],
    r_previous: &[f64],
    r: &[f64],
    dt: f64,
    [increment, impulse]: [&mut [f64; LANES]; 2],
) {
    let len = v.len();
    let (a, r) = (&a[..len], &r[..len]);
    let r_previous = if INCREMENT { &r_previous[..len] } else { r };
    #[cfg(target_arch = "x86_64")]
    let done = if AVX2 {
        // SAFETY: `AVX2` is true only in the step compiled for AVX2, run when the CPU has it.
        unsafe {
            crate::matrix_avx2::velocity_lanes::<INCREMENT>(
                v, a, r_previous, r, dt, increment, impulse,
            )
        }
    } else {
        0
    };
    #[cfg(not(target_arch = "x86_64"))]
    let done = 0;
    let (mut sum, mut product) = (*increment, *impulse);
    for i in done..len {
        if INCREMENT {
            sum[i % LANES] += v[i] * (r_previous[i] + r[i]);
        }
        product[i % LANES] += a[i] * r[i];
        v[i] += dt * a[i];
    }
    (*increment, *impulse) = (sum, product);
}

/// For the nodes of `v` (starting at a multiple of [`LANES`]): add `v^{n+1/2} (r^n + r^{n+1})`
/// to the increment lanes and, `COPY`, copy `r^{n+1}` to `copy` (unused without it);
/// `r_previous`, `r` and `copy` hold the same nodes as `v` (`r_previous` may be longer).
/// `AVX2`: the whole chunks run [`crate::matrix_avx2::increment_lanes`].
#[inline(always)]
pub(crate) fn increment_lanes<const AVX2: bool, const COPY: bool>(
    v: &[f64],
    r_previous: &[f64],
    r: &[f64],
    copy: &mut [f64],
    increment: &mut [f64; LANES],
) {
    let len = v.len();
    let (r_previous, r) = (&r_previous[..len], &r[..len]);
    #[cfg(target_arch = "x86_64")]
    let done = if AVX2 {
        // SAFETY: `AVX2` is true only in the step compiled for AVX2, run when the CPU has it.
        unsafe { crate::matrix_avx2::increment_lanes::<COPY>(v, r_previous, r, copy, increment) }
    } else {
        0
    };
    #[cfg(not(target_arch = "x86_64"))]
    let done = 0;
    let mut sum = *increment;
    for i in done..len {
        sum[i % LANES] += v[i] * (r_previous[i] + r[i]);
    }
    if COPY {
        copy[done..len].copy_from_slice(&r[done..]);
    }
    *increment = sum;
}

/// Add `N_e du_e`, `N_e = k[e] du_e`, `du_e = u[e + 1] - u[e]`, of the elements of `k` to lane
/// `e % LANES` (the slices start at a multiple of [`LANES`] of the whole element array).
#[inline(always)]
pub(crate) fn strain_lanes(k: &[f64], u: &[f64], lanes: &mut [f64; LANES]) {
    let mut local = *lanes;
    let whole = k.len() / LANES * LANES;
    for (kk, uu) in k[..whole]
        .chunks_exact(LANES)
        .zip(u.windows(LANES + 1).step_by(LANES))
    {
        for l in 0..LANES {
            let du = uu[l + 1] - uu[l];
            let force = kk[l] * du;
            local[l] += force * du;
        }
    }
    for e in whole..k.len() {
        let du = u[e + 1] - u[e];
        let force = k[e] * du;
        local[e % LANES] += force * du;
    }
    *lanes = local;
}

/// `r[i] = N_i - N_{i-1}` for rows `from..to`, overwriting `r` in place after keeping the old
/// value in `kept[i - from]` (the loads are added by the caller), with the element forces `N`
/// of padded index `i + 1` formed as `k[i + 1] (u[i + 1] - u[i])` (`k` the padded stiffness,
/// length `n + 1`) and the ghost forces 0: the whole-pass step's
/// `element_force[i + 1] - element_force[i]`, operation for operation.
#[inline(always)]
pub(crate) fn residual_rows(
    k: &[f64],
    u: &[f64],
    r: &mut [f64],
    kept: &mut [f64],
    from: usize,
    to: usize,
) {
    let n = u.len();
    if from >= to {
        return;
    }
    let kept = &mut kept[..to - from];
    let set = |i: usize, value: f64, r: &mut [f64], kept: &mut [f64]| {
        kept[i - from] = r[i];
        r[i] = value;
    };
    let force = |i: usize| k[i + 1] * (u[i + 1] - u[i]);
    if n == 1 {
        // One node, no element: both ghost forces, `0 - 0 = +0`.
        set(0, 0.0, r, kept);
        return;
    }
    if from == 0 {
        set(0, force(0) - 0.0, r, kept);
    }
    let (lo, hi) = (from.max(1), to.min(n - 1));
    if lo < hi {
        let rows = r[lo..hi]
            .iter_mut()
            .zip(u[lo - 1..hi + 1].windows(3))
            .zip(k[lo..hi + 1].windows(2));
        let value = |us: &[f64], ks: &[f64]| ks[1] * (us[2] - us[1]) - ks[0] * (us[1] - us[0]);
        for (((ri, us), ks), old) in rows.zip(&mut kept[lo - from..hi - from]) {
            *old = *ri;
            *ri = value(us, ks);
        }
    }
    if to == n {
        set(n - 1, 0.0 - force(n - 2), r, kept);
    }
}

/// `a[i - from] = (M^-1 r)_i` for rows `from..to` of the symmetric tridiagonal `M^-1` (`diag`,
/// `off`), each row formed as [`crate::tridiagonal::Tridiagonal::apply`] forms it (same
/// operations, same order); interior rows as zipped windows, so the loop vectorises.
#[inline(always)]
pub(crate) fn apply_rows(
    diag: &[f64],
    off: &[f64],
    r: &[f64],
    a: &mut [f64],
    from: usize,
    to: usize,
) {
    let n = diag.len();
    if from >= to {
        return;
    }
    if n == 1 {
        a[0] = diag[0] * r[0];
        return;
    }
    if from == 0 {
        a[0] = diag[0] * r[0] + off[0] * r[1];
    }
    let (lo, hi) = (from.max(1), to.min(n - 1));
    if lo < hi {
        for (((ai, rs), di), os) in a[lo - from..hi - from]
            .iter_mut()
            .zip(r[lo - 1..hi + 1].windows(3))
            .zip(&diag[lo..hi])
            .zip(off[lo - 1..hi].windows(2))
        {
            *ai = os[0] * rs[0] + di * rs[1] + os[1] * rs[2];
        }
    }
    if to == n {
        a[n - 1 - from] = off[n - 2] * r[n - 2] + diag[n - 1] * r[n - 1];
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

/// How far the CMM/AMM step's first passes have got: `u` advanced to `u_done`, the strain lanes
/// to element `e_done`, the residual (with the loads up to `next_force` and the increment
/// lanes) to row `r_done`.
#[derive(Debug, Default)]
pub(crate) struct ResidualFront {
    u_done: usize,
    e_done: usize,
    r_done: usize,
    next_force: usize,
}

impl ResidualFront {
    /// Advance in blocks of [`BLOCK`] rows (from 0, whatever `to`: the lanes' order is the
    /// whole-pass step's) until the residual reaches row `to` or the end: `u` one node ahead
    /// of the residual, whose element forces are formed in registers; with `COPY` the residual
    /// also copied to `copy` (the right-hand side of the global solve).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(crate) fn advance<const AVX2: bool, const COPY: bool>(
        &mut self,
        to: usize,
        dt: f64,
        k: &[f64],
        u: &mut [f64],
        v: &[f64],
        r: &mut [f64],
        previous: &mut [f64],
        copy: &mut [f64],
        forces: &[(usize, f64)],
        lanes: &mut EnergyLanes,
    ) {
        let n = u.len();
        while self.r_done < to.min(n) {
            let (from, r_to) = (self.r_done, (self.r_done + BLOCK).min(n));
            let e_to = r_to.div_ceil(LANES).saturating_mul(LANES).min(n - 1);
            let u_to = (e_to + 1).min(n);
            let counters = (&mut self.u_done, &mut self.e_done);
            advance_and_strain(dt, k, u, v, counters, (u_to, e_to), lanes);
            residual_rows(k, u, r, previous, from, r_to);
            while let Some(&(node, f)) = forces.get(self.next_force).filter(|f| f.0 < r_to) {
                r[node] += f;
                self.next_force += 1;
            }
            let copy: &mut [f64] = if COPY { &mut copy[from..r_to] } else { &mut [] };
            increment_lanes::<AVX2, COPY>(
                &v[from..r_to],
                previous,
                &r[from..r_to],
                copy,
                &mut lanes.increment,
            );
            self.r_done = r_to;
        }
    }
}

/// `u^{n+1} = u^n + dt v^{n+1/2}` for nodes `*u_done..u_to`, then the strain lanes of elements
/// `*e_done..e_to` (which read `u` up to `e_to`); both counters advance.
#[inline(always)]
pub(crate) fn advance_and_strain(
    dt: f64,
    k: &[f64],
    u: &mut [f64],
    v: &[f64],
    (u_done, e_done): (&mut usize, &mut usize),
    (u_to, e_to): (usize, usize),
    lanes: &mut EnergyLanes,
) {
    for (ui, vi) in u[*u_done..u_to].iter_mut().zip(&v[*u_done..u_to]) {
        *ui += dt * vi;
    }
    *u_done = u_to.max(*u_done);
    if *e_done < e_to {
        strain_lanes(
            &k[*e_done + 1..e_to + 1],
            &u[*e_done..e_to + 1],
            &mut lanes.strain,
        );
    }
    *e_done = e_to.max(*e_done);
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
