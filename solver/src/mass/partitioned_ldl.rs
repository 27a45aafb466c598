//! Partitioned ("SPIKE") solve of an SPD tridiagonal system: the global factor of CMM and AMM
//! (the step's solve for bars shorter than a group of windows, [`crate::mass::windows`], and for
//! masses whose inverse decays too slowly for windows), and of RMM's `C` for `M v`.
//!
//! The Thomas algorithm is one recurrence, `z_i = r_i - l_{i-1} z_{i-1}`: every row waits for
//! the previous one, so its time is the latency of a multiply-add per row, not the machine's
//! throughput. Cutting the matrix into `P` diagonal blocks gives `P` independent recurrences
//! that run interleaved; the blocks are then coupled exactly through a small interface system
//! (Sameh and Kuck, J. ACM 25 (1978); Polizzi and Sameh, Parallel Comput. 32 (2006)):
//!
//! ```text
//!   A = blockdiag(A_0 .. A_{P-1}) + couplings b_{e_j - 1} between the last row of block j and
//!       the first row of block j + 1
//!   y_j = A_j^-1 r_j                                   (P interleaved LDL^T solves)
//!   V_j = b_{e_j - 1} A_j^-1 e_last,  W_j = b_{s_j - 1} A_j^-1 e_first     (spikes, set up once)
//!   x_j = y_j - V_j t_{j+1} - W_j l_{j-1}              (t_j, l_j: first and last x of block j)
//! ```
//!
//! The last equation, taken at the first and last rows of every block, is a system of order
//! `2(P - 1)` for the interface values `(l_0, t_1, l_1, t_2, ..)`; it is LU-factored once (partial
//! pivoting). The arithmetic is O(n) and exact up to round-off for any SPD tridiagonal matrix
//! (its diagonal blocks are SPD too); the spikes decay geometrically away from the block ends
//! and the correction skips the rows where a spike is exactly zero. The partition depends only
//! on `n`, so results are bit-identical run to run.

use crate::error::NotPositiveDefinite;
use crate::mass::tridiagonal::Tridiagonal;

/// Number of blocks (independent recurrences) for large matrices: enough multiply-adds in
/// flight to cover their latency on a superscalar core.
const BLOCKS: usize = 8;

/// Order of the interface system with [`BLOCKS`] blocks.
const INTERFACE: usize = 2 * (BLOCKS - 1);

/// Smallest block worth partitioning for; smaller matrices use one block (plain LDL^T).
const MIN_BLOCK_ROWS: usize = 16;

/// Partitioned `L D L^T` factor of an SPD tridiagonal matrix (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct PartitionedLdl {
    /// Number of blocks: [`BLOCKS`] or 1.
    blocks: usize,
    /// Rows of every block but the last, which also takes the remainder.
    block_rows: usize,
    /// `lower[i] = L[i + 1][i]` of the block factor (0 at the last row of a block).
    lower: Vec<f64>,
    /// `1 / D[i]` of the block factor.
    inverse_pivot: Vec<f64>,
    /// `(V_i, W_i)`: the right and left spikes of the row's block.
    spikes: Vec<[f64; 2]>,
    /// Per block, the rows where the right spike is nonzero (a range ending at the block end).
    right_support: Vec<std::ops::Range<usize>>,
    /// Per block, the rows where the left spike is nonzero (a range starting at the block start).
    left_support: Vec<std::ops::Range<usize>>,
    /// LU factor of the interface system.
    interface: DenseLu,
}

impl PartitionedLdl {
    /// Factor the SPD tridiagonal matrix `a` for solves.
    ///
    /// # Errors
    /// [`NotPositiveDefinite`] when a pivot of its plain `L D L^T` factorisation is not
    /// positive.
    pub fn new(a: &Tridiagonal) -> Result<Self, NotPositiveDefinite> {
        Self::factor(a).ok_or(NotPositiveDefinite)
    }

    /// [`Self::new`], `None` for a matrix that is not positive definite.
    fn factor(a: &Tridiagonal) -> Option<Self> {
        let n = a.diag.len();
        // Positive definite iff every pivot of the plain factorisation is positive; the blocks'
        // pivots alone do not show it (each block may be SPD while the whole is not).
        let (mut lower, mut inverse_pivot) = (vec![0.0; n], vec![0.0; n]);
        if n == 0 || !factor_rows(a, 0..n, &mut lower, &mut inverse_pivot) {
            return None;
        }
        let blocks = if n >= BLOCKS * MIN_BLOCK_ROWS {
            BLOCKS
        } else {
            1
        };
        let block_rows = n / blocks;
        let range = |j: usize| {
            j * block_rows..if j + 1 == blocks {
                n
            } else {
                (j + 1) * block_rows
            }
        };
        // Block factors: the off-diagonal entry that couples two blocks is left out (with one
        // block, the plain factor above is it).
        if blocks > 1 {
            for j in 0..blocks {
                if !factor_rows(a, range(j), &mut lower, &mut inverse_pivot) {
                    return None;
                }
            }
        }
        // Spikes, block by block, and the rows where they are nonzero.
        let mut spikes = vec![[0.0; 2]; n];
        let mut right_support = vec![0..0; blocks];
        let mut left_support = vec![0..0; blocks];
        let mut column = vec![0.0; n];
        for j in 0..blocks {
            let rows = range(j);
            for (side, coupling, unit_row) in [
                (
                    0,
                    (j + 1 < blocks).then(|| a.off[rows.end - 1]),
                    rows.end - 1,
                ),
                (1, (j > 0).then(|| a.off[rows.start - 1]), rows.start),
            ] {
                let Some(b) = coupling else { continue };
                let x = &mut column[rows.clone()];
                x.fill(0.0);
                x[unit_row - rows.start] = b;
                solve_block(&lower[rows.clone()], &inverse_pivot[rows.clone()], x);
                for (s, xi) in spikes[rows.clone()].iter_mut().zip(x.iter()) {
                    s[side] = *xi;
                }
                let first = x.iter().position(|v| *v != 0.0).unwrap_or(x.len());
                let last = x.iter().rposition(|v| *v != 0.0).map_or(0, |p| p + 1);
                let support = rows.start + first..rows.start + last.max(first);
                if side == 0 {
                    right_support[j] = support;
                } else {
                    left_support[j] = support;
                }
            }
        }
        // Interface system for z = (l_0, t_1, l_1, t_2, .., l_{P-2}, t_{P-1}):
        //   row 2q     (last row i of block q):      z_2q   + V_i z_{2q+1} + W_i z_{2q-2} = y_i
        //   row 2q + 1 (first row i of block q + 1): z_2q+1 + V_i z_{2q+3} + W_i z_{2q}   = y_i
        let order = 2 * (blocks - 1);
        let mut system = vec![vec![0.0; order]; order];
        for q in 0..blocks - 1 {
            let (last, first) = (range(q).end - 1, range(q + 1).start);
            let [v, w] = spikes[last];
            system[2 * q][2 * q] = 1.0;
            system[2 * q][2 * q + 1] = v;
            if q > 0 {
                system[2 * q][2 * q - 2] = w;
            }
            let [v, w] = spikes[first];
            system[2 * q + 1][2 * q + 1] = 1.0;
            system[2 * q + 1][2 * q] = w;
            if q + 2 < blocks {
                system[2 * q + 1][2 * q + 3] = v;
            }
        }
        Some(Self {
            blocks,
            block_rows,
            lower,
            inverse_pivot,
            spikes,
            right_support,
            left_support,
            interface: DenseLu::new(system)?,
        })
    }

    /// Number of independent blocks the solve runs.
    pub fn blocks(&self) -> usize {
        self.blocks
    }

    /// Solve `A x = r` in place (`r` becomes `x`).
    pub fn solve_in_place(&self, x: &mut [f64]) {
        assert_eq!(
            x.len(),
            self.lower.len(),
            "right-hand side of the wrong length"
        );
        if self.blocks == 1 {
            solve_block(&self.lower, &self.inverse_pivot, x);
            return;
        }
        self.solve_blocks_interleaved(x);
        // Interface values from the block solutions, then the spike correction.
        let mut z = [0.0; INTERFACE];
        for q in 0..BLOCKS - 1 {
            let first = (q + 1) * self.block_rows;
            z[2 * q] = x[first - 1];
            z[2 * q + 1] = x[first];
        }
        self.interface.solve_in_place(&mut z);
        for j in 0..self.blocks {
            if j + 1 < self.blocks {
                let t_next = z[2 * j + 1];
                for i in self.right_support[j].clone() {
                    x[i] -= self.spikes[i][0] * t_next;
                }
            }
            if j > 0 {
                let l_previous = z[2 * j - 2];
                for i in self.left_support[j].clone() {
                    x[i] -= self.spikes[i][1] * l_previous;
                }
            }
        }
    }

    /// The [`BLOCKS`] block solves with their recurrences interleaved row by row; the last
    /// block's extra rows (the remainder of `n / BLOCKS`) run on their own.
    fn solve_blocks_interleaved(&self, x: &mut [f64]) {
        let m = self.block_rows;
        let n = self.lower.len();
        let tail = BLOCKS * m..n;
        let (l, p) = (&self.lower[..], &self.inverse_pivot[..]);
        assert!(m >= 1 && x.len() == n && l.len() == n && p.len() == n && BLOCKS * m <= n);
        let (lp, pp) = (l.as_ptr(), p.as_ptr());
        // Forward: z_i = r_i - l_{i-1} z_{i-1} within each block.
        let mut carry = [0.0; BLOCKS];
        for (j, c) in carry.iter_mut().enumerate() {
            *c = x[j * m];
        }
        let xp = x.as_mut_ptr();
        for k in 1..m {
            for (j, c) in carry.iter_mut().enumerate() {
                let i = j * m + k;
                // SAFETY: 1 <= i < BLOCKS * m <= n, the length of x, l and p (asserted above).
                unsafe {
                    let z = *xp.add(i) - *lp.add(i - 1) * *c;
                    *xp.add(i) = z;
                    *c = z;
                }
            }
        }
        let mut c = carry[BLOCKS - 1];
        for i in tail.clone() {
            c = x[i] - l[i - 1] * c;
            x[i] = c;
        }
        // Backward: x_i = z_i / d_i - l_i x_{i+1} (l_i = 0 at a block's last row).
        let mut next = 0.0;
        for i in tail.rev() {
            next = x[i] * p[i] - l[i] * next;
            x[i] = next;
        }
        let mut carry = [0.0; BLOCKS];
        carry[BLOCKS - 1] = next;
        let xp = x.as_mut_ptr();
        for k in (0..m).rev() {
            for (j, c) in carry.iter_mut().enumerate() {
                let i = j * m + k;
                // SAFETY: i < BLOCKS * m <= n, the length of x, l and p (asserted above).
                unsafe {
                    let xi = *xp.add(i) * *pp.add(i) - *lp.add(i) * *c;
                    *xp.add(i) = xi;
                    *c = xi;
                }
            }
        }
    }
}

/// `L D L^T` solve of one block with its factor `lower`, `inverse_pivot` (`lower` 0 at its last
/// row), `x` holding exactly the block's rows.
fn solve_block(lower: &[f64], inverse_pivot: &[f64], x: &mut [f64]) {
    for i in 1..x.len() {
        x[i] -= lower[i - 1] * x[i - 1];
    }
    let mut next = 0.0;
    for i in (0..x.len()).rev() {
        next = x[i] * inverse_pivot[i] - lower[i] * next;
        x[i] = next;
    }
}

/// `L D L^T` factor of the rows `rows` of `a` on their own (the coupling to the rows outside is
/// left out): `lower[i] = l_i` (0 at the last row), `inverse_pivot[i] = 1/d_i`; false when a
/// pivot is not positive (the rows are not positive definite).
pub(crate) fn factor_rows(
    a: &Tridiagonal,
    rows: std::ops::Range<usize>,
    lower: &mut [f64],
    inverse_pivot: &mut [f64],
) -> bool {
    let mut previous: Option<(f64, f64)> = None; // (pivot, lower) of the row above
    for i in rows.clone() {
        let pivot = a.diag[i] - previous.map_or(0.0, |(d, l)| l * l * d);
        if pivot.is_nan() || pivot <= 0.0 {
            return false;
        }
        let l = if i + 1 < rows.end {
            a.off[i] / pivot
        } else {
            0.0
        };
        lower[i] = l;
        inverse_pivot[i] = 1.0 / pivot;
        previous = Some((pivot, l));
    }
    true
}

/// Dense LU factor with partial pivoting of a small square matrix (the interface system).
#[derive(Debug, Clone, PartialEq)]
struct DenseLu {
    /// `L` (unit, strictly below the diagonal) and `U` (on and above it), by rows.
    lu: Vec<Vec<f64>>,
    /// Row `i` of the factor is row `permutation[i]` of the matrix.
    permutation: Vec<usize>,
}

impl DenseLu {
    /// Doolittle elimination with partial pivoting; `None` when the matrix is singular.
    fn new(mut a: Vec<Vec<f64>>) -> Option<Self> {
        let order = a.len();
        let mut permutation: Vec<usize> = (0..order).collect();
        for k in 0..order {
            let pivot_row = (k..order).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))?;
            if a[pivot_row][k] == 0.0 || !a[pivot_row][k].is_finite() {
                return None;
            }
            a.swap(k, pivot_row);
            permutation.swap(k, pivot_row);
            let (done, below) = a.split_at_mut(k + 1);
            let pivot = &done[k];
            for row in below {
                let factor = row[k] / pivot[k];
                row[k] = factor;
                for (x, p) in row[k + 1..].iter_mut().zip(&pivot[k + 1..]) {
                    *x -= factor * p;
                }
            }
        }
        Some(Self { lu: a, permutation })
    }

    /// Solve `A x = b` in place (order at most [`INTERFACE`]; no allocation).
    fn solve_in_place(&self, b: &mut [f64]) {
        let order = b.len();
        let mut buffer = [0.0; INTERFACE];
        let x = &mut buffer[..order];
        for (xi, &row) in x.iter_mut().zip(&self.permutation) {
            *xi = b[row];
        }
        for i in 0..order {
            for j in 0..i {
                x[i] -= self.lu[i][j] * x[j];
            }
        }
        for i in (0..order).rev() {
            for j in i + 1..order {
                x[i] -= self.lu[i][j] * x[j];
            }
            x[i] /= self.lu[i][i];
        }
        b.copy_from_slice(x);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A varied SPD tridiagonal matrix (diagonally dominant by `dominance`).
    fn matrix(n: usize, dominance: f64) -> Tridiagonal {
        let off: Vec<f64> = (0..n.saturating_sub(1))
            .map(|i| 0.9 * (i as f64 * 1.3).cos() + 0.05)
            .collect();
        let diag = (0..n)
            .map(|i| {
                let left = if i > 0 { off[i - 1].abs() } else { 0.0 };
                let right = if i + 1 < n { off[i].abs() } else { 0.0 };
                dominance * (left + right) + 0.01 * (1.0 + (i as f64 * 0.7).sin())
            })
            .collect();
        Tridiagonal { diag, off }
    }

    fn max_difference(p: &[f64], q: &[f64]) -> f64 {
        p.iter()
            .zip(q)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
    }

    fn residual(a: &Tridiagonal, x: &[f64], b: &[f64]) -> f64 {
        let mut ax = vec![0.0; x.len()];
        a.apply(x, &mut ax);
        max_difference(&ax, b)
    }

    #[test]
    fn solves_every_order_with_one_or_many_blocks() {
        // Orders around the partition threshold and with every remainder of n / BLOCKS.
        for n in (1..=40).chain(120..=140).chain([1000, 1003, 4099]) {
            // Barely dominant (spikes reach across whole blocks) and strongly dominant.
            for dominance in [1.0, 4.0] {
                let a = matrix(n, dominance);
                let factor = PartitionedLdl::new(&a).unwrap();
                assert_eq!(factor.blocks(), if n >= 128 { BLOCKS } else { 1 });
                let x: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).cos() - 0.2).collect();
                let mut b = vec![0.0; n];
                a.apply(&x, &mut b);
                let rhs = b.clone();
                factor.solve_in_place(&mut b);
                let error = max_difference(&b, &x);
                // Measured: error <= 1.1e-14, residual <= 3.6e-15 over all of these.
                assert!(
                    error < 1e-13,
                    "n = {n}, dominance {dominance}: error {error:e}"
                );
                assert!(residual(&a, &b, &rhs) < 1e-14);
            }
        }
    }

    #[test]
    fn decoupled_rows_and_zero_couplings_at_block_boundaries() {
        // Decoupled rows (fixed nodes) at both ends and on block boundaries: the interface
        // system then has zero spikes there and the blocks are independent.
        let n = 1000;
        let mut a = matrix(n, 1.5);
        let m = n / BLOCKS;
        for i in [0, m - 1, m, 3 * m, n - 1] {
            a.decouple(i);
        }
        let factor = PartitionedLdl::new(&a).unwrap();
        let b: Vec<f64> = (0..n).map(|i| (i as f64 * 0.11).sin()).collect();
        let mut x = b.clone();
        factor.solve_in_place(&mut x);
        assert!(residual(&a, &x, &b) < 1e-12);
        for i in [0, m - 1, m, 3 * m, n - 1] {
            assert_eq!(x[i], b[i], "a decoupled row is its own right-hand side");
        }
    }

    #[test]
    fn spikes_are_skipped_only_where_exactly_zero() {
        // Strongly dominant: the spikes underflow to zero far from the block ends, and the
        // support ranges leave those rows out without changing any value.
        let n = 100_000;
        let a = matrix(n, 20.0);
        let factor = PartitionedLdl::new(&a).unwrap();
        let m = n / BLOCKS;
        assert!(factor.right_support[0].len() < m / 4);
        assert!(factor.left_support[1].len() < m / 4);
        for j in 0..BLOCKS {
            let block = j * m..if j + 1 == BLOCKS { n } else { (j + 1) * m };
            for (side, range) in [&factor.right_support[j], &factor.left_support[j]]
                .into_iter()
                .enumerate()
            {
                for i in block.clone().filter(|i| !range.contains(i)) {
                    assert_eq!(factor.spikes[i][side], 0.0, "block {j}, row {i}");
                }
            }
        }
        let x: Vec<f64> = (0..n).map(|i| 1.0 + (i as f64 * 0.01).sin()).collect();
        let mut b = vec![0.0; n];
        a.apply(&x, &mut b);
        factor.solve_in_place(&mut b);
        let error = max_difference(&b, &x);
        assert!(error < 1e-13, "error {error:e}");
    }

    #[test]
    fn indefinite_matrices_are_refused() {
        let indefinite = Tridiagonal {
            diag: vec![1.0, 1.0],
            off: vec![2.0],
        };
        assert!(PartitionedLdl::new(&indefinite).is_err());
        // Every block SPD, the whole not: the plain pivots catch it.
        let n = 256;
        let mut a = matrix(n, 1.0);
        a.off[n / BLOCKS - 1] = 1e3;
        assert!(PartitionedLdl::new(&a).is_err());
    }

    #[test]
    fn interface_lu_solves_with_pivoting() {
        let a = vec![
            vec![0.0, 2.0, 1.0],
            vec![1.0, 1.0, 0.0],
            vec![3.0, 0.0, 1.0],
        ];
        let lu = DenseLu::new(a.clone()).unwrap();
        let x = [1.0, -2.0, 0.5];
        let mut b: Vec<f64> = a
            .iter()
            .map(|row| row.iter().zip(&x).map(|(p, q)| p * q).sum())
            .collect();
        lu.solve_in_place(&mut b);
        for i in 0..3 {
            assert!((b[i] - x[i]).abs() < 1e-15);
        }
        assert!(DenseLu::new(vec![vec![1.0, 2.0], vec![2.0, 4.0]]).is_none());
    }
}
