//! The exact quantities of a case's analytic reference that a finite-element result is
//! compared with: element averages of the stress, the extreme stress of the field (for
//! overshoots), nodal displacement and velocity, energies. Evaluated by `courant-references`
//! through its one contract (`courant_references::ExactSolution`, never by the solver), on the
//! mesh of the record: this file only maps mesh coordinates to the reference's.

use crate::scene::reference::Reference;
use courant_references::Energies;
use courant_solver::Mesh;

/// What a reference gives to compare a result with, on a mesh.
pub trait ExactOnMesh {
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

impl ExactOnMesh for Reference {
    /// Exact element averages of the stress at time `t` (the contract's `stress_averages` on the
    /// mesh's nodes, measured from the bar's start).
    fn element_averages(&self, mesh: &Mesh, t: f64) -> Vec<f64> {
        let nodes: Vec<f64> = mesh.nodes().iter().map(|x| x - mesh.start()).collect();
        self.exact().stress_averages(&nodes, t)
    }

    /// Exact stress at each `x` (from the bar's start) at time `t` (one field evaluation for all
    /// points where the reference allows).
    fn point_values(&self, xs: &[f64], t: f64) -> Vec<f64> {
        self.exact().stress_profile(xs, t)
    }

    /// The largest value of `load_sign * sigma(x, t)` over the whole bar: the exact extreme an
    /// overshoot is measured against (for a single step front, the plateau behind it).
    ///
    /// Whole-bar rather than per element on purpose: a per-element envelope would count the
    /// smeared numerical front in the element just ahead of an exact front as "overshoot"
    /// (about a third of the jump), and would depend on round-off where a front sits on a node.
    /// Piecewise-constant references are evaluated on every piece between fronts; the graded
    /// field (smooth between fronts) on 4000 points per length plus both sides of each front
    /// (`ExactSolution::stress_extreme` of `courant-references`).
    fn extreme(&self, t: f64) -> f64 {
        self.exact().stress_extreme(self.load_sign(), t)
    }

    /// Exact displacement at `x` (mesh coordinates), where the reference provides it.
    fn displacement(&self, mesh: &Mesh, x: f64, t: f64) -> Option<f64> {
        self.exact().displacement(x - mesh.start(), t)
    }

    /// Exact velocity at `x`; for d'Alembert the mean of its limits in time where a front sits
    /// exactly on `x` (what a central-difference full-step velocity represents there).
    fn velocity(&self, mesh: &Mesh, x: f64, t: f64) -> Option<f64> {
        self.exact().velocity(x - mesh.start(), t)
    }

    /// Exact kinetic and strain energies and work, where the reference provides them.
    fn energies(&self, t: f64) -> Option<Energies> {
        self.exact().energies(t)
    }
}
