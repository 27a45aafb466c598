//! The bars of a contact scene: homogeneous or layered, as the solver's `Bar` and as the layers
//! of the exact references, and the exact contact force a case is graded against
//! ([`ContactReference`]).

use super::budget;
use super::error::{SceneError, Source};
use super::magnitude;
use super::schema::RawContactBar;
use courant_references::ContactHistory;
use courant_references::contact::{ImpactBar, ImpactForce, ImpactLayer, LayeredImpact};
use courant_solver::{Bar, Field, Mesh};
use toml::Spanned;

/// A contact bar as the solver's `Bar` and as the layers of the exact references (one layer for
/// a homogeneous bar).
pub(super) fn bar(
    src: &Source,
    spanned: &Spanned<RawContactBar>,
    key: &str,
    area: f64,
) -> Result<(Bar, Vec<ImpactLayer>), SceneError> {
    let raw = spanned.get_ref();
    let span = Some(spanned.span());
    let fail = |msg: String| src.error(span.clone(), key, msg);
    let layers: Vec<(f64, f64, f64)> = match &raw.layers {
        None => vec![(
            raw.length,
            raw.modulus.unwrap_or(1.0),
            raw.density.unwrap_or(1.0),
        )],
        Some(_) if raw.modulus.is_some() || raw.density.is_some() => {
            return Err(fail(
                "give either `layers` or `modulus`/`density`, not both".into(),
            ));
        }
        Some(list) if list.is_empty() => {
            return Err(fail("`layers` is empty; give at least one layer".into()));
        }
        Some(list) => list
            .iter()
            .map(|l| (l.thickness, l.modulus, l.density.unwrap_or(1.0)))
            .collect(),
    };
    for (name, v) in std::iter::once(("length", raw.length)).chain(
        layers
            .iter()
            .flat_map(|&(h, e, rho)| [("thickness", h), ("modulus", e), ("density", rho)]),
    ) {
        if !(v.is_finite() && v > 0.0) {
            return Err(fail(format!("{name} = {v} must be positive and finite")));
        }
        magnitude::input(src, span.clone(), key, name, v)?;
    }
    let elements =
        budget::element_count(src, span.clone(), &format!("{key}.elements"), raw.elements)?;
    let mesh = Mesh::uniform(raw.length, elements).map_err(|e| fail(e.to_string()))?;
    let total: f64 = layers.iter().map(|l| l.0).sum();
    if (total - raw.length).abs() > 1e-12 * raw.length {
        return Err(fail(format!(
            "the layers' thicknesses sum to {total}, not the length {}",
            raw.length
        )));
    }
    // Every interface on a node, so that each element is one material.
    let h = raw.length / elements as f64;
    let mut x = 0.0;
    for &(thickness, ..) in &layers[..layers.len() - 1] {
        x += thickness;
        if ((x / h).round() * h - x).abs() > 1e-9 * h {
            return Err(fail(format!(
                "the layer interface at x = {x} is not a node of the {elements}-element mesh (h = {h})"
            )));
        }
    }
    let bar = if layers.len() == 1 {
        Bar::homogeneous(mesh, layers[0].1, layers[0].2, area)
    } else {
        let (mut modulus, mut density) = (Vec::new(), Vec::new());
        for e in 0..elements {
            let mid = (e as f64 + 0.5) * h;
            let mut end = 0.0;
            let found = layers.iter().find(|l| {
                end += l.0;
                mid < end
            });
            let &(_, m, rho) = found.unwrap_or(&layers[layers.len() - 1]);
            modulus.push(m);
            density.push(rho);
        }
        Bar::new(
            mesh,
            &Field::PerElement(modulus),
            &Field::PerElement(density),
            &Field::Constant(area),
        )
    }
    .map_err(|e| fail(e.to_string()))?;
    let impact = layers
        .iter()
        .map(|&(h, e, rho)| ImpactLayer::new(h, e, rho, area))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| fail(e.to_string()))?;
    Ok((bar, impact))
}

/// The exact contact force a contact case is graded against.
#[derive(Debug, Clone, PartialEq)]
pub enum ContactReference {
    /// Homogeneous bars, or a bar onto a rigid wall: the first contact's force staircase
    /// (`ImpactForce`, methods.md §7).
    Homogeneous(ImpactForce),
    /// Layered bars: the exact impact by characteristics, every contact until the end time
    /// (`LayeredImpact`, re-contacts included).
    Layered(LayeredImpact),
}

impl ContactReference {
    /// The force history, through the contract every contact reference honours.
    pub fn history(&self) -> &dyn ContactHistory {
        match self {
            ContactReference::Homogeneous(f) => f,
            ContactReference::Layered(l) => l,
        }
    }
}

/// Transit time of a bar given by its layers.
pub(super) fn transit(layers: &[ImpactLayer]) -> f64 {
    layers.iter().map(ImpactLayer::travel_time).sum()
}

/// A homogeneous bar's impact data (one layer).
pub(super) fn homogeneous(layers: &[ImpactLayer]) -> Option<ImpactBar> {
    match layers {
        [l] => ImpactBar::from_material(l.modulus(), l.density(), l.area(), l.thickness()).ok(),
        _ => None,
    }
}
