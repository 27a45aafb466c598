//! The time shift of a file's stress profiles on continuous time: the `s` (in steps of `dt`)
//! for which the exact solution at `t + s dt` fits the file best.
//!
//! A profile's error hides a shift of a step behind the dispersion of a front; its integral does
//! not. With `S(x, t) = int_x^L sigma(y, t) dy` (the stress integrated from the far end: `E`
//! times the displacement relative to the fixed end of a homogeneous bar), the file's `S` at the
//! ends of its cells (elements, or the cells of its points) is compared with the exact `S` at
//! the same places at `t + s dt`, computed from exact cell averages: an exact integral, so the
//! comparison is continuous in `s` even where a front sits inside a cell, and element-average
//! and point files give the same `s` for the same run. The least squares over every profile,
//!
//! ```text
//!   min_s  sum_p |S_file,p - S_exact,p(t_p + s dt)|_w^2      (w: cell lengths)
//! ```
//!
//! is solved by Gauss-Newton steps from `s = 0`, the derivative taken over one step,
//! `d = S_exact(t + (s + 1/2) dt) - S_exact(t + (s - 1/2) dt)`; `S_exact` is piecewise linear in
//! `t` between the times a front crosses a cell end, so two or three steps converge. The
//! residual `r = |e - s d|_w / |d|_w` is the part of the error no shift explains, in steps.

/// Gauss-Newton steps at most.
const ITERATIONS: usize = 12;

/// A step below this (steps) ends the iteration.
const CONVERGED: f64 = 1e-6;

/// The search stays within this many steps of 0 (beyond it no diagnostic is read).
const REACH: f64 = 4.0;

/// `S_i = sum_{j >= i} w_j v_j`: the integral from value `i` to the far end.
pub fn integral_from_end(weights: &[f64], values: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; values.len()];
    let mut sum = 0.0;
    for i in (0..values.len()).rev() {
        sum += weights[i] * values[i];
        out[i] = sum;
    }
    out
}

/// The least-squares shift `s` of the error `e` against the one-step change `d` and its
/// residual `r` (weights `w`); `None` when `d` vanishes (nothing moves over a step).
pub fn fit_shift(weights: &[f64], e: &[f64], d: &[f64]) -> Option<(f64, f64)> {
    let dot = |a: &[f64], b: &[f64]| -> f64 {
        weights
            .iter()
            .zip(a.iter().zip(b))
            .map(|(w, (x, y))| w * x * y)
            .sum()
    };
    let dd = dot(d, d);
    let scale = dot(e, e).max(dd);
    if dd.is_nan() || dd <= 1e-28 * scale || !dd.is_finite() {
        return None;
    }
    let s = dot(e, d) / dd;
    let residual: Vec<f64> = e.iter().zip(d).map(|(x, y)| x - s * y).collect();
    Some((s, (dot(&residual, &residual) / dd).sqrt()))
}

/// One profile to fit: its time, its cells' lengths and its values (sign corrected).
pub struct FitProfile<'a> {
    /// Output time.
    pub time: f64,
    /// Cell lengths (element lengths, or the cells of the points).
    pub weights: Vec<f64>,
    /// The file's values, as the reference's sign and layout would have them.
    pub values: &'a [f64],
}

/// The shift `(s, r)` of `profiles` against `exact(profile index, t)`, the exact cell averages
/// of a profile's cells at time `t` (clamped to `t >= 0`); `None` when the exact solution does
/// not change over a step at the profiles' times, or the iteration does not settle.
pub fn fit_profiles(
    profiles: &[FitProfile<'_>],
    dt: f64,
    exact: &dyn Fn(usize, f64) -> Vec<f64>,
) -> Option<(f64, f64)> {
    let file: Vec<f64> = profiles
        .iter()
        .flat_map(|p| integral_from_end(&p.weights, p.values))
        .collect();
    let weights: Vec<f64> = profiles
        .iter()
        .flat_map(|p| p.weights.iter().copied())
        .collect();
    let at = |s: f64| -> Vec<f64> {
        profiles
            .iter()
            .enumerate()
            .flat_map(|(i, p)| integral_from_end(&p.weights, &exact(i, (p.time + s * dt).max(0.0))))
            .collect()
    };
    let mut s = 0.0;
    for _ in 0..ITERATIONS {
        let now = at(s);
        let (ahead, behind) = (at(s + 0.5), at(s - 0.5));
        let d: Vec<f64> = ahead.iter().zip(&behind).map(|(a, b)| a - b).collect();
        let e: Vec<f64> = file.iter().zip(&now).map(|(f, x)| f - x).collect();
        let (step, residual) = fit_shift(&weights, &e, &d)?;
        if !step.is_finite() {
            return None;
        }
        let next = (s + step).clamp(-REACH, REACH);
        if (next - s).abs() < CONVERGED || next.abs() >= REACH {
            return Some((next, residual));
        }
        s = next;
    }
    let now = at(s);
    let d: Vec<f64> = at(s + 0.5)
        .iter()
        .zip(&at(s - 0.5))
        .map(|(a, b)| a - b)
        .collect();
    let e: Vec<f64> = file.iter().zip(&now).map(|(f, x)| f - x).collect();
    fit_shift(&weights, &e, &d).map(|(step, r)| (s + step, r))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact cell averages of a unit step front `sigma = -1` for `x < t` on cells of `h`.
    fn front(h: f64, n: usize, t: f64) -> Vec<f64> {
        (0..n)
            .map(|i| {
                let (a, b) = (i as f64 * h, (i + 1) as f64 * h);
                -((t.clamp(a, b) - a) / h)
            })
            .collect()
    }

    #[test]
    fn a_pure_shift_is_fitted_exactly() {
        let e = [-0.25, -0.5, -0.125];
        let d = [1.0, 2.0, 0.5];
        let (s, r) = fit_shift(&[1.0; 3], &e, &d).unwrap();
        assert!((s + 0.25).abs() < 1e-15 && r < 1e-15);
        assert_eq!(fit_shift(&[1.0; 3], &e, &[0.0; 3]), None);
        assert_eq!(integral_from_end(&[1.0, 2.0], &[3.0, 4.0]), vec![11.0, 8.0]);
    }

    #[test]
    fn a_front_shifted_by_a_fraction_of_a_step_is_found_on_any_cells() {
        // A front moving one cell per 10 steps (Co = 0.1): a shift of a quarter step moves it
        // a fortieth of a cell, which the integral resolves.
        let (h, n, dt) = (0.01, 100, 0.001);
        for shift in [-1.0, -0.5, -0.25, 0.5, 2.0] {
            let values = front(h, n, 0.5 + shift * dt);
            let p = [FitProfile {
                time: 0.5,
                weights: vec![h; n],
                values: &values,
            }];
            let (s, r) = fit_profiles(&p, dt, &|_, t| front(h, n, t)).unwrap();
            assert!((s - shift).abs() < 1e-9 && r < 1e-9, "{shift}: {s} {r}");
        }
    }
}
