//! The linearly graded bar (methods.md §4): its data, the closed forms of travel time, transit
//! and fronts, and the jump law of the passes of the load front. Both full-field routes and the
//! layered bars start from here.
//!
//! # Closed forms (travel time, transit, fronts)
//!
//! ```text
//!   tau(x) = int_0^x dx'/c = 2 sqrt(rho) (sqrt(E(x)) - sqrt(E1))/b = 2 rho x/(z(x) + z1)
//!   T      = tau(L) = 2 L sqrt(rho)/(sqrt(E1) + sqrt(E2))
//!   z      = z1 + b tau/2          (z is linear in the travel time)
//!   x(tau) = tau (z1 + b tau/4)/rho,   first-transit front x_f(t) = x(t), 0 <= t <= T
//! ```
//!
//! The rationalised forms are used: they have no cancellation and reduce to `x/c` and `c t`
//! for `b -> 0` (exactly for `b = 0`).
//!
//! # Characteristics and the transport of jumps
//!
//! With the wave amplitudes `p = (sigma/sqrt(z) - sqrt(z) v)/2` (running toward the fixed end)
//! and `m = (sigma/sqrt(z) + sqrt(z) v)/2` (running back), i.e. `sigma = sqrt(z) (p + m)`,
//! `v = (m - p)/sqrt(z)`, the bar equations become, in the travel-time coordinate,
//!
//! ```text
//!   (d/dt + d/dtau) p = -kappa(tau) m,     (d/dt - d/dtau) m = +kappa(tau) p,
//!   kappa = (1/2) d ln z/dtau = b/(4 z) = b/(4 z1 + 2 b tau),
//!   tau = 0:  p + m = sigma0/sqrt(z1)  (t >= 0),        tau = T:  m = p  (v = 0).
//! ```
//!
//! Across a front running toward the fixed end `m` is continuous, so its jump obeys
//! `d[p]/dt = -kappa [m] = 0`: **`[p]` is constant along the ray** (the transport equation; the
//! energy flux `A [sigma]^2/Z` is conserved). Hence `[sigma] = sqrt(z) [p]` scales like
//! `sqrt(Z(x)/Z1) = (E(x)/E1)^(1/4)`. The load creates `[p] = sigma0/sqrt(z1)`. At the fixed
//! end `m = p` gives `[m] = [p]` (stress reflection +1); at the loaded end `p + m` is held, so
//! `[p] = -[m]` (reflection -1). Therefore pass k = 0, 1, ... toward the fixed end reaches x at
//! `t = 2kT + tau(x)`, the returning pass at `t = 2(k+1)T - tau(x)`, both with
//!
//! ```text
//!   [sigma] = (-1)^k sigma0 sqrt(z(x)/z1),   [v] = -[sigma]/z (toward the fixed end), +[sigma]/z (back).
//! ```
//!
//! Between fronts the field is smooth but not constant (the grading scatters continuously),
//! which is why two full-field routes are provided.

use crate::dalembert::FRONT_TOLERANCE;
use crate::error::ReferenceError;

/// Free-fixed bar with Young's modulus linear in x, `E(x) = E1 + (E2 - E1) x/L`, constant
/// density and area, loaded by `sigma(0,t) = sigma0 H(t)` at x = 0 and fixed at x = L.
///
/// Source: module documentation (methods.md §4). Evaluation methods return NaN for points
/// outside `[0, L]` or non-finite input and zero before the first front arrives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GradedBar {
    length: f64,
    modulus_loaded: f64,
    modulus_fixed: f64,
    density: f64,
    area: f64,
    sigma0: f64,
}

/// Stress and particle velocity at one point and time (per unit area).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldPoint {
    /// Stress sigma.
    pub stress: f64,
    /// Particle velocity v = u_t.
    pub velocity: f64,
}

impl FieldPoint {
    pub(super) const NAN: Self = Self {
        stress: f64::NAN,
        velocity: f64::NAN,
    };
    pub(super) const ZERO: Self = Self {
        stress: 0.0,
        velocity: 0.0,
    };
}

/// Direction in which a front travels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// From the loaded end x = 0 toward the fixed end x = L.
    TowardFixedEnd,
    /// From the fixed end back toward the loaded end.
    TowardLoadedEnd,
}

/// One passage of the load front through a point (closed form, see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pass {
    /// Round trip k = 0, 1, ...: the pass left the loaded end at `2kT`.
    pub round_trip: usize,
    /// Direction of travel.
    pub direction: Direction,
    /// Arrival time: `2kT + tau(x)` toward the fixed end, `2(k+1)T - tau(x)` back.
    pub time: f64,
    /// Stress jump `(-1)^k sigma0 sqrt(z(x)/z1)` (after minus before).
    pub stress_jump: f64,
    /// Velocity jump `-[sigma]/z` toward the fixed end, `+[sigma]/z` back.
    pub velocity_jump: f64,
}

impl GradedBar {
    /// Builds the bar after validating its data.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] naming the first offending parameter if `length`,
    /// `modulus_loaded`, `modulus_fixed`, `density` or `area` is not positive and finite, or
    /// `sigma0` is not finite.
    pub fn new(
        length: f64,
        modulus_loaded: f64,
        modulus_fixed: f64,
        density: f64,
        area: f64,
        sigma0: f64,
    ) -> Result<Self, ReferenceError> {
        Ok(Self {
            length: ReferenceError::require_positive("length", length)?,
            modulus_loaded: ReferenceError::require_positive("modulus_loaded", modulus_loaded)?,
            modulus_fixed: ReferenceError::require_positive("modulus_fixed", modulus_fixed)?,
            density: ReferenceError::require_positive("density", density)?,
            area: ReferenceError::require_positive("area", area)?,
            sigma0: ReferenceError::require_finite("sigma0", sigma0)?,
        })
    }

    /// The bar of the seed paper's Fig. 2: `E1 = 16` (loaded end), `E2 = 1`, `rho = L = A = 1`,
    /// `sigma0 = -1` (transit `T = 0.4`).
    #[must_use]
    pub fn seed_fig2() -> Self {
        Self {
            length: 1.0,
            modulus_loaded: 16.0,
            modulus_fixed: 1.0,
            density: 1.0,
            area: 1.0,
            sigma0: -1.0,
        }
    }

    /// Bar length L (> 0).
    #[must_use]
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Modulus E1 at the loaded end x = 0 (> 0).
    #[must_use]
    pub fn modulus_loaded(&self) -> f64 {
        self.modulus_loaded
    }

    /// Modulus E2 at the fixed end x = L (> 0).
    #[must_use]
    pub fn modulus_fixed(&self) -> f64 {
        self.modulus_fixed
    }

    /// Mass density rho (> 0).
    #[must_use]
    pub fn density(&self) -> f64 {
        self.density
    }

    /// Cross-section area A (> 0); enters only forces.
    #[must_use]
    pub fn area(&self) -> f64 {
        self.area
    }

    /// Amplitude sigma0 of the end traction (finite; negative is compressive).
    #[must_use]
    pub fn sigma0(&self) -> f64 {
        self.sigma0
    }

    /// Modulus gradient `b = (E2 - E1)/L`.
    #[must_use]
    pub fn gradient(&self) -> f64 {
        (self.modulus_fixed - self.modulus_loaded) / self.length
    }

    /// `E(x) = E1 + (E2 - E1) x/L`.
    #[must_use]
    pub fn modulus(&self, x: f64) -> f64 {
        self.modulus_loaded + (self.modulus_fixed - self.modulus_loaded) * (x / self.length)
    }

    /// Local wave speed `c(x) = sqrt(E(x)/rho)`.
    #[must_use]
    pub fn wave_speed(&self, x: f64) -> f64 {
        (self.modulus(x) / self.density).sqrt()
    }

    /// Local impedance per unit area `z(x) = sqrt(rho E(x)) = rho c(x)` (bar impedance
    /// `Z = A z`).
    #[must_use]
    pub fn impedance(&self, x: f64) -> f64 {
        (self.density * self.modulus(x)).sqrt()
    }

    /// Nodal force at x = 0 equivalent to the traction: `F0 = -sigma0 A` (methods.md §2).
    #[must_use]
    pub fn end_force(&self) -> f64 {
        -self.sigma0 * self.area
    }

    pub(super) fn z1(&self) -> f64 {
        (self.density * self.modulus_loaded).sqrt()
    }

    pub(super) fn z2(&self) -> f64 {
        (self.density * self.modulus_fixed).sqrt()
    }

    /// Transit time `T = 2 L sqrt(rho)/(sqrt(E1) + sqrt(E2))` of a front across the bar.
    #[must_use]
    pub fn transit_time(&self) -> f64 {
        2.0 * self.density * self.length / (self.z1() + self.z2())
    }

    /// Travel time from the loaded end, `tau(x) = 2 sqrt(rho)(sqrt(E(x)) - sqrt(E1))/b`,
    /// evaluated as `2 rho x/(z(x) + z1)` (no cancellation; `x/c` for `b = 0`).
    #[must_use]
    pub fn travel_time(&self, x: f64) -> f64 {
        2.0 * self.density * x / (self.impedance(x) + self.z1())
    }

    /// Inverse of [`Self::travel_time`]: `x(tau) = tau (z1 + b tau/4)/rho`.
    #[must_use]
    pub fn position_at_travel_time(&self, tau: f64) -> f64 {
        tau * (self.z1() + 0.25 * self.gradient() * tau) / self.density
    }

    /// Impedance per unit area at travel time tau: `z = z1 + b tau/2`.
    pub(super) fn impedance_at_travel_time(&self, tau: f64) -> f64 {
        self.z1() + 0.5 * self.gradient() * tau
    }

    /// Position `x_f(t) = x(t)` of the first front during its first transit `0 <= t <= T`;
    /// `None` outside that interval.
    #[must_use]
    pub fn front_position(&self, t: f64) -> Option<f64> {
        (0.0..=self.transit_time())
            .contains(&t)
            .then(|| self.position_at_travel_time(t).min(self.length))
    }

    /// Stress jump across the first front at x: `sigma0 (E(x)/E1)^(1/4) = sigma0 sqrt(Z(x)/Z1)`.
    #[must_use]
    pub fn first_jump(&self, x: f64) -> f64 {
        self.sigma0 * (self.modulus(x) / self.modulus_loaded).sqrt().sqrt()
    }

    /// Positions in `[0, L]` of all fronts at time t, ascending, without duplicates: travel
    /// times `t - 2kT` (toward the fixed end) and `2(k+1)T - t` (back) mapped by
    /// [`Self::position_at_travel_time`]. Empty for t < 0 or non-finite t.
    #[must_use]
    pub fn front_positions(&self, t: f64) -> Vec<f64> {
        if !t.is_finite() || t < 0.0 {
            return Vec::new();
        }
        let transit = self.transit_time();
        let k_max = (t / (2.0 * transit)).floor() as usize + 1;
        let mut xs: Vec<f64> = (0..=k_max)
            .flat_map(|k| {
                let k = k as f64;
                [t - 2.0 * k * transit, 2.0 * (k + 1.0) * transit - t]
            })
            .filter(|tau| (0.0..=transit).contains(tau))
            .map(|tau| self.position_at_travel_time(tau).clamp(0.0, self.length))
            .collect();
        xs.sort_by(f64::total_cmp);
        xs.dedup();
        xs
    }

    /// All passes of the load front through x up to `t_max`, in time order, with their closed
    /// form arrival times and jumps (module documentation). Empty for x outside the bar.
    #[must_use]
    pub fn passes(&self, x: f64, t_max: f64) -> Vec<Pass> {
        if !self.in_bar(x) || !t_max.is_finite() {
            return Vec::new();
        }
        let x = x.clamp(0.0, self.length);
        let transit = self.transit_time();
        let tau = self.travel_time(x);
        let z = self.impedance(x);
        let amplitude = self.sigma0 * (z / self.z1()).sqrt();
        let mut out = Vec::new();
        for k in 0usize.. {
            let sign = if k.is_multiple_of(2) { 1.0 } else { -1.0 };
            let toward = 2.0 * k as f64 * transit + tau;
            if toward > t_max {
                break;
            }
            out.push(Pass {
                round_trip: k,
                direction: Direction::TowardFixedEnd,
                time: toward,
                stress_jump: sign * amplitude,
                velocity_jump: -sign * amplitude / z,
            });
            let back = 2.0 * (k + 1) as f64 * transit - tau;
            if back <= t_max {
                out.push(Pass {
                    round_trip: k,
                    direction: Direction::TowardLoadedEnd,
                    time: back,
                    stress_jump: sign * amplitude,
                    velocity_jump: sign * amplitude / z,
                });
            }
        }
        out
    }

    /// `kappa(tau) = b/(4 z(tau))`, the coupling of the two wave amplitudes.
    pub(super) fn kappa(&self, tau: f64) -> f64 {
        let b = self.gradient();
        b / (4.0 * self.z1() + 2.0 * b * tau)
    }

    /// Largest coupling `kappa_max = |b|/(4 z_min)` (at the soft end); `1/kappa_max` is the
    /// time scale on which the field varies between fronts.
    pub(super) fn kappa_max(&self) -> f64 {
        0.25 * self.gradient().abs() / self.z1().min(self.z2())
    }

    /// True if x is in `[0, L]` up to the relative margin [`FRONT_TOLERANCE`].
    pub(super) fn in_bar(&self, x: f64) -> bool {
        let margin = FRONT_TOLERANCE * self.length;
        x.is_finite() && (-margin..=self.length + margin).contains(&x)
    }

    /// Time within which a front counts as sitting on the evaluation point (as in
    /// [`crate::dalembert`]).
    pub(super) fn time_tolerance(&self, t: f64) -> f64 {
        let transit = self.transit_time();
        (FRONT_TOLERANCE * (transit + t.abs())).min(0.125 * transit)
    }
}
