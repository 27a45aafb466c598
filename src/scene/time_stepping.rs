//! The cases of a time-stepping scene: every element count x scheme x mass kind x Courant
//! number (or step), each with its plan, output request, critical step and reference.

use super::bar::model_of;
use super::cases::Case;
use super::error::{SceneError, Source, collect_all};
use super::expectation::{ExpectContext, Expectation, Study, expectation};
use super::geometry::Geometry;
use super::mass::mass_name;
use super::outputs::Outputs;
use super::reference::Reference;
use super::schema::{RawCourantUnit, RawScene, RawTimeUnit};
use super::scheme_keys::SchemeKey;
use super::stepping::{Stepping, keep_step_plan};
use courant_solver::{CriticalStep, Integration, OutputRequest};
use std::sync::Arc;

/// Samples kept by default for histories and energy logs: every step up to this many steps,
/// then every `ceil(steps / MAX_SAMPLES)`-th step.
pub const MAX_SAMPLES: usize = 10_000;

/// Largest `steps x elements` a scene case (and a whole scene) may ask for.
pub use super::budget::MAX_NODE_STEPS;

/// The cases and expectations of a time-stepping scene.
pub(super) fn build(
    src: &Source,
    raw: &RawScene,
    geometry: &Geometry,
    scheme_keys: &[SchemeKey],
) -> Result<(Vec<Case>, Vec<Expectation>), SceneError> {
    let Some(integrator) = &raw.integrator else {
        return Err(src.error(
            None,
            "integrator",
            "is required: give [integrator] with `courant` or `dt`",
        ));
    };
    let stepping = Stepping::read(src, integrator, scheme_keys)?;
    let transit = geometry.transit_time();
    let outputs = Outputs::read(src, &raw.output, transit)?;

    let mut cases = Vec::new();
    for &elements in &geometry.element_counts {
        let model = Arc::new(model_of(src, raw, geometry, elements)?);
        let reference = match &raw.reference.kind {
            None => None,
            Some(kind) => Reference::for_model(*kind.get_ref(), &model, &geometry.material)
                .map_err(|m| src.error(Some(kind.span()), "reference.kind", m))?,
        };
        let history_nodes = outputs.history_nodes(src, &model)?;
        let (stiffest, element_dt) = model.bar().stiffest_element();
        for (named, &mass) in stepping
            .schemes
            .iter()
            .flat_map(|s| stepping.masses.iter().map(move |m| (s, m)))
        {
            // The mass's critical steps (a Sturm bisection over the whole bar), computed once per
            // (scheme, mass) and given to every case's check and run.
            let mut critical_of_mass: Option<CriticalStep> = None;
            // The scheme's own limit on this mesh, when the Courant numbers are multiples of it.
            let exact_limit = match (stepping.by_courant, stepping.unit) {
                (true, RawCourantUnit::Exact) => {
                    let operator =
                        courant_solver::MassOperator::new(&model, mass).map_err(|e| {
                            src.error(Some(stepping.span.clone()), stepping.key, e.to_string())
                        })?;
                    let critical = CriticalStep::of(&model, mass, &operator).map_err(|e| {
                        src.error(Some(stepping.span.clone()), stepping.key, e.to_string())
                    })?;
                    critical_of_mass = Some(critical);
                    Some(named.scheme.limit(&model, &critical).dt())
                }
                _ => None,
            };
            for &value in &stepping.values {
                let mut case_name = String::new();
                if geometry.element_counts.len() > 1 {
                    case_name += &format!("n{elements}-");
                }
                if !named.prefix.is_empty() {
                    case_name += &format!("{}-", named.prefix);
                }
                if stepping.masses.len() > 1 {
                    case_name += &format!("{}-", mass_name(mass));
                }
                if stepping.by_courant {
                    case_name += &format!("co{}", super::names::number(value));
                } else {
                    case_name += &format!("dt{}", super::names::number(value));
                }
                let fail = |msg: String| {
                    src.error(
                        Some(stepping.span.clone()),
                        stepping.key,
                        format!("case {case_name}: {msg}"),
                    )
                };
                let nominal_dt = match (stepping.by_courant, stepping.unit) {
                    (false, _) => value,
                    (true, RawCourantUnit::StiffestElement) => value * element_dt,
                    (true, RawCourantUnit::Critical) => {
                        value * mass.critical_courant() * element_dt
                    }
                    (true, RawCourantUnit::Exact) => value * exact_limit.unwrap_or(f64::NAN),
                };
                let plan = if stepping.keep_step {
                    keep_step_plan(
                        src,
                        &outputs,
                        nominal_dt,
                        &case_name,
                        (stepping.span.clone(), stepping.key),
                    )?
                } else {
                    courant_solver::plan(nominal_dt, &outputs.profile_times, outputs.end_time)
                        .map_err(|e| fail(e.to_string()))?
                };
                let integrator = Integration {
                    dt: plan.dt,
                    mass,
                    start: stepping.start,
                    stability: stepping.stability,
                    scheme: named.scheme.clone(),
                    threads: None,
                };
                let checked = match critical_of_mass {
                    Some(critical) => integrator.check_stability_given(&model, critical),
                    None => integrator.check_stability(&model),
                };
                let critical = checked.map_err(|e| match &e {
                    courant_solver::RunError::Unstable(u) => {
                        let asked = if stepping.by_courant {
                            format!("courant = {value}")
                        } else {
                            format!("dt = {value:e}")
                        };
                        let became = if plan.dt == nominal_dt {
                            String::new()
                        } else {
                            format!(
                                "; shrunk to hit the output times, the step is dt = {:.6e}",
                                plan.dt
                            )
                        };
                        fail(format!(
                            "asked {asked}{became}: Courant number {:.6} (stiffest element {stiffest}, h/c = {element_dt:.6e}) \
                             is above the critical {:.6} of {} with {} (dt_crit = {:.6e}, {}); lower it or set allow_unstable = true",
                            u.courant,
                            u.dt_crit / element_dt,
                            mass.label(),
                            named.scheme.label(),
                            u.dt_crit,
                            u.limit
                        ))
                    }
                    _ => fail(e.to_string()),
                })?;
                critical_of_mass = Some(critical);
                let node_steps = plan.steps as f64 * model.bar().element_count() as f64;
                if node_steps > MAX_NODE_STEPS {
                    return Err(fail(format!(
                        "{} steps x {} elements = {node_steps:.2e} node-steps, more than the {MAX_NODE_STEPS:.0e} a scene \
                         may ask for; coarsen the mesh, raise the step or shorten the run",
                        plan.steps,
                        model.bar().element_count()
                    )));
                }
                let thinned = plan.steps.div_ceil(MAX_SAMPLES).max(1);
                let request = OutputRequest {
                    profile_steps: plan.output_steps.clone(),
                    history_nodes: history_nodes.clone(),
                    history_every: outputs.history_every.unwrap_or(thinned),
                    energy_every: outputs.energy_every.unwrap_or(thinned),
                };
                let limit = integrator.limit(&model, &critical);
                cases.push(Case {
                    name: case_name,
                    model: Arc::clone(&model),
                    integrator,
                    plan,
                    request,
                    critical,
                    limit,
                    reference: reference.clone(),
                    transit_time: transit,
                    swept: named.swept.clone(),
                    parameters: named.parameters.clone(),
                    times_in_transits: raw.output.time_unit == RawTimeUnit::Transit,
                });
            }
        }
    }
    let mut seen = std::collections::HashSet::new();
    if let Some(dup) = cases.iter().find(|c| !seen.insert(c.name.clone())) {
        return Err(src.error(
            Some(stepping.span.clone()),
            stepping.key,
            format!("case {} appears twice", dup.name),
        ));
    }
    let has_reference = cases.iter().any(|c| c.reference.is_some());
    let names: Vec<String> = cases.iter().map(|c| c.name.clone()).collect();
    let ctx = ExpectContext {
        names: &names,
        has_reference,
        study: Study::TimeStepping,
        profile_times: &outputs.profile_times,
        unit: outputs.unit,
        masses: &[],
    };
    let expectations = collect_all(raw.expectations.iter().map(|e| expectation(src, e, &ctx)))?;
    Ok((cases, expectations))
}
