//! Truncated power series in `1/s` for the front expansions of route (a): the Hankel series of
//! the normalised Bessel functions, their algebra, and the shifted Taylor basis
//! `e^{-a t} sum d_m t^m/m!` (and its transform) that is subtracted before the inversion.

use super::bessel::hankel_ratio;
use num_complex::Complex64 as C;

/// Order N of the front expansions subtracted before the inversion: the remainder has N
/// continuous derivatives at every front.
pub const FRONT_SERIES_ORDER: usize = 12;
pub(super) const NS: usize = FRONT_SERIES_ORDER + 1;
/// Truncated power series in 1/s (coefficients of `s^0 .. s^-N`).
pub(super) type Series = [f64; NS];
/// Hankel series of a normalised function of order nu at `s rho`, as a series in `1/s`.
pub(super) fn hankel_series(nu: f64, inv_rho: f64, alternating: bool) -> Series {
    let sign = if alternating { -1.0 } else { 1.0 };
    let mut out = [0.0; NS];
    out[0] = 1.0;
    for j in 1..NS {
        out[j] = out[j - 1] * hankel_ratio(nu, j) * inv_rho * sign;
    }
    out
}

pub(super) fn series_mul(a: &Series, b: &Series) -> Series {
    let mut out = [0.0; NS];
    for (i, ai) in a.iter().enumerate() {
        for (o, bj) in out[i..].iter_mut().zip(b) {
            *o += ai * bj;
        }
    }
    out
}

pub(super) fn series_div(a: &Series, b: &Series) -> Series {
    let mut out = [0.0; NS];
    for n in 0..NS {
        let acc: f64 = (1..=n).map(|j| b[j] * out[n - j]).sum();
        out[n] = (a[n] - acc) / b[0];
    }
    out
}

pub(super) fn series_scale(a: &Series, f: f64) -> Series {
    a.map(|v| v * f)
}

/// Coefficients `d_m = sum_n binom(m, n) a^(m-n) c_n` of `e^{at} sum c_n t^n/n!`, so that
/// `e^{-at} sum d_m t^m/m!` has the Taylor coefficients c at t = 0 (Leibniz).
pub(super) fn leibniz_shift(c: &Series, a: f64) -> Series {
    let mut out = [0.0; NS];
    for (m, o) in out.iter_mut().enumerate() {
        let mut binom = 1.0; // binom(m, m - k) as k grows
        let mut power = 1.0; // a^k
        for k in 0..=m {
            if k > 0 {
                binom *= (m - k + 1) as f64 / k as f64;
                power *= a;
            }
            *o += binom * power * c[m - k];
        }
    }
    out
}

/// `e^{-a t} sum_m d_m t^m/m!` for t >= 0.
pub(super) fn shifted_taylor(d: &Series, a: f64, t: f64) -> f64 {
    let mut sum = 0.0;
    let mut power = 1.0;
    for (m, dm) in d.iter().enumerate() {
        if m > 0 {
            power *= t / m as f64;
        }
        sum += dm * power;
    }
    (-a * t).exp() * sum
}

/// Laplace transform of [`shifted_taylor`]: `sum_m d_m/(s + a)^(m+1)`.
pub(super) fn shifted_taylor_transform(d: &Series, a: f64, s: C) -> C {
    let u = 1.0 / (s + a);
    d.iter()
        .rev()
        .fold(C::new(0.0, 0.0), |acc, dm| acc * u + dm)
        * u
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_division_inverts_multiplication() {
        let a = hankel_series(1.0, 0.7, true);
        let b = hankel_series(0.0, 1.3, false);
        let back = series_div(&series_mul(&a, &b), &b);
        for (x, y) in back.iter().zip(&a) {
            assert!((x - y).abs() < 1e-12 * (1.0 + y.abs()));
        }
    }

    #[test]
    fn leibniz_shift_reproduces_the_taylor_coefficients() {
        // e^{-a t} sum d_m t^m/m! must equal sum c_n t^n/n! to order N at t -> 0.
        let mut c = [0.0; NS];
        c[0] = 1.0;
        c[1] = -0.5;
        c[2] = 0.25;
        let a = 3.0;
        let d = leibniz_shift(&c, a);
        let t = 1e-3;
        let exact = 1.0 - 0.5 * t + 0.25 * t * t / 2.0;
        assert!((shifted_taylor(&d, a, t) - exact).abs() < 1e-15);
    }
}
