//! Closed-form spectra of uniform linear-element bars and the dispersion of central difference.
//!
//! A uniform mesh of N two-node elements of length `h = L/N` on a homogeneous bar (wave speed
//! `c`) has the sampled continuum modes as exact discrete eigenvectors; mode n, with continuum
//! wavenumber `k_n`, has the discrete frequency
//!
//! ```text
//!   omega_n = (c/h) Omega(k_n h),      s = sin(k h / 2),
//!   LMM          Omega = 2 s
//!   CMM          Omega = 2 s / sqrt(1 - 2 s^2 / 3)
//!   AMM(beta)    Omega = 2 s / sqrt(1 - 2 (1 - beta) s^2 / 3)
//!   RMM(beta)    Omega = 2 s sqrt(1 + gamma s^2),   gamma = 2 (1 - beta) / (1 + 2 beta)
//! ```
//!
//! where the mass matrices are (element `e`, `m_e = rho A h`)
//!
//! ```text
//!   LMM = m_e/2 I,   CMM = m_e/6 [[2, 1], [1, 2]],   AMM(beta) = (1 - beta) CMM + beta LMM,
//!   RMM(beta):  M^-1 = A^-1 C A^-1,  A = LMM (assembled, diagonal),  C = sum_e C_e,
//!               C_e = m_e / (2 (1 + 2 beta)) [[2 + beta, beta - 1], [beta - 1, 2 + beta]].
//! ```
//!
//! Central difference (CD) with `Co = c dt / h` is stable for `Co <= 2 / max Omega` and has the
//! fully discrete dispersion relation `sin(omega_hat dt / 2) = (Co/2) Omega(kh)`.
//!
//! Sources: courant's methods.md §1 and §5 (the corrected forms and conventions used here; it
//! wins over the seed paper); the CD stability limit after Fried (1972) and Hughes, *The Finite
//! Element Method* (1987), ch. 9; the reciprocal mass matrix after González et al. (2018) and
//! Tkachuk & Bischoff (2015). The integration tests in `tests/spectra_closed_forms.rs` check
//! every closed form against hand-assembled K and M (or M^-1) independently of any solver.

use std::ops::RangeInclusive;

use crate::error::ReferenceError;

/// Values of `(Co/2) Omega` within this round-off of 1 (either side) are treated as exactly 1,
/// the marginal mode at the critical Courant number, by [`phase_speed_ratio`]. `asin` is
/// ill-conditioned at 1 (an input error `e` moves the result by `sqrt(2 e)`), so without the
/// snap the marginal mode of CMM or AMM would come out with an error of about 1e-8.
const MARGINAL_TOLERANCE: f64 = 8.0 * f64::EPSILON;

/// Rule shared by the averaged and reciprocal mass parameters (see [`MassKind::validate`]).
const BETA_RULE: &str = "finite and > -1/2 (positive definite mass)";

/// Mass matrix of a two-node linear bar element (methods.md §5).
///
/// The parametrised kinds are valid for finite `beta > -1/2`, see [`MassKind::validate`];
/// `beta = 1` is the lumped mass for both, `beta = 0` is the consistent mass for
/// [`MassKind::Averaged`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassKind {
    /// Lumped (diagonal) mass, LMM = `m_e/2 I`.
    Lumped,
    /// Consistent mass, CMM = `m_e/6 [[2, 1], [1, 2]]`.
    Consistent,
    /// Averaged mass AMM(beta) = `(1 - beta) CMM + beta LMM` (beta = 1/2 is the usual choice).
    Averaged {
        /// Weight of the lumped mass.
        beta: f64,
    },
    /// Reciprocal mass RMM(beta): the sparse inverse `M^-1 = A^-1 C A^-1`,
    /// `C_e = m_e / (2 (1 + 2 beta)) [[2 + beta, beta - 1], [beta - 1, 2 + beta]]`, A the lumped
    /// mass (González et al. 2018, Tkachuk & Bischoff 2015; closed form from methods.md §5).
    Reciprocal {
        /// Mass parameter; beta = 1 gives the lumped mass.
        beta: f64,
    },
}

impl MassKind {
    /// Short name for tables and file names: `"lmm"`, `"cmm"`, `"amm(0.5)"`, `"rmm(0.5)"`
    /// (beta printed with Rust's shortest round-trip formatting, e.g. `"amm(1)"`).
    #[must_use]
    pub fn label(&self) -> String {
        match *self {
            Self::Lumped => "lmm".to_owned(),
            Self::Consistent => "cmm".to_owned(),
            Self::Averaged { beta } => format!("amm({beta})"),
            Self::Reciprocal { beta } => format!("rmm({beta})"),
        }
    }

    /// Returns the kind unchanged if its parameter is admissible.
    ///
    /// Rule, for both [`MassKind::Averaged`] and [`MassKind::Reciprocal`]: `beta` finite and
    /// `beta > -1/2`. This is exactly the range in which the mass matrix (for AMM) or its
    /// reciprocal (for RMM) is positive definite: on the element, both have the eigenvalue
    /// `m_e/2` on the translation `[1, 1]`, and on the stretch `[1, -1]` the AMM eigenvalue is
    /// `m_e (1 + 2 beta)/6` and the eigenvalue of `C_e` is `3 m_e / (2 (1 + 2 beta))`. Hence every
    /// valid kind has real, finite frequencies and a positive CD stability limit
    /// ([`critical_courant`]). `beta > 1` is allowed (frequencies below LMM's).
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] named `"beta"` if the rule is violated.
    pub fn validate(self) -> Result<Self, ReferenceError> {
        match self {
            Self::Lumped | Self::Consistent => Ok(self),
            Self::Averaged { beta } | Self::Reciprocal { beta } => {
                if beta.is_finite() && beta > -0.5 {
                    Ok(self)
                } else {
                    Err(ReferenceError::InvalidParameter {
                        name: "beta",
                        value: beta,
                        rule: BETA_RULE,
                    })
                }
            }
        }
    }

    /// Validated [`MassKind::Averaged`].
    ///
    /// # Errors
    /// As [`MassKind::validate`].
    pub fn averaged(beta: f64) -> Result<Self, ReferenceError> {
        Self::Averaged { beta }.validate()
    }

    /// Validated [`MassKind::Reciprocal`].
    ///
    /// # Errors
    /// As [`MassKind::validate`].
    pub fn reciprocal(beta: f64) -> Result<Self, ReferenceError> {
        Self::Reciprocal { beta }.validate()
    }

    fn is_valid(self) -> bool {
        self.validate().is_ok()
    }
}

/// `gamma = 2 (1 - beta) / (1 + 2 beta)` of RMM(beta).
fn rmm_gamma(beta: f64) -> f64 {
    2.0 * (1.0 - beta) / (1.0 + 2.0 * beta)
}

/// Dimensionless discrete frequency `Omega(kh) = omega h / c` of a uniform mesh
/// (methods.md §5), with `s = sin(kh/2)`:
///
/// ```text
///   LMM 2 s;   CMM 2 s / sqrt(1 - 2 s^2/3);   AMM(beta) 2 s / sqrt(1 - 2 (1 - beta) s^2/3);
///   RMM(beta) 2 s sqrt(1 + gamma s^2),  gamma = 2 (1 - beta)/(1 + 2 beta).
/// ```
///
/// Derivation: insert `u_j = exp(i k x_j)` into the assembled rows; K gives
/// `(E A/h) 4 s^2`, CMM `m (1 - 2 s^2/3)`, RMM's `C` gives `m (1 + gamma s^2)`.
/// AMM(0) is CMM and AMM(1), RMM(1) are LMM, bit for bit. Small `theta = kh`:
/// `Omega = theta (1 + a theta^2 + O(theta^4))`, `a_LMM = -1/24`, `a_CMM = 1/24`,
/// `a_AMM = (1 - 2 beta)/24`, `a_RMM = (3 gamma - 1)/24`.
///
/// Returns `Omega >= 0` for every finite `kh` (it is even and 2 pi periodic); NaN if `kh` is not
/// finite or the kind is invalid ([`MassKind::validate`]).
#[must_use]
pub fn dimensionless_frequency(kind: MassKind, kh: f64) -> f64 {
    if !kind.is_valid() || !kh.is_finite() {
        return f64::NAN;
    }
    let s = (0.5 * kh).sin().abs();
    let s2 = s * s;
    let averaged = |beta: f64| 2.0 * s / (1.0 - 2.0 * (1.0 - beta) * s2 / 3.0).sqrt();
    match kind {
        MassKind::Lumped => 2.0 * s,
        MassKind::Consistent => averaged(0.0),
        MassKind::Averaged { beta } => averaged(beta),
        MassKind::Reciprocal { beta } => 2.0 * s * (1.0 + rmm_gamma(beta) * s2).sqrt(),
    }
}

/// `max over kh of Omega(kh)`, so that `omega_max = (c/h) max Omega` on a uniform mesh.
///
/// LMM 2, CMM `2 sqrt(3)`, AMM(beta) `2 sqrt(3/(1 + 2 beta))` (Omega increases with s for every
/// valid beta, so the maximum is at `kh = pi`, s = 1). RMM(beta): `Omega^2 = 4 (s^2 + gamma s^4)`
/// peaks at s = 1 while `gamma >= -1/2`, i.e. `beta <= 5/2`, giving `2 sqrt(1 + gamma) =
/// 2 sqrt(3/(1 + 2 beta))` as for AMM; for `beta > 5/2` it peaks inside, at
/// `s^2 = -1/(2 gamma)`, with value `1/sqrt(-gamma)`. NaN for an invalid kind.
#[must_use]
pub fn max_dimensionless_frequency(kind: MassKind) -> f64 {
    if !kind.is_valid() {
        return f64::NAN;
    }
    match kind {
        MassKind::Lumped => 2.0,
        MassKind::Consistent => 2.0 * 3.0_f64.sqrt(),
        MassKind::Averaged { beta } => 2.0 * (3.0 / (1.0 + 2.0 * beta)).sqrt(),
        MassKind::Reciprocal { beta } => {
            let gamma = rmm_gamma(beta);
            if gamma >= -0.5 {
                2.0 * (3.0 / (1.0 + 2.0 * beta)).sqrt()
            } else {
                1.0 / (-gamma).sqrt()
            }
        }
    }
}

/// Critical Courant number `Co_cr = 2 / max Omega` of central difference on a uniform mesh
/// (methods.md §5; stability limit after Fried 1972 and Hughes 1987, ch. 9):
///
/// ```text
///   LMM 1,   CMM 1/sqrt(3),   AMM(beta) and RMM(beta) sqrt((1 + 2 beta)/3).
/// ```
///
/// The AMM/RMM formula holds for RMM only while `beta <= 5/2`; beyond, `max Omega` is interior
/// (see [`max_dimensionless_frequency`]) and `Co_cr = 2 sqrt(-gamma) = 2 sqrt(2 (beta - 1) /
/// (1 + 2 beta))`. CD is stable for `Co <= Co_cr` (the mode at `Co = Co_cr` is marginal).
/// NaN for an invalid kind.
#[must_use]
pub fn critical_courant(kind: MassKind) -> f64 {
    if !kind.is_valid() {
        return f64::NAN;
    }
    match kind {
        MassKind::Lumped => 1.0,
        MassKind::Consistent => (1.0_f64 / 3.0).sqrt(),
        MassKind::Averaged { beta } => ((1.0 + 2.0 * beta) / 3.0).sqrt(),
        MassKind::Reciprocal { beta } => {
            let gamma = rmm_gamma(beta);
            if gamma >= -0.5 {
                ((1.0 + 2.0 * beta) / 3.0).sqrt()
            } else {
                2.0 * (-gamma).sqrt()
            }
        }
    }
}

/// Phase-speed ratio `omega_hat / (c k)` of central difference with mass `kind` at `kh` and
/// Courant number `Co = c dt / h`, from the fully discrete dispersion relation (methods.md §5)
///
/// ```text
///   sin(omega_hat dt / 2) = (Co/2) Omega(kh),   omega_hat / (c k) = 2 asin((Co/2) Omega) / (Co kh).
/// ```
///
/// Returns `None` when `(Co/2) Omega > 1` (no real `omega_hat`: the mode grows, CD is unstable
/// for it), and also for an invalid kind, non-finite or negative `kh` or `Co`. A value within
/// round-off of 1 (8 machine epsilons, either side) is taken as the marginal mode
/// `omega_hat dt = pi`. Limits: `kh = 0` gives 1 (the ratio tends to 1 as `kh -> 0`);
/// `Co = 0` gives the semi-discrete ratio `Omega(kh)/kh`. Ratios below 1 are lagging waves.
#[must_use]
pub fn phase_speed_ratio(kind: MassKind, kh: f64, co: f64) -> Option<f64> {
    let valid = |v: f64| v.is_finite() && v >= 0.0;
    if !kind.is_valid() || !valid(kh) || !valid(co) {
        return None;
    }
    if kh == 0.0 {
        return Some(1.0);
    }
    let omega = dimensionless_frequency(kind, kh);
    if co == 0.0 {
        return Some(omega / kh);
    }
    let half = 0.5 * co * omega;
    if half > 1.0 + MARGINAL_TOLERANCE {
        return None;
    }
    // asin is ill-conditioned at 1: snap round-off-close values to the marginal mode.
    let half = if (half - 1.0).abs() <= MARGINAL_TOLERANCE {
        1.0
    } else {
        half
    };
    Some(2.0 * half.asin() / (co * kh))
}

/// Checks that `co` is a Courant number in `[0, 1]` (finite).
fn require_unit_courant(co: f64) -> Result<f64, ReferenceError> {
    if co.is_finite() && (0.0..=1.0).contains(&co) {
        Ok(co)
    } else {
        Err(ReferenceError::InvalidParameter {
            name: "co",
            value: co,
            rule: "finite and in [0, 1]",
        })
    }
}

/// The AMM parameter making central difference fourth-order accurate in phase at Courant number
/// `co`: `beta = (1 + Co^2) / 2`.
///
/// Derivation (theta = kh): `Omega = theta (1 + a theta^2 + O(theta^4))` with
/// `a_AMM = (1 - 2 beta)/24` (see [`dimensionless_frequency`]), and
/// `omega_hat dt = 2 asin(Co Omega/2) = Co Omega (1 + Co^2 Omega^2/24 + ...)`, so the phase-speed
/// ratio `omega_hat dt / (Co theta)` is `1 + (a + Co^2/24) theta^2 + O(theta^4)`. The error is
/// fourth order iff `a = -Co^2/24`, i.e. `1 - 2 beta = -Co^2`. `Co = 0` gives the
/// semi-discrete optimum 1/2, `Co = 1` gives beta = 1 (LMM, exact). The result is stable:
/// `Co <= sqrt((1 + 2 beta)/3) = sqrt((2 + Co^2)/3)` is equivalent to `Co <= 1`.
///
/// # Errors
/// [`ReferenceError::InvalidParameter`] named `"co"` unless `0 <= co <= 1` (for `Co > 1` the
/// formula's beta would be unstable at that Co).
pub fn fourth_order_beta_averaged(co: f64) -> Result<f64, ReferenceError> {
    let co = require_unit_courant(co)?;
    Ok(0.5 * (1.0 + co * co))
}

/// The RMM parameter making central difference fourth-order accurate in phase at Courant number
/// `co`: `beta = (5 + Co^2) / (8 - 2 Co^2)`.
///
/// Derivation as for [`fourth_order_beta_averaged`], with `a_RMM = (3 gamma - 1)/24`: fourth
/// order iff `3 gamma - 1 = -Co^2`, i.e. `gamma = 2 (1 - beta)/(1 + 2 beta) = (1 - Co^2)/3`,
/// so `6 (1 - beta) = (1 - Co^2)(1 + 2 beta)` and `beta (8 - 2 Co^2) = 5 + Co^2`. `Co = 0` gives
/// 5/8, `Co = 1` gives beta = 1 (LMM, exact). The result is stable: beta is in `[5/8, 1]`
/// (so `gamma >= 0` and `Co_cr = sqrt((1 + 2 beta)/3) = sqrt(3/(4 - Co^2))`), and
/// `Co^2 <= 3/(4 - Co^2)` is `(Co^2 - 1)(Co^2 - 3) >= 0`, true for `Co <= 1`.
///
/// # Errors
/// [`ReferenceError::InvalidParameter`] named `"co"` unless `0 <= co <= 1`.
pub fn fourth_order_beta_reciprocal(co: f64) -> Result<f64, ReferenceError> {
    let co = require_unit_courant(co)?;
    let co2 = co * co;
    Ok((5.0 + co2) / (8.0 - 2.0 * co2))
}

/// End conditions of a bar `0 <= x <= L` for its modal spectrum.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BarEnds {
    /// Both ends free: `k_n = n pi / L`, modes `cos(k_n x)`, n = 0, 1, ... (n = 0 rigid).
    FreeFree,
    /// Free at x = 0, fixed at x = L (the loaded bar of methods.md §2):
    /// `k_n = (2n - 1) pi / (2L)`, modes `cos(k_n x)`, n = 1, 2, ...
    FixedFree,
}

impl BarEnds {
    /// Mode numbers carried by a uniform mesh of `elements` elements: `0..=N` (N + 1 modes)
    /// free-free, `1..=N` (N modes; the fixed node is deleted) fixed-free.
    #[must_use]
    pub fn modes(self, elements: usize) -> RangeInclusive<usize> {
        match self {
            Self::FreeFree => 0..=elements,
            Self::FixedFree => 1..=elements,
        }
    }

    /// Continuum wavenumber `k_n`: `n pi / L` free-free, `(2n - 1) pi / (2L)` fixed-free.
    /// NaN for the non-existent fixed-free mode n = 0.
    #[must_use]
    pub fn wavenumber(self, n: usize, length: f64) -> f64 {
        match self {
            Self::FreeFree => n as f64 * std::f64::consts::PI / length,
            Self::FixedFree if n == 0 => f64::NAN,
            Self::FixedFree => (2 * n - 1) as f64 * std::f64::consts::FRAC_PI_2 / length,
        }
    }
}

/// Homogeneous bar of length L and wave speed c on a uniform mesh of N linear elements, with
/// its continuum and discrete modal frequencies (methods.md §5).
///
/// The discrete eigenvectors are the continuum modes `cos(k_n x)` sampled at the nodes (exact
/// for the uniform bar, for every [`MassKind`]), so mode n has
/// `omega_n = (c/h) Omega(k_n h)`, `h = L/N`, against the continuum `omega_n = c k_n`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UniformBar {
    /// Bar length L (> 0).
    pub length: f64,
    /// Wave speed c = sqrt(E/rho) (> 0).
    pub wave_speed: f64,
    /// Number N of elements (>= 1).
    pub elements: usize,
    /// End conditions.
    pub ends: BarEnds,
}

impl UniformBar {
    /// Builds the bar after validating its data.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] naming the first offending parameter if `length` or
    /// `wave_speed` is not positive and finite, or `elements` is 0.
    pub fn new(
        length: f64,
        wave_speed: f64,
        elements: usize,
        ends: BarEnds,
    ) -> Result<Self, ReferenceError> {
        let length = ReferenceError::require_positive("length", length)?;
        let wave_speed = ReferenceError::require_positive("wave_speed", wave_speed)?;
        if elements == 0 {
            return Err(ReferenceError::InvalidParameter {
                name: "elements",
                value: 0.0,
                rule: "at least 1",
            });
        }
        Ok(Self {
            length,
            wave_speed,
            elements,
            ends,
        })
    }

    /// Element length `h = L/N`.
    #[must_use]
    pub fn element_length(&self) -> f64 {
        self.length / self.elements as f64
    }

    /// Mode numbers of the mesh, see [`BarEnds::modes`].
    #[must_use]
    pub fn modes(&self) -> RangeInclusive<usize> {
        self.ends.modes(self.elements)
    }

    /// Continuum wavenumber `k_n`, see [`BarEnds::wavenumber`].
    #[must_use]
    pub fn wavenumber(&self, n: usize) -> f64 {
        self.ends.wavenumber(n, self.length)
    }

    /// Continuum angular frequency `omega_n = c k_n` (any mode number of the continuum).
    #[must_use]
    pub fn continuum_frequency(&self, n: usize) -> f64 {
        self.wave_speed * self.wavenumber(n)
    }

    /// Discrete angular frequency `omega_n = (c/h) Omega(k_n h)` of mode n of the mesh.
    ///
    /// NaN if n is not in [`Self::modes`] (beyond them the formula only aliases lower modes)
    /// or the kind is invalid.
    #[must_use]
    pub fn discrete_frequency(&self, kind: MassKind, n: usize) -> f64 {
        if !self.modes().contains(&n) {
            return f64::NAN;
        }
        let h = self.element_length();
        self.wave_speed / h * dimensionless_frequency(kind, self.wavenumber(n) * h)
    }

    /// Continuum frequencies of the modes in [`Self::modes`], in that order.
    #[must_use]
    pub fn continuum_frequencies(&self) -> Vec<f64> {
        self.modes().map(|n| self.continuum_frequency(n)).collect()
    }

    /// The complete discrete spectrum of the mesh, ascending, one entry per mode in
    /// [`Self::modes`]: N + 1 frequencies free-free (the first is the rigid mode, 0), N
    /// fixed-free. (For RMM with beta > 5/2 the top modes are not ascending, see
    /// [`max_dimensionless_frequency`]; the order is then still by mode number.)
    #[must_use]
    pub fn discrete_frequencies(&self, kind: MassKind) -> Vec<f64> {
        self.modes()
            .map(|n| self.discrete_frequency(kind, n))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rmm_gamma_vanishes_for_lumped_and_is_one_half_at_beta_one_half() {
        assert_eq!(rmm_gamma(1.0), 0.0);
        assert_eq!(rmm_gamma(0.5), 0.5);
        assert_eq!(rmm_gamma(0.0), 2.0);
    }

    #[test]
    fn marginal_mode_at_the_critical_courant_number_is_kept() {
        for kind in [
            MassKind::Lumped,
            MassKind::Consistent,
            MassKind::Averaged { beta: 0.3 },
            MassKind::Reciprocal { beta: 0.7 },
        ] {
            let co = critical_courant(kind);
            let ratio = phase_speed_ratio(kind, std::f64::consts::PI, co).unwrap();
            assert!((ratio - 1.0 / co).abs() < 1e-12, "{}", kind.label());
        }
    }
}
