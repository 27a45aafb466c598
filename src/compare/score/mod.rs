//! Grading another code's results (files in the exchange format, `results::exchange`) against
//! the scene's references, with exactly the norms and expectations of `courant run`, plus the
//! diagnostics a verification engineer needs when wiring a code to a harness.
//!
//! ```text
//!   exchange set ──> bind (file -> scene case, checked) ──> profiles / force / spectrum
//!                                                            ├─> diagnostics (offset, sign, H(0))
//!                                                            └─> expect (the scene's [[expect]])
//!   several sets of one case at different N ──> convergence (the report study's band)
//! ```
//!
//! - [`bind`]: each file to the case its stem names, checked against it (kind, mesh on the bar,
//!   masses, modes; the reference work its times ask for, [`reference_work`]); [`profiles`], [`force`], [`spectrum`]: a file beside its reference;
//!   [`diagnostics`]: time-level offset, sign and load convention; [`expect`]: the scene's
//!   expectations; [`convergence`]: orders across sets; [`set`]: all of it for one set or
//!   several; [`outcome`]: what it produces; [`tables`]: its CSV tables; [`export`]: a compared
//!   courant run as an exchange set (`courant run --exchange`); [`answers`]: the exact answers as
//!   an exchange set (`courant reference`).
//!
//! Enters: a scene and exchange records. Leaves: scored sets, verdicts, tables. Must not know:
//! files on disk, how the records were produced, documents, the command line.

pub mod answers;
pub mod applies;
pub mod bind;
pub mod convergence;
pub mod diagnostics;
pub mod expect;
pub mod export;
pub mod force;
pub mod outcome;
pub mod profiles;
pub mod reference_work;
pub mod set;
pub mod shift_fit;
pub mod spectrum;
pub mod stated;
pub mod tables;
pub mod time_level;
