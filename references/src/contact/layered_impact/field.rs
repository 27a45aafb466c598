//! The fields of a tracked [`LayeredImpact`]: point values and element means from the prefix
//! sums of each layer's waves, fronts, energy and momentum, and the contracts of
//! [`crate::exact`] (module documentation of the parent: the method and its cost).

use super::LayeredImpact;
use crate::error::ReferenceError;
use crate::exact::ForcePlateau;
use crate::exact::{ContactHistory, Evaluation, ExactSolution};

impl LayeredImpact {
    /// The layer holding `x` (the right one at a boundary) and whether `(x, t)` is evaluable.
    fn locate(&self, x: f64, t: f64) -> Option<usize> {
        let length = self.boundaries[self.layers.len()];
        let margin = 1e-10 * length;
        if !(x.is_finite() && t.is_finite()) || x < -margin || x > length + margin {
            return None;
        }
        if t > self.valid_until + self.tol {
            return None;
        }
        let i = self.boundaries.partition_point(|&b| b <= x);
        Some(i.saturating_sub(1).min(self.layers.len() - 1))
    }

    /// Initial velocity of layer i.
    fn initial_velocity(&self, i: usize) -> f64 {
        if i < self.contact { self.velocity } else { 0.0 }
    }

    /// Axial force (tension positive) and velocity at `(x, t)`, right-continuous in t; NaN
    /// outside the bars or beyond [`Self::valid_until`]. At a layer boundary the layer on the
    /// right is used; at the contact after opening, the target's end.
    #[must_use]
    pub fn state(&self, x: f64, t: f64) -> (f64, f64) {
        let Some(i) = self.locate(x, t) else {
            return (f64::NAN, f64::NAN);
        };
        let layer = self.layers[i];
        let c = layer.wave_speed();
        let (x0, x1) = (self.boundaries[i], self.boundaries[i + 1]);
        let tol = self.tol;
        let r = self.right[i].count_until(t - (x - x0).max(0.0) / c + tol);
        let l = self.left[i].count_until(t - (x1 - x).max(0.0) / c + tol);
        let (fr, vr) = self.right[i].sums(r);
        let (fl, vl) = self.left[i].sums(l);
        (fr + fl, self.initial_velocity(i) + vr + vl)
    }

    /// Mean axial force and velocity over `[xa, xb]` at t (exact: each wave contributes its jump
    /// times the length of the interval behind it). NaN unless `xa < xb` within the bars.
    #[must_use]
    pub fn mean_state(&self, xa: f64, xb: f64, t: f64) -> (f64, f64) {
        let (Some(_), Some(_)) = (self.locate(xa, t), self.locate(xb, t)) else {
            return (f64::NAN, f64::NAN);
        };
        if xa >= xb {
            return (f64::NAN, f64::NAN);
        }
        let (mut force, mut velocity) = (0.0, 0.0);
        for (i, layer) in self.layers.iter().enumerate() {
            let (x0, x1) = (self.boundaries[i], self.boundaries[i + 1]);
            let (a, b) = (xa.max(x0), xb.min(x1));
            if b <= a {
                continue;
            }
            let c = layer.wave_speed();
            velocity += self.initial_velocity(i) * (b - a);
            // Right-moving waves cover [x0, x0 + c (t - s)], left-moving [x1 - c (t - s), x1].
            for (waves, far, near) in [
                (&self.right[i], b - x0, a - x0),
                (&self.left[i], x1 - a, x1 - b),
            ] {
                let full = waves.count_until(t - far / c);
                let some = waves.count_until(t - near / c);
                let (f, v) = waves.sums(full);
                force += f * (b - a);
                velocity += v * (b - a);
                for k in full..some {
                    let reach = c * (t - waves.start[k]);
                    let covered = (reach - near).clamp(0.0, b - a);
                    let (df, dv) = waves.jump(k);
                    force += df * covered;
                    velocity += dv * covered;
                }
            }
        }
        (force / (xb - xa), velocity / (xb - xa))
    }

    /// Positions of all fronts inside the layers at t, ascending.
    #[must_use]
    pub fn front_positions(&self, t: f64) -> Vec<f64> {
        let mut out = Vec::new();
        for (i, layer) in self.layers.iter().enumerate() {
            let (x0, x1, c) = (
                self.boundaries[i],
                self.boundaries[i + 1],
                layer.wave_speed(),
            );
            let tau = layer.travel_time();
            for (waves, rightward) in [(&self.right[i], true), (&self.left[i], false)] {
                let from = waves.count_until(t - tau);
                let to = waves.count_until(t);
                for &s in &waves.start[from..to] {
                    let reach = c * (t - s);
                    out.push(if rightward { x0 + reach } else { x1 - reach });
                }
            }
        }
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }

    /// Kinetic energy, strain energy and momentum of both bars at t, exact (the fields are
    /// constant between fronts: each piece is evaluated at its midpoint).
    #[must_use]
    pub fn energy_and_momentum(&self, t: f64) -> (f64, f64, f64) {
        let fronts = self.front_positions(t);
        let (mut kinetic, mut strain, mut momentum) = (0.0, 0.0, 0.0);
        for (i, layer) in self.layers.iter().enumerate() {
            let (x0, x1) = (self.boundaries[i], self.boundaries[i + 1]);
            let mut cuts = vec![x0, x1];
            cuts.extend(fronts.iter().filter(|&&f| f > x0 && f < x1));
            cuts.sort_by(f64::total_cmp);
            let mass_per_length = layer.density() * layer.area;
            for w in cuts.windows(2) {
                let width = w[1] - w[0];
                if width <= 0.0 {
                    continue;
                }
                let (n, v) = self.state(0.5 * (w[0] + w[1]), t);
                kinetic += 0.5 * mass_per_length * v * v * width;
                strain += 0.5 * n * n / (layer.modulus() * layer.area) * width;
                momentum += mass_per_length * v * width;
            }
        }
        (kinetic, strain, momentum)
    }
}

impl ContactHistory for LayeredImpact {
    fn contact_force(&self, t: f64) -> f64 {
        if t.is_nan() {
            return f64::NAN;
        }
        let k = self.plateaus.partition_point(|p| p.start <= t);
        match k.checked_sub(1).map(|k| self.plateaus[k]) {
            Some(p) if t < p.end => p.force,
            _ => 0.0,
        }
    }

    fn force_plateaus(&self) -> &[ForcePlateau] {
        &self.plateaus
    }

    fn first_plateau_force(&self) -> f64 {
        self.first_plateau
    }

    fn separation_time(&self) -> f64 {
        self.separation
    }
}

impl ExactSolution for LayeredImpact {
    fn name(&self) -> &'static str {
        "layered-impact"
    }

    /// The first contact stress `-F1/A` of the striker's contact layer (compressive).
    fn characteristic_stress(&self) -> f64 {
        -self.first_plateau / self.layers[self.contact - 1].area
    }

    fn domain_length(&self) -> f64 {
        self.boundaries[self.layers.len()]
    }

    fn stress(&self, x: f64, t: f64) -> f64 {
        let (force, _) = self.state(x, t);
        self.locate(x, t)
            .map_or(f64::NAN, |i| force / self.layers[i].area)
    }

    /// Mean stress, for an interval within one area (the mean force over the mean area
    /// otherwise: what a linear element of constant area compares with).
    fn stress_average(&self, x0: f64, x1: f64, t: f64) -> f64 {
        let (force, _) = self.mean_state(x0, x1, t);
        self.locate(0.5 * (x0 + x1), t)
            .map_or(f64::NAN, |i| force / self.layers[i].area)
    }

    fn stress_extreme(&self, sign: f64, t: f64) -> f64 {
        let length = self.domain_length();
        let mut cuts = vec![0.0];
        cuts.extend(self.boundaries.iter().copied());
        cuts.extend(self.front_positions(t));
        cuts.push(length);
        cuts.sort_by(f64::total_cmp);
        cuts.windows(2)
            .filter(|w| w[1] > w[0])
            .map(|w| sign * ExactSolution::stress(self, 0.5 * (w[0] + w[1]), t))
            .fold(f64::NEG_INFINITY, f64::max)
    }

    fn velocity(&self, x: f64, t: f64) -> Option<f64> {
        Some(self.state(x, t).1)
    }

    fn contact(&self) -> Option<&dyn ContactHistory> {
        Some(self)
    }

    /// Tracking was paid at construction; an evaluation costs a few binary searches (one unit).
    fn evaluation_work(&self, t: f64) -> Result<f64, ReferenceError> {
        if t.is_finite() && t <= self.valid_until + self.tol {
            Ok(1.0)
        } else {
            Err(ReferenceError::BeyondReach {
                reference: "layered-impact",
                t,
                limit: format!("tracked up to t = {:e}", self.valid_until),
            })
        }
    }

    fn evaluations(&self, what: Evaluation<'_>, _t: f64) -> usize {
        match what {
            Evaluation::Averages(nodes) => nodes.len().saturating_sub(1),
            Evaluation::Points(xs) => xs.len(),
            Evaluation::Extreme => 2 * self.layers.len(),
        }
    }

    fn cost_detail(&self) -> String {
        format!(
            " (a layered impact, {} layers, {} events)",
            self.layers.len(),
            self.events
        )
    }
}
