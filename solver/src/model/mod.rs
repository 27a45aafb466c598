//! The discrete bar: its mesh, its material and section per element, its loads, and the model
//! that gathers them with supports and initial conditions.
//!
//! **Enters:** node positions, fields of `x` (modulus, density, area), loads and their time
//! functions, supports and initial conditions, all built in code. **Leaves:** [`Model`], with
//! the operators derived once from it (element stiffness, lumped nodal mass and its inverse).
//! It must not know mass matrices other than the lumped one, time stepping or any scheme.
//!
//! Files: `mesh` (nodes and elements), `bar` (per-element `E`, `rho`, `A` and the quantities
//! derived from them), `load` (nodal forces, end tractions, time functions), `problem`
//! ([`Model`]: supports, loads and initial conditions on a bar).

pub(crate) mod bar;
pub(crate) mod load;
pub(crate) mod mesh;
pub(crate) mod problem;

pub use bar::{Bar, Field};
pub use load::{End, Load, NodalLoad, TimeFunction};
pub use mesh::{MAX_ELEMENTS, Mesh};
pub use problem::{InitialConditions, Model, Support, Supports};
