//! Spectrum scenes: the discrete frequencies of a bar for several mass kinds and end conditions
//! (the seed's Fig. 6), beside the continuum and the closed-form discrete spectra.

use super::bar::bar_of;
use super::budget;
use super::error::{SceneError, Source};
use super::geometry::Geometry;
use super::mass::parse_mass;
use super::schema::{RawScene, RawSpectrum};
use courant_references::spectra::{BarEnds, UniformBar};
use courant_solver::{MassKind, MassOperator, Model, Support, Supports};

/// One spectrum case: an end condition and a mesh.
#[derive(Debug, Clone)]
pub struct SpectrumCase {
    /// Case name, e.g. `free-free-n20`.
    pub name: String,
    /// The bar (unloaded).
    pub model: Model,
    /// Mass kinds compared.
    pub masses: Vec<MassKind>,
    /// Closed forms of the uniform homogeneous bar, when the scene's bar is one.
    pub closed_form: Option<UniformBar>,
}

pub(super) fn build(
    src: &Source,
    raw: &RawScene,
    spectrum: &RawSpectrum,
    geometry: &Geometry,
) -> Result<Vec<SpectrumCase>, SceneError> {
    let fail =
        |span: std::ops::Range<usize>, key: &str, msg: String| src.error(Some(span), key, msg);
    let masses = spectrum
        .masses
        .get_ref()
        .values()
        .iter()
        .map(|l| parse_mass(l).map_err(|m| fail(spectrum.masses.span(), "spectrum.masses", m)))
        .collect::<Result<Vec<_>, _>>()?;
    if masses.is_empty() {
        return Err(fail(
            spectrum.masses.span(),
            "spectrum.masses",
            "the list is empty".into(),
        ));
    }
    let ends = spectrum.ends.get_ref().values();
    if ends.is_empty() {
        return Err(fail(
            spectrum.ends.span(),
            "spectrum.ends",
            "the list is empty".into(),
        ));
    }
    let uniform =
        geometry.grading == 1.0 && !geometry.equal_transit && geometry.material.is_homogeneous();
    budget::validation(
        src,
        &(Some(spectrum.ends.span()), "spectrum.ends"),
        ends.len() * geometry.element_counts.len(),
        0.0,
    )?;
    let mut cases = Vec::new();
    for end in &ends {
        let (supports, closed_ends) = match end.as_str() {
            "free-free" => (
                Supports {
                    left: Support::Free,
                    right: Support::Free,
                },
                Some(BarEnds::FreeFree),
            ),
            "fixed-free" => (
                Supports {
                    left: Support::Fixed,
                    right: Support::Free,
                },
                Some(BarEnds::FixedFree),
            ),
            "fixed-fixed" => (
                Supports {
                    left: Support::Fixed,
                    right: Support::Fixed,
                },
                None,
            ),
            other => {
                return Err(fail(
                    spectrum.ends.span(),
                    "spectrum.ends",
                    format!("\"{other}\" is not one of free-free, fixed-free, fixed-fixed"),
                ));
            }
        };
        for &elements in &geometry.element_counts {
            let bar = bar_of(src, raw, geometry, elements)?;
            if bar.node_count() > courant_solver::analysis::MAX_DENSE_NODES {
                return Err(fail(
                    raw.mesh.elements.span(),
                    "mesh.elements",
                    format!(
                        "{elements} elements: a dense spectrum is limited to {} nodes",
                        courant_solver::analysis::MAX_DENSE_NODES
                    ),
                ));
            }
            let closed_form = match (uniform, closed_ends) {
                (true, Some(ends)) => {
                    let c = bar.wave_speed(0);
                    UniformBar::new(geometry.length, c, elements, ends).ok()
                }
                _ => None,
            };
            if bar.node_count() < 3
                && supports.left == Support::Fixed
                && supports.right == Support::Fixed
            {
                return Err(fail(
                    raw.mesh.elements.span(),
                    "mesh.elements",
                    format!("{end} with {elements} element(s) has no free node"),
                ));
            }
            let model = Model::unloaded(bar, supports);
            // The mass matrices the spectra need, built now: a failure names its place here,
            // not after the other cases have run.
            for &kind in &masses {
                MassOperator::new(&model, kind).map_err(|e| {
                    fail(
                        spectrum.masses.span(),
                        "spectrum.masses",
                        format!("{end} with {elements} elements: {e}"),
                    )
                })?;
            }
            cases.push(SpectrumCase {
                name: format!("{end}-n{elements}"),
                model,
                masses: masses.clone(),
                closed_form,
            });
        }
    }
    Ok(cases)
}
