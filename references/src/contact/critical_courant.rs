//! Part 1 of the contact references: the critical Courant number of the bipenalized Signorini
//! problem (a lumped bar against a rigid wall) and of two bars joined by a relative bipenalty
//! link, central difference.
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

/// The mode localized at the contact node of a semi-infinite lumped bar (module docs):
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
/// kappa^2 = 0` with `4 < Lambda < (2 + kappa)/(1/2 + mu)` (derivation and source: module
/// docs; methods.md §7). Evaluated without cancellation for any finite `beta_s`, `beta_m`.
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
/// Source: Kopačka et al., IJNME 113 (2018); derivation in the module docs.
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
/// do not stretch the link (module docs). The penalty ratio r is the same as for the
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
