//! Bar geometry and material as a scene states them (`[bar]`, `[material]`, `[mesh]`),
//! validated, with the transit time of the continuum bar.

use super::budget;
use super::error::{SceneError, Source, positive};
use super::magnitude;
use super::material::Material;
use super::schema::{RawField, RawLinear, RawScene};
use courant_solver::{Field, Mesh};
use toml::Spanned;

/// Bar geometry and material as the scene states them.
pub struct Geometry<'r> {
    pub(super) length: f64,
    pub(super) area: f64,
    pub(super) element_counts: Vec<usize>,
    pub(super) grading: f64,
    pub(super) equal_transit: bool,
    /// The material.
    pub material: Material,
    pub(super) raw: &'r RawScene,
}

impl<'r> Geometry<'r> {
    pub(super) fn read(src: &Source, raw: &'r RawScene) -> Result<Self, SceneError> {
        let optional = |v: &Option<Spanned<f64>>, key: &str| {
            v.as_ref()
                .map(|v| {
                    let x = positive(src, v, key)?;
                    magnitude::input(src, Some(v.span()), key, key, x)?;
                    Ok(x)
                })
                .transpose()
        };
        let counts = raw.mesh.elements.get_ref().values();
        let span = raw.mesh.elements.span();
        if counts.is_empty() {
            return Err(src.error(
                Some(span),
                "mesh.elements",
                "the list is empty; give at least one element count",
            ));
        }
        for &n in &counts {
            budget::element_count(src, Some(span.clone()), "mesh.elements", n)?;
        }
        let material = match (&raw.material.layers, &raw.material.modulus) {
            (Some(layers), None) if raw.material.density.is_none() => {
                let mut list = Vec::new();
                for l in layers.get_ref() {
                    let density = l.density.unwrap_or(1.0);
                    for (name, v) in [
                        ("thickness", l.thickness),
                        ("modulus", l.modulus),
                        ("density", density),
                    ] {
                        if !(v.is_finite() && v > 0.0) {
                            return Err(src.error(
                                Some(layers.span()),
                                "material.layers",
                                format!("{name} = {v} must be positive and finite"),
                            ));
                        }
                        magnitude::input(src, Some(layers.span()), "material.layers", name, v)?;
                    }
                    list.push((l.thickness, l.modulus, density));
                }
                if list.is_empty() {
                    return Err(src.error(
                        Some(layers.span()),
                        "material.layers",
                        "the list is empty",
                    ));
                }
                Material::Layers(list)
            }
            (Some(layers), _) => {
                return Err(src.error(
                    Some(layers.span()),
                    "material.layers",
                    "give either `layers` or `modulus`/`density`, not both",
                ));
            }
            (None, Some(modulus)) => Material::Fields {
                modulus: field(modulus),
                density: raw
                    .material
                    .density
                    .as_ref()
                    .map(field)
                    .unwrap_or(Field::Constant(1.0)),
            },
            (None, None) => {
                return Err(src.error(None, "material", "needs `modulus` (or `layers`)"));
            }
        };
        if let Material::Fields { modulus, density } = &material {
            for (key, f) in [("material.modulus", modulus), ("material.density", density)] {
                let ends = match f {
                    Field::Constant(c) => [*c, *c],
                    Field::Linear { left, right } => [*left, *right],
                    Field::PerElement(_) => [1.0, 1.0],
                };
                let span = if key == "material.modulus" {
                    raw.material.modulus.as_ref()
                } else {
                    raw.material.density.as_ref()
                }
                .map(|s| s.span());
                if let Some(bad) = ends.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
                    return Err(src.error(
                        span,
                        key,
                        format!("{bad} must be positive and finite (along the whole bar)"),
                    ));
                }
                magnitude::inputs(src, span, key, &key["material.".len()..], ends)?;
            }
        }
        let layered_length = match &material {
            Material::Layers(l) => Some(l.iter().map(|x| x.0).sum::<f64>()),
            Material::Fields { .. } => None,
        };
        let length = optional(&raw.bar.length, "bar.length")?
            .or(layered_length)
            .unwrap_or(1.0);
        if let Some(total) = layered_length
            && (total - length).abs() > 1e-12 * length
        {
            return Err(src.error(
                None,
                "material.layers",
                format!("the layers add up to {total}, not the bar length {length}"),
            ));
        }
        let equal_transit = match raw
            .mesh
            .spacing
            .as_ref()
            .map(|s| (s.get_ref().as_str(), s.span()))
        {
            None | Some(("uniform", _)) => false,
            Some(("equal-transit", span)) => {
                if raw.mesh.grading.is_some() {
                    return Err(src.error(
                        Some(span),
                        "mesh.spacing",
                        "equal-transit spacing takes no `grading`",
                    ));
                }
                true
            }
            Some((other, span)) => {
                return Err(src.error(
                    Some(span),
                    "mesh.spacing",
                    format!("\"{other}\" is not one of uniform, equal-transit"),
                ));
            }
        };
        Ok(Self {
            length,
            area: optional(&raw.bar.area, "bar.area")?.unwrap_or(1.0),
            element_counts: counts.iter().map(|&n| n as usize).collect(),
            grading: optional(&raw.mesh.grading, "mesh.grading")?.unwrap_or(1.0),
            equal_transit,
            material,
            raw,
        })
    }

    /// Transit time of the continuum bar, `T = int_0^L dx / c(x)`: exact for constant
    /// properties and layers, composite Simpson (20000 intervals, ~1e-15 relative for linear
    /// fields) otherwise. Independent of the mesh, so times in transit units mean the same for
    /// every N.
    pub(super) fn transit_time(&self) -> f64 {
        let slowness = |x: f64| {
            let (e, rho) = self.material.at(x, self.length);
            (rho / e).sqrt()
        };
        match &self.material {
            Material::Layers(layers) => {
                layers.iter().map(|&(t, e, rho)| t * (rho / e).sqrt()).sum()
            }
            Material::Fields { modulus, density }
                if modulus.is_constant() && density.is_constant() =>
            {
                self.length * slowness(0.0)
            }
            Material::Fields { .. } => {
                let n = 20_000;
                let h = self.length / n as f64;
                let sum: f64 = (0..=n)
                    .map(|i| {
                        let w = if i == 0 || i == n {
                            1.0
                        } else if i % 2 == 1 {
                            4.0
                        } else {
                            2.0
                        };
                        w * slowness(i as f64 * h)
                    })
                    .sum();
                sum * h / 3.0
            }
        }
    }

    /// Element fields of the material on `mesh`: fields keep their exact midpoint sampling,
    /// layers are sampled at element midpoints.
    pub(super) fn element_fields(&self, mesh: &Mesh) -> (Field, Field) {
        match &self.material {
            Material::Fields { modulus, density } => (modulus.clone(), density.clone()),
            Material::Layers(_) => {
                let (e, rho): (Vec<f64>, Vec<f64>) = (0..mesh.element_count())
                    .map(|k| {
                        self.material
                            .at(mesh.midpoint(k) - mesh.start(), self.length)
                    })
                    .unzip();
                (Field::PerElement(e), Field::PerElement(rho))
            }
        }
    }
}

pub(super) fn field(f: &Spanned<RawField>) -> Field {
    raw_field(f.get_ref())
}

/// A property as the solver's field: a constant, or linear between the bar's ends (sampled at
/// element midpoints by `Bar::new`, methods.md §1).
pub(super) fn raw_field(f: &RawField) -> Field {
    match f {
        RawField::Constant(c) => Field::Constant(*c),
        RawField::Linear(RawLinear {
            linear: [left, right],
        }) => Field::Linear {
            left: *left,
            right: *right,
        },
    }
}
