//! The Noh-Bathe step with the lumped mass as one sweep over the bar (the scheme and its
//! equations: [`crate::schemes::noh_bathe`]; Noh & Bathe, Comput. Struct. 129 (2013) 178-193).
//!
//! **Enters:** the state `u^n`, `v^n`, `a^n`, the padded element stiffnesses, `1/m_i` and `m_i`,
//! the step's coefficients and the loads at `t + p dt` and `t + dt`. **Leaves:** the state at
//! `t + dt` and the step's sums (`1/2 u K u`, `v M v`, `a M a`). It must not know the time loop,
//! its outputs, the stability policy or the scheme's registry entry.
//!
//! Files: `lumped` ([`LumpedNohBathe`]: the three stages of a step, each a node behind the
//! previous one, in chunks that stay in the first-level cache).

mod lumped;

pub use lumped::{LumpedNohBathe, NohBatheArrays};
