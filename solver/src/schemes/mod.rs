//! The time-integration schemes, each written against the public integrator interface
//! ([`crate::integrator`]), and the registry scenes name them through.
//!
//! **Enters:** the interface and the step kernels (`kernels`: `lumped`, `matrix_mass`,
//! `park`). **Leaves:** [`REGISTRY`] (what scenes, `courant list --schemes` and the report see) and
//! each scheme's public types. Schemes know the interface, never the reverse, and never each other
//! (Park's schemes reuse central difference's `half_step_start`, the one exception).
//!
//! Names: a scheme's `Scheme` (its parameters, what the registry builds) is `XxxScheme`, its
//! `Integrator` (what the time loop drives) `XxxStepper`, and the arithmetic of its step, where
//! it is a type of its own in `kernels`, `XxxStep` (`LumpedStep`, `MatrixMassStep`,
//! `ParkStep`).
//!
//! Adding a scheme: one file here (its `Integrator`, its `Scheme` and its `SchemeEntry`, as
//! `noh_bathe.rs`), its `pub mod` line and its line in [`REGISTRY`]. Nothing else changes: every
//! scene may name it, with the parameters its entry declares.

pub mod central_difference;
pub mod noh_bathe;
pub mod park;
pub mod park_printed;
pub mod seed;

use crate::integrator::SchemeEntry;

/// Every scheme a scene may name, in the order `courant list --schemes` shows them.
pub const REGISTRY: &[SchemeEntry] = &[
    central_difference::ENTRY,
    park::LOCAL_STEPPING,
    park::GLOBAL_STEP,
    noh_bathe::ENTRY,
    park_printed::ENTRY,
];

/// The entry answering to `name` (its name or an alias).
pub fn find(name: &str) -> Option<&'static SchemeEntry> {
    REGISTRY.iter().find(|e| e.answers_to(name))
}

/// Every name scenes may use, as one list for messages: `cd (central-difference), park-lts, ...`.
pub fn names() -> String {
    REGISTRY
        .iter()
        .map(|e| {
            if e.aliases.is_empty() {
                e.name.to_string()
            } else {
                format!("{} ({})", e.name, e.aliases.join(", "))
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}
