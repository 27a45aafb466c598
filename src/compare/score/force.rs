//! A contact force history of a file beside 1D wave theory, with the measures of `courant run`
//! ([`force_metrics`]) and the diagnostics: the sign, and the least-squares shift of the impulse
//! as a measured number only. A force history written one step late is not told apart from a
//! scheme's start-up and impulse error: every built-in contact scene starts in contact, where
//! central difference delivers its first momentum over half a step (a force spike, e.g. 1.85 F
//! for the predictor-corrector on `contact_wall`), and a lagged copy carries that spike one step
//! later, where the trapezoid rule counts it twice; measured here: such a copy of courant's own
//! `contact_wall` run reads as -0.17 steps, the run itself as -0.11.

use super::bind::Bound;
use super::diagnostics::{Diagnostics, SignCheck, fit_shift};
use super::outcome::{Scored, ScoredCase, ScoredForce};
use super::profiles::cell_lengths;
use crate::compare::contact::force_metrics;
use crate::results::exchange::record::ForceHistory;
use crate::scene::contact::ContactCase;
use courant_references::contact::ImpactForce;

/// `int_0^t F dt` of the exact staircase.
pub fn exact_impulse(reference: &ImpactForce, t: f64) -> f64 {
    reference
        .plateaus()
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
    let reference = &case.reference;
    let samples: Vec<(f64, f64)> = h
        .time
        .iter()
        .copied()
        .zip(h.force.iter().copied())
        .collect();
    let cumulative = trapezoid_impulse(&h.time, &h.force);
    let impulse = cumulative.last().copied().unwrap_or(0.0);
    let (exact, metrics) = force_metrics(&samples, impulse, reference);
    let (t0, t1) = (h.time[0], h.time[h.time.len() - 1]);
    let weights = cell_lengths(&h.time, t0, t1);
    let (mut error, mut error_flipped) = (0.0, 0.0);
    for ((w, f), e) in weights.iter().zip(&h.force).zip(&exact) {
        error += w * (f - e).abs();
        error_flipped += w * (-f - e).abs();
    }
    // Relative to the exact impulse, as the force L1 error.
    let sign = SignCheck {
        error: error / reference.impulse(),
        error_flipped: error_flipped / reference.impulse(),
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
                "measured only: least-squares shift of the impulse {s:+.3} steps (residual {r:.2}); a force history's shift is confounded with its start-up and its impulse error (a history one step late of courant's own contact_wall run reads as -0.17 steps)"
            ),
            None => "not measurable: the exact impulse does not change over a step".into(),
        }
    });
    ScoredCase {
        case: bound.file.case.clone(),
        file: bound.file.file.clone(),
        scheme: bound.meta.and_then(|m| m.scheme.clone()),
        mass: bound.mass.map(|m| m.label()),
        elements: bound.meta.and_then(|m| m.elements).map(|e| e.0),
        dt: bound.dt,
        reference: "impact",
        scored: Scored::Force(ScoredForce {
            time: h.time.clone(),
            force: h.force.clone(),
            reference: exact,
            impulse,
            metrics,
        }),
        diagnostics: Diagnostics {
            shift: Err(shift.unwrap_or_else(|| "not measurable: no dt".into())),
            sign: Ok(sign),
            load: Err("not applicable: a contact case has no step load".into()),
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
