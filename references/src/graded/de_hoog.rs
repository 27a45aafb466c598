//! Numerical inversion of a Laplace transform on a Bromwich line: de Hoog, Knight & Stokes,
//! *An improved method for numerical inversion of Laplace transforms*, SIAM J. Sci. Stat.
//! Comput. 3 (1982) 357-366.

use num_complex::Complex64 as C;
use std::f64::consts::PI;

/// de Hoog, Knight & Stokes (1982): `f(t)` from `fp[k] = F(gamma + i k pi/half_period)`,
/// `k = 0..=2M`, by the quotient-difference continued fraction of the Fourier series with
/// their improved remainder. If the QD table breaks down (a division by zero when the data are
/// at round-off level), the continued fraction is truncated before the breakdown.
pub(super) fn de_hoog(fp: &[C], t: f64, half_period: f64, gamma: f64) -> f64 {
    let m = (fp.len() - 1) / 2;
    let zero = C::new(0.0, 0.0);
    let finite = |v: &C| v.re.is_finite() && v.im.is_finite();
    let mut d = Vec::with_capacity(2 * m + 1);
    d.push(fp[0] * 0.5);
    let mut q: Vec<C> = (0..2 * m)
        .map(|i| fp[i + 1] / if i == 0 { fp[0] * 0.5 } else { fp[i] })
        .collect();
    let mut e = vec![zero; 2 * m + 1];
    for r in 1..=m {
        let e_new: Vec<C> = (0..2 * (m - r) + 1)
            .map(|i| q[i + 1] - q[i] + e[i + 1])
            .collect();
        let (dq, de) = (-q[0], -e_new[0]);
        if !(finite(&dq) && finite(&de)) {
            break;
        }
        d.push(dq);
        d.push(de);
        if r < m {
            q = (0..2 * (m - r))
                .map(|i| q[i + 1] * e_new[i + 1] / e_new[i])
                .collect();
        }
        e = e_new;
        e.push(zero);
    }
    let n = d.len() - 1;
    let z = C::from_polar(1.0, PI * t / half_period);
    let one = C::new(1.0, 0.0);
    let (mut a0, mut a1, mut b0, mut b1) = (zero, d[0], one, one);
    if n >= 2 {
        for di in &d[1..n] {
            (a0, a1) = (a1, a1 + di * a0 * z);
            (b0, b1) = (b1, b1 + di * b0 * z);
        }
        let brem = (one + (d[n - 1] - d[n]) * z) * 0.5;
        let w = d[n] * z / brem;
        // brem (sqrt(1 + w) - 1), without cancellation for small w
        let rem = brem * (w / ((one + w).sqrt() + 1.0));
        (a1, b1) = (a1 + rem * a0, b1 + rem * b0);
    }
    let scale = (gamma * t).exp() / half_period;
    let value = scale * (a1 / b1).re;
    // Guard: the true value cannot exceed the sum of the moduli of the Fourier terms (up to
    // the small tail). A Pade approximant of data at round-off level (a remainder that
    // vanishes identically, e.g. the velocity at the fixed end) can have spurious poles;
    // fall back to the plain trapezoidal sum then.
    let bound = scale * (0.5 * fp[0].norm() + fp[1..].iter().map(|f| f.norm()).sum::<f64>());
    if value.is_finite() && value.abs() <= 10.0 * bound {
        return value;
    }
    let mut power = one;
    let mut sum = fp[0] * 0.5;
    for f in &fp[1..] {
        power *= z;
        sum += f * power;
    }
    scale * sum.re
}

#[cfg(test)]
mod tests {
    use super::*;
    // The parameters route (a) inverts with.
    use crate::graded::laplace::{DE_HOOG_TERMS, DE_HOOG_TOLERANCE};

    #[test]
    fn de_hoog_inverts_a_smooth_and_a_delayed_step_transform() {
        let invert = |f: &dyn Fn(C) -> C, t: f64| {
            let half = 1.5 * t;
            let gamma = -DE_HOOG_TOLERANCE.ln() / (2.0 * half);
            let fp: Vec<C> = (0..=2 * DE_HOOG_TERMS)
                .map(|k| f(C::new(gamma, k as f64 * PI / half)))
                .collect();
            de_hoog(&fp, t, half, gamma)
        };
        let sine = |s: C| 1.0 / (s * s + 1.0);
        for t in [0.3, 1.0, 2.5] {
            assert!((invert(&sine, t) - f64::sin(t)).abs() < 1e-10);
        }
        let step = |s: C| 1.0 / s;
        assert!((invert(&step, 0.7) - 1.0).abs() < 1e-10);
    }
}
