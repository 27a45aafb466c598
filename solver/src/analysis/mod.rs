//! What is known about a model before it runs: its critical steps, its discrete spectrum and the
//! plan of steps that hits the output times.
//!
//! **Enters:** a [`Model`](crate::model::Model), a mass kind and its operator, output times.
//! **Leaves:** [`CriticalStep`] (exact by Sturm bisection, with element and Gershgorin
//! estimates), angular frequencies, [`TimePlan`]. It must not run a scheme: a limit that needs a
//! run (a measured critical step) belongs to [`crate::integrator`].
//!
//! Files: `stability` (critical steps of central difference for every mass), `spectrum` (dense
//! eigenvalues of small meshes), `time_step` (step plans that hit output times).

pub(crate) mod spectrum;
pub(crate) mod stability;
pub(crate) mod time_step;

pub use spectrum::{MAX_DENSE_NODES, angular_frequencies};
pub use stability::{BISECTION_STEPS, BOUND_DOUBLINGS, CriticalStep};
pub use time_step::{MAX_STEPS, ROUNDING_SLACK, TimePlan, plan, plan_keeping_step};
