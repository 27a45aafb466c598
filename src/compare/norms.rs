//! Error norms of an element-stress profile against exact element averages.
//!
//! All norms are normalised by the stress scale `|sigma0|` and the bar length `L` (point values
//! of another code weigh their cells instead of `h_e`, [`ErrorNorms::weighted`]):
//!
//! ```text
//!   L1   = (1/L) sum_e h_e |sigma_e - sigma_ref,e| / |sigma0|
//!   L2   = sqrt( (1/L) sum_e h_e (sigma_e - sigma_ref,e)^2 ) / |sigma0|
//!   Linf = max_e |sigma_e - sigma_ref,e| / |sigma0|
//!   overshoot = max(0, max_e s sigma_e - max_x s sigma(x,t)) / |sigma0|,  s = sign(sigma0)
//!   tv_ratio  = sum_e |sigma_{e+1} - sigma_e| / sum_e |sigma_ref,e+1 - sigma_ref,e|
//! ```
//!
//! The overshoot measures how far the numerical stress goes beyond the exact solution's extreme
//! value in the direction of the load: for a step front it is the Gibbs-like overshoot behind
//! the front as a fraction of the jump, which tends to 27.4 % for the Airy front of lumped CD at
//! Co < 1 (methods.md §3). An overshoot against a lower plateau than the extreme is not counted.

use courant_solver::Mesh;

/// Error norms of one profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrorNorms {
    /// Normalised L1 error.
    pub l1: f64,
    /// Normalised L2 error.
    pub l2: f64,
    /// Normalised max error.
    pub linf: f64,
    /// Overshoot beyond the exact envelope, fraction of the jump.
    pub overshoot: f64,
    /// Total variation of the element stresses over that of the exact element averages,
    /// `sum_e |sigma_{e+1} - sigma_e| / sum_e |sigma_ref,e+1 - sigma_ref,e|`: 1 for a profile
    /// without spurious oscillations, above 1 when it oscillates. `None` where the exact
    /// profile has no variation (one element, or no front in the bar yet): the ratio is
    /// undefined there.
    pub tv_ratio: Option<f64>,
}

impl ErrorNorms {
    /// Compute the norms of `stress` against `reference` (exact element averages) and `extreme`
    /// (the largest `s sigma_exact` over the bar): [`ErrorNorms::weighted`] with the element
    /// lengths `h_e` as weights and the mesh length as `L`.
    pub fn of(
        mesh: &Mesh,
        stress: &[f64],
        reference: &[f64],
        extreme: f64,
        scale: f64,
        sign: f64,
    ) -> Self {
        let lengths: Vec<f64> = (0..stress.len()).map(|e| mesh.element_length(e)).collect();
        Self::weighted(
            &lengths,
            mesh.length(),
            stress,
            reference,
            extreme,
            scale,
            sign,
        )
    }

    /// The norms with weight `w_i` for value `i` and length `L` (the formulas of the module with
    /// `h_e` replaced by `w_i`): element lengths for element averages, cell lengths for point
    /// values (each point's cell runs from the midpoint with its left neighbour, or the bar's
    /// start, to the midpoint with its right neighbour, or the bar's end; on points that include
    /// both ends this is the trapezoid rule, and the weights sum to `L`).
    pub fn weighted(
        weights: &[f64],
        length: f64,
        stress: &[f64],
        reference: &[f64],
        extreme: f64,
        scale: f64,
        sign: f64,
    ) -> Self {
        let (mut l1, mut l2, mut linf, mut overshoot) = (0.0, 0.0, 0.0_f64, 0.0_f64);
        for e in 0..stress.len() {
            let h = weights[e];
            let err = (stress[e] - reference[e]).abs();
            l1 += h * err;
            l2 += h * err * err;
            linf = linf.max(err);
            overshoot = overshoot.max(sign * stress[e] - extreme);
        }
        let variation = |v: &[f64]| v.windows(2).map(|w| (w[1] - w[0]).abs()).sum::<f64>();
        let exact_variation = variation(reference);
        Self {
            l1: l1 / length / scale,
            l2: (l2 / length).sqrt() / scale,
            linf: linf / scale,
            overshoot: overshoot / scale,
            tv_ratio: (exact_variation > 0.0).then(|| variation(stress) / exact_variation),
        }
    }

    /// The worst (largest) of each norm over several profiles (the TV ratio over the profiles
    /// where it is defined).
    pub fn worst(norms: impl IntoIterator<Item = ErrorNorms>) -> Option<ErrorNorms> {
        norms.into_iter().reduce(|a, b| ErrorNorms {
            l1: a.l1.max(b.l1),
            l2: a.l2.max(b.l2),
            linf: a.linf.max(b.linf),
            overshoot: a.overshoot.max(b.overshoot),
            tv_ratio: match (a.tv_ratio, b.tv_ratio) {
                (Some(x), Some(y)) => Some(x.max(y)),
                (x, y) => x.or(y),
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn norms_of_a_single_wrong_element() {
        let mesh = Mesh::uniform(1.0, 4).unwrap();
        let n = ErrorNorms::of(
            &mesh,
            &[-1.0, -1.5, 0.0, 0.0],
            &[-1.0, -1.0, 0.0, 0.0],
            1.0,
            1.0,
            -1.0,
        );
        assert_eq!(n.l1, 0.125);
        assert_eq!(n.l2, (0.25_f64 * 0.25).sqrt());
        assert_eq!(n.linf, 0.5);
        assert_eq!(n.overshoot, 0.5);
        assert_eq!(n.tv_ratio, Some(2.0));
    }

    #[test]
    fn the_tv_ratio_of_a_profile_without_exact_variation_is_undefined() {
        let mesh = Mesh::uniform(1.0, 1).unwrap();
        let n = ErrorNorms::of(&mesh, &[-0.5], &[-0.25], 1.0, 1.0, -1.0);
        assert_eq!(n.tv_ratio, None);
        assert!(n.l1.is_finite() && n.linf.is_finite());
    }
}
