//! What a scene is once validated: its cases, ready to run, and its expectations.

use super::contact::{ContactCase, StabilitySweep};
use super::dispersion::DispersionCase;
use super::expectation::Expectation;
use super::finding::Finding;
use super::reference::Reference;
use super::spectrum::SpectrumCase;
use courant_solver::{CriticalStep, Integration, Model, OutputRequest, SchemeLimit, TimePlan};
use std::sync::Arc;

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
    pub spectra: Vec<SpectrumCase>,
    /// The dispersion cases (dispersion scenes only).
    pub dispersion: Vec<DispersionCase>,
    /// The contact cases (contact scenes only).
    pub contact: Vec<ContactCase>,
    /// The contact stability sweeps (contact stability scenes only).
    pub contact_sweeps: Vec<StabilitySweep>,
    /// Expectations every run is checked against.
    pub expectations: Vec<Expectation>,
    /// A stability scene: every case gets a stability verdict (predicted against observed).
    pub stability: bool,
    /// Disagreements with stability theory the scene states, with their sources.
    pub findings: Vec<Finding>,
}

/// One runnable case of a scene.
#[derive(Debug, Clone)]
pub struct Case {
    /// Case name, e.g. `co0.5`.
    pub name: String,
    /// The model (shared by the cases of a sweep: one copy of its arrays, not one per case).
    pub model: Arc<Model>,
    /// The scheme and its run settings, with the final time step.
    pub integrator: Integration,
    /// The time-step plan.
    pub plan: TimePlan,
    /// What to record.
    pub request: OutputRequest,
    /// Critical-step estimates of the model.
    pub critical: CriticalStep,
    /// The stability limit of the case's scheme (CD's `2/omega_max`, Park's `alpha_e <= 1`,
    /// Noh-Bathe's `Omega_crit(p)/omega_max`, ...).
    pub limit: SchemeLimit,
    /// Analytic reference, if the scene names one.
    pub reference: Option<Reference>,
    /// Transit time of the bar, `T = sum_e h_e/c_e`.
    pub transit_time: f64,
    /// The scene states its times in transit times (`[output] time_unit = "transit"`): reports
    /// show them as `t/T`.
    pub times_in_transits: bool,
    /// The scheme parameters the scene lists (a sweep, `theta = [0, 0.5, 1]`) with this case's
    /// value of each; empty when none is a list.
    pub swept: Vec<(String, courant_solver::integrator::ParameterValue)>,
    /// Every scheme parameter the scene gives this case's scheme (listed or not).
    pub parameters: Vec<(String, courant_solver::integrator::ParameterValue)>,
}
