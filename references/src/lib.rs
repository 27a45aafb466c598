//! Analytic reference solutions for one-dimensional elastic bars.
//!
//! This crate is courant's independent yardstick: it evaluates closed-form solutions of the
//! continuum wave equation and depends on no solver crate, so a finite-element result compared
//! against it is checked against theory, not against another piece of the same code.
//! Conventions (units, load sign, Heaviside at t = 0) follow courant's methods note
//! (`docs/methods.md`, §1-3).
//!
//! **Enters:** physical or dimensionless data of a bar (lengths, moduli, densities, areas,
//! impedances, loads, penalties) and evaluation points. **Leaves:** exact fields, frequencies,
//! critical Courant numbers and contact forces, or a [`ReferenceError`] for invalid data. It must
//! never know the solver (`courant-solver`): no dependency, no shared code, no solver types
//! (checked by `tests/architecture/main.rs`); nor files or scenes (no I/O).
//!
//! - [`dalembert`]: the homogeneous free-fixed bar under a Heaviside end traction.
//! - [`graded`]: the linearly graded bar (two full-field routes) and layered bars.
//! - [`spectra`]: closed-form spectra of uniform bars for each mass matrix and the dispersion of
//!   central difference.
//! - [`contact`]: the stability limit of penalty contact and the contact forces of 1D impact.
//! - [`error`]: the validation error shared by all references.
//! - [`exact`]: the contract every exact solution honours ([`ExactSolution`]), with the contact
//!   force history as a capability ([`ContactHistory`]) and the work of an evaluation.

#![warn(missing_docs)]

pub mod contact;
pub mod dalembert;
pub mod error;
pub mod exact;
pub mod graded;
pub mod spectra;

pub use dalembert::{DalembertBar, Energies};
pub use error::ReferenceError;
pub use exact::{ContactHistory, Evaluation, ExactSolution};
