//! Dispersion scenes: single-mode runs of central difference with each mass kind against the
//! fully discrete dispersion relation (methods.md §5).

use super::budget;
use super::error::{SceneError, Source};
use super::geometry::Geometry;
use super::mass::{mass_name, parse_mass};
use super::schema::RawDispersion;
use courant_references::spectra as closed;
use courant_solver::MassKind;

/// One dispersion case: a mass kind at a Courant number, over a list of modes.
#[derive(Debug, Clone, PartialEq)]
pub struct DispersionCase {
    /// Case name, e.g. `amm0.5-co0.5` or `amm4th-co0.5`.
    pub name: String,
    /// The mass kind (with the fourth-order beta resolved for `amm(4th)`, `rmm(4th)`).
    pub mass: MassKind,
    /// Whether beta was chosen for fourth order at this Courant number.
    pub fourth_order: bool,
    /// Courant number `c dt/h`.
    pub courant: f64,
    /// Elements of the free-free unit bar.
    pub elements: usize,
    /// Mode numbers.
    pub modes: Vec<usize>,
}

pub(super) fn build(
    src: &Source,
    study: &RawDispersion,
    geometry: &Geometry,
) -> Result<Vec<DispersionCase>, SceneError> {
    let fail =
        |span: std::ops::Range<usize>, key: &str, msg: String| src.error(Some(span), key, msg);
    let &[elements] = geometry.element_counts.as_slice() else {
        return Err(src.error(
            None,
            "mesh.elements",
            "a dispersion scene takes one element count",
        ));
    };
    if !(geometry.grading == 1.0 && !geometry.equal_transit && geometry.material.is_homogeneous()) {
        return Err(src.error(
            None,
            "mesh",
            "a dispersion scene needs a uniform homogeneous bar (single modes exist only there)",
        ));
    }
    let modes: Vec<usize> = study
        .modes
        .get_ref()
        .values()
        .iter()
        .map(|&n| {
            if n >= 1 && (n as usize) < elements {
                Ok(n as usize)
            } else {
                Err(fail(
                    study.modes.span(),
                    "dispersion.modes",
                    format!("{n} must lie in 1..{elements} (kh = n pi/N below pi)"),
                ))
            }
        })
        .collect::<Result<_, _>>()?;
    let courants = study.courant.get_ref().values();
    if let Some(bad) = courants.iter().find(|c| !(c.is_finite() && **c > 0.0)) {
        return Err(fail(
            study.courant.span(),
            "dispersion.courant",
            format!("{bad} must be positive and finite"),
        ));
    }
    budget::validation(
        src,
        &(Some(study.masses.span()), "dispersion.masses"),
        study.masses.get_ref().values().len() * courants.len(),
        0.0,
    )?;
    let mut cases = Vec::new();
    for raw_label in study.masses.get_ref().values() {
        let label = raw_label.trim();
        for &co in &courants {
            let (mass, fourth_order) = match label {
                "amm(4th)" | "rmm(4th)" => {
                    let beta = if label.starts_with("amm") {
                        closed::fourth_order_beta_averaged(co)
                    } else {
                        closed::fourth_order_beta_reciprocal(co)
                    }
                    .map_err(|e| {
                        fail(
                            study.courant.span(),
                            "dispersion.courant",
                            format!("{label} at Co = {co}: {e}"),
                        )
                    })?;
                    let kind = if label.starts_with("amm") {
                        MassKind::Averaged { beta }
                    } else {
                        MassKind::Reciprocal { beta }
                    };
                    (kind, true)
                }
                other => (
                    parse_mass(other)
                        .map_err(|m| fail(study.masses.span(), "dispersion.masses", m))?,
                    false,
                ),
            };
            if co > mass.critical_courant() {
                return Err(fail(
                    study.courant.span(),
                    "dispersion.courant",
                    format!(
                        "Co = {co} is above the critical Courant number {:.6} of {}",
                        mass.critical_courant(),
                        mass.label()
                    ),
                ));
            }
            let prefix = if fourth_order {
                format!("{}4th", &label[..3])
            } else {
                mass_name(mass)
            };
            cases.push(DispersionCase {
                name: format!("{prefix}-co{}", super::names::number(co)),
                mass,
                fourth_order,
                courant: co,
                elements,
                modes: modes.clone(),
            });
        }
    }
    Ok(cases)
}
