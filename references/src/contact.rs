//! Contact references: the stability limit of penalty and bipenalty contact on a lumped bar, and
//! the exact contact forces of one-dimensional impact.
//!
//! Conventions are those of methods.md §1 and §7: two-node linear elements of length h, lumped
//! mass, `k = E A/h`, `m = rho A h`, `c = sqrt(E/rho)`, `Z = rho c A`; contact penalties are the
//! nodal stiffness `k_s` and the nodal mass `m_p`, in dimensionless form
//!
//! ```text
//!   beta_s = k_s h/(E A) = k_s/k,    beta_m = m_p/(rho A h) = m_p/m,
//!   r = (k_s/m_p)/omega_max,0^2 = beta_s/(4 beta_m)     (omega_max,0 = 2c/h, lumped, uniform)
//!   Lambda = omega^2 h^2/c^2,        Cr = 2/sqrt(Lambda_max)   (central difference).
//! ```
//!
//! # Part 1: critical Courant number of the bipenalized Signorini problem
//!
//! A semi-infinite uniform lumped bar, nodes `j = 0, 1, 2, ...`, is in contact with a rigid wall
//! at node 0, which carries the spring `k_s` and the extra mass `m_p`. In units `k = m = 1` the
//! eigenproblem `K u = Lambda M u` reads
//!
//! ```text
//!   interior (j >= 1):  -u_{j-1} + 2 u_j - u_{j+1} = Lambda u_j
//!   contact node 0:     (1 + kappa) u_0 - u_1      = Lambda (1/2 + mu) u_0,
//!   kappa = beta_s,  mu = beta_m.
//! ```
//!
//! The interior admits `u_j = q^j` with `q + 1/q = 2 - Lambda`: for `0 <= Lambda <= 4`, `|q| = 1`
//! (the continuous spectrum, whose top `Lambda = 4`, `q = -1`, is the contact-free limit
//! `Cr = 1`); for `Lambda > 4` both roots are real and negative and the mode decays into the bar
//! only with the root `-1 < q < 0`. The contact row then fixes `q = 1 + kappa - (1/2 + mu) Lambda`;
//! multiplying it by q and using `Lambda = 2 - q - 1/q` gives the quadratic in q
//!
//! ```text
//!   p(q) = (mu - 1/2) q^2 + (kappa - 2 mu) q + (mu + 1/2) = 0,
//!   discriminant D = 1 + kappa (kappa - 4 mu),
//! ```
//!
//! and eliminating q instead gives methods.md's quadratic in Lambda,
//! `(mu^2 - 1/4) Lambda^2 + (1 - 2 mu kappa) Lambda + kappa^2 = 0` (same discriminant). Its two
//! roots are `Lambda(q_1)`, `Lambda(q_2)`; the admissible one is the root whose
//! `q = 1 + kappa - (1/2 + mu) Lambda` lies in `(-1, 0)`, i.e.
//! `4 < Lambda < (2 + kappa)/(1/2 + mu)`.
//!
//! **Which root, and when.** `p(0) = mu + 1/2 > 0` and `p(-1) = 4 mu - kappa`.
//! - `kappa > 4 mu` (r > 1): p changes sign on `(-1, 0)`, so exactly one root is admissible.
//! - `kappa <= 4 mu` (r <= 1): no root lies in `(-1, 0)`. For `mu <= 1/2` p is concave (or linear)
//!   and positive at both ends of `[-1, 0]`; for `mu > 1/2` two roots inside would need the vertex
//!   inside, `2 mu < kappa < 4 mu - 1`, and `D > 0`, i.e. `kappa (4 mu - kappa) < 1`, but then
//!   `kappa > 1` and `4 mu - kappa > 1`. So there is no localized mode and `Cr = 1`.
//!
//! Hence `beta_s/beta_m = 4` (r = 1) is a sharp threshold, for every `beta_s`. It is sharp even
//! on a finite bar with a free far end: flipping the sign of every other entry turns `4 M - K`
//! into the free-free chain Laplacian (positive semidefinite, null vector constant) plus
//! `(4 mu - kappa)` on the contact diagonal, so `Lambda_max <= 4` iff `kappa <= 4 mu`.
//!
//! **Cancellation-free root.** Writing `q = -s`, the admissible `s` in `(0, 1)` is
//!
//! ```text
//!   s = (1 + 2 mu) / ( (kappa - 2 mu) + sqrt(1 + kappa (kappa - 4 mu)) ),
//!   Lambda = (1 + s)^2 / s,        Cr = 2/sqrt(Lambda) = 2 sqrt(s)/(1 + s),
//! ```
//!
//! the "citardauq" form of the root (the product of the roots of p is `(2 mu + 1)/(2 mu - 1)`):
//! for `kappa > 4 mu` every term is positive, so nothing cancels, while the textbook quadratic
//! formula for Lambda subtracts numbers of size `(mu kappa)^2` to form D and loses all its digits
//! once `beta_s` exceeds about 1e7. For `mu > 1/2` the other root `(b + sqrt D)/(2 mu - 1)` is the
//! larger one (their product exceeds 1), for `mu < 1/2` it is negative, and for `mu = 1/2` p is
//! linear with the root `s = 1/(kappa - 1)`, which the formula reproduces.
//!
//! Consequences: penalty only (`mu = 0`): `s = 1/(kappa + sqrt(1 + kappa^2))`,
//! `Cr^2 = 4/(1/s + 2 + s) = 2/(1 + sqrt(1 + beta_s^2))`. At fixed r > 1 and `beta_s -> inf`,
//! `p/mu -> q^2 + (4r - 2) q + 1`, so `Lambda -> 4r`, `Cr -> 1/sqrt(r)`. Since `q < 0` and
//! `q > -1`, the localized Lambda is bracketed by the contact row's nodal ratio and Gershgorin
//! row sum: `(1 + kappa)/(1/2 + mu) < Lambda < (2 + kappa)/(1/2 + mu)`. The nodal estimate
//! `K_00/M_00 = (k + k_s)/(m/2 + m_p)` therefore always underestimates `omega_max` (it is NOT a
//! conservative step), the row-sum bound never does.
//!
//! **Two equal bars** joined by a relative link (`K_p = k_s [[1,-1],[-1,1]]`,
//! `M_p = m_p [[1,-1],[-1,1]]` on the contact pair): symmetric modes (`u_a = u_b`) do not stretch
//! the link and stay contact-free (`Lambda <= 4`); antisymmetric modes (`u_b = -u_a`) see at
//! node a the spring force `k_s (u_a - u_b) = 2 k_s u_a` and the penalty inertia
//! `m_p (a_a - a_b) = 2 m_p a_a`, i.e. a wall with `(2 k_s, 2 m_p)`:
//! `Cr_two(beta_s, beta_m) = Cr_wall(2 beta_s, 2 beta_m)`. The ratio r is unchanged, so r <= 1
//! is neutral for two bars as well.
//!
//! Sources: bipenalty method, Askes, Caramés-Saddler, Rodríguez-Ferran, Proc. R. Soc. A 466
//! (2010) 1389-1408; its stability on the Signorini problem, Kopačka, Tkachuk, Gabriel, Kolman,
//! Bischoff, Plešek, Int. J. Numer. Meth. Engng 113 (2018) 1607-1629 (seed ref. \[9\], Fig. 3);
//! the derivation above and the corrected conventions are courant's methods.md §7.
//!
//! # Part 2: contact forces of one-dimensional impact
//!
//! [`ImpactForce`]: a striker (impedance `Z1`, wave speed `c1`, length `L1`, velocity `v0`) hits
//! a target bar (`Z2`, `c2`, `L2`, at rest) or a rigid wall; the bars touch at t = 0 and their
//! far ends are free. The force history is piecewise constant and computed exactly by tracking
//! the characteristic invariants (see [`ImpactForce`]). [`PenaltyWallForce`]: the bar hits a
//! penalty spring `k_s` instead of a rigid wall. Source: elementary wave theory of impact, e.g.
//! Graff, *Wave Motion in Elastic Solids* (1975), ch. 2; Johnson, *Impact Strength of Materials*
//! (1972), ch. 3; conventions of methods.md §7.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::error::ReferenceError;

/// Checks that `value` is finite and `>= 0` (a penalty may be switched off).
fn require_non_negative(name: &'static str, value: f64) -> Result<f64, ReferenceError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(ReferenceError::InvalidParameter {
            name,
            value,
            rule: "non-negative and finite",
        })
    }
}

/// Checks that `value` is positive and finite.
fn require_positive(name: &'static str, value: f64) -> Result<f64, ReferenceError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(ReferenceError::InvalidParameter {
            name,
            value,
            rule: "positive and finite",
        })
    }
}

// ---------------------------------------------------------------------------------------------
// Part 1: stability of penalty / bipenalty contact
// ---------------------------------------------------------------------------------------------

/// The mode localized at the contact node of a semi-infinite lumped bar (module docs, part 1):
/// `u_j = q^j`, `-1 < q < 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalizedMode {
    /// Ratio `q = u_{j+1}/u_j` of neighbouring nodal amplitudes, in `(-1, 0)`.
    pub decay_ratio: f64,
    /// `Lambda = omega^2 h^2/c^2 = (1 - q)^2/(-q) > 4`.
    pub lambda: f64,
    /// `Cr = 2/sqrt(Lambda) = 2 sqrt(-q)/(1 - q) < 1`.
    pub critical_courant: f64,
}

impl LocalizedMode {
    /// Builds the mode from `s = -q` in `(0, 1)`.
    fn from_s(s: f64) -> Self {
        Self {
            decay_ratio: -s,
            lambda: (1.0 + s) * (1.0 + s) / s,
            critical_courant: 2.0 * s.sqrt() / (1.0 + s),
        }
    }
}

/// `s = -q` from the pieces `1 + 2 mu`, `kappa - 2 mu`, `kappa - 4 mu` (each computed by the
/// caller without cancellation), if `kappa > 4 mu`.
///
/// `s = (1 + 2 mu)/((kappa - 2 mu) + sqrt(1 + kappa (kappa - 4 mu)))`; the square root is formed
/// as `hypot(1, sqrt(kappa) sqrt(kappa - 4 mu))` so that it does not overflow.
fn localized_s(kappa: f64, one_plus_2mu: f64, kappa_m_2mu: f64, kappa_m_4mu: f64) -> Option<f64> {
    if kappa_m_4mu > 0.0 {
        let root = 1.0_f64.hypot(kappa.sqrt() * kappa_m_4mu.sqrt());
        Some(one_plus_2mu / (kappa_m_2mu + root))
    } else {
        None
    }
}

/// The localized contact mode of the bipenalized Signorini problem (semi-infinite uniform lumped
/// bar against a rigid wall), or `None` when there is none, i.e. when `beta_s <= 4 beta_m`.
///
/// ```text
///   s = (1 + 2 beta_m)/((beta_s - 2 beta_m) + sqrt(1 + beta_s (beta_s - 4 beta_m))),   q = -s,
///   Lambda = (1 + s)^2/s,   Cr = 2 sqrt(s)/(1 + s).
/// ```
///
/// `q` is the unique root in `(-1, 0)` of `(mu - 1/2) q^2 + (kappa - 2 mu) q + (mu + 1/2)`,
/// equivalently Lambda is the root of `(mu^2 - 1/4) Lambda^2 + (1 - 2 mu kappa) Lambda +
/// kappa^2 = 0` with `4 < Lambda < (2 + kappa)/(1/2 + mu)` (derivation and source: module docs,
/// part 1; methods.md §7). Evaluated without cancellation for any finite `beta_s`, `beta_m`.
///
/// # Errors
/// [`ReferenceError::InvalidParameter`] if `beta_s` or `beta_m` is negative or not finite.
pub fn signorini_localized_mode(
    beta_s: f64,
    beta_m: f64,
) -> Result<Option<LocalizedMode>, ReferenceError> {
    let kappa = require_non_negative("beta_s", beta_s)?;
    let mu = require_non_negative("beta_m", beta_m)?;
    let s = localized_s(kappa, 1.0 + 2.0 * mu, kappa - 2.0 * mu, kappa - 4.0 * mu);
    Ok(s.map(LocalizedMode::from_s))
}

/// Critical Courant number of penalty-only contact (`beta_m = 0`) of a uniform lumped bar
/// against a rigid wall, central difference (methods.md §7):
///
/// ```text
///   Cr = sqrt(2/(1 + sqrt(1 + beta_s^2)))          (about sqrt(2/beta_s) for large beta_s)
/// ```
///
/// Evaluated as `sqrt(2/(1 + hypot(1, beta_s)))`: a sum of positive terms (no cancellation) whose
/// square never overflows, accurate to a few ulps from `beta_s = 0` (Cr = 1) to `1e300`.
/// Derivation: the localized mode of [`signorini_localized_mode`] with `mu = 0`, `s = 1/(beta_s +
/// sqrt(1 + beta_s^2))`, `Cr^2 = 4/(1/s + 2 + s)`. Source: Kopačka et al., IJNME 113 (2018);
/// methods.md §7.
///
/// # Errors
/// [`ReferenceError::InvalidParameter`] if `beta_s` is negative or not finite.
pub fn signorini_critical_courant_penalty(beta_s: f64) -> Result<f64, ReferenceError> {
    let kappa = require_non_negative("beta_s", beta_s)?;
    Ok((2.0 / (1.0 + 1.0_f64.hypot(kappa))).sqrt())
}

/// Critical Courant number of bipenalty contact of a semi-infinite uniform lumped bar against a
/// rigid wall, central difference (methods.md §7):
///
/// ```text
///   Cr = 1                          if beta_s <= 4 beta_m   (r <= 1: no localized mode)
///   Cr = 2 sqrt(s)/(1 + s)          otherwise, s of signorini_localized_mode
/// ```
///
/// `Cr -> 1/sqrt(r)` as `beta_s -> inf` at fixed `r = beta_s/(4 beta_m) > 1`; with `beta_m = 0`
/// it equals [`signorini_critical_courant_penalty`] to rounding. A finite bar has a slightly
/// larger contact-free Cr (e.g. `1/cos(pi/(4N))` fixed-free); this is the semi-infinite value.
/// Source: Kopačka et al., IJNME 113 (2018); derivation in the module docs, part 1.
///
/// # Errors
/// [`ReferenceError::InvalidParameter`] if `beta_s` or `beta_m` is negative or not finite.
pub fn signorini_critical_courant_bipenalty(
    beta_s: f64,
    beta_m: f64,
) -> Result<f64, ReferenceError> {
    Ok(signorini_localized_mode(beta_s, beta_m)?.map_or(1.0, |mode| mode.critical_courant))
}

/// [`signorini_critical_courant_bipenalty`] parameterised by the penalty ratio
/// `r = beta_s/(4 beta_m)` (methods.md §7; r = 1 is neutral), i.e. `beta_m = beta_s/(4 r)`:
///
/// ```text
///   Cr = 1                          if r <= 1 or beta_s = 0
///   s  = (1 + beta_s/(2r)) / (beta_s (2r - 1)/(2r) + sqrt(1 + beta_s^2 (r - 1)/r)),
///   Cr = 2 sqrt(s)/(1 + s)          otherwise.
/// ```
///
/// The differences `kappa - 2 mu`, `kappa - 4 mu` are formed from `r` directly, so they stay
/// accurate even for r within rounding of 1. `r = +inf` is the penalty-only limit.
///
/// # Errors
/// [`ReferenceError::InvalidParameter`] if `beta_s` is negative or not finite, or `r` is not
/// positive (`+inf` is allowed).
pub fn signorini_critical_courant_ratio(beta_s: f64, r: f64) -> Result<f64, ReferenceError> {
    let kappa = require_non_negative("beta_s", beta_s)?;
    if r.is_nan() || r <= 0.0 {
        return Err(ReferenceError::InvalidParameter {
            name: "r",
            value: r,
            rule: "positive (+inf allowed)",
        });
    }
    if r == f64::INFINITY {
        return signorini_critical_courant_penalty(kappa);
    }
    let s = localized_s(
        kappa,
        1.0 + kappa / (2.0 * r),
        kappa * ((2.0 * r - 1.0) / (2.0 * r)),
        kappa * ((r - 1.0) / r),
    );
    Ok(s.map_or(1.0, |s| LocalizedMode::from_s(s).critical_courant))
}

/// Critical Courant number of two equal semi-infinite uniform lumped bars whose end nodes are
/// joined by the relative bipenalty link of methods.md §7 (`K_p = k_s [[1,-1],[-1,1]]`,
/// `M_p = m_p [[1,-1],[-1,1]]`), central difference:
///
/// ```text
///   Cr_two(beta_s, beta_m) = Cr_wall(2 beta_s, 2 beta_m)
/// ```
///
/// Antisymmetric modes see a wall with doubled stiffness and doubled penalty mass, symmetric ones
/// do not stretch the link (module docs, part 1). The penalty ratio r is the same as for the
/// wall, so `beta_s <= 4 beta_m` keeps Cr = 1. Source: methods.md §7 (stiffness part); the mass
/// counterpart is derived here.
///
/// # Errors
/// [`ReferenceError::InvalidParameter`] if `beta_s` or `beta_m` is negative or not finite.
pub fn two_bar_critical_courant(beta_s: f64, beta_m: f64) -> Result<f64, ReferenceError> {
    let kappa = require_non_negative("beta_s", beta_s)?;
    let mu = require_non_negative("beta_m", beta_m)?;
    signorini_critical_courant_bipenalty(2.0 * kappa, 2.0 * mu)
}

// ---------------------------------------------------------------------------------------------
// Part 2: one-dimensional impact
// ---------------------------------------------------------------------------------------------

/// A homogeneous elastic bar as seen by 1D impact: impedance `Z = rho c A`, wave speed c,
/// length L.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactBar {
    /// Impedance `Z = rho c A` (force per velocity, > 0).
    pub impedance: f64,
    /// Bar wave speed `c = sqrt(E/rho)` (> 0).
    pub wave_speed: f64,
    /// Length L (> 0).
    pub length: f64,
}

impl ImpactBar {
    /// Builds the bar after validating its data.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if a value is not positive and finite.
    pub fn new(impedance: f64, wave_speed: f64, length: f64) -> Result<Self, ReferenceError> {
        Ok(Self {
            impedance: require_positive("impedance", impedance)?,
            wave_speed: require_positive("wave_speed", wave_speed)?,
            length: require_positive("length", length)?,
        })
    }

    /// Builds the bar from its material: `c = sqrt(E/rho)`, `Z = rho c A = A sqrt(E rho)`.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if a value is not positive and finite.
    pub fn from_material(
        modulus: f64,
        density: f64,
        area: f64,
        length: f64,
    ) -> Result<Self, ReferenceError> {
        let modulus = require_positive("modulus", modulus)?;
        let density = require_positive("density", density)?;
        let area = require_positive("area", area)?;
        Self::new(
            area * (modulus * density).sqrt(),
            (modulus / density).sqrt(),
            length,
        )
    }

    /// Transit time `T = L/c`.
    #[must_use]
    pub fn transit_time(&self) -> f64 {
        self.length / self.wave_speed
    }

    /// Mass `rho A L = Z T`.
    #[must_use]
    pub fn mass(&self) -> f64 {
        self.impedance * self.transit_time()
    }
}

/// What the striker hits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ImpactTarget {
    /// An elastic bar at rest, far end free.
    Bar(ImpactBar),
    /// A rigid, fixed wall (the limit `Z2 -> inf`).
    RigidWall,
}

/// One constant stretch of the contact force: `force` on `[start, end)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForcePlateau {
    /// Start time (inclusive).
    pub start: f64,
    /// End time (exclusive).
    pub end: f64,
    /// Contact force, compression positive (`>= 0`).
    pub force: f64,
    /// Velocity of the contact interface (`0` against a rigid wall).
    pub interface_velocity: f64,
}

/// Relative time tolerance (of `T1 + T2`) within which two wave arrivals at the interface count
/// as simultaneous; plateaus shorter than this are merged away.
pub const ARRIVAL_TOLERANCE: f64 = 1e-10;

/// Relative force tolerance (of `Z1 v0`) below which an interface force counts as zero.
const FORCE_TOLERANCE: f64 = 1e-12;

/// Most plateaus tracked before giving up (only reached for extreme transit-time ratios).
const MAX_PLATEAUS: usize = 1_000_000;

/// Exact contact force of a 1D impact: striker `(Z1, c1, L1)` moving at `v0 > 0` hits a target
/// bar `(Z2, c2, L2)` at rest (or a rigid wall); the bars touch at t = 0, far ends free, contact
/// is unilateral (compression only), frictionless and lossless. Source: elementary wave theory of
/// impact (Graff 1975, ch. 2; Johnson 1972, ch. 3); methods.md §7.
///
/// **Method (exact wave tracking).** With N the axial force (tension positive), `N - Z v` is
/// constant along `dx/dt = +c` and `N + Z v` along `dx/dt = -c`. At the interface the striker
/// delivers the right-going invariant `a(t)`, the target the left-going `b(t)`. In contact
/// (`N1 = N2 = N`, `v1 = v2 = v`):
///
/// ```text
///   N = (Z2 a + Z1 b)/(Z1 + Z2),   v = (b - a)/(Z1 + Z2),   F = -N (compression positive);
///   emitted: into the striker N + Z1 v, into the target N - Z2 v.
/// ```
///
/// A free end (N = 0) returns an invariant with its sign reversed, so
/// `a(t) = -Z1 v0` for `t < 2 T1` and `a(t) = -(N + Z1 v)(t - 2 T1)` after; `b(t) = 0` for
/// `t < 2 T2` and `b(t) = -(N - Z2 v)(t - 2 T2)` after (`T_i = L_i/c_i`). Against a rigid wall
/// `v = 0`, `N = a`. Every change of the interface state therefore happens at a time
/// `2 i T1 + 2 j T2`, and the force is piecewise constant. The contact opens at the first such
/// time at which the welded N would be tensile: then `N (Z1 + Z2)/(Z1 Z2) = a/Z1 + b/Z2` is the
/// opening rate of the gap between the two free ends, so `N > 0` is exactly "the gap opens". A
/// welded `N = 0` keeps the ends touching with zero force (they move together); such interior
/// zero plateaus are kept, trailing ones are dropped. Only the first contact is described; the
/// bars are not followed after the gap opens.
///
/// **Hand results** (checked in the tests):
/// - First plateau `F1 = Z1 Z2 v0/(Z1 + Z2)` while `t < 2 min(T1, T2)`.
/// - Equal impedance (`Z1 = Z2 = Z`, no reflection at the interface): `F = Z v0/2` for
///   `0 <= t < 2 min(T1, T2)`, then 0. Impulse `Z v0 min(T1, T2) = min(m1, m2) v0`, i.e.
///   `rho A L_short v0` for equal materials. Momentum: if `T1 <= T2` the striker stops completely
///   (its momentum loss `m1 v0` is the impulse; its energy `m1 v0^2/2` is all passed on, carried
///   by a compressive pulse of length `2 c2 T1` in the target); the target's end stays at rest,
///   touching at zero force, until that pulse returns from the target's free end at `2 T2`, when
///   the gap opens ([`Self::separation_time`]). If `T1 > T2` the target leaves with uniform `v0`
///   and no stress at `2 T2` (impulse `m2 v0`); the striker keeps `(m1 - m2) v0` and an
///   unloading pulse, its end moves with the target at zero force until the striker's own
///   reflected wave returns at `2 T1`, when the gap opens. Either way the gap opens at
///   `2 max(T1, T2)`.
/// - Equal transit times `T1 = T2 = T`: `F = F1` for `0 <= t < 2T` for every impedance ratio
///   (at 2T the welded N would be `+F1`); impulse `2 T F1`, which is `m1 v0` for `Z1 = Z2` and
///   tends to `2 m1 v0` (elastic bounce) for `Z2 -> inf`.
/// - Rigid wall: `F = Z1 v0` for `0 <= t < 2 T1`; impulse `2 m1 v0`.
/// - Otherwise a staircase: e.g. `Z1 < Z2`, `T2 < T1` continues after 2 T2 with
///   `F2 = F1 (Z2 - Z1)/(Z1 + Z2)`, and so on; `Z1 > Z2`, `T2 < T1` separates at `2 T2`.
///
/// The impulse equals the striker's momentum loss (`m1 v0 - p1`, the only external force on
/// the striker is the contact force) and the target's momentum gain.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactForce {
    striker: ImpactBar,
    target: ImpactTarget,
    velocity: f64,
    plateaus: Vec<ForcePlateau>,
    separation: f64,
}

/// A pending wave arrival at the interface at `2 (i T1 + j T2)`; ordered as a min-heap on time.
#[derive(Debug, Clone, Copy)]
struct Arrival {
    time: f64,
    i: u32,
    j: u32,
}

impl PartialEq for Arrival {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Arrival {}

impl PartialOrd for Arrival {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Arrival {
    fn cmp(&self, other: &Self) -> Ordering {
        // Reversed: BinaryHeap is a max-heap.
        other
            .time
            .total_cmp(&self.time)
            .then_with(|| other.i.cmp(&self.i))
            .then_with(|| other.j.cmp(&self.j))
    }
}

/// The interface state from time `time` on.
#[derive(Debug, Clone, Copy)]
struct InterfaceState {
    time: f64,
    /// Incoming invariants.
    a: f64,
    b: f64,
    /// Axial force (tension positive) and velocity of the interface.
    n: f64,
    v: f64,
}

impl ImpactForce {
    /// Striker hitting an elastic target bar at rest.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if `v0` is not positive and finite (the bars must
    /// approach), or, for extreme transit-time ratios, if the first contact needs more than
    /// 10^6 plateaus (named `transit-time ratio T1/T2`).
    pub fn new(striker: ImpactBar, target: ImpactBar, v0: f64) -> Result<Self, ReferenceError> {
        Self::with_target(striker, ImpactTarget::Bar(target), v0)
    }

    /// Striker hitting a rigid wall: `F = Z1 v0` for `2 L1/c1`.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if `v0` is not positive and finite.
    pub fn rigid_wall(striker: ImpactBar, v0: f64) -> Result<Self, ReferenceError> {
        Self::with_target(striker, ImpactTarget::RigidWall, v0)
    }

    /// Striker hitting `target`.
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn with_target(
        striker: ImpactBar,
        target: ImpactTarget,
        v0: f64,
    ) -> Result<Self, ReferenceError> {
        let striker = ImpactBar::new(striker.impedance, striker.wave_speed, striker.length)?;
        let target = match target {
            ImpactTarget::Bar(bar) => {
                ImpactTarget::Bar(ImpactBar::new(bar.impedance, bar.wave_speed, bar.length)?)
            }
            ImpactTarget::RigidWall => ImpactTarget::RigidWall,
        };
        let velocity = require_positive("v0", v0)?;
        let (plateaus, separation) = track(striker, target, velocity)?;
        Ok(Self {
            striker,
            target,
            velocity,
            plateaus,
            separation,
        })
    }

    /// The striker.
    #[must_use]
    pub fn striker(&self) -> ImpactBar {
        self.striker
    }

    /// The target.
    #[must_use]
    pub fn target(&self) -> ImpactTarget {
        self.target
    }

    /// Impact velocity v0.
    #[must_use]
    pub fn impact_velocity(&self) -> f64 {
        self.velocity
    }

    /// First plateau `F1 = Z1 Z2 v0/(Z1 + Z2)` (`Z1 v0` against a rigid wall).
    #[must_use]
    pub fn first_plateau(&self) -> f64 {
        match self.target {
            ImpactTarget::Bar(t) => {
                let (z1, z2) = (self.striker.impedance, t.impedance);
                z1 * z2 / (z1 + z2) * self.velocity
            }
            ImpactTarget::RigidWall => self.striker.impedance * self.velocity,
        }
    }

    /// Contact force at time t, compression positive, right-continuous (the new value at a
    /// step); 0 for `t < 0` and `t >= duration()`, NaN for NaN.
    #[must_use]
    pub fn force(&self, t: f64) -> f64 {
        if t.is_nan() {
            return f64::NAN;
        }
        if t < 0.0 || t >= self.duration() {
            return 0.0;
        }
        let k = self.plateaus.partition_point(|p| p.start <= t);
        self.plateaus[k - 1].force
    }

    /// End of the last plateau with positive force.
    #[must_use]
    pub fn duration(&self) -> f64 {
        self.plateaus.last().map_or(0.0, |p| p.end)
    }

    /// Time at which the gap opens (`>= duration()`; larger when the ends keep touching at zero
    /// force, e.g. equal impedance with `T1 > T2`).
    #[must_use]
    pub fn separation_time(&self) -> f64 {
        self.separation
    }

    /// The piecewise-constant force history, in time order, ending with a positive plateau.
    #[must_use]
    pub fn plateaus(&self) -> &[ForcePlateau] {
        &self.plateaus
    }

    /// Impulse `int F dt` = the striker's momentum loss = the target's momentum gain.
    #[must_use]
    pub fn impulse(&self) -> f64 {
        self.plateaus
            .iter()
            .map(|p| p.force * (p.end - p.start))
            .sum()
    }

    /// Work `int F v dt` done by the striker on the target through the interface: the striker's
    /// energy loss, equal to the target's energy (kinetic + strain) after separation.
    #[must_use]
    pub fn energy_transferred(&self) -> f64 {
        self.plateaus
            .iter()
            .map(|p| p.force * p.interface_velocity * (p.end - p.start))
            .sum()
    }

    /// Mean (centre-of-mass) velocity of the striker after separation, `v0 - impulse/m1`.
    #[must_use]
    pub fn striker_mean_velocity_after(&self) -> f64 {
        self.velocity - self.impulse() / self.striker.mass()
    }
}

/// Exact wave tracking of the first contact; returns the plateaus (trailing zero-force ones
/// dropped) and the time the gap opens.
fn track(
    striker: ImpactBar,
    target: ImpactTarget,
    v0: f64,
) -> Result<(Vec<ForcePlateau>, f64), ReferenceError> {
    let z1 = striker.impedance;
    let t1 = striker.transit_time();
    let (z2, t2) = match target {
        ImpactTarget::Bar(bar) => (bar.impedance, bar.transit_time()),
        ImpactTarget::RigidWall => (f64::INFINITY, f64::INFINITY),
    };
    let rigid = matches!(target, ImpactTarget::RigidWall);
    let time_tol = ARRIVAL_TOLERANCE * if rigid { t1 } else { t1 + t2 };
    let force_tol = FORCE_TOLERANCE * z1 * v0;

    let weld = |time: f64, a: f64, b: f64| -> InterfaceState {
        let (n, v) = if rigid {
            (a, 0.0)
        } else {
            ((z2 * a + z1 * b) / (z1 + z2), (b - a) / (z1 + z2))
        };
        InterfaceState { time, a, b, n, v }
    };
    // Invariants emitted into the striker and the target by a state.
    let out1 = |s: &InterfaceState| s.n + z1 * s.v;
    let out2 = |s: &InterfaceState| s.n - z2 * s.v;
    let at = |history: &[InterfaceState], tau: f64| -> InterfaceState {
        let k = history.partition_point(|s| s.time <= tau + time_tol);
        history[k.max(1) - 1]
    };
    let arrival = |i: u32, j: u32| -> Arrival {
        let time = if rigid {
            2.0 * f64::from(i) * t1
        } else {
            2.0 * (f64::from(i) * t1 + f64::from(j) * t2)
        };
        Arrival { time, i, j }
    };

    let mut history = vec![weld(0.0, -z1 * v0, 0.0)];
    let mut queue = BinaryHeap::new();
    let spawn = |queue: &mut BinaryHeap<Arrival>, i: u32, j: u32| {
        queue.push(arrival(i + 1, j));
        if !rigid {
            queue.push(arrival(i, j + 1));
        }
    };
    spawn(&mut queue, 0, 0);

    let separation = loop {
        let Some(next) = queue.pop() else {
            // Nothing will ever change again: cannot happen for a physical impact (the
            // striker's release wave always returns), kept as a guard.
            return Err(ReferenceError::InvalidParameter {
                name: "transit-time ratio T1/T2",
                value: t1 / t2,
                rule: "such that the contact ends",
            });
        };
        let last = history[history.len() - 1];
        if next.time <= last.time + time_tol {
            continue;
        }
        let t = next.time;
        let a = if t < 2.0 * t1 - time_tol {
            -z1 * v0
        } else {
            -out1(&at(&history, t - 2.0 * t1))
        };
        let b = if rigid || t < 2.0 * t2 - time_tol {
            0.0
        } else {
            -out2(&at(&history, t - 2.0 * t2))
        };
        if a == last.a && b == last.b {
            continue;
        }
        let state = weld(t, a, b);
        if state.n > force_tol {
            break t;
        }
        history.push(state);
        if history.len() > MAX_PLATEAUS {
            return Err(ReferenceError::InvalidParameter {
                name: "transit-time ratio T1/T2",
                value: t1 / t2,
                rule: "such that the first contact ends within 10^6 plateaus",
            });
        }
        spawn(&mut queue, next.i, next.j);
    };

    let mut plateaus: Vec<ForcePlateau> = history
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let end = history.get(k + 1).map_or(separation, |n| n.time);
            let force = if -s.n > force_tol { -s.n } else { 0.0 };
            ForcePlateau {
                start: s.time,
                end,
                force,
                interface_velocity: s.v,
            }
        })
        .collect();
    while plateaus.last().is_some_and(|p| p.force == 0.0) {
        plateaus.pop();
    }
    Ok((plateaus, separation))
}

/// A bar hitting a rigid wall through a penalty spring `k_s` (unilateral, massless): the
/// penalty-regularised counterpart of [`ImpactForce::rigid_wall`]. Bar `(Z, c, L)`, velocity
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
            bar: ImpactBar::new(bar.impedance, bar.wave_speed, bar.length)?,
            velocity: require_positive("v0", v0)?,
            stiffness: require_positive("stiffness", stiffness)?,
        })
    }

    /// Rise time constant `tau = Z/k_s`.
    #[must_use]
    pub fn time_constant(&self) -> f64 {
        self.bar.impedance / self.stiffness
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
        let (z, v0, tau) = (self.bar.impedance, self.velocity, self.time_constant());
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
        let (z, v0, tau) = (self.bar.impedance, self.velocity, self.time_constant());
        let (e, theta) = self.decay();
        let s = self.release_sigma();
        let es = (-s).exp();
        let first = 2.0 * self.bar.transit_time() + tau * (-theta).exp_m1();
        let second = tau * ((2.0 - e) * (1.0 - es) + 2.0 * (1.0 - (1.0 + s) * es) - s);
        Some(z * v0 * (first + second))
    }
}
