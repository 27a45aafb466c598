//! Exact d'Alembert solution of a homogeneous free-fixed bar under a Heaviside end traction.
//!
//! ```text
//!   sigma(0,t) = sigma0 H(t)                                   u(L,t) = 0
//!        <==|==========================================|//
//!           |  E, rho, A  (c = sqrt(E/rho), z = rho c)  |//  fixed end
//!           x = 0                                   x = L
//!   loaded free end                     fronts bounce between the ends, transit T = L/c
//! ```
//!
//! The bar is at rest for t < 0. With `H` the Heaviside step and `R(s) = max(s, 0)` the ramp,
//!
//! ```text
//! sigma(x,t) =  sigma0     * sum_{k>=0} (-1)^k [ H(t - (2kL + x)/c) + H(t - (2(k+1)L - x)/c) ]
//! v(x,t)     = -(sigma0/z) * sum_{k>=0} (-1)^k [ H(t - (2kL + x)/c) - H(t - (2(k+1)L - x)/c) ]
//! u(x,t)     = -(sigma0/z) * sum_{k>=0} (-1)^k [ R(t - (2kL + x)/c) - R(t - (2(k+1)L - x)/c) ]
//! ```
//!
//! The first family of terms are fronts travelling in +x (positions `c t - 2kL`), the second
//! fronts travelling in -x (positions `2(k+1)L - c t`). Stress reflects with factor +1 at the
//! fixed end and -1 at the loaded end; `sigma0 < 0` is compressive. Only the terms with
//! `2kL/c <= t + L/c` can be non-zero, so every sum here is finite. The solution has period
//! `4T` in t for t >= 0.
//!
//! Source: d'Alembert's solution, e.g. Graff, *Wave Motion in Elastic Solids* (1975), ch. 2;
//! conventions of courant's methods.md §2-3 (load on from t = 0 inclusive, `H(0) = 1`).

use crate::error::ReferenceError;

/// Relative tolerance within which a front is treated as sitting exactly on the evaluation
/// point.
///
/// A Heaviside argument `s` (a time) with `|s| <= FRONT_TOLERANCE * (T + |t|)` (capped at
/// `T/8`) counts as `s = 0`, so the chosen value at the front (1 for the right-continuous fields, 1/2 for the
/// means) is returned even when the caller's `x` and `t` carry round-off (e.g. `x = i h`,
/// `t = n dt` at Courant number 1). The same relative margin decides whether `x` lies in the
/// bar. Closed-form averages and energies do not use it: they are continuous in the front
/// positions.
pub const FRONT_TOLERANCE: f64 = 1e-10;

/// Times beyond this many periods `4T` are first reduced modulo `4T` (exact for t >= 0 by the
/// periodicity of the solution), which bounds every sum by a few hundred terms.
const DIRECT_PERIODS: f64 = 256.0;

/// Homogeneous elastic bar `0 <= x <= L`, loaded by the traction `sigma(0,t) = sigma0 H(t)` at
/// the free end x = 0 and fixed at x = L, at rest at t = 0.
///
/// Source: d'Alembert's solution, e.g. Graff, *Wave Motion in Elastic Solids* (1975), ch. 2;
/// conventions of courant's methods.md §2-3. Fields are f64 in any consistent unit system.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DalembertBar {
    length: f64,
    modulus: f64,
    density: f64,
    area: f64,
    sigma0: f64,
}

/// Energies of the bar at one time, each computed independently of the others.
///
/// `work = kinetic + strain` holds exactly for the continuum solution; the self-tests check it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Energies {
    /// Kinetic energy `int_0^L rho A v^2 / 2 dx`.
    pub kinetic: f64,
    /// Strain energy `int_0^L A sigma^2 / (2E) dx`.
    pub strain: f64,
    /// Work of the constant end force, `end_force() * u(0, t)`.
    pub work: f64,
}

/// Heaviside step `H(s)` with value `at_zero` for `|s| <= tol`.
fn heaviside(s: f64, at_zero: f64, tol: f64) -> f64 {
    if s > tol {
        1.0
    } else if s < -tol {
        0.0
    } else {
        at_zero
    }
}

/// Time at which the sums are evaluated, its front tolerance and the last term index needed.
#[derive(Debug, Clone, Copy)]
struct Clock {
    t: f64,
    tol: f64,
    k_max: usize,
}

impl DalembertBar {
    /// Builds the bar after validating its data.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] naming the first offending parameter if `length`,
    /// `modulus`, `density` or `area` is not positive and finite, or `sigma0` is not finite.
    pub fn new(
        length: f64,
        modulus: f64,
        density: f64,
        area: f64,
        sigma0: f64,
    ) -> Result<Self, ReferenceError> {
        Ok(Self {
            length: ReferenceError::require_positive("length", length)?,
            modulus: ReferenceError::require_positive("modulus", modulus)?,
            density: ReferenceError::require_positive("density", density)?,
            area: ReferenceError::require_positive("area", area)?,
            sigma0: ReferenceError::require_finite("sigma0", sigma0)?,
        })
    }

    /// The bar from data already validated by another reference's constructor.
    pub(crate) fn validated(
        length: f64,
        modulus: f64,
        density: f64,
        area: f64,
        sigma0: f64,
    ) -> Self {
        Self {
            length,
            modulus,
            density,
            area,
            sigma0,
        }
    }

    /// Bar length L (> 0).
    #[must_use]
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Young's modulus E (> 0).
    #[must_use]
    pub fn modulus(&self) -> f64 {
        self.modulus
    }

    /// Mass density rho (> 0).
    #[must_use]
    pub fn density(&self) -> f64 {
        self.density
    }

    /// Cross-section area A (> 0); enters only forces and energies.
    #[must_use]
    pub fn area(&self) -> f64 {
        self.area
    }

    /// Amplitude sigma0 of the end traction (any finite value; negative is compressive).
    #[must_use]
    pub fn sigma0(&self) -> f64 {
        self.sigma0
    }

    /// Bar wave speed `c = sqrt(E / rho)`.
    #[must_use]
    pub fn wave_speed(&self) -> f64 {
        (self.modulus / self.density).sqrt()
    }

    /// Impedance per unit area `z = rho c`; the velocity behind a stress jump `s` moving in +x
    /// is `-s / z` (methods.md §3).
    #[must_use]
    pub fn impedance(&self) -> f64 {
        self.density * self.wave_speed()
    }

    /// Transit time `T = L / c` of a front across the bar.
    #[must_use]
    pub fn transit_time(&self) -> f64 {
        self.length / self.wave_speed()
    }

    /// Nodal force at x = 0 equivalent to the traction: `F0 = -sigma0 A` (outward normal -x,
    /// methods.md §2).
    #[must_use]
    pub fn end_force(&self) -> f64 {
        -self.sigma0 * self.area
    }

    /// Stress `sigma(x, t) = sigma0 sum_k (-1)^k [H(t - (2kL + x)/c) + H(t - (2(k+1)L - x)/c)]`
    /// with `H(0) = 1` (right-continuous in t: the value just after a front arrives).
    ///
    /// Returns NaN for non-finite input or `x` outside `[0, L]`; a front within
    /// [`FRONT_TOLERANCE`] of `(x, t)` counts as arrived.
    #[must_use]
    pub fn stress(&self, x: f64, t: f64) -> f64 {
        self.stress_with(x, t, 1.0)
    }

    /// Stress with `H(0) = 1/2`: the mean of the limits in t before and after a front that
    /// sits exactly at `(x, t)`; elsewhere equal to [`Self::stress`].
    #[must_use]
    pub fn stress_mean(&self, x: f64, t: f64) -> f64 {
        self.stress_with(x, t, 0.5)
    }

    /// Velocity `v(x, t) = -(sigma0/z) sum_k (-1)^k [H(t - (2kL + x)/c) - H(t - (2(k+1)L - x)/c)]`
    /// with `H(0) = 1` (right-continuous in t).
    ///
    /// Returns NaN for non-finite input or `x` outside `[0, L]`.
    #[must_use]
    pub fn velocity(&self, x: f64, t: f64) -> f64 {
        self.velocity_with(x, t, 1.0)
    }

    /// Velocity with `H(0) = 1/2`: the mean of the limits in t at a front sitting exactly at
    /// `(x, t)`. This is what the full-step velocity of the central-difference method
    /// reproduces at such a node; elsewhere equal to [`Self::velocity`].
    #[must_use]
    pub fn velocity_mean(&self, x: f64, t: f64) -> f64 {
        self.velocity_with(x, t, 0.5)
    }

    /// Displacement `u(x, t) = -(sigma0/z) sum_k (-1)^k [R(t - (2kL + x)/c) - R(t - (2(k+1)L - x)/c)]`,
    /// `R(s) = max(s, 0)`; continuous, piecewise linear in x and t.
    ///
    /// Returns NaN for non-finite input or `x` outside `[0, L]`.
    #[must_use]
    pub fn displacement(&self, x: f64, t: f64) -> f64 {
        let Some(clock) = self.clock_at(x, t) else {
            return f64::NAN;
        };
        let (a, b) = self.family_sums(x, clock, |s| s.max(0.0));
        -(self.sigma0 / self.impedance()) * (a - b)
    }

    /// Exact mean of `sigma(., t)` over `[xa, xb]`, `0 <= xa < xb <= L`: what the stress of a
    /// linear element spanning `[xa, xb]` is compared with.
    ///
    /// Closed form, no quadrature: each front family term contributes `sigma0 (-1)^k` times the
    /// fraction of the interval behind its front, i.e. `clamp(c t - 2kL - xa, 0, xb - xa)` for
    /// +x fronts and `clamp(xb - (2(k+1)L - c t), 0, xb - xa)` for -x fronts, divided by
    /// `xb - xa`. It is therefore exact also when a front sits exactly at `xa` or `xb`.
    /// Returns NaN unless `xa < xb`, both in `[0, L]` and `t` finite.
    #[must_use]
    pub fn stress_average(&self, xa: f64, xb: f64, t: f64) -> f64 {
        let (Some(clock), true) = (self.clock_at(xa, t), self.in_bar(xb) && xa < xb) else {
            return f64::NAN;
        };
        let (l, ct, width) = (self.length, self.wave_speed() * clock.t, xb - xa);
        let mut behind = 0.0;
        for k in 0..=clock.k_max {
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            let forward = ct - 2.0 * k as f64 * l;
            let backward = 2.0 * (k + 1) as f64 * l - ct;
            behind += sign * ((forward - xa).clamp(0.0, width) + (xb - backward).clamp(0.0, width));
        }
        self.sigma0 * behind / width
    }

    /// Kinetic energy `int rho A v^2/2 dx`, strain energy `int A sigma^2/(2E) dx` and the work
    /// `end_force() * u(0, t)` of the constant end force.
    ///
    /// The integrals are exact: `[0, L]` is split at [`Self::front_positions`], the fields are
    /// constant on each piece and are evaluated at its midpoint. The work uses only the
    /// displacement, so `work = kinetic + strain` is an independent check. NaN if `t` is not
    /// finite.
    #[must_use]
    pub fn energies(&self, t: f64) -> Energies {
        let Some(mut clock) = self.clock_at(0.0, t) else {
            return Energies {
                kinetic: f64::NAN,
                strain: f64::NAN,
                work: f64::NAN,
            };
        };
        // Midpoints lie strictly between fronts: classify them exactly.
        clock.tol = 0.0;
        let mut cuts = vec![0.0];
        cuts.extend(
            self.front_positions(t)
                .into_iter()
                .filter(|&x| x > 0.0 && x < self.length),
        );
        cuts.push(self.length);
        let (z, a) = (self.impedance(), self.area);
        let (mut kinetic, mut strain) = (0.0, 0.0);
        for pair in cuts.windows(2) {
            let (x0, x1) = (pair[0], pair[1]);
            let (fwd, bwd) = self.family_sums(0.5 * (x0 + x1), clock, |s| heaviside(s, 0.5, 0.0));
            let sigma = self.sigma0 * (fwd + bwd);
            let v = -(self.sigma0 / z) * (fwd - bwd);
            kinetic += 0.5 * self.density * a * v * v * (x1 - x0);
            strain += 0.5 * a * sigma * sigma / self.modulus * (x1 - x0);
        }
        Energies {
            kinetic,
            strain,
            work: self.end_force() * self.displacement(0.0, t),
        }
    }

    /// Positions in `[0, L]` of all fronts at time t, sorted ascending without duplicates:
    /// `c t - 2kL` (moving in +x) and `2(k+1)L - c t` (moving in -x), k >= 0.
    ///
    /// For t < 0 or non-finite t the list is empty. A single Heaviside load carries one front,
    /// which coincides with its reflection at the ends (t a multiple of T).
    #[must_use]
    pub fn front_positions(&self, t: f64) -> Vec<f64> {
        let Some(clock) = self.clock_at(0.0, t) else {
            return Vec::new();
        };
        if clock.t < 0.0 {
            return Vec::new();
        }
        let (l, ct) = (self.length, self.wave_speed() * clock.t);
        let mut fronts: Vec<f64> = (0..=clock.k_max)
            .flat_map(|k| [ct - 2.0 * k as f64 * l, 2.0 * (k + 1) as f64 * l - ct])
            .filter(|x| (0.0..=l).contains(x))
            .collect();
        fronts.sort_by(f64::total_cmp);
        fronts.dedup();
        fronts
    }

    fn stress_with(&self, x: f64, t: f64, at_front: f64) -> f64 {
        let Some(clock) = self.clock_at(x, t) else {
            return f64::NAN;
        };
        let (a, b) = self.family_sums(x, clock, |s| heaviside(s, at_front, clock.tol));
        self.sigma0 * (a + b)
    }

    fn velocity_with(&self, x: f64, t: f64, at_front: f64) -> f64 {
        let Some(clock) = self.clock_at(x, t) else {
            return f64::NAN;
        };
        let (a, b) = self.family_sums(x, clock, |s| heaviside(s, at_front, clock.tol));
        -(self.sigma0 / self.impedance()) * (a - b)
    }

    /// True if `x` is in `[0, L]` up to the relative round-off margin [`FRONT_TOLERANCE`].
    fn in_bar(&self, x: f64) -> bool {
        let margin = FRONT_TOLERANCE * self.length;
        (-margin..=self.length + margin).contains(&x)
    }

    /// Validates `(x, t)` and prepares the evaluation time; `None` if the input is unusable.
    fn clock_at(&self, x: f64, t: f64) -> Option<Clock> {
        if !t.is_finite() || !self.in_bar(x) {
            return None;
        }
        let transit = self.transit_time();
        let period = 4.0 * transit;
        // Round-off in the caller's t grows with t; the cap keeps the sums bounded and only
        // matters for absurd times (beyond 1e9 T) where no front position is resolvable.
        let tol = (FRONT_TOLERANCE * (transit + t.abs())).min(0.125 * transit);
        let t = if t > DIRECT_PERIODS * period {
            t % period
        } else {
            t
        };
        // Terms with 2kT > t + T + tol vanish for every x in the bar; one spare term is kept.
        // A negative quotient saturates to 0 in the cast.
        let k_max = ((t + transit + tol) / (2.0 * transit)).floor() as usize + 1;
        Some(Clock { t, tol, k_max })
    }

    /// `(sum_k (-1)^k f(t - (2kL + x)/c), sum_k (-1)^k f(t - (2(k+1)L - x)/c))`.
    fn family_sums(&self, x: f64, clock: Clock, f: impl Fn(f64) -> f64) -> (f64, f64) {
        let (l, c) = (self.length, self.wave_speed());
        let (mut forward, mut backward) = (0.0, 0.0);
        for k in 0..=clock.k_max {
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            forward += sign * f(clock.t - (2.0 * k as f64 * l + x) / c);
            backward += sign * f(clock.t - (2.0 * (k + 1) as f64 * l - x) / c);
        }
        (forward, backward)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heaviside_takes_the_requested_value_only_within_the_tolerance() {
        assert_eq!(heaviside(1e-3, 0.5, 1e-9), 1.0);
        assert_eq!(heaviside(-1e-3, 0.5, 1e-9), 0.0);
        assert_eq!(heaviside(1e-12, 0.5, 1e-9), 0.5);
        assert_eq!(heaviside(0.0, 1.0, 0.0), 1.0);
        assert_eq!(heaviside(-1e-300, 1.0, 0.0), 0.0);
    }

    #[test]
    fn term_count_covers_every_contributing_term_and_stays_bounded_for_huge_times() {
        let bar = DalembertBar::new(1.0, 1.0, 1.0, 1.0, -1.0).unwrap();
        for &t in &[0.0, 0.99, 1.0, 2.0, 3.5, 20.5, 1000.0] {
            let clock = bar.clock_at(0.0, t).unwrap();
            // First omitted term k_max + 1 must vanish in both families for all x in [0, L].
            let k = (clock.k_max + 1) as f64;
            assert!(t - 2.0 * k < -clock.tol && t - (2.0 * k + 1.0) < -clock.tol);
        }
        assert!(bar.clock_at(0.5, 1e300).unwrap().k_max <= 3);
        assert!(bar.clock_at(0.5, 1000.0).unwrap().k_max <= 502);
        assert_eq!(bar.clock_at(0.5, -5.0).unwrap().k_max, 1);
    }
}
