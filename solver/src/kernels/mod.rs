//! The step kernels: the arithmetic of one step (or a block of steps) of each scheme, on flat
//! arrays, with no knowledge of the time loop, its outputs or the stability policy.
//!
//! **Enters:** a [`Model`](crate::model::Model), the step `dt`, a start state, the loads of each
//! step. **Leaves:** the new state and each step's energies ([`StepEnergy`](energy::StepEnergy)).
//! The schemes in [`crate::schemes`] wrap these kernels into steppers the shared time loop drives.
//! A kernel must not know the time loop, outputs, the stability policy or any scheme's
//! registry entry: it is arithmetic a stepper calls, so a faster kernel changes nothing above it.
//!
//! Folders: `lumped/` (central difference with the lumped mass: the cache-blocked step, its
//! AVX2 energy sweep, temporal blocking in tiles and the multi-threaded pipeline of blocks),
//! `matrix_mass/` (central difference with CMM, AMM and RMM: the blocked passes, their AVX2
//! sweeps, the placed state arrays), `noh_bathe/` (the Noh-Bathe step with the lumped mass in one sweep), `park/` (Park's folded
//! step). `energy` holds what every
//! kernel reports.

pub(crate) mod energy;
pub(crate) mod lumped;
pub(crate) mod matrix_mass;
pub(crate) mod noh_bathe;
pub(crate) mod park;
