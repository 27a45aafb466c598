//! The bar and the model of a time-stepping or spectrum case: mesh (uniform, geometric or
//! equal-transit), element fields, supports, loads and initial conditions.

use super::error::{SceneError, Source};
use super::geometry::{Geometry, field};
use super::magnitude::{self, Scale};
use super::material::Material;
use super::schema::{RawEnd, RawField, RawLoad, RawLoadKind, RawScene, RawSupport, RawTimeKind};
use courant_solver::{
    Bar, End, Field, InitialConditions, InputError, Load, Mesh, Model, Support, Supports,
    TimeFunction,
};
use toml::Spanned;

pub(super) fn model_of(
    src: &Source,
    raw: &RawScene,
    g: &Geometry,
    elements: usize,
) -> Result<Model, SceneError> {
    let bar = bar_of(src, raw, g, elements)?;
    let supports = Supports {
        left: support(raw.supports.left),
        right: support(raw.supports.right),
    };
    let loads = raw
        .loads
        .iter()
        .map(|l| load_of(src, l, bar.node_count() - 1))
        .collect::<Result<Vec<_>, _>>()?;
    let nodal = |f: &Option<Spanned<RawField>>| -> Option<Vec<f64>> {
        f.as_ref().map(|f| {
            let field = field(f);
            let mesh = bar.mesh();
            mesh.nodes()
                .iter()
                .map(|&x| match &field {
                    Field::Linear { left, right } => {
                        left + (right - left) * (x - mesh.start()) / mesh.length()
                    }
                    Field::Constant(c) => *c,
                    Field::PerElement(_) => f64::NAN,
                })
                .collect()
        })
    };
    let initial = InitialConditions {
        displacement: nodal(&raw.initial.displacement),
        velocity: nodal(&raw.initial.velocity),
    };
    debug_assert!(std::ptr::eq(raw, g.raw));
    for (key, field) in [
        ("initial.displacement", &raw.initial.displacement),
        ("initial.velocity", &raw.initial.velocity),
    ] {
        if let Some(f) = field {
            let values = match f.get_ref() {
                RawField::Constant(c) => vec![*c],
                RawField::Linear(l) => l.linear.to_vec(),
            };
            magnitude::inputs(src, Some(f.span()), key, &key["initial.".len()..], values)?;
        }
    }
    let model = Model::new(bar, supports, &loads, initial).map_err(|e| {
        let (key, span) = match &e {
            InputError::NodeValue {
                field: "initial displacement",
                ..
            } => (
                "initial.displacement",
                raw.initial.displacement.as_ref().map(|d| d.span()),
            ),
            InputError::NodeValue {
                field: "initial velocity",
                ..
            } => (
                "initial.velocity",
                raw.initial.velocity.as_ref().map(|d| d.span()),
            ),
            _ => ("load", raw.loads.first().map(|l| l.span())),
        };
        src.error(span, key, e.to_string())
    })?;
    check_scales(src, raw, &model)?;
    Ok(model)
}

/// The derived scales of `model` within [`magnitude`]'s bounds, blaming the input each comes
/// from (stiffness and frequency: the modulus or layers; mass: the density or layers; a load:
/// the first load).
pub(super) fn check_scales(src: &Source, raw: &RawScene, model: &Model) -> Result<(), SceneError> {
    let material = |key: &'static str, field: &Option<Spanned<RawField>>| match (
        field,
        &raw.material.layers,
    ) {
        (Some(f), _) => (Some(f.span()), key),
        (None, Some(l)) => (Some(l.span()), "material.layers"),
        // A default density: the mass comes from the area and the element length.
        (None, None) => match &raw.bar.area {
            Some(a) => (Some(a.span()), "bar.area"),
            None => (Some(raw.mesh.elements.span()), "mesh.elements"),
        },
    };
    magnitude::model(
        src,
        |scale| match scale {
            Scale::Stiffness | Scale::Frequency => {
                material("material.modulus", &raw.material.modulus)
            }
            Scale::Mass => material("material.density", &raw.material.density),
            Scale::Load => (raw.loads.first().map(|l| l.span()), "load"),
        },
        model,
    )
}

/// The bar of a scene with `elements` elements (mesh spacing and material as stated).
pub(super) fn bar_of(
    src: &Source,
    raw: &RawScene,
    g: &Geometry,
    elements: usize,
) -> Result<Bar, SceneError> {
    let mesh_error = |e: InputError| match (&e, &raw.mesh.grading) {
        (
            InputError::Parameter {
                field: "grading ratio",
                ..
            },
            Some(s),
        ) => src.error(Some(s.span()), "mesh.grading", e.to_string()),
        _ => src.error(
            Some(raw.mesh.elements.span()),
            "mesh.elements",
            e.to_string(),
        ),
    };
    let material_span = raw.material.modulus.as_ref().map(|m| m.span()).or(raw
        .material
        .layers
        .as_ref()
        .map(|l| l.span()));
    let bar_error = |e: InputError| {
        let (key, span) = match &e {
            InputError::ElementProperty {
                field: "density", ..
            } => (
                "material.density",
                raw.material.density.as_ref().map(|d| d.span()),
            ),
            InputError::ElementProperty { field: "area", .. } => {
                ("bar.area", raw.bar.area.as_ref().map(|d| d.span()))
            }
            _ if raw.material.modulus.is_some() => ("material.modulus", material_span.clone()),
            _ => ("material.layers", material_span.clone()),
        };
        src.error(span, key, e.to_string())
    };
    let area = Field::Constant(g.area);
    if g.equal_transit {
        let slowness = |x: f64| {
            let (e, rho) = g.material.at(x, g.length);
            (rho / e).sqrt()
        };
        // Layer interfaces are where the slowness jumps: the travel-time quadrature splits there.
        let breaks: Vec<f64> = match &g.material {
            Material::Layers(layers) => layers
                .iter()
                .scan(0.0, |x, l| {
                    *x += l.0;
                    Some(*x)
                })
                .collect(),
            Material::Fields { .. } => Vec::new(),
        };
        if let Material::Layers(layers) = &g.material {
            // Exact layered models need every interface on a node: each layer must take a whole
            // number of element transit times.
            let total = g.transit_time();
            for (k, &(thickness, e, rho)) in layers.iter().enumerate() {
                let share = thickness * (rho / e).sqrt() / total * elements as f64;
                if (share - share.round()).abs() > 1e-6 * share.max(1.0) || share.round() < 1.0 {
                    return Err(src.error(
                        raw.mesh.spacing.as_ref().map(|s| s.span()),
                        "mesh.spacing",
                        format!(
                            "equal-transit spacing puts {share:.6} elements in layer {k} with N = {elements}: choose N so that \
                             every layer holds a whole number of elements (layer transit fractions must times N be integers)"
                        ),
                    ));
                }
            }
        }
        let (mesh, transit) =
            Mesh::equal_transit(g.length, elements, &slowness, &breaks).map_err(mesh_error)?;
        let (_, density) = g.element_fields(&mesh);
        Bar::equal_transit(mesh, transit, &density, &area).map_err(bar_error)
    } else {
        let mesh = Mesh::geometric(g.length, elements, g.grading).map_err(mesh_error)?;
        let (modulus, density) = g.element_fields(&mesh);
        Bar::new(mesh, &modulus, &density, &area).map_err(bar_error)
    }
}

fn support(s: RawSupport) -> Support {
    match s {
        RawSupport::Free => Support::Free,
        RawSupport::Fixed => Support::Fixed,
    }
}

fn load_of(src: &Source, spanned: &Spanned<RawLoad>, last_node: usize) -> Result<Load, SceneError> {
    let raw = spanned.get_ref();
    let fail = |msg: String| src.error(Some(spanned.span()), "load", msg);
    let start = raw.start.unwrap_or(0.0);
    let needs_duration = |what: &str| {
        raw.duration
            .ok_or_else(|| fail(format!("time = \"{what}\" needs `duration`")))
    };
    let time = match raw.time {
        RawTimeKind::Step => TimeFunction::Step {
            start,
            value_at_start: raw.value_at_start.unwrap_or(1.0),
        },
        RawTimeKind::Ramp => TimeFunction::Ramp {
            start,
            rise: needs_duration("ramp")?,
        },
        RawTimeKind::Pulse => TimeFunction::Pulse {
            start,
            duration: needs_duration("pulse")?,
        },
        RawTimeKind::Table => {
            let table = raw
                .table
                .as_ref()
                .ok_or_else(|| fail("time = \"table\" needs `table = [[t, f], ...]`".into()))?;
            TimeFunction::Table {
                times: table.iter().map(|p| p[0]).collect(),
                values: table.iter().map(|p| p[1]).collect(),
            }
        }
    };
    if raw.value_at_start.is_some() && raw.time != RawTimeKind::Step {
        return Err(fail(
            "`value_at_start` applies only to time = \"step\"".into(),
        ));
    }
    time.validate().map_err(|e| fail(e.to_string()))?;
    if !raw.value.is_finite() {
        return Err(fail(format!("value = {} must be finite", raw.value)));
    }
    let span = Some(spanned.span());
    magnitude::input(src, span.clone(), "load", "value", raw.value)?;
    let times = [raw.start, raw.duration].into_iter().flatten();
    let table = raw.table.iter().flatten().flat_map(|p| [p[0], p[1]]);
    magnitude::inputs(src, span, "load", "time or table entry", times.chain(table))?;
    match (raw.kind, raw.end, raw.node) {
        (RawLoadKind::Traction, Some(end), None) => Ok(Load::Traction {
            end: if end == RawEnd::Left {
                End::Left
            } else {
                End::Right
            },
            stress: raw.value,
            time,
        }),
        (RawLoadKind::Force, None, Some(node)) if node >= 0 && node as usize <= last_node => {
            Ok(Load::Force {
                node: node as usize,
                magnitude: raw.value,
                time,
            })
        }
        (RawLoadKind::Force, None, Some(node)) => Err(fail(format!(
            "node = {node} is not a node of the mesh (nodes 0..={last_node})"
        ))),
        (RawLoadKind::Traction, _, _) => Err(fail(
            "kind = \"traction\" needs `end` (\"left\" or \"right\") and no `node`".into(),
        )),
        (RawLoadKind::Force, _, _) => {
            Err(fail("kind = \"force\" needs `node` and no `end`".into()))
        }
    }
}
