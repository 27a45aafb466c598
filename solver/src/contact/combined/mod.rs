//! Contact with local time stepping or the reciprocal mass: Park's pull-back scheme (methods.md
//! §6) or central difference with RMM (methods.md §5) in the bulk, each with every contact
//! scheme of [`crate::contact`] (penalty, bipenalty, predictor-corrector, Lagrange multiplier),
//! at a wall or between two bars. The guide: `docs/contact_with_local_stepping.md`.
//!
//! **Enters:** a [`ContactProblem`](crate::contact::ContactProblem), a [`BulkScheme`], a
//! [`ContactScheme`](crate::contact::ContactScheme) and a step. **Leaves:** the levels of a run
//! ([`CombinedStepper`]: contact gap, momentum and force, state, momenta, energies) and the
//! measured step limit of the combination ([`amplification`]). It must not know scenes, files
//! or references, and the Park kernel does not know it (this is a separate, element-by-element
//! path: `kernels::park` keeps its hot loop).
//!
//! # The decision: the contact nodes step at the global step, by central difference
//!
//! All nodes advance together from `t^n` to `t^{n+1} = t^n + dt` (Park's global step, `dt <=
//! min_e dt_e`). Park predicts the displacement of every node but the contact node(s); there
//! the blend is `theta = 0`:
//!
//! ```text
//!   u_c^{n+1} = u_c^n + dt v_c^n + dt^2/2 a_c^n                     (contact nodes: CD)
//!   u_i^{n+1} = theta u_fs,i + (1 - theta) u_cd,i                  (all others: Park, §6)
//!   a^{n+1}   = a0 + M^-1 N J^{n+1}/dt,   a0 = M^-1 (F^{n+1} - K u^{n+1})
//!   v^{n+1}   = v^n + dt/2 (a^n + a^{n+1})
//! ```
//!
//! with `J^{n+1}` the contact momentum of the chosen contact scheme, computed by the same O(1)
//! formulas as on the lumped central-difference bulk (module docs of [`crate::contact`]) from
//! `g^{n+1} = N^T u^{n+1} + g0`, `N^T v^{n+1/2}` (`v^{n+1/2} = v^n + dt/2 a^n`), `N^T a0` and
//! `s = N^T M^-1 N`. Why:
//!
//! 1. **The contact force has no value at `t^n + dt_e`.** Park's element problems push each
//!    element to its own `t^n + dt_e` under the loads *at that time*; the contact force there is
//!    unknown (it is what the step decides, and it switches on and off with the gap). Pulling
//!    back a guess of it would make the contact force depend on an extrapolation across a
//!    switch. At `theta = 0` the contact node's displacement needs only `a^n`, which holds the
//!    contact force of level n exactly.
//! 2. **The contact schemes keep their meaning.** With the contact node(s) on central
//!    difference, `g^{n+2}` predicted from level n+1 is `g^{n+1} + dt N^T (v^{n+1/2} + dt
//!    a^{n+1})` exactly, as on the lumped bulk: the predictor-corrector's gap and the Lagrange
//!    multiplier's closure `g^{n+2} = 0` hold to round-off, and the penalty force is a function
//!    of the level's gap only. On the lumped central-difference bulk this stepper gives the
//!    levels of [`crate::contact::ContactStepper`] (velocity-Verlet form of the same scheme).
//! 3. **Stability is not reduced.** A contact node steps at `dt`, which is at most its own
//!    element's `dt_e` (`alpha_e <= 1`), so the node is at or below its local limit: the
//!    smaller of the two local steps is never needed. The measured limits
//!    ([`amplification::measured_limit`]) confirm it (guide: the table of limits).
//! 4. **Cost.** The contact stays O(1) per level; the Park prediction of all other nodes is
//!    unchanged, so the neighbour of a contact node still uses its two element predictions (the
//!    contact element's uses `a_c^n`, which holds the contact force).
//!
//! # Momentum (exact for the discrete scheme)
//!
//! Whatever the displacement predictor, the velocity update `v^{n+1} = v^n + dt/2 (a^n +
//! a^{n+1})` with `A a^n = A M^-1 (F^n - K u^n) + A M^-1 N J^n/(w_n dt)` gives, with `A` the
//! lumped masses and `1^T A M^-1 = 1^T` (LMM trivially; RMM because `C 1 = A 1`, so also
//! `1^T M = 1^T A` and its momentum is `sum A_i v_i`, methods.md §5):
//!
//! ```text
//!   sum_i A_i v_i^{n+1} - sum_i A_i v_i^n = dt/2 (1^T F^n + 1^T F^{n+1})
//!                                         + (1^T N) (J^n/w_n + J^{n+1})/2
//! ```
//!
//! since `1^T K = 0` on free-free bodies. For a pair `1^T N = 0`: the total momentum is
//! conserved to round-off, each body's changes by the contact impulse; at a wall `1^T N = +-1`
//! and the bar's momentum changes by the delivered contact momenta.
//!
//! # The reciprocal mass and the bipenalty
//!
//! RMM's `M^-1` is assembled (tridiagonal); the bipenalty needs `(M + m_p N N^T)^-1`, which is
//! the rank-one (Sherman-Morrison) update of it ([`ContactDirection::penalized_inverse`]):
//! `q = M^-1 N` has at most three nonzeros per contact node, so the update is O(bandwidth) per
//! contact node and nothing is ever solved. All four contact schemes use `M^-1` only through
//! `q` and `s`, so all four run with RMM; RMM spreads the contact force to the contact node's
//! neighbour (`q` is not local to the node), so its contact-active step limit is measured, not
//! taken from the lumped pencil. Park runs on the lumped mass only.
//!
//! # Energy
//!
//! [`CombinedEnergy`]: `1/2 v M v - dt^2/8 a M a + 1/2 u K u` is central difference's conserved
//! energy; Park's pull-back dissipates it a little in the bulk (theta = 1/2, alpha < 1), the
//! Lagrange multiplier removes the relative kinetic energy of the contact nodes at each closure,
//! and the penalty schemes store `1/2 k_s g^2` (and `1/2 m_p (N^T v)^2`) while in contact and
//! can gain or lose energy at the switches of `H(-g)`.

pub mod amplification;
mod bulk;
mod run;
mod stepper;
#[cfg(test)]
mod tests;

pub use bulk::{BulkScheme, ContactDirection};
pub use run::CombinedIntegrator;
pub use stepper::{CombinedEnergy, CombinedLevel, CombinedStepper, ContactMode};
