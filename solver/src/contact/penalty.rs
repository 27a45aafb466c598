//! The contact penalties: the nodal stiffness and mass in physical units, and how the mass
//! penalty is given (methods.md §7). The problem turns dimensionless values into a [`Penalty`]
//! ([`ContactProblem::penalty`](super::ContactProblem::penalty)); the schemes carry it.

/// Nodal penalty parameters in physical units: stiffness `k_s = eps_s A` and mass
/// `m_p = eps_m A` (methods.md §7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Penalty {
    /// `k_s` (force per length).
    pub stiffness: f64,
    /// `m_p` (mass); `M_p = m_p N N^T`.
    pub mass: f64,
}

/// How the mass penalty is given when building a [`Penalty`] from `beta_s`
/// ([`ContactProblem::penalty`](super::ContactProblem::penalty)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassPenalty {
    /// No mass penalty (`beta_m = 0`).
    None,
    /// Penalty ratio `r = beta_s/(4 beta_m)`; r = 1 is neutral (methods.md §7).
    Ratio(f64),
    /// `beta_m = m_p/(rho A h)` directly.
    Dimensionless(f64),
}
