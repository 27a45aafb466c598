//! Scenes: declarative cases read from TOML, validated into ready-to-run cases.
//!
//! ```text
//!   scene ──> run ──> results ──> compare ──> report / check
//!   ^^^^^
//! ```
//!
//! A scene states only what its case needs; everything else has the default documented in
//! [`schema`]. A list of Courant numbers (or time steps, meshes, schemes, mass kinds) expands
//! into one case each. Validation happens here, before anything runs: a scene that parses is a
//! scene that can run, and bad input is a [`SceneError`] naming the file, line, column and key.
//!
//! - [`parse`] reads a file and dispatches by study kind: [`time_stepping`] (with [`geometry`],
//!   [`material`], [`bar`], [`stepping`] with [`scheme_keys`] (schemes by their registry names,
//!   with the parameters they declare), [`outputs`]), [`spectrum`], [`dispersion`],
//!   [`contact`]; [`expectation`] reads `[[expect]]` (its [`bound`]s), [`finding`] `[[finding]]`; [`reference`](mod@reference) binds a case to its analytic
//!   reference in `courant-references` (validated against the model, evaluated by `compare`).
//! - [`magnitude`]: the range of magnitudes inputs and derived scales may take, so that no
//!   numerics overflow; [`budget`]: the size, work and output memory a scene may ask for
//!   ([`work`] estimates them);
//!   [`names`]: case names, bounded and safe as file names; [`spelling`]: the nearest name to
//!   a misspelt one.
//! - [`builtin`]: the scenes compiled into the binary; [`studies`]: the report's convergence and
//!   work-precision studies, each a built-in scene derived onto a sequence of meshes.
//!
//! Enters: TOML text. Leaves: [`Scene`]s of [`Case`]s (models, integrators, plans, output
//! requests, references) and expectations. Must not know: how cases run, records, norms,
//! verdicts, reports.

pub mod bar;
pub mod bound;
pub mod budget;
pub mod builtin;
pub mod cases;
pub mod contact;
pub mod contact_bar;
pub mod contact_bulk;
mod contact_problem;
pub mod dispersion;
pub mod error;
pub mod expectation;
pub mod finding;
pub mod geometry;
pub mod limits;
pub mod magnitude;
pub mod mass;
pub mod material;
pub mod metric;
pub mod names;
pub mod outputs;
pub mod parse;
pub mod reference;
pub mod schema;
pub mod scheme_keys;
pub mod spectrum;
pub mod spelling;
pub mod stepping;
pub mod studies;
pub mod time_stepping;
pub mod work;

pub use cases::{Case, Scene};
pub use error::SceneError;
