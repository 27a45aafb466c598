//! Critical time step of central difference, `dt_crit = 2/omega_max` (seed eq. 5), for every
//! mass kind, by three estimates:
//!
//! - **element** (Fried): `2/max_e omega_max^e`, `omega_max^e` of the element's own matrices:
//!   `Co_e min_e h_e/c_e` with `Co_e` = 1 (LMM), `1/sqrt 3` (CMM), `sqrt((1 + 2 beta)/3)` (AMM,
//!   RMM). Fried's theorem (`omega_max <= max_e omega_max^e`, Fried 1972) makes it conservative
//!   for assembled masses (LMM, CMM, AMM); for RMM it is **not** a bound, since the inverse mass
//!   is assembled: with `beta > 5/2` the assembled spectrum peaks inside the band and the
//!   element estimate is too large. (Also reported: the closed-form infinite-mesh value.)
//! - **Gershgorin** (nodal): LMM: row sums of `M^-1/2 K M^-1/2`; CMM/AMM: the pencil bound
//!   `max_i sum_j |K_ij| / (M_ii - sum_{j != i} |M_ij|)` where `M` is diagonally dominant, else
//!   `1/min(1, (1 + 2 beta)/3)` times the lumped bound (since `M >= min(1, (1 + 2 beta)/3) LMM`); RMM: the row-sum
//!   norm of `M^-1 K`. All conservative.
//! - **exact**: the largest eigenvalue by bisection on the inertia of a shifted pencil (Sylvester;
//!   Wilkinson, The Algebraic Eigenvalue Problem (1965), §5.37): the symmetric tridiagonal
//!   `M^-1/2 K M^-1/2` for LMM, `K - x M` for CMM/AMM, the band-3 `M^-1 K M^-1 - x M^-1` for RMM
//!   (congruent to `K - x M`). Unlike power iteration it does not slow down when the top of the
//!   spectrum is clustered, as it is on uniform meshes. Runs use this one.

use crate::error::NoConvergence;
use crate::mass::{MassKind, MassOperator};
use crate::model::Model;

/// Iteration bound of every bisection on Sturm counts: halving a bracket `[0, hi]` reaches
/// adjacent doubles in at most about 1100 steps whatever `hi`, and in about 60 when the upper
/// bound is within a few orders of magnitude of `lambda_max` (the bounds used here are within a
/// factor 4).
pub const BISECTION_STEPS: usize = 1100;

/// Doublings allowed to lift a starting bound above the spectrum (round-off may leave an
/// eigenvalue a hair above a Gershgorin bound; 64 doublings is a factor 1.8e19).
pub const BOUND_DOUBLINGS: usize = 64;

/// The method name of the critical-step bisection in [`NoConvergence`] errors.
const BISECTION: &str = "the critical-step bisection (Sturm counts of K - x M)";

/// The critical-step estimates of one model and mass kind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalStep {
    /// The mass kind.
    pub mass: MassKind,
    /// Exact `2/omega_max` (the one runs are checked against).
    pub exact: f64,
    /// Largest angular frequency `omega_max` of the free nodes.
    pub omega_max: f64,
    /// Element (Fried) estimate `2/max_e omega_max^e` = `element_courant(kind) min_e h_e/c_e`
    /// (a bound except for RMM).
    pub element: f64,
    /// Closed-form critical step of the infinite uniform mesh,
    /// `critical_courant(kind) min_e h_e/c_e` (the uniform-mesh value, not a bound in general).
    pub infinite_mesh: f64,
    /// The element with the smallest transit time.
    pub controlling_element: usize,
    /// Its transit time `min_e h_e/c_e`.
    pub element_transit: f64,
    /// Nodal Gershgorin estimate (conservative).
    pub gershgorin: f64,
}

impl CriticalStep {
    /// All estimates for a lumped-mass model.
    ///
    /// # Errors
    /// [`NoConvergence`] when the bisection does not close within [`BISECTION_STEPS`] (only for
    /// entries whose products overflow or underflow).
    pub fn lumped(model: &Model) -> Result<Self, NoConvergence> {
        let (diag, off) = scaled_stiffness(model);
        let gershgorin_bound = gershgorin_upper_bound(&diag, &off);
        let lambda_max = largest_eigenvalue(&diag, &off, gershgorin_bound)?;
        Ok(Self::from_eigenvalues(
            model,
            MassKind::Lumped,
            lambda_max,
            gershgorin_bound,
        ))
    }

    /// All estimates for `model` with the mass `operator` of `kind`.
    ///
    /// # Errors
    /// [`NoConvergence`] when no bound above the spectrum is found within [`BOUND_DOUBLINGS`]
    /// doublings or the bisection does not close within [`BISECTION_STEPS`].
    pub fn of(
        model: &Model,
        kind: MassKind,
        operator: &MassOperator,
    ) -> Result<Self, NoConvergence> {
        if kind == MassKind::Lumped {
            return Self::lumped(model);
        }
        let gershgorin_bound = nodal_gershgorin(model, kind, operator);
        let (p, q) = operator.pencil(model);
        let n = p.order();
        // Start from the Gershgorin bound and make sure it is above the spectrum (doubling),
        // so the bisection never depends on the bound being right.
        let start = gershgorin_bound.max(f64::MIN_POSITIVE) * (1.0 + 1e-12);
        let hi = lift_above_spectrum(start, |x| p.negative_pivots_of_shifted(&q, x) == n)?;
        let lambda_max = bisect_top(hi, 0.0, |x| p.negative_pivots_of_shifted(&q, x) == n)?;
        Ok(Self::from_eigenvalues(
            model,
            kind,
            lambda_max,
            gershgorin_bound,
        ))
    }

    fn from_eigenvalues(
        model: &Model,
        mass: MassKind,
        lambda_max: f64,
        gershgorin_bound: f64,
    ) -> Self {
        let (controlling_element, element_transit) = model.bar().stiffest_element();
        let omega_max = lambda_max.sqrt();
        let step = |lambda: f64| {
            if lambda > 0.0 {
                2.0 / lambda.sqrt()
            } else {
                f64::INFINITY
            }
        };
        Self {
            mass,
            exact: step(lambda_max),
            omega_max,
            element: mass.element_courant() * element_transit,
            infinite_mesh: mass.critical_courant() * element_transit,
            controlling_element,
            element_transit,
            gershgorin: step(gershgorin_bound),
        }
    }
}

/// Nodal Gershgorin-type upper bound on `omega_max^2` (see the module doc).
fn nodal_gershgorin(model: &Model, kind: MassKind, operator: &MassOperator) -> f64 {
    let (diag, off) = scaled_stiffness(model);
    let lumped = gershgorin_upper_bound(&diag, &off);
    // The stiffness with fixed rows and columns deleted (the (K, M) pencil of the lumped mass;
    // the RMM pencil is (M^-1 K M^-1, M^-1), not (K, .)).
    let (mass, inverse) = model.shared_lumped_mass();
    let (k, _) = MassOperator::Diagonal { inverse, mass }.pencil(model);
    let n = k.order();
    let row_sum = |i: usize| -> f64 {
        (i.saturating_sub(1)..=(i + 1).min(n - 1))
            .map(|j| k.get(i, j).abs())
            .sum()
    };
    match operator {
        MassOperator::Diagonal { .. } => lumped,
        MassOperator::Tridiagonal { matrix, fixed, .. } => {
            let beta = match kind {
                MassKind::Averaged { beta } => beta,
                _ => 0.0,
            };
            // M >= min(1, (1 + 2 beta)/3) LMM element by element (element eigenvalues m/2 and
            // m(1 + 2 beta)/6 against m/2), so lambda_max <= lumped / min(1, (1 + 2 beta)/3).
            let fallback = lumped / ((1.0 + 2.0 * beta) / 3.0).min(1.0);
            let mut bound = 0.0_f64;
            for i in (0..n).filter(|&i| !fixed[i]) {
                let left = if i > 0 { matrix.off[i - 1].abs() } else { 0.0 };
                let right = if i + 1 < n { matrix.off[i].abs() } else { 0.0 };
                let margin = matrix.diag[i] - left - right;
                if margin <= 0.0 {
                    return fallback;
                }
                bound = bound.max(row_sum(i) / margin);
            }
            bound.min(fallback)
        }
        MassOperator::Reciprocal { inverse, .. } => {
            // Row sums of |M^-1 K|, M^-1 K pentadiagonal.
            let entry =
                |t: &crate::mass::banded::Tridiagonal, i: usize, j: usize| match i.abs_diff(j) {
                    0 => t.diag[i],
                    1 => t.off[i.min(j)],
                    _ => 0.0,
                };
            (0..n)
                .map(|i| {
                    (i.saturating_sub(2)..=(i + 2).min(n - 1))
                        .map(|j| {
                            (i.saturating_sub(1)..=(i + 1).min(n - 1))
                                .filter(|a| a.abs_diff(j) <= 1)
                                .map(|a| entry(inverse, i, a) * k.get(a, j))
                                .sum::<f64>()
                                .abs()
                        })
                        .sum::<f64>()
                })
                .fold(0.0, f64::max)
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
///
/// # Errors
/// [`NoConvergence`] for a non-finite `upper` or a bisection that does not close within
/// [`BISECTION_STEPS`].
pub fn largest_eigenvalue(diag: &[f64], off: &[f64], upper: f64) -> Result<f64, NoConvergence> {
    let n = diag.len();
    let hi = upper * (1.0 + 4.0 * f64::EPSILON);
    if hi <= 0.0 {
        return Ok(0.0);
    }
    bisect_top(hi, 0.0, |x| count_below(diag, off, x) == n)
}

/// `start`, doubled (at most [`BOUND_DOUBLINGS`] times) until `all_below(x)` holds: every
/// eigenvalue is below it.
///
/// # Errors
/// [`NoConvergence`] when the bound becomes non-finite or the doublings run out.
pub fn lift_above_spectrum(
    start: f64,
    all_below: impl Fn(f64) -> bool,
) -> Result<f64, NoConvergence> {
    let mut hi = start;
    for _ in 0..=BOUND_DOUBLINGS {
        if !hi.is_finite() {
            break;
        }
        if all_below(hi) {
            return Ok(hi);
        }
        hi *= 2.0;
    }
    Err(NoConvergence {
        method: BISECTION,
        iterations: BOUND_DOUBLINGS,
        why: format!(
            "no upper bound of the spectrum from {start:e} (doubled to {hi:e}): the model's entries are too large or too small for f64"
        ),
    })
}

/// The largest eigenvalue by bisection of `[0, hi]` on `all_below(x)` (every eigenvalue is below
/// `x`), which must hold at `hi`, to adjacent doubles or a bracket of relative width
/// `rel_width` (0: adjacent doubles).
///
/// # Errors
/// [`NoConvergence`] for a non-finite `hi` or when [`BISECTION_STEPS`] halvings do not close
/// the bracket.
pub fn bisect_top(
    hi: f64,
    rel_width: f64,
    all_below: impl Fn(f64) -> bool,
) -> Result<f64, NoConvergence> {
    let fail = |why: String| NoConvergence {
        method: BISECTION,
        iterations: BISECTION_STEPS,
        why,
    };
    if !hi.is_finite() {
        return Err(fail(format!("its upper bound {hi} is not finite")));
    }
    let (mut lo, mut hi) = (0.0_f64, hi);
    for _ in 0..BISECTION_STEPS {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi || hi - lo <= rel_width * hi {
            return Ok(0.5 * (lo + hi));
        }
        if all_below(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Err(fail(format!("the bracket [{lo:e}, {hi:e}] is still open")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::bar::Bar;
    use crate::model::load::{End, Load, TimeFunction};
    use crate::model::mesh::Mesh;
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
            let cs = CriticalStep::lumped(&model(bar, Supports::FREE_FIXED)).unwrap();
            let h = 1.0 / n as f64;
            let omega = 2.0 / h * (std::f64::consts::PI / (4.0 * n as f64)).cos();
            assert!(
                (cs.omega_max - omega).abs() <= 4.0 * f64::EPSILON * omega,
                "N = {n}: {} vs {omega}",
                cs.omega_max
            );
            assert!(cs.exact >= cs.element && cs.gershgorin <= cs.exact);
            assert_eq!(cs.element, cs.element_transit);
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
        ))
        .unwrap();
        assert!((cs.exact / cs.element - 1.0).abs() < 1e-14);
    }

    /// Every bisection is bounded: a bound that never covers the spectrum, or a non-finite one,
    /// is a typed error after at most `BOUND_DOUBLINGS` doublings, never a loop.
    #[test]
    fn bisections_stop_with_an_error_at_their_bounds() {
        let e = lift_above_spectrum(1.0, |_| false).unwrap_err();
        assert_eq!(e.iterations, BOUND_DOUBLINGS);
        assert!(bisect_top(f64::INFINITY, 0.0, |_| true).is_err());
        assert!(largest_eigenvalue(&[1.0], &[], f64::NAN).is_err());
        // A well-posed one closes to adjacent doubles: [0, 8] on "x > 3".
        let top = bisect_top(8.0, 0.0, |x| x > 3.0).unwrap();
        assert!((top - 3.0).abs() <= 4.0 * f64::EPSILON * 3.0, "{top}");
    }

    #[test]
    fn graded_bar_is_controlled_by_its_stiff_end() {
        let cs = CriticalStep::lumped(&crate::fixtures::graded_seed_bar(100).unwrap()).unwrap();
        assert_eq!(cs.controlling_element, 0);
        assert!(
            cs.exact >= cs.element,
            "Fried's bound is conservative for lumped mass"
        );
    }
}
