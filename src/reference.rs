//! Binding of a scene to its analytic reference from `courant-references`, and the exact
//! quantities a finite-element result is compared with.

use crate::scene::Material;
use crate::scene::schema::RawReferenceKind;
use courant_references::graded::{GradedBar, Layer, LayeredBar};
use courant_references::{DalembertBar, Energies};
use courant_solver::{Field, Mesh, Model, Support, TimeFunction};

/// Points per bar length at which the graded field is sampled for its extreme value.
const EXTREME_SAMPLES: usize = 4000;

/// An analytic reference for a case.
#[derive(Debug, Clone, PartialEq)]
pub enum Reference {
    /// d'Alembert's solution of the homogeneous free-fixed bar under a Heaviside end traction
    /// (methods.md §3).
    Dalembert(DalembertBar),
    /// The free-fixed bar with modulus linear in x (methods.md §4; Laplace transform inverted by
    /// de Hoog's algorithm, cross-checked by characteristics).
    Graded(GradedBar),
    /// Piecewise-constant layers: exact wave tracking with transmission and reflection at every
    /// interface.
    Layered(LayeredBar),
}

impl Reference {
    /// The reference of `kind` for `model` (whose material the scene states as `material`), or a
    /// sentence saying why the model is not the case that reference solves.
    pub fn for_model(
        kind: RawReferenceKind,
        model: &Model,
        material: &Material,
    ) -> Result<Option<Reference>, String> {
        if kind == RawReferenceKind::None {
            return Ok(None);
        }
        let rule = match kind {
            RawReferenceKind::Dalembert => "reference = \"dalembert\" solves a homogeneous bar",
            RawReferenceKind::Graded => {
                "reference = \"graded\" solves a bar with modulus linear in x and constant density"
            }
            _ => "reference = \"layered\" solves a bar of homogeneous layers (`material.layers`)",
        };
        let common = ", free and loaded at the left end by a step traction from t = 0, fixed at the right end, starting at rest";
        let sigma0 = load_case(model).map_err(|why| format!("{rule}{common}; {why}"))?;
        let bar = model.bar();
        let (length, area) = (bar.mesh().length(), bar.area()[0]);
        let reference = match (kind, material) {
            (RawReferenceKind::Dalembert, _) if bar.is_homogeneous() => Reference::Dalembert(
                DalembertBar::new(length, bar.modulus()[0], bar.density()[0], area, sigma0)
                    .map_err(|e| e.to_string())?,
            ),
            (
                RawReferenceKind::Graded,
                Material::Fields {
                    modulus: Field::Linear { left, right },
                    density: Field::Constant(rho),
                },
            ) => Reference::Graded(
                GradedBar::new(length, *left, *right, *rho, area, sigma0)
                    .map_err(|e| e.to_string())?,
            ),
            (RawReferenceKind::Layered, Material::Layers(layers)) => {
                let layers = layers
                    .iter()
                    .map(|&(t, e, rho)| Layer::new(t, e, rho))
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(|e| e.to_string())?;
                Reference::Layered(
                    LayeredBar::new(&layers, area, sigma0).map_err(|e| e.to_string())?,
                )
            }
            _ => {
                return Err(format!(
                    "{rule}{common}; this bar's material does not match"
                ));
            }
        };
        Ok(Some(reference))
    }

    /// Short name, as written in scene files.
    pub fn name(&self) -> &'static str {
        match self {
            Reference::Dalembert(_) => "dalembert",
            Reference::Graded(_) => "graded",
            Reference::Layered(_) => "layered",
        }
    }

    fn sigma0(&self) -> f64 {
        match self {
            Reference::Dalembert(d) => d.sigma0,
            Reference::Graded(g) => g.sigma0,
            Reference::Layered(l) => l.sigma0(),
        }
    }

    /// `|sigma0|`: the stress scale errors are normalised by (the jump of the load front).
    pub fn stress_scale(&self) -> f64 {
        self.sigma0().abs()
    }

    /// Sign of the applied stress (direction in which an overshoot is measured).
    pub fn load_sign(&self) -> f64 {
        self.sigma0().signum()
    }

    /// Exact element averages of the stress at time `t`.
    pub fn element_averages(&self, mesh: &Mesh, t: f64) -> Vec<f64> {
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

    /// The largest value of `load_sign * sigma(x, t)` over the whole bar: the exact extreme an
    /// overshoot is measured against (for a single step front, the plateau behind it).
    ///
    /// Whole-bar rather than per element on purpose: a per-element envelope would count the
    /// smeared numerical front in the element just ahead of an exact front as "overshoot"
    /// (about a third of the jump), and would depend on round-off where a front sits on a node.
    /// Piecewise-constant references are evaluated on every piece between fronts; the graded
    /// field (smooth between fronts) on 4000 points per length plus both sides of each front.
    pub fn extreme(&self, t: f64) -> f64 {
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
    pub fn displacement(&self, mesh: &Mesh, x: f64, t: f64) -> Option<f64> {
        match self {
            Reference::Dalembert(d) => Some(d.displacement(x - mesh.start(), t)),
            _ => None,
        }
    }

    /// Exact velocity at `x`; for d'Alembert the mean of its limits in time where a front sits
    /// exactly on `x` (what a central-difference full-step velocity represents there).
    pub fn velocity(&self, mesh: &Mesh, x: f64, t: f64) -> Option<f64> {
        let x = x - mesh.start();
        match self {
            Reference::Dalembert(d) => Some(d.velocity_mean(x, t)),
            Reference::Graded(g) => Some(g.velocity(x, t)),
            Reference::Layered(l) => l.field(t).ok().map(|f| f.velocity(x)),
        }
    }

    /// Exact kinetic and strain energies and work, where the reference provides them.
    pub fn energies(&self, t: f64) -> Option<Energies> {
        match self {
            Reference::Dalembert(d) => Some(d.energies(t)),
            _ => None,
        }
    }
}

/// The applied stress `sigma0` when the model is the free-fixed bar under one left step
/// traction from `t = 0`, at rest; otherwise why not.
fn load_case(model: &Model) -> Result<f64, String> {
    let supports = model.supports();
    if supports.left != Support::Free || supports.right != Support::Fixed {
        return Err(format!(
            "this bar's supports are left = {:?}, right = {:?}",
            supports.left, supports.right
        ));
    }
    let loads = model.loads();
    let step_from_zero =
        |t: &TimeFunction| matches!(t, TimeFunction::Step { start, .. } if *start == 0.0);
    if loads.len() != 1 || loads[0].node != 0 || !step_from_zero(&loads[0].time) {
        return Err(format!(
            "this scene has {} load(s), not one step traction at the left end",
            loads.len()
        ));
    }
    if model
        .initial_displacement()
        .iter()
        .chain(model.initial_velocity())
        .any(|&v| v != 0.0)
    {
        return Err("this scene has initial displacement or velocity".into());
    }
    if !model.bar().area().windows(2).all(|w| w[0] == w[1]) {
        return Err("this bar's area varies".into());
    }
    // Nodal force F0 = -sigma0 A at the left end (methods.md §2).
    Ok(-loads[0].magnitude / model.bar().area()[0])
}
