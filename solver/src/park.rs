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

/// Per-element constants of the push-forward and pull-back.
#[derive(Debug, Clone)]
struct ElementStep {
    dt_e: f64,
    beta1: f64,
    beta2: f64,
    stiffness: f64,
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
    loaded: Vec<bool>,
    u: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    u_fs: Vec<f64>,
    u_next: Vec<f64>,
    force_now: Vec<f64>,
    force_push: Vec<f64>,
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
            elements.push(ElementStep {
                dt_e,
                beta1: alpha * (1.0 + 3.0 * alpha - alpha * alpha) / 6.0,
                beta2: alpha * (alpha * alpha - 1.0) / 6.0,
                stiffness: k,
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
            loaded: (0..n)
                .map(|i| model.loads().iter().any(|l| l.node == i))
                .collect(),
            u: model.initial_displacement().to_vec(),
            v: model.initial_velocity().to_vec(),
            a: vec![0.0; n],
            u_fs: vec![0.0; n],
            u_next: vec![0.0; n],
            force_now: vec![0.0; n],
            force_push: vec![0.0; n],
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

    /// Advance from `t^n = t` to `t + dt`. Energies at the new level: kinetic `1/2 v M v` (also
    /// reported as the staggered kinetic energy: Park's scheme has no staggered velocities) and
    /// strain `1/2 u K u`.
    pub fn step(&mut self, model: &Model, t: f64) -> StepEnergy {
        let (dt, theta) = (self.dt, self.options.theta);
        let n = self.u.len();
        self.u_fs.iter_mut().for_each(|x| *x = 0.0);
        // Loads are sparse: only loaded nodes are evaluated (the arrays stay 0 elsewhere).
        for i in (0..n).filter(|&i| self.loaded[i]) {
            self.force_now[i] = model.external_force_at(i, t);
        }
        for (e, el) in self.elements.iter().enumerate() {
            let (i, j) = (e, e + 1);
            let dte = el.dt_e;
            for node in [i, j] {
                if self.loaded[node] {
                    self.force_push[node] = model.external_force_at(node, t + dte);
                }
            }
            let ut_i = self.u[i] + dte * self.v[i] + 0.5 * dte * dte * self.a[i];
            let ut_j = self.u[j] + dte * self.v[j] + 0.5 * dte * dte * self.a[j];
            // Element loads: each node's load shared by mass.
            let (fi, fj) = (self.share_right[i], self.share_left[j]);
            let (at_i, at_j) = match self.options.variant {
                ParkVariant::Free => {
                    let tension = el.stiffness * (ut_j - ut_i);
                    (
                        el.inverse_half_mass * (fi * self.force_push[i] + tension),
                        el.inverse_half_mass * (fj * self.force_push[j] - tension),
                    )
                }
                ParkVariant::Incremental => {
                    let d_tension = el.stiffness * ((ut_j - self.u[j]) - (ut_i - self.u[i]));
                    (
                        self.a[i]
                            + el.inverse_half_mass
                                * (fi * (self.force_push[i] - self.force_now[i]) + d_tension),
                        self.a[j]
                            + el.inverse_half_mass
                                * (fj * (self.force_push[j] - self.force_now[j]) - d_tension),
                    )
                }
            };
            let pull = |u: f64, v: f64, a: f64, at: f64| {
                u + dt * v + dte * dte * (el.beta1 * a + el.beta2 * at)
            };
            self.u_fs[i] += pull(self.u[i], self.v[i], self.a[i], at_i);
            self.u_fs[j] += pull(self.u[j], self.v[j], self.a[j], at_j);
        }
        for i in 0..n {
            let u_cd = self.u[i] + dt * self.v[i] + 0.5 * dt * dt * self.a[i];
            let u_fs = self.u_fs[i] * self.inverse_count[i];
            self.u_next[i] = if self.inverse_mass[i] == 0.0 {
                0.0
            } else {
                theta * u_fs + (1.0 - theta) * u_cd
            };
        }
        std::mem::swap(&mut self.u, &mut self.u_next);
        let t_next = t + dt;
        for i in (0..n).filter(|&i| self.loaded[i]) {
            self.force_next[i] = model.external_force_at(i, t_next);
        }
        let (mut kinetic, mut strain) = (0.0, 0.0);
        for i in 0..n {
            let a_next =
                self.inverse_mass[i] * (self.force_next[i] + model.internal_force_at(&self.u, i));
            self.v[i] += 0.5 * dt * (self.a[i] + a_next);
            self.a[i] = a_next;
            kinetic += self.mass[i] * self.v[i] * self.v[i];
            if i + 1 < n {
                let du = self.u[i + 1] - self.u[i];
                strain += model.stiffness()[i] * du * du;
            }
        }
        StepEnergy {
            kinetic_staggered: 0.5 * kinetic,
            kinetic: 0.5 * kinetic,
            strain: 0.5 * strain,
        }
    }
}
