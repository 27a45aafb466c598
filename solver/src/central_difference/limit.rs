//! The stability limit of the scheme a run uses: central difference's `2/omega_max` of the
//! assembled pencil, or Park's `alpha_e <= 1`.

use crate::model::Model;
use crate::park::{ParkOptions, ParkScheme};
use crate::stability::CriticalStep;

/// The stability limit of the scheme a [`CentralDifference`](super::CentralDifference) runs:
/// the largest stable step and where it comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SchemeLimit {
    /// Central difference (any mass): `dt <= 2/omega_max` of the assembled `(K, M)`
    /// ([`CriticalStep::exact`]; Hughes, *The Finite Element Method*, 2000, §9.3).
    CentralDifference {
        /// `2/omega_max`.
        dt: f64,
    },
    /// Park's scheme: `alpha_e = dt/dt_e <= 1` in every element (methods.md §6), i.e.
    /// `dt <= min_e dt_e` ([`ParkScheme::limit_step`]). The bound comes from the amplification
    /// analysis of a uniform mesh, whose spectral radius exceeds 1 just above `alpha = 1` at
    /// `kh = pi` (tests/park_amplification_analysis.rs): on a mesh where every element has the
    /// same `dt_e` it is the limit (up to the finite mesh's top mode, a hair below `kh = pi`); on a
    /// graded mesh it is only sufficient (measured: Park's global step on the `graded_1e4` mesh
    /// stays bounded at `alpha = 1.012`).
    Park {
        /// `min_e dt_e`.
        dt: f64,
        /// The element with the smallest `dt_e` (the first whose `alpha_e` exceeds 1).
        element: usize,
        /// True when the elements' `dt_e` differ (relative spread above 1e-12): `alpha_e <= 1`
        /// guarantees stability but above it nothing is predicted.
        sufficient_only: bool,
    },
}

impl SchemeLimit {
    /// The limit of central difference (`park = None`) or of Park's scheme with `park` on
    /// `model`, given the critical steps of its mass: CD's `critical.exact`, or Park's
    /// `alpha_e <= 1` (at or below CD's for the lumped mass: Fried's bound
    /// `omega_max <= max_e 2 c_e/h_e` gives `2/omega_max >= min_e h_e/c_e`).
    pub fn of(park: Option<&ParkOptions>, model: &Model, critical: &CriticalStep) -> Self {
        match park {
            None => SchemeLimit::CentralDifference { dt: critical.exact },
            Some(_) => {
                let bar = model.bar();
                let dt = ParkScheme::limit_step(model);
                let slowest = (0..bar.element_count())
                    .map(|e| bar.element_transit_time(e))
                    .fold(dt, f64::max);
                SchemeLimit::Park {
                    dt,
                    element: bar.stiffest_element().0,
                    sufficient_only: slowest > dt * (1.0 + 1e-12),
                }
            }
        }
    }

    /// The largest stable step.
    pub fn dt(&self) -> f64 {
        match *self {
            SchemeLimit::CentralDifference { dt } | SchemeLimit::Park { dt, .. } => dt,
        }
    }

    /// What the limit is, for tables: `2/omega_max`, `alpha_e <= 1`, or `alpha_e <= 1
    /// (sufficient)` on a graded mesh.
    pub fn name(&self) -> &'static str {
        match self {
            SchemeLimit::CentralDifference { .. } => "2/omega_max",
            SchemeLimit::Park {
                sufficient_only: false,
                ..
            } => "alpha_e <= 1",
            SchemeLimit::Park {
                sufficient_only: true,
                ..
            } => "alpha_e <= 1 (sufficient)",
        }
    }

    /// True when the limit only guarantees stability below it and predicts nothing above.
    pub fn sufficient_only(&self) -> bool {
        matches!(
            self,
            SchemeLimit::Park {
                sufficient_only: true,
                ..
            }
        )
    }
}
