//! Park's explicit scheme with local time stepping and pull-back interpolation (seed §3.1, as
//! corrected in methods.md §6; Park et al., the seed's refs. [11-13]).
//!
//! Per step `n -> n+1` with the global `dt`; element `e` has its own critical step
//! `dt_e = h_e/c_e` and `alpha_e = dt/dt_e <= 1`:
//!
//! ```text
//!   1. push forward each element alone to t^n + dt_e (element LMM M_e = m_e/2 I):
//!        u~_e = u_e^n + dt_e v_e^n + dt_e^2/2 a_e^n
//!        a~_e = M_e^-1 (f_e - K_e u~_e)                                  (variant "free")
//!        a~_e = a_e^n + M_e^-1 (df_e - K_e (u~_e - u_e^n))                (variant "incremental")
//!   2. pull back to t^{n+1} by cubic interpolation in time:
//!        u_fs,e = u_e^n + dt v_e^n + dt_e^2 (beta1 a_e^n + beta2 a~_e),
//!        beta1 = alpha (1 + 3 alpha - alpha^2)/6,  beta2 = alpha (alpha^2 - 1)/6
//!   3. u_fs = plain average of the element predictions at each node
//!   4. u_cd = u^n + dt v^n + dt^2/2 a^n;   u^{n+1} = theta u_fs + (1 - theta) u_cd
//!      a^{n+1} = M^-1 (f^{n+1} - K u^{n+1});   v^{n+1} = v^n + dt/2 (a^n + a^{n+1})
//! ```
//!
//! The seed prints `dt_e v` in step 2 and drops `dt` in the velocity update: both misprints
//! (methods.md §6). `theta = 0` is central difference; at `alpha = 1` every theta is. `theta = 1/2`
//! cancels the leading phase error `(2 theta - 1)(1 - alpha^2)(kh)^2/24`. A nodal load is shared
//! between the two elements of its node in proportion to their share of the nodal mass, so the
//! element problems see the same acceleration as the assembled one under a uniform state.
//! "Without local stepping" uses one common `dt_e` (the stiffest element's) for every element.

use crate::error::InputError;
use crate::kernel::StepEnergy;
use crate::model::Model;

/// The element acceleration of step 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ParkVariant {
    /// `a~_e = M_e^-1 (f_e - K_e u~_e)`: the seed's literal formula.
    #[default]
    Free,
    /// `a~_e = a_e^n + M_e^-1 (df_e - K_e (u~_e - u_e^n))`: interface forces frozen at `t^n`;
    /// keeps a static state static on heterogeneous meshes.
    Incremental,
}

impl ParkVariant {
    /// Name in outputs.
    pub fn name(self) -> &'static str {
        match self {
            ParkVariant::Free => "free",
            ParkVariant::Incremental => "incremental",
        }
    }
}

/// Parameters of Park's scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParkOptions {
    /// Blend of the pulled-back and CD predictions, `0 <= theta <= 1` (default 1/2).
    pub theta: f64,
    /// Element acceleration variant (default `free`).
    pub variant: ParkVariant,
    /// Each element steps with its own `dt_e` (default); otherwise all use the stiffest one's.
    pub local_stepping: bool,
}

impl Default for ParkOptions {
    fn default() -> Self {
        Self {
            theta: 0.5,
            variant: ParkVariant::Free,
            local_stepping: true,
        }
    }
}

impl ParkOptions {
    /// Short name, e.g. `park-lts-free`.
    pub fn label(&self) -> String {
        format!(
            "park-{}-{}",
            if self.local_stepping { "lts" } else { "global" },
            self.variant.name()
        )
    }
}

/// Per-element constants of the push-forward and pull-back, premultiplied for the step.
#[derive(Debug, Clone, Copy)]
struct ElementStep {
    dt_e: f64,
    /// `dt_e^2 / 2`.
    half_dt_e2: f64,
    /// `dt_e^2 beta1`.
    pull_a: f64,
    /// `dt_e^2 beta2`.
    pull_at: f64,
    /// `k_e 2/m_e`: element acceleration per unit stretch.
    stiffness_per_mass: f64,
    /// `2 / m_e`: the inverse of each node's share of the element LMM.
    inverse_half_mass: f64,
}

/// Park's scheme on a lumped-mass bar.
#[derive(Debug, Clone)]
pub struct ParkScheme {
    dt: f64,
    options: ParkOptions,
    elements: Vec<ElementStep>,
    /// `1/(number of elements at the node)`.
    inverse_count: Vec<f64>,
    /// Share of a nodal load carried by the element on the node's left and right.
    share_left: Vec<f64>,
    share_right: Vec<f64>,
    inverse_mass: Vec<f64>,
    mass: Vec<f64>,
    /// Nodes that carry a load (the others have zero external force at every time).
    loaded_nodes: Vec<usize>,
    /// 1 at free nodes, 0 at fixed ones.
    free: Vec<f64>,
    u: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    u_fs: Vec<f64>,
    u_next: Vec<f64>,
    /// `F^{n+1}`, nonzero only at loaded nodes.
    force_next: Vec<f64>,
}

impl ParkScheme {
    /// Set up for `model` with step `dt`; `alpha_e = dt/dt_e > 1` in any element is refused
    /// (the scheme is unstable there), naming the element.
    pub fn new(model: &Model, dt: f64, options: ParkOptions) -> Result<Self, InputError> {
        if !(0.0..=1.0).contains(&options.theta) {
            return Err(InputError::Parameter {
                field: "theta",
                value: options.theta,
                rule: "must lie in [0, 1]",
            });
        }
        let bar = model.bar();
        let n = bar.node_count();
        let (_, stiffest) = bar.stiffest_element();
        let masses = bar.element_mass();
        let mut elements = Vec::with_capacity(n - 1);
        for (e, (&k, &m)) in model.stiffness().iter().zip(&masses).enumerate() {
            let dt_e = if options.local_stepping {
                bar.element_transit_time(e)
            } else {
                stiffest
            };
            let alpha = dt / dt_e;
            if alpha > 1.0 + crate::time_step::ROUNDING_SLACK {
                return Err(InputError::Other(format!(
                    "Park's scheme needs alpha_e = dt/dt_e <= 1 in every element; element {e} has alpha = {alpha:.6} \
                     (dt = {dt:e}, dt_e = {dt_e:e}): lower the Courant number"
                )));
            }
            let alpha = alpha.min(1.0);
            let beta1 = alpha * (1.0 + 3.0 * alpha - alpha * alpha) / 6.0;
            let beta2 = alpha * (alpha * alpha - 1.0) / 6.0;
            elements.push(ElementStep {
                dt_e,
                half_dt_e2: 0.5 * dt_e * dt_e,
                pull_a: dt_e * dt_e * beta1,
                pull_at: dt_e * dt_e * beta2,
                stiffness_per_mass: k * 2.0 / m,
                inverse_half_mass: 2.0 / m,
            });
        }
        let mut inverse_count = vec![0.5; n];
        inverse_count[0] = 1.0;
        inverse_count[n - 1] = 1.0;
        let nodal = model.nodal_mass();
        let share_left: Vec<f64> = (0..n)
            .map(|i| {
                if i > 0 {
                    0.5 * masses[i - 1] / nodal[i]
                } else {
                    0.0
                }
            })
            .collect();
        let share_right: Vec<f64> = (0..n)
            .map(|i| {
                if i + 1 < n {
                    0.5 * masses[i] / nodal[i]
                } else {
                    0.0
                }
            })
            .collect();
        Ok(Self {
            dt,
            options,
            elements,
            inverse_count,
            share_left,
            share_right,
            inverse_mass: model.inverse_mass().to_vec(),
            mass: nodal.to_vec(),
            loaded_nodes: (0..n)
                .filter(|&i| model.loads().iter().any(|l| l.node == i))
                .collect(),
            free: (0..n)
                .map(|i| if model.is_fixed(i) { 0.0 } else { 1.0 })
                .collect(),
            u: model.initial_displacement().to_vec(),
            v: model.initial_velocity().to_vec(),
            a: vec![0.0; n],
            u_fs: vec![0.0; n],
            u_next: vec![0.0; n],
            force_next: vec![0.0; n],
        })
    }

    /// Set the starting acceleration `a^0 = M^-1 (F(0) - K u^0)`.
    pub fn start(&mut self, model: &Model) {
        for i in 0..self.a.len() {
            self.a[i] = model.acceleration_at(&self.u, i, 0.0);
        }
    }

    /// Time step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Options.
    pub fn options(&self) -> ParkOptions {
        self.options
    }

    /// `u^n`.
    pub fn displacement(&self) -> &[f64] {
        &self.u
    }

    /// `v^n` (full step).
    pub fn velocity(&self) -> &[f64] {
        &self.v
    }

    /// `a^n`.
    pub fn acceleration(&self) -> &[f64] {
        &self.a
    }

    /// Advance from `t^n = t` to `t + dt`. Energies at the new level: kinetic `1/2 v M v`, strain
    /// `1/2 u K u`, and as "staggered" kinetic energy `1/2 v M v - dt^2/8 a M a`, which equals
    /// CD's conserved `1/2 v^{n-1/2} M v^{n+1/2}` when the scheme is CD (theta = 0 or alpha = 1).
    ///
    /// Loads are sparse: the element loop runs load-free and the few loaded (element, node)
    /// pairs are corrected afterwards (the loads enter the predictions linearly).
    pub fn step(&mut self, model: &Model, t: f64) -> StepEnergy {
        let (dt, theta) = (self.dt, self.options.theta);
        let n = self.u.len();
        let incremental = self.options.variant == ParkVariant::Incremental;
        let (u, v, a) = (&self.u, &self.v, &self.a);
        // 1. Push forward, element acceleration and pull back, element by element; each node's
        //    two predictions are summed with a carry (no separate zeroing pass).
        let mut carry = 0.0;
        for (e, el) in self.elements.iter().enumerate() {
            let (ui, uj, vi, vj, ai, aj) = (u[e], u[e + 1], v[e], v[e + 1], a[e], a[e + 1]);
            let dte = el.dt_e;
            let ut_i = ui + dte * vi + el.half_dt_e2 * ai;
            let ut_j = uj + dte * vj + el.half_dt_e2 * aj;
            let (at_i, at_j) = if incremental {
                let d = el.stiffness_per_mass * ((ut_j - uj) - (ut_i - ui));
                (ai + d, aj - d)
            } else {
                let d = el.stiffness_per_mass * (ut_j - ut_i);
                (d, -d)
            };
            self.u_fs[e] = carry + ui + dt * vi + el.pull_a * ai + el.pull_at * at_i;
            carry = uj + dt * vj + el.pull_a * aj + el.pull_at * at_j;
        }
        self.u_fs[n - 1] = carry;
        // 2. Loads on the element problems: a~ gains inverse_half_mass * share * F (free) or
        //    * share * dF (incremental), and u_fs gains dt_e^2 beta2 times that.
        for &node in &self.loaded_nodes {
            let now = model.external_force_at(node, t);
            for (e, share) in [
                (node.checked_sub(1), self.share_left[node]),
                (Some(node).filter(|&k| k + 1 < n), self.share_right[node]),
            ] {
                let Some(e) = e else { continue };
                let el = &self.elements[e];
                let push = model.external_force_at(node, t + el.dt_e);
                let force = if incremental { push - now } else { push };
                self.u_fs[node] += el.pull_at * el.inverse_half_mass * share * force;
            }
        }
        // 3. Blend with the CD prediction; fixed nodes stay at 0.
        for i in 0..n {
            let u_cd = self.u[i] + dt * self.v[i] + 0.5 * dt * dt * self.a[i];
            self.u_next[i] = self.free[i]
                * (theta * self.u_fs[i] * self.inverse_count[i] + (1.0 - theta) * u_cd);
        }
        std::mem::swap(&mut self.u, &mut self.u_next);
        // 4. New accelerations (element forces carried node to node), trapezoidal velocities.
        let t_next = t + dt;
        for &node in &self.loaded_nodes {
            self.force_next[node] = model.external_force_at(node, t_next);
        }
        let k = model.stiffness();
        let (mut kinetic, mut strain, mut left, mut impulse) = (0.0, 0.0, 0.0, 0.0);
        let mut node = |i: usize, right: f64, this: &mut Self| {
            let a_next = this.inverse_mass[i] * (this.force_next[i] + right - left);
            left = right;
            this.v[i] += 0.5 * dt * (this.a[i] + a_next);
            this.a[i] = a_next;
            kinetic += this.mass[i] * this.v[i] * this.v[i];
            impulse += this.mass[i] * a_next * a_next;
        };
        for (i, &ki) in k.iter().enumerate() {
            let du = self.u[i + 1] - self.u[i];
            let right = ki * du;
            strain += right * du;
            node(i, right, self);
        }
        node(n - 1, 0.0, self);
        // T - dt^2/8 a M a: with full-step velocities this is CD's conserved kinetic part
        // 1/2 v^{n-1/2} M v^{n+1/2}, so the energy balance of the CD limits is round-off.
        StepEnergy {
            kinetic_staggered: 0.5 * kinetic - 0.125 * dt * dt * impulse,
            kinetic: 0.5 * kinetic,
            strain: 0.5 * strain,
        }
    }
}
