//! Mass matrices and their solves: the lumped, consistent, averaged and reciprocal masses of the
//! bar (methods.md §5), as operators a step applies (`M v`) and inverts (`M^-1 r`).
//!
//! **Enters:** a [`Model`](crate::model::Model) and a [`MassKind`]. **Leaves:** a
//! [`MassOperator`] (assembled once per run), and the banded matrices the critical-step analysis
//! counts eigenvalues with. It must not know time stepping or any scheme.
//!
//! Files: `operator` ([`MassKind`], [`MassOperator`]: assembly and the choice of solve),
//! `tridiagonal` (the symmetric tridiagonal matrix), `partitioned_ldl` (its SPD factor: the
//! global solve, in independent blocks coupled through a small interface system), `banded` (the
//! symmetric banded matrix and its inertia), `windows/` (the CMM/AMM solve of long bars in
//! overlapping windows, twelve side by side, with its AVX2 intrinsics in `windows/avx2`), `work`
//! ([`MassWork`]: the solves and products of a step without allocating).

pub(crate) mod banded;
pub(crate) mod operator;
pub(crate) mod partitioned_ldl;
pub(crate) mod tridiagonal;
pub(crate) mod windows;
pub(crate) mod work;

pub use operator::{MassKind, MassOperator, TridiagonalSolve};
pub use work::MassWork;
