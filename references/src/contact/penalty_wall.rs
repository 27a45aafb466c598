//! The penalty-regularised counterpart of the rigid wall: a bar hitting a unilateral penalty
//! spring, in closed form over the first two transits (Graff 1975, ch. 2, with a spring
//! boundary; methods.md §7).

use super::impact::ImpactBar;
use crate::error::ReferenceError;

/// A bar hitting a rigid wall through a penalty spring `k_s` (unilateral, massless): the
/// penalty-regularised counterpart of [`ImpactForce::rigid_wall`](super::ImpactForce::rigid_wall). Bar `(Z, c, L)`, velocity
/// `v0`, free far end, touching the unloaded spring at t = 0.
///
/// **Derivation.** Let u be the penetration (spring compression) of the contact end, `F = k_s u`.
/// The bar delivers the right-going invariant `a = N - Z v`, with `N = -F` and `v = u'`, so
/// `Z u' + k_s u = -a(t)`. For `t < 2T` (`T = L/c`) the bar ahead of the reflected wave is
/// undisturbed, `a = -Z v0`, and with `tau = Z/k_s`
///
/// ```text
///   F(t) = Z v0 (1 - exp(-t/tau)),                         0 <= t <= 2T   (first transit).
/// ```
///
/// The end emits `N + Z v = Z v0 - 2F`, which the free far end returns with reversed sign at
/// `t + 2T`: `a(t) = 2 F(t - 2T) - Z v0`, i.e. the delay equation
/// `tau F' + F = Z v0 - 2 F(t - 2T)`. On the second transit, with `sigma = (t - 2T)/tau` and
/// `E = exp(-2T/tau)`, its solution continuous at 2T is
///
/// ```text
///   F(t) = Z v0 [ (2 - E + 2 sigma) exp(-sigma) - 1 ],     2T <= t <= 4T, while F > 0.
/// ```
///
/// `(2 - E + 2 sigma) exp(-sigma)` rises until `sigma = E/2` and then falls to 0, so F has one
/// zero `sigma*`, the root of `ln(2 - E + 2 sigma) = sigma` (between 1.256 for `E -> 1` and 1.678
/// for `E -> 0`). If `sigma* tau <= 2T` the contact ends at `2T + sigma* tau` (the spring
/// unloads, the end leaves the wall); otherwise it lasts beyond 4T and this reference stops at
/// 4T. As `k_s -> inf` the force tends to the rigid-wall `Z v0` for `2T` (duration
/// `2T + 1.678 Z/k_s`). Source: 1D wave theory (Graff 1975, ch. 2) with a spring boundary;
/// methods.md §7.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PenaltyWallForce {
    bar: ImpactBar,
    velocity: f64,
    stiffness: f64,
}

impl PenaltyWallForce {
    /// Builds the case after validating its data.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if a bar value, `v0` or `stiffness` (k_s) is not
    /// positive and finite.
    pub fn new(bar: ImpactBar, v0: f64, stiffness: f64) -> Result<Self, ReferenceError> {
        Ok(Self {
            bar: ImpactBar::new(bar.impedance(), bar.wave_speed(), bar.length())?,
            velocity: ReferenceError::require_positive("v0", v0)?,
            stiffness: ReferenceError::require_positive("stiffness", stiffness)?,
        })
    }

    /// Rise time constant `tau = Z/k_s`.
    #[must_use]
    pub fn time_constant(&self) -> f64 {
        self.bar.impedance() / self.stiffness
    }

    /// `E = exp(-2T/tau)` and `Theta = 2T/tau`.
    fn decay(&self) -> (f64, f64) {
        let theta = 2.0 * self.bar.transit_time() / self.time_constant();
        ((-theta).exp(), theta)
    }

    /// Root `sigma*` of `ln(2 - E + 2 sigma) = sigma` on `sigma > E/2` (Newton from the right:
    /// the function is concave and decreasing there, so the iterates fall monotonically).
    fn release_sigma(&self) -> f64 {
        let (e, _) = self.decay();
        let mut sigma: f64 = 4.0;
        for _ in 0..100 {
            let h = (2.0 - e + 2.0 * sigma).ln() - sigma;
            let dh = 2.0 / (2.0 - e + 2.0 * sigma) - 1.0;
            let next = sigma - h / dh;
            if (next - sigma).abs() <= 4.0 * f64::EPSILON * sigma {
                return next;
            }
            sigma = next;
        }
        sigma
    }

    /// End of contact, `2T + sigma* tau`, if it falls within the second transit; `None` if the
    /// contact lasts beyond `4T` (not covered by this reference).
    #[must_use]
    pub fn duration(&self) -> Option<f64> {
        let (_, theta) = self.decay();
        let sigma = self.release_sigma();
        (sigma <= theta).then(|| 2.0 * self.bar.transit_time() + sigma * self.time_constant())
    }

    /// Last time covered: `duration()` or `4T`.
    #[must_use]
    pub fn valid_until(&self) -> f64 {
        self.duration().unwrap_or(4.0 * self.bar.transit_time())
    }

    /// Contact force at t (compression positive): the two closed forms of the type docs; 0 for
    /// `t < 0` and after [`Self::duration`]; NaN for `t > 4T` when the contact outlasts 4T, or
    /// for NaN.
    #[must_use]
    pub fn force(&self, t: f64) -> f64 {
        if t.is_nan() {
            return f64::NAN;
        }
        if t < 0.0 {
            return 0.0;
        }
        let (z, v0, tau) = (self.bar.impedance(), self.velocity, self.time_constant());
        let two_t = 2.0 * self.bar.transit_time();
        match self.duration() {
            Some(end) if t >= end => return 0.0,
            None if t > 2.0 * two_t => return f64::NAN,
            _ => {}
        }
        if t <= two_t {
            -z * v0 * (-t / tau).exp_m1()
        } else {
            let (e, _) = self.decay();
            let sigma = (t - two_t) / tau;
            (z * v0 * ((2.0 - e + 2.0 * sigma) * (-sigma).exp() - 1.0)).max(0.0)
        }
    }

    /// Impulse `int F dt` over the contact, if it ends within the second transit:
    ///
    /// ```text
    ///   Z v0 [ 2T - tau (1 - E) ] + Z v0 tau [ (2 - E)(1 - e^-s) + 2 (1 - (1 + s) e^-s) - s ],
    ///   s = sigma*.
    /// ```
    ///
    /// Tends to `2 Z v0 T = 2 m v0` (elastic bounce) as `k_s -> inf`.
    #[must_use]
    pub fn impulse(&self) -> Option<f64> {
        self.duration()?;
        let (z, v0, tau) = (self.bar.impedance(), self.velocity, self.time_constant());
        let (e, theta) = self.decay();
        let s = self.release_sigma();
        let es = (-s).exp();
        let first = 2.0 * self.bar.transit_time() + tau * (-theta).exp_m1();
        let second = tau * ((2.0 - e) * (1.0 - es) + 2.0 * (1.0 - (1.0 + s) * es) - s);
        Some(z * v0 * (first + second))
    }
}
