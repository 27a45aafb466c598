//! Shared by the Noh-Bathe tests: the closed-form amplification matrix (derived for courant, the
//! module docs of `courant_solver::schemes::noh_bathe`), and runs of the scheme through the
//! public interface.

#![allow(dead_code)]

use courant_solver::schemes::noh_bathe::NohBatheScheme;
use courant_solver::{
    Bar, InitialConditions, Integration, MassKind, Mesh, Model, OutputRequest, RunError, RunOutput,
    StabilityPolicy, Supports,
};
use std::sync::Arc;

/// The amplification matrix of one step on `(u, dt v)` for `u'' + omega^2 u = 0`, `W = omega dt`.
pub fn amplification(w: f64, p: f64) -> [[f64; 2]; 2] {
    let w2 = w * w;
    let a11 = 1.0 - w2 / 2.0 + p * p * (1.0 - p) * w2 * w2 / 4.0;
    let a12 = 1.0 - p * (1.0 - p) * w2 / 2.0;
    let a21 = -w2 + p * (2.0 - p) * w2 * w2 / 4.0 - p.powi(3) * (1.0 - p) * w2 * w2 * w2 / 8.0;
    [[a11, a12], [a21, a11]]
}

/// Spectral radius of a real 2x2 matrix.
pub fn spectral_radius(a: [[f64; 2]; 2]) -> f64 {
    let half_trace = 0.5 * (a[0][0] + a[1][1]);
    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    let disc = half_trace * half_trace - det;
    if disc >= 0.0 {
        half_trace.abs() + disc.sqrt()
    } else {
        det.sqrt()
    }
}

/// `det A = 1 - (1 - p)^2 (2p - 1) W^4 / 4`.
pub fn determinant(w: f64, p: f64) -> f64 {
    1.0 - (1.0 - p).powi(2) * (2.0 * p - 1.0) * w.powi(4) / 4.0
}

/// The unit fixed-free bar (free at x = 0, fixed at x = 1, E = rho = A = 1) of `elements`
/// uniform elements in free vibration from `displacement` (its value at the fixed node is set to
/// 0: a mode's `cos(k L)` is 0 only to round-off).
pub fn free_bar(elements: usize, mut displacement: Vec<f64>) -> Model {
    displacement[elements] = 0.0;
    let bar = Bar::homogeneous(Mesh::uniform(1.0, elements).unwrap(), 1.0, 1.0, 1.0).unwrap();
    Model::new(
        bar,
        Supports::FREE_FIXED,
        &[],
        InitialConditions {
            displacement: Some(displacement),
            velocity: None,
        },
    )
    .unwrap()
}

/// Noh-Bathe with `p`, step `dt` and `mass`, unstable runs allowed or not.
pub fn noh_bathe(p: f64, dt: f64, mass: MassKind, allow_unstable: bool) -> Integration {
    Integration {
        mass,
        stability: StabilityPolicy {
            allow_unstable,
            ..StabilityPolicy::default()
        },
        ..Integration::new(dt, Arc::new(NohBatheScheme { p }))
    }
}

/// Run `steps` steps, every energy sample and the history of `nodes` every step.
pub fn run(
    integration: &Integration,
    model: &Model,
    steps: usize,
    nodes: &[usize],
) -> Result<RunOutput, RunError> {
    let request = OutputRequest {
        history_nodes: nodes.to_vec(),
        ..OutputRequest::default()
    };
    integration.run(model, steps, &request)
}
