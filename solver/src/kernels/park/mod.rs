//! Park's explicit scheme with local time stepping and pull-back interpolation (seed §3.1, as
//! corrected in methods.md §6; Park et al., the seed's refs. [11-13]).
//!
//! **Enters:** a lumped [`Model`](crate::Model), the global step `dt` and [`ParkOptions`].
//! **Leaves:** the state `u^n`, `v^n`, `a^n` and the energies of each step
//! ([`StepEnergy`](crate::kernels::energy::StepEnergy)). It must not know the run loop, its outputs
//! or the stability policy (the shared time loop drives it through [`crate::schemes::park`]), nor
//! any I/O.
//!
//! Files: `options` (what the user chooses), `step` ([`ParkStep`]: the per-element constants
//! from the model, the loads, the AVX2 dispatch), `folded` (the folded step as one blocked sweep).
//!
//! Per step `n -> n+1` with the global `dt`; element `e` has its own critical step
//! `dt_e = h_e/c_e` and `alpha_e = dt/dt_e <= 1`:
//!
//! ```text
//!   1. push forward each element alone to t^n + dt_e (element LMM M_e = m_e/2 I):
//!        u~_e = u_e^n + dt_e v_e^n + dt_e^2/2 a_e^n
//!        a~_e = M_e^-1 (f_e - K_e u~_e)                                  (variant "free")
//!        a~_e = a_e^n + M_e^-1 (df_e - K_e (u~_e - u_e^n))                (variant "incremental")
//!   2. pull back to t^{n+1} by cubic interpolation in time:
//!        u_fs,e = u_e^n + dt v_e^n + dt_e^2 (beta1 a_e^n + beta2 a~_e),
//!        beta1 = alpha (1 + 3 alpha - alpha^2)/6,  beta2 = alpha (alpha^2 - 1)/6
//!   3. u_fs = plain average of the element predictions at each node
//!   4. u_cd = u^n + dt v^n + dt^2/2 a^n;   u^{n+1} = theta u_fs + (1 - theta) u_cd
//!      a^{n+1} = M^-1 (f^{n+1} - K u^{n+1});   v^{n+1} = v^n + dt/2 (a^n + a^{n+1})
//! ```
//!
//! The seed prints `dt_e v` in step 2 and drops `dt` in the velocity update: both misprints
//! (methods.md §6). `theta = 0` is central difference; at `alpha = 1` every theta is. `theta = 1/2`
//! cancels the leading phase error `(2 theta - 1)(1 - alpha^2)(kh)^2/24`. A nodal load is shared
//! between the two elements of its node in proportion to their share of the nodal mass, so the
//! element problems see the same acceleration as the assembled one under a uniform state.
//! "Without local stepping" uses one common `dt_e` (the stiffest element's) for every element.
//!
//! # Folded form (what [`ParkStep::step`] computes)
//!
//! Steps 1-4 are linear in the state, so they are evaluated in an equivalent folded form (the
//! same mathematics, reassociated: results agree with the element-by-element form to round-off).
//! With `k_e`, `m_e` the element's stiffness and mass, `S_e = 2 k_e/m_e` (element acceleration
//! per unit stretch, from `M_e = m_e/2 I`), `c_i = 1/(number of elements at node i)` (1 at the
//! ends, 1/2 inside) and `free_i` = 0 at a fixed node, 1 otherwise:
//!
//! ```text
//!   stretch of element e = (i, j = i+1) under the push forward, load-free:
//!        D_e = (u_j - u_i) + dt_e (v_j - v_i) + dt_e^2/2 (a_j - a_i)      (free)
//!        D_e =               dt_e (v_j - v_i) + dt_e^2/2 (a_j - a_i)      (incremental)
//!   a~ = +-S_e D_e (free) or a^n +- S_e D_e (incremental), so with q_e = dt_e^2 beta2 S_e:
//!   u^{n+1}_i = free_i (u_i + dt v_i) + A_i a_i + free_i theta c_i (q_e D_e - q_{e-1} D_{e-1})
//!        A_i = free_i (theta c_i sum_{e at i} P_e + (1 - theta) dt^2/2),
//!        P_e = dt_e^2 beta1 (free),  dt_e^2 (beta1 + beta2) (incremental)
//! ```
//!
//! (`e` is the element on the node's right and `e-1` the one on its left; a missing element
//! contributes nothing.) Nodal loads are added afterwards at the loaded nodes only: element `e`
//! of loaded node `i` adds `free_i theta c_i dt_e^2 beta2 (2/m_e) share_e F` to `u^{n+1}_i`, with
//! `F = F_i(t^n + dt_e)` (free) or `F_i(t^n + dt_e) - F_i(t^n)` (incremental). The acceleration,
//! velocity and energies of step 4 are unchanged.

mod folded;
mod options;
mod step;

pub use options::{ParkOptions, ParkVariant};
pub use step::ParkStep;
