//! Producing records: courant's own solver runs each case of a scene.
//!
//! ```text
//!   scene ──> run ──> results ──> compare ──> report / check
//!             ^^^
//! ```
//!
//! - [`stepping`]: a time-stepping case (central difference with any mass, Park's scheme);
//! - [`contact`], [`spectrum`], [`dispersion`], [`sweep`]: contact impacts, dense spectra,
//!   single-mode phase measurements, critical Courant numbers of contact-active systems;
//! - [`scene`]: every case of a scene, in parallel, records in case order;
//! - [`threads`]: the thread setting (`COURANT_THREADS`) every run takes;
//! - [`force_floor`]: the measured time of one lumped element force evaluation, the floor the
//!   timing page states each work-precision run's time against.
//!
//! Enters: validated cases (`scene`). Leaves: records (`results`), with what each run cost.
//! Must not know: references, norms, expectations, verdicts, tables, reports.

pub mod contact;
pub mod dispersion;
pub mod force_floor;
pub mod scene;
pub mod spectrum;
pub mod stepping;
pub mod sweep;
pub mod threads;
