//! Typed errors of the solver. Every variant carries the context a user needs to act on it: the
//! field, the offending value and the rule it breaks, or the element/node/step where it happened.

use thiserror::Error;

/// Invalid model data or run parameters. Raised before any time step is taken.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum InputError {
    /// A scalar parameter breaks its rule (e.g. `length = -1 must be positive and finite`).
    #[error("{field} = {value} {rule}")]
    Parameter {
        /// Name of the parameter.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// The rule it breaks, phrased to follow the value.
        rule: &'static str,
    },
    /// A per-element property breaks its rule.
    #[error("{field} of element {element} = {value} {rule}")]
    ElementProperty {
        /// Name of the property (`modulus`, `density`, `area`).
        field: &'static str,
        /// Element index (0-based, from the left end).
        element: usize,
        /// The offending value.
        value: f64,
        /// The rule it breaks.
        rule: &'static str,
    },
    /// A per-node value breaks its rule (node positions, initial fields).
    #[error("{field} at node {node} = {value} {rule}")]
    NodeValue {
        /// Name of the field.
        field: &'static str,
        /// Node index (0-based, from the left end).
        node: usize,
        /// The offending value.
        value: f64,
        /// The rule it breaks.
        rule: &'static str,
    },
    /// A vector has the wrong length.
    #[error("{field} has {actual} entries but the mesh needs {expected}")]
    Length {
        /// Name of the vector.
        field: &'static str,
        /// Entries required.
        expected: usize,
        /// Entries given.
        actual: usize,
    },
    /// A node index is outside the mesh.
    #[error("{field} = {node} is not a node of the mesh (nodes 0..={last})")]
    NodeIndex {
        /// Name of the field holding the index.
        field: &'static str,
        /// The index given.
        node: usize,
        /// The last valid node index.
        last: usize,
    },
    /// An iterative method reached its iteration bound (the model's numbers are beyond what it
    /// resolves, e.g. entries whose products overflow).
    #[error(transparent)]
    NoConvergence(#[from] NoConvergence),
    /// An assembled mass matrix is not positive definite (an AMM or RMM `beta` outside the
    /// range its element matrices stay definite in, or element masses that cancel).
    #[error("the {mass} mass matrix is not positive definite")]
    MassNotPositiveDefinite {
        /// The mass as outputs label it (`cmm`, `amm(0.5)`, ...).
        mass: String,
    },
    /// A scheme that runs with the lumped mass only was given another.
    #[error("{scheme} runs with the lumped mass only, not {mass}")]
    LumpedMassOnly {
        /// The scheme's name.
        scheme: String,
        /// The mass it was given, as outputs label it.
        mass: String,
    },
    /// Critical steps computed for one mass were given for a run with another.
    #[error("critical steps of the {given} mass given for a run with the {run} mass")]
    CriticalStepsOfAnotherMass {
        /// The mass the critical steps belong to.
        given: String,
        /// The mass of the run.
        run: String,
    },
    /// A load on a fixed node: it would do nothing.
    #[error(
        "a load acts on node {node}, which is fixed: it would do nothing; load a free node or free that end"
    )]
    LoadOnFixedNode {
        /// The loaded node.
        node: usize,
    },
    /// A load table whose times and values do not pair up.
    #[error(
        "a load table needs as many values as times and at least one point; it has {times} times and {values} values"
    )]
    LoadTableShape {
        /// Times given.
        times: usize,
        /// Values given.
        values: usize,
    },
    /// A contact end that is fixed (contact needs a free end to move).
    #[error("contact node {node} of body {body} is fixed: a contact end must be free")]
    ContactNodeFixed {
        /// The contact node.
        node: usize,
        /// The body it belongs to.
        body: usize,
    },
    /// A profile asked at a step the run does not reach.
    #[error("profile step {step} is after the last step {last}")]
    ProfileAfterLastStep {
        /// The profile's step.
        step: usize,
        /// The run's last step.
        last: usize,
    },
    /// A dense spectrum (an `n x n` eigenproblem) beyond the size it is meant for.
    #[error("a dense spectrum of {nodes} free nodes is too large (at most {max})")]
    DenseSpectrumTooLarge {
        /// Free nodes of the model.
        nodes: usize,
        /// The largest count allowed.
        max: usize,
    },
    /// Park's step above its limit, `alpha_e = dt/dt_e > 1` in an element (methods.md §6), when
    /// unstable runs are not allowed.
    #[error(
        "Park's scheme needs alpha_e = dt/dt_e <= 1 in every element; element {element} has alpha = {alpha:.6} (dt = {dt:e}, dt_e = {dt_e:e}): lower the Courant number"
    )]
    ParkAlphaAboveOne {
        /// The first element above the limit.
        element: usize,
        /// Its `alpha_e`.
        alpha: f64,
        /// The step.
        dt: f64,
        /// The element's critical step `h_e/c_e`.
        dt_e: f64,
    },
    /// Nothing sets the problem in motion: no load, no initial displacement or velocity.
    #[error(
        "nothing excites {what}: give a nonzero load or a nonzero initial displacement or velocity"
    )]
    NothingExcites {
        /// What is at rest ("the bar", "the contact problem").
        what: &'static str,
    },
    /// A recording interval of zero steps.
    #[error("{field} must be at least 1")]
    EveryIsZero {
        /// The interval's name (`history_every`, `energy_every`, or both).
        field: &'static str,
    },
    /// A scheme refuses a start it does not define.
    #[error("{scheme} starts from {own}; the {start} start is {whose}")]
    StartNotDefined {
        /// The scheme's name.
        scheme: &'static str,
        /// The start it uses.
        own: &'static str,
        /// The start asked for.
        start: &'static str,
        /// The scheme the asked-for start belongs to.
        whose: &'static str,
    },
    /// More steps than a run may take to reach its end through its output times.
    #[error(
        "the run needs {steps:.3e} steps of dt <= {dt:e} to reach {end_time} through the output times (common interval {interval:e}); at most {max} are allowed: raise the step, shorten the run or choose output times that are multiples of a longer common interval"
    )]
    TooManyStepsThroughOutputs {
        /// Steps needed.
        steps: f64,
        /// The largest step allowed.
        dt: f64,
        /// The end time.
        end_time: f64,
        /// The common interval of the output times.
        interval: f64,
        /// The most steps a run may take.
        max: usize,
    },
    /// More steps than a run may take at a fixed step.
    #[error(
        "the run needs {steps:.3e} steps of dt = {dt:e} to reach {end_time}; at most {max} are allowed: raise the step or shorten the run"
    )]
    TooManySteps {
        /// Steps needed.
        steps: f64,
        /// The step.
        dt: f64,
        /// The end time.
        end_time: f64,
        /// The most steps a run may take.
        max: usize,
    },
    /// An end time so short that the fixed step would take no step.
    #[error(
        "the end time {end_time} is shorter than half a step (dt = {dt:e}): keeping the step, the run would take no step"
    )]
    EndBeforeFirstStep {
        /// The end time.
        end_time: f64,
        /// The step.
        dt: f64,
    },
    /// An output time after the end of the run.
    #[error("output time {time} is after the end time {end_time}")]
    OutputAfterEnd {
        /// The output time.
        time: f64,
        /// The end time.
        end_time: f64,
    },
    /// The bisection that measures a scheme's critical step found no bracket.
    #[error("measuring the critical step of {scheme}: {what}")]
    CriticalStepNotBracketed {
        /// The scheme's label.
        scheme: String,
        /// Which side of the bracket is missing.
        what: &'static str,
    },
}

/// A symmetric tridiagonal matrix that is not positive definite: its `L D L^T` factorisation
/// met a pivot that is not positive (or not finite), so it has no SPD factor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Error)]
#[error("the matrix is not positive definite")]
pub struct NotPositiveDefinite;

/// An iterative method stopped at its iteration bound without an answer. Every iterative method
/// of the solver has such a bound: none can loop forever, whatever its input.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{method} found no answer within {iterations} iterations: {why}")]
pub struct NoConvergence {
    /// The method, e.g. `the critical-step bisection (Sturm counts of K - x M)`.
    pub method: &'static str,
    /// Its iteration bound.
    pub iterations: usize,
    /// What was left, e.g. the bracket, or the non-finite value met.
    pub why: String,
}

/// The time step is above the critical step of the scheme and unstable runs were not allowed.
#[derive(Debug, Clone, PartialEq, Error)]
#[error(
    "time step dt = {dt:.6e} exceeds the critical step dt_crit = {dt_crit:.6e} ({limit}) by {:.3e} \
     relative (Courant number {courant:.6} relative to the stiffest element; element {element} \
     controls with h/c = {element_dt:.6e}); lower the Courant number or set allow_unstable = true",
    dt / dt_crit - 1.0
)]
pub struct UnstableStepError {
    /// The requested time step.
    pub dt: f64,
    /// The limit exceeded: the exact critical step 2/omega_max, or Park's `min_e h_e/c_e`.
    pub dt_crit: f64,
    /// Which limit: `2/omega_max` or `alpha_e <= 1` (`SchemeLimit::name`).
    pub limit: &'static str,
    /// Courant number of the requested step, `dt * max_e(c_e/h_e)`.
    pub courant: f64,
    /// The element with the smallest transit time h_e/c_e.
    pub element: usize,
    /// That element's transit time.
    pub element_dt: f64,
}

/// A run that was allowed above its critical step and blew up.
#[derive(Debug, Clone, PartialEq, Error)]
#[error(
    "run diverged at step {step} (t = {time:.6e}): mechanical energy reached {energy_ratio:.3e} \
     times its reference scale; largest displacement at node {node}; Courant number {courant:.6}"
)]
pub struct DivergenceError {
    /// The step at which divergence was detected.
    pub step: usize,
    /// Its time.
    pub time: f64,
    /// Node with the largest |u| at detection.
    pub node: usize,
    /// (kinetic + strain) / energy scale at detection (infinite if non-finite values appeared).
    pub energy_ratio: f64,
    /// Courant number of the run.
    pub courant: f64,
}

/// Why a run did not complete.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RunError {
    /// Bad parameters; nothing ran.
    #[error(transparent)]
    Input(#[from] InputError),
    /// `dt` above the critical step and unstable runs not allowed; nothing ran.
    #[error(transparent)]
    Unstable(#[from] UnstableStepError),
    /// An allowed unstable run blew up; `partial` holds everything recorded before.
    #[error("{error}")]
    Diverged {
        /// Where and how it diverged.
        error: DivergenceError,
        /// Outputs up to the divergence.
        partial: Box<crate::output::RunOutput>,
    },
}
