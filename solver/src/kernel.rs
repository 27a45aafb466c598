//! The lumped central-difference step, O(N) with no global matrices.
//!
//! State: `u^n` and the half-step velocity `v^{n+1/2}`. One step (seed eqs. 2-4 in half-step
//! form, methods.md §2):
//!
//! ```text
//!   u^{n+1}   = u^n + dt v^{n+1/2}
//!   a^{n+1}   = M^-1 (F^{n+1} - K u^{n+1}),   (K u)_i = -[k_i (u_{i+1} - u_i) - k_{i-1} (u_i - u_{i-1})]
//!   v^{n+3/2} = v^{n+1/2} + dt a^{n+1}
//! ```
//!
//! Arrays carry one ghost node at each end (index 0 and N+2) with zero stiffness, mass and
//! motion, so every real node runs the same branch-free stencil. Fixed nodes have `M^-1 = 0`.
//! External forces act on a few nodes: the node loop runs in branch-free segments between them.

use crate::model::Model;

/// Energy sums of one step, at the new level `t^{n+1}`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepEnergy {
    /// `1/2 v^{n+1/2} M v^{n+3/2}`.
    pub kinetic_staggered: f64,
    /// `1/2 v^{n+1} M v^{n+1}`, `v^{n+1} = (v^{n+1/2} + v^{n+3/2})/2`.
    pub kinetic: f64,
    /// `1/2 u^{n+1} K u^{n+1}`.
    pub strain: f64,
}

/// Lumped-mass central difference on a ghost-padded node layout.
#[derive(Debug, Clone)]
pub struct LumpedCentralDifference {
    dt: f64,
    /// `k[j]`: stiffness between padded nodes j and j+1 (0 for the ghost links); length N+2.
    k: Vec<f64>,
    /// `dt / m_i` (0 at fixed and ghost nodes); length N+3.
    dt_inverse_mass: Vec<f64>,
    /// `m_i` (0 at ghosts); length N+3.
    mass: Vec<f64>,
    /// Padded displacement `u^n`; length N+3.
    u: Vec<f64>,
    /// Padded half-step velocity `v^{n+1/2}`; length N+3.
    v: Vec<f64>,
}

impl LumpedCentralDifference {
    /// Set up the operators of `model` for step `dt`, with state `u = u^0` and
    /// `v = v^{1/2}` supplied by the caller (see [`crate::central_difference::Start`]).
    pub fn new(model: &Model, dt: f64, u0: &[f64], v_half: &[f64]) -> Self {
        let n = model.bar().node_count();
        let pad = |inner: &mut dyn Iterator<Item = f64>| -> Vec<f64> {
            std::iter::once(0.0)
                .chain(inner)
                .chain(std::iter::once(0.0))
                .collect()
        };
        let k = pad(&mut model.stiffness().iter().copied());
        let dt_inverse_mass = pad(&mut model.inverse_mass().iter().map(|m| dt * m));
        let mass = pad(&mut model.nodal_mass().iter().copied());
        let u = pad(&mut u0.iter().copied());
        let v = pad(&mut v_half.iter().copied());
        debug_assert_eq!(u.len(), n + 2);
        Self {
            dt,
            k,
            dt_inverse_mass,
            mass,
            u,
            v,
        }
    }

    /// The time step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Displacements `u^n` of the real nodes.
    pub fn displacement(&self) -> &[f64] {
        &self.u[1..self.u.len() - 1]
    }

    /// Half-step velocities `v^{n+1/2}` of the real nodes.
    pub fn half_step_velocity(&self) -> &[f64] {
        &self.v[1..self.v.len() - 1]
    }

    /// Advance one step. `forces` lists `(node, F_node^{n+1})`, sorted by node, each node once.
    #[inline]
    pub fn step(&mut self, forces: &[(usize, f64)]) {
        self.advance::<false>(forces);
    }

    /// Advance one step and return the energies at the new level (same arithmetic as
    /// [`Self::step`], so both give bit-identical states).
    #[inline]
    pub fn step_with_energy(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        self.advance::<true>(forces)
    }

    fn advance<const ENERGY: bool>(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        let dt = self.dt;
        for (u, v) in self.u.iter_mut().zip(&self.v) {
            *u += dt * v;
        }
        let mut sums = StepEnergy::default();
        let real_nodes = self.u.len() - 2;
        let mut next = 1; // padded index of the next node to update
        for &(node, force) in forces {
            let p = node + 1;
            self.sweep::<ENERGY>(next, p, &mut sums);
            self.update_node::<ENERGY>(p, force, &mut sums);
            next = p + 1;
        }
        self.sweep::<ENERGY>(next, real_nodes + 1, &mut sums);
        if ENERGY {
            // Strain energy over every element: links 1..=N-1 of the padded layout are real; the
            // ghost links have k = 0. Computed here, outside the velocity loop, once per step.
            let strain: f64 = self
                .k
                .iter()
                .zip(self.u.windows(2))
                .map(|(k, w)| k * (w[1] - w[0]) * (w[1] - w[0]))
                .sum();
            sums.strain = 0.5 * strain;
            sums.kinetic *= 0.125;
            sums.kinetic_staggered *= 0.5;
        }
        sums
    }

    /// Velocity update of padded nodes `from..to` (no external force).
    #[inline(always)]
    fn sweep<const ENERGY: bool>(&mut self, from: usize, to: usize, sums: &mut StepEnergy) {
        if from >= to {
            return;
        }
        let (u, k) = (&self.u[from - 1..=to], &self.k[from - 1..to]);
        let (v, s) = (&mut self.v[from..to], &self.dt_inverse_mass[from..to]);
        if ENERGY {
            let m = &self.mass[from..to];
            for i in 0..v.len() {
                let right = u[i + 2] - u[i + 1];
                let r = k[i + 1] * right - k[i] * (u[i + 1] - u[i]);
                let old = v[i];
                let new = old + s[i] * r;
                v[i] = new;
                sums.strain += k[i + 1] * right * right;
                sums.kinetic_staggered += m[i] * old * new;
                sums.kinetic += m[i] * (old + new) * (old + new);
            }
        } else {
            for i in 0..v.len() {
                let r = k[i + 1] * (u[i + 2] - u[i + 1]) - k[i] * (u[i + 1] - u[i]);
                v[i] += s[i] * r;
            }
        }
    }

    /// Velocity update of one padded node `p` carrying an external force.
    #[inline(always)]
    fn update_node<const ENERGY: bool>(&mut self, p: usize, force: f64, sums: &mut StepEnergy) {
        let (u, k) = (&self.u, &self.k);
        let r = k[p] * (u[p + 1] - u[p]) - k[p - 1] * (u[p] - u[p - 1]) + force;
        let old = self.v[p];
        let new = old + self.dt_inverse_mass[p] * r;
        self.v[p] = new;
        if ENERGY {
            let right = u[p + 1] - u[p];
            sums.strain += k[p] * right * right;
            sums.kinetic_staggered += self.mass[p] * old * new;
            sums.kinetic += self.mass[p] * (old + new) * (old + new);
        }
    }
}
