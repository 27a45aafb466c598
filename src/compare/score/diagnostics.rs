//! Diagnostics of a result file, each with its own verdict: the time-level offset (a result
//! written one step early or late is the commonest bug when a code is wired to a harness), the
//! sign convention (tension positive) and the load convention (`H(0) = 1` or `1/2`).
//!
//! **Time shift.** A stress profile's error hides a shift of a step behind the dispersion of a
//! front; its integral does not. With `S(x, t) = int_x^L sigma(y, t) dy` (the stress integrated
//! from the far end, proportional to the displacement of a homogeneous bar fixed there), the
//! error `e = S_file - S_exact(t)` is compared with the change of the exact `S` over one step,
//! `d = (S_exact(t + dt) - S_exact(t - dt)) / 2` (forward when `t < dt`). The least-squares
//! shift in steps and its residual are
//!
//! ```text
//!   s = <e, d>_w / <d, d>_w,      r = |e - s d|_w / |d|_w     (w: element or cell lengths)
//! ```
//!
//! A file written one step late gives `s = -1`; a step load with `H(0) = 1/2` instead of 1 gives
//! `s = -1/4` (central difference then delivers `F dt/4` less momentum in its first half step,
//! which lags the motion by a quarter step). `r` is the part of the error no shift explains, in
//! steps: small for an accurate run, about 1 where dispersion is as large as a step's change
//! (measured here on the Fig. 1 bar: `r` = 0.23 and 0.38 for lumped CD at Co = 0.5, 1.3 and 2.1
//! at Co = 0.1, at t = 0.5 and 1.5, with `s` biased by up to 0.25 at Co = 0.1). Hence:
//!
//! - offset = `round(mean s)` over the profiles, a failure unless 0; claimed only when the fit
//!   explains the error as a shift of a few steps, `|s| <= 2.5` ([`MAX_OFFSET`]) and `r <= 3`
//!   ([`MAX_RESIDUAL`]); beyond, the file differs from the reference by more than a time level
//!   (e.g. a soft contact penalty that delays the force: measured here on the Fig. 5 impact,
//!   `s = -4`, `r = 2.9` at beta_s = 0.25) and no verdict is given;
//! - load convention, from the profiles with `r <= 0.5` ([`RESOLVED`]): the fraction
//!   `f = mean s - offset` is `H(0) = 1` when `|f| <= 1/8`, `H(0) = 1/2` (a failure) when
//!   `|f + 1/4| <= 1/8`, otherwise unexplained (no verdict); not detectable without such a profile.
//!
//! A contact force history is fitted the same way through its impulse `I(t) = int_0^t F`
//! (trapezoid rule over the samples against the exact staircase's integral), but the number is
//! reported without a verdict (`compare::score::force` says why).
//!
//! **Sign.** The L1 error of the file against the reference and that of the negated file
//! (normalised as the norms are: by `L`, `|sigma0|` and the number of profiles; a force history
//! by the exact impulse): the sign is the file's when its error is below half the negated one's,
//! flipped when above twice it, undecided between.

/// Largest residual `r` (in steps) of a profile that may decide the load convention.
pub const RESOLVED: f64 = 0.5;

/// Largest `|s|` (steps) read as a time-level offset.
pub const MAX_OFFSET: f64 = 2.5;

/// Largest residual `r` (steps) with which a shift is read as a time-level offset.
pub const MAX_RESIDUAL: f64 = 3.0;

/// The time shift of a file, in steps of its `dt`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeShift {
    /// Mean least-squares shift `s` over the profiles, in steps.
    pub steps: f64,
    /// `round(steps)`: the whole steps that best match the reference.
    pub offset: i64,
    /// Largest residual `r` over the profiles, in steps.
    pub residual: f64,
    /// Profiles the shift was fitted on.
    pub profiles: usize,
}

impl TimeShift {
    /// True when the fit explains the error as an offset of a few steps ([`MAX_OFFSET`],
    /// [`MAX_RESIDUAL`]).
    pub fn decided(&self) -> bool {
        self.steps.abs() <= MAX_OFFSET && self.residual <= MAX_RESIDUAL
    }
}

/// The L1 errors of the file and of the negated file against the reference.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SignCheck {
    /// Error of the file as given.
    pub error: f64,
    /// Error of the negated file.
    pub error_flipped: f64,
}

impl SignCheck {
    /// `Some(true)`: the file's sign is the reference's; `Some(false)`: flipped; `None`: the two
    /// errors are within a factor 2.
    pub fn matches(&self) -> Option<bool> {
        if self.error < 0.5 * self.error_flipped {
            Some(true)
        } else if self.error > 2.0 * self.error_flipped {
            Some(false)
        } else {
            None
        }
    }
}

/// What the fractional shift says of the load at `t = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LoadConvention {
    /// `H(0) = 1` (courant's, methods.md §2).
    One,
    /// `H(0) = 1/2`.
    Half,
    /// A fractional shift neither explains.
    Unexplained,
}

/// The load convention and the fractional shift it was read from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadCheck {
    /// The convention.
    pub convention: LoadConvention,
    /// `mean s - offset` over the resolved profiles, in steps.
    pub fraction: f64,
}

/// The diagnostics of one case file; `Err` says why one is not measured.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostics {
    /// Time shift.
    pub shift: Result<TimeShift, String>,
    /// Sign.
    pub sign: Result<SignCheck, String>,
    /// Load convention.
    pub load: Result<LoadCheck, String>,
}

/// One diagnostic as a check: name, verdict (`None`: measured only or not measurable), what was
/// measured, and a note.
pub type DiagnosticRow = (&'static str, Option<bool>, String, String);

impl Diagnostics {
    /// Nothing measurable, for the same reason each.
    pub fn none(why: &str) -> Self {
        Self {
            shift: Err(why.into()),
            sign: Err(why.into()),
            load: Err(why.into()),
        }
    }

    /// `time_offset`, `sign`, `load_convention` as checks.
    pub fn verdicts(&self) -> [DiagnosticRow; 3] {
        let shift = match &self.shift {
            Ok(s) if !s.decided() => (
                "time_offset",
                None,
                "-".into(),
                format!(
                    "not a time-level offset: the best shift is {:+.3} steps with residual {:.2} (an offset is read within {MAX_OFFSET} steps and residual {MAX_RESIDUAL})",
                    s.steps, s.residual
                ),
            ),
            Ok(s) => (
                "time_offset",
                Some(s.offset == 0),
                format!("{} steps", s.offset),
                format!(
                    "least-squares shift {:+.3} steps (residual {:.2}) over {} profile(s)",
                    s.steps, s.residual, s.profiles
                ),
            ),
            Err(why) => ("time_offset", None, "-".into(), why.clone()),
        };
        let sign = match &self.sign {
            Ok(s) => (
                "sign",
                s.matches(),
                match s.matches() {
                    Some(true) => "tension positive".into(),
                    Some(false) => "flipped".into(),
                    None => "undecided".into(),
                },
                format!(
                    "L1 error {:.3e} as given, {:.3e} negated",
                    s.error, s.error_flipped
                ),
            ),
            Err(why) => ("sign", None, "-".into(), why.clone()),
        };
        let load = match &self.load {
            Ok(l) => (
                "load_convention",
                match l.convention {
                    LoadConvention::One => Some(true),
                    LoadConvention::Half => Some(false),
                    LoadConvention::Unexplained => None,
                },
                match l.convention {
                    LoadConvention::One => "H(0) = 1".into(),
                    LoadConvention::Half => "H(0) = 1/2".into(),
                    LoadConvention::Unexplained => "unexplained".into(),
                },
                format!("fractional shift {:+.3} steps", l.fraction),
            ),
            Err(why) => ("load_convention", None, "-".into(), why.clone()),
        };
        [shift, sign, load]
    }
}

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

/// The file's time shift from the `(s, r)` of its profiles, and its load convention.
pub fn combine(fits: &[(f64, f64)]) -> (Result<TimeShift, String>, Result<LoadCheck, String>) {
    if fits.is_empty() {
        let why = "not measurable: the exact solution does not change over a step at these times";
        return (Err(why.into()), Err(why.into()));
    }
    let mean = |v: &[(f64, f64)]| v.iter().map(|f| f.0).sum::<f64>() / v.len() as f64;
    let steps = mean(fits);
    let offset = steps.round() as i64;
    let shift = TimeShift {
        steps,
        offset,
        residual: fits.iter().map(|f| f.1).fold(0.0, f64::max),
        profiles: fits.len(),
    };
    let resolved: Vec<(f64, f64)> = fits.iter().copied().filter(|f| f.1 <= RESOLVED).collect();
    let load = if !shift.decided() {
        Err("not detectable: the error is not a time-level shift".into())
    } else if resolved.is_empty() {
        Err(format!(
            "not detectable: no profile resolves a quarter step (residual {:.2} > {RESOLVED})",
            shift.residual
        ))
    } else {
        let fraction = mean(&resolved) - offset as f64;
        let convention = if fraction.abs() <= 0.125 {
            LoadConvention::One
        } else if (fraction + 0.25).abs() <= 0.125 {
            LoadConvention::Half
        } else {
            LoadConvention::Unexplained
        };
        Ok(LoadCheck {
            convention,
            fraction,
        })
    };
    (Ok(shift), load)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pure_shift_is_fitted_exactly_and_classified() {
        let w = [1.0, 1.0, 1.0];
        let d = [1.0, 2.0, 0.5];
        let e: Vec<f64> = d.iter().map(|x| -0.25 * x).collect();
        let (s, r) = fit_shift(&w, &e, &d).unwrap();
        assert!((s + 0.25).abs() < 1e-15 && r < 1e-15);
        let (shift, load) = combine(&[(s, r), (-1.0, 0.0)]);
        assert_eq!(shift.unwrap().offset, -1, "mean -0.625 rounds to -1");
        assert_eq!(load.unwrap().convention, LoadConvention::Unexplained);
        let (shift, load) = combine(&[(-1.25, 0.1)]);
        assert_eq!(shift.unwrap().offset, -1);
        assert_eq!(load.unwrap().convention, LoadConvention::Half);
        let (_, load) = combine(&[(0.02, 0.9)]);
        assert!(
            load.is_err(),
            "a residual of 0.9 steps cannot resolve a quarter step"
        );
        assert_eq!(fit_shift(&w, &e, &[0.0; 3]), None);
        assert_eq!(integral_from_end(&[1.0, 2.0], &[3.0, 4.0]), vec![11.0, 8.0]);
    }

    #[test]
    fn the_sign_is_decided_only_by_a_clear_margin() {
        let s = |error, error_flipped| {
            SignCheck {
                error,
                error_flipped,
            }
            .matches()
        };
        assert_eq!(s(0.05, 1.0), Some(true));
        assert_eq!(s(1.0, 0.05), Some(false));
        assert_eq!(s(1.0, 1.5), None);
    }
}
