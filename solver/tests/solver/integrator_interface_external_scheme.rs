//! Source of truth: central difference written in its full-step (velocity Verlet) form, which is
//! algebraically the half-step form of the seed's eqs. 2-4 (methods.md §2), so the two agree to
//! round-off; and the exact critical step `2/omega_max` (Hughes 2000, §9.3).
//!
//! ```text
//!   this file:  impl Integrator for Verlet  +  impl Scheme for VerletScheme (limit: Measured)
//!        |                                        |
//!        +---> courant_solver::integrator::time_loop::run  <---  Integration::run
//! ```
//!
//! Proves: a scheme written outside the crate, against the public interface alone (no registry
//! entry needed to run it; no block stepping, an opt-in capability, `BlockStepper`, it does not
//! take), runs through the shared time loop with its outputs, energy balance and guard: its
//! profiles and histories equal the registered `cd` to 1e-12 of the peak, its balance (it reports
//! `T* = T`, having no energy of its own) is its full-step energy error; a scheme without a
//! stability analysis declares `LimitKind::Measured`, the interface measures its critical step
//! (within `MEASURED_PRECISION` below `2/omega_max`) and refuses a step above it naming the
//! measured limit.

use courant_solver::bench::graded_seed_bar;
use courant_solver::integrator::StepEnergy;
use courant_solver::integrator::{
    InitialState, Integrator, LimitKind, MEASURED_PRECISION, RunSetup, SchemeLimit,
    measure_critical_step, time_loop,
};
use courant_solver::{
    CentralDifference, CriticalStep, InputError, Integration, MassKind, MassOperator, Model,
    OutputRequest, RunError, RunOutput, Scheme, Start,
};
use std::sync::Arc;

/// Velocity Verlet: `u+ = u + dt v + dt^2/2 a`, `a+ = M^-1 (F+ - K u+)`, `v+ = v + dt/2 (a + a+)`.
struct Verlet {
    dt: f64,
    mass: MassOperator,
    stiffness: Vec<f64>,
    u: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    r: Vec<f64>,
    a_next: Vec<f64>,
    mv: Vec<f64>,
    kinetic0: f64,
}

impl Integrator for Verlet {
    type Parameters = ();

    fn start(_: &(), state: InitialState<'_>) -> Result<Self, InputError> {
        Ok(Self {
            dt: state.dt,
            stiffness: state.model.stiffness().to_vec(),
            u: state.displacement.to_vec(),
            v: state.velocity.to_vec(),
            a: state.acceleration.to_vec(),
            r: vec![0.0; state.displacement.len()],
            a_next: vec![0.0; state.displacement.len()],
            mv: vec![0.0; state.displacement.len()],
            kinetic0: state.kinetic,
            mass: state.mass,
        })
    }

    fn dt(&self) -> f64 {
        self.dt
    }

    fn displacement(&self) -> &[f64] {
        &self.u
    }

    fn velocity_and_acceleration_at(&self, _: &Model, i: usize, _: f64) -> (f64, f64) {
        (self.v[i], self.a[i])
    }

    fn step(&mut self, _: &Model, _: f64, forces: &[(usize, f64)]) -> StepEnergy {
        let dt = self.dt;
        for i in 0..self.u.len() {
            self.u[i] += dt * self.v[i] + 0.5 * dt * dt * self.a[i];
        }
        self.r.iter_mut().for_each(|r| *r = 0.0);
        let mut strain = 0.0;
        for (e, k) in self.stiffness.iter().enumerate() {
            let force = k * (self.u[e + 1] - self.u[e]);
            self.r[e] += force;
            self.r[e + 1] -= force;
            strain += 0.5 * force * (self.u[e + 1] - self.u[e]);
        }
        for &(node, f) in forces {
            self.r[node] += f;
        }
        self.mass.apply_inverse(&self.r, &mut self.a_next);
        for i in 0..self.v.len() {
            self.v[i] += 0.5 * dt * (self.a[i] + self.a_next[i]);
        }
        std::mem::swap(&mut self.a, &mut self.a_next);
        self.mass.apply(&self.v, &mut self.mv);
        let kinetic: f64 = 0.5
            * self
                .v
                .iter()
                .zip(&self.mv)
                .map(|(v, mv)| v * mv)
                .sum::<f64>();
        // No energy of its own: the balance measures T + U - W.
        StepEnergy {
            kinetic_staggered: kinetic,
            kinetic,
            strain,
        }
    }

    fn start_energy(&self) -> f64 {
        self.kinetic0
    }
}

/// The contributor's scheme: no stability analysis, so its limit is measured.
#[derive(Debug)]
struct VerletScheme;

impl Scheme for VerletScheme {
    fn name(&self) -> &'static str {
        "verlet"
    }
    fn label(&self) -> String {
        "verlet".into()
    }
    fn force_evaluations(&self) -> usize {
        1
    }
    fn check_settings(&self, _: MassKind, _: Start) -> Result<(), InputError> {
        Ok(())
    }
    fn limit(&self, model: &Model, critical: &CriticalStep) -> SchemeLimit {
        let scheme: Arc<dyn Scheme> = Arc::new(VerletScheme);
        SchemeLimit {
            // Guessed well below the limit, so that the search brackets and bisects.
            dt: measure_critical_step(&scheme, model, critical.mass, 0.3 * critical.exact)
                .expect("a measurable scheme"),
            rule: "measured",
            kind: LimitKind::Measured,
        }
    }
    fn run(&self, setup: RunSetup<'_>) -> Result<RunOutput, RunError> {
        time_loop::run::<Verlet>(&(), setup)
    }
}

#[test]
fn a_scheme_written_outside_the_crate_runs_through_the_shared_loop() {
    let model = graded_seed_bar(24).unwrap();
    let dt = 0.5 * model.bar().stiffest_element().1;
    let steps = 300;
    let request = OutputRequest {
        profile_steps: vec![100, 200, 300],
        history_nodes: vec![0, 12],
        ..OutputRequest::default()
    };
    let verlet = Integration::new(dt, Arc::new(VerletScheme))
        .run(&model, steps, &request)
        .unwrap();
    let cd = CentralDifference::new(dt)
        .run(&model, steps, &request)
        .unwrap();
    let peak = cd
        .profiles
        .iter()
        .flat_map(|p| &p.stress)
        .fold(0.0_f64, |m, s| m.max(s.abs()));
    assert_eq!(verlet.profiles.len(), cd.profiles.len());
    assert!(!cd.profiles.is_empty());
    assert_eq!(verlet.histories.len(), cd.histories.len());
    assert!(!cd.histories.is_empty());
    for (a, b) in verlet.profiles.iter().zip(&cd.profiles) {
        assert_eq!(a.step, b.step);
        for (x, y) in a.stress.iter().zip(&b.stress) {
            assert!((x - y).abs() <= 1e-12 * peak, "step {}: {x} vs {y}", a.step);
        }
    }
    for (a, b) in verlet.histories.iter().zip(&cd.histories) {
        for (x, y) in a.samples.iter().zip(&b.samples) {
            assert!(
                (x.velocity - y.velocity).abs() <= 1e-12 * peak,
                "{x:?} vs {y:?}"
            );
        }
    }
    // Its balance is the full-step energy error of CD, dt^2/8 a M a: not round-off.
    assert!(verlet.energy.relative_balance_error() > 1e-6);
    assert!(cd.energy.relative_balance_error() < 1e-13);
}

#[test]
fn a_scheme_without_analysis_gets_a_measured_limit_and_the_refusal_names_it() {
    let model = graded_seed_bar(16).unwrap();
    let critical = CriticalStep::of(
        &model,
        MassKind::Lumped,
        &MassOperator::new(&model, MassKind::Lumped).unwrap(),
    )
    .unwrap();
    let limit = VerletScheme.limit(&model, &critical);
    let ratio = limit.dt / critical.exact;
    assert!(
        (1.0 - MEASURED_PRECISION..=1.0 + 1e-12).contains(&ratio),
        "{ratio}"
    );
    match Integration::new(1.01 * critical.exact, Arc::new(VerletScheme)).run(
        &model,
        10,
        &OutputRequest::default(),
    ) {
        Err(RunError::Unstable(e)) => assert_eq!(e.limit, "measured"),
        other => panic!("not refused: {other:?}"),
    }
}
