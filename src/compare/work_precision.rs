//! The points of a work-precision study: what each run cost (elements, steps, wall time) beside
//! the error it bought.

use crate::results::table::Table;
use crate::scene::studies::work_precision::WorkPrecisionStudy;

/// One run of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPoint {
    /// Scheme or mass label (the case name without its mesh and Courant parts).
    pub method: String,
    /// The Courant setting of its variant ([`CourantVariant::courant`](crate::scene::studies::work_precision::CourantVariant::courant)), when the study has
    /// several.
    pub setting: Option<&'static str>,
    /// Courant number of the run relative to the stiffest element, `c dt / h_min`.
    pub courant: f64,
    /// The critical Courant number of the case's scheme (exact, methods.md §5 and §7).
    pub critical_courant: f64,
    /// Elements.
    pub elements: usize,
    /// Steps.
    pub steps: usize,
    /// Internal-force evaluations `K u` per step of the scheme (central difference 1; Park and
    /// Noh-Bathe 2; a contact scheme 1, its bulk being central difference).
    pub force_evaluations: usize,
    /// Normalised L1 error of the stress.
    pub l1: f64,
    /// Wall time of the integration, in seconds.
    pub wall_time: f64,
}

impl WorkPoint {
    /// Element force evaluations, `N x steps x K u per step`: the work in units of one element's
    /// internal force, whatever the scheme.
    pub fn element_force_evaluations(&self) -> usize {
        self.elements * self.steps * self.force_evaluations
    }

    /// Legend label: the method, with its Courant setting when the study's schemes run at
    /// different ones.
    pub fn label(&self) -> String {
        match self.setting {
            Some(setting) => format!("{} ({setting})", self.method),
            None => self.method.clone(),
        }
    }
}

/// Deterministic table: `method, Co, Co_crit, N, steps, node_steps, l1, force_evals_per_step,
/// element_force_evals` (`Co` relative to the stiffest element, `Co_crit` the exact critical
/// Courant number of the case's scheme).
pub fn table(points: &[WorkPoint]) -> Table {
    let mut t = Table::new(&[
        "method",
        "Co",
        "Co_crit",
        "N",
        "steps",
        "node_steps",
        "l1",
        "force_evals_per_step",
        "element_force_evals",
    ]);
    for p in points {
        t.push(vec![
            p.method.as_str().into(),
            p.courant.into(),
            p.critical_courant.into(),
            p.elements.into(),
            p.steps.into(),
            (p.elements * p.steps).into(),
            p.l1.into(),
            p.force_evaluations.into(),
            p.element_force_evaluations().into(),
        ]);
    }
    t
}

/// `study, method, Co, N, steps, l1, wall_time_s` of every study's runs (machine-dependent).
pub fn cpu_table(studies: &[WorkPrecisionStudy], work: &[Vec<WorkPoint>]) -> Table {
    let mut t = Table::new(&["study", "method", "Co", "N", "steps", "l1", "wall_time_s"]);
    for (study, points) in studies.iter().zip(work) {
        for p in points {
            t.push(vec![
                study.name.into(),
                p.method.as_str().into(),
                p.courant.into(),
                p.elements.into(),
                p.steps.into(),
                p.l1.into(),
                p.wall_time.into(),
            ]);
        }
    }
    t
}
