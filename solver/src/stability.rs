//! Critical time step of lumped-mass central difference, `dt_crit = 2/omega_max` (seed eq. 5),
//! by three estimates:
//!
//! - **element**: `min_e h_e/c_e`. For the two-node lumped element `omega_max^e = 2 c_e/h_e`, and
//!   Fried's theorem (`omega_max <= max_e omega_max^e`, Fried 1972) makes it conservative.
//! - **Gershgorin**: `omega_max^2 <= max_i sum_j |K_ij|/sqrt(m_i m_j)` over free nodes (row
//!   sums of the symmetric `M^-1/2 K M^-1/2`); conservative.
//! - **exact**: the largest eigenvalue of `M^-1/2 K M^-1/2` (symmetric tridiagonal, fixed nodes
//!   deleted), found by Sturm-sequence bisection to full precision (Wilkinson, The Algebraic
//!   Eigenvalue Problem (1965), §5.37). Unlike power iteration it does not slow down when the top
//!   of the spectrum is clustered, as it is on uniform meshes.

use crate::model::Model;

/// The critical-step estimates of one model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalStep {
    /// Exact `2/omega_max`.
    pub exact: f64,
    /// Largest angular frequency `omega_max` of the free nodes.
    pub omega_max: f64,
    /// Element estimate `min_e h_e/c_e`.
    pub element: f64,
    /// The element that attains the element estimate.
    pub controlling_element: usize,
    /// Gershgorin estimate `2/sqrt(max_i sum_j |K_ij|/sqrt(m_i m_j))`.
    pub gershgorin: f64,
}

impl CriticalStep {
    /// Compute all three estimates for a lumped-mass model.
    pub fn lumped(model: &Model) -> Self {
        let (diag, off) = scaled_stiffness(model);
        let gershgorin_bound = gershgorin_upper_bound(&diag, &off);
        let lambda_max = largest_eigenvalue(&diag, &off, gershgorin_bound);
        let (controlling_element, element) = model.bar().stiffest_element();
        let omega_max = lambda_max.sqrt();
        Self {
            exact: if omega_max > 0.0 {
                2.0 / omega_max
            } else {
                f64::INFINITY
            },
            omega_max,
            element,
            controlling_element,
            gershgorin: if gershgorin_bound > 0.0 {
                2.0 / gershgorin_bound.sqrt()
            } else {
                f64::INFINITY
            },
        }
    }
}

/// The symmetric tridiagonal `S = M^-1/2 K M^-1/2` over all nodes, with the rows and columns of
/// fixed nodes zeroed (their eigenvalue 0 never controls the step). Returns (diagonal,
/// off-diagonal) with `off[i] = S_{i,i+1}`.
pub fn scaled_stiffness(model: &Model) -> (Vec<f64>, Vec<f64>) {
    let k = model.stiffness();
    let minv = model.inverse_mass();
    let n = minv.len();
    let mut diag = vec![0.0; n];
    let mut off = vec![0.0; n - 1];
    for (e, &ke) in k.iter().enumerate() {
        diag[e] += ke * minv[e];
        diag[e + 1] += ke * minv[e + 1];
        off[e] = -ke * (minv[e] * minv[e + 1]).sqrt();
    }
    (diag, off)
}

/// Gershgorin bound on the largest eigenvalue of a symmetric tridiagonal matrix.
pub fn gershgorin_upper_bound(diag: &[f64], off: &[f64]) -> f64 {
    (0..diag.len())
        .map(|i| {
            let left = if i > 0 { off[i - 1].abs() } else { 0.0 };
            let right = if i < off.len() { off[i].abs() } else { 0.0 };
            diag[i] + left + right
        })
        .fold(0.0, f64::max)
}

/// Number of eigenvalues of the symmetric tridiagonal (diag, off) smaller than `x`
/// (Sturm sequence count via the LDL^T pivots).
fn count_below(diag: &[f64], off: &[f64], x: f64) -> usize {
    let mut count = 0;
    let mut q = 1.0;
    for i in 0..diag.len() {
        let coupling = if i > 0 { off[i - 1] * off[i - 1] } else { 0.0 };
        q = diag[i] - x - if coupling == 0.0 { 0.0 } else { coupling / q };
        if q == 0.0 {
            q = -f64::EPSILON * (x.abs() + f64::MIN_POSITIVE);
        }
        if q < 0.0 {
            count += 1;
        }
    }
    count
}

/// Largest eigenvalue of a symmetric tridiagonal matrix by bisection on the Sturm count, to a
/// relative width of a few ulps. `upper` must bound the spectrum from above.
pub fn largest_eigenvalue(diag: &[f64], off: &[f64], upper: f64) -> f64 {
    let n = diag.len();
    let (mut lo, mut hi) = (0.0_f64, upper * (1.0 + 4.0 * f64::EPSILON));
    if hi <= 0.0 {
        return 0.0;
    }
    // Invariant: fewer than n eigenvalues below hi is false (all are below hi); lo has < n below.
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if count_below(diag, off, mid) == n {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bar::Bar;
    use crate::load::{End, Load, TimeFunction};
    use crate::mesh::Mesh;
    use crate::model::{InitialConditions, Model, Support, Supports};

    fn model(bar: Bar, supports: Supports) -> Model {
        let load = Load::Traction {
            end: End::Left,
            stress: -1.0,
            time: TimeFunction::HEAVISIDE,
        };
        Model::new(bar, supports, &[load], InitialConditions::default()).unwrap()
    }

    /// Closed form, uniform lumped free-fixed bar of N elements: the free nodes 0..N-1 have
    /// `omega_n = (2c/h) sin((2n-1) pi/(4N))`, n = 1..N, so `omega_max = (2c/h) cos(pi/(4N))`.
    #[test]
    fn exact_step_matches_the_closed_form_of_the_uniform_free_fixed_bar() {
        for n in [1, 2, 10, 100, 1000] {
            let bar = Bar::homogeneous(Mesh::uniform(1.0, n).unwrap(), 1.0, 1.0, 1.0).unwrap();
            let cs = CriticalStep::lumped(&model(bar, Supports::FREE_FIXED));
            let h = 1.0 / n as f64;
            let omega = 2.0 / h * (std::f64::consts::PI / (4.0 * n as f64)).cos();
            assert!(
                (cs.omega_max - omega).abs() <= 4.0 * f64::EPSILON * omega,
                "N = {n}: {} vs {omega}",
                cs.omega_max
            );
            assert!(cs.exact >= cs.element && cs.gershgorin <= cs.exact);
        }
    }

    /// Free-free uniform lumped bar: the saw-tooth mode gives omega_max = 2c/h exactly.
    #[test]
    fn free_free_uniform_bar_has_critical_courant_number_one() {
        let bar = Bar::homogeneous(Mesh::uniform(1.0, 64).unwrap(), 1.0, 1.0, 1.0).unwrap();
        let cs = CriticalStep::lumped(&model(
            bar,
            Supports {
                left: Support::Free,
                right: Support::Free,
            },
        ));
        assert!((cs.exact / cs.element - 1.0).abs() < 1e-14);
    }

    #[test]
    fn graded_bar_is_controlled_by_its_stiff_end() {
        let cs = CriticalStep::lumped(&crate::fixtures::graded_seed_bar(100).unwrap());
        assert_eq!(cs.controlling_element, 0);
        assert!(
            cs.exact >= cs.element,
            "Fried's bound is conservative for lumped mass"
        );
    }
}
