//! Measured dispersion of central difference: the phase speed of one standing mode, from a run
//! of the solver.
//!
//! On a uniform free-free bar every sampled cosine `u_j = cos(k x_j)`, `k = n pi/L`, is an exact
//! discrete mode for every mass kind (their matrices all have the Neumann structure), so a run
//! started from it at rest stays in it: `u_j^s = cos(s theta) u_j^0`, with the discrete phase
//! per step `theta = omega_hat dt`. The measured `theta = acos(u^s/u^0)/s` (taken at a step `s`
//! where `s theta` is near `pi/2`, where `acos` is well conditioned) gives the phase-speed ratio
//! `omega_hat/(c k) = theta/(Co kh)`, `Co = c dt/h`. Theory (methods.md §5):
//! `sin(theta/2) = (Co/2) Omega(kh)`.

use crate::results::dispersion::{DispersionRecord, ModeMeasurement};
use crate::scene::dispersion::DispersionCase;
use courant_solver::{
    Bar, CentralDifference, InitialConditions, MassKind, Mesh, Model, OutputRequest, RunError,
    Support, Supports,
};
use std::f64::consts::PI;

/// Run mode `n` of a unit free-free bar of `elements` elements with mass `kind` at Courant number
/// `co` (relative to `c dt / h`) and measure its phase speed.
pub fn measure_mode(
    kind: MassKind,
    elements: usize,
    n: usize,
    co: f64,
) -> Result<ModeMeasurement, RunError> {
    let length = 1.0;
    let bar = Bar::homogeneous(Mesh::uniform(length, elements)?, 1.0, 1.0, 1.0)?;
    let k = n as f64 * PI / length;
    let u0: Vec<f64> = bar.mesh().nodes().iter().map(|&x| (k * x).cos()).collect();
    let initial = InitialConditions {
        displacement: Some(u0.clone()),
        velocity: None,
    };
    let model = Model::new(
        bar,
        Supports {
            left: Support::Free,
            right: Support::Free,
        },
        &[],
        initial,
    )?;
    let h = length / elements as f64;
    let kh = k * h;
    let dt = co * h;
    // Continuum phase per step as a first guess for where s theta ~ pi/2.
    let steps = ((PI / 2.0) / (co * kh)).round().clamp(1.0, 100_000.0) as usize;
    let integrator = CentralDifference {
        mass: kind,
        ..CentralDifference::new(dt)
    };
    // At most 17 nodes recorded (evenly spread, both ends included): enough to see a leak out
    // of the mode, and memory independent of N.
    let stride = elements.div_ceil(16).max(1);
    let mut nodes: Vec<usize> = (0..=elements).step_by(stride).collect();
    if nodes.last() != Some(&elements) {
        nodes.push(elements);
    }
    let request = OutputRequest {
        history_nodes: nodes,
        ..Default::default()
    };
    let out =
        super::threads::with_setting(&integrator.integration()).run(&model, steps, &request)?;
    let (u_first, u_last) = (u0[0], out.histories[0].samples[steps].displacement);
    let phase_per_step = (u_last / u_first).clamp(-1.0, 1.0).acos() / steps as f64;
    let mut mode_leak = 0.0_f64;
    for history in &out.histories {
        for sample in &history.samples {
            let expected = (sample.step as f64 * phase_per_step).cos() * u0[history.node];
            mode_leak = mode_leak.max((sample.displacement - expected).abs());
        }
    }
    Ok(ModeMeasurement {
        kh,
        phase_per_step,
        phase_speed_ratio: phase_per_step / (co * kh),
        steps,
        mode_leak,
    })
}

/// Run every mode of a dispersion case.
///
/// # Errors
/// The solver refuses a run (it cannot for a valid case: every run is below its critical step).
pub fn run_dispersion(case: &DispersionCase) -> Result<DispersionRecord, RunError> {
    let modes = case
        .modes
        .iter()
        .map(|&mode| {
            Ok((
                mode,
                measure_mode(case.mass, case.elements, mode, case.courant)?,
            ))
        })
        .collect::<Result<_, RunError>>()?;
    Ok(DispersionRecord {
        case: case.name.clone(),
        modes,
    })
}
