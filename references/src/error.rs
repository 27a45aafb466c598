//! Errors raised when constructing an analytic reference from invalid data.

/// An invalid input to an analytic reference.
///
/// Constructors validate their parameters and return this error instead of panicking; once a
/// reference is constructed its evaluation methods never fail.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ReferenceError {
    /// A physical parameter violates its rule, e.g. `modulus = -1 must be positive and finite`.
    #[error("{name} = {value} must be {rule}")]
    InvalidParameter {
        /// Name of the parameter as spelled in the constructor.
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// The rule it violates, e.g. "positive and finite".
        rule: &'static str,
    },
    /// The reference cannot be evaluated at time `t`: not finite, or beyond what it reaches.
    #[error("the {reference} reference is not evaluable at t = {t:e}: {limit}")]
    BeyondReach {
        /// Name of the reference.
        reference: &'static str,
        /// The time asked for.
        t: f64,
        /// What limits it, e.g. "evaluated up to 1000 transit times".
        limit: String,
    },
    /// An exact computation needs more events than its cap (a typed refusal instead of an
    /// unbounded run).
    #[error("the {reference} reference needs more than {cap} {what}")]
    TooManyEvents {
        /// Name of the reference.
        reference: &'static str,
        /// What is counted (waves, interface states).
        what: &'static str,
        /// The cap.
        cap: usize,
    },
}

impl ReferenceError {
    /// Checks that `value` is positive and finite (length, modulus, density, area, ...).
    pub(crate) fn require_positive(name: &'static str, value: f64) -> Result<f64, Self> {
        if value.is_finite() && value > 0.0 {
            Ok(value)
        } else {
            Err(Self::InvalidParameter {
                name,
                value,
                rule: "positive and finite",
            })
        }
    }

    /// Checks that `value` is finite (any sign allowed, e.g. a load amplitude).
    pub(crate) fn require_finite(name: &'static str, value: f64) -> Result<f64, Self> {
        if value.is_finite() {
            Ok(value)
        } else {
            Err(Self::InvalidParameter {
                name,
                value,
                rule: "finite",
            })
        }
    }
}
