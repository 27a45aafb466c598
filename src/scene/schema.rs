//! The scene file format, exactly as written in TOML. Unknown keys are errors
//! (`deny_unknown_fields`); every optional key's default is stated on it. Values that need a
//! semantic check keep their span so the error can point at them.

use serde::Deserialize;
use toml::Spanned;

/// A whole scene file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawScene {
    pub scene: RawHeader,
    /// Default: `length = 1`, `area = 1`.
    #[serde(default)]
    pub bar: RawBar,
    pub material: RawMaterial,
    pub mesh: RawMesh,
    /// Default: `left = "free"`, `right = "fixed"` (the seed's bar).
    #[serde(default)]
    pub supports: RawSupports,
    /// Default: no loads.
    #[serde(default, rename = "load")]
    pub loads: Vec<Spanned<RawLoad>>,
    /// Default: at rest, undeformed.
    #[serde(default)]
    pub initial: RawInitial,
    /// Required for time-stepping scenes; absent in spectrum scenes.
    pub integrator: Option<RawIntegrator>,
    /// Makes the scene a spectrum study (no time stepping).
    pub spectrum: Option<RawSpectrum>,
    /// Makes the scene a dispersion study (single-mode runs).
    pub dispersion: Option<RawDispersion>,
    #[serde(default)]
    pub output: RawOutput,
    /// Default: `kind = "none"`.
    #[serde(default)]
    pub reference: RawReference,
    /// Default: none.
    #[serde(default, rename = "expect")]
    pub expectations: Vec<Spanned<RawExpect>>,
    /// Default: none (stability scenes only).
    #[serde(default, rename = "finding")]
    pub findings: Vec<Spanned<RawFinding>>,
}

/// A disagreement between stability theory and a run that the scene states as an expected
/// finding, with its source: the stability verdict of those cases then passes as a finding
/// instead of failing.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFinding {
    /// Cases it applies to.
    pub cases: Vec<String>,
    /// What the runs do against the prediction: `energy growth`, `energy created`, `diverged`
    /// or `stable`.
    pub observed: String,
    /// Where the finding is established (a paper, or "measured here" with what was measured).
    pub source: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawHeader {
    /// One line: what the scene shows.
    pub description: Spanned<String>,
    /// Its source of truth (paper and figure, closed form, textbook result).
    pub source: Spanned<String>,
    /// A stability scene (default false): every case gets a stability verdict, the step against
    /// its scheme's limit, predicted against observed, and appears in the report's
    /// stability-at-the-extremes table.
    #[serde(default)]
    pub stability: bool,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBar {
    /// Default 1.
    pub length: Option<Spanned<f64>>,
    /// Default 1.
    pub area: Option<Spanned<f64>>,
}

/// A property along the bar: a number, or `{ linear = [left, right] }`.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum RawField {
    Constant(f64),
    Linear(RawLinear),
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLinear {
    pub linear: [f64; 2],
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawMaterial {
    /// Required unless `layers` is given.
    pub modulus: Option<Spanned<RawField>>,
    /// Default 1.
    pub density: Option<Spanned<RawField>>,
    /// Piecewise-constant layers from the loaded (left) end, instead of `modulus`/`density`.
    pub layers: Option<Spanned<Vec<RawLayer>>>,
}

/// One homogeneous layer.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLayer {
    pub thickness: f64,
    pub modulus: f64,
    /// Default 1.
    pub density: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawMesh {
    /// Element count(s); a list makes one case per count.
    pub elements: Spanned<OneOrManyInts>,
    /// Ratio of consecutive element lengths, `h_{e+1}/h_e`. Default 1 (uniform).
    pub grading: Option<Spanned<f64>>,
    /// `uniform` (default; with `grading`, geometric) or `equal-transit` (element lengths
    /// proportional to the local wave speed, methods.md §4).
    pub spacing: Option<Spanned<String>>,
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum RawSupport {
    Free,
    Fixed,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSupports {
    pub left: RawSupport,
    pub right: RawSupport,
}

impl Default for RawSupports {
    fn default() -> Self {
        Self {
            left: RawSupport::Free,
            right: RawSupport::Fixed,
        }
    }
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum RawEnd {
    Left,
    Right,
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum RawLoadKind {
    Traction,
    Force,
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "lowercase")]
pub enum RawTimeKind {
    #[default]
    Step,
    Ramp,
    Pulse,
    Table,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLoad {
    /// `traction` (needs `end`) or `force` (needs `node`).
    pub kind: RawLoadKind,
    pub end: Option<RawEnd>,
    pub node: Option<i64>,
    /// Stress of a traction (positive in tension) or magnitude of a force (positive along +x).
    pub value: f64,
    /// Default `step`.
    #[serde(default)]
    pub time: RawTimeKind,
    /// Default 0.
    pub start: Option<f64>,
    /// Rise time of a ramp, length of a pulse.
    pub duration: Option<f64>,
    /// Value of a step at exactly `t = start`. Default 1 (H(0) = 1, methods.md §2).
    pub value_at_start: Option<f64>,
    /// `[[t, f], ...]` for `time = "table"`.
    pub table: Option<Vec<[f64; 2]>>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawInitial {
    /// Default 0.
    pub displacement: Option<Spanned<RawField>>,
    /// Default 0.
    pub velocity: Option<Spanned<RawField>>,
}

/// One integer or a list of integers (each a case).
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum OneOrManyInts {
    One(i64),
    Many(Vec<i64>),
}

impl OneOrManyInts {
    pub fn values(&self) -> Vec<i64> {
        match self {
            OneOrManyInts::One(x) => vec![*x],
            OneOrManyInts::Many(v) => v.clone(),
        }
    }
}

/// One number or a list of numbers (each a case).
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum OneOrMany {
    One(f64),
    Many(Vec<f64>),
}

impl OneOrMany {
    pub fn values(&self) -> Vec<f64> {
        match self {
            OneOrMany::One(x) => vec![*x],
            OneOrMany::Many(v) => v.clone(),
        }
    }
}

/// One string or a list of strings (each a case).
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum OneOrManyStrings {
    One(String),
    Many(Vec<String>),
}

impl OneOrManyStrings {
    pub fn values(&self) -> Vec<String> {
        match self {
            OneOrManyStrings::One(x) => vec![x.clone()],
            OneOrManyStrings::Many(v) => v.clone(),
        }
    }
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "kebab-case")]
pub enum RawCourantUnit {
    /// Courant numbers relative to the stiffest element, `c dt / h` (methods.md §1).
    #[default]
    StiffestElement,
    /// Multiples of the mass kind's closed-form critical Courant number (1 for LMM,
    /// 1/sqrt(3) for CMM, sqrt((1 + 2 beta)/3) for AMM and RMM): the infinite uniform mesh's
    /// limit, a hair below a finite mesh's exact one.
    Critical,
    /// Multiples of the exact critical step of the case's scheme on the assembled mesh: CD's
    /// `2/omega_max` (`CriticalStep::exact`, any mass), Park's `min_e dt_e` (`alpha_e <= 1`,
    /// methods.md §6). With `keep_step = true`, 1.00 is that step to round-off.
    Exact,
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "kebab-case")]
pub enum RawStart {
    #[default]
    HalfStep,
    ThreeLevel,
}

/// The keys of `[integrator]` itself (the fields of [`RawIntegrator`]); every other key of the
/// table is a parameter of its schemes, declared by their registry entries
/// (`courant_solver::schemes::REGISTRY`; `theta` and `park_variant` for Park, `p` for
/// Noh-Bathe), taken out before the table is read (`super::scheme_keys`).
pub const INTEGRATOR_KEYS: &[&str] = &[
    "scheme",
    "mass",
    "courant_unit",
    "keep_step",
    "courant",
    "dt",
    "start",
    "allow_unstable",
    "blowup_energy_ratio",
];

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawIntegrator {
    /// Scheme or schemes (one case each), by their registry names: `cd` (or
    /// `central-difference`), `park-lts` (Park's scheme with local time stepping), `park-global`
    /// (without), `noh-bathe`, ... (`courant list --schemes`). Default `central-difference`.
    pub scheme: Option<Spanned<OneOrManyStrings>>,
    /// Mass matrix or matrices (one case each): `lmm`, `cmm`, `amm`, `rmm` (beta = 1/2), or
    /// `amm(beta)`, `rmm(beta)`. Default `lmm`.
    pub mass: Option<Spanned<OneOrManyStrings>>,
    /// What the `courant` values are relative to: `stiffest-element` (default), `critical` or
    /// `exact`. Applies to `courant` only.
    pub courant_unit: Option<Spanned<RawCourantUnit>>,
    /// Keep the step exactly as `courant` or `dt` gives it (default false: the step is shrunk
    /// until a whole number of steps lands on every output time). When true, the end time and
    /// each profile time snap to their nearest step (each profile time needs its own step), and
    /// profiles, histories and references are taken at the step's actual time.
    pub keep_step: Option<bool>,
    /// Courant number(s) relative to the stiffest element; one case each. Exactly one of
    /// `courant` and `dt`.
    pub courant: Option<Spanned<OneOrMany>>,
    /// Time step(s); one case each.
    pub dt: Option<Spanned<OneOrMany>>,
    /// Default `half-step`.
    #[serde(default)]
    pub start: RawStart,
    /// Default false: a step above the critical step is refused.
    #[serde(default)]
    pub allow_unstable: bool,
    /// Default 1e6: kinetic + strain energy above this multiple of the work done (or the initial
    /// energy) stops the run as diverged.
    pub blowup_energy_ratio: Option<Spanned<f64>>,
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "lowercase")]
pub enum RawTimeUnit {
    /// Times in the scene's own unit.
    #[default]
    Absolute,
    /// Times in transit times `T = sum_e h_e/c_e`.
    Transit,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawOutput {
    /// Default `absolute`.
    #[serde(default)]
    pub time_unit: RawTimeUnit,
    /// Times of the stress profiles. Default none.
    pub profile_times: Option<Spanned<Vec<f64>>>,
    /// Positions of the nodal histories (snapped to the nearest node). Default none.
    pub history_points: Option<Spanned<Vec<f64>>>,
    /// Default: the last profile time (required when there are none).
    pub end_time: Option<Spanned<f64>>,
    /// Default: every step for runs of up to 10000 steps, else every ceil(steps/10000)-th.
    pub history_every: Option<Spanned<i64>>,
    /// Default: every step for runs of up to 10000 steps, else every ceil(steps/10000)-th (the
    /// balance is checked at every step regardless).
    pub energy_every: Option<Spanned<i64>>,
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "lowercase")]
pub enum RawReferenceKind {
    #[default]
    None,
    /// Homogeneous free-fixed bar (methods.md §3).
    Dalembert,
    /// Linearly graded modulus, constant density (methods.md §4).
    Graded,
    /// Piecewise-constant layers (exact wave tracking).
    Layered,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawReference {
    /// Default `none`.
    pub kind: Option<Spanned<RawReferenceKind>>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawExpect {
    /// Cases it applies to. Default: all.
    pub cases: Option<Vec<String>>,
    /// A metric name (`scene::expectation::Metric`): `l1`, `l2`, `linf`, `overshoot`, ...
    pub metric: String,
    /// Profile time it applies to (in `output.time_unit`). Default: the worst over all times.
    pub at: Option<f64>,
    /// Upper bound (inclusive).
    pub max: Option<f64>,
    /// Lower bound (inclusive).
    pub min: Option<f64>,
    /// For boolean metrics (`diverged`).
    pub equals: Option<bool>,
    /// A case the value is relative to (`value / value(relative_to)`; for
    /// `force_history_difference` the case whose history is the comparison).
    pub relative_to: Option<String>,
    /// `mass_deviation`, `mode_error_ratio`: the mass kind compared.
    pub mass: Option<String>,
    /// `mass_deviation`, `mode_error_ratio`: the mass kind it is compared against.
    pub against: Option<String>,
    /// Contact force metrics: `penalty` or `transferred`, instead of the scene's `force`.
    pub force: Option<String>,
    /// `bound` (an error bound any code at least as accurate meets) or `signature` (what the
    /// case's scheme and mass do). Default: from the metric and the bound
    /// (`scene::expectation::RowKind::default_for`).
    pub kind: Option<String>,
    /// A stated finding (default false): the row measures where a claim of the seed does not
    /// hold as stated (its source says which claim and what was measured); when its bound holds
    /// it passes as a finding, counted and listed on the report's first screen.
    pub finding: Option<bool>,
    /// The source of truth the bound comes from.
    pub source: String,
}

/// A spectrum study: the frequencies of `K u = omega^2 M u` for each mass kind.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSpectrum {
    /// End conditions, one case each: `free-free`, `fixed-free` (one end fixed), `fixed-fixed`.
    pub ends: Spanned<OneOrManyStrings>,
    /// Mass kinds, one column each (as `integrator.mass`).
    pub masses: Spanned<OneOrManyStrings>,
}

/// A dispersion study: phase speeds of single-mode runs against the closed form.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDispersion {
    /// Mass kinds (as `integrator.mass`); `amm(4th)` and `rmm(4th)` take the fourth-order beta
    /// of each Courant number.
    pub masses: Spanned<OneOrManyStrings>,
    /// Courant numbers `c dt/h`.
    pub courant: Spanned<OneOrMany>,
    /// Mode numbers `n` of the free-free bar (`kh = n pi/N`).
    pub modes: Spanned<OneOrManyInts>,
}

/// One bar of a contact problem.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContactBar {
    pub length: f64,
    pub elements: i64,
    /// Default 1; `{ linear = [left, right] }` grades the bar (as `material.modulus`): each
    /// element takes the value at its midpoint (`scene::contact_bar`).
    pub modulus: Option<RawField>,
    /// Default 1; constant on a graded bar.
    pub density: Option<RawField>,
    /// Piecewise-constant layers from the bar's left end, instead of `modulus`/`density`; their
    /// thicknesses sum to `length` and every interface falls on a node of the uniform mesh.
    pub layers: Option<Vec<RawLayer>>,
}

/// A contact-impact study: a striker at `velocity` onto a target bar or a rigid wall.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContact {
    /// `two-bars` (striker onto target, far ends free) or `wall` (striker onto a rigid wall).
    pub problem: Spanned<String>,
    /// The moving bar.
    pub striker: Spanned<RawContactBar>,
    /// The bar at rest (`two-bars` only).
    pub target: Option<Spanned<RawContactBar>>,
    /// Impact velocity, positive.
    pub velocity: Spanned<f64>,
    /// Initial gap, default 0 (touching at t = 0).
    pub gap: Option<Spanned<f64>>,
    /// Schemes, one case each (with every `beta_s` for the penalty schemes): `cd-penalty`,
    /// `cd-bipenalty`, `predictor-corrector`, `lagrange-multiplier`.
    pub schemes: Spanned<OneOrManyStrings>,
    /// Dimensionless penalty stiffness(es) `beta_s = k_s h/(E A)`.
    pub beta_s: Option<Spanned<OneOrMany>>,
    /// Penalty ratio(s) `r = beta_s/(4 beta_m)` (default 1, the neutral ratio); several give one
    /// case each, named `-r<r>`.
    pub ratio: Option<Spanned<OneOrMany>>,
    /// Dimensionless penalty mass `beta_m = m_p/(rho A h)`, instead of `ratio`.
    pub beta_m: Option<Spanned<f64>>,
    /// Courant number(s), one case each (named `-co<Co>` when there are several): relative to
    /// the stiffest element by default, or multiples of each case's exact critical step with
    /// `courant_unit = "critical"`.
    pub courant: Spanned<OneOrMany>,
    /// `stiffest-element` (default, `c dt/h_min`) or `critical`: multiples of the exact
    /// critical step of each case's scheme (`ContactCriticalStep::applicable`).
    #[serde(default)]
    pub courant_unit: RawContactCourantUnit,
    /// End time in transit times of the striker, `2 L1/c1` is one contact of equal bars.
    pub end_time: Spanned<f64>,
    /// Run above the critical step (default false).
    #[serde(default)]
    pub allow_unstable: bool,
    /// Keep a sample every this many steps (default 1).
    pub history_every: Option<Spanned<i64>>,
    /// The force the penalty schemes are graded and plotted by: `penalty` (default: the seed's
    /// `f_cont = eps_s x penetration`, seed eq. 15) or `transferred` (the momentum delivered to
    /// the bars per step over dt). The Lagrange multiplier method has no penalty and always
    /// uses `transferred`.
    pub force: Option<Spanned<String>>,
    /// Bulk scheme(s), one case each (prefixed `<bulk>-` except `cd-lmm`): `cd-lmm` (default),
    /// `cd-rmm`, `park-lts`, `park-global` (`scene::contact_bulk`).
    pub bulk: Option<Spanned<OneOrManyStrings>>,
    /// RMM's beta for a `cd-rmm` bulk (default 1/2).
    pub rmm_beta: Option<Spanned<f64>>,
    /// Park's element acceleration for a `park-*` bulk: `incremental` (default) or `free`.
    pub park_variant: Option<Spanned<String>>,
    /// Layers of the equal-travel-time layering a graded bar's reference is computed on
    /// (default 64, `scene::contact_bar`).
    pub reference_layers: Option<Spanned<i64>>,
}

/// The unit of a contact scene's Courant numbers.
#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "kebab-case")]
pub enum RawContactCourantUnit {
    /// `c dt / h` of the stiffest element (methods.md §1).
    #[default]
    StiffestElement,
    /// Multiples of the exact critical step of the case's scheme: `2/omega_max` of the
    /// contact-active pencil for CD with (bi)penalty, `min(dt_free, sqrt((m_c + m_p)/k_s))` for
    /// the predictor-corrector, the contact-free step for the Lagrange multiplier (methods.md §7).
    /// `"exact"` is accepted too, the word `[integrator]` uses for a scheme's exact limit.
    #[serde(alias = "exact")]
    Critical,
    /// Multiples of the combination's measured limit: the largest step with the spectral radius
    /// of the one-step amplification matrix at most `1 + 1e-6`, contact always active and
    /// contact off (`courant_solver::contact::combined::amplification`; dense, <= 400 nodes).
    Measured,
}

/// A contact stability sweep: the critical Courant number of a bar against a rigid wall
/// versus `beta_s`, from the solver's eigenvalues beside the closed form.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContactStability {
    /// Elements of the bar (unit bar, E = rho = A = 1).
    pub elements: Spanned<i64>,
    /// `[min, max]` of the log-spaced `beta_s` grid.
    pub beta_s_range: Spanned<[f64; 2]>,
    /// Grid points.
    pub points: Spanned<i64>,
    /// Penalty ratios `r` of the bipenalty curves.
    pub ratios: Spanned<Vec<f64>>,
    /// Also the penalty-only curve (default true).
    pub penalty_only: Option<bool>,
}

/// A contact scene: its bars are given in `[contact]`, or it is a `[contact_stability]` sweep.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContactScene {
    pub scene: RawHeader,
    /// Default: `area = 1` (`length` is not used: each bar has its own).
    #[serde(default)]
    pub bar: RawBar,
    pub contact: Option<RawContact>,
    pub contact_stability: Option<RawContactStability>,
    #[serde(default, rename = "expect")]
    pub expectations: Vec<Spanned<RawExpect>>,
    #[serde(default, rename = "finding")]
    pub findings: Vec<Spanned<RawFinding>>,
}
