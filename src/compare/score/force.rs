//! A contact force history of a file beside 1D wave theory, with the errors of `courant run`
//! ([`ForceErrors`]) and the diagnostics: the sign, and the least-squares shift of the impulse
//! as a measured number only. A force history written one step late is not told apart from the
//! force it records: the seed's penalty force `eps_s x penetration` trails the momentum the bars
//! receive by about a step, and the momentum per step starts with a half-step spike (every
//! built-in contact scene starts in contact) that a copy one step late carries to its second
//! sample, where the trapezoid rule counts it twice. Measured here on `contact_wall`: courant's
//! own predictor-corrector (penalty force) reads -1.10 steps and a copy one step late -2.09; its
//! Lagrange multiplier (momentum) -0.03 and a copy one step late -0.02.

use super::bind::Bound;
use super::diagnostics::{Diagnostics, SignCheck};
use super::outcome::{Read, Scored, ScoredCase, ScoredForce};
use super::profiles::cell_lengths;
use super::shift_fit::fit_shift;
use crate::compare::contact::ForceErrors;
use crate::results::exchange::record::ForceHistory;
use crate::scene::contact::ContactCase;
use courant_references::ContactHistory;

/// `int_0^t F dt` of the exact staircase.
pub fn exact_impulse(reference: &dyn ContactHistory, t: f64) -> f64 {
    reference
        .force_plateaus()
        .iter()
        .map(|p| p.force * (t.min(p.end) - p.start).max(0.0))
        .sum()
}

/// The cumulative impulse of samples by the trapezoid rule, 0 at the first sample.
pub fn trapezoid_impulse(time: &[f64], force: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(time.len());
    let mut sum = 0.0;
    for k in 0..time.len() {
        if k > 0 {
            sum += 0.5 * (force[k - 1] + force[k]) * (time[k] - time[k - 1]);
        }
        out.push(sum);
    }
    out
}

/// Score a force history against the case's analytic force. The impulse of the file is the
/// trapezoid rule over its samples (courant's own runs sum the momentum of every step; the two
/// agree when every step is sampled and the force ends at 0).
pub fn score_force(bound: &Bound, case: &ContactCase, h: &ForceHistory) -> ScoredCase {
    let reference = case.reference.history();
    let samples: Vec<(f64, f64)> = h
        .time
        .iter()
        .copied()
        .zip(h.force.iter().copied())
        .collect();
    let cumulative = trapezoid_impulse(&h.time, &h.force);
    let impulse = cumulative.last().copied().unwrap_or(0.0);
    let exact: Vec<f64> = samples
        .iter()
        .map(|s| reference.contact_force(s.0))
        .collect();
    let errors = ForceErrors::of_samples(&samples, &exact, reference);
    let impulse_error = (impulse - reference.contact_impulse()).abs() / reference.contact_impulse();
    let (t0, t1) = (h.time[0], h.time[h.time.len() - 1]);
    let weights = cell_lengths(&h.time, t0, t1);
    let (mut error, mut error_flipped) = (0.0, 0.0);
    for ((w, f), e) in weights.iter().zip(&h.force).zip(&exact) {
        error += w * (f - e).abs();
        error_flipped += w * (-f - e).abs();
    }
    // Relative to the exact impulse, as the force L1 error.
    let sign = SignCheck {
        error: error / reference.contact_impulse(),
        error_flipped: error_flipped / reference.contact_impulse(),
    };
    let factor = if sign.matches() == Some(false) {
        -1.0
    } else {
        1.0
    };
    let shift = bound.dt.map(|(dt, _)| {
        let file: Vec<f64> = cumulative.iter().map(|i| factor * i).collect();
        let at = |t: f64| exact_impulse(reference, t);
        let e: Vec<f64> = h.time.iter().zip(&file).map(|(&t, i)| i - at(t)).collect();
        let d: Vec<f64> = h
            .time
            .iter()
            .map(|&t| {
                if t >= dt {
                    0.5 * (at(t + dt) - at(t - dt))
                } else {
                    at(t + dt) - at(t)
                }
            })
            .collect();
        match fit_shift(&weights, &e, &d) {
            Some((s, r)) => format!(
                "measured only: least-squares shift of the impulse {s:+.3} steps (residual {r:.2}); a force history's shift is confounded with the force it records and its start-up (courant's own penalty force reads about -1 step)"
            ),
            None => "not measurable: the exact impulse does not change over a step".into(),
        }
    });
    ScoredCase {
        case: bound.file.case.clone(),
        file: bound.file.file.clone(),
        scheme: bound.meta.and_then(|m| m.scheme.clone()),
        applies: bound.applies.clone(),
        mass: bound.mass.map(|m| m.label()),
        elements: bound.meta.and_then(|m| m.elements).map(|e| e.0),
        read: Read {
            values: h.time.len(),
            times: 1,
            rows: h.time.len(),
        },
        dt: bound.dt,
        reference: "impact",
        scored: Scored::Force(ScoredForce {
            time: h.time.clone(),
            force: h.force.clone(),
            reference: exact,
            impulse,
            impulse_error,
            plateau: reference.first_plateau_force(),
            errors,
        }),
        diagnostics: Diagnostics {
            magnitude: Err("not applicable: a force history has no stress scale".into()),
            shift: Err(shift.unwrap_or_else(|| "not measurable: no dt".into())),
            sign: Ok(sign),
            layout: Err("not applicable: a force history has no positions".into()),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_trapezoid_impulse_of_a_constant_force_is_exact() {
        assert_eq!(
            trapezoid_impulse(&[0.0, 0.5, 1.0], &[2.0, 2.0, 2.0]),
            vec![0.0, 1.0, 2.0]
        );
    }
}
