//! Contact-impact of 1D bars: node-to-node penalty, bipenalty, the stabilized predictor-corrector
//! scheme and the forward-increment Lagrange multiplier method, on lumped central difference.
//!
//! **Enters:** one or two lumped [`Model`](crate::Model)s and a gap made into a [`ContactProblem`],
//! a [`ContactScheme`] (with its [`Penalty`]) and a time step. **Leaves:** a [`ContactRun`]
//! (samples, stress profiles, momenta) or a [`ContactError`], and the critical steps
//! ([`ContactCriticalStep`]). It builds on the bulk's lumped kernel and banded inertia
//! (`kernels::lumped::kernel`, `mass::banded`); it must not know scenes, files or
//! the analytic references (no I/O; `courant_references::contact` is compared with it elsewhere),
//! and the contact-free integrators do not know it.
//!
//! Files: `problem` (bodies, contact nodes, gap), `penalty` (penalty parameters), `scheme` (the
//! schemes and their O(1) level update), `stability` (critical steps), `stepper` (the time
//! loop's state), `run` (the checked, guarded run), `output` (what a run records), `error`;
//! `combined` (Park's local stepping or the reciprocal mass in the bulk, with every contact
//! scheme: the decision for the contact nodes, the rank-one bipenalty update, measured limits).
//!
//! # Problems ([`ContactProblem`])
//!
//! ```text
//!   (i) Signorini, wall on the right:            (ii) two bars, end to end:
//!
//!       o---o---o---o  -> g0 <-  |//                striker (1)            target (2)
//!       0           c            |//           o---o---o---a  -> g0 <-  b---o---o---o---o
//!                                                          v0 ->                    at rest
//!       g = g0 - u_c          (N = [-1])       g = g0 + u_b - u_a      (N = [-1, +1] on (a, b))
//!       wall on the left: g = g0 + u_0  (N = [+1])
//! ```
//!
//! The gap is `g = N^T u + g0` (methods.md §7): the initial gap `g0 >= 0` plus the approach of
//! the contact node(s). Contact is active (penetration) when `g < 0`. Every contact force acts
//! along N: a force `lambda >= 0` (compression positive) applies `N lambda` to the contact nodes,
//! pushing the bodies apart. The two bars sit in one global numbering (the striker's nodes, then
//! the target's), so the pair `(a, b) = (N1, N1 + 1)` is adjacent and every operator stays
//! tridiagonal.
//!
//! # Penalties ([`Penalty`])
//!
//! Nodal penalty stiffness `k_s = eps_s A` and penalty mass `m_p = eps_m A`, switched on by
//! H(-g) (the seed's H(g) with its gap sign, eq. 15):
//!
//! ```text
//!   K_p = k_s N N^T,   M_p = m_p N N^T,   f_p = k_s N g0,
//!   contact residual  R_c = M_p a + K_p u + f_p = N (m_p N^T a + k_s g).
//! ```
//!
//! For two bodies `M_p = m_p [[1, -1], [-1, 1]]` is the *relative* mass penalty: `1^T M_p = 0`,
//! so it conserves momentum. Dimensionless (methods.md §7): `beta_s = k_s h/(E A)`,
//! `beta_m = m_p/(rho A h)`, penalty ratio `r = beta_s/(4 beta_m)` (r = 1 neutral), for the
//! reference element of [`ContactProblem::reference_element`].
//!
//! # The level update (all schemes)
//!
//! The bulk is the project's lumped central difference in half-step form
//! ([`crate::kernels::lumped::kernel::LumpedStep`], methods.md §2): from `u^n`, `v^{n-1/2}`,
//!
//! ```text
//!   u^n = u^{n-1} + dt v^{n-1/2},   a^n = M^-1 (F^n - K u^n + N J^n/dt),   v^{n+1/2} = v^{n-1/2} + dt a^n,
//! ```
//!
//! and at the start `v^{1/2} = v^0 + (dt/2) M^-1 (F^0 - K u^0) + M^-1 N J^0`. Each scheme only
//! chooses the **contact momentum** `J^n` delivered along N at level n. It is O(1): it needs
//! `u^n` at the contact node(s) and their neighbours (formed as `u^{n-1} + dt v^{n-1/2}`, the
//! same arithmetic as the kernel), `v^{n-1/2}` there and the bulk residual
//! `R = F - K u^n` there. With `s = N^T M^-1 N` (`1/m_c` at a wall, `1/m_a + 1/m_b = 1/m_red`
//! for a pair) and `w_n` the fraction of a step the level's velocity update spans (`w_0 = 1/2`,
//! `w_n = 1` after):
//!
//! * **(a), (b) central difference with penalty / bipenalty** (seed eq. 17; Kopačka et al.,
//!   IJNME 113 (2018), the seed's ref. \[9\]). Solve `(M + M_p) a^n = R - k_s g^n N` when
//!   `g^n < 0`. Only the pair block of `M + M_p` is not diagonal; by Sherman-Morrison
//!   `(M + m_p N N^T)^-1 = M^-1 - m_p M^-1 N N^T M^-1/(1 + m_p s)`, so
//!
//!   ```text
//!     N^T a0 = N^T M^-1 R - k_s g^n s                  (acceleration with M alone)
//!     lambda^n = -k_s g^n - m_p N^T a0/(1 + m_p s)  =  -k_s g^n - m_p N^T a^n,
//!     J^n = w_n dt lambda^n.
//!   ```
//!
//!   The contact force is the spring force *minus the penalty mass's inertia*, so
//!   `eps_s x penetration` is not the force once `m_p > 0` (methods.md §7). Penalty only is
//!   `m_p = 0`. In closed form for a pair, `(M + M_p)^-1 = [[m_b + m_p, m_p], [m_p, m_a + m_p]]
//!   / (m_a m_b + m_p (m_a + m_b))`; the Sherman-Morrison form is the same and serves walls and
//!   pairs alike.
//!
//! * **(c) stabilized predictor-corrector** (the seed's flowchart after "Wu", ref. \[15\]; the
//!   attribution is unverified, methods.md §7). Bulk prediction with M only,
//!   `v_pred = v^{n-1/2} + w_n dt M^-1 R`, `u_pred^{n+1} = u^n + dt v_pred`,
//!   `g_pred = N^T u_pred^{n+1} + g0`; if `g_pred < 0` the contact force
//!   `f_cont = -k_s g_pred N` is applied through `(M + M_p)^-1` as a velocity correction
//!   `dt (M + M_p)^-1 f_cont = M^-1 N dt (-k_s g_pred)/(1 + m_p s)`:
//!
//!   ```text
//!     J^n = -dt k_s g_pred/(1 + m_p s),   new gap  g^{n+1} = g_pred (1 - kappa),
//!     kappa = k_s dt^2 s/(1 + m_p s) = k_s dt^2/(m_c + m_p),   m_c = 1/s.
//!   ```
//!
//!   The correction is applied in full (`dt`, not `w_n dt`) at every level, the start included:
//!   it is an impulse that acts on the predicted gap. Stable only while `kappa <= 1`
//!   (methods.md §7); with r = 1 (`m_p = beta_s m/4`) and large `beta_s`, `kappa -> 4 Co^2`
//!   for a wall (`m_c = m/2`) and for a pair of equal bars (`m_red = m/4`, relative `m_p`), so
//!   the largest Courant number is 1/2. At `kappa = 1` it is scheme (d).
//!
//! * **(d) forward-increment Lagrange multiplier** (Carpenter, Taylor and Katona, IJNME 32
//!   (1991) 103-128). The same predictor; the multiplier makes the predicted gap at `t^{n+1}`
//!   exactly zero if it would be negative:
//!
//!   ```text
//!     J^n = -g_pred/(dt s)  if g_pred < 0, else 0      (so g^{n+1} = 0 exactly).
//!   ```
//!
//!   The exact-constraint reference: while in compression the two contact nodes move as one
//!   node of mass `m_a + m_b` (a welded chain), which at Co = 1 on bars of equal `c/h` is
//!   the exact layered chain of methods.md §4.
//!
//! **Reported contact force** (methods.md §7): the momentum delivered to the real masses at
//! level n divided by the length of the interval the level's velocity update spans,
//! `F^n = J^n/(w_n dt)`, stamped `t^n`; compression positive. The start level spans `[0, dt/2]`.
//! For (d) at Co = 1 on bars of equal `c/h`, while the contact stays closed, this is the exact
//! force averaged with the level's hat function over `[t^{n-1}, t^{n+1}]`: a jump of the exact
//! force at a level shows as the mean of its two sides. At the level where the exact force drops
//! to zero for good, the forward-increment update delivers nothing (it cannot anticipate a
//! release), an O(h) impulse deficit of half a level's force.
//!
//! **Energy.** Contact is passive, yet switching H(g) is not energy-neutral in (a) and (b): a
//! step that finds penetration engages a spring already compressed by up to `dt |g'|`. With
//! r = 1, (b) keeps the persistent-contact stability limit for every `beta_s`, but on an impact
//! with `beta_s >= 25` at Co = 0.5 its contact chatters (open about two levels in five) and on a
//! persistent, chattering contact it gains energy; (c) at `kappa <= 1` and (d) only dissipate
//! (tests `contact_fig5_central_difference`, `contact_fig5_predictor_corrector`).
//!
//! # Stability ([`ContactCriticalStep`])
//!
//! The exact critical step of the contact-active system is `2/omega_max` of the pencil
//! `(K + K_p, M + M_p)`, found by bisection on Sturm counts (Sylvester's inertia of
//! `K + K_p - x (M + M_p)`; Wilkinson (1965) §5.37), as in `analysis::stability`; a run
//! passes through contact-free and contact-active states and must respect both. Closed forms to
//! compare with: `courant_references::contact` (methods.md §7).
//!
//! # Cost
//!
//! A contact run is a separate integrator: a model without contact never runs this code. Per
//! step the contact adds O(1) work (a few nodal values, one scalar update) on top of the
//! unchanged lumped kernel, which receives the contact momentum as a nodal force.

pub mod combined;
mod error;
mod output;
mod penalty;
mod problem;
mod run;
mod scheme;
mod stability;
mod stepper;

pub use error::{ContactError, ContactUnstableError};
pub use output::{ContactProfile, ContactRequest, ContactRun, ContactSample};
pub use penalty::{MassPenalty, Penalty};
pub use problem::{ContactKind, ContactNode, ContactProblem};
pub use run::ContactIntegrator;
pub use scheme::{CONTACT_SCHEMES, ContactScheme, ContactSchemeEntry};
pub use stability::{ContactCriticalStep, ContactPencil, LIMIT_TIE, StepLimit};
pub use stepper::ContactStepper;
