//! The central-difference step with a non-diagonal mass (CMM, AMM: a pre-factored, partitioned
//! tridiagonal solve, [`crate::partitioned_ldl`]; RMM: a tridiagonal product with the assembled
//! `M^-1`, no solve), O(N) per step, no dense matrix, no allocation; the passes run in cache
//! blocks ([`MatrixCentralDifference::step_with_energy`]).
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
//! and, at sampled steps, `T*` from `M` itself ([`MatrixCentralDifference::staggered_kinetic_from_mass`]),
//! which checks the mass operator against the update.

use crate::kernel::{LANES, StepEnergy, has_avx2};
use crate::mass::MassOperator;

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

/// Central difference with a tridiagonal mass or inverse mass.
#[derive(Debug, Clone)]
pub struct MatrixCentralDifference {
    dt: f64,
    /// Element stiffnesses padded with a zero at both ends (length N + 2).
    stiffness: Vec<f64>,
    mass: MassOperator,
    u: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    r: Vec<f64>,
    r_previous: Vec<f64>,
    scratch: Vec<f64>,
    staggered: f64,
    /// Whether the CPU has AVX2 (the blocked step then runs its AVX2-compiled copy).
    avx2: bool,
}

impl MatrixCentralDifference {
    /// Set up with element stiffnesses, the mass operator, `u^0`, `v^{1/2}`, `a^0`, the residual
    /// `r^0 = F^0 - K u^0` and the staggered kinetic energy `1/2 v^{-1/2} M v^{1/2}`.
    pub fn new(dt: f64, stiffness: &[f64], mass: MassOperator, start: &StartState) -> Self {
        let StartState {
            displacement: u0,
            half_step_velocity: v_half,
            acceleration: a0,
            residual: r0,
            kinetic_staggered: staggered0,
        } = *start;
        let n = u0.len();
        let mut padded = vec![0.0; n + 1];
        padded[1..n].copy_from_slice(stiffness);
        Self {
            dt,
            stiffness: padded,
            mass,
            u: u0.to_vec(),
            v: v_half.to_vec(),
            a: a0.to_vec(),
            r: vec![0.0; n],
            r_previous: r0.to_vec(),
            scratch: vec![0.0; n],
            staggered: staggered0,
            avx2: has_avx2(),
        }
    }

    /// Time step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// `u^n`.
    pub fn displacement(&self) -> &[f64] {
        &self.u
    }

    /// `v^{n+1/2}`.
    pub fn half_step_velocity(&self) -> &[f64] {
        &self.v
    }

    /// `a^n`.
    pub fn acceleration(&self) -> &[f64] {
        &self.a
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
        self.blocked_step(forces)
    }

    /// The step as whole passes over the arrays (any mass operator): the reference the blocked
    /// step is tested against.
    #[cfg(test)]
    fn whole_pass_step(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        let dt = self.dt;
        // Element forces padded with a zero at both ends (length N + 2).
        let mut element_force = vec![0.0; self.u.len() + 1];
        for (u, v) in self.u.iter_mut().zip(&self.v) {
            *u += dt * v;
        }
        // Element forces N_e = k_e (u_{e+1} - u_e) at padded index e + 1 (ghosts stay 0).
        let n = self.u.len();
        let [strain] = lane_sums(
            &mut element_force[1..n],
            (&self.stiffness[1..n], &self.u[..]),
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
            &mut self.v,
            (&self.a[..], (&self.r_previous[..], &self.r[..])),
            |i, v, (a, (r_previous, r))| {
                let terms = [*v * (r_previous[i] + r[i]), a[i] * r[i]];
                *v += dt * a[i];
                terms
            },
        );
        self.staggered += 0.5 * dt * increment;
        std::mem::swap(&mut self.r, &mut self.r_previous);
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
    /// in the same block), so a block's data are still in L1 when the next pass reads them.
    /// CMM and AMM solve with the whole residual after the blocks, then update `v` in one pass.
    /// Every value is computed by the same operations as in whole passes, and each pass's
    /// blocks start at multiples of [`LANES`], so every energy term goes to the same lane in the
    /// same order: bit-identical to the whole-pass step (tested).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn blocked_step_avx2(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        self.blocked_step(forces)
    }

    #[inline(always)]
    fn blocked_step(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        let mass = &self.mass;
        let reciprocal = match mass {
            MassOperator::Reciprocal { inverse, .. } => Some((&inverse.diag[..], &inverse.off[..])),
            _ => None,
        };
        let (dt, n) = (self.dt, self.u.len());
        let (u, v, a, r) = (&mut self.u, &mut self.v, &mut self.a, &mut self.r);
        let (k, r_previous) = (&self.stiffness, &self.r_previous);
        let (mut strain, mut increment, mut impulse) = ([0.0; LANES], [0.0; LANES], [0.0; LANES]);
        let (mut u_done, mut e_done, mut r_done, mut v_done) = (0, 0, 0, 0);
        let mut next_force = 0;
        while r_done < n {
            let v_to = (v_done + BLOCK).min(n);
            let r_to = (v_to + 1).min(n);
            let e_to = r_to.div_ceil(LANES).saturating_mul(LANES).min(n - 1);
            let u_to = (e_to + 1).min(n);
            // u^{n+1} = u^n + dt v^{n+1/2}.
            for (ui, vi) in u[u_done..u_to].iter_mut().zip(&v[u_done..u_to]) {
                *ui += dt * vi;
            }
            u_done = u_to;
            // Strain lanes of the elements: N_e du_e, N_e = k_e du_e.
            if e_done < e_to {
                strain_lanes(&k[e_done + 1..e_to + 1], &u[e_done..e_to + 1], &mut strain);
            }
            e_done = e_to.max(e_done);
            // r_i = N_i - N_{i-1} + F_i, each N formed as the whole-pass step forms it (the
            // ghost forces beyond the ends are 0).
            residual_rows(k, u, r, r_done, r_to);
            while let Some(&(node, f)) = forces.get(next_force).filter(|f| f.0 < r_to) {
                r[node] += f;
                next_force += 1;
            }
            r_done = r_to;
            // Reciprocal mass: a = M^-1 r, row by row as `Tridiagonal::apply` forms it, and v.
            if let Some((diag, off)) = reciprocal {
                apply_rows(diag, off, r, a, v_done, v_to);
                velocity_lanes(
                    v,
                    a,
                    r_previous,
                    r,
                    dt,
                    v_done,
                    v_to,
                    [&mut increment, &mut impulse],
                );
            }
            v_done = v_to;
        }
        if reciprocal.is_none() {
            // a = M^-1 r (CMM, AMM: the factored solve), then v in one pass.
            mass.apply_inverse(r, a);
            velocity_lanes(
                v,
                a,
                r_previous,
                r,
                dt,
                0,
                n,
                [&mut increment, &mut impulse],
            );
        }
        let total = |lanes: [f64; LANES]| lanes.iter().sum::<f64>();
        self.staggered += 0.5 * dt * total(increment);
        std::mem::swap(&mut self.r, &mut self.r_previous);
        StepEnergy {
            kinetic_staggered: self.staggered,
            kinetic: self.staggered + 0.125 * dt * dt * total(impulse),
            strain: 0.5 * total(strain),
        }
    }

    /// `1/2 v^{n-1/2} . M v^{n+1/2}` computed with the mass operator itself (one product or
    /// solve): compared with the running `T*` it checks `M^-1` against `M`.
    pub fn staggered_kinetic_from_mass(&mut self) -> f64 {
        let dt = self.dt;
        self.mass.apply(&self.v, &mut self.scratch);
        0.5 * self
            .v
            .iter()
            .zip(&self.a)
            .zip(&self.scratch)
            .map(|((v, a), mv)| (v - dt * a) * mv)
            .sum::<f64>()
    }
}

/// Nodes per block of the blocked reciprocal-mass step (a multiple of [`LANES`]).
const BLOCK: usize = 512;

/// `v^{n+3/2} = v^{n+1/2} + dt a^{n+1}` for nodes `from..to` (`from` a multiple of [`LANES`]),
/// adding `v^{n+1/2} (r^n + r^{n+1})` and `a r` to the increment and impulse lanes.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn velocity_lanes(
    v: &mut [f64],
    a: &[f64],
    r_previous: &[f64],
    r: &[f64],
    dt: f64,
    from: usize,
    to: usize,
    lanes: [&mut [f64; LANES]; 2],
) {
    lane_sums_into(
        &mut v[from..to],
        (&a[from..to], (&r_previous[from..to], &r[from..to])),
        |i, v, (a, (r_previous, r))| {
            let terms = [*v * (r_previous[i] + r[i]), a[i] * r[i]];
            *v += dt * a[i];
            terms
        },
        &mut { lanes },
    );
}

/// Add `N_e du_e`, `N_e = k[e] du_e`, `du_e = u[e + 1] - u[e]`, of the elements of `k` to lane
/// `e % LANES` (the slices start at a multiple of [`LANES`] of the whole element array).
#[inline(always)]
fn strain_lanes(k: &[f64], u: &[f64], lanes: &mut [f64; LANES]) {
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

/// `r[i] = N_i - N_{i-1}` for rows `from..to` (the loads are added by the caller), with the
/// element forces `N` of padded index `i + 1` formed as `k[i + 1] (u[i + 1] - u[i])` (`k` the
/// padded stiffness, length `n + 1`) and the ghost forces 0: the whole-pass step's
/// `element_force[i + 1] - element_force[i]`, operation for operation.
#[inline(always)]
fn residual_rows(k: &[f64], u: &[f64], r: &mut [f64], from: usize, to: usize) {
    let n = u.len();
    if from >= to {
        return;
    }
    let force = |i: usize| k[i + 1] * (u[i + 1] - u[i]);
    if n == 1 {
        // One node, no element: both ghost forces, `0 - 0 = +0`.
        r[0] = 0.0;
        return;
    }
    if from == 0 {
        r[0] = force(0) - 0.0;
    }
    let (lo, hi) = (from.max(1), to.min(n - 1));
    if lo < hi {
        for ((ri, us), ks) in r[lo..hi]
            .iter_mut()
            .zip(u[lo - 1..hi + 1].windows(3))
            .zip(k[lo..hi + 1].windows(2))
        {
            *ri = ks[1] * (us[2] - us[1]) - ks[0] * (us[1] - us[0]);
        }
    }
    if to == n {
        r[n - 1] = 0.0 - force(n - 2);
    }
}

/// `a[i] = (M^-1 r)_i` for rows `from..to` of the symmetric tridiagonal `M^-1` (`diag`, `off`),
/// each row formed as [`crate::tridiagonal::Tridiagonal::apply`] forms it (same operations, same
/// order); interior rows as zipped windows, so the loop vectorises.
#[inline(always)]
fn apply_rows(diag: &[f64], off: &[f64], r: &[f64], a: &mut [f64], from: usize, to: usize) {
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
        for (((ai, rs), di), os) in a[lo..hi]
            .iter_mut()
            .zip(r[lo - 1..hi + 1].windows(3))
            .zip(&diag[lo..hi])
            .zip(off[lo - 1..hi].windows(2))
        {
            *ai = os[0] * rs[0] + di * rs[1] + os[1] * rs[2];
        }
    }
    if to == n {
        a[n - 1] = off[n - 2] * r[n - 2] + diag[n - 1] * r[n - 1];
    }
}

/// [`lane_sums`] adding into `lanes` (one per term) instead of returning the totals: `x` and
/// the data start at a multiple of [`LANES`] of the whole array, so local index `i` adds to the
/// lane of its global index.
#[inline(always)]
fn lane_sums_into<const K: usize, D: Copy>(
    x: &mut [f64],
    data: D,
    f: impl Fn(usize, &mut f64, D) -> [f64; K],
    lanes: &mut [&mut [f64; LANES]; K],
) {
    let mut local = [[0.0; LANES]; K];
    for (l, lane) in local.iter_mut().zip(lanes.iter()) {
        *l = **lane;
    }
    let whole = x.len() / LANES * LANES;
    let (body, rest) = x.split_at_mut(whole);
    for (c, chunk) in body.chunks_exact_mut(LANES).enumerate() {
        for (l, xi) in chunk.iter_mut().enumerate() {
            let terms = f(c * LANES + l, xi, data);
            for (lane, term) in local.iter_mut().zip(terms) {
                lane[l] += term;
            }
        }
    }
    for (l, xi) in rest.iter_mut().enumerate() {
        let terms = f(whole + l, xi, data);
        for (lane, term) in local.iter_mut().zip(terms) {
            lane[l] += term;
        }
    }
    for (lane, l) in lanes.iter_mut().zip(local) {
        **lane = l;
    }
}

#[cfg(test)]
/// Update every `x[i]` with `f(i, &mut x[i], data)` and sum each of the `K` terms it returns in
/// [`LANES`] partial sums, added up in a fixed order at the end.
#[inline(always)]
fn lane_sums<const K: usize, D: Copy>(
    x: &mut [f64],
    data: D,
    f: impl Fn(usize, &mut f64, D) -> [f64; K],
) -> [f64; K] {
    let mut lanes = [[0.0; LANES]; K];
    lane_sums_into(x, data, f, &mut lanes.each_mut());
    lanes.map(|lane| lane.iter().sum())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass::MassKind;

    fn matrix_kernel(n: usize, kind: MassKind) -> MatrixCentralDifference {
        let model = crate::fixtures::graded_seed_bar(n).unwrap();
        let dt = 0.5 * kind.critical_courant() * model.bar().stiffest_element().1;
        let v = crate::fixtures::smooth_half_velocity(n);
        let zeros = vec![0.0; n + 1];
        let start = StartState {
            displacement: &zeros,
            half_step_velocity: &v,
            acceleration: &zeros,
            residual: &zeros,
            kinetic_staggered: 0.0,
        };
        let mass = MassOperator::new(&model, kind).unwrap();
        MatrixCentralDifference::new(dt, model.stiffness(), mass, &start)
    }

    #[test]
    fn blocked_step_is_bit_identical_to_whole_passes_for_every_matrix_mass() {
        // Several blocks, loads inside a block, at a block edge and at the last node; and a
        // mesh shorter than a block.
        for (n, forces) in [
            (
                3 * BLOCK + 37,
                vec![
                    (0, 1.0),
                    (700, -0.25),
                    (2 * BLOCK, 0.5),
                    (3 * BLOCK + 37, 2.0),
                ],
            ),
            (5, vec![(0, 1.0)]),
        ] {
            for (kind, avx2) in [
                MassKind::Reciprocal { beta: 0.5 },
                MassKind::Consistent,
                MassKind::Averaged { beta: 0.5 },
            ]
            .into_iter()
            .flat_map(|kind| [(kind, false), (kind, has_avx2())])
            {
                let mut blocked = matrix_kernel(n, kind);
                blocked.avx2 = avx2;
                let mut whole = matrix_kernel(n, kind);
                for _ in 0..200 {
                    let a = blocked.step_with_energy(&forces);
                    let b = whole.whole_pass_step(&forces);
                    assert_eq!(a, b, "{kind:?}");
                }
                assert_eq!((&blocked.u, &blocked.v), (&whole.u, &whole.v));
                assert_eq!(
                    (&blocked.a, &blocked.r_previous),
                    (&whole.a, &whole.r_previous)
                );
            }
        }
    }
}
