//! Analytic reference solutions for one-dimensional elastic bars.
//!
//! This crate is courant's independent yardstick: it evaluates closed-form solutions of the
//! continuum wave equation and depends on no solver crate, so a finite-element result compared
//! against it is checked against theory, not against another piece of the same code.
//! Conventions (units, load sign, Heaviside at t = 0) follow courant's methods note
//! (`shared/notes/methods.md`, §1-3).
//!
//! - [`dalembert`]: the homogeneous free-fixed bar under a Heaviside end traction.
//! - [`error`]: the validation error shared by all references.

pub mod contact;
pub mod dalembert;
pub mod error;
pub mod graded;
pub mod spectra;

pub use dalembert::{DalembertBar, Energies};
pub use error::ReferenceError;
