//! Exact element averages of the graded bar's stress: the interval split at the fronts and in
//! pieces shorter than the smoothness length, each integrated by Gauss-Legendre.

use super::bar::GradedBar;
use std::f64::consts::PI;

/// Gauss-Legendre nodes and weights on `[-1, 1]` (Newton on the Legendre recurrence).
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut derivative = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    (p0, p1) = (p1, p2);
                }
                derivative = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / derivative;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * derivative * derivative))
        })
        .collect()
}

/// Most Gauss points per smooth piece of an element average.
const AVERAGE_POINTS_MAX: usize = 12;

impl GradedBar {
    /// Length on which the field between fronts is analytic in x: the front expansions
    /// converge for time lags below `1/(2 kappa_max)`, i.e. over `c_min/(2 kappa_max)` in x.
    fn smoothness_length(&self) -> f64 {
        let b = self.gradient().abs();
        if b == 0.0 {
            return self.length();
        }
        let z_min = self.z1().min(self.z2());
        let c_min = z_min / self.density();
        (2.0 * c_min * z_min / b).min(self.length())
    }

    /// Exact mean of `sigma(., t)` over `[xa, xb]` (`0 <= xa < xb <= L`), what a linear
    /// element spanning `[xa, xb]` is compared with.
    ///
    /// The interval is split at [`Self::front_positions`]; each smooth piece (further split
    /// into parts no longer than the smoothness length `2 c_min z_min/|b|`) is integrated by
    /// Gauss-Legendre with 3 to 12 points chosen from the part's length for 1e-12 relative
    /// accuracy, using [`Self::stress`]. NaN unless the interval is valid and t finite.
    #[must_use]
    pub fn stress_average(&self, xa: f64, xb: f64, t: f64) -> f64 {
        if !(self.in_bar(xa) && self.in_bar(xb) && xa < xb && t.is_finite()) {
            return f64::NAN;
        }
        let (xa, xb) = (xa.clamp(0.0, self.length()), xb.clamp(0.0, self.length()));
        let mut sum = 0.0;
        for (x0, parts, width, n) in self.quadrature_plan(xa, xb, t) {
            let rule = gauss_legendre(n);
            for part in 0..parts {
                let mid = x0 + (part as f64 + 0.5) * width;
                for &(node, weight) in &rule {
                    sum += weight * 0.5 * width * self.stress(mid + 0.5 * width * node, t);
                }
            }
        }
        sum / (xb - xa)
    }

    /// The quadrature of [`Self::stress_average`] over `[xa, xb]` (inside the bar): per smooth
    /// piece between fronts, its start, the number of parts, their width and the Gauss points
    /// per part.
    fn quadrature_plan(&self, xa: f64, xb: f64, t: f64) -> Vec<(f64, usize, f64, usize)> {
        let mut cuts = vec![xa];
        cuts.extend(
            self.front_positions(t)
                .into_iter()
                .filter(|&x| x > xa && x < xb),
        );
        cuts.push(xb);
        let smooth = self.smoothness_length();
        cuts.windows(2)
            .map(|pair| {
                let (x0, x1) = (pair[0], pair[1]);
                let parts = ((x1 - x0) / smooth).ceil().max(1.0) as usize;
                let width = (x1 - x0) / parts as f64;
                // Error ~ (width/(4 smooth))^(2n): 1e-12 needs 2n log10(4 smooth/width) >= 12.
                let digits = (4.0 * smooth / width).log10().max(0.5);
                let n = ((6.0 / digits).ceil() as usize).clamp(3, AVERAGE_POINTS_MAX);
                (x0, parts, width, n)
            })
            .collect()
    }

    /// How many evaluations of [`Self::stress`] [`Self::stress_averages`] makes over `nodes` at
    /// time `t`, counted from its quadrature without evaluating anything: what
    /// [`Self::evaluation_work`] prices.
    #[must_use]
    pub fn average_evaluations(&self, nodes: &[f64], t: f64) -> usize {
        nodes
            .windows(2)
            .filter(|w| self.in_bar(w[0]) && self.in_bar(w[1]) && w[0] < w[1] && t.is_finite())
            .map(|w| {
                let (xa, xb) = (
                    w[0].clamp(0.0, self.length()),
                    w[1].clamp(0.0, self.length()),
                );
                self.quadrature_plan(xa, xb, t)
                    .iter()
                    .map(|&(_, parts, _, n)| parts.saturating_mul(n))
                    .fold(0usize, usize::saturating_add)
            })
            .fold(0usize, usize::saturating_add)
    }

    /// Element averages over consecutive pairs of `nodes` (ascending positions of a mesh).
    #[must_use]
    pub fn stress_averages(&self, nodes: &[f64], t: f64) -> Vec<f64> {
        nodes
            .windows(2)
            .map(|w| self.stress_average(w[0], w[1], t))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        let rule = gauss_legendre(5);
        let integral: f64 = rule.iter().map(|(x, w)| w * x.powi(8)).sum();
        assert!((integral - 2.0 / 9.0).abs() < 1e-14);
    }
}
