//! [`CombinedStepper`]: the time loop's state of a combined contact run (bulk of
//! [`BulkScheme`], contact of [`ContactScheme`]) in velocity-Verlet form, `u^n`, `v^n`, `a^n`
//! with the contact in `a^n` (module docs of [`crate::contact::combined`]).

use super::bulk::{Assembly, BulkScheme, ContactDirection};
use crate::contact::problem::ContactProblem;
use crate::contact::scheme::{ContactScheme, MomentumInput, contact_momentum};
use crate::error::InputError;

/// How the contact condition is applied.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactMode {
    /// Contact acts when the scheme's (predicted) gap is negative: the impact.
    Unilateral,
    /// Contact acts at every level whatever the gap: the linear contact-active map, whose
    /// amplification matrix gives the persistent-contact step limit.
    Bilateral,
    /// No contact: the contact-free bulk, the baseline of the step limits (Park then steps the
    /// contact nodes too: the pure Park scheme).
    Off,
}

/// One level's contact: gap `g^n`, whether it acted, momentum `J^n`, force `F^n = J^n/(w_n dt)`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CombinedLevel {
    /// Step index n.
    pub step: usize,
    /// `t^n`.
    pub time: f64,
    /// `g^n = N^T u^n + g0`.
    pub gap: f64,
    /// Whether contact acted at level n.
    pub active: bool,
    /// `J^n` along N (compression positive).
    pub impulse: f64,
    /// `F^n = J^n/(w_n dt)` (compression positive), stamped `t^n`.
    pub force: f64,
}

/// The energies of the current level (O(N); RMM: one solve with `C` for `M v`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CombinedEnergy {
    /// `1/2 v^n M v^n`.
    pub kinetic: f64,
    /// `1/2 v M v - dt^2/8 a M a`: central difference's conserved `1/2 v^{n-1/2} M v^{n+1/2}`
    /// on the lumped mass (and Park's balance energy, [`crate::schemes::park`]).
    pub kinetic_staggered: f64,
    /// `1/2 u K u`.
    pub strain: f64,
    /// The penalty spring `1/2 k_s g^2` when the gap is negative and the scheme has `k_s`.
    pub penalty_spring: f64,
}

/// A combined contact run being integrated. It does not check stability: see
/// [`super::amplification`] and [`CombinedStepper::new`].
#[derive(Debug, Clone)]
pub struct CombinedStepper<'a> {
    problem: &'a ContactProblem,
    bulk: BulkScheme,
    scheme: ContactScheme,
    mode: ContactMode,
    dt: f64,
    step: usize,
    assembly: Assembly,
    direction: ContactDirection,
    /// Nodes stepped by central difference under Park (the contact nodes).
    cd_nodes: Vec<bool>,
    u: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    /// The previous level's acceleration (swapped with `a` each step, not copied).
    a_prev: Vec<f64>,
    /// Work arrays of [`Self::energy`]: `M v` and `M a`.
    mass_products: [Vec<f64>; 2],
    next: Vec<f64>,
    residual: Vec<f64>,
    level: CombinedLevel,
    impulse: f64,
}

impl<'a> CombinedStepper<'a> {
    /// Set up the start: `a^0 = M^-1 (F^0 - K u^0) + M^-1 N J^0/(dt/2)` with the level-0 contact
    /// (`w_0 = 1/2`), so that `v^{1/2} = v^0 + dt/2 a^0` is the lumped stepper's start.
    ///
    /// # Errors
    /// [`InputError`] if `dt` is not positive, the scheme's parameters or the mass are invalid,
    /// or Park's `alpha_e = dt/dt_e` exceeds 1 in some element (refused: Park is unstable there;
    /// [`Self::allowing_unstable`] runs it).
    pub fn new(
        problem: &'a ContactProblem,
        bulk: BulkScheme,
        scheme: ContactScheme,
        dt: f64,
    ) -> Result<Self, InputError> {
        let stepper = Self::allowing_unstable(problem, bulk, scheme, ContactMode::Unilateral, dt)?;
        if !matches!(bulk, BulkScheme::Park(_)) {
            return Ok(stepper);
        }
        if let Some(e) = stepper
            .assembly
            .elements
            .iter()
            .find(|e| dt > e.dt_e * (1.0 + 1e-12))
        {
            return Err(InputError::Parameter {
                field: "dt/dt_e of Park's scheme",
                value: dt / e.dt_e,
                rule: "must not exceed 1 in any element (methods.md §6)",
            });
        }
        Ok(stepper)
    }

    /// As [`Self::new`] with the contact `mode`, Park's `alpha_e > 1` run with its true value.
    ///
    /// # Errors
    /// As [`Self::new`], except the Park limit.
    pub fn allowing_unstable(
        problem: &'a ContactProblem,
        bulk: BulkScheme,
        scheme: ContactScheme,
        mode: ContactMode,
        dt: f64,
    ) -> Result<Self, InputError> {
        crate::model::mesh::positive("dt", dt)?;
        scheme.validate()?;
        if let BulkScheme::Park(o) = bulk
            && !(0.0..=1.0).contains(&o.theta)
        {
            return Err(InputError::Parameter {
                field: "theta",
                value: o.theta,
                rule: "must lie in [0, 1]",
            });
        }
        let assembly = Assembly::new(problem, &bulk)?;
        let direction = assembly.direction(problem);
        let n = problem.node_count();
        let mut cd_nodes = vec![false; n];
        if mode != ContactMode::Off {
            direction.n.iter().for_each(|&(i, _)| cd_nodes[i] = true);
        }
        let mut u = Vec::with_capacity(n);
        let mut v = Vec::with_capacity(n);
        for model in problem.bodies() {
            u.extend_from_slice(model.initial_displacement());
            v.extend_from_slice(model.initial_velocity());
        }
        let mut s = Self {
            problem,
            bulk,
            scheme,
            mode,
            dt,
            step: 0,
            assembly,
            direction,
            cd_nodes,
            a: vec![0.0; n],
            a_prev: vec![0.0; n],
            mass_products: [vec![0.0; n], vec![0.0; n]],
            next: vec![0.0; n],
            residual: vec![0.0; n],
            u,
            v,
            level: CombinedLevel::default(),
            impulse: 0.0,
        };
        let v0 = s.v.clone();
        s.accelerate(0.0, &v0, 0.5);
        Ok(s)
    }

    /// Set `a` at the current level from `u` (contact included): `a0 = M^-1 R`, then
    /// `a = a0 + q J/(w dt)` with `J` of the contact scheme from `g`, `N^T v_prior` (the
    /// velocity `v^{n-1/2}`, or `v^0` at the start) and `N^T a0`.
    fn accelerate(&mut self, t: f64, v_prior: &[f64], weight: f64) {
        self.assembly
            .residual(self.problem, &self.u, t, &mut self.residual);
        self.assembly.inverse.apply(&self.residual, &mut self.a);
        let d = &self.direction;
        let gap = d.project(&self.u) + self.problem.initial_gap();
        let (active, impulse) = match self.mode {
            ContactMode::Off => (false, 0.0),
            mode => contact_momentum(
                &self.scheme,
                &MomentumInput {
                    gap,
                    relative_velocity: d.project(v_prior),
                    relative_acceleration: d.project(&self.a),
                    compliance: d.compliance,
                    weight,
                    dt: self.dt,
                },
                mode == ContactMode::Bilateral,
            ),
        };
        let force = impulse / (weight * self.dt);
        d.add_scaled(force, &mut self.a);
        self.impulse += impulse;
        self.level = CombinedLevel {
            step: self.step,
            time: t,
            gap,
            active,
            impulse,
            force,
        };
    }

    /// Advance one step, `n -> n+1`; returns the new level's contact.
    pub fn step(&mut self) -> CombinedLevel {
        let dt = self.dt;
        let t = self.step as f64 * dt;
        match self.bulk {
            BulkScheme::Park(options) => self.assembly.park_displacement(
                self.problem,
                &options,
                &self.cd_nodes,
                [&self.u, &self.v, &self.a],
                dt,
                t,
                &mut self.next,
            ),
            _ => {
                for (k, x) in self.next.iter_mut().enumerate() {
                    *x = if self.assembly.fixed[k] {
                        0.0
                    } else {
                        self.u[k] + dt * self.v[k] + 0.5 * dt * dt * self.a[k]
                    };
                }
            }
        }
        std::mem::swap(&mut self.u, &mut self.next);
        // v^{n+1/2} = v^n + dt/2 a^n: the velocity the level-(n+1) contact predicts with.
        let mut half = std::mem::take(&mut self.next);
        for ((h, v), a) in half.iter_mut().zip(&self.v).zip(&self.a) {
            *h = v + 0.5 * dt * a;
        }
        self.step += 1;
        std::mem::swap(&mut self.a, &mut self.a_prev);
        self.accelerate(t + dt, &half, 1.0);
        for ((v, a0), a1) in self.v.iter_mut().zip(&self.a_prev).zip(&self.a) {
            *v += 0.5 * dt * (a0 + a1);
        }
        self.next = half;
        self.level
    }

    /// The current level's contact.
    pub fn level(&self) -> CombinedLevel {
        self.level
    }

    /// Sum of the contact momenta `J^k` delivered so far (levels 0..=n).
    pub fn impulse(&self) -> f64 {
        self.impulse
    }

    /// The time step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Step index n.
    pub fn step_index(&self) -> usize {
        self.step
    }

    /// `(u^n, v^n, a^n)` over the global numbering (the bodies' nodes one after the other).
    pub fn state(&self) -> [&[f64]; 3] {
        [&self.u, &self.v, &self.a]
    }

    /// Replace the state (for the amplification matrix: a unit perturbation per column).
    pub(super) fn set_state(&mut self, u: &[f64], v: &[f64], a: &[f64]) {
        self.step = 1;
        self.u.copy_from_slice(u);
        self.v.copy_from_slice(v);
        self.a.copy_from_slice(a);
    }

    /// The range of body `b` in the global numbering.
    pub fn body_range(&self, b: usize) -> std::ops::Range<usize> {
        let start = self.assembly.offsets[b];
        start..start + self.problem.bodies()[b].bar().node_count()
    }

    /// Momentum of each body, `sum_i A_i v_i^n` (RMM preserves `1^T M = 1^T A`, methods.md §5).
    pub fn momenta(&self) -> Vec<f64> {
        (0..self.problem.bodies().len())
            .map(|b| {
                self.body_range(b)
                    .map(|i| self.assembly.lumped[i] * self.v[i])
                    .sum()
            })
            .collect()
    }

    /// The energies of the current level.
    pub fn energy(&mut self) -> CombinedEnergy {
        let [mut mv, mut ma] = std::mem::take(&mut self.mass_products);
        self.assembly.mass_times(&self.v, &mut mv);
        self.assembly.mass_times(&self.a, &mut ma);
        let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(p, q)| p * q).sum::<f64>();
        let kinetic = 0.5 * dot(&self.v, &mv);
        let strain = 0.5
            * self
                .assembly
                .elements
                .iter()
                .map(|e| e.stiffness * (self.u[e.i + 1] - self.u[e.i]).powi(2))
                .sum::<f64>();
        let gap = self.level.gap;
        let penalty_spring = if gap < 0.0 {
            0.5 * self.scheme.penalty().stiffness * gap * gap
        } else {
            0.0
        };
        let kinetic_staggered = kinetic - 0.125 * self.dt * self.dt * dot(&self.a, &ma);
        self.mass_products = [mv, ma];
        CombinedEnergy {
            kinetic,
            kinetic_staggered,
            strain,
            penalty_spring,
        }
    }

    /// Element stresses of body `b` at the current level.
    pub fn stress(&self, b: usize) -> Vec<f64> {
        self.problem.bodies()[b].element_stress(&self.u[self.body_range(b)])
    }

    /// The contact direction `M^-1 N`, `s` (the bipenalty's rank-one update).
    pub fn direction(&self) -> &ContactDirection {
        &self.direction
    }

    /// Node count of the global numbering.
    pub fn node_count(&self) -> usize {
        self.u.len()
    }
}
