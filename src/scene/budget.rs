//! What a scene may ask for, checked when it is validated, before anything big is allocated or
//! anything runs: its size, the work of validating it, the work of running it (time stepping,
//! contact, dispersion and stability sweeps alike, summed over the whole scene, so that a study
//! of many cases is bounded as a whole), the memory of its outputs, and the work of its
//! reference.
//!
//! | limit | value | why |
//! |---|---|---|
//! | elements of one bar | [`MAX_ELEMENTS`] | a lumped model of 5x10^5 elements takes ~75 MB and 0.25 s to validate (measured); more could not run one transit within the node-step cap |
//! | cases of a scene | [`MAX_CASES`] | each case holds its model and writes its files |
//! | elements validated | [`MAX_VALIDATED_ELEMENTS`] | summed over the cases (a matrix mass counts [`MATRIX_MASS_WEIGHT`] times, a contact case [`CONTACT_WEIGHT`] times): each case's exact critical step is a Sturm bisection over its mesh |
//! | node-steps | [`MAX_NODE_STEPS`] | summed over the cases: about 4 minutes for lumped central difference (2.5 ns per node-step), up to about 12 for Noh-Bathe with matrix masses (~7 ns) |
//! | output values | [`MAX_OUTPUT_VALUES`] | numbers recorded and written (profiles, histories, energy logs, force histories), ~30 bytes each in memory as records and CSV text |
//! | reference work | [`MAX_REFERENCE_WORK`] | lattice nodes of the graded reference's characteristics (~7 ns each, measured; an upper bound), or tracked waves of the layered one |
//!
//! Every refusal names the key, the line, what the scene asks for, the limit and what to change.
//!
//! Large runs are an explicit opt-in ([`Limits::LARGE`], `courant run --large`): the elements of
//! one bar, the elements validated and the output values are raised so that a bar of up to
//! 10^7 elements (the solver's own mesh cap, `courant_solver::model::MAX_ELEMENTS`) runs with one
//! profile time; the node-step, case and reference limits stay. The defaults ([`Limits::DEFAULT`])
//! are what every other command, the report and the fuzz tests use.
//! What a validated scene asks for is estimated by [`super::work`].

use super::error::{SceneError, Source};
pub use super::limits::{LARGE_ELEMENTS, LARGE_OUTPUT_VALUES, Limits};
use super::mass::parse_mass;
use super::schema::RawScene;
use super::scheme_keys::SchemeKey;
use courant_solver::MassKind;
use std::ops::Range;

/// Largest `steps x elements` a scene may ask for, summed over its cases (and for each case):
/// about 4 minutes at 2.5 ns per node-step (lumped central difference; up to about 12 for
/// Noh-Bathe with matrix masses, ~7 ns). Sturm passes of a stability sweep count as
/// node-steps.
pub const MAX_NODE_STEPS: f64 = 1e11;
/// Most elements of one bar (a mesh of a time-stepping, spectrum or dispersion scene, a contact
/// striker or target).
pub const MAX_ELEMENTS: i64 = Limits::DEFAULT.elements;
/// Most cases of one scene.
pub const MAX_CASES: usize = 10_000;
/// Most elements validated per scene, summed over its cases with their weights: validation of
/// 10^6 lumped elements took 0.47 to 0.9 s here (release build, idle to loaded machine), of 10^6
/// consistent-mass elements 2.9 s; at this limit a scene validates in about a quarter of a
/// second.
pub const MAX_VALIDATED_ELEMENTS: f64 = Limits::DEFAULT.validated_elements;
/// Validation weight of a case with a consistent, averaged or reciprocal mass: its exact
/// critical step is a banded Sturm bisection, measured 6 times the lumped one.
pub const MATRIX_MASS_WEIGHT: f64 = 6.0;
/// Validation weight of a contact case: two pencils (contact-free and contact-active) bisected.
pub const CONTACT_WEIGHT: f64 = 2.0;
/// Most numbers a scene records and writes (profiles x elements x 6 columns, history samples x
/// nodes x 8, energy samples x 10, contact samples x 12).
pub const MAX_OUTPUT_VALUES: f64 = Limits::DEFAULT.output_values;
/// Most work of a scene's reference, in lattice nodes of the graded bar's characteristics
/// (`courant_references::graded`, ~7 ns each measured). The estimate is an upper bound: for the
/// Fig. 2 bar with modulus ratios 256 and 1000 it was 6.5 and 3 times the work done (15 s and
/// 214 s measured here), so a scene within the limit needs at most about 2.5 minutes.
pub const MAX_REFERENCE_WORK: f64 = 2e10;

/// Boundary events the exact layered impact of a contact scene may track at validation
/// (`LayeredImpact::with_cap`; one event is one boundary's arrivals at one instant): layers
/// whose travel times share no small common step multiply the instants (its module
/// documentation), and validation must stay under a second (an unoptimised build tracks about
/// 1e6 events a second). The built-in scenes need at most 79 469 (impact_layered_stability).
pub const MAX_LAYERED_IMPACT_EVENTS: usize = 100_000;
/// Work of one tracked wave of the layered reference in lattice-node equivalents (defined with
/// the reference, whose contract counts its work).
pub use courant_references::exact::LAYERED_WAVE_WORK;
/// Sturm passes over the nodes per point of a contact stability sweep: two pencils, each with at
/// most 64 doublings and ~64 halvings in practice. Counted as node-steps.
pub const SWEEP_PASSES_PER_POINT: f64 = 256.0;

/// A span and a key an error names.
pub type Blame<'a> = (Option<Range<usize>>, &'a str);

/// The error at `blame`.
pub fn refuse(src: &Source, blame: &Blame, message: String) -> SceneError {
    src.error(blame.0.clone(), blame.1, message)
}

/// An element count within `1 ..= ` the limits' elements ([`MAX_ELEMENTS`] by default).
pub fn element_count(
    src: &Source,
    span: Option<Range<usize>>,
    key: &str,
    n: i64,
) -> Result<usize, SceneError> {
    let limits = src.limits;
    if (1..=limits.elements).contains(&n) {
        Ok(n as usize)
    } else {
        let hint = if n > limits.elements {
            limits.hint()
        } else {
            ""
        };
        Err(src.error(
            span,
            key,
            format!(
                "{n} must lie in 1..={} (elements of one bar){hint}",
                limits.elements
            ),
        ))
    }
}

/// Before the cases of a time-stepping scene are built (each one a Sturm bisection over its
/// mesh): at most [`MAX_CASES`] cases and [`MAX_VALIDATED_ELEMENTS`] weighted elements. A
/// scheme parameter given as a list multiplies the cases by its length (counted for every
/// scheme: an upper bound where only some schemes declare it).
pub fn time_stepping_validation(
    src: &Source,
    raw: &RawScene,
    element_counts: &[usize],
    scheme_keys: &[SchemeKey],
) -> Result<(), SceneError> {
    let Some(integrator) = &raw.integrator else {
        return Ok(());
    };
    let Some(values) = integrator.courant.as_ref().or(integrator.dt.as_ref()) else {
        return Ok(());
    };
    let schemes = integrator
        .scheme
        .as_ref()
        .map_or(1, |s| s.get_ref().values().len());
    let weights: Vec<f64> = integrator.mass.as_ref().map_or(vec![1.0], |m| {
        m.get_ref()
            .values()
            .iter()
            .map(|label| match parse_mass(label) {
                Ok(MassKind::Lumped) => 1.0,
                _ => MATRIX_MASS_WEIGHT,
            })
            .collect()
    });
    let sweeps: usize = scheme_keys
        .iter()
        .filter(|k| k.listed)
        .fold(1usize, |n, k| n.saturating_mul(k.values.len()));
    let per_mesh = (values.get_ref().values().len() * schemes).saturating_mul(sweeps);
    let cases = (element_counts.len() * weights.len()).saturating_mul(per_mesh);
    let weighted: f64 = element_counts.iter().map(|&n| n as f64).sum::<f64>()
        * per_mesh as f64
        * weights.iter().sum::<f64>();
    validation(
        src,
        &(Some(values.span()), key_of(integrator.courant.is_some())),
        cases,
        weighted,
    )
}

fn key_of(courant: bool) -> &'static str {
    if courant {
        "integrator.courant"
    } else {
        "integrator.dt"
    }
}

/// At most [`MAX_CASES`] cases and the limits' weighted elements to validate
/// ([`MAX_VALIDATED_ELEMENTS`] by default).
pub fn validation(
    src: &Source,
    blame: &Blame,
    cases: usize,
    weighted_elements: f64,
) -> Result<(), SceneError> {
    if cases > MAX_CASES {
        return Err(refuse(
            src,
            blame,
            format!(
                "the scene would have {cases} cases, more than the {MAX_CASES} a scene may have"
            ),
        ));
    }
    let limits = src.limits;
    if weighted_elements > limits.validated_elements {
        return Err(refuse(
            src,
            blame,
            format!(
                "the scene's {cases} cases hold {weighted_elements:.3e} elements to validate (each case's exact critical step is a \
                 Sturm bisection over its mesh; a consistent, averaged or reciprocal mass counts {MATRIX_MASS_WEIGHT} times, a \
                 contact case {CONTACT_WEIGHT} times), more than the {:e} a scene may hold; use fewer \
                 cases or coarser meshes{}",
                limits.validated_elements,
                limits.hint()
            ),
        ));
    }
    Ok(())
}
