//! The record of a time-stepping case.

use courant_solver::{
    CriticalStep, DivergenceError, EnergyLog, Mesh, NodeHistory, SchemeLimit, StressProfile,
};
use std::time::Duration;

/// How a case ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Status {
    /// All steps taken.
    Completed,
    /// An allowed unstable run blew up; outputs hold what was recorded before.
    Diverged(DivergenceError),
}

/// What a time-stepping run states about itself, the same in its record and in its comparison
/// (`compare::case::CaseResult`): the case and scheme, the step, what it cost and how it ended.
#[derive(Debug, Clone, PartialEq)]
pub struct RunFacts {
    /// Case name.
    pub case: String,
    /// The time-stepping scheme that ran: `cd`, or Park's with its stepping, element-acceleration
    /// variant and blend, e.g. `park-lts-free theta=0.5` (methods.md §6).
    pub scheme: String,
    /// Courant number relative to the stiffest element.
    pub courant: f64,
    /// Time step.
    pub dt: f64,
    /// Steps planned.
    pub steps_planned: usize,
    /// Steps taken.
    pub steps: usize,
    /// Critical-step estimates of the model and mass.
    pub critical: CriticalStep,
    /// The stability limit of the scheme that ran (CD's `2/omega_max`, Park's `alpha_e <= 1`).
    pub limit: SchemeLimit,
    /// Number of distinct profile times requested.
    pub profiles_requested: usize,
    /// Completed or diverged.
    pub status: Status,
    /// Wall time of the integration (not of any comparison).
    pub wall_time: Duration,
}

/// What a time-stepping run produced: element stresses at the profile times, nodal histories,
/// the energy log, and its facts (what it cost among them).
#[derive(Debug, Clone, PartialEq)]
pub struct CaseRecord {
    /// The case, scheme, step, cost and end of the run.
    pub run: RunFacts,
    /// The mesh the stresses live on (element `e` spans nodes `e` and `e + 1`; shared with the comparison's cache, never copied).
    pub mesh: std::sync::Arc<Mesh>,
    /// Element-stress profiles recorded (fewer than requested when the run diverged first).
    pub profiles: Vec<StressProfile>,
    /// Nodal histories.
    pub histories: Vec<NodeHistory>,
    /// Energy log.
    pub energy: EnergyLog,
}
