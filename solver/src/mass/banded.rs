//! Small symmetric banded-matrix kernels: tridiagonal matrix-vector products ([`Tridiagonal`]),
//! the SPD solve of [`PartitionedLdl`], and the inertia (count of negative pivots) of a symmetric
//! banded matrix, which by Sylvester's law of inertia counts the eigenvalues of a definite pencil
//! below a shift (Wilkinson, The Algebraic Eigenvalue Problem (1965), §5.37; Parlett, The
//! Symmetric Eigenvalue Problem (1998), §3.3).
//!
//! The tridiagonal matrix and its factor live in their own modules (the factor is built from the
//! matrix, so the matrix sits below it); this module gathers them with the banded matrix.

pub use crate::mass::partitioned_ldl::PartitionedLdl;
pub use crate::mass::tridiagonal::Tridiagonal;

/// Symmetric banded matrix stored by rows in one array: `A[i][i + j]` at `i (bandwidth + 1) + j`
/// for `j = 0..=bandwidth`.
#[derive(Debug, Clone, PartialEq)]
pub struct SymmetricBanded {
    /// Half-bandwidth.
    pub bandwidth: usize,
    /// Order.
    order: usize,
    /// Upper band by rows.
    band: Vec<f64>,
}

impl SymmetricBanded {
    /// Zero matrix of order `n` and half-bandwidth `bandwidth`.
    pub fn zeros(n: usize, bandwidth: usize) -> Self {
        Self {
            bandwidth,
            order: n,
            band: vec![0.0; n * (bandwidth + 1)],
        }
    }

    /// Order.
    pub fn order(&self) -> usize {
        self.order
    }

    /// `A[i][j]` for `|i - j| <= bandwidth` (0 outside the band).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        let (i, j) = if i <= j { (i, j) } else { (j, i) };
        if j - i > self.bandwidth {
            0.0
        } else {
            self.band[i * (self.bandwidth + 1) + j - i]
        }
    }

    /// Add `value` to `A[i][j]` (and its mirror).
    pub fn add(&mut self, i: usize, j: usize, value: f64) {
        let (i, j) = if i <= j { (i, j) } else { (j, i) };
        self.band[i * (self.bandwidth + 1) + j - i] += value;
    }

    /// Set `A[i][j]` (and its mirror) to `value`.
    pub fn set(&mut self, i: usize, j: usize, value: f64) {
        let (i, j) = if i <= j { (i, j) } else { (j, i) };
        self.band[i * (self.bandwidth + 1) + j - i] = value;
    }

    /// Largest absolute row sum `max_i sum_j |A_ij|` (bounds the spectral radius).
    pub fn max_abs_row_sum(&self) -> f64 {
        let n = self.order();
        (0..n)
            .map(|i| {
                let lo = i.saturating_sub(self.bandwidth);
                let hi = (i + self.bandwidth).min(n - 1);
                (lo..=hi).map(|j| self.get(i, j).abs()).sum::<f64>()
            })
            .fold(0.0, f64::max)
    }

    /// Number of negative pivots of the LDL^T factorisation (without pivoting) of `self - x other`,
    /// both of the same order. By Sylvester's law of inertia this is the number of eigenvalues of
    /// the pencil `(self, other)` below `x` when `other` is positive definite. A zero pivot is
    /// replaced by a tiny negative one (the shift is then an eigenvalue to working precision).
    pub fn negative_pivots_of_shifted(&self, other: &SymmetricBanded, x: f64) -> usize {
        let n = self.order();
        let b = self.bandwidth.max(other.bandwidth);
        let entry = |i: usize, j: usize| self.get(i, j) - x * other.get(i, j);
        // Row i of L reads rows and pivots i - b..i only: the last b + 1 rows of L (strictly
        // lower part, by distance from the diagonal) and pivots d, row r in slot r & mask (a
        // ring of a power of two >= b + 1 slots). No allocation per row (a bisection calls
        // this many times on long bars).
        let slots = (b + 1).next_power_of_two();
        let mask = slots - 1;
        let mut d = vec![0.0; slots];
        let mut l = vec![0.0; slots * slots]; // L[r][r - k] at (r & mask) * slots + k
        let at = |r: usize, k: usize| (r & mask) * slots + k;
        let mut count = 0;
        let scale = x.abs().max(f64::MIN_POSITIVE);
        for i in 0..n {
            for k in (1..=b.min(i)).rev() {
                let j = i - k;
                // L[i][j] = (A[i][j] - sum_{m < j, i - m <= b} L[i][m] L[j][m] d[m]) / d[j]
                let mut s = entry(i, j);
                for m in i.saturating_sub(b)..j {
                    s -= l[at(i, i - m)] * l[at(j, j - m)] * d[m & mask];
                }
                l[at(i, k)] = s / d[j & mask];
            }
            let mut s = entry(i, i);
            for m in i.saturating_sub(b)..i {
                s -= l[at(i, i - m)] * l[at(i, i - m)] * d[m & mask];
            }
            if s == 0.0 {
                s = -f64::EPSILON * scale;
            }
            d[i & mask] = s;
            if s < 0.0 {
                count += 1;
            }
        }
        count
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inertia_counts_eigenvalues_of_a_pencil_below_a_shift() {
        // Pencil (diag(1, 2, 3), I): eigenvalues 1, 2, 3.
        let mut a = SymmetricBanded::zeros(3, 1);
        let mut m = SymmetricBanded::zeros(3, 1);
        for i in 0..3 {
            a.add(i, i, (i + 1) as f64);
            m.add(i, i, 1.0);
        }
        assert_eq!(a.negative_pivots_of_shifted(&m, 0.5), 0);
        assert_eq!(a.negative_pivots_of_shifted(&m, 2.5), 2);
        assert_eq!(a.negative_pivots_of_shifted(&m, 9.0), 3);
    }
}
