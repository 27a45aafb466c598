//! The symmetric tridiagonal matrix of the 1D mass operators (consistent, averaged and
//! reciprocal masses): storage, the matrix-vector product and the decoupling of a fixed row. Its
//! SPD factor, [`crate::mass::partitioned_ldl::PartitionedLdl`], is built from it in its own
//! module (the matrix sits below its factor).

/// Symmetric tridiagonal matrix: `diag[i]`, `off[i] = A[i][i+1] = A[i+1][i]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Tridiagonal {
    /// Diagonal, length n.
    pub diag: Vec<f64>,
    /// Super-diagonal, length n - 1.
    pub off: Vec<f64>,
}

impl Tridiagonal {
    /// `y = A x`.
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        let n = self.diag.len();
        let (d, o) = (&self.diag, &self.off);
        if n == 1 {
            y[0] = d[0] * x[0];
            return;
        }
        y[0] = d[0] * x[0] + o[0] * x[1];
        // Interior rows as zipped windows: no bounds checks, so the loop vectorises.
        for (((yi, xs), di), os) in y[1..n - 1]
            .iter_mut()
            .zip(x.windows(3))
            .zip(&d[1..n - 1])
            .zip(o.windows(2))
        {
            *yi = os[0] * xs[0] + di * xs[1] + os[1] * xs[2];
        }
        y[n - 1] = o[n - 2] * x[n - 2] + d[n - 1] * x[n - 1];
    }

    /// Decouple row and column `i`: zero its off-diagonals and set the diagonal to 1 (the
    /// matrix of the remaining rows and columns is the one with `i` deleted).
    pub fn decouple(&mut self, i: usize) {
        self.diag[i] = 1.0;
        if i > 0 {
            self.off[i - 1] = 0.0;
        }
        if i < self.off.len() {
            self.off[i] = 0.0;
        }
    }
}
