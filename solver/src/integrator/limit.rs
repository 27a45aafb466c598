//! The stability limit of a scheme on a model: the step, what it is called in tables, and what
//! kind of statement it is (exact, a sufficient bound, or measured).

use crate::analysis::stability::CriticalStep;

/// What a scheme's limit promises (the refusal rule is the same for all three: a step above
/// `dt` is refused unless unstable runs are allowed; what theory predicts above it differs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LimitKind {
    /// The largest stable step of the linear system: stable below, marginal at, unstable above
    /// (central difference's `2/omega_max`, Noh-Bathe's `Omega_crit(p)/omega_max`).
    Exact,
    /// Only a sufficient bound: stable at and below, nothing predicted above (Park's
    /// `alpha_e <= 1` on a mesh whose elements have different transit times).
    Bound,
    /// No analysis: the critical step was measured by running the scheme
    /// ([`crate::integrator::measure_critical_step`]), to the relative precision stated there.
    Measured,
}

/// The stability limit of the scheme a run uses: the largest stable step and where it comes
/// from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SchemeLimit {
    /// The step.
    pub dt: f64,
    /// What the limit is, for tables: `2/omega_max`, `alpha_e <= 1`, ...
    pub rule: &'static str,
    /// Exact, a bound, or measured.
    pub kind: LimitKind,
}

impl SchemeLimit {
    /// Central difference (any mass): `dt <= 2/omega_max` of the assembled `(K, M)`
    /// ([`CriticalStep::exact`]; Hughes, *The Finite Element Method*, 2000, §9.3).
    pub fn central_difference(critical: &CriticalStep) -> Self {
        Self {
            dt: critical.exact,
            rule: "2/omega_max",
            kind: LimitKind::Exact,
        }
    }

    /// The largest stable step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// What the limit is, for tables, e.g. `2/omega_max` or `alpha_e <= 1 (sufficient)`.
    pub fn name(&self) -> &'static str {
        self.rule
    }

    /// True when the limit only guarantees stability below it and predicts nothing above.
    pub fn sufficient_only(&self) -> bool {
        self.kind == LimitKind::Bound
    }
}
