//! What an evaluation of the graded bar's field costs, known before evaluating: so that a caller
//! can bound the reference's work (or refuse a grading it cannot afford) up front.
//!
//! [`GradedBar::state`] uses route (a) (de Hoog's inversion, a fixed number of Bessel
//! evaluations) while the difficulty `D` of [`LAPLACE_DIFFICULTY_LIMIT`] is below 5 and route
//! (b) beyond. Route (b) integrates a lattice of characteristics: with `c` coarsest cells per
//! transit ([`GradedBar::characteristic_cells`], growing like `kappa_max T = (sqrt(E_max/E_min)
//! - 1)/2`), `2^l` refinement on level `l` of [`CHARACTERISTIC_LEVELS`] and `t + tau <= t + T`,
//! it visits at most `2 ((t + T)/T) (c 2^l)^2` nodes per level (the lattice has `2 c 2^l` lines
//! per period `2T`, and each eta-line meets at most one period of xi-lines). Work is counted in
//! those lattice nodes; route (a) counts as [`ROUTE_A_WORK`] of them.
//!
//! Measured here (release build, one core): 6 to 7 ns per lattice node (seed bar at 10 and
//! 100 transits, modulus ratio 100 at 10 transits), 0.17 to 0.35 ms per route-(a) evaluation.

use super::bar::GradedBar;
use super::characteristics::{CHARACTERISTIC_LEVELS, CHARACTERISTIC_TRANSITS_MAX};
use super::field::LAPLACE_DIFFICULTY_LIMIT;

/// The work of one route-(a) evaluation in lattice-node equivalents: 0.35 ms (the slowest
/// measured) at 7 ns per node.
pub const ROUTE_A_WORK: f64 = 5.0e4;

impl GradedBar {
    /// Upper bound of the work of one [`Self::state`] evaluation at time `t`, anywhere in the bar,
    /// in lattice nodes (module docs); `None` where the field is not available (`t` beyond
    /// [`CHARACTERISTIC_TRANSITS_MAX`] transits of a graded bar, or not finite).
    #[must_use]
    pub fn evaluation_work(&self, t: f64) -> Option<f64> {
        if !t.is_finite() {
            return None;
        }
        let t = t.max(0.0);
        // The hardest point is the loaded end (tau = 0): the longest elapsed time.
        if self.gradient() == 0.0 || self.laplace_difficulty(t) < LAPLACE_DIFFICULTY_LIMIT {
            return Some(ROUTE_A_WORK);
        }
        let transit = self.transit_time();
        if t > CHARACTERISTIC_TRANSITS_MAX * transit {
            return None;
        }
        let cells = self.characteristic_cells() as f64;
        let levels: f64 = (0..CHARACTERISTIC_LEVELS)
            .map(|l| (cells * f64::from(1u32 << l)).powi(2))
            .sum();
        Some(2.0 * (t + transit) / transit * levels)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn work_grows_with_the_grading_and_the_time_and_ends_where_the_field_does() {
        let seed = GradedBar::seed_fig2();
        let early = seed.evaluation_work(0.5 * seed.transit_time()).unwrap();
        assert_eq!(early, ROUTE_A_WORK, "the seed bar at 0.5 T uses route (a)");
        let late = seed.evaluation_work(100.0 * seed.transit_time()).unwrap();
        assert!(late > 50.0 * early, "{late}");
        let strong = GradedBar::new(1.0, 1e12, 1.0, 1.0, 1.0, -1.0).unwrap();
        let work = strong.evaluation_work(1.5 * strong.transit_time()).unwrap();
        assert!(work > 1e12, "modulus ratio 1e12: {work:e} lattice nodes");
        assert_eq!(seed.evaluation_work(2000.0 * seed.transit_time()), None);
        assert_eq!(seed.evaluation_work(f64::NAN), None);
    }
}
