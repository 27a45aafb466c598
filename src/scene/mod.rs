//! Scenes: declarative cases read from TOML, validated into ready-to-run [`Case`]s.
//!
//! A scene states only what its case needs; everything else has the default documented in
//! [`schema`]. A list of Courant numbers (or time steps) expands into one case each. Validation
//! happens here, before anything runs: a scene that parses is a scene that can run.

pub mod contact;
pub mod dispersion;
pub mod error;
pub mod schema;
pub mod spectrum;

use crate::reference::Reference;
use courant_solver::{
    Bar, CentralDifference, CriticalStep, End, Field, InitialConditions, InputError, Load,
    MassKind, Mesh, Model, OutputRequest, ParkOptions, ParkVariant, SchemeLimit, StabilityPolicy,
    Start, Support, Supports, TimeFunction, TimePlan,
};
pub use error::{SceneError, Source};
use schema::*;
use std::ops::Range;
use toml::Spanned;

/// Samples kept by default for histories and energy logs: every step up to this many steps,
/// then every `ceil(steps / MAX_SAMPLES)`-th step.
pub const MAX_SAMPLES: usize = 10_000;

/// Largest `steps x elements` a scene case may ask for (about 4 minutes at 2.5 ns per node-step).
pub const MAX_NODE_STEPS: f64 = 1e11;

/// Parse a mass label: `lmm`/`lumped`, `cmm`/`consistent`, `amm`/`averaged`, `rmm`/`reciprocal`
/// (beta = 1/2), or `amm(beta)`, `rmm(beta)`.
pub fn parse_mass(label: &str) -> Result<MassKind, String> {
    let label = label.trim();
    let (name, beta) = match label.split_once('(') {
        Some((name, rest)) => {
            let inner = rest
                .strip_suffix(')')
                .ok_or_else(|| format!("\"{label}\": a beta is written amm(0.5)"))?;
            let beta: f64 = inner
                .trim()
                .parse()
                .map_err(|_| format!("\"{label}\": beta \"{inner}\" is not a number"))?;
            (name.trim(), Some(beta))
        }
        None => (label, None),
    };
    let kind = match (name, beta) {
        ("lmm" | "lumped", None) => MassKind::Lumped,
        ("cmm" | "consistent", None) => MassKind::Consistent,
        ("amm" | "averaged", b) => MassKind::Averaged {
            beta: b.unwrap_or(0.5),
        },
        ("rmm" | "reciprocal", b) => MassKind::Reciprocal {
            beta: b.unwrap_or(0.5),
        },
        ("lmm" | "lumped" | "cmm" | "consistent", Some(_)) => {
            return Err(format!("\"{label}\": only amm and rmm take a beta"));
        }
        _ => {
            return Err(format!(
                "\"{label}\" is not a mass kind (lmm, cmm, amm, rmm, amm(beta), rmm(beta))"
            ));
        }
    };
    kind.validate().map_err(|e| format!("\"{label}\": {e}"))?;
    Ok(kind)
}

/// File-name friendly mass name: `lmm`, `cmm`, `amm0.5`, `rmm0.5`.
pub fn mass_name(kind: MassKind) -> String {
    match kind {
        MassKind::Lumped => "lmm".into(),
        MassKind::Consistent => "cmm".into(),
        MassKind::Averaged { beta } => format!("amm{beta}"),
        MassKind::Reciprocal { beta } => format!("rmm{beta}"),
    }
}

/// A validated scene.
#[derive(Debug, Clone)]
pub struct Scene {
    /// Name (file stem), used for the output directory.
    pub name: String,
    /// One-line description.
    pub description: String,
    /// Source of truth.
    pub source: String,
    /// The time-stepping cases, in file order.
    pub cases: Vec<Case>,
    /// The spectrum cases (spectrum scenes only).
    pub spectra: Vec<spectrum::SpectrumCase>,
    /// The dispersion cases (dispersion scenes only).
    pub dispersion: Vec<dispersion::DispersionCase>,
    /// The contact cases (contact scenes only).
    pub contact: Vec<contact::ContactCase>,
    /// The contact stability sweeps (contact stability scenes only).
    pub contact_sweeps: Vec<contact::StabilitySweep>,
    /// Expectations every run is checked against.
    pub expectations: Vec<Expectation>,
}

/// One runnable case of a scene.
#[derive(Debug, Clone)]
pub struct Case {
    /// Case name, e.g. `co0.5`.
    pub name: String,
    /// The model.
    pub model: Model,
    /// The integrator with its final time step.
    pub integrator: CentralDifference,
    /// The time-step plan.
    pub plan: TimePlan,
    /// What to record.
    pub request: OutputRequest,
    /// Critical-step estimates of the model.
    pub critical: CriticalStep,
    /// The stability limit of the case's scheme (CD's `2/omega_max` or Park's `alpha_e <= 1`).
    pub limit: SchemeLimit,
    /// Analytic reference, if the scene names one.
    pub reference: Option<Reference>,
    /// Transit time of the bar, `T = sum_e h_e/c_e`.
    pub transit_time: f64,
}

/// A metric an expectation bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Metric {
    /// L1 error of the element stresses, `(1/L) sum_e h_e |sigma_e - sigma_ref,e| / |sigma0|`.
    L1,
    /// L2 error, `sqrt((1/L) sum_e h_e (sigma_e - sigma_ref,e)^2) / |sigma0|`.
    L2,
    /// Max error, `max_e |sigma_e - sigma_ref,e| / |sigma0|`.
    Linf,
    /// Overshoot beyond the exact solution's envelope, as a fraction of the jump |sigma0|.
    Overshoot,
    /// Largest |energy balance error| relative to the energy scale of the run.
    EnergyBalance,
    /// Whether the run diverged.
    Diverged,
    /// Total variation of the profile over the exact one's (1 = no spurious oscillation).
    TvRatio,
    /// Energy the scheme dissipated by the end of the run, relative to the energy scale:
    /// `-(T + U - W)_end / scale` (0 for CD up to round-off; Park dissipates a little).
    EnergyLost,
    /// Spectrum scenes: largest relative deviation of the computed elastic frequencies from the
    /// closed-form discrete spectra (methods.md §5), over every mode and mass kind.
    ClosedFormDeviation,
    /// Dispersion scenes: largest `|measured - closed form|` of the phase-speed ratio.
    DispersionDeviation,
    /// Dispersion scenes: smallest observed order of the phase error between modes `n` and `2n`.
    PhaseErrorOrder,
    /// Contact: largest `|F - F1|/F1` inside the first plateau (10 % to 90 % of it).
    PlateauDeviation,
    /// Contact: `|impulse - exact| / exact`.
    ImpulseError,
    /// Contact: `|duration - exact| / exact` (duration from the half-plateau crossings).
    DurationError,
    /// Contact: L1 norm in time of the force error over the exact impulse.
    ForceL1Error,
    /// Contact: energy of the real masses at the end over the initial energy.
    EnergyRatio,
    /// Contact stability: largest relative deviation of the solver's critical Courant number
    /// from the closed form.
    CourantDeviation,
}

/// The kind of study a scene is; each metric belongs to one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Study {
    /// Time-stepping cases.
    TimeStepping,
    /// Spectra.
    Spectrum,
    /// Single-mode dispersion runs.
    Dispersion,
    /// Contact-impact runs.
    Contact,
    /// Contact stability sweep.
    ContactStability,
}

impl Study {
    /// Name in messages.
    pub fn name(self) -> &'static str {
        match self {
            Study::TimeStepping => "time-stepping",
            Study::Spectrum => "spectrum",
            Study::Dispersion => "dispersion",
            Study::Contact => "contact",
            Study::ContactStability => "contact stability",
        }
    }
}

impl Metric {
    /// Scene-file name.
    pub fn name(self) -> &'static str {
        match self {
            Metric::L1 => "l1",
            Metric::L2 => "l2",
            Metric::Linf => "linf",
            Metric::Overshoot => "overshoot",
            Metric::TvRatio => "tv_ratio",
            Metric::EnergyLost => "energy_lost",
            Metric::EnergyBalance => "energy_balance",
            Metric::Diverged => "diverged",
            Metric::ClosedFormDeviation => "closed_form_deviation",
            Metric::DispersionDeviation => "dispersion_deviation",
            Metric::PhaseErrorOrder => "phase_error_order",
            Metric::PlateauDeviation => "plateau_deviation",
            Metric::ImpulseError => "impulse_error",
            Metric::DurationError => "duration_error",
            Metric::ForceL1Error => "force_l1_error",
            Metric::EnergyRatio => "energy_ratio",
            Metric::CourantDeviation => "courant_deviation",
        }
    }

    fn parse(s: &str) -> Option<Self> {
        [
            Metric::L1,
            Metric::L2,
            Metric::Linf,
            Metric::Overshoot,
            Metric::EnergyBalance,
            Metric::Diverged,
            Metric::TvRatio,
            Metric::EnergyLost,
            Metric::ClosedFormDeviation,
            Metric::DispersionDeviation,
            Metric::PhaseErrorOrder,
            Metric::PlateauDeviation,
            Metric::ImpulseError,
            Metric::DurationError,
            Metric::ForceL1Error,
            Metric::EnergyRatio,
            Metric::CourantDeviation,
        ]
        .into_iter()
        .find(|m| m.name() == s)
    }

    /// The study the metric belongs to.
    pub fn study(self) -> Study {
        match self {
            Metric::ClosedFormDeviation => Study::Spectrum,
            Metric::DispersionDeviation | Metric::PhaseErrorOrder => Study::Dispersion,
            Metric::PlateauDeviation
            | Metric::ImpulseError
            | Metric::DurationError
            | Metric::ForceL1Error
            | Metric::EnergyRatio => Study::Contact,
            Metric::CourantDeviation => Study::ContactStability,
            _ => Study::TimeStepping,
        }
    }

    /// True for metrics measured on profiles (they need a reference).
    pub fn needs_reference(self) -> bool {
        matches!(
            self,
            Metric::L1 | Metric::L2 | Metric::Linf | Metric::Overshoot
        )
    }
}

/// The bound of an expectation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    /// `min <= value <= max` (either side optional).
    Range {
        /// Lower bound.
        min: Option<f64>,
        /// Upper bound.
        max: Option<f64>,
    },
    /// A boolean metric equals this.
    Equals(bool),
}

/// A requirement a case must meet, with its source of truth.
#[derive(Debug, Clone, PartialEq)]
pub struct Expectation {
    /// Cases it applies to.
    pub cases: Vec<String>,
    /// The metric.
    pub metric: Metric,
    /// Profile time (absolute), or `None` for the worst over all profile times.
    pub at: Option<f64>,
    /// The bound.
    pub bound: Bound,
    /// Where the bound comes from.
    pub source: String,
}

impl Scene {
    /// Parse and validate a scene. `file` is the path or name shown in errors; `name` becomes the
    /// output directory.
    pub fn parse(name: &str, file: &str, text: &str) -> Result<Scene, SceneError> {
        let src = Source { file, text };
        let table: toml::Table = toml::from_str(text).map_err(|e| src.from_toml(&e))?;
        if table.contains_key("contact") || table.contains_key("contact_stability") {
            let raw: RawContactScene = toml::from_str(text).map_err(|e| src.from_toml(&e))?;
            return build_contact(name, &src, raw);
        }
        let raw: RawScene = toml::from_str(text).map_err(|e| src.from_toml(&e))?;
        build(name, &src, raw)
    }

    /// Read a scene from a file; its name is the file stem.
    pub fn from_path(path: &std::path::Path) -> Result<Scene, SceneError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| SceneError {
            file: file.clone(),
            line: 0,
            column: 0,
            key: String::new(),
            message: format!("cannot read the file: {e}"),
        })?;
        let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("scene");
        Scene::parse(name, &file, &text)
    }
}

fn build(name: &str, src: &Source, raw: RawScene) -> Result<Scene, SceneError> {
    for (value, key) in [
        (&raw.scene.description, "scene.description"),
        (&raw.scene.source, "scene.source"),
    ] {
        if value.get_ref().trim().is_empty() {
            return Err(src.error(Some(value.span()), key, "must not be empty"));
        }
    }
    let geometry = Geometry::read(src, &raw)?;
    if raw.spectrum.is_some() || raw.dispersion.is_some() {
        let (kind, study) = if raw.spectrum.is_some() {
            ("spectrum", Study::Spectrum)
        } else {
            ("dispersion", Study::Dispersion)
        };
        if raw.integrator.is_some() || (raw.spectrum.is_some() && raw.dispersion.is_some()) {
            return Err(src.error(
                None,
                kind,
                "a spectrum or dispersion scene has no [integrator] and is one study only",
            ));
        }
        let (spectra, dispersion) = match (&raw.spectrum, &raw.dispersion) {
            (Some(s), _) => (spectrum::build(src, &raw, s, &geometry)?, Vec::new()),
            (None, Some(d)) => (Vec::new(), dispersion::build(src, d, &geometry)?),
            (None, None) => (Vec::new(), Vec::new()),
        };
        let names: Vec<String> = spectra
            .iter()
            .map(|c| c.name.clone())
            .chain(dispersion.iter().map(|c| c.name.clone()))
            .collect();
        let mut seen = std::collections::HashSet::new();
        if let Some(dup) = names.iter().find(|n| !seen.insert(*n)) {
            return Err(src.error(None, kind, format!("case {dup} appears twice")));
        }
        let expectations = raw
            .expectations
            .iter()
            .map(|e| expectation(src, e, &names, false, study, &[], 1.0))
            .collect::<Result<Vec<_>, _>>()?;
        return Ok(Scene {
            name: name.to_string(),
            description: raw.scene.description.get_ref().clone(),
            source: raw.scene.source.get_ref().clone(),
            cases: Vec::new(),
            spectra,
            dispersion,
            contact: Vec::new(),
            contact_sweeps: Vec::new(),
            expectations,
        });
    }
    let Some(integrator) = &raw.integrator else {
        return Err(src.error(
            None,
            "integrator",
            "is required: give [integrator] with `courant` or `dt`",
        ));
    };
    let stepping = Stepping::read(src, integrator)?;
    let transit = geometry.transit_time();
    let outputs = Outputs::read(src, &raw.output, transit)?;

    let mut cases = Vec::new();
    for &elements in &geometry.element_counts {
        let model = model_of(src, &raw, &geometry, elements)?;
        let reference = match &raw.reference.kind {
            None => None,
            Some(kind) => Reference::for_model(*kind.get_ref(), &model, &geometry.material)
                .map_err(|m| src.error(Some(kind.span()), "reference.kind", m))?,
        };
        let history_nodes = outputs.history_nodes(src, &model)?;
        let (stiffest, element_dt) = model.bar().stiffest_element();
        for (&(scheme_name, park), &mass) in stepping
            .schemes
            .iter()
            .flat_map(|s| stepping.masses.iter().map(move |m| (s, m)))
        {
            // The scheme's own limit on this mesh, once per (scheme, mass), when the Courant
            // numbers are multiples of it: CD's 2/omega_max (a Sturm bisection), Park's
            // min_e h_e/c_e.
            let exact_limit = match (stepping.by_courant, stepping.unit, park) {
                (true, RawCourantUnit::Exact, Some(_)) => {
                    Some(courant_solver::ParkScheme::limit_step(&model))
                }
                (true, RawCourantUnit::Exact, None) => {
                    let operator =
                        courant_solver::MassOperator::new(&model, mass).map_err(|e| {
                            src.error(Some(stepping.span.clone()), stepping.key, e.to_string())
                        })?;
                    Some(CriticalStep::of(&model, mass, &operator).exact)
                }
                _ => None,
            };
            for &value in &stepping.values {
                let mut case_name = String::new();
                if geometry.element_counts.len() > 1 {
                    case_name += &format!("n{elements}-");
                }
                if stepping.schemes.len() > 1 {
                    case_name += &format!("{scheme_name}-");
                }
                if stepping.masses.len() > 1 {
                    case_name += &format!("{}-", mass_name(mass));
                }
                if stepping.by_courant {
                    case_name += &format!("co{value}");
                } else {
                    case_name += &format!("dt{value}");
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
                let integrator = CentralDifference {
                    dt: plan.dt,
                    start: stepping.start,
                    stability: stepping.stability,
                    mass,
                    park,
                };
                let critical = integrator.check_stability(&model).map_err(|e| match &e {
                    courant_solver::RunError::Unstable(u) => fail(format!(
                        "{e} ({} {scheme_name} critical Courant number {:.6}, element {stiffest})",
                        mass.label(),
                        u.dt_crit / element_dt
                    )),
                    _ => fail(e.to_string()),
                })?;
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
                    model: model.clone(),
                    integrator,
                    plan,
                    request,
                    critical,
                    limit,
                    reference: reference.clone(),
                    transit_time: transit,
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
    let expectations = raw
        .expectations
        .iter()
        .map(|e| {
            expectation(
                src,
                e,
                &names,
                has_reference,
                Study::TimeStepping,
                &outputs.profile_times,
                outputs.unit,
            )
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Scene {
        name: name.to_string(),
        description: raw.scene.description.into_inner(),
        source: raw.scene.source.into_inner(),
        cases,
        spectra: Vec::new(),
        dispersion: Vec::new(),
        contact: Vec::new(),
        contact_sweeps: Vec::new(),
        expectations,
    })
}

fn build_contact(name: &str, src: &Source, raw: RawContactScene) -> Result<Scene, SceneError> {
    for (value, key) in [
        (&raw.scene.description, "scene.description"),
        (&raw.scene.source, "scene.source"),
    ] {
        if value.get_ref().trim().is_empty() {
            return Err(src.error(Some(value.span()), key, "must not be empty"));
        }
    }
    let (cases, sweeps, study) = match (&raw.contact, &raw.contact_stability) {
        (Some(study), None) => (
            contact::cases(src, &raw, study)?,
            Vec::new(),
            Study::Contact,
        ),
        (None, Some(study)) => (
            Vec::new(),
            vec![contact::sweep(src, study)?],
            Study::ContactStability,
        ),
        _ => {
            return Err(src.error(
                None,
                "contact",
                "a contact scene has either [contact] or [contact_stability], not both",
            ));
        }
    };
    let names: Vec<String> = if study == Study::Contact {
        cases.iter().map(|c| c.name.clone()).collect()
    } else {
        vec!["stability".into()]
    };
    let expectations = raw
        .expectations
        .iter()
        .map(|e| expectation(src, e, &names, false, study, &[], 1.0))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Scene {
        name: name.to_string(),
        description: raw.scene.description.get_ref().clone(),
        source: raw.scene.source.get_ref().clone(),
        cases: Vec::new(),
        spectra: Vec::new(),
        dispersion: Vec::new(),
        contact: cases,
        contact_sweeps: sweeps,
        expectations,
    })
}

fn positive(src: &Source, v: &Spanned<f64>, key: &str) -> Result<f64, SceneError> {
    let x = *v.get_ref();
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(src.error(
            Some(v.span()),
            key,
            format!("{x} must be positive and finite"),
        ))
    }
}

/// The material along the bar: fields of `x`, or homogeneous layers.
#[derive(Debug, Clone, PartialEq)]
pub enum Material {
    /// Modulus and density as constant or linear fields.
    Fields {
        /// Modulus field.
        modulus: Field,
        /// Density field.
        density: Field,
    },
    /// Layers from the loaded end: (thickness, modulus, density).
    Layers(Vec<(f64, f64, f64)>),
}

impl Material {
    /// `(E(x), rho(x))` at `x` in `[0, length]` (a layer interface belongs to the layer on its
    /// right).
    pub fn at(&self, x: f64, length: f64) -> (f64, f64) {
        let field = |f: &Field| match f {
            Field::Constant(c) => *c,
            Field::Linear { left, right } => left + (right - left) * x / length,
            Field::PerElement(_) => f64::NAN,
        };
        match self {
            Material::Fields { modulus, density } => (field(modulus), field(density)),
            Material::Layers(layers) => {
                let mut end = 0.0;
                for &(thickness, e, rho) in layers {
                    end += thickness;
                    if x < end {
                        return (e, rho);
                    }
                }
                layers
                    .last()
                    .map_or((f64::NAN, f64::NAN), |&(_, e, rho)| (e, rho))
            }
        }
    }

    /// True for a homogeneous material.
    pub fn is_homogeneous(&self) -> bool {
        match self {
            Material::Fields { modulus, density } => modulus.is_constant() && density.is_constant(),
            Material::Layers(layers) => layers
                .windows(2)
                .all(|w| w[0].1 == w[1].1 && w[0].2 == w[1].2),
        }
    }
}

/// Bar geometry and material as the scene states them.
pub struct Geometry<'r> {
    length: f64,
    area: f64,
    element_counts: Vec<usize>,
    grading: f64,
    equal_transit: bool,
    /// The material.
    pub material: Material,
    raw: &'r RawScene,
}

impl<'r> Geometry<'r> {
    fn read(src: &Source, raw: &'r RawScene) -> Result<Self, SceneError> {
        let optional = |v: &Option<Spanned<f64>>, key: &str| {
            v.as_ref().map(|v| positive(src, v, key)).transpose()
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
        if let Some(bad) = counts.iter().find(|&&n| n < 1) {
            return Err(src.error(
                Some(span),
                "mesh.elements",
                format!("{bad} must be at least 1"),
            ));
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
                if let Some(bad) = ends.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
                    let span = if key == "material.modulus" {
                        raw.material.modulus.as_ref()
                    } else {
                        raw.material.density.as_ref()
                    };
                    return Err(src.error(
                        span.map(|s| s.span()),
                        key,
                        format!("{bad} must be positive and finite (along the whole bar)"),
                    ));
                }
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
    fn transit_time(&self) -> f64 {
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
    fn element_fields(&self, mesh: &Mesh) -> (Field, Field) {
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

fn model_of(
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
    Model::new(bar, supports, &loads, initial).map_err(|e| {
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
    })
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

/// The integrator settings of a time-stepping scene.
struct Stepping {
    key: &'static str,
    span: Range<usize>,
    values: Vec<f64>,
    by_courant: bool,
    /// What `courant` values are relative to.
    unit: RawCourantUnit,
    /// `keep_step = true`: the step is kept exactly, output times snap to it.
    keep_step: bool,
    masses: Vec<MassKind>,
    /// (case-name prefix, Park options or `None` for CD).
    schemes: Vec<(&'static str, Option<ParkOptions>)>,
    start: Start,
    stability: StabilityPolicy,
}

impl Stepping {
    fn read(src: &Source, raw: &RawIntegrator) -> Result<Self, SceneError> {
        let (key, spanned, by_courant) = match (&raw.courant, &raw.dt) {
            (Some(c), None) => ("integrator.courant", c, true),
            (None, Some(d)) => ("integrator.dt", d, false),
            (Some(c), Some(_)) => {
                return Err(src.error(
                    Some(c.span()),
                    "integrator",
                    "give either `courant` or `dt`, not both",
                ));
            }
            (None, None) => {
                return Err(src.error(
                    None,
                    "integrator",
                    "needs `courant` (Courant numbers) or `dt` (time steps)",
                ));
            }
        };
        let span = spanned.span();
        let values = spanned.get_ref().values();
        if values.is_empty() {
            return Err(src.error(
                Some(span),
                key,
                "the list is empty; give at least one value",
            ));
        }
        if let Some(bad) = values.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
            return Err(src.error(
                Some(span),
                key,
                format!("{bad} must be positive and finite"),
            ));
        }
        let masses = match &raw.mass {
            None => vec![MassKind::Lumped],
            Some(m) => {
                let labels = m.get_ref().values();
                if labels.is_empty() {
                    return Err(src.error(
                        Some(m.span()),
                        "integrator.mass",
                        "the list is empty; give at least one mass",
                    ));
                }
                labels
                    .iter()
                    .map(|l| {
                        parse_mass(l)
                            .map_err(|msg| src.error(Some(m.span()), "integrator.mass", msg))
                    })
                    .collect::<Result<_, _>>()?
            }
        };
        let blowup_energy_ratio = match &raw.blowup_energy_ratio {
            Some(v) => positive(src, v, "integrator.blowup_energy_ratio")?,
            None => StabilityPolicy::default().blowup_energy_ratio,
        };
        let start = match raw.start {
            RawStart::HalfStep => Start::HalfStep,
            RawStart::ThreeLevel => Start::ThreeLevel,
        };
        let stability = StabilityPolicy {
            allow_unstable: raw.allow_unstable,
            blowup_energy_ratio,
        };
        let theta = match &raw.theta {
            None => 0.5,
            Some(t) if (0.0..=1.0).contains(t.get_ref()) => *t.get_ref(),
            Some(t) => {
                return Err(src.error(
                    Some(t.span()),
                    "integrator.theta",
                    format!("{} must lie in [0, 1]", t.get_ref()),
                ));
            }
        };
        let variant = match raw
            .park_variant
            .as_ref()
            .map(|v| (v.get_ref().as_str(), v.span()))
        {
            None | Some(("free", _)) => ParkVariant::Free,
            Some(("incremental", _)) => ParkVariant::Incremental,
            Some((other, span)) => {
                return Err(src.error(
                    Some(span),
                    "integrator.park_variant",
                    format!("\"{other}\" is not one of free, incremental"),
                ));
            }
        };
        let labels = raw
            .scheme
            .as_ref()
            .map(|s| s.get_ref().values())
            .unwrap_or_else(|| vec!["central-difference".into()]);
        let scheme_span = raw.scheme.as_ref().map(|s| s.span());
        if labels.is_empty() {
            return Err(src.error(
                scheme_span,
                "integrator.scheme",
                "the list is empty; give at least one scheme",
            ));
        }
        let schemes = labels
            .iter()
            .map(|label| match label.as_str() {
                "central-difference" | "cd" => Ok(("cd", None)),
                "park-lts" => Ok((
                    "park-lts",
                    Some(ParkOptions {
                        theta,
                        variant,
                        local_stepping: true,
                    }),
                )),
                "park-global" => Ok((
                    "park-global",
                    Some(ParkOptions {
                        theta,
                        variant,
                        local_stepping: false,
                    }),
                )),
                other => Err(src.error(
                    scheme_span.clone(),
                    "integrator.scheme",
                    format!(
                        "\"{other}\" is not one of central-difference (cd), park-lts, park-global"
                    ),
                )),
            })
            .collect::<Result<Vec<_>, _>>()?;
        if !schemes.iter().any(|s| s.1.is_some())
            && (raw.theta.is_some() || raw.park_variant.is_some())
        {
            return Err(src.error(
                scheme_span,
                "integrator",
                "`theta` and `park_variant` apply only to the park-lts and park-global schemes",
            ));
        }
        if schemes.iter().any(|s| s.1.is_some()) && masses.iter().any(|m| *m != MassKind::Lumped) {
            return Err(src.error(
                scheme_span,
                "integrator.scheme",
                "Park's scheme runs with the lumped mass only",
            ));
        }
        let unit = match (&raw.courant_unit, by_courant) {
            (None, _) => RawCourantUnit::StiffestElement,
            (Some(u), true) => *u.get_ref(),
            (Some(u), false) => {
                return Err(src.error(
                    Some(u.span()),
                    "integrator.courant_unit",
                    "applies to `courant` only; a `dt` is a time step in the scene's own unit",
                ));
            }
        };
        let keep_step = raw.keep_step.unwrap_or(false);
        Ok(Self {
            key,
            span,
            values,
            by_courant,
            unit,
            keep_step,
            masses,
            schemes,
            start,
            stability,
        })
    }
}

/// The plan of a `keep_step` case: the step as given, end and profile times snapped to their
/// nearest steps ([`courant_solver::plan_keeping_step`]); two profile times on one step are
/// refused (each needs its own profile).
fn keep_step_plan(
    src: &Source,
    outputs: &Outputs,
    dt: f64,
    case_name: &str,
    stepping: (Range<usize>, &'static str),
) -> Result<TimePlan, SceneError> {
    // Blame the end time where the file sets it, else the step (courant or dt) that ran into it.
    let (span, key) = match outputs.raw.end_time.as_ref() {
        Some(end) => (end.span(), "output.end_time"),
        None => stepping,
    };
    let plan = courant_solver::plan_keeping_step(dt, &outputs.profile_times, outputs.end_time)
        .map_err(|e| {
            src.error(
                Some(span),
                key,
                format!(
                    "case {case_name}: {e} (times in absolute units, not the scene's time_unit)"
                ),
            )
        })?;
    let mut taken: Vec<(usize, f64)> = Vec::with_capacity(plan.output_steps.len());
    for (&t, &n) in outputs.profile_times.iter().zip(&plan.output_steps) {
        if let Some(&(_, other)) = taken.iter().find(|(m, u)| *m == n && *u != t) {
            return Err(src.error(
                outputs.raw.profile_times.as_ref().map(|p| p.span()),
                "output.profile_times",
                format!(
                    "case {case_name}: {} and {} fall on the same step {n} (dt = {dt:e}); with keep_step = true \
                     each profile time needs its own step",
                    other / outputs.unit,
                    t / outputs.unit
                ),
            ));
        }
        taken.push((n, t));
    }
    Ok(plan)
}

/// The output settings, with times converted to absolute time.
struct Outputs<'r> {
    unit: f64,
    profile_times: Vec<f64>,
    end_time: f64,
    raw: &'r RawOutput,
    history_every: Option<usize>,
    energy_every: Option<usize>,
}

impl<'r> Outputs<'r> {
    fn read(src: &Source, raw: &'r RawOutput, transit: f64) -> Result<Self, SceneError> {
        let unit = match raw.time_unit {
            RawTimeUnit::Absolute => 1.0,
            RawTimeUnit::Transit => transit,
        };
        let profile_span = raw.profile_times.as_ref().map(|p| p.span());
        let given: Vec<f64> = raw
            .profile_times
            .as_ref()
            .map(|p| p.get_ref().clone())
            .unwrap_or_default();
        if let Some(bad) = given.iter().find(|t| !(t.is_finite() && **t >= 0.0)) {
            return Err(src.error(
                profile_span,
                "output.profile_times",
                format!("{bad} must be finite and not negative"),
            ));
        }
        let profile_times: Vec<f64> = given.iter().map(|t| t * unit).collect();
        let end_time = match &raw.end_time {
            Some(e) => positive(src, e, "output.end_time")? * unit,
            None => match profile_times.iter().copied().reduce(f64::max) {
                Some(t) if t > 0.0 => t,
                _ => {
                    return Err(src.error(
                        profile_span,
                        "output.end_time",
                        "is needed when no positive profile time is given",
                    ));
                }
            },
        };
        if let Some(&late) = profile_times
            .iter()
            .find(|&&t| t > end_time * (1.0 + 1e-12))
        {
            return Err(src.error(
                profile_span,
                "output.profile_times",
                format!(
                    "{} is after the end time {}; profile times must lie in [0, end_time]",
                    late / unit,
                    end_time / unit
                ),
            ));
        }
        // `None` means the default: every step up to MAX_SAMPLES steps, then thinned so that a
        // long run keeps about MAX_SAMPLES samples (decided per case, from its step count).
        let every = |v: &Option<Spanned<i64>>, key: &str| -> Result<Option<usize>, SceneError> {
            match v {
                None => Ok(None),
                Some(s) if *s.get_ref() >= 1 => Ok(Some(*s.get_ref() as usize)),
                Some(s) => Err(src.error(
                    Some(s.span()),
                    key,
                    format!("{} must be at least 1", s.get_ref()),
                )),
            }
        };
        Ok(Self {
            unit,
            profile_times,
            end_time,
            raw,
            history_every: every(&raw.history_every, "output.history_every")?,
            energy_every: every(&raw.energy_every, "output.energy_every")?,
        })
    }

    /// History points snapped to the nearest nodes of `model`.
    fn history_nodes(&self, src: &Source, model: &Model) -> Result<Vec<usize>, SceneError> {
        let Some(points) = &self.raw.history_points else {
            return Ok(Vec::new());
        };
        let mesh = model.bar().mesh();
        let (start, length) = (mesh.start(), mesh.length());
        points
            .get_ref()
            .iter()
            .map(|&x| {
                if x.is_finite()
                    && x >= start - 1e-12 * length
                    && x <= start + length * (1.0 + 1e-12)
                {
                    Ok(mesh.nearest_node(x))
                } else {
                    Err(src.error(
                        Some(points.span()),
                        "output.history_points",
                        format!("{x} is outside the bar [0, {length}]"),
                    ))
                }
            })
            .collect()
    }
}

fn field(f: &Spanned<RawField>) -> Field {
    match f.get_ref() {
        RawField::Constant(c) => Field::Constant(*c),
        RawField::Linear(RawLinear {
            linear: [left, right],
        }) => Field::Linear {
            left: *left,
            right: *right,
        },
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

fn expectation(
    src: &Source,
    spanned: &Spanned<RawExpect>,
    names: &[String],
    has_reference: bool,
    study: Study,
    profile_times: &[f64],
    unit: f64,
) -> Result<Expectation, SceneError> {
    let raw = spanned.get_ref();
    let fail = |msg: String| src.error(Some(spanned.span()), "expect", msg);
    let metric = Metric::parse(&raw.metric).ok_or_else(|| {
        fail(format!(
            "metric = \"{}\" is not one of l1, l2, linf, overshoot, energy_balance, energy_lost, tv_ratio, diverged, closed_form_deviation, dispersion_deviation, phase_error_order, plateau_deviation, impulse_error, duration_error, force_l1_error, energy_ratio, courant_deviation",
            raw.metric
        ))
    })?;
    if metric.needs_reference() && !has_reference {
        return Err(fail(format!(
            "metric \"{}\" compares with a reference, but the scene has none",
            metric.name()
        )));
    }
    let applies =
        metric.study() == study || (metric == Metric::Diverged && study == Study::Contact);
    if !applies {
        return Err(fail(format!(
            "metric \"{}\" does not apply to a {} scene",
            metric.name(),
            study.name()
        )));
    }
    let selected = match &raw.cases {
        None => names.to_vec(),
        Some(list) => {
            if let Some(unknown) = list.iter().find(|c| !names.contains(c)) {
                return Err(fail(format!(
                    "case \"{unknown}\" does not exist (cases: {})",
                    names.join(", ")
                )));
            }
            list.clone()
        }
    };
    let at = match raw.at {
        None => None,
        Some(t) => {
            let t = t * unit;
            if !profile_times
                .iter()
                .any(|&p| (p - t).abs() <= 1e-9 * p.abs().max(1e-300))
            {
                return Err(fail(format!(
                    "at = {} is not one of the profile times",
                    t / unit
                )));
            }
            Some(t)
        }
    };
    let bound = match (metric, raw.min, raw.max, raw.equals) {
        (Metric::Diverged, None, None, Some(b)) => Bound::Equals(b),
        (Metric::Diverged, _, _, _) => {
            return Err(fail(
                "metric \"diverged\" takes `equals = true|false` only".into(),
            ));
        }
        (_, _, _, Some(_)) => {
            return Err(fail("`equals` applies only to metric \"diverged\"".into()));
        }
        (_, None, None, None) => return Err(fail("needs `max`, `min` or both".into())),
        (_, Some(lo), Some(hi), None) if lo > hi => {
            return Err(fail(format!("min = {lo} is above max = {hi}")));
        }
        (_, min, max, None) => Bound::Range { min, max },
    };
    if raw.source.trim().is_empty() {
        return Err(fail(
            "`source` must name the source of truth of the bound".into(),
        ));
    }
    Ok(Expectation {
        cases: selected,
        metric,
        at,
        bound,
        source: raw.source.clone(),
    })
}
