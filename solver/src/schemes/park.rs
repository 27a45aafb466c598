//! Park's scheme through the integrator interface: the `park-lts` and `park-global` registry
//! entries and their stepper around [`crate::kernels::park::ParkStep`] (the folded, blocked step;
//! methods.md §6).
//!
//! Balance energy: `1/2 v M v - dt^2/8 a M a + 1/2 u K u`, which is central difference's
//! conserved energy when the scheme is CD (theta = 0 or alpha = 1), so the balance measures
//! Park's own dissipation. Limit: `alpha_e = dt/dt_e <= 1` in every element. Two
//! internal-force evaluations per step: the element predictions `K_e u~_e` and the assembled
//! `K u^{n+1}`. Lumped mass only.

use super::central_difference::half_step_start;
use crate::analysis::stability::CriticalStep;
use crate::error::{InputError, RunError};
use crate::integrator::{
    InitialState, Integrator, LimitKind, Parameter, ParameterDefault, ParameterError,
    ParameterValues, RunSetup, Scheme, SchemeEntry, SchemeLimit, Start, lumped_only, time_loop,
};
use crate::kernels::energy::StepEnergy;
use crate::kernels::park::{ParkOptions, ParkStep, ParkVariant};
use crate::mass::MassKind;
use crate::model::Model;
use crate::output::RunOutput;
use std::sync::Arc;

/// Park's parameters, shared by both entries.
const PARAMETERS: &[Parameter] = &[
    Parameter {
        key: "theta",
        default: ParameterDefault::Number(0.5),
        rule: "must lie in [0, 1]",
        meaning: "blend of the pulled-back and CD predictions (0 is CD; 1/2 cancels the leading phase error)",
    },
    Parameter {
        key: "park_variant",
        default: ParameterDefault::Text("free"),
        rule: "must be one of free, incremental",
        meaning: "element acceleration: free (the seed's formula; creates energy over long runs under a sustained load on graded meshes) or incremental (keeps statics static, dissipative: pick it for long runs)",
    },
];

const SOURCE: &str = "Kolman et al. (seed) §3.1 after Park et al., as corrected in methods.md §6; limit alpha_e <= 1 (methods.md §6)";

/// Park's scheme with local time stepping.
pub const LOCAL_STEPPING: SchemeEntry = SchemeEntry {
    name: "park-lts",
    aliases: &[],
    summary: "Park's pull-back scheme, each element at its own dt_e (local stepping); 2 K u per step",
    source: SOURCE,
    masses: "lmm",
    parameters: PARAMETERS,
    build: |values| build(values, true),
};

/// Park's scheme with one `dt_e` (the stiffest element's) for every element.
pub const GLOBAL_STEP: SchemeEntry = SchemeEntry {
    name: "park-global",
    aliases: &[],
    summary: "Park's pull-back scheme, every element at the stiffest one's dt_e; 2 K u per step",
    source: SOURCE,
    masses: "lmm",
    parameters: PARAMETERS,
    build: |values| build(values, false),
};

fn build(
    values: &ParameterValues<'_>,
    local_stepping: bool,
) -> Result<Arc<dyn Scheme>, ParameterError> {
    let theta = values.number_in("theta", 0.0, 1.0)?;
    let variant = values.choice(
        "park_variant",
        &[
            ("free", ParkVariant::Free),
            ("incremental", ParkVariant::Incremental),
        ],
    )?;
    Ok(Arc::new(ParkScheme {
        options: ParkOptions {
            theta,
            variant,
            local_stepping,
        },
    }))
}

/// Park's scheme with its options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParkScheme {
    /// theta, variant, local stepping.
    pub options: ParkOptions,
}

impl Scheme for ParkScheme {
    fn name(&self) -> &'static str {
        if self.options.local_stepping {
            LOCAL_STEPPING.name
        } else {
            GLOBAL_STEP.name
        }
    }

    fn label(&self) -> String {
        format!("{} theta={}", self.options.label(), self.options.theta)
    }

    fn force_evaluations(&self) -> usize {
        2
    }

    fn check_settings(&self, mass: MassKind, _start: Start) -> Result<(), InputError> {
        lumped_only("Park's scheme", mass)
    }

    /// `alpha_e = dt/dt_e <= 1` in every element (methods.md §6), i.e. `dt <= min_e dt_e`
    /// ([`ParkStep::limit_step`]), at or below CD's `2/omega_max` (Fried's bound
    /// `omega_max <= max_e 2 c_e/h_e`). It comes from the amplification analysis of a uniform
    /// mesh, whose spectral radius exceeds 1 just above `alpha = 1` at `kh = pi`
    /// (tests/verification/park_amplification_analysis.rs): where every element has the same `dt_e` it is the
    /// limit ([`LimitKind::Exact`], up to the finite mesh's top mode, a hair below `kh = pi`); on
    /// a graded mesh only sufficient ([`LimitKind::Bound`]; measured: the global step on the
    /// `graded_1e4` mesh stays bounded at `alpha = 1.012`).
    fn limit(&self, model: &Model, _critical: &CriticalStep) -> SchemeLimit {
        let bar = model.bar();
        let dt = ParkStep::limit_step(model);
        let slowest = (0..bar.element_count())
            .map(|e| bar.element_transit_time(e))
            .fold(dt, f64::max);
        if slowest > dt * (1.0 + 1e-12) {
            SchemeLimit {
                dt,
                rule: "alpha_e <= 1 (sufficient)",
                kind: LimitKind::Bound,
            }
        } else {
            SchemeLimit {
                dt,
                rule: "alpha_e <= 1",
                kind: LimitKind::Exact,
            }
        }
    }

    fn run(&self, setup: RunSetup<'_>) -> Result<RunOutput, RunError> {
        time_loop::run::<ParkStepper>(&self.options, setup)
    }
}

/// Park's scheme as a stepper of the time loop.
#[derive(Debug, Clone)]
pub struct ParkStepper {
    park: ParkStep,
    staggered0: f64,
}

impl Integrator for ParkStepper {
    type Parameters = ParkOptions;

    /// Above `alpha_e = 1` the scheme is refused, or run with its true `alpha_e` when unstable
    /// runs are allowed ([`ParkStep::allowing_unstable`]). The balance starts from central
    /// difference's `T*^0`, which is Park's `T - dt^2/8 a M a` at `t^0` for the half-step start.
    fn start(options: &ParkOptions, state: InitialState<'_>) -> Result<Self, InputError> {
        let (_, staggered0) = half_step_start(&state);
        let (model, dt) = (state.model, state.dt);
        let mut park = if state.allow_unstable {
            ParkStep::allowing_unstable(model, dt, *options)?
        } else {
            ParkStep::new(model, dt, *options)?
        };
        park.start(model);
        Ok(Self { park, staggered0 })
    }

    fn dt(&self) -> f64 {
        self.park.dt()
    }

    fn displacement(&self) -> &[f64] {
        self.park.displacement()
    }

    fn velocity_and_acceleration_at(&self, _model: &Model, i: usize, _t: f64) -> (f64, f64) {
        (self.park.velocity()[i], self.park.acceleration()[i])
    }

    #[inline]
    fn step(&mut self, model: &Model, t: f64, _forces: &[(usize, f64)]) -> StepEnergy {
        self.park.step(model, t)
    }

    fn start_energy(&self) -> f64 {
        self.staggered0
    }
}
