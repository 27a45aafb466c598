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
//!
//! **Enters:** dimensionless penalties (`beta_s`, `beta_m`, `r`) or the impedances, wave speeds,
//! lengths and impact velocity of the bars. **Leaves:** critical Courant numbers, the localized
//! contact mode, exact contact-force histories, impulses and energies, or a
//! [`ReferenceError`](crate::ReferenceError) for invalid data. It must not know any solver (the
//! solver's contact runs are compared with it elsewhere), nor files.
//!
//! - `critical_courant` (part 1): the stability limit of penalty and bipenalty contact on a
//!   semi-infinite lumped bar ([`signorini_critical_courant_bipenalty`] and friends).
//! - `impact` (part 2): the exact force of a striker on a bar or a rigid wall ([`ImpactForce`]).
//! - `penalty_wall`: the same bar against a penalty spring ([`PenaltyWallForce`]).
//! - `layered_impact`: the exact impact of two layered bars, force history, separation and
//!   fields ([`LayeredImpact`], method of characteristics).

mod critical_courant;
mod impact;
mod layered_impact;
mod penalty_wall;

pub use critical_courant::{
    LocalizedMode, signorini_critical_courant_bipenalty, signorini_critical_courant_penalty,
    signorini_critical_courant_ratio, signorini_localized_mode, two_bar_critical_courant,
};
pub use impact::{ARRIVAL_TOLERANCE, ForcePlateau, ImpactBar, ImpactForce, ImpactTarget};
pub use layered_impact::{DEFAULT_MAX_EVENTS, ImpactLayer, LayeredImpact};
pub use penalty_wall::PenaltyWallForce;
