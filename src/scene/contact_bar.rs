//! The bars of a contact scene: homogeneous, layered or graded, as the solver's `Bar` and as the
//! layers of the exact references, and the contact force a case is graded against
//! ([`ContactReference`]).
//!
//! A graded bar (`modulus = { linear = [left, right] }`, constant density) is the time-stepping
//! bar's linear field (`scene::geometry::raw_field`; each element takes the modulus at its
//! midpoint, methods.md §1). No exact impact of a continuously graded bar is known: its
//! reference layers are the equal-travel-time (Goupillaud) layering of the graded bar into
//! [`GRADED_REFERENCE_LAYERS`] layers (`courant_references::graded::LayeredBar::
//! equal_transit_layers`, methods.md §4; `[contact] reference_layers` sets K), whose impact
//! `LayeredImpact` tracks exactly: the
//! reference is exact for that layered bar, not for the graded one, and converges to it at first
//! order in `1/K` (test `impact_graded_reference`). Equal travel times keep the layered impact's
//! arrivals on a lattice, so its events stay `O(K^2)` per transit.

use super::budget;
use super::error::{SceneError, Source};
use super::geometry::raw_field;
use super::magnitude;
use super::schema::{RawContact, RawContactBar, RawField};
use courant_references::ContactHistory;
use courant_references::contact::{ImpactBar, ImpactForce, ImpactLayer, LayeredImpact};
use courant_references::graded::{GradedBar, LayeredBar};
use courant_solver::{Bar, Field, Mesh};
use toml::Spanned;

/// Layers of the equal-travel-time layering that stands in for a graded contact bar in its
/// reference by default (module documentation). At `K = 64` the layering's own error, measured
/// against `K = 128`, is far below the meshes' (test `impact_graded_reference`).
pub const GRADED_REFERENCE_LAYERS: usize = 64;

/// Most reference layers a scene may ask for: the layered impact's events grow like `K^2` per
/// transit (module documentation).
pub const MAX_REFERENCE_LAYERS: i64 = 1024;

/// `[contact] reference_layers`: the layers of a graded bar's reference, 1 to
/// [`MAX_REFERENCE_LAYERS`] (default [`GRADED_REFERENCE_LAYERS`]).
pub(super) fn reference_layers(src: &Source, study: &RawContact) -> Result<usize, SceneError> {
    match &study.reference_layers {
        None => Ok(GRADED_REFERENCE_LAYERS),
        Some(k) if (1..=MAX_REFERENCE_LAYERS).contains(k.get_ref()) => Ok(*k.get_ref() as usize),
        Some(k) => Err(src.error(
            Some(k.span()),
            "contact.reference_layers",
            format!(
                "reference_layers = {} must be a whole number from 1 to {MAX_REFERENCE_LAYERS} \
                 (the layers of a graded bar's equal-travel-time reference)",
                k.get_ref()
            ),
        )),
    }
}

/// The material of a contact bar's `modulus`/`density` keys: homogeneous `(E, rho)` or a linear
/// modulus `[left, right]` with a constant density.
enum Stated {
    Homogeneous(f64, f64),
    Graded([f64; 2], f64),
}

/// What `modulus` and `density` state, checked: every value positive and finite and within the
/// magnitude bounds, a graded bar's density constant.
fn stated(src: &Source, spanned: &Spanned<RawContactBar>, key: &str) -> Result<Stated, SceneError> {
    let raw = spanned.get_ref();
    let span = Some(spanned.span());
    let ends = |name: &str, f: &Option<RawField>| -> Result<[f64; 2], SceneError> {
        let ends = match f.as_ref().map(raw_field) {
            None => [1.0, 1.0],
            Some(Field::Linear { left, right }) => [left, right],
            Some(Field::Constant(c)) => [c, c],
            Some(Field::PerElement(_)) => [f64::NAN, f64::NAN],
        };
        if let Some(bad) = ends.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
            return Err(src.error(
                span.clone(),
                &format!("{key}.{name}"),
                format!("{name} = {bad} must be positive and finite (along the whole bar)"),
            ));
        }
        magnitude::inputs(src, span.clone(), &format!("{key}.{name}"), name, ends)?;
        Ok(ends)
    };
    let [e_left, e_right] = ends("modulus", &raw.modulus)?;
    let [rho_left, rho_right] = ends("density", &raw.density)?;
    if rho_left != rho_right {
        return Err(src.error(
            span,
            &format!("{key}.density"),
            format!(
                "density = {{ linear = [{rho_left}, {rho_right}] }}: a contact bar takes a \
                 constant density (a graded contact bar grades its modulus; its reference is the \
                 equal-travel-time layering of a linear modulus at constant density, methods.md §4)"
            ),
        ));
    }
    Ok(if e_left == e_right {
        Stated::Homogeneous(e_left, rho_left)
    } else {
        Stated::Graded([e_left, e_right], rho_left)
    })
}

/// A contact bar as the solver's `Bar` and as the layers of the exact references (one layer for
/// a homogeneous bar).
pub(super) fn bar(
    src: &Source,
    spanned: &Spanned<RawContactBar>,
    key: &str,
    area: f64,
    reference_layers: usize,
) -> Result<(Bar, Vec<ImpactLayer>), SceneError> {
    let raw = spanned.get_ref();
    let span = Some(spanned.span());
    let fail = |msg: String| src.error(span.clone(), key, msg);
    let (layers, graded): (Vec<(f64, f64, f64)>, _) = match &raw.layers {
        None => match stated(src, spanned, key)? {
            Stated::Homogeneous(e, rho) => (vec![(raw.length, e, rho)], None),
            Stated::Graded(e, rho) => (vec![(raw.length, e[0], rho)], Some((e, rho))),
        },
        Some(_) if raw.modulus.is_some() || raw.density.is_some() => {
            return Err(fail(
                "give either `layers` or `modulus`/`density`, not both".into(),
            ));
        }
        Some(list) if list.is_empty() => {
            return Err(fail("`layers` is empty; give at least one layer".into()));
        }
        Some(list) => (
            list.iter()
                .map(|l| (l.thickness, l.modulus, l.density.unwrap_or(1.0)))
                .collect(),
            None,
        ),
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
    if let Some(([left, right], rho)) = graded {
        return graded_bar(mesh, raw.length, [left, right], rho, area, reference_layers)
            .map_err(fail);
    }
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

/// A graded contact bar: the solver's bar with the linear modulus sampled at element midpoints
/// and constant density, and the reference layers, the equal-travel-time layering of the same
/// graded bar into `layers` layers (module documentation).
fn graded_bar(
    mesh: Mesh,
    length: f64,
    [left, right]: [f64; 2],
    density: f64,
    area: f64,
    layers: usize,
) -> Result<(Bar, Vec<ImpactLayer>), String> {
    let bar = Bar::new(
        mesh,
        &Field::Linear { left, right },
        &Field::Constant(density),
        &Field::Constant(area),
    )
    .map_err(|e| e.to_string())?;
    let impact =
        graded_layers(length, [left, right], density, area, layers).map_err(|e| e.to_string())?;
    Ok((bar, impact))
}

/// The equal-travel-time layering of a bar of modulus linear from `left` (its `x = 0`) to
/// `right` (its `x = length`), constant density, into `layers` layers as impact layers
/// (`LayeredBar::equal_transit_layers`, methods.md §4): the layers a graded contact bar's
/// reference is computed on.
///
/// # Errors
/// A value the references refuse (not positive and finite, no layer).
pub fn graded_layers(
    length: f64,
    [left, right]: [f64; 2],
    density: f64,
    area: f64,
    layers: usize,
) -> Result<Vec<ImpactLayer>, courant_references::ReferenceError> {
    let graded = GradedBar::new(length, left, right, density, area, 0.0)?;
    LayeredBar::equal_transit_layers(&graded, layers)?
        .layers()
        .iter()
        .map(|l| ImpactLayer::new(l.thickness(), l.modulus(), l.density(), area))
        .collect()
}

/// The contact force a contact case is graded against.
#[derive(Debug, Clone, PartialEq)]
pub enum ContactReference {
    /// Homogeneous bars, or a bar onto a rigid wall: the first contact's force staircase
    /// (`ImpactForce`, methods.md §7).
    Homogeneous(ImpactForce),
    /// Layered bars: the exact impact by characteristics, every contact until the end time
    /// (`LayeredImpact`, re-contacts included). A graded bar enters as its equal-travel-time
    /// layering (module documentation): exact for that layering, not for the graded bar.
    Layered(LayeredImpact),
    /// A graded bar (or two): the exact impact of their equal-travel-time layering into
    /// `layers` layers each, exact for that layering, not for the graded bars.
    GradedLayering {
        /// The layered impact.
        impact: LayeredImpact,
        /// Layers per graded bar.
        layers: usize,
    },
}

impl ContactReference {
    /// The force history, through the contract every contact reference honours.
    pub fn history(&self) -> &dyn ContactHistory {
        match self {
            ContactReference::Homogeneous(f) => f,
            ContactReference::Layered(l) | ContactReference::GradedLayering { impact: l, .. } => l,
        }
    }

    /// The reference's name in a figure's legend: what it is, not more.
    pub fn label(&self) -> String {
        match self {
            ContactReference::Homogeneous(_) | ContactReference::Layered(_) => {
                "1D wave theory".into()
            }
            ContactReference::GradedLayering { layers, .. } => {
                format!("exact impact of the {layers}-layer layering (not exact)")
            }
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

#[cfg(test)]
mod tests {
    use crate::scene::cases::Scene;

    fn scene(striker: &str) -> String {
        format!(
            "[scene]\ndescription = \"d\"\nsource = \"s\"\n\n[contact]\nproblem = \"two-bars\"\n\
             striker = {{ length = 1.0, elements = 8, {striker} }}\n\
             target = {{ length = 1.0, elements = 8 }}\n\
             velocity = 1.0\nschemes = \"lagrange-multiplier\"\ncourant = 0.5\nend_time = 1.0\n"
        )
    }

    /// Source of truth: the scene rules (README, "Scene files": an error names its key, the value
    /// and the rule) and the graded contact bar's rules (module documentation). Proves: a
    /// graded density, a modulus that is not positive at an end, and `layers` beside a graded
    /// modulus are refused at the bar's own key with the value and the rule; a graded modulus
    /// parses into a bar with the midpoint samples of the linear field and a reference layered
    /// into `GRADED_REFERENCE_LAYERS` equal-travel-time layers.
    #[test]
    fn graded_contact_bars_are_checked_and_sampled_at_midpoints() {
        let e = Scene::parse(
            "t",
            "t.toml",
            &scene("modulus = { linear = [1.0, 4.0] }, density = { linear = [1.0, 2.0] }"),
        )
        .unwrap_err();
        assert_eq!(e.key, "contact.striker.density", "{e}");
        assert!(
            e.message.contains("linear = [1, 2]") && e.message.contains("constant density"),
            "{e}"
        );
        let e =
            Scene::parse("t", "t.toml", &scene("modulus = { linear = [1.0, -2.0] }")).unwrap_err();
        assert_eq!(e.key, "contact.striker.modulus", "{e}");
        assert!(
            e.message.contains("-2") && e.message.contains("positive and finite"),
            "{e}"
        );
        let both = scene(
            "modulus = { linear = [1.0, 4.0] }, layers = [{ thickness = 1.0, modulus = 1.0 }]",
        );
        let e = Scene::parse("t", "t.toml", &both).unwrap_err();
        assert_eq!(e.key, "contact.striker", "{e}");
        assert!(e.message.contains("not both"), "{e}");
        let graded = scene("modulus = { linear = [1.0, 9.0] }");
        let e =
            Scene::parse("t", "t.toml", &format!("{graded}reference_layers = 0\n")).unwrap_err();
        assert_eq!(e.key, "contact.reference_layers", "{e}");
        assert!(
            e.message.contains("= 0 must be a whole number from 1"),
            "{e}"
        );
        let ok = Scene::parse("t", "t.toml", &graded).unwrap();
        let bar = ok.contact[0].problem.bodies()[0].bar();
        let first = bar.modulus()[0];
        assert!((first - (1.0 + 8.0 * 0.5 / 8.0)).abs() < 1e-12, "{first}");
        match &ok.contact[0].reference {
            super::ContactReference::GradedLayering { impact: l, .. } => {
                assert_eq!(l.layers().len(), super::GRADED_REFERENCE_LAYERS + 1);
            }
            other => panic!("{other:?}"),
        }
    }
}
