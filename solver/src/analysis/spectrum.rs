//! Discrete spectra: all angular frequencies of `K u = omega^2 M u` for a model and mass kind,
//! by a dense symmetric eigen-decomposition (nalgebra) of an equivalent symmetric matrix, for
//! meshes up to a few hundred elements (the seed's Fig. 6).
//!
//! Fixed nodes are deleted. The symmetric forms (no matrix is inverted):
//!
//! ```text
//!   LMM       S = M^-1/2 K M^-1/2
//!   CMM, AMM  S = L^-1 K L^-T,        M = L L^T (Cholesky; triangular solves)
//!   RMM       S = R A^-1 K A^-1 R^T,  C = R^T R (Cholesky of C), M^-1 = A^-1 C A^-1,
//!             similar to M^-1 K because XY and YX share their eigenvalues
//! ```

use crate::error::InputError;
use crate::mass::{MassKind, MassOperator};
use crate::model::Model;
use nalgebra::{DMatrix, DVector};

/// Largest mesh (free nodes) a dense spectrum is computed for.
pub const MAX_DENSE_NODES: usize = 2000;

/// Angular frequencies `omega_n`, ascending (the rigid mode of a free-free bar is 0 up to
/// round-off, clamped at 0).
pub fn angular_frequencies(model: &Model, kind: MassKind) -> Result<Vec<f64>, InputError> {
    let operator = MassOperator::new(model, kind)?;
    let n_all = model.bar().node_count();
    let free: Vec<usize> = (0..n_all).filter(|&i| !model.is_fixed(i)).collect();
    let n = free.len();
    if n == 0 {
        return Ok(Vec::new());
    }
    if n > MAX_DENSE_NODES {
        return Err(InputError::DenseSpectrumTooLarge {
            nodes: n,
            max: MAX_DENSE_NODES,
        });
    }
    let position = |i: usize| free.binary_search(&i).ok();
    let mut k = DMatrix::<f64>::zeros(n, n);
    for (e, &ke) in model.stiffness().iter().enumerate() {
        for (a, b, sign) in [
            (e, e, 1.0),
            (e + 1, e + 1, 1.0),
            (e, e + 1, -1.0),
            (e + 1, e, -1.0),
        ] {
            if let (Some(i), Some(j)) = (position(a), position(b)) {
                k[(i, j)] += sign * ke;
            }
        }
    }
    let not_spd = || InputError::MassNotPositiveDefinite { mass: kind.label() };
    let s = match &operator {
        MassOperator::Diagonal { mass, .. } => {
            let d = DVector::from_iterator(n, free.iter().map(|&i| 1.0 / mass[i].sqrt()));
            DMatrix::from_fn(n, n, |i, j| d[i] * k[(i, j)] * d[j])
        }
        MassOperator::Tridiagonal { matrix, .. } => {
            let m = DMatrix::from_fn(n, n, |i, j| {
                tridiagonal_entry(&matrix.diag, &matrix.off, free[i], free[j])
            });
            let l = m.cholesky().ok_or_else(not_spd)?.l();
            let x = l.solve_lower_triangular(&k).ok_or_else(not_spd)?; // L^-1 K
            let y = l
                .solve_lower_triangular(&x.transpose())
                .ok_or_else(not_spd)?; // L^-1 (L^-1 K)^T = L^-1 K L^-T
            (&y + y.transpose()) * 0.5
        }
        MassOperator::Reciprocal {
            inverse, lumped, ..
        } => {
            // C = A M^-1 A on the free nodes.
            let c = DMatrix::from_fn(n, n, |i, j| {
                lumped[free[i]]
                    * tridiagonal_entry(&inverse.diag, &inverse.off, free[i], free[j])
                    * lumped[free[j]]
            });
            let r = c.cholesky().ok_or_else(not_spd)?.l().transpose(); // C = R^T R
            let a_inv = DVector::from_iterator(n, free.iter().map(|&i| 1.0 / lumped[i]));
            let scaled = DMatrix::from_fn(n, n, |i, j| a_inv[i] * k[(i, j)] * a_inv[j]);
            let s = &r * scaled * r.transpose();
            (&s + s.transpose()) * 0.5
        }
    };
    let mut omega: Vec<f64> = s
        .symmetric_eigenvalues()
        .iter()
        .map(|&l| l.max(0.0).sqrt())
        .collect();
    omega.sort_by(f64::total_cmp);
    Ok(omega)
}

fn tridiagonal_entry(diag: &[f64], off: &[f64], i: usize, j: usize) -> f64 {
    match i.abs_diff(j) {
        0 => diag[i],
        1 => off[i.min(j)],
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::stability::CriticalStep;
    use crate::fixtures::seed_bar;
    use crate::{Field, TimeFunction};

    #[test]
    fn largest_frequency_matches_the_bisection_for_every_kind() {
        let model = seed_bar(
            60,
            Field::Linear {
                left: 9.0,
                right: 1.0,
            },
            TimeFunction::HEAVISIDE,
        )
        .unwrap();
        for kind in [
            MassKind::Lumped,
            MassKind::Consistent,
            MassKind::Averaged { beta: 0.5 },
            MassKind::Reciprocal { beta: 0.5 },
            MassKind::Reciprocal { beta: 0.0 },
        ] {
            let omega = angular_frequencies(&model, kind).unwrap();
            let op = MassOperator::new(&model, kind).unwrap();
            let c = CriticalStep::of(&model, kind, &op).unwrap();
            let dense = *omega.last().unwrap();
            assert!(
                (c.omega_max - dense).abs() <= 1e-10 * dense,
                "{kind:?}: bisection {} vs dense {dense}",
                c.omega_max
            );
            assert!(
                c.gershgorin <= c.exact * (1.0 + 1e-12),
                "{kind:?}: Gershgorin must be conservative"
            );
        }
    }
}
