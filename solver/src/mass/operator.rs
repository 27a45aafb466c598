//! Mass matrices of the two-node bar element and their assembled operators (methods.md §5).
//!
//! Element matrices, `m_e = rho_e A_e h_e`:
//!
//! ```text
//!   LMM        m_e/2 [[1, 0], [0, 1]]                              (row-sum lumping)
//!   CMM        m_e/6 [[2, 1], [1, 2]]                              (consistent)
//!   AMM(beta)  (1 - beta) CMM + beta LMM                           (averaged)
//!   RMM(beta)  M^-1 = A^-1 C A^-1, A = LMM (assembled, diagonal),
//!              C = sum_e C_e, C_e = m_e/(2(1 + 2 beta)) [[2 + beta, beta - 1], [beta - 1, 2 + beta]]
//! ```
//!
//! RMM is the reciprocal (directly inverted) mass of Tkachuk and Bischoff (2015) and González et
//! al. (2018): `C_e = A_e AMM_e(beta)^-1 A_e`, so its inverse is assembled directly, sparse with
//! the stiffness pattern; `beta = 1` gives LMM. Dirichlet nodes: their rows and columns are
//! deleted (of `M`, or of `M^-1` for RMM).

use crate::error::{InputError, NotPositiveDefinite};
use crate::mass::banded::{PartitionedLdl, SymmetricBanded, Tridiagonal};
use crate::mass::windows::{HaloTiles, halo_rows, scaled_spectral_ratio};
use crate::model::Model;
use std::sync::Arc;

/// The mass matrix of a run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum MassKind {
    /// Row-sum lumped mass (diagonal).
    #[default]
    Lumped,
    /// Consistent mass.
    Consistent,
    /// Averaged mass `(1 - beta) CMM + beta LMM`.
    Averaged {
        /// Weight of the lumped mass, `0 <= beta <= 1`.
        beta: f64,
    },
    /// Reciprocal mass: `M^-1` assembled directly from `C_e`.
    Reciprocal {
        /// Weight parameter, `0 <= beta <= 1` (`beta = 1` is LMM).
        beta: f64,
    },
}

impl MassKind {
    /// Short name: `lmm`, `cmm`, `amm(0.5)`, `rmm(0.5)`.
    pub fn label(&self) -> String {
        match self {
            MassKind::Lumped => "lmm".into(),
            MassKind::Consistent => "cmm".into(),
            MassKind::Averaged { beta } => format!("amm({beta})"),
            MassKind::Reciprocal { beta } => format!("rmm({beta})"),
        }
    }

    /// `beta` must be finite and above `-1/2`: exactly where the element mass (AMM) or its
    /// inverse (RMM) is positive definite (element eigenvalues `m(1 + 2 beta)/6` and
    /// `3m/(2(1 + 2 beta))`). The usual range is `[0, 1]`.
    pub fn validate(&self) -> Result<(), InputError> {
        match self {
            MassKind::Averaged { beta } | MassKind::Reciprocal { beta }
                if !(beta.is_finite() && *beta > -0.5) =>
            {
                Err(InputError::Parameter {
                    field: "beta",
                    value: *beta,
                    rule: "must be finite and above -1/2 (positive definite mass)",
                })
            }
            _ => Ok(()),
        }
    }

    /// Critical Courant number of central difference on the infinite uniform mesh,
    /// `2 / max_kh Omega(kh)` (methods.md §5): LMM 1, CMM `1/sqrt(3)`, AMM `sqrt((1 + 2 beta)/3)`,
    /// RMM `sqrt((1 + 2 beta)/3)` for `beta <= 5/2`. For RMM with `beta > 5/2`,
    /// `gamma = 2(1 - beta)/(1 + 2 beta) < -1/2` and `Omega = 2 s sqrt(1 + gamma s^2)` peaks inside
    /// the band, at `s^2 = -1/(2 gamma)`, with `Omega_max = 1/sqrt(-gamma)`: Co_crit =
    /// `2 sqrt(-gamma)`.
    pub fn critical_courant(&self) -> f64 {
        match self {
            MassKind::Reciprocal { beta } => {
                let gamma = 2.0 * (1.0 - beta) / (1.0 + 2.0 * beta);
                if gamma < -0.5 {
                    2.0 * (-gamma).sqrt()
                } else {
                    self.element_courant()
                }
            }
            _ => self.element_courant(),
        }
    }

    /// `2/(omega_max^e h/c)` of one element: the Courant number Fried's element estimate allows.
    /// LMM 1, CMM `1/sqrt(3)`, AMM and RMM `sqrt((1 + 2 beta)/3)` (the element's antisymmetric
    /// mode: `omega_e^2 = 12 k/(m (1 + 2 beta))`).
    pub fn element_courant(&self) -> f64 {
        ((1.0 + 2.0 * self.beta()) / 3.0).sqrt()
    }

    /// The lumped weight `beta` of the element mass `(1 - beta) CMM + beta LMM` that the kind
    /// is built from (CMM 0, LMM 1).
    fn beta(&self) -> f64 {
        match self {
            MassKind::Lumped => 1.0,
            MassKind::Consistent => 0.0,
            MassKind::Averaged { beta } | MassKind::Reciprocal { beta } => *beta,
        }
    }

    /// Whether Fried's element bound `omega_max <= max_e omega_max^e` holds: it does for
    /// assembled element masses (LMM, CMM, AMM), not for RMM, whose inverse is assembled.
    pub fn element_bound_holds(&self) -> bool {
        !matches!(self, MassKind::Reciprocal { .. })
    }
}

/// The assembled mass of a model, in the form the time loop needs: `M^-1 r` in O(N) and `M v`
/// in O(N) (for kinetic energies). Fixed nodes are deleted (decoupled, with `M^-1 r = 0` there).
#[derive(Debug, Clone)]
pub enum MassOperator {
    /// `M` diagonal: `inverse[i] = 1/m_i` (0 at fixed nodes) and `mass[i] = m_i`.
    Diagonal {
        /// `1/m_i`, 0 at fixed nodes (the model's own array, shared).
        inverse: Arc<[f64]>,
        /// `m_i` (the model's own array, shared).
        mass: Arc<[f64]>,
    },
    /// `M` tridiagonal (CMM, AMM): solve with its factor or windows, multiply with the matrix.
    Tridiagonal {
        /// `M` with fixed nodes decoupled.
        matrix: Tridiagonal,
        /// How `M a = r` is solved.
        solve: TridiagonalSolve,
        /// Fixed-node flags.
        fixed: Vec<bool>,
        /// Indices of the fixed nodes.
        fixed_nodes: Vec<usize>,
    },
    /// `M^-1 = A^-1 C A^-1` tridiagonal (RMM): multiply with it; `M v = A C^-1 A v` by a solve.
    Reciprocal {
        /// `M^-1` with fixed rows and columns zero.
        inverse: Tridiagonal,
        /// How `C y = b` is solved (`C` with fixed nodes decoupled): windows where they apply,
        /// else the global factor. `C`'s element matrices have lumped-scaled eigenvalue ratios
        /// 1 and `3/(1 + 2 beta)`, the reciprocals of AMM(beta)'s, so the same spectral ratio
        /// and halo (`mass::windows`).
        c_solve: TridiagonalSolve,
        /// Lumped masses `A`.
        lumped: Vec<f64>,
        /// Fixed-node flags.
        fixed: Vec<bool>,
    },
}

/// The solve of a tridiagonal mass.
#[derive(Debug, Clone)]
pub enum TridiagonalSolve {
    /// The partitioned `L D L^T` factor of the whole matrix.
    Global(PartitionedLdl),
    /// Overlapping windows (`HaloTiles`), which the step solves tile by tile: from a group of
    /// windows on, when the inverse decays fast enough (CMM, AMM with `beta` not near -1/2);
    /// the solution to round-off, as the global factor's.
    Windows(HaloTiles),
}

/// Element mass of `(1 - beta) CMM + beta LMM`: (diagonal, off-diagonal) entries.
fn element_mass(me: f64, beta: f64) -> (f64, f64) {
    (
        (1.0 - beta) * me / 3.0 + beta * me / 2.0,
        (1.0 - beta) * me / 6.0,
    )
}

/// Element `C_e` of RMM: (diagonal, off-diagonal) entries.
fn element_reciprocal(me: f64, beta: f64) -> (f64, f64) {
    let f = me / (2.0 * (1.0 + 2.0 * beta));
    ((2.0 + beta) * f, (beta - 1.0) * f)
}

/// The solve of the SPD tridiagonal `m` (fixed rows decoupled) whose lumped-scaled spectral
/// ratio is that of `(1 - beta) CMM + beta LMM`: windows where they apply, else the global
/// factor; [`NotPositiveDefinite`] when `m` is not (windows refuse such a matrix, and the
/// global factor then reports it).
fn tridiagonal_solve(
    m: &Tridiagonal,
    beta: f64,
    fixed_nodes: &[usize],
) -> Result<TridiagonalSolve, NotPositiveDefinite> {
    match halo_rows(scaled_spectral_ratio(beta))
        .and_then(|halo| HaloTiles::new(m, halo, fixed_nodes))
    {
        Some(tiles) => Ok(TridiagonalSolve::Windows(tiles)),
        None => PartitionedLdl::new(m).map(TridiagonalSolve::Global),
    }
}

fn assemble(element: &[(f64, f64)]) -> Tridiagonal {
    let mut t = Tridiagonal {
        diag: vec![0.0; element.len() + 1],
        off: vec![0.0; element.len()],
    };
    for (e, &(d, o)) in element.iter().enumerate() {
        t.diag[e] += d;
        t.diag[e + 1] += d;
        t.off[e] += o;
    }
    t
}

impl MassOperator {
    /// Assemble the mass of `kind` for `model`.
    pub fn new(model: &Model, kind: MassKind) -> Result<Self, InputError> {
        kind.validate()?;
        let masses = model.bar().element_mass();
        let n = model.bar().node_count();
        let fixed: Vec<bool> = (0..n).map(|i| model.is_fixed(i)).collect();
        let not_spd =
            |_: NotPositiveDefinite| InputError::MassNotPositiveDefinite { mass: kind.label() };
        Ok(match kind {
            MassKind::Lumped => {
                let (mass, inverse) = model.shared_lumped_mass();
                MassOperator::Diagonal { inverse, mass }
            }
            MassKind::Consistent | MassKind::Averaged { .. } => {
                let beta = kind.beta();
                let mut matrix = assemble(
                    &masses
                        .iter()
                        .map(|&m| element_mass(m, beta))
                        .collect::<Vec<_>>(),
                );
                fixed
                    .iter()
                    .enumerate()
                    .filter(|(_, f)| **f)
                    .for_each(|(i, _)| matrix.decouple(i));
                let fixed_nodes: Vec<usize> = (0..n).filter(|&i| fixed[i]).collect();
                let solve = tridiagonal_solve(&matrix, beta, &fixed_nodes).map_err(not_spd)?;
                MassOperator::Tridiagonal {
                    matrix,
                    solve,
                    fixed,
                    fixed_nodes,
                }
            }
            MassKind::Reciprocal { beta } => {
                let mut c = assemble(
                    &masses
                        .iter()
                        .map(|&m| element_reciprocal(m, beta))
                        .collect::<Vec<_>>(),
                );
                let lumped = model.nodal_mass().to_vec();
                let mut inverse = Tridiagonal {
                    diag: (0..n)
                        .map(|i| c.diag[i] / (lumped[i] * lumped[i]))
                        .collect(),
                    off: (0..n - 1)
                        .map(|i| c.off[i] / (lumped[i] * lumped[i + 1]))
                        .collect(),
                };
                for (i, _) in fixed.iter().enumerate().filter(|(_, f)| **f) {
                    c.decouple(i);
                    inverse.decouple(i);
                    inverse.diag[i] = 0.0;
                }
                let fixed_nodes: Vec<usize> = (0..n).filter(|&i| fixed[i]).collect();
                let c_solve = tridiagonal_solve(&c, beta, &fixed_nodes).map_err(not_spd)?;
                MassOperator::Reciprocal {
                    inverse,
                    c_solve,
                    lumped,
                    fixed,
                }
            }
        })
    }

    /// `a = M^-1 r` (0 at fixed nodes).
    pub fn apply_inverse(&self, r: &[f64], a: &mut [f64]) {
        match self {
            MassOperator::Reciprocal { inverse, .. } => inverse.apply(r, a),
            _ => {
                a.copy_from_slice(r);
                self.apply_inverse_in_place(a);
            }
        }
    }

    /// `a <- M^-1 a` in place (0 at fixed nodes), the operations of [`Self::apply_inverse`]:
    /// a scaling for the diagonal mass, the factored or windowed solve for the tridiagonal ones
    /// (the windows' the step's own arithmetic); the
    /// reciprocal mass's product needs a copy of `a` (allocated here: its step never calls this).
    pub fn apply_inverse_in_place(&self, a: &mut [f64]) {
        match self {
            MassOperator::Diagonal { inverse, .. } => {
                for (ai, inv) in a.iter_mut().zip(inverse.iter()) {
                    *ai *= inv;
                }
            }
            MassOperator::Tridiagonal {
                solve: TridiagonalSolve::Windows(tiles),
                ..
            } => tiles.solve_in_place(a),
            MassOperator::Tridiagonal {
                solve: TridiagonalSolve::Global(factor),
                fixed_nodes,
                ..
            } => {
                fixed_nodes.iter().for_each(|&i| a[i] = 0.0);
                factor.solve_in_place(a);
            }
            MassOperator::Reciprocal { inverse, .. } => {
                let r = a.to_vec();
                inverse.apply(&r, a);
            }
        }
    }

    /// The windowed solve of a tridiagonal mass, if it has one.
    pub fn windows(&self) -> Option<&HaloTiles> {
        match self {
            MassOperator::Tridiagonal {
                solve: TridiagonalSolve::Windows(tiles),
                ..
            } => Some(tiles),
            _ => None,
        }
    }

    /// The windowed solve of the reciprocal mass's `C` (its `M v = A C^-1 A v`), if it has one.
    pub fn reciprocal_windows(&self) -> Option<&HaloTiles> {
        match self {
            MassOperator::Reciprocal {
                c_solve: TridiagonalSolve::Windows(tiles),
                ..
            } => Some(tiles),
            _ => None,
        }
    }

    /// RMM: `y = A v` (0 at fixed nodes), the right-hand side of `C x = A v` in
    /// `M v = A C^-1 A v`; nothing for the other masses.
    pub(crate) fn lumped_scaled(&self, v: &[f64], y: &mut [f64]) {
        if let MassOperator::Reciprocal { lumped, fixed, .. } = self {
            let rows = (y.iter_mut().zip(v)).zip(lumped.iter().zip(fixed));
            for ((y, v), (m, fixed)) in rows {
                *y = if *fixed { 0.0 } else { m * v };
            }
        }
    }

    /// RMM: `x <- C^-1 x` with `C`'s windows or global factor (the windows allocate their
    /// copy of `x` here; the step's mass check uses them tile by tile instead); nothing for the
    /// other masses.
    pub(crate) fn solve_reciprocal_in_place(&self, x: &mut [f64]) {
        if let MassOperator::Reciprocal { c_solve, .. } = self {
            match c_solve {
                TridiagonalSolve::Windows(tiles) => tiles.solve_in_place(x),
                TridiagonalSolve::Global(factor) => factor.solve_in_place(x),
            }
        }
    }

    /// `y = M v` for a velocity field that vanishes at fixed nodes.
    pub fn apply(&self, v: &[f64], y: &mut [f64]) {
        match self {
            MassOperator::Diagonal { mass, .. } => {
                for i in 0..v.len() {
                    y[i] = mass[i] * v[i];
                }
            }
            MassOperator::Tridiagonal { matrix, .. } => matrix.apply(v, y),
            MassOperator::Reciprocal { lumped, .. } => {
                self.lumped_scaled(v, y);
                self.solve_reciprocal_in_place(y);
                for i in 0..v.len() {
                    y[i] *= lumped[i];
                }
            }
        }
    }

    /// The pencil `(P, Q)` whose eigenvalues are those of `M^-1 K` on the free nodes, as
    /// symmetric banded matrices (fixed nodes decoupled, contributing eigenvalue 0):
    /// `(K, M)` for assembled masses, `(M^-1 K M^-1, M^-1)` for RMM (congruent to `K - x M`
    /// by `M^-1`, so it has the same inertia for every shift `x`).
    pub fn pencil(&self, model: &Model) -> (SymmetricBanded, SymmetricBanded) {
        let n = model.bar().node_count();
        let fixed = |i: usize| model.is_fixed(i);
        let mut k = SymmetricBanded::zeros(n, 1);
        for (e, &ke) in model.stiffness().iter().enumerate() {
            for (i, j, s) in [(e, e, 1.0), (e + 1, e + 1, 1.0), (e, e + 1, -1.0)] {
                if !fixed(i) && !fixed(j) {
                    k.add(i, j, s * ke);
                }
            }
        }
        let tridiagonal = |t: &Tridiagonal| {
            let mut m = SymmetricBanded::zeros(n, 1);
            for i in 0..n {
                m.add(i, i, t.diag[i]);
                if i + 1 < n {
                    m.add(i, i + 1, t.off[i]);
                }
            }
            m
        };
        match self {
            MassOperator::Diagonal { mass, .. } => {
                let mut m = SymmetricBanded::zeros(n, 1);
                (0..n).for_each(|i| m.add(i, i, if fixed(i) { 1.0 } else { mass[i] }));
                (k, m)
            }
            MassOperator::Tridiagonal { matrix, .. } => (k, tridiagonal(matrix)),
            MassOperator::Reciprocal { inverse, .. } => {
                let mut q = tridiagonal(inverse);
                (0..n).filter(|&i| fixed(i)).for_each(|i| q.set(i, i, 1.0));
                // P = Q K Q with Q = M^-1 tridiagonal: bandwidth 3.
                let mut p = SymmetricBanded::zeros(n, 3);
                for i in 0..n {
                    for j in i..(i + 4).min(n) {
                        let mut s = 0.0;
                        for a in i.saturating_sub(1)..=(i + 1).min(n - 1) {
                            for b in j.saturating_sub(1)..=(j + 1).min(n - 1) {
                                if a.abs_diff(b) <= 1 {
                                    s += inverse_entry(inverse, i, a)
                                        * k.get(a, b)
                                        * inverse_entry(inverse, b, j);
                                }
                            }
                        }
                        p.add(i, j, s);
                    }
                }
                (p, q)
            }
        }
    }
}

fn inverse_entry(t: &Tridiagonal, i: usize, j: usize) -> f64 {
    match i.abs_diff(j) {
        0 => t.diag[i],
        1 => t.off[i.min(j)],
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::seed_bar;
    use crate::{Field, TimeFunction};

    fn model(n: usize) -> Model {
        seed_bar(
            n,
            Field::Linear {
                left: 4.0,
                right: 1.0,
            },
            TimeFunction::HEAVISIDE,
        )
        .unwrap()
    }

    #[test]
    fn rmm_with_beta_one_is_the_lumped_inverse() {
        let m = model(9);
        let MassOperator::Reciprocal { inverse, .. } =
            MassOperator::new(&m, MassKind::Reciprocal { beta: 1.0 }).unwrap()
        else {
            panic!()
        };
        assert!(inverse.off.iter().all(|&o| o == 0.0));
        for i in 0..10 {
            assert!(
                (inverse.diag[i] - m.inverse_mass()[i]).abs()
                    <= 1e-15 * m.inverse_mass()[i].max(1.0)
            );
        }
    }

    #[test]
    fn mass_and_its_inverse_are_inverse_for_every_kind() {
        let m = model(12);
        for kind in [
            MassKind::Lumped,
            MassKind::Consistent,
            MassKind::Averaged { beta: 0.5 },
            MassKind::Reciprocal { beta: 0.5 },
            MassKind::Reciprocal { beta: 0.0 },
        ] {
            let op = MassOperator::new(&m, kind).unwrap();
            let mut v: Vec<f64> = (0..13).map(|i| (i as f64 * 0.7).sin()).collect();
            v[12] = 0.0; // fixed node
            let mut mv = vec![0.0; 13];
            op.apply(&v, &mut mv);
            let mut back = vec![0.0; 13];
            op.apply_inverse(&mv, &mut back);
            for i in 0..13 {
                assert!(
                    (back[i] - v[i]).abs() < 1e-13,
                    "{kind:?} node {i}: {} vs {}",
                    back[i],
                    v[i]
                );
            }
        }
    }

    #[test]
    fn every_kind_preserves_total_mass() {
        let m = model(10);
        let total: f64 = m.bar().element_mass().iter().sum();
        let free_free = Model::new(
            m.bar().clone(),
            crate::Supports::default(),
            &[crate::Load::Force {
                node: 3,
                magnitude: 1.0,
                time: TimeFunction::HEAVISIDE,
            }],
            Default::default(),
        )
        .unwrap();
        for kind in [
            MassKind::Lumped,
            MassKind::Consistent,
            MassKind::Averaged { beta: 0.3 },
            MassKind::Reciprocal { beta: 0.3 },
        ] {
            let op = MassOperator::new(&free_free, kind).unwrap();
            let mut ones_m = vec![0.0; 11];
            op.apply(&[1.0; 11], &mut ones_m);
            let sum: f64 = ones_m.iter().sum();
            assert!(
                (sum - total).abs() < 1e-13 * total,
                "{kind:?}: {sum} vs {total}"
            );
        }
    }

    #[test]
    fn beta_at_or_below_minus_one_half_is_refused() {
        let err = MassOperator::new(&model(3), MassKind::Averaged { beta: -0.5 }).unwrap_err();
        assert_eq!(
            err.to_string(),
            "beta = -0.5 must be finite and above -1/2 (positive definite mass)"
        );
        assert!(MassOperator::new(&model(3), MassKind::Reciprocal { beta: 3.0 }).is_ok());
    }

    #[test]
    fn rmm_maps_the_lumped_force_of_a_uniform_acceleration_to_that_acceleration() {
        // C 1 = A 1 (row sums of C_e are m_e/2), so M^-1 (A g 1) = A^-1 C g 1 = g 1.
        let m = model(11);
        let free_free = Model::unloaded(m.bar().clone(), crate::Supports::default());
        for beta in [0.0, 0.5, 1.0, 2.0] {
            let op = MassOperator::new(&free_free, MassKind::Reciprocal { beta }).unwrap();
            let force: Vec<f64> = free_free.nodal_mass().iter().map(|mi| 9.81 * mi).collect();
            let mut a = vec![0.0; 12];
            op.apply_inverse(&force, &mut a);
            assert!(
                a.iter().all(|ai| (ai - 9.81).abs() < 1e-12),
                "beta {beta}: {a:?}"
            );
        }
    }
}
