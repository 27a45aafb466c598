//! The mass operator's solves and products without allocating: [`MassWork`] holds the work
//! arrays the windowed solves need (`mass::windows`: a group's rows and solution, and a copy of
//! the right-hand side for RMM's `C^-1`), made once per run, so a scheme's step that inverts or
//! applies a matrix mass touches no heap (the cost rule: "the element loop does no
//! allocation"). The same operations, in the same order, as
//! [`MassOperator::apply_inverse`] and [`MassOperator::apply`]: the same bits.

use crate::mass::operator::{MassOperator, TridiagonalSolve};
use crate::mass::windows::GroupBuffers;

/// Work arrays for [`MassOperator::apply_inverse_with`] and [`MassOperator::apply_with`]
/// (empty for a mass without windows).
#[derive(Debug, Clone, Default)]
pub struct MassWork {
    /// A group's rows and solution ([`crate::mass::windows::HaloTiles::buffers`]).
    buffers: GroupBuffers,
    /// RMM with windows: `A v`, the right-hand side of `C y = A v`.
    rhs: Vec<f64>,
}

impl MassOperator {
    /// The work arrays this operator's solves need.
    pub fn work(&self) -> MassWork {
        match self {
            MassOperator::Tridiagonal {
                solve: TridiagonalSolve::Windows(tiles),
                ..
            } => MassWork {
                buffers: tiles.buffers(),
                rhs: Vec::new(),
            },
            MassOperator::Reciprocal {
                c_solve: TridiagonalSolve::Windows(tiles),
                lumped,
                ..
            } => MassWork {
                buffers: tiles.buffers(),
                rhs: vec![0.0; lumped.len()],
            },
            _ => MassWork::default(),
        }
    }

    /// `a = M^-1 r` (0 at fixed nodes), [`Self::apply_inverse`] without allocating: the windows
    /// solve from `r` straight into `a`.
    pub fn apply_inverse_with(&self, r: &[f64], a: &mut [f64], work: &mut MassWork) {
        match self {
            MassOperator::Tridiagonal {
                solve: TridiagonalSolve::Windows(tiles),
                ..
            } => tiles.solve_into(r, a, &mut work.buffers),
            _ => self.apply_inverse(r, a),
        }
    }

    /// `y = M v` for a velocity field that vanishes at fixed nodes, [`Self::apply`] without
    /// allocating: RMM's `C^-1 (A v)` by its windows from a copy of `A v` in `work`.
    pub fn apply_with(&self, v: &[f64], y: &mut [f64], work: &mut MassWork) {
        match self {
            MassOperator::Reciprocal {
                c_solve: TridiagonalSolve::Windows(tiles),
                lumped,
                ..
            } => {
                self.lumped_scaled(v, &mut work.rhs);
                tiles.solve_into(&work.rhs, y, &mut work.buffers);
                for (y, m) in y.iter_mut().zip(lumped) {
                    *y *= m;
                }
            }
            _ => self.apply(v, y),
        }
    }
}
