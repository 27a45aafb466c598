//! The Noh-Bathe explicit scheme (G. Noh, K.J. Bathe, "An explicit time integration scheme for
//! the analysis of wave propagations", Computers & Structures 129 (2013) 178-193), written
//! against courant's public integrator interface ([`crate::integrator`]) as any contributor's
//! scheme would be: this file and one line in [`crate::schemes::REGISTRY`].
//!
//! # The step
//!
//! Two sub-steps with splitting parameter `p` (`p = 0.54` recommended), `h1 = p dt`,
//! `h2 = (1 - p) dt`. The equations are those of OpenSees' `ExplicitBathe.cpp` (and of suanPan,
//! PlatypusBytes and MGroup, which agree line for line; the paper's own text was not available
//! to us):
//!
//! ```text
//!   q1 = (1 - 2p)/(2p(1 - p)),   q2 = 1/2 - p q1,   q0 = -q1 - q2 + 1/2
//!   sub-step 1 (t -> t + p dt), a central-difference (velocity Verlet) step of h1:
//!     u_p = u + h1 v + h1^2/2 a,     a_p = M^-1 (F(t + p dt) - K u_p),
//!     v_p = v + h1/2 (a + a_p)
//!   sub-step 2 (t + p dt -> t + dt):
//!     u_n = u_p + h2 v_p + h2^2/2 a_p,     a_n = M^-1 (F(t + dt) - K u_n),
//!     v_n = v_p + h2 (q0 a + (1/2 + q1) a_p + q2 a_n)
//! ```
//!
//! The weight on `a_p` is `1/2 + q1`, not `q1`: the three weights sum to 1 (`q0 + q1 + q2 = 1/2`).
//! At `p = 1/2` (`q0 = q1 = 0`, `q2 = 1/2`) the step is exactly two central-difference half
//! steps. Start: `a^0 = M^-1 (F(0) - K u^0)` (the common start of the time loop). Cost: two
//! internal-force evaluations `K u` and two mass solves per step (each a product with `1/m_i`
//! for the lumped mass); every mass kind runs.
//!
//! # Analysis (derived for courant and checked by `solver/tests/noh_bathe_*.rs`)
//!
//! For `u'' + omega^2 u = 0`, `Omega = omega dt`, the step maps `(u, dt v)` by
//!
//! ```text
//!   A11 = A22 = 1 - Omega^2/2 + p^2 (1 - p) Omega^4/4
//!   A12       = 1 - p (1 - p) Omega^2/2
//!   A21       = -Omega^2 + p (2 - p) Omega^4/4 - p^3 (1 - p) Omega^6/8
//!   det A     = 1 - (1 - p)^2 (2p - 1) Omega^4/4        (< 1 for p > 1/2: dissipative)
//! ```
//!
//! - **Stability**: spectral radius <= 1 for `Omega <= Omega_crit = 2/sqrt((1 - p)(3p - 1))`,
//!   `1/2 <= p <= 3/4` (an eigenvalue crosses +1 there), so on a model the exact limit is
//!   `dt_crit = Omega_crit/omega_max`: `Omega_crit/2 = 1.8725` times central difference's
//!   `2/omega_max` at `p = 0.54`. The spectral radius returns to 1 at the limit; the strongest
//!   damping is at the bifurcation `Omega = 2/p` (radius `(p^2 - 4p + 2)/p^2`, 0.451 at
//!   `p = 0.54`). Above `p = 3/4` the limit is another root (an eigenvalue at -1); this file
//!   takes `p` in `[1/2, 3/4]` only.
//! - **Order**: second order in `u` and `v` (local error `(1/6 - p(1 - p)/2) Omega^3`); period
//!   error `-(3p - 2)^2 Omega^2/24` (central difference: `-Omega^2/24`).
//! - **Energy**: the physical energy is not monotone (the amplification matrix is not normal);
//!   the modified energy `E_mod = 1/2 v M v + 1/2 u K u - (p dt)^2/8 a M a` decays by `det A` per
//!   mode and step in free vibration (`A^T Q A = det(A) Q` with `Q = diag(Omega^2 (1 -
//!   p^2 Omega^2/4), 1)`), so it is the balance energy here: `T* = T - (p dt)^2/8 a M a`, and
//!   the balance reports what the scheme dissipates.

use crate::analysis::stability::CriticalStep;
use crate::error::{InputError, RunError};
use crate::integrator::{
    InitialState, Integrator, LimitKind, Parameter, ParameterDefault, RunSetup, Scheme,
    SchemeEntry, SchemeLimit, Start, time_loop,
};
use crate::kernels::energy::StepEnergy;
use crate::kernels::noh_bathe::{LumpedNohBathe, NohBatheArrays};
use crate::mass::{MassKind, MassOperator, MassWork};
use crate::model::Model;
use crate::output::RunOutput;
use std::sync::Arc;

/// The registry entry.
pub const ENTRY: SchemeEntry = SchemeEntry {
    name: "noh-bathe",
    aliases: &[],
    summary: "Noh-Bathe explicit two-sub-step scheme, dissipates the unresolved modes; 2 K u per step",
    source: "Noh & Bathe, Comput. Struct. 129 (2013) 178-193 (equations as OpenSees ExplicitBathe); \
             amplification matrix, limit 2/sqrt((1-p)(3p-1))/omega_max and modified energy derived here",
    masses: "lmm, cmm, amm(beta), rmm(beta)",
    parameters: &[Parameter {
        key: "p",
        default: ParameterDefault::Number(0.54),
        rule: "must lie in [0.5, 0.75]",
        meaning: "splitting parameter: the first sub-step is p dt (0.5 is two CD half steps; below 1/2 \
                  every mode grows; above 3/4 the limit is another root, not implemented)",
    }],
    build: |values| {
        Ok(Arc::new(NohBatheScheme {
            p: values.number_in("p", 0.5, 0.75)?,
        }) as Arc<dyn Scheme>)
    },
};

/// The Noh-Bathe scheme with splitting parameter `p`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NohBatheScheme {
    /// Splitting parameter, in `[1/2, 3/4]`.
    pub p: f64,
}

impl NohBatheScheme {
    /// `Omega_crit = omega_max dt_crit = 2/sqrt((1 - p)(3p - 1))` for `1/2 <= p <= 3/4`.
    pub fn critical_omega(p: f64) -> f64 {
        2.0 / ((1.0 - p) * (3.0 * p - 1.0)).sqrt()
    }

    /// The weights `(q0, 1/2 + q1, q2)` of `a`, `a_p`, `a_n` in the last velocity update (they
    /// sum to 1).
    pub fn velocity_weights(p: f64) -> [f64; 3] {
        let q1 = (1.0 - 2.0 * p) / (2.0 * p * (1.0 - p));
        let q2 = 0.5 - p * q1;
        let q0 = -q1 - q2 + 0.5;
        [q0, 0.5 + q1, q2]
    }

    fn check(p: f64) -> Result<(), InputError> {
        if (0.5..=0.75).contains(&p) {
            Ok(())
        } else {
            Err(InputError::Parameter {
                field: "noh-bathe p",
                value: p,
                rule: "must lie in [0.5, 0.75]",
            })
        }
    }
}

impl Scheme for NohBatheScheme {
    fn name(&self) -> &'static str {
        ENTRY.name
    }

    fn label(&self) -> String {
        format!("noh-bathe p={}", self.p)
    }

    fn force_evaluations(&self) -> usize {
        2
    }

    fn check_settings(&self, _mass: MassKind, start: Start) -> Result<(), InputError> {
        Self::check(self.p)?;
        match start {
            Start::HalfStep => Ok(()),
            Start::ThreeLevel => Err(InputError::StartNotDefined {
                scheme: "noh-bathe",
                own: "a^0 = M^-1 (F(0) - K u^0)",
                start: "three-level",
                whose: "central difference's",
            }),
        }
    }

    fn limit(&self, _model: &Model, critical: &CriticalStep) -> SchemeLimit {
        SchemeLimit {
            dt: 0.5 * Self::critical_omega(self.p) * critical.exact,
            rule: "Omega_crit(p)/omega_max",
            kind: LimitKind::Exact,
        }
    }

    fn run(&self, setup: RunSetup<'_>) -> Result<RunOutput, RunError> {
        time_loop::run::<NohBatheStepper>(&self.p, setup)
    }
}

/// The Noh-Bathe stepper: state `u^n`, `v^n`, `a^n`.
#[derive(Debug, Clone)]
pub struct NohBatheStepper {
    dt: f64,
    /// `p dt`.
    h1: f64,
    /// `a0..a7` of the update (module docs): `h1, h1^2/2, h1/2, h2, h2^2/2, h2 w0, h2 w1, h2 w2`.
    c: [f64; 8],
    mass: MassOperator,
    /// The work arrays of its windowed solves, if it has them (a step allocates nothing).
    work: MassWork,
    /// The one-sweep step of the lumped mass (`None` for the matrix masses, which step pass
    /// by pass through the arrays below, empty for the lumped mass).
    lumped: Option<LumpedNohBathe>,
    /// Element stiffnesses padded with a zero at both ends (length N + 2 for N + 1 nodes).
    stiffness: Vec<f64>,
    u: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    a_mid: Vec<f64>,
    a_next: Vec<f64>,
    residual: Vec<f64>,
    /// Element forces padded with a zero at both ends.
    element_force: Vec<f64>,
    /// `M v` (matrix masses only).
    scratch: Vec<f64>,
    /// `(node, F(t + p dt))` of the loaded nodes.
    mid_forces: Vec<(usize, f64)>,
    balance0: f64,
}

impl NohBatheStepper {
    /// `r = F - K u` into `self.residual` (element forces padded, branch-free); returns the
    /// strain energy `1/2 u K u`.
    #[inline]
    fn residual_of_displacement(&mut self, forces: &[(usize, f64)]) -> f64 {
        let n = self.u.len();
        let mut strain = 0.0;
        for e in 1..n {
            let du = self.u[e] - self.u[e - 1];
            let force = self.stiffness[e] * du;
            self.element_force[e] = force;
            strain += force * du;
        }
        for (r, pair) in self.residual.iter_mut().zip(self.element_force.windows(2)) {
            *r = pair[1] - pair[0];
        }
        for &(node, f) in forces {
            self.residual[node] += f;
        }
        0.5 * strain
    }
}

impl Integrator for NohBatheStepper {
    type Parameters = f64;

    fn start(&p: &f64, state: InitialState<'_>) -> Result<Self, InputError> {
        NohBatheScheme::check(p)?;
        let (dt, n) = (state.dt, state.displacement.len());
        let (h1, h2) = (p * dt, (1.0 - p) * dt);
        let [w0, w1, w2] = NohBatheScheme::velocity_weights(p);
        let mut stiffness = vec![0.0; n + 1];
        stiffness[1..n].copy_from_slice(state.model.stiffness());
        let mut load_nodes: Vec<usize> = state.model.loads().iter().map(|l| l.node).collect();
        load_nodes.sort_unstable();
        load_nodes.dedup();
        let c = [
            h1,
            0.5 * h1 * h1,
            0.5 * h1,
            h2,
            0.5 * h2 * h2,
            h2 * w0,
            h2 * w1,
            h2 * w2,
        ];
        let lumped = matches!(state.mass, MassOperator::Diagonal { .. });
        // The pass-by-pass arrays, for the matrix masses only.
        let scratch = |len: usize| if lumped { Vec::new() } else { vec![0.0; len] };
        let impulse: f64 = state
            .acceleration
            .iter()
            .zip(state.residual)
            .map(|(a, r)| a * r)
            .sum();
        Ok(Self {
            dt,
            h1,
            c,
            work: state.mass.work(),
            mass: state.mass,
            lumped: lumped.then(|| LumpedNohBathe::new(c)),
            stiffness,
            u: state.displacement.to_vec(),
            v: state.velocity.to_vec(),
            a: state.acceleration.to_vec(),
            a_mid: scratch(n),
            a_next: scratch(n),
            residual: scratch(n),
            element_force: scratch(n + 1),
            scratch: scratch(n),
            mid_forces: load_nodes.iter().map(|&i| (i, 0.0)).collect(),
            balance0: state.kinetic - 0.125 * h1 * h1 * impulse,
        })
    }

    fn dt(&self) -> f64 {
        self.dt
    }

    fn displacement(&self) -> &[f64] {
        &self.u
    }

    fn velocity_and_acceleration_at(&self, _model: &Model, i: usize, _t: f64) -> (f64, f64) {
        (self.v[i], self.a[i])
    }

    fn step(&mut self, model: &Model, t: f64, forces: &[(usize, f64)]) -> StepEnergy {
        if let (Some(kernel), MassOperator::Diagonal { inverse, mass }) =
            (&mut self.lumped, &self.mass)
        {
            for f in self.mid_forces.iter_mut() {
                f.1 = model.external_force_at(f.0, t + self.h1);
            }
            let arrays = NohBatheArrays {
                u: &mut self.u,
                v: &mut self.v,
                a: &mut self.a,
                stiffness: &self.stiffness,
                inverse_mass: inverse,
                mass,
            };
            let sums = kernel.step(arrays, &self.mid_forces, forces);
            let kinetic = 0.5 * sums.twice_kinetic;
            return StepEnergy {
                kinetic_staggered: kinetic - 0.125 * self.h1 * self.h1 * sums.impulse,
                kinetic,
                strain: 0.5 * sums.twice_strain,
            };
        }
        let [c0, c1, c2, c3, c4, c5, c6, c7] = self.c;
        // Sub-step 1: u <- u_p, a_p = M^-1 (F(t + p dt) - K u_p).
        for ((u, v), a) in self.u.iter_mut().zip(&self.v).zip(&self.a) {
            *u += c0 * v + c1 * a;
        }
        let mut mid = std::mem::take(&mut self.mid_forces);
        for f in mid.iter_mut() {
            f.1 = model.external_force_at(f.0, t + self.h1);
        }
        self.residual_of_displacement(&mid);
        self.mid_forces = mid;
        self.mass
            .apply_inverse_with(&self.residual, &mut self.a_mid, &mut self.work);
        // v <- v_p; sub-step 2: u <- u_n, a_n = M^-1 (F(t + dt) - K u_n).
        for (((u, v), a), am) in self
            .u
            .iter_mut()
            .zip(self.v.iter_mut())
            .zip(&self.a)
            .zip(&self.a_mid)
        {
            *v += c2 * (a + am);
            *u += c3 * *v + c4 * am;
        }
        let strain = self.residual_of_displacement(forces);
        self.mass
            .apply_inverse_with(&self.residual, &mut self.a_next, &mut self.work);
        for (((v, a), am), an) in self
            .v
            .iter_mut()
            .zip(&self.a)
            .zip(&self.a_mid)
            .zip(&self.a_next)
        {
            *v += c5 * a + c6 * am + c7 * an;
        }
        std::mem::swap(&mut self.a, &mut self.a_next);
        // Energies at t + dt: T = 1/2 v M v, a M a = a . r (M a = r on the free nodes, a = 0 at
        // fixed ones).
        let twice_kinetic = match &self.mass {
            MassOperator::Diagonal { mass, .. } => dot(&self.v, mass, Some(&self.v)),
            operator => {
                operator.apply_with(&self.v, &mut self.scratch, &mut self.work);
                dot(&self.v, &self.scratch, None)
            }
        };
        let impulse = dot(&self.a, &self.residual, None);
        let kinetic = 0.5 * twice_kinetic;
        StepEnergy {
            kinetic_staggered: kinetic - 0.125 * self.h1 * self.h1 * impulse,
            kinetic,
            strain,
        }
    }

    fn start_energy(&self) -> f64 {
        self.balance0
    }
}

/// `sum_i x_i y_i (z_i)` in four partial sums (a fixed order: deterministic).
#[inline]
fn dot(x: &[f64], y: &[f64], z: Option<&[f64]>) -> f64 {
    let mut lanes = [0.0; 4];
    for i in 0..x.len() {
        let term = x[i] * y[i] * z.map_or(1.0, |z| z[i]);
        lanes[i % 4] += term;
    }
    (lanes[0] + lanes[1]) + (lanes[2] + lanes[3])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::{graded_seed_bar, smooth_half_velocity};
    use crate::integrator::Start;

    /// The one-sweep lumped step (`kernels::noh_bathe`) against the pass-by-pass step it
    /// replaces (the step of the module docs, one array sweep per operation), on the graded seed
    /// bar under a load at node 0 from a smooth moving start: the same bits in `u`, `v`, `a` and
    /// every energy, step after step, on bars of one chunk and of several (with a partial last).
    #[test]
    fn the_one_sweep_lumped_step_gives_the_pass_by_pass_bits() {
        for n in [7, 100, 1000, 1537] {
            let model = graded_seed_bar(n).unwrap();
            let dt = 0.5 * model.bar().stiffest_element().1;
            let u0 = vec![0.0; n + 1];
            let v0 = smooth_half_velocity(n);
            let r0: Vec<f64> = (0..=n).map(|i| 1e-3 * (i as f64).sin()).collect();
            let mass = MassOperator::new(&model, MassKind::Lumped).unwrap();
            let mut a0 = vec![0.0; n + 1];
            mass.apply_inverse(&r0, &mut a0);
            let state = || InitialState {
                model: &model,
                dt,
                displacement: &u0,
                velocity: &v0,
                acceleration: &a0,
                residual: &r0,
                kinetic: 0.0,
                start: Start::HalfStep,
                allow_unstable: false,
                mass: mass.clone(),
                threads: 1,
            };
            let mut fused = NohBatheStepper::start(&0.54, state()).unwrap();
            let mut passes = NohBatheStepper::start(&0.54, state()).unwrap();
            assert!(fused.lumped.is_some());
            passes.lumped = None;
            for array in [
                &mut passes.a_mid,
                &mut passes.a_next,
                &mut passes.residual,
                &mut passes.scratch,
            ] {
                *array = vec![0.0; n + 1];
            }
            passes.element_force = vec![0.0; n + 2];
            let bits = |x: &[f64]| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            for step in 0..40 {
                let t = step as f64 * dt;
                let forces = [(0, -1.0 - 0.01 * step as f64)];
                let (e1, e2) = (
                    fused.step(&model, t, &forces),
                    passes.step(&model, t, &forces),
                );
                let energies =
                    |e: StepEnergy| [e.kinetic, e.kinetic_staggered, e.strain].map(f64::to_bits);
                assert_eq!(energies(e1), energies(e2), "energies, n = {n}, step {step}");
                assert_eq!(bits(&fused.u), bits(&passes.u), "u, n = {n}, step {step}");
                assert_eq!(bits(&fused.v), bits(&passes.v), "v, n = {n}, step {step}");
                assert_eq!(bits(&fused.a), bits(&passes.a), "a, n = {n}, step {step}");
            }
        }
    }
}
