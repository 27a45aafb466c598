//! The measured step limit of a combined contact run: the spectral radius of its one-step
//! amplification matrix in the contact-active state ([`ContactMode::Bilateral`]) or without
//! contact ([`ContactMode::Off`]), and the largest step where it does not exceed 1, by bisection.
//!
//! The step `x^n -> x^{n+1}` of the state `x = (u, dt v, dt^2 a)` (scaled so that its entries are
//! dimensionless) is affine with a persistent contact and no loads; its linear part `G` is
//! assembled column by column from one step of each unit state, minus the step of the zero state.
//! Stable means `rho(G) <= 1 + RHO_TOLERANCE`: the rigid-body motion is a 2x2 Jordan block at
//! eigenvalue 1, which a dense eigensolver returns as `1 +- O(sqrt(eps))`. Eigenvalues of the
//! real Schur form (Golub and Van Loan, Matrix Computations, 4th ed., §7.5). O((3N)^3) per
//! step size: for meshes of up to a few hundred nodes.

use super::bulk::BulkScheme;
use super::stepper::{CombinedStepper, ContactMode};
use crate::contact::problem::ContactProblem;
use crate::contact::scheme::ContactScheme;
use crate::error::{InputError, NoConvergence};
use nalgebra::DMatrix;

/// `rho(G) - 1` above which a step counts as unstable.
pub const RHO_TOLERANCE: f64 = 1e-6;

/// Why a measured limit is not available.
#[derive(Debug, thiserror::Error)]
pub enum AmplificationError {
    /// The problem or scheme is invalid.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The eigensolver did not converge.
    #[error(transparent)]
    NoConvergence(#[from] NoConvergence),
    /// No stable step or no unstable step was found in the search range.
    #[error("no {0} step found between 1e-6 and 1e6 times the stiffest element's transit time")]
    NotBracketed(&'static str),
    /// The mesh is too large for the dense amplification matrix.
    #[error("{nodes} nodes: the dense amplification matrix is limited to {limit} nodes")]
    TooLarge {
        /// Nodes of the problem.
        nodes: usize,
        /// The limit.
        limit: usize,
    },
}

const SCHUR_ITERATIONS: usize = 100_000;

/// Largest problem (nodes) the dense analysis accepts.
pub const MAX_NODES: usize = 400;

/// The spectral radius of the one-step amplification matrix at step `dt`.
///
/// # Errors
/// [`AmplificationError`] for invalid input, a mesh above [`MAX_NODES`] or no convergence.
pub fn spectral_radius(
    problem: &ContactProblem,
    bulk: BulkScheme,
    scheme: ContactScheme,
    mode: ContactMode,
    dt: f64,
) -> Result<f64, AmplificationError> {
    let n = problem.node_count();
    if n > MAX_NODES {
        return Err(AmplificationError::TooLarge {
            nodes: n,
            limit: MAX_NODES,
        });
    }
    let mut stepper = CombinedStepper::allowing_unstable(problem, bulk, scheme, mode, dt)?;
    let scale = [1.0, dt, dt * dt];
    let image = |stepper: &mut CombinedStepper<'_>, x: &[f64]| -> Vec<f64> {
        let (u, rest) = x.split_at(n);
        let (v, a) = rest.split_at(n);
        let v: Vec<f64> = v.iter().map(|y| y / scale[1]).collect();
        let a: Vec<f64> = a.iter().map(|y| y / scale[2]).collect();
        stepper.set_state(u, &v, &a);
        stepper.step();
        let [u, v, a] = stepper.state();
        let mut y = Vec::with_capacity(3 * n);
        y.extend_from_slice(u);
        y.extend(v.iter().map(|z| z * scale[1]));
        y.extend(a.iter().map(|z| z * scale[2]));
        y
    };
    let zero = vec![0.0; 3 * n];
    let origin = image(&mut stepper, &zero);
    let mut g = DMatrix::<f64>::zeros(3 * n, 3 * n);
    let mut unit = zero;
    for j in 0..3 * n {
        unit[j] = 1.0;
        let column = image(&mut stepper, &unit);
        unit[j] = 0.0;
        for i in 0..3 * n {
            g[(i, j)] = column[i] - origin[i];
        }
    }
    let schur = nalgebra::linalg::Schur::try_new(g, f64::EPSILON, SCHUR_ITERATIONS).ok_or(
        NoConvergence {
            method: "the real Schur form of the amplification matrix",
            iterations: SCHUR_ITERATIONS,
            why: format!("dt = {dt}"),
        },
    )?;
    Ok(schur
        .complex_eigenvalues()
        .iter()
        .map(|z| z.norm())
        .fold(0.0, f64::max))
}

/// The largest step with `rho(G) <= 1 + RHO_TOLERANCE`, to a relative `1e-10`, found by
/// bracketing from the stiffest element's transit time and bisecting.
///
/// # Errors
/// As [`spectral_radius`], and [`AmplificationError::NotBracketed`].
pub fn measured_limit(
    problem: &ContactProblem,
    bulk: BulkScheme,
    scheme: ContactScheme,
    mode: ContactMode,
) -> Result<f64, AmplificationError> {
    let stable = |dt: f64| -> Result<bool, AmplificationError> {
        Ok(spectral_radius(problem, bulk, scheme, mode, dt)? <= 1.0 + RHO_TOLERANCE)
    };
    let start = problem.stiffest_transit();
    let (mut lo, mut hi) = if stable(start)? {
        let mut hi = start;
        loop {
            hi *= 1.25;
            if hi > 1e6 * start {
                return Err(AmplificationError::NotBracketed("unstable"));
            }
            if !stable(hi)? {
                break (hi / 1.25, hi);
            }
        }
    } else {
        let mut lo = start;
        loop {
            lo *= 0.8;
            if lo < 1e-6 * start {
                return Err(AmplificationError::NotBracketed("stable"));
            }
            if stable(lo)? {
                break (lo, lo / 0.8);
            }
        }
    };
    while hi - lo > 1e-10 * lo {
        let mid = 0.5 * (lo + hi);
        if stable(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(lo)
}
