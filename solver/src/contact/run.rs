//! The contact time loop: start, per-step O(1) contact update on the unchanged lumped kernel,
//! histories, profiles, stability check and blow-up guard.

use super::error::{ContactError, ContactUnstableError};
use super::problem::ContactProblem;
use super::scheme::{ContactScheme, LevelInput, LevelUpdate, level_update};
use super::stability::ContactCriticalStep;
use crate::central_difference::StabilityPolicy;
use crate::error::{DivergenceError, InputError};
use crate::kernel::LumpedCentralDifference;
use crate::model::Model;

/// One level `t^n` of a contact run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactSample {
    /// Step index n.
    pub step: usize,
    /// `t^n = n dt`.
    pub time: f64,
    /// Contact force, compression positive: the momentum `J^n` delivered to the real masses at
    /// level n over the span of the level's velocity update (`dt`, or `dt/2` at n = 0),
    /// stamped `t^n` (methods.md §7).
    pub force: f64,
    /// `eps_s x penetration = k_s max(0, -g^n)` (0 for the Lagrange multiplier method). Not the
    /// contact force once a mass penalty acts, nor for the predictor-corrector scheme.
    pub penalty_force: f64,
    /// Gap `g^n = N^T u^n + g0`.
    pub gap: f64,
    /// Whether the scheme applied contact at level n (CD: `g^n < 0`; predictor-corrector and
    /// Lagrange multiplier: predicted `g^{n+1} < 0`).
    pub active: bool,
    /// Cumulative contact impulse `sum_{k <= n} J^k`.
    pub impulse: f64,
    /// Kinetic energy `1/2 v^n M v^n`, `v^n = (v^{n-1/2} + v^{n+1/2})/2` (`v^0` at n = 0).
    pub kinetic: f64,
    /// Central difference's staggered kinetic term `1/2 v^{n-1/2} M v^{n+1/2}` (`kinetic` at
    /// n = 0, where `v^{-1/2}` does not exist). With `strain` it is the energy CD conserves
    /// exactly for free bodies (`1/2 v^{n-1/2} M v^{n+1/2} + 1/2 u^n K u^n`, Hughes 1987, §9.1),
    /// positive definite below the critical step; unlike `kinetic` it does not count the
    /// step-scale oscillation of a mode near the limit as energy.
    pub kinetic_staggered: f64,
    /// Strain energy `1/2 u^n K u^n`.
    pub strain: f64,
    /// Penalty spring energy `1/2 k_s min(g^n, 0)^2`.
    pub penalty_spring: f64,
    /// Penalty-mass kinetic energy `1/2 m_p (N^T v^n)^2` while active, for CD bipenalty (the
    /// only scheme in which the penalty mass carries a state; the predictor-corrector scheme
    /// only weights its correction with it). It appears when the contact switches on with a
    /// nonzero relative velocity: a property of the bipenalty functional, not energy gained by
    /// the bodies.
    pub penalty_kinetic: f64,
    /// `kinetic + strain + penalty_spring + penalty_kinetic`.
    pub total: f64,
}

/// Element stresses of every body at one level.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactProfile {
    /// Step index n.
    pub step: usize,
    /// `t^n`.
    pub time: f64,
    /// `sigma_e^n` per body ([`Model::element_stress`]).
    pub stress: Vec<Vec<f64>>,
}

/// What a contact run records.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRequest {
    /// Keep a [`ContactSample`] every this many steps (>= 1); step 0 and the last step always.
    pub history_every: usize,
    /// Steps at which to record stress profiles.
    pub profile_steps: Vec<usize>,
}

impl Default for ContactRequest {
    fn default() -> Self {
        Self {
            history_every: 1,
            profile_steps: Vec::new(),
        }
    }
}

/// Everything a contact run recorded.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRun {
    /// The scheme.
    pub scheme: ContactScheme,
    /// Time step.
    pub dt: f64,
    /// Steps taken (fewer than planned when the run diverged).
    pub steps: usize,
    /// Courant number relative to the stiffest element.
    pub courant: f64,
    /// The critical steps of the problem under the scheme.
    pub critical: ContactCriticalStep,
    /// Samples at the requested interval.
    pub history: Vec<ContactSample>,
    /// Stress profiles at the requested steps that were reached.
    pub profiles: Vec<ContactProfile>,
    /// Total contact impulse.
    pub impulse: f64,
    /// Momentum `sum_i m_i v_i^0` of each body at the start.
    pub initial_momentum: Vec<f64>,
    /// Momentum `sum_i m_i v_i^{n+1/2}` of each body after the last step n.
    pub final_momentum: Vec<f64>,
    /// Largest `|force|` over every step.
    pub max_force: f64,
}

/// Contact integrator: step, scheme and stability policy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactIntegrator {
    /// Time step.
    pub dt: f64,
    /// Contact scheme.
    pub scheme: ContactScheme,
    /// Refusal above the critical step (`allow_unstable`) and blow-up guard ratio.
    pub stability: StabilityPolicy,
}

impl ContactIntegrator {
    /// `scheme` with step `dt` and the default stability policy.
    pub fn new(dt: f64, scheme: ContactScheme) -> Self {
        Self {
            dt,
            scheme,
            stability: StabilityPolicy::default(),
        }
    }

    /// The critical steps, and an error if `dt` exceeds the applicable one (with the time plan's
    /// relative allowance [`crate::time_step::ROUNDING_SLACK`]) and unstable runs are not
    /// allowed.
    ///
    /// # Errors
    /// [`ContactError::Input`] for bad parameters, [`ContactError::Unstable`] above the limit.
    pub fn check_stability(
        &self,
        problem: &ContactProblem,
    ) -> Result<ContactCriticalStep, ContactError> {
        crate::mesh::positive("dt", self.dt)?;
        self.scheme.validate()?;
        let critical = ContactCriticalStep::of(problem, &self.scheme);
        if self.dt > critical.applicable * (1.0 + crate::time_step::ROUNDING_SLACK)
            && !self.stability.allow_unstable
        {
            return Err(ContactUnstableError {
                scheme: self.scheme.label(),
                dt: self.dt,
                dt_crit: critical.applicable,
                courant: critical.courant(self.dt),
                critical_courant: critical.critical_courant(),
                limit: critical.binding,
            }
            .into());
        }
        Ok(critical)
    }

    /// Integrate `steps` steps from the problem's initial state.
    ///
    /// # Errors
    /// [`ContactError::Input`] for bad parameters or a problem nothing excites,
    /// [`ContactError::Unstable`] above the critical step (unless allowed),
    /// [`ContactError::Diverged`] when an allowed unstable run blows up: the energy of the real
    /// masses, `kinetic + strain`, exceeds `blowup_energy_ratio` times the largest of its
    /// initial value, the external work and the loads' one-step impulse energy (as
    /// [`crate::central_difference`]'s guard). Contact is passive: a stable scheme can only keep
    /// or dissipate energy, so on an impact a ratio of ten already detects an unstable one.
    /// The penalty terms are left out: the spring energy of a first-step penetration
    /// `k_s (dt v0)^2/2` grows without bound with `k_s` even when the run is stable.
    pub fn run(
        &self,
        problem: &ContactProblem,
        steps: usize,
        request: &ContactRequest,
    ) -> Result<ContactRun, ContactError> {
        if request.history_every == 0 {
            return Err(InputError::Other("history_every must be at least 1".into()).into());
        }
        if let Some(&step) = request.profile_steps.iter().find(|&&s| s > steps) {
            return Err(InputError::Other(format!(
                "profile step {step} is after the last step {steps}"
            ))
            .into());
        }
        if !problem.is_excited() {
            return Err(InputError::Other(
                "nothing excites the contact problem: give a nonzero load or a nonzero initial displacement or velocity".into(),
            )
            .into());
        }
        let critical = self.check_stability(problem)?;
        let mut stepper = ContactStepper::new(problem, self.dt, self.scheme)?;
        let mut profile_steps = request.profile_steps.clone();
        profile_steps.sort_unstable();
        profile_steps.dedup();
        let mut next_profile = profile_steps.into_iter().peekable();
        let first = stepper.sample();
        let mut run = ContactRun {
            scheme: self.scheme,
            dt: self.dt,
            steps: 0,
            courant: critical.courant(self.dt),
            critical,
            history: vec![first],
            profiles: Vec::new(),
            impulse: first.impulse,
            initial_momentum: (0..problem.bodies().len())
                .map(|b| initial_momentum(&problem.bodies()[b]))
                .collect(),
            final_momentum: Vec::new(),
            max_force: first.force.abs(),
        };
        let mut profile = |stepper: &ContactStepper, run: &mut ContactRun, step: usize| {
            if next_profile.peek() == Some(&step) {
                next_profile.next();
                run.profiles.push(stepper.profile());
            }
        };
        profile(&stepper, &mut run, 0);
        let ratio = self.stability.blowup_energy_ratio;
        for step in 1..=steps {
            let sample = stepper.step();
            run.steps = step;
            run.impulse = sample.impulse;
            run.max_force = run.max_force.max(sample.force.abs());
            let reference = stepper.energy_reference();
            let mechanical = sample.kinetic + sample.strain;
            // NaN (a non-finite state) counts as diverged.
            let diverged = mechanical.is_nan() || mechanical > ratio * reference;
            if diverged || step.is_multiple_of(request.history_every) || step == steps {
                run.history.push(sample);
            }
            profile(&stepper, &mut run, step);
            if diverged {
                run.final_momentum = stepper.momenta();
                let error = DivergenceError {
                    step,
                    time: sample.time,
                    node: stepper.largest_displacement_node(),
                    energy_ratio: if mechanical.is_finite() {
                        mechanical / reference
                    } else {
                        f64::INFINITY
                    },
                    courant: run.courant,
                };
                return Err(ContactError::Diverged {
                    error,
                    partial: Box::new(run),
                });
            }
        }
        run.final_momentum = stepper.momenta();
        Ok(run)
    }
}

fn initial_momentum(model: &Model) -> f64 {
    model
        .nodal_mass()
        .iter()
        .zip(model.initial_velocity())
        .map(|(m, v)| m * v)
        .sum()
}

/// Loads and contact force of one body, as the kernel takes them.
#[derive(Debug, Clone)]
struct BodyForces {
    /// `(node, F)` sorted by node, each node once: the load nodes and the contact node(s).
    forces: Vec<(usize, f64)>,
    /// Slot of each model load in `forces`.
    load_slots: Vec<usize>,
    /// Load part of each slot at the previous level (for the trapezoidal work).
    previous: Vec<f64>,
}

impl BodyForces {
    fn new(model: &Model, contact_nodes: &[usize]) -> Self {
        let mut nodes: Vec<usize> = model
            .loads()
            .iter()
            .map(|l| l.node)
            .chain(contact_nodes.iter().copied())
            .collect();
        nodes.sort_unstable();
        nodes.dedup();
        let load_slots = model
            .loads()
            .iter()
            .map(|l| nodes.binary_search(&l.node).unwrap_or(0))
            .collect();
        let forces: Vec<(usize, f64)> = nodes.iter().map(|&n| (n, 0.0)).collect();
        let previous = vec![0.0; forces.len()];
        Self {
            forces,
            load_slots,
            previous,
        }
    }

    /// Fill the load part of every slot at time `t`.
    fn eval_loads(&mut self, model: &Model, t: f64) {
        self.forces.iter_mut().for_each(|f| f.1 = 0.0);
        for (load, &slot) in model.loads().iter().zip(&self.load_slots) {
            self.forces[slot].1 += load.force(t);
        }
    }

    fn slot_of(&self, node: usize) -> usize {
        self.forces
            .binary_search_by_key(&node, |f| f.0)
            .unwrap_or(0)
    }
}

/// A contact problem being integrated: the per-body lumped kernels plus the O(1) contact update.
/// [`ContactIntegrator::run`] drives it; benchmarks and tests may step it directly. It does not
/// check stability.
#[derive(Debug, Clone)]
pub struct ContactStepper<'a> {
    problem: &'a ContactProblem,
    scheme: ContactScheme,
    dt: f64,
    step: usize,
    kernels: Vec<LumpedCentralDifference>,
    bodies: Vec<BodyForces>,
    /// Slot of each contact node in its body's forces.
    contact_slots: [usize; 2],
    impulse: f64,
    work: f64,
    load_energy: f64,
    initial_mechanical: f64,
    current: ContactSample,
}

impl<'a> ContactStepper<'a> {
    /// Set up the start: `a^0 = M^-1 (F^0 - K u^0)`, the level-0 contact update, and
    /// `v^{1/2} = v^0 + (dt/2) a^0 + M^-1 N J^0`.
    ///
    /// # Errors
    /// [`InputError`] if `dt` is not positive and finite or the scheme's parameters are invalid.
    pub fn new(
        problem: &'a ContactProblem,
        dt: f64,
        scheme: ContactScheme,
    ) -> Result<Self, InputError> {
        crate::mesh::positive("dt", dt)?;
        scheme.validate()?;
        let nodes = problem.contact_nodes();
        let mut bodies = Vec::new();
        for (b, model) in problem.bodies().iter().enumerate() {
            let own: Vec<usize> = nodes
                .iter()
                .filter(|c| c.body == b)
                .map(|c| c.node)
                .collect();
            let mut forces = BodyForces::new(model, &own);
            forces.eval_loads(model, 0.0);
            forces.previous = forces.forces.iter().map(|f| f.1).collect();
            bodies.push(forces);
        }
        let mut contact_slots = [0; 2];
        for (i, c) in nodes.iter().enumerate() {
            contact_slots[i] = bodies[c.body].slot_of(c.node);
        }
        // Level 0.
        let mut input = LevelInput {
            weight: 0.5,
            displacement: [0.0; 2],
            velocity: [0.0; 2],
            residual: [0.0; 2],
        };
        for (i, c) in nodes.iter().enumerate() {
            let model = &problem.bodies()[c.body];
            let u = model.initial_displacement();
            input.displacement[i] = u[c.node];
            input.velocity[i] = model.initial_velocity()[c.node];
            input.residual[i] = model.external_force_at(c.node, 0.0)
                + c.element_stiffness * (u[c.neighbour] - u[c.node]);
        }
        let update = level_update(&scheme, problem, dt, &input);
        let mut kernels = Vec::new();
        let (mut kinetic, mut strain) = (0.0, 0.0);
        for (b, model) in problem.bodies().iter().enumerate() {
            let u0 = model.initial_displacement();
            let v0 = model.initial_velocity();
            let mut v_half: Vec<f64> = (0..u0.len())
                .map(|i| v0[i] + 0.5 * dt * model.acceleration_at(u0, i, 0.0))
                .collect();
            for c in nodes.iter().filter(|c| c.body == b) {
                v_half[c.node] += c.sign * update.impulse / c.mass;
            }
            kinetic += 0.5
                * model
                    .nodal_mass()
                    .iter()
                    .zip(v0)
                    .map(|(m, v)| m * v * v)
                    .sum::<f64>();
            strain += model.strain_energy(u0);
            kernels.push(LumpedCentralDifference::new(model, dt, u0, &v_half));
        }
        let relative_velocity: f64 = nodes
            .iter()
            .map(|c| c.sign * problem.bodies()[c.body].initial_velocity()[c.node])
            .sum();
        let load_energy = load_impulse_energy(problem, &bodies, dt);
        let mut stepper = Self {
            problem,
            scheme,
            dt,
            step: 0,
            kernels,
            bodies,
            contact_slots,
            impulse: 0.0,
            work: 0.0,
            load_energy,
            initial_mechanical: 0.0,
            current: ContactSample::default(),
        };
        stepper.current =
            stepper.sample_of(0, &update, [kinetic, kinetic], strain, relative_velocity);
        stepper.initial_mechanical = stepper.current.kinetic + stepper.current.strain;
        Ok(stepper)
    }

    /// Advance one step, `(u^{n-1}, v^{n-1/2}) -> (u^n, v^{n+1/2})`, and return the sample of
    /// level n.
    pub fn step(&mut self) -> ContactSample {
        let n = self.step + 1;
        let dt = self.dt;
        let t = n as f64 * dt;
        let problem = self.problem;
        let nodes = problem.contact_nodes();
        // u^n at the contact nodes and their neighbours, as the kernel will form it.
        let mut input = LevelInput {
            weight: 1.0,
            displacement: [0.0; 2],
            velocity: [0.0; 2],
            residual: [0.0; 2],
        };
        let mut neighbour = [0.0; 2];
        for (i, c) in nodes.iter().enumerate() {
            let kernel = &self.kernels[c.body];
            let (u, v) = (kernel.displacement(), kernel.half_step_velocity());
            input.displacement[i] = u[c.node] + dt * v[c.node];
            input.velocity[i] = v[c.node];
            neighbour[i] = u[c.neighbour] + dt * v[c.neighbour];
        }
        // Loads at t^n and their trapezoidal work over the step.
        for (b, model) in problem.bodies().iter().enumerate() {
            let forces = &mut self.bodies[b];
            if forces.load_slots.is_empty() {
                continue;
            }
            forces.eval_loads(model, t);
            let v = self.kernels[b].half_step_velocity();
            for (slot, f) in forces.forces.iter().enumerate() {
                self.work += 0.5 * (f.1 + forces.previous[slot]) * dt * v[f.0];
                forces.previous[slot] = f.1;
            }
        }
        for (i, c) in nodes.iter().enumerate() {
            let load = self.bodies[c.body].forces[self.contact_slots[i]].1;
            input.residual[i] = load + c.element_stiffness * (neighbour[i] - input.displacement[i]);
        }
        let update = level_update(&self.scheme, problem, dt, &input);
        let relative_before: f64 = nodes
            .iter()
            .enumerate()
            .map(|(i, c)| c.sign * input.velocity[i])
            .sum();
        for (i, c) in nodes.iter().enumerate() {
            self.bodies[c.body].forces[self.contact_slots[i]].1 += c.sign * update.impulse / dt;
        }
        let (mut kinetic, mut staggered, mut strain) = (0.0, 0.0, 0.0);
        for (kernel, forces) in self.kernels.iter_mut().zip(&self.bodies) {
            let e = kernel.step_with_energy(&forces.forces);
            kinetic += e.kinetic;
            staggered += e.kinetic_staggered;
            strain += e.strain;
        }
        for (i, c) in nodes.iter().enumerate() {
            // Remove the contact part so that the next level starts from the loads alone.
            self.bodies[c.body].forces[self.contact_slots[i]].1 -= c.sign * update.impulse / dt;
        }
        let relative_after: f64 = nodes
            .iter()
            .map(|c| c.sign * self.kernels[c.body].half_step_velocity()[c.node])
            .sum();
        self.load_energy = self
            .load_energy
            .max(load_impulse_energy(problem, &self.bodies, dt));
        self.step = n;
        self.current = self.sample_of(
            n,
            &update,
            [kinetic, staggered],
            strain,
            0.5 * (relative_before + relative_after),
        );
        self.current
    }

    fn sample_of(
        &mut self,
        step: usize,
        update: &LevelUpdate,
        [kinetic, kinetic_staggered]: [f64; 2],
        strain: f64,
        relative_velocity: f64,
    ) -> ContactSample {
        self.impulse += update.impulse;
        let penalty = self.scheme.penalty();
        let penetration = (-update.gap).max(0.0);
        let penalty_spring = 0.5 * penalty.stiffness * penetration * penetration;
        let penalty_kinetic = if update.active && matches!(self.scheme, ContactScheme::Bipenalty(_))
        {
            0.5 * penalty.mass * relative_velocity * relative_velocity
        } else {
            0.0
        };
        ContactSample {
            step,
            time: step as f64 * self.dt,
            force: update.force,
            penalty_force: penalty.stiffness * penetration,
            gap: update.gap,
            active: update.active,
            impulse: self.impulse,
            kinetic,
            kinetic_staggered,
            strain,
            penalty_spring,
            penalty_kinetic,
            total: kinetic + strain + penalty_spring + penalty_kinetic,
        }
    }

    /// The sample of the current level.
    pub fn sample(&self) -> ContactSample {
        self.current
    }

    /// Current step index n (state `u^n`, `v^{n+1/2}`).
    pub fn step_index(&self) -> usize {
        self.step
    }

    /// The time step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Displacements `u^n` of body `body`.
    pub fn displacement(&self, body: usize) -> &[f64] {
        self.kernels[body].displacement()
    }

    /// Half-step velocities `v^{n+1/2}` of body `body`.
    pub fn half_step_velocity(&self, body: usize) -> &[f64] {
        self.kernels[body].half_step_velocity()
    }

    /// Momentum `sum_i m_i v_i^{n+1/2}` of each body (O(N)).
    pub fn momenta(&self) -> Vec<f64> {
        self.problem
            .bodies()
            .iter()
            .zip(&self.kernels)
            .map(|(model, kernel)| {
                model
                    .nodal_mass()
                    .iter()
                    .zip(kernel.half_step_velocity())
                    .map(|(m, v)| m * v)
                    .sum()
            })
            .collect()
    }

    /// Element stresses of every body at the current level (O(N)).
    pub fn profile(&self) -> ContactProfile {
        ContactProfile {
            step: self.step,
            time: self.step as f64 * self.dt,
            stress: self
                .problem
                .bodies()
                .iter()
                .zip(&self.kernels)
                .map(|(model, kernel)| model.element_stress(kernel.displacement()))
                .collect(),
        }
    }

    /// The blow-up guard's reference: the largest of the initial `kinetic + strain`, `|W|` of the
    /// loads so far and their one-step impulse energy `sum dt^2 F^2/(8 m)`.
    pub fn energy_reference(&self) -> f64 {
        self.initial_mechanical
            .max(self.work.abs())
            .max(self.load_energy)
            .max(f64::MIN_POSITIVE)
    }

    /// Global node index (bodies numbered one after the other) with the largest `|u|`, NaN first.
    fn largest_displacement_node(&self) -> usize {
        let mut best = (0, -1.0_f64);
        let mut offset = 0;
        for kernel in &self.kernels {
            let u = kernel.displacement();
            for (i, &x) in u.iter().enumerate() {
                let size = if x.is_nan() { f64::INFINITY } else { x.abs() };
                if size > best.1 {
                    best = (offset + i, size);
                }
            }
            offset += u.len();
        }
        best.0
    }
}

/// `sum_j dt^2 F_j^2/(8 m_j)` over the load part of the current forces.
fn load_impulse_energy(problem: &ContactProblem, bodies: &[BodyForces], dt: f64) -> f64 {
    problem
        .bodies()
        .iter()
        .zip(bodies)
        .map(|(model, forces)| {
            forces
                .forces
                .iter()
                .map(|&(node, f)| 0.125 * dt * dt * f * f * model.inverse_mass()[node])
                .sum::<f64>()
        })
        .sum()
}
