//! The exact quantities of a case's analytic reference that a finite-element result is
//! compared with: element averages of the stress, the extreme stress of the field (for
//! overshoots), nodal displacement and velocity, energies. Evaluated by `courant-references`
//! (never by the solver), on the mesh of the record.

use crate::scene::reference::{GRADED_EXTREME_SAMPLES as EXTREME_SAMPLES, Reference};
use courant_references::Energies;
use courant_solver::Mesh;

/// What a reference gives to compare a result with.
pub trait ExactSolution {
    /// Exact element averages of the stress at time `t`.
    fn element_averages(&self, mesh: &Mesh, t: f64) -> Vec<f64>;
    /// Exact stress at each `x` (measured from the bar's start) at time `t`, right-continuous in
    /// t (a front exactly at a point has arrived, as the references define it).
    fn point_values(&self, xs: &[f64], t: f64) -> Vec<f64>;
    /// The largest value of `load_sign * sigma(x, t)` over the whole bar.
    fn extreme(&self, t: f64) -> f64;
    /// Exact displacement at `x` (mesh coordinates), where the reference provides it.
    fn displacement(&self, mesh: &Mesh, x: f64, t: f64) -> Option<f64>;
    /// Exact velocity at `x` (mesh coordinates).
    fn velocity(&self, mesh: &Mesh, x: f64, t: f64) -> Option<f64>;
    /// Exact kinetic and strain energies and work, where the reference provides them.
    fn energies(&self, t: f64) -> Option<Energies>;
}

impl ExactSolution for Reference {
    /// Exact element averages of the stress at time `t`.
    fn element_averages(&self, mesh: &Mesh, t: f64) -> Vec<f64> {
        let nodes: Vec<f64> = mesh.nodes().iter().map(|x| x - mesh.start()).collect();
        match self {
            Reference::Dalembert(d) => nodes
                .windows(2)
                .map(|w| d.stress_average(w[0], w[1], t))
                .collect(),
            Reference::Graded(g) => g.stress_averages(&nodes, t),
            Reference::Layered(l) => match l.field(t) {
                Ok(field) => nodes
                    .windows(2)
                    .map(|w| field.stress_average(w[0], w[1]))
                    .collect(),
                Err(_) => vec![f64::NAN; nodes.len() - 1],
            },
        }
    }

    /// Exact stress at each `x` (from the bar's start) at time `t`: d'Alembert's and the graded
    /// bar's `stress(x, t)`, the layered field evaluated once for all points.
    fn point_values(&self, xs: &[f64], t: f64) -> Vec<f64> {
        match self {
            Reference::Dalembert(d) => xs.iter().map(|&x| d.stress(x, t)).collect(),
            Reference::Graded(g) => g.stress_profile(xs, t),
            Reference::Layered(l) => match l.field(t) {
                Ok(field) => xs.iter().map(|&x| field.stress(x)).collect(),
                Err(_) => vec![f64::NAN; xs.len()],
            },
        }
    }

    /// The largest value of `load_sign * sigma(x, t)` over the whole bar: the exact extreme an
    /// overshoot is measured against (for a single step front, the plateau behind it).
    ///
    /// Whole-bar rather than per element on purpose: a per-element envelope would count the
    /// smeared numerical front in the element just ahead of an exact front as "overshoot"
    /// (about a third of the jump), and would depend on round-off where a front sits on a node.
    /// Piecewise-constant references are evaluated on every piece between fronts; the graded
    /// field (smooth between fronts) on 4000 points per length plus both sides of each front.
    fn extreme(&self, t: f64) -> f64 {
        let s = self.load_sign();
        let pieces = |length: f64, fronts: Vec<f64>, stress: &dyn Fn(f64) -> f64| {
            let mut cuts = vec![0.0];
            cuts.extend(fronts.into_iter().filter(|&f| f > 0.0 && f < length));
            cuts.push(length);
            cuts.windows(2)
                .map(|w| s * stress(0.5 * (w[0] + w[1])))
                .fold(f64::NEG_INFINITY, f64::max)
        };
        match self {
            Reference::Dalembert(d) => pieces(d.length, d.front_positions(t), &|x| d.stress(x, t)),
            Reference::Layered(l) => match l.field(t) {
                Ok(field) => pieces(l.length(), field.front_positions(), &|x| field.stress(x)),
                Err(_) => f64::NAN,
            },
            Reference::Graded(g) => {
                let eps = 1e-9 * g.length;
                let mut xs: Vec<f64> = (0..=EXTREME_SAMPLES)
                    .map(|i| g.length * i as f64 / EXTREME_SAMPLES as f64)
                    .collect();
                for f in g.front_positions(t) {
                    xs.extend([(f - eps).max(0.0), (f + eps).min(g.length)]);
                }
                xs.iter()
                    .map(|&x| s * g.stress(x, t))
                    .filter(|v| v.is_finite())
                    .fold(f64::NEG_INFINITY, f64::max)
            }
        }
    }

    /// Exact displacement at `x` (mesh coordinates), where the reference provides it.
    fn displacement(&self, mesh: &Mesh, x: f64, t: f64) -> Option<f64> {
        match self {
            Reference::Dalembert(d) => Some(d.displacement(x - mesh.start(), t)),
            _ => None,
        }
    }

    /// Exact velocity at `x`; for d'Alembert the mean of its limits in time where a front sits
    /// exactly on `x` (what a central-difference full-step velocity represents there).
    fn velocity(&self, mesh: &Mesh, x: f64, t: f64) -> Option<f64> {
        let x = x - mesh.start();
        match self {
            Reference::Dalembert(d) => Some(d.velocity_mean(x, t)),
            Reference::Graded(g) => Some(g.velocity(x, t)),
            Reference::Layered(l) => l.field(t).ok().map(|f| f.velocity(x)),
        }
    }

    /// Exact kinetic and strain energies and work, where the reference provides them.
    fn energies(&self, t: f64) -> Option<Energies> {
        match self {
            Reference::Dalembert(d) => Some(d.energies(t)),
            _ => None,
        }
    }
}
