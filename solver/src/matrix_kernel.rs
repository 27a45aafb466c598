//! The central-difference step with a non-diagonal mass (CMM, AMM: a pre-factored, partitioned
//! tridiagonal solve, [`crate::partitioned_ldl`]; RMM: a tridiagonal product with the assembled
//! `M^-1`, no solve), O(N) per step, no dense matrix, no allocation.
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

use crate::kernel::{LANES, StepEnergy};
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
    /// Element forces padded with a zero at both ends (length N + 2).
    element_force: Vec<f64>,
    scratch: Vec<f64>,
    staggered: f64,
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
            element_force: vec![0.0; n + 1],
            scratch: vec![0.0; n],
            staggered: staggered0,
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
        let dt = self.dt;
        for (u, v) in self.u.iter_mut().zip(&self.v) {
            *u += dt * v;
        }
        // Element forces N_e = k_e (u_{e+1} - u_e) at padded index e + 1 (ghosts stay 0).
        let n = self.u.len();
        let [strain] = lane_sums(
            &mut self.element_force[1..n],
            (&self.stiffness[1..n], &self.u[..]),
            |e, force, (k, u)| {
                let du = u[e + 1] - u[e];
                *force = k[e] * du;
                [*force * du]
            },
        );
        // r_i = N_i - N_{i-1} + F_i.
        for (r, pair) in self.r.iter_mut().zip(self.element_force.windows(2)) {
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

/// Update every `x[i]` with `f(i, &mut x[i], data)` and sum each of the `K` terms it returns in
/// [`LANES`] partial sums, added up in a fixed order at the end.
#[inline(always)]
fn lane_sums<const K: usize, D: Copy>(
    x: &mut [f64],
    data: D,
    f: impl Fn(usize, &mut f64, D) -> [f64; K],
) -> [f64; K] {
    let mut lanes = [[0.0; LANES]; K];
    let whole = x.len() / LANES * LANES;
    let (body, rest) = x.split_at_mut(whole);
    for (c, chunk) in body.chunks_exact_mut(LANES).enumerate() {
        for (l, xi) in chunk.iter_mut().enumerate() {
            let terms = f(c * LANES + l, xi, data);
            for (lane, term) in lanes.iter_mut().zip(terms) {
                lane[l] += term;
            }
        }
    }
    for (l, xi) in rest.iter_mut().enumerate() {
        let terms = f(whole + l, xi, data);
        for (lane, term) in lanes.iter_mut().zip(terms) {
            lane[l] += term;
        }
    }
    lanes.map(|lane| lane.iter().sum())
}
