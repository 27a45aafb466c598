//! Scenes: declarative cases read from TOML, validated into ready-to-run [`Case`]s.
//!
//! A scene states only what its case needs; everything else has the default documented in
//! [`schema`]. A list of Courant numbers (or time steps) expands into one case each. Validation
//! happens here, before anything runs: a scene that parses is a scene that can run.

pub mod error;
pub mod schema;

use crate::reference::Reference;
use courant_solver::{
    Bar, CentralDifference, CriticalStep, End, Field, InitialConditions, InputError, Load, Mesh,
    Model, OutputRequest, StabilityPolicy, Start, Support, Supports, TimeFunction, TimePlan,
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

/// A validated scene.
#[derive(Debug, Clone)]
pub struct Scene {
    /// Name (file stem), used for the output directory.
    pub name: String,
    /// One-line description.
    pub description: String,
    /// Source of truth.
    pub source: String,
    /// The cases, in file order.
    pub cases: Vec<Case>,
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
}

impl Metric {
    /// Scene-file name.
    pub fn name(self) -> &'static str {
        match self {
            Metric::L1 => "l1",
            Metric::L2 => "l2",
            Metric::Linf => "linf",
            Metric::Overshoot => "overshoot",
            Metric::EnergyBalance => "energy_balance",
            Metric::Diverged => "diverged",
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
        ]
        .into_iter()
        .find(|m| m.name() == s)
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
    let err = |span: Range<usize>, key: &str, msg: String| src.error(Some(span), key, msg);
    let positive = |v: &Spanned<f64>, key: &str| -> Result<f64, SceneError> {
        let x = *v.get_ref();
        if x.is_finite() && x > 0.0 {
            Ok(x)
        } else {
            Err(err(
                v.span(),
                key,
                format!("{x} must be positive and finite"),
            ))
        }
    };
    for (value, key) in [
        (&raw.scene.description, "scene.description"),
        (&raw.scene.source, "scene.source"),
    ] {
        if value.get_ref().trim().is_empty() {
            return Err(err(value.span(), key, "must not be empty".into()));
        }
    }

    // Geometry and material.
    let length = raw
        .bar
        .length
        .as_ref()
        .map(|v| positive(v, "bar.length"))
        .transpose()?
        .unwrap_or(1.0);
    let area = raw
        .bar
        .area
        .as_ref()
        .map(|v| positive(v, "bar.area"))
        .transpose()?
        .unwrap_or(1.0);
    let elements = *raw.mesh.elements.get_ref();
    if elements < 1 {
        return Err(err(
            raw.mesh.elements.span(),
            "mesh.elements",
            format!("{elements} must be at least 1"),
        ));
    }
    let grading = raw
        .mesh
        .grading
        .as_ref()
        .map(|v| positive(v, "mesh.grading"))
        .transpose()?
        .unwrap_or(1.0);
    let mesh = Mesh::geometric(length, elements as usize, grading).map_err(|e| {
        match (&e, &raw.mesh.grading) {
            (
                InputError::Parameter {
                    field: "grading ratio",
                    ..
                },
                Some(g),
            ) => err(g.span(), "mesh.grading", e.to_string()),
            _ => err(raw.mesh.elements.span(), "mesh.elements", e.to_string()),
        }
    })?;
    let modulus = field(&raw.material.modulus);
    let density = raw
        .material
        .density
        .as_ref()
        .map(field)
        .unwrap_or(Field::Constant(1.0));
    let bar = Bar::new(mesh, &modulus, &density, &Field::Constant(area)).map_err(|e| {
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
            _ => ("material.modulus", Some(raw.material.modulus.span())),
        };
        src.error(span, key, e.to_string())
    })?;

    let supports = Supports {
        left: support(raw.supports.left),
        right: support(raw.supports.right),
    };
    let mut loads = Vec::with_capacity(raw.loads.len());
    for load in &raw.loads {
        loads.push(load_of(src, load, bar.node_count() - 1)?);
    }
    let nodal = |f: &Option<Spanned<RawField>>| -> Option<Vec<f64>> {
        f.as_ref().map(|f| {
            let field = field(f);
            let mesh = bar.mesh();
            mesh.nodes()
                .iter()
                .map(|&x| match &field {
                    Field::Constant(c) => *c,
                    Field::Linear { left, right } => {
                        left + (right - left) * (x - mesh.start()) / mesh.length()
                    }
                    Field::PerElement(_) => unreachable!("scene fields are constant or linear"),
                })
                .collect()
        })
    };
    let initial = InitialConditions {
        displacement: nodal(&raw.initial.displacement),
        velocity: nodal(&raw.initial.velocity),
    };
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
            _ if raw.loads.is_empty() => ("load", None),
            _ => ("load", raw.loads.first().map(|l| l.span())),
        };
        src.error(span, key, e.to_string())
    })?;
    let transit_time = model.bar().transit_time();

    // Time stepping.
    let (steps_key, spanned, by_courant) = match (&raw.integrator.courant, &raw.integrator.dt) {
        (Some(c), None) => ("integrator.courant", c, true),
        (None, Some(d)) => ("integrator.dt", d, false),
        (Some(c), Some(_)) => {
            return Err(err(
                c.span(),
                "integrator",
                "give either `courant` or `dt`, not both".into(),
            ));
        }
        (None, None) => {
            return Err(src.error(
                None,
                "integrator",
                "needs `courant` (Courant numbers) or `dt` (time steps)".to_string(),
            ));
        }
    };
    let values = spanned.get_ref().values();
    if values.is_empty() {
        return Err(err(
            spanned.span(),
            steps_key,
            "the list is empty; give at least one value".into(),
        ));
    }
    if let Some(bad) = values.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
        return Err(err(
            spanned.span(),
            steps_key,
            format!("{bad} must be positive and finite"),
        ));
    }
    let blowup_energy_ratio = match &raw.integrator.blowup_energy_ratio {
        Some(v) => positive(v, "integrator.blowup_energy_ratio")?,
        None => StabilityPolicy::default().blowup_energy_ratio,
    };
    let stability = StabilityPolicy {
        allow_unstable: raw.integrator.allow_unstable,
        blowup_energy_ratio,
    };
    let start = match raw.integrator.start {
        RawStart::HalfStep => Start::HalfStep,
        RawStart::ThreeLevel => Start::ThreeLevel,
    };

    // Outputs.
    let unit = match raw.output.time_unit {
        RawTimeUnit::Absolute => 1.0,
        RawTimeUnit::Transit => transit_time,
    };
    let profile_times: Vec<f64> = raw
        .output
        .profile_times
        .as_ref()
        .map(|p| p.get_ref().iter().map(|t| t * unit).collect())
        .unwrap_or_default();
    let profile_span = raw.output.profile_times.as_ref().map(|p| p.span());
    if let Some(bad) = profile_times
        .iter()
        .find(|t| !(t.is_finite() && **t >= 0.0))
    {
        return Err(src.error(
            profile_span,
            "output.profile_times",
            format!("{} must be finite and not negative", bad / unit),
        ));
    }
    let end_time = match &raw.output.end_time {
        Some(e) => positive(e, "output.end_time")? * unit,
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
    let mut history_nodes = Vec::new();
    if let Some(points) = &raw.output.history_points {
        let mesh = model.bar().mesh();
        for &x in points.get_ref() {
            let inside = x.is_finite()
                && x >= mesh.start() - 1e-12 * length
                && x <= mesh.start() + length * (1.0 + 1e-12);
            if !inside {
                return Err(err(
                    points.span(),
                    "output.history_points",
                    format!("{x} is outside the bar [0, {length}]"),
                ));
            }
            history_nodes.push(mesh.nearest_node(x));
        }
    }
    // `None` here means "the default": every step up to MAX_SAMPLES steps, then thinned so
    // that a long run keeps about MAX_SAMPLES samples (decided per case, from its step count).
    let every = |v: &Option<Spanned<i64>>, key: &str| -> Result<Option<usize>, SceneError> {
        match v {
            None => Ok(None),
            Some(s) if *s.get_ref() >= 1 => Ok(Some(*s.get_ref() as usize)),
            Some(s) => Err(err(
                s.span(),
                key,
                format!("{} must be at least 1", s.get_ref()),
            )),
        }
    };
    let history_every = every(&raw.output.history_every, "output.history_every")?;
    let energy_every = every(&raw.output.energy_every, "output.energy_every")?;

    // Reference.
    let reference = match &raw.reference.kind {
        None => None,
        Some(kind) => Reference::for_model(*kind.get_ref(), &model)
            .map_err(|m| err(kind.span(), "reference.kind", m))?,
    };

    // Cases.
    let critical = CriticalStep::lumped(&model);
    let (stiffest, element_dt) = model.bar().stiffest_element();
    let mut cases = Vec::with_capacity(values.len());
    for &value in &values {
        let (case_name, nominal_dt) = if by_courant {
            (format!("co{value}"), value * element_dt)
        } else {
            (format!("dt{value}"), value)
        };
        let plan = courant_solver::plan(nominal_dt, &profile_times, end_time)
            .map_err(|e| err(spanned.span(), steps_key, format!("case {case_name}: {e}")))?;
        let integrator = CentralDifference {
            dt: plan.dt,
            start,
            stability,
        };
        integrator.check_stability(&model).map_err(|e| {
            err(
                spanned.span(),
                steps_key,
                format!(
                    "case {case_name}: {e} (critical Courant number {:.6}, element {stiffest})",
                    critical.exact / element_dt
                ),
            )
        })?;
        let node_steps = plan.steps as f64 * model.bar().element_count() as f64;
        if node_steps > MAX_NODE_STEPS {
            return Err(err(
                spanned.span(),
                steps_key,
                format!(
                    "case {case_name}: {} steps x {} elements = {node_steps:.2e} node-steps, more than the {MAX_NODE_STEPS:.0e} \
                     a scene may ask for; coarsen the mesh, raise the step or shorten the run",
                    plan.steps,
                    model.bar().element_count()
                ),
            ));
        }
        let thinned = plan.steps.div_ceil(MAX_SAMPLES).max(1);
        let request = OutputRequest {
            profile_steps: plan.output_steps.clone(),
            history_nodes: history_nodes.clone(),
            history_every: history_every.unwrap_or(thinned),
            energy_every: energy_every.unwrap_or(thinned),
        };
        cases.push(Case {
            name: case_name,
            model: model.clone(),
            integrator,
            plan,
            request,
            critical,
            reference: reference.clone(),
            transit_time,
        });
    }
    let mut seen = std::collections::HashSet::new();
    if let Some(dup) = cases.iter().find(|c| !seen.insert(c.name.clone())) {
        return Err(err(
            spanned.span(),
            steps_key,
            format!("case {} appears twice", dup.name),
        ));
    }

    let expectations = raw
        .expectations
        .iter()
        .map(|e| expectation(src, e, &cases, reference.is_some(), &profile_times, unit))
        .collect::<Result<Vec<_>, _>>()?;

    Ok(Scene {
        name: name.to_string(),
        description: raw.scene.description.into_inner(),
        source: raw.scene.source.into_inner(),
        cases,
        expectations,
    })
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
    cases: &[Case],
    has_reference: bool,
    profile_times: &[f64],
    unit: f64,
) -> Result<Expectation, SceneError> {
    let raw = spanned.get_ref();
    let fail = |msg: String| src.error(Some(spanned.span()), "expect", msg);
    let metric = Metric::parse(&raw.metric).ok_or_else(|| {
        fail(format!(
            "metric = \"{}\" is not one of l1, l2, linf, overshoot, energy_balance, diverged",
            raw.metric
        ))
    })?;
    if metric.needs_reference() && !has_reference {
        return Err(fail(format!(
            "metric \"{}\" compares with a reference, but the scene has none",
            metric.name()
        )));
    }
    let names: Vec<String> = cases.iter().map(|c| c.name.clone()).collect();
    let selected = match &raw.cases {
        None => names.clone(),
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
