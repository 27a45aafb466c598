//! Park's scheme with local time stepping **as the seed prints it** (seed §3.1, eqs. 8 and 13),
//! to show what its two misprints break beside the corrected scheme (`park-lts`, methods.md §6).
//! Not a scheme to use: its registry entry exists so that scenes can run the printed equations.
//!
//! Per step, element by element (methods.md §6, steps 1-4), with the misprints switched by
//! `misprint`:
//!
//! ```text
//!   eq. 8 as printed:  u_fs,e = u_e^n + dt_e v_e^n + dt_e^2 (beta1 a_e^n + beta2 a~_e)   (corrected: dt v_e^n)
//!   eq. 13 as printed: v^{n+1} = v^n + (a^n + a^{n+1})/2                                (corrected: (dt/2)(a^n + a^{n+1}))
//! ```
//!
//! `misprint = "none"` is the corrected scheme, element by element (the same mathematics as
//! `park-lts`'s folded kernel, unoptimised). Limit, start and energy as `park-lts`: element
//! acceleration variant `free`, `alpha_e = dt/dt_e <= 1`, lumped mass only, O(N) per step.

use super::central_difference::half_step_start;
use crate::analysis::stability::CriticalStep;
use crate::error::{InputError, RunError};
use crate::integrator::{
    InitialState, Integrator, LimitKind, Parameter, ParameterDefault, ParameterError,
    ParameterValues, RunSetup, Scheme, SchemeEntry, SchemeLimit, Start, lumped_only, time_loop,
};
use crate::kernels::energy::StepEnergy;
use crate::kernels::park::{ParkOptions, ParkStep};
use crate::mass::MassKind;
use crate::model::Model;
use crate::output::RunOutput;
use std::sync::Arc;

const PARAMETERS: &[Parameter] = &[
    Parameter {
        key: "theta",
        default: ParameterDefault::Number(0.5),
        rule: "must lie in [0, 1]",
        meaning: "blend of the pulled-back and CD predictions, as in park-lts",
    },
    Parameter {
        key: "misprint",
        default: ParameterDefault::Text("both"),
        rule: "must be one of none, eq8, eq13, both",
        meaning: "which of the seed's printed equations replace the corrected ones (eq. 8: dt_e v in the pull-back; eq. 13: the velocity update without dt)",
    },
];

/// The registry entry.
pub const ENTRY: SchemeEntry = SchemeEntry {
    name: "park-printed",
    aliases: &[],
    summary: "Park's scheme with local stepping as the seed prints eqs. 8 and 13 (misprints; to show what they break), element by element",
    source: "Kolman et al. (seed) §3.1, eqs. 8 and 13 as printed; corrected forms in methods.md §6",
    masses: "lmm",
    parameters: PARAMETERS,
    build,
};

/// The printed equations in force.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Misprints {
    /// Eq. 8 as printed: `dt_e v` in the pull-back.
    pub eq8: bool,
    /// Eq. 13 as printed: the velocity update without `dt`.
    pub eq13: bool,
}

fn build(values: &ParameterValues<'_>) -> Result<Arc<dyn Scheme>, ParameterError> {
    let theta = values.number_in("theta", 0.0, 1.0)?;
    let misprints = values.choice(
        "misprint",
        &[
            (
                "none",
                Misprints {
                    eq8: false,
                    eq13: false,
                },
            ),
            (
                "eq8",
                Misprints {
                    eq8: true,
                    eq13: false,
                },
            ),
            (
                "eq13",
                Misprints {
                    eq8: false,
                    eq13: true,
                },
            ),
            (
                "both",
                Misprints {
                    eq8: true,
                    eq13: true,
                },
            ),
        ],
    )?;
    Ok(Arc::new(ParkPrintedScheme { theta, misprints }))
}

/// Park's scheme as printed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParkPrintedScheme {
    /// Blend of the pulled-back and CD predictions.
    pub theta: f64,
    /// The printed equations in force.
    pub misprints: Misprints,
}

impl Scheme for ParkPrintedScheme {
    fn name(&self) -> &'static str {
        ENTRY.name
    }

    fn label(&self) -> String {
        let printed = match (self.misprints.eq8, self.misprints.eq13) {
            (false, false) => "none",
            (true, false) => "eq8",
            (false, true) => "eq13",
            (true, true) => "both",
        };
        format!("park-printed-{printed} theta={}", self.theta)
    }

    fn force_evaluations(&self) -> usize {
        2
    }

    fn check_settings(&self, mass: MassKind, _start: Start) -> Result<(), InputError> {
        lumped_only("Park's scheme as printed", mass)
    }

    /// `alpha_e <= 1` in every element, as `park-lts` (methods.md §6); a bound here, since
    /// the printed equations have no stability analysis.
    fn limit(&self, model: &Model, _critical: &CriticalStep) -> SchemeLimit {
        SchemeLimit {
            dt: ParkStep::limit_step(model),
            rule: "alpha_e <= 1 (of the corrected scheme)",
            kind: LimitKind::Bound,
        }
    }

    fn run(&self, setup: RunSetup<'_>) -> Result<RunOutput, RunError> {
        time_loop::run::<ParkPrintedStepper>(self, setup)
    }
}

/// The state `u^n, v^n, a^n` of the printed scheme.
#[derive(Debug, Clone)]
pub struct ParkPrintedStepper {
    scheme: ParkPrintedScheme,
    dt: f64,
    u: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    pulled: Vec<f64>,
    staggered0: f64,
}

impl Integrator for ParkPrintedStepper {
    type Parameters = ParkPrintedScheme;

    /// `alpha_e > 1` is refused unless unstable runs are allowed (then `alpha_e` is used as is).
    fn start(scheme: &ParkPrintedScheme, state: InitialState<'_>) -> Result<Self, InputError> {
        let (_, staggered0) = half_step_start(&state);
        if !state.allow_unstable {
            // The corrected scheme's check of alpha_e <= 1, with its error.
            ParkStep::new(state.model, state.dt, ParkOptions::default())?;
        }
        Ok(Self {
            scheme: *scheme,
            dt: state.dt,
            u: state.displacement.to_vec(),
            v: state.velocity.to_vec(),
            a: state.acceleration.to_vec(),
            pulled: vec![0.0; state.displacement.len()],
            staggered0,
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

    /// Steps 1-4 of methods.md §6, element by element (variant `free`, local stepping), with
    /// the printed eq. 8 and eq. 13 where `misprint` says.
    fn step(&mut self, model: &Model, t: f64, _forces: &[(usize, f64)]) -> StepEnergy {
        let (dt, theta) = (self.dt, self.scheme.theta);
        let bar = model.bar();
        let n = self.u.len();
        let masses = bar.element_mass();
        let nodal = model.nodal_mass();
        let (u, v, a) = (&mut self.u, &mut self.v, &mut self.a);
        self.pulled.iter_mut().for_each(|x| *x = 0.0);
        for (e, &mass) in masses.iter().enumerate() {
            let dt_e = bar.element_transit_time(e);
            let alpha = dt / dt_e;
            let beta1 = alpha * (1.0 + 3.0 * alpha - alpha * alpha) / 6.0;
            let beta2 = alpha * (alpha * alpha - 1.0) / 6.0;
            let m_e = 0.5 * mass;
            let push =
                |node: usize| 0.5 * mass / nodal[node] * model.external_force_at(node, t + dt_e);
            let k = model.stiffness()[e];
            let ut = [e, e + 1].map(|i| u[i] + dt_e * v[i] + 0.5 * dt_e * dt_e * a[i]);
            let stretch = ut[1] - ut[0];
            let at = [
                (push(e) + k * stretch) / m_e,
                (push(e + 1) - k * stretch) / m_e,
            ];
            let velocity_step = if self.scheme.misprints.eq8 { dt_e } else { dt };
            for (s, i) in [e, e + 1].into_iter().enumerate() {
                self.pulled[i] +=
                    u[i] + velocity_step * v[i] + dt_e * dt_e * (beta1 * a[i] + beta2 * at[s]);
            }
        }
        for i in 0..n {
            let count = if i == 0 || i == n - 1 { 1.0 } else { 2.0 };
            let u_cd = u[i] + dt * v[i] + 0.5 * dt * dt * a[i];
            let free = if model.is_fixed(i) { 0.0 } else { 1.0 };
            self.pulled[i] = free * (theta * self.pulled[i] / count + (1.0 - theta) * u_cd);
        }
        std::mem::swap(u, &mut self.pulled);
        let velocity_weight = if self.scheme.misprints.eq13 {
            0.5
        } else {
            0.5 * dt
        };
        let (mut kinetic, mut impulse) = (0.0, 0.0);
        for i in 0..n {
            let a_next = model.acceleration_at(u, i, t + dt);
            v[i] += velocity_weight * (a[i] + a_next);
            a[i] = a_next;
            kinetic += nodal[i] * v[i] * v[i];
            impulse += nodal[i] * a_next * a_next;
        }
        StepEnergy {
            kinetic_staggered: 0.5 * kinetic - 0.125 * dt * dt * impulse,
            kinetic: 0.5 * kinetic,
            strain: model.strain_energy(u),
        }
    }

    fn start_energy(&self) -> f64 {
        self.staggered0
    }
}
