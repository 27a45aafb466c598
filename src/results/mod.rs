//! The records every producer emits, as plain data: what a run measured, before anything is
//! compared with a reference.
//!
//! ```text
//!   scene ──> run ──> results ──> compare ──> report / check
//!                     ^^^^^^^
//! ```
//!
//! - [`case`]: a time-stepping case (stress profiles, nodal histories, energy log, cost, how it
//!   ended);
//! - [`contact`]: a contact-impact case (force history, energies);
//! - [`spectrum`], [`dispersion`], [`sweep`]: computed frequencies, single-mode phase speeds,
//!   critical Courant numbers of the contact-active system;
//! - [`scene`]: all records of one scene, in case order;
//! - [`table`]: named tables and their CSV/Markdown forms (fixed or round-trip precision), the
//!   form every stage writes its records and verdicts in.
//!
//! Enters: what a producer measured (courant's solver today). Leaves: records, read by
//! `compare`. Must not know: scenes, references, norms, verdicts, how records are produced.

pub mod case;
pub mod contact;
pub mod dispersion;
pub mod scene;
pub mod spectrum;
pub mod sweep;
pub mod table;
