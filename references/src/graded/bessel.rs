//! The modified Bessel functions of route (a), normalised so that every exponential factors out:
//! `I^_nu(w) = sqrt(2 pi w) e^-w I_nu(w)`, `K^_nu(w) = sqrt(2 w/pi) e^w K_nu(w)` (module docs of
//! the Laplace route), from complex-bessel or, for large arguments, from their Hankel series
//! (Abramowitz & Stegun 9.7.1-9.7.2).

use complex_bessel::{Scaling, besseli_seq, besselk_seq};
use num_complex::Complex64 as C;
use std::f64::consts::PI;

/// For `Re(s r)` at least this, the Hankel series replaces complex-bessel (the terms that are
/// exponentially small, `e^{-2 Re(s r)} < 1e-34`, are dropped).
const ASYMPTOTIC_RE: f64 = 40.0;
/// Normalised modified Bessel functions of orders 0 and 1 at `w = s rho`:
/// `i[nu] = sqrt(2 pi w) e^-w I_nu(w)`, `k[nu] = sqrt(2 w/pi) e^w K_nu(w)`.
#[derive(Clone, Copy)]
pub(super) struct Normalised {
    pub(super) i: [C; 2],
    pub(super) k: [C; 2],
}

impl Normalised {
    const ONE: Self = Self {
        i: [C::new(1.0, 0.0); 2],
        k: [C::new(1.0, 0.0); 2],
    };
}

/// Ratio `a_j(nu)/a_{j-1}(nu) = (4 nu^2 - (2j - 1)^2)/(8j)` of the Hankel coefficients
/// (Abramowitz & Stegun 9.7.1-2: `K ~ sum a_j w^-j`, `I ~ sum (-1)^j a_j w^-j`).
pub(super) fn hankel_ratio(nu: f64, j: usize) -> f64 {
    let odd = (2 * j - 1) as f64;
    (4.0 * nu * nu - odd * odd) / (8.0 * j as f64)
}

/// Hankel series of the normalised functions for `Re w >= ASYMPTOTIC_RE` (terms decrease until
/// `j ~ 2|w| >= 80`, so 1e-17 is reached first).
fn normalised_asymptotic(w: C) -> Normalised {
    let mut out = Normalised::ONE;
    let inv = 1.0 / w;
    for nu in 0..2 {
        let mut term = C::new(1.0, 0.0);
        let (mut si, mut sk) = (term, term);
        for j in 1..80 {
            term *= inv * hankel_ratio(nu as f64, j);
            if j.is_multiple_of(2) {
                si += term;
            } else {
                si -= term;
            }
            sk += term;
            if term.norm() < 1e-17 {
                break;
            }
        }
        out.i[nu] = si;
        out.k[nu] = sk;
    }
    out
}

/// Normalised functions at `w = s/inv_rho` (`inv_rho = 1/rho = 0` means rho = infinity, the
/// homogeneous limit, where they are all 1). `None` if complex-bessel fails.
pub(super) fn normalised_bessel(s: C, inv_rho: f64) -> Option<Normalised> {
    if inv_rho == 0.0 {
        return Some(Normalised::ONE);
    }
    let w = s / inv_rho;
    if w.re >= ASYMPTOTIC_RE {
        return Some(normalised_asymptotic(w));
    }
    // complex-bessel's scaled values: e^{-|Re w|} I(w) and e^{w} K(w).
    let iv = besseli_seq(0.0, w, 2, Scaling::Exponential).ok()?.values;
    let kv = besselk_seq(0.0, w, 2, Scaling::Exponential).ok()?.values;
    let to_i = (w * (2.0 * PI)).sqrt() * C::from_polar(1.0, -w.im);
    let to_k = (w * (2.0 / PI)).sqrt();
    Some(Normalised {
        i: [iv[0] * to_i, iv[1] * to_i],
        k: [kv[0] * to_k, kv[1] * to_k],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalised_bessel_matches_its_asymptotic_series_where_both_apply() {
        let s = C::new(45.0, 30.0);
        let direct = {
            let w = s;
            let iv = besseli_seq(0.0, w, 2, Scaling::Exponential).unwrap().values;
            let kv = besselk_seq(0.0, w, 2, Scaling::Exponential).unwrap().values;
            let to_i = (w * (2.0 * PI)).sqrt() * C::from_polar(1.0, -w.im);
            let to_k = (w * (2.0 / PI)).sqrt();
            [iv[0] * to_i, iv[1] * to_i, kv[0] * to_k, kv[1] * to_k]
        };
        let series = normalised_asymptotic(s);
        let got = [series.i[0], series.i[1], series.k[0], series.k[1]];
        for (a, b) in direct.iter().zip(&got) {
            assert!((a - b).norm() < 1e-14, "{a} vs {b}");
        }
    }
}
