//! The one contract every exact solution of this crate honours, so that a caller compares a
//! numerical result with any of them through the same methods (in the spirit of LANL ExactPack's
//! `ExactSolver`, called as `solver(r, t)`: Singleton & al., *ExactPack documentation*, LA-UR-16-23260).
//!
//! [`ExactSolution`]: the stress at `(x, t)`, its mean over `[x0, x1]` (what a linear element's
//! constant stress is compared with), the velocity and displacement where the reference gives
//! them, the largest stress of the field (what an overshoot is measured against), energies, the
//! contact force history as a capability ([`ContactHistory`]), and the work of an evaluation,
//! known before evaluating ([`ExactSolution::evaluation_work`], [`Evaluation`]). Positions are
//! measured from the start of the reference's own domain; stresses are per unit area, tension
//! positive.
//!
//! **Enters:** a reference built by its validating `new`. **Leaves:** exact values, or NaN
//! where the reference is not defined (outside its domain, beyond its reach); the work bound is
//! a `Result` so a caller can refuse an evaluation before paying for it. It must not know any
//! solver, mesh type or file.

use crate::dalembert::{DalembertBar, Energies};
use crate::error::ReferenceError;
use crate::graded::{GradedBar, LayeredBar};

/// Points per bar length at which a field that is smooth between its fronts (the graded bar) is
/// sampled for its extreme value, besides both sides of each front.
pub const GRADED_EXTREME_SAMPLES: usize = 4000;

/// Work of one tracked wave of the layered references in work units (lattice-node equivalents of
/// the graded bar's characteristics, ~7 ns each): 0.18 to 0.65 us per wave measured (ten layers,
/// 10 to 1.7e5 waves).
pub const LAYERED_WAVE_WORK: f64 = 100.0;

/// What a caller asks of a reference at one time, to count the evaluations it costs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Evaluation<'a> {
    /// Element averages between consecutive `nodes`.
    Averages(&'a [f64]),
    /// Values at the points `xs`.
    Points(&'a [f64]),
    /// The extreme of the field ([`ExactSolution::stress_extreme`]).
    Extreme,
}

/// One constant stretch of the contact force: `force` on `[start, end)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForcePlateau {
    /// Start time (inclusive).
    pub start: f64,
    /// End time (exclusive).
    pub end: f64,
    /// Contact force, compression positive (`>= 0`).
    pub force: f64,
    /// Velocity of the contact interface (`0` against a rigid wall).
    pub interface_velocity: f64,
}

/// The contact force history of an impact, as a capability of an exact solution.
///
/// Compression is positive. The histories of this crate are piecewise constant (step waves in
/// piecewise-constant media), so they are given exactly as [`ForcePlateau`]s.
pub trait ContactHistory {
    /// Contact force at t, right-continuous; 0 before contact and after the last positive plateau.
    fn contact_force(&self, t: f64) -> f64;
    /// The piecewise-constant history in time order, ending with a positive plateau.
    fn force_plateaus(&self) -> &[ForcePlateau];
    /// Force of the first plateau (the impedance-matched value `Z1 Z2 v0/(Z1 + Z2)`).
    fn first_plateau_force(&self) -> f64 {
        self.force_plateaus().first().map_or(0.0, |p| p.force)
    }
    /// End of the last plateau of positive force.
    fn contact_duration(&self) -> f64 {
        self.force_plateaus().last().map_or(0.0, |p| p.end)
    }
    /// Time at which the contact opens (the welded force would turn tensile), `>= duration`.
    fn separation_time(&self) -> f64;
    /// Impulse `int F dt` over the contact.
    fn contact_impulse(&self) -> f64 {
        self.force_plateaus()
            .iter()
            .map(|p| p.force * (p.end - p.start))
            .sum()
    }
}

/// An exact solution of a 1D bar problem (module documentation).
pub trait ExactSolution {
    /// Short name, as scene files spell the reference.
    fn name(&self) -> &'static str;

    /// Signed stress scale: the applied stress `sigma0` of a loaded bar, the first contact stress
    /// of an impact (compressive, negative).
    fn characteristic_stress(&self) -> f64;

    /// Length of the domain `[0, L]` on which positions are measured.
    fn domain_length(&self) -> f64;

    /// Stress at `(x, t)`, right-continuous in t (a front exactly at the point has arrived).
    fn stress(&self, x: f64, t: f64) -> f64;

    /// Stress at each of `xs` at time t (one field evaluation where the reference allows).
    fn stress_profile(&self, xs: &[f64], t: f64) -> Vec<f64> {
        xs.iter().map(|&x| self.stress(x, t)).collect()
    }

    /// Exact mean of the stress over `[x0, x1]` at t.
    fn stress_average(&self, x0: f64, x1: f64, t: f64) -> f64;

    /// Exact means over each pair of consecutive `nodes` (the elements of a mesh).
    fn stress_averages(&self, nodes: &[f64], t: f64) -> Vec<f64> {
        nodes
            .windows(2)
            .map(|w| self.stress_average(w[0], w[1], t))
            .collect()
    }

    /// The largest value of `sign * sigma(x, t)` over the whole domain.
    fn stress_extreme(&self, sign: f64, t: f64) -> f64;

    /// Velocity at `(x, t)` where the reference gives it.
    fn velocity(&self, x: f64, t: f64) -> Option<f64>;

    /// Displacement at `(x, t)` where the reference gives it.
    fn displacement(&self, _x: f64, _t: f64) -> Option<f64> {
        None
    }

    /// Kinetic and strain energies and the work done on the domain, where offered.
    fn energies(&self, _t: f64) -> Option<Energies> {
        None
    }

    /// The contact force history, for an impact.
    fn contact(&self) -> Option<&dyn ContactHistory> {
        None
    }

    /// Upper bound of the work of one evaluation at time t, in work units (~7 ns each): for
    /// references whose work grows with t, the bound at t covers every earlier time.
    ///
    /// # Errors
    /// [`ReferenceError::BeyondReach`] when the reference is not evaluable at t (not finite, or
    /// beyond its limit).
    fn evaluation_work(&self, t: f64) -> Result<f64, ReferenceError>;

    /// True when [`Self::evaluation_work`] is a closed form, far cheaper than the evaluation;
    /// false when computing it costs about as much as evaluating (then a caller bounds the work
    /// once, at the latest time it needs).
    fn work_known_up_front(&self) -> bool {
        true
    }

    /// How many evaluations of [`Self::evaluation_work`] `what` costs at t.
    fn evaluations(&self, what: Evaluation<'_>, t: f64) -> usize;

    /// A phrase naming what makes this reference expensive, e.g. ` (a layered bar of 3 layers)`,
    /// empty when nothing does.
    fn cost_detail(&self) -> String {
        String::new()
    }
}

/// Largest `sign * stress` over the pieces between `fronts` of a field that is constant between
/// its fronts: each piece is evaluated at its midpoint.
fn piecewise_extreme(length: f64, fronts: Vec<f64>, sign: f64, stress: &dyn Fn(f64) -> f64) -> f64 {
    let mut cuts = vec![0.0];
    cuts.extend(fronts.into_iter().filter(|&f| f > 0.0 && f < length));
    cuts.push(length);
    cuts.windows(2)
        .map(|w| sign * stress(0.5 * (w[0] + w[1])))
        .fold(f64::NEG_INFINITY, f64::max)
}

impl ExactSolution for DalembertBar {
    fn name(&self) -> &'static str {
        "dalembert"
    }

    fn characteristic_stress(&self) -> f64 {
        self.sigma0()
    }

    fn domain_length(&self) -> f64 {
        self.length()
    }

    fn stress(&self, x: f64, t: f64) -> f64 {
        DalembertBar::stress(self, x, t)
    }

    fn stress_average(&self, x0: f64, x1: f64, t: f64) -> f64 {
        DalembertBar::stress_average(self, x0, x1, t)
    }

    fn stress_extreme(&self, sign: f64, t: f64) -> f64 {
        piecewise_extreme(self.length(), self.front_positions(t), sign, &|x| {
            DalembertBar::stress(self, x, t)
        })
    }

    /// The mean of the limits in t where a front sits exactly on `x` (what a central-difference
    /// full-step velocity represents there), [`DalembertBar::velocity_mean`].
    fn velocity(&self, x: f64, t: f64) -> Option<f64> {
        Some(self.velocity_mean(x, t))
    }

    fn displacement(&self, x: f64, t: f64) -> Option<f64> {
        Some(DalembertBar::displacement(self, x, t))
    }

    fn energies(&self, t: f64) -> Option<Energies> {
        Some(DalembertBar::energies(self, t))
    }

    /// Closed form: no work worth counting.
    fn evaluation_work(&self, _t: f64) -> Result<f64, ReferenceError> {
        Ok(0.0)
    }

    fn evaluations(&self, what: Evaluation<'_>, _t: f64) -> usize {
        match what {
            Evaluation::Averages(nodes) => nodes.len().saturating_sub(1),
            Evaluation::Points(xs) => xs.len(),
            Evaluation::Extreme => 1,
        }
    }
}

impl ExactSolution for GradedBar {
    fn name(&self) -> &'static str {
        "graded"
    }

    fn characteristic_stress(&self) -> f64 {
        self.sigma0()
    }

    fn domain_length(&self) -> f64 {
        self.length()
    }

    fn stress(&self, x: f64, t: f64) -> f64 {
        GradedBar::stress(self, x, t)
    }

    fn stress_profile(&self, xs: &[f64], t: f64) -> Vec<f64> {
        GradedBar::stress_profile(self, xs, t)
    }

    fn stress_average(&self, x0: f64, x1: f64, t: f64) -> f64 {
        GradedBar::stress_average(self, x0, x1, t)
    }

    fn stress_averages(&self, nodes: &[f64], t: f64) -> Vec<f64> {
        GradedBar::stress_averages(self, nodes, t)
    }

    /// The field is smooth between fronts: sampled at [`GRADED_EXTREME_SAMPLES`] points per
    /// length plus both sides of each front.
    fn stress_extreme(&self, sign: f64, t: f64) -> f64 {
        let length = self.length();
        let eps = 1e-9 * length;
        let mut xs: Vec<f64> = (0..=GRADED_EXTREME_SAMPLES)
            .map(|i| length * i as f64 / GRADED_EXTREME_SAMPLES as f64)
            .collect();
        for f in self.front_positions(t) {
            xs.extend([(f - eps).max(0.0), (f + eps).min(length)]);
        }
        xs.iter()
            .map(|&x| sign * GradedBar::stress(self, x, t))
            .filter(|v| v.is_finite())
            .fold(f64::NEG_INFINITY, f64::max)
    }

    fn velocity(&self, x: f64, t: f64) -> Option<f64> {
        Some(GradedBar::velocity(self, x, t))
    }

    fn evaluation_work(&self, t: f64) -> Result<f64, ReferenceError> {
        GradedBar::evaluation_work(self, t).ok_or(ReferenceError::BeyondReach {
            reference: "graded",
            t,
            limit: format!(
                "evaluated up to {} transit times (route (b) declines beyond)",
                crate::graded::CHARACTERISTIC_TRANSITS_MAX
            ),
        })
    }

    fn evaluations(&self, what: Evaluation<'_>, t: f64) -> usize {
        match what {
            Evaluation::Averages(nodes) => self.average_evaluations(nodes, t),
            Evaluation::Points(xs) => xs.len(),
            Evaluation::Extreme => GRADED_EXTREME_SAMPLES + 1 + 2 * self.front_positions(t).len(),
        }
    }

    fn cost_detail(&self) -> String {
        let (e1, e2) = (self.modulus_loaded(), self.modulus_fixed());
        format!(
            " (a graded bar, modulus {e1:e} -> {e2:e}: ratio {:.3e})",
            e1.max(e2) / e1.min(e2)
        )
    }
}

impl ExactSolution for LayeredBar {
    fn name(&self) -> &'static str {
        "layered"
    }

    fn characteristic_stress(&self) -> f64 {
        self.sigma0()
    }

    fn domain_length(&self) -> f64 {
        self.length()
    }

    fn stress(&self, x: f64, t: f64) -> f64 {
        self.field(t).map_or(f64::NAN, |f| f.stress(x))
    }

    /// One tracked field for all points.
    fn stress_profile(&self, xs: &[f64], t: f64) -> Vec<f64> {
        match self.field(t) {
            Ok(field) => xs.iter().map(|&x| field.stress(x)).collect(),
            Err(_) => vec![f64::NAN; xs.len()],
        }
    }

    fn stress_average(&self, x0: f64, x1: f64, t: f64) -> f64 {
        self.field(t).map_or(f64::NAN, |f| f.stress_average(x0, x1))
    }

    /// One tracked field for all elements.
    fn stress_averages(&self, nodes: &[f64], t: f64) -> Vec<f64> {
        match self.field(t) {
            Ok(field) => nodes
                .windows(2)
                .map(|w| field.stress_average(w[0], w[1]))
                .collect(),
            Err(_) => vec![f64::NAN; nodes.len().saturating_sub(1)],
        }
    }

    fn stress_extreme(&self, sign: f64, t: f64) -> f64 {
        match self.field(t) {
            Ok(field) => piecewise_extreme(self.length(), field.front_positions(), sign, &|x| {
                field.stress(x)
            }),
            Err(_) => f64::NAN,
        }
    }

    fn velocity(&self, x: f64, t: f64) -> Option<f64> {
        self.field(t).ok().map(|f| f.velocity(x))
    }

    /// The work of tracking the field to t: [`LAYERED_WAVE_WORK`] per wave.
    fn evaluation_work(&self, t: f64) -> Result<f64, ReferenceError> {
        self.field(t)
            .map(|f| f.wave_count() as f64 * LAYERED_WAVE_WORK)
    }

    /// Knowing the wave count means tracking the waves.
    fn work_known_up_front(&self) -> bool {
        false
    }

    /// One tracked field serves every point of one time.
    fn evaluations(&self, _what: Evaluation<'_>, _t: f64) -> usize {
        1
    }

    fn cost_detail(&self) -> String {
        format!(" (a layered bar of {} layers)", self.layers().len())
    }
}
