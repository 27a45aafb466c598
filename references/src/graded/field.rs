//! The default evaluation of the graded bar's field: route (a) while it is cheap and accurate,
//! route (b) beyond (the difficulty `D` of [`LAPLACE_DIFFICULTY_LIMIT`]).

use super::bar::{FieldPoint, GradedBar};

/// Largest difficulty `D = max((t - tau(x))/T, kappa_max (t - tau(x))/1.7)` for which
/// [`GradedBar::state`] uses route (a); beyond it route (a) needs more abscissae than it is
/// calibrated for and route (b) is used instead. `kappa_max = |b|/(4 z_min)` is the largest
/// coupling of the two wave amplitudes (the characteristic system of the bar): `D` counts the
/// transits for
/// moderate gradings (seed bar: `kappa_max T = 1.5`) and the variation time `1/kappa_max` of
/// the field for strong ones.
pub const LAPLACE_DIFFICULTY_LIMIT: f64 = 5.0;

impl GradedBar {
    /// Stress and velocity at `(x, t)`, right-continuous in t (a front exactly at x has
    /// arrived, as in [`crate::dalembert`]).
    ///
    /// Uses route (a), [`Self::state_laplace`], while the difficulty `D` of
    /// [`LAPLACE_DIFFICULTY_LIMIT`] is below 5 (for the seed bar: `t - tau(x) < 5T`) and
    /// route (b), [`Self::state_characteristics`], beyond. Both agree to 1e-11..1e-10 |sigma0|
    /// (measured; the tests assert 1e-9). NaN for x outside `[0, L]`, non-finite input or
    /// (graded bars) `t > 1000 T`; zero before the first front arrives.
    #[must_use]
    pub fn state(&self, x: f64, t: f64) -> FieldPoint {
        if !self.in_bar(x) || !t.is_finite() {
            return FieldPoint::NAN;
        }
        let elapsed = t - self.travel_time(x.clamp(0.0, self.length()));
        if self.gradient() == 0.0 || self.laplace_difficulty(elapsed) < LAPLACE_DIFFICULTY_LIMIT {
            self.state_laplace(x, t)
        } else {
            self.state_characteristics(x, t)
        }
    }

    /// Stress of [`Self::state`].
    #[must_use]
    pub fn stress(&self, x: f64, t: f64) -> f64 {
        self.state(x, t).stress
    }

    /// Velocity of [`Self::state`].
    #[must_use]
    pub fn velocity(&self, x: f64, t: f64) -> f64 {
        self.state(x, t).velocity
    }

    /// Stress of [`Self::state`] at every x of `xs` (a profile at one time).
    #[must_use]
    pub fn stress_profile(&self, xs: &[f64], t: f64) -> Vec<f64> {
        xs.iter().map(|&x| self.stress(x, t)).collect()
    }
}
