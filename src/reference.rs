//! Binding of a scene to its analytic reference from `courant-references`, and the exact
//! quantities a finite-element result is compared with.

use crate::scene::schema::RawReferenceKind;
use courant_references::{DalembertBar, Energies};
use courant_solver::{Mesh, Model, Support, TimeFunction};

/// An analytic reference for a case.
#[derive(Debug, Clone, PartialEq)]
pub enum Reference {
    /// d'Alembert's solution of the homogeneous free-fixed bar under a Heaviside end traction
    /// (methods.md §3).
    Dalembert(DalembertBar),
}

impl Reference {
    /// The reference of `kind` for `model`, or a sentence saying why the model is not the case
    /// that reference solves.
    pub fn for_model(kind: RawReferenceKind, model: &Model) -> Result<Option<Reference>, String> {
        match kind {
            RawReferenceKind::None => Ok(None),
            RawReferenceKind::Dalembert => dalembert(model).map(|d| Some(Reference::Dalembert(d))),
        }
    }

    /// Short name, as written in scene files.
    pub fn name(&self) -> &'static str {
        match self {
            Reference::Dalembert(_) => "dalembert",
        }
    }

    /// `|sigma0|`: the stress scale errors are normalised by, and the jump of every front.
    pub fn stress_scale(&self) -> f64 {
        match self {
            Reference::Dalembert(d) => d.sigma0.abs(),
        }
    }

    /// Sign of the applied stress (direction in which an overshoot is measured).
    pub fn load_sign(&self) -> f64 {
        match self {
            Reference::Dalembert(d) => d.sigma0.signum(),
        }
    }

    /// Exact element averages of the stress at time `t`.
    pub fn element_averages(&self, mesh: &Mesh, t: f64) -> Vec<f64> {
        match self {
            Reference::Dalembert(d) => {
                let x0 = mesh.start();
                (0..mesh.element_count())
                    .map(|e| d.stress_average(mesh.nodes()[e] - x0, mesh.nodes()[e + 1] - x0, t))
                    .collect()
            }
        }
    }

    /// The largest value of `load_sign * sigma(x, t)` over the whole bar: the exact extreme an
    /// overshoot is measured against (for a single step front, the plateau behind it).
    ///
    /// Whole-bar rather than per element on purpose: a per-element envelope would count the
    /// smeared numerical front in the element just ahead of an exact front as "overshoot"
    /// (about a third of the jump), and would depend on round-off where a front sits on a node.
    pub fn extreme(&self, t: f64) -> f64 {
        match self {
            Reference::Dalembert(d) => {
                let s = d.sigma0.signum();
                let mut cuts = vec![0.0];
                cuts.extend(
                    d.front_positions(t)
                        .into_iter()
                        .filter(|&f| f > 0.0 && f < d.length),
                );
                cuts.push(d.length);
                cuts.windows(2)
                    .map(|w| s * d.stress(0.5 * (w[0] + w[1]), t))
                    .fold(f64::NEG_INFINITY, f64::max)
            }
        }
    }

    /// Exact displacement at `x` (mesh coordinates).
    pub fn displacement(&self, mesh: &Mesh, x: f64, t: f64) -> f64 {
        match self {
            Reference::Dalembert(d) => d.displacement(x - mesh.start(), t),
        }
    }

    /// Exact velocity at `x`, the mean of its limits in time where a front sits exactly on `x`
    /// (what a central-difference full-step velocity represents there).
    pub fn velocity(&self, mesh: &Mesh, x: f64, t: f64) -> f64 {
        match self {
            Reference::Dalembert(d) => d.velocity_mean(x - mesh.start(), t),
        }
    }

    /// Exact kinetic and strain energies and work.
    pub fn energies(&self, t: f64) -> Energies {
        match self {
            Reference::Dalembert(d) => d.energies(t),
        }
    }
}

fn dalembert(model: &Model) -> Result<DalembertBar, String> {
    let rule = "reference = \"dalembert\" solves a homogeneous bar, free and loaded at the left end by a \
                step traction from t = 0, fixed at the right end, starting at rest";
    let bar = model.bar();
    if !bar.is_homogeneous() {
        return Err(format!(
            "{rule}; this bar's modulus, density or area varies along it"
        ));
    }
    let supports = model.supports();
    if supports.left != Support::Free || supports.right != Support::Fixed {
        return Err(format!(
            "{rule}; this bar's supports are left = {:?}, right = {:?}",
            supports.left, supports.right
        ));
    }
    let loads = model.loads();
    let step_from_zero =
        |t: &TimeFunction| matches!(t, TimeFunction::Step { start, .. } if *start == 0.0);
    if loads.len() != 1 || loads[0].node != 0 || !step_from_zero(&loads[0].time) {
        return Err(format!(
            "{rule}; this scene has {} load(s), not one step traction at the left end",
            loads.len()
        ));
    }
    if model
        .initial_displacement()
        .iter()
        .chain(model.initial_velocity())
        .any(|&v| v != 0.0)
    {
        return Err(format!(
            "{rule}; this scene has initial displacement or velocity"
        ));
    }
    let area = bar.area()[0];
    // Nodal force F0 = -sigma0 A at the left end (methods.md §2).
    let sigma0 = -loads[0].magnitude / area;
    DalembertBar::new(
        bar.mesh().length(),
        bar.modulus()[0],
        bar.density()[0],
        area,
        sigma0,
    )
    .map_err(|e| e.to_string())
}
