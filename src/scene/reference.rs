//! Binding of a case to its analytic reference from `courant-references`: which exact solution
//! and with which parameters, validated against the case's model when the scene is parsed. The
//! exact quantities are evaluated by `compare::exact`.

use super::material::Material;
use super::schema::RawReferenceKind;
use courant_references::graded::{GradedBar, Layer, LayeredBar};
use courant_references::{DalembertBar, ExactSolution};
use courant_solver::{Field, Model, Support, TimeFunction};

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

    /// The exact solution, through the one contract every reference honours: the only place
    /// that looks at which reference this is.
    pub fn exact(&self) -> &dyn ExactSolution {
        match self {
            Reference::Dalembert(d) => d,
            Reference::Graded(g) => g,
            Reference::Layered(l) => l,
        }
    }

    /// Short name, as written in scene files.
    pub fn name(&self) -> &'static str {
        self.exact().name()
    }

    /// The applied stress `sigma0` (methods.md §2: nodal force `F0 = -sigma0 A` at x = 0).
    pub fn sigma0(&self) -> f64 {
        self.exact().characteristic_stress()
    }

    /// `|sigma0|`: the stress scale errors are normalised by (the jump of the load front).
    pub fn stress_scale(&self) -> f64 {
        self.sigma0().abs()
    }

    /// Sign of the applied stress (direction in which an overshoot is measured).
    pub fn load_sign(&self) -> f64 {
        self.sigma0().signum()
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
    if !model.bar().area().is_uniform() {
        return Err("this bar's area varies".into());
    }
    // Nodal force F0 = -sigma0 A at the left end (methods.md §2).
    Ok(-loads[0].magnitude / model.bar().area()[0])
}
