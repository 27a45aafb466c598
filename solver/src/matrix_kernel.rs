//! The central-difference step with a non-diagonal mass (CMM, AMM: a pre-factored tridiagonal
//! solve; RMM: a tridiagonal product with the assembled `M^-1`), O(N) per step, no dense matrix.
//!
//! ```text
//!   u^{n+1}   = u^n + dt v^{n+1/2}
//!   r^{n+1}   = F^{n+1} - K u^{n+1}              (element by element)
//!   a^{n+1}   = M^-1 r^{n+1}                      (solve, or product with M^-1)
//!   v^{n+3/2} = v^{n+1/2} + dt a^{n+1}
//! ```
//!
//! Energies use `M` itself: `1/2 v^{n+1/2} . M v^{n+3/2}` from the kept product `M v^{n+1/2}`,
//! so the balance checks the mass operator as well as the update.

use crate::kernel::StepEnergy;
use crate::mass::MassOperator;

/// Central difference with a tridiagonal mass or inverse mass.
#[derive(Debug, Clone)]
pub struct MatrixCentralDifference {
    dt: f64,
    stiffness: Vec<f64>,
    mass: MassOperator,
    u: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    r: Vec<f64>,
    mv_old: Vec<f64>,
    mv_new: Vec<f64>,
}

impl MatrixCentralDifference {
    /// Set up with element stiffnesses, the mass operator, `u^0`, `v^{1/2}` and `a^0`.
    pub fn new(
        dt: f64,
        stiffness: &[f64],
        mass: MassOperator,
        u0: &[f64],
        v_half: &[f64],
        a0: &[f64],
    ) -> Self {
        let n = u0.len();
        let mut mv_old = vec![0.0; n];
        mass.apply(v_half, &mut mv_old);
        Self {
            dt,
            stiffness: stiffness.to_vec(),
            mass,
            u: u0.to_vec(),
            v: v_half.to_vec(),
            a: a0.to_vec(),
            r: vec![0.0; n],
            mv_old,
            mv_new: vec![0.0; n],
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
    pub fn step_with_energy(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        let dt = self.dt;
        for (u, v) in self.u.iter_mut().zip(&self.v) {
            *u += dt * v;
        }
        let n = self.u.len();
        let mut strain = 0.0;
        self.r.iter_mut().for_each(|r| *r = 0.0);
        for (e, &k) in self.stiffness.iter().enumerate() {
            let du = self.u[e + 1] - self.u[e];
            let force = k * du;
            self.r[e] += force;
            self.r[e + 1] -= force;
            strain += force * du;
        }
        for &(node, f) in forces {
            self.r[node] += f;
        }
        self.mass.apply_inverse(&mut self.r, &mut self.a);
        for i in 0..n {
            self.v[i] += dt * self.a[i];
        }
        self.mass.apply(&self.v, &mut self.mv_new);
        let (mut staggered, mut kinetic) = (0.0, 0.0);
        for i in 0..n {
            let old = self.v[i] - dt * self.a[i];
            staggered += self.v[i] * self.mv_old[i];
            kinetic += (old + self.v[i]) * (self.mv_old[i] + self.mv_new[i]);
        }
        std::mem::swap(&mut self.mv_old, &mut self.mv_new);
        StepEnergy {
            kinetic_staggered: 0.5 * staggered,
            kinetic: 0.125 * kinetic,
            strain: 0.5 * strain,
        }
    }
}
