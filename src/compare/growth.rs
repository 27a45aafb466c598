//! A run's energy growth: its energy ratio ([`time_stepping_energy_ratio`]) against the band of
//! a stable run ([`ENERGY_BAND`]), and the growth law of a run exactly at its stability limit
//! (methods.md §2, "At the limit"), [`Growth`]: there the critical mode of central difference
//! has the double eigenvalue `-1` with one eigenvector, its amplitude grows at most linearly in
//! the step count `n` and its energy at most like `n^2`, whatever the mode's content of the
//! initial state; an eigenvalue `|lambda| > 1` grows exponentially. Two scale-free tests of that law on a run's own logged mechanical energy
//! `E = T + U` (full-step kinetic energy) over the energy supplied so far:
//!
//! - **the growth exponent over the last doubling**, `p = log2(R)`,
//!   `R = max E over the samples in (n/2, n] / max E over the samples in [0, n/2]`, `n` the last
//!   logged step. A linear amplitude `g` sampled every `k` steps gives
//!   `R <= 1 + ((3n + 2k)/(n - 2k))^2` ([`doubling_bound`]), 10 for `n >> k`; `p -> 2` as
//!   `n -> infinity`. Measured when the first half holds at least [`MIN_SAMPLES`] samples.
//! - **the end ratio** `E_end / E_supplied <= ENERGY_BAND + 4 (1 + n)^2` ([`end_bound`]), for
//!   every run, the only test of a run caught within its first few logged samples.
//!
//! A run whose energy breaks either bound grows faster than the double root allows.

use courant_solver::{EnergyLog, EnergySample};

/// Largest `energy_ratio` of a run observed as `stable`; above it a completed run shows
/// `energy growth`. A passive system (contact can only keep or dissipate energy; a loaded bar
/// holds what the load put in) has ratio 1 up to what the measure itself adds. Contact rows
/// measure central difference's conserved energy `1/2 v^{n-1/2} M v^{n+1/2} + 1/2 u K u` left in
/// the bodies at the end (`ContactResult::energy_ratio_conserved`); time-stepping rows the
/// largest full-step `T + U` over the energy supplied, sampled every `energy_every` steps.
/// Measured in the report: the runs that cannot gain energy sit at 0.990-1.101
/// (predictor-corrector contact rows, `kappa <= 1`; 1.101 at 1.5 of its limit, beta_s = 1e8) and
/// 0.9975-1.001 (stable time-stepping rows, CD and Park), CD with (bi)penalty at beta_s = 1 and
/// 0.99 of its limit at 1.008-1.014; the runs that gain sit at 2.61 and above (CD with
/// (bi)penalty at beta_s >= 1e4 from 0.99 of its limit, at beta_s = 1 from 1.00). 1.5 separates
/// the two with a wide margin on both sides.
pub const ENERGY_BAND: f64 = 1.5;

/// Fewest logged samples in the first half of a run for its growth exponent to be measured
/// (with fewer, only the end ratio is tested): steps `0, k, 2k, 3k <= n/2` need `n >= 6k`, where
/// the doubling bound is `1 + (20/4)^2 = 26`, `p <= 4.70`.
pub const MIN_SAMPLES: usize = 4;

/// The largest `R = max E over (n/2, n] / max E over [0, n/2]` the double root allows for a run
/// whose energy is logged every `k` steps up to step `n` (methods.md §2). The critical mode's
/// amplitude is linear, `g(j) = a + b j`: with `s >= n/2 - k` the last sample of the first half,
/// `g(n) = g(0) + (n/s)(g(s) - g(0))` so `|g(n)| <= (2n/s - 1) max(|g(0)|, |g(s)|)`, and over
/// `[s, n]` a linear `|g|` peaks at an end: the late maximum of `g^2` is at most
/// `A = ((3n + 2k)/(n - 2k))^2` times the early one (tight when `g` changes sign at `n/4`; `A <= 4`
/// when it does not change sign and `k = 0`). The mode's energy `c + g^2` (`c >= 0` its constant
/// kinetic part) keeps the factor; the bounded modes, orthogonal to it, may peak late at their
/// early maximum, which adds at most 1 (a load's static share of the critical mode counts with
/// them). `None` when `n <= 2k` (no sample in the first half but 0).
pub fn doubling_bound(n: usize, k: usize) -> Option<f64> {
    let (n, k) = (n as f64, k as f64);
    (n > 2.0 * k).then(|| 1.0 + ((3.0 * n + 2.0 * k) / (n - 2.0 * k)).powi(2))
}

/// The largest energy ratio `E_n / E_supplied` the double root allows after `n` steps
/// (methods.md §2): one critical mode of central difference at `omega dt = 2` has
/// `u^j = (-1)^j (A + B j)`, full-step kinetic energy `B^2/(2 dt^2)` and strain energy
/// `2 (A + B j)^2/dt^2` (unit modal mass), so by Cauchy-Schwarz
/// `(A + B n)^2 <= (A^2 + B^2/4)(1 + 4 n^2)` its energy grows by at most `2 + 4 n^2 <= 4 (1 + n)^2`;
/// the bounded rest of the run holds at most [`ENERGY_BAND`] of the energy supplied, as a stable
/// run does.
pub fn end_bound(n: usize) -> f64 {
    ENERGY_BAND + 4.0 * (1.0 + n as f64).powi(2)
}

/// Energy ratio of a time-stepping run: the largest logged mechanical energy `T + U` over the
/// largest energy supplied, `max(E^0, |W|)` over the logged samples (`W` the external work): 1
/// up to the full-step kinetic term for a run that only holds what it was given, far above 1 for
/// a run that gains energy (courant's guard stops a run at 1e6 of the same kind of ratio).
/// `None` when nothing was supplied.
pub fn time_stepping_energy_ratio(log: &EnergyLog) -> Option<f64> {
    let mechanical = |s: &EnergySample| s.kinetic + s.strain;
    let initial = log.samples.first().map_or(0.0, mechanical);
    let supplied = log
        .samples
        .iter()
        .map(|s| s.work.abs())
        .fold(initial, f64::max);
    let peak = log.samples.iter().map(mechanical).fold(0.0, |m: f64, e| {
        if e.is_nan() { f64::INFINITY } else { m.max(e) }
    });
    (supplied > 0.0).then(|| peak / supplied)
}

/// The growth of a time-stepping run against the double-root law ([`Growth::of`]): its logged
/// `T + U` over the energy supplied so far, `max(E^0, |W|)` up to each sample (samples before
/// any energy was supplied left out); `end` the guard's step and energy ratio for a caught run.
pub fn time_stepping_growth(log: &EnergyLog, end: Option<(usize, f64)>) -> Option<Growth> {
    let initial = log.samples.first().map_or(0.0, |s| s.kinetic + s.strain);
    let normalised: Vec<(usize, f64)> = log
        .samples
        .iter()
        .scan(initial, |supplied, s| {
            *supplied = supplied.max(s.work.abs());
            Some((*supplied > 0.0).then(|| (s.step, (s.kinetic + s.strain) / *supplied)))
        })
        .flatten()
        .collect();
    Growth::of(&normalised, end)
}

/// A run's energy growth against the double-root law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Growth {
    /// Steps the end ratio is taken over (the guard's step for a caught run).
    pub steps: usize,
    /// Energy at the end over the energy supplied (a caught run: the guard's ratio).
    pub end_ratio: f64,
    /// `p = log2 R` over the last doubling of the log and its bound `log2` [`doubling_bound`],
    /// when the first half holds [`MIN_SAMPLES`] samples and some energy.
    pub exponent: Option<(f64, f64)>,
}

impl Growth {
    /// Measure the growth of a logged energy history `(step, e)` (steps increasing, from step
    /// 0), `e = E/S` the mechanical energy over the energy supplied so far (`S` nondecreasing:
    /// the initial energy, or the largest `|W|` of the load's work up to that step), and where
    /// the run ended: `end = (steps, ratio)`, the guard's step and energy ratio for a caught run,
    /// else the last sample. Dividing by the running `S` takes a loading transient out of the
    /// growth (a loaded bar holds about what it was given, `e ~ 1`); it only lowers late values
    /// against early ones, so the bounds still hold. The sampling interval `k` is the largest gap
    /// between logged steps. `None` with fewer than two samples.
    pub fn of(log: &[(usize, f64)], end: Option<(usize, f64)>) -> Option<Self> {
        let &(last, last_ratio) = log.last()?;
        if log.len() < 2 {
            return None;
        }
        let unbounded = |e: f64| if e.is_nan() { f64::INFINITY } else { e };
        let (steps, end_ratio) = end.unwrap_or((last, last_ratio));
        let k = log.windows(2).map(|w| w[1].0 - w[0].0).max().unwrap_or(1);
        let half = last as f64 / 2.0;
        let (early, late): (Vec<_>, Vec<_>) = log.iter().partition(|(s, _)| *s as f64 <= half);
        let max = |xs: &[&(usize, f64)]| xs.iter().map(|(_, e)| unbounded(*e)).fold(0.0, f64::max);
        let exponent = match (doubling_bound(last, k), max(&early)) {
            (Some(bound), first) if early.len() >= MIN_SAMPLES && first > 0.0 => {
                Some(((max(&late) / first).log2(), bound.log2()))
            }
            _ => None,
        };
        Some(Self {
            steps,
            end_ratio: unbounded(end_ratio),
            exponent,
        })
    }

    /// True when the growth breaks neither bound of the law.
    pub fn within_law(&self) -> bool {
        self.end_ratio <= end_bound(self.steps) && self.exponent.is_none_or(|(p, max)| p <= max)
    }

    /// `within the n^2 law (p = 0.01, law <= 3.32)` when the exponent was measured and the end
    /// ratio keeps its bound, else the end ratio against its bound:
    /// `beyond the n^2 law (x1.434e6 in 72 steps, law <= 2.132e4)`.
    pub fn describe(&self) -> String {
        let end = format!(
            "x{:.3e} in {} steps, law <= {:.3e}",
            self.end_ratio,
            self.steps,
            end_bound(self.steps)
        );
        let what = if self.within_law() {
            "within"
        } else {
            "beyond"
        };
        match self.exponent {
            Some((p, max)) if self.end_ratio <= end_bound(self.steps) => {
                format!("{what} the n^2 law (p = {p:.2}, law <= {max:.2})")
            }
            _ => format!("{what} the n^2 law ({end})"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(kinetic: f64, strain: f64, work: f64) -> EnergySample {
        EnergySample {
            step: 0,
            time: 0.0,
            kinetic,
            kinetic_staggered: kinetic,
            strain,
            work,
            balance_error: 0.0,
        }
    }

    /// Source of truth: the definition, largest T + U over the largest of E^0 and |W|.
    /// Proves: a loaded bar that holds what the load put in reads 1, one that doubles it reads
    /// 2, an initial-value run uses its initial energy, a run that was never supplied any energy
    /// has no ratio, and a NaN state counts as unbounded.
    #[test]
    fn time_stepping_energy_ratio_is_peak_energy_over_energy_supplied() {
        let log = |samples: Vec<EnergySample>| EnergyLog {
            samples,
            ..EnergyLog::default()
        };
        let held = log(vec![
            sample(0.0, 0.0, 0.0),
            sample(0.5, 0.5, 1.0),
            sample(1.0, 1.0, 2.0),
            sample(0.1, 0.1, 0.2),
        ]);
        assert_eq!(time_stepping_energy_ratio(&held), Some(1.0));
        let doubled = log(vec![sample(0.0, 0.0, 0.0), sample(2.0, 2.0, 2.0)]);
        assert_eq!(time_stepping_energy_ratio(&doubled), Some(2.0));
        let free = log(vec![sample(0.5, 0.0, 0.0), sample(0.25, 0.5, 0.0)]);
        assert_eq!(time_stepping_energy_ratio(&free), Some(1.5));
        assert_eq!(
            time_stepping_energy_ratio(&log(vec![sample(0.0, 0.0, 0.0)])),
            None
        );
        let nan = log(vec![sample(0.0, 0.0, 0.0), sample(f64::NAN, 0.0, 1.0)]);
        assert_eq!(time_stepping_energy_ratio(&nan), Some(f64::INFINITY));
    }

    fn log(n: usize, k: usize, e: impl Fn(f64) -> f64) -> Vec<(usize, f64)> {
        let mut steps: Vec<usize> = (0..=n).step_by(k).collect();
        if steps.last() != Some(&n) {
            steps.push(n);
        }
        steps.into_iter().map(|j| (j, e(j as f64))).collect()
    }

    /// Source of truth: the double-root law (methods.md §2, "At the limit"). Proves: bounded
    /// energy (an oscillation about 1) has `p ~ 0`; the critical mode's `(a + b n)^2` has
    /// `p <= 2` when the amplitude keeps its sign and stays within the doubling bound when it
    /// changes sign at `n/4` (the worst case, `R -> 9`); both are within the law.
    #[test]
    fn bounded_and_quadratic_energy_are_within_the_law() {
        let bounded = Growth::of(&log(10_000, 10, |j| 1.0 + 0.1 * (0.3 * j).sin()), None).unwrap();
        let (p, max) = bounded.exponent.unwrap();
        assert!(p.abs() < 0.01 && bounded.within_law(), "{bounded:?}");
        assert!((max - 10f64.log2()).abs() < 0.01, "{max}");
        let same_sign = Growth::of(&log(10_000, 10, |j| (1.0 + 0.5 * j).powi(2)), None).unwrap();
        let (p, _) = same_sign.exponent.unwrap();
        assert!(p <= 2.0 && p > 1.99, "{p}");
        assert!(same_sign.within_law(), "{same_sign:?}");
        // Amplitude changing sign at n/4: g(n/4) = 0, R = (3/1)^2 at n >> k.
        let crossing = Growth::of(&log(10_000, 10, |j| (j - 2500.0).powi(2) + 1.0), None).unwrap();
        let (p, max) = crossing.exponent.unwrap();
        assert!(p > 2.0 && p <= 9f64.log2() && p <= max, "{crossing:?}");
        assert!(crossing.within_law());
        assert!(
            crossing
                .describe()
                .starts_with("within the n^2 law (p = 3.17")
        );
    }

    /// Source of truth: methods.md §2: an eigenvalue of modulus above 1 grows exponentially.
    /// Proves: energy `1.01^n` over 2000 steps logged every 10 breaks the end bound (4.4e8 >
    /// 1.6e7); over 1000 steps its end ratio (2.1e4) is within the end bound (4.0e6) and only the
    /// exponent, `p = 500 log2 1.01 = 7.18` against the doubling bound's 3.39, sees it.
    #[test]
    fn exponential_energy_is_beyond_the_law() {
        let long = Growth::of(&log(2000, 10, |j| 1.01f64.powf(j)), None).unwrap();
        assert!(!long.within_law(), "{long:?}");
        let short = Growth::of(&log(1000, 10, |j| 1.01f64.powf(j)), None).unwrap();
        assert!(short.end_ratio < end_bound(1000), "{short:?}");
        let (p, max) = short.exponent.unwrap();
        assert!(
            (p - 500.0 * 1.01f64.log2()).abs() < 0.1 && p > max,
            "{short:?}"
        );
        assert!(!short.within_law());
        assert!(short.describe().starts_with("beyond the n^2 law (p = 7.1"));
    }

    /// Source of truth: the end bound `ENERGY_BAND + 4 (1 + n)^2` of the double root
    /// (methods.md §2). Proves: a run caught by the guard at step 72 with its energy multiplied
    /// by 1.434e6 (two logged samples: no exponent) is beyond the law (bound 2.13e4); caught at
    /// step 12197 with 1e6 it is within the end bound (6.0e8).
    #[test]
    fn a_run_too_short_for_an_exponent_is_graded_by_its_end_ratio() {
        let exploding = Growth::of(&[(0, 1.0), (71, 3e5)], Some((72, 1.434e6))).unwrap();
        assert_eq!(exploding.exponent, None);
        assert!(!exploding.within_law(), "{exploding:?}");
        assert_eq!(
            exploding.describe(),
            "beyond the n^2 law (x1.434e6 in 72 steps, law <= 2.132e4)"
        );
        let slow = Growth::of(&[(0, 1.0), (12_000, 9e5)], Some((12_197, 1e6))).unwrap();
        assert!(slow.within_law(), "{slow:?}");
        assert!(end_bound(0) == ENERGY_BAND + 4.0);
    }

    /// Source of truth: the derivation of [`doubling_bound`]. Proves: it is 10 for `n >> k`, the
    /// sampling raises it (k = n/8: 22.8) and a first half without a sample but step 0 has none.
    #[test]
    fn doubling_bound_and_its_sampling() {
        assert!((doubling_bound(1_000_000, 1).unwrap() - 10.0).abs() < 1e-4);
        assert!(
            (doubling_bound(80, 10).unwrap() - (1.0 + (260.0f64 / 60.0).powi(2))).abs() < 1e-12
        );
        assert_eq!(doubling_bound(20, 10), None);
    }
}
