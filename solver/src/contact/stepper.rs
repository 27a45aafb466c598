//! The contact time loop's state: the per-body bulk steppers (central difference with the lumped
//! mass, the registry's `cd` stepper, stepped through the [`Integrator`] interface), their loads
//! and the O(1) contact update of every level (module docs of [`crate::contact`], "The level
//! update"), with the energies and momenta a run records. It does not check stability or record
//! anything.

use super::output::{ContactProfile, ContactSample};
use super::problem::ContactProblem;
use super::scheme::{ContactScheme, LevelInput, LevelUpdate, level_update};
use crate::error::InputError;
use crate::integrator::Integrator;
use crate::kernels::lumped::kernel::LumpedStep;
use crate::model::Model;
use crate::schemes::central_difference::LumpedStepper;

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
/// [`ContactIntegrator::run`](super::ContactIntegrator::run) drives it; benchmarks and tests may
/// step it directly. It does not check stability.
#[derive(Debug, Clone)]
pub struct ContactStepper<'a> {
    problem: &'a ContactProblem,
    scheme: ContactScheme,
    dt: f64,
    step: usize,
    kernels: Vec<LumpedStepper>,
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
        crate::model::mesh::positive("dt", dt)?;
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
            kernels.push(LumpedStepper::from_kernel(LumpedStep::new(
                model, dt, u0, &v_half,
            )));
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
        for ((kernel, forces), model) in self
            .kernels
            .iter_mut()
            .zip(&self.bodies)
            .zip(problem.bodies())
        {
            // The contact momentum rides on the loads at t^n: the bulk step is cd's.
            let e = kernel.step(model, t - dt, &forces.forces);
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
    pub(super) fn largest_displacement_node(&self) -> usize {
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
