//! Central-difference integration of a bar: start, time loop, outputs, energy balance,
//! stability guard; lumped (the fused kernel), consistent, averaged or reciprocal mass, or Park's
//! pull-back scheme in place of the CD predictor.
//!
//! **Enters:** a [`Model`](crate::Model), a step `dt` and the run's settings
//! ([`CentralDifference`]: start, stability policy, mass, Park's options), the number of steps
//! and an [`OutputRequest`]. **Leaves:** a [`RunOutput`](crate::RunOutput) (profiles, node
//! histories, energy log with its balance) or a [`RunError`]; the scheme's limit
//! ([`SchemeLimit`]). It must not know scenes, files or the analytic references (no I/O), nor
//! contact (the contact integrator builds on it, not the reverse).
//!
//! Files: `settings` (start, stability policy, output request), `limit` (the scheme's stability
//! limit), `integrator` (the integrator, its check and the time loop), `step_kernel` (the three
//! step kernels behind one interface), `guard` (blow-up detection), `record` (profiles and
//! histories).

mod guard;
mod integrator;
mod limit;
mod record;
mod settings;
mod step_kernel;

pub use integrator::{CentralDifference, RunError};
pub use limit::SchemeLimit;
pub use settings::{OutputRequest, StabilityPolicy, Start};
