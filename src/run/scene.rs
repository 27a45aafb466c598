//! Running every case of a scene.

use super::contact::ContactRunError;
use crate::io::parallel::in_order;
use crate::results::case::CaseRecord;
use crate::results::scene::SceneRecords;
use crate::scene::cases::{Case, Scene};
use courant_solver::RunError;
use rayon::prelude::*;

/// Run every case of a scene. The cases are independent: each list (time-stepping cases,
/// spectra, dispersion, contact cases, sweeps) runs in parallel (rayon), records keep the case
/// order, and an error is that of the first failing case in that order, so the records do not
/// depend on the thread count.
///
/// # Errors
/// The first case (in order) the solver refuses.
pub fn run_scene(scene: &Scene) -> Result<SceneRecords, RefusedRun> {
    Ok(SceneRecords {
        cases: run_cases(&scene.cases)?,
        spectra: in_order(
            scene
                .spectra
                .par_iter()
                .map(super::spectrum::run_spectrum)
                .collect(),
        )?,
        dispersion: in_order(
            scene
                .dispersion
                .par_iter()
                .map(super::dispersion::run_dispersion)
                .collect(),
        )?,
        contact: in_order(
            scene
                .contact
                .par_iter()
                .map(super::contact::run_contact)
                .collect(),
        )?,
        sweeps: in_order(
            scene
                .contact_sweeps
                .par_iter()
                .map(super::sweep::run_sweep)
                .collect(),
        )?,
    })
}

/// Every case, in input order: those whose run uses several threads
/// ([`courant_solver::Integration::threads`]: lumped runs from 1e5 nodes on) one at a time, the
/// others in parallel (one case per core), so that two multi-threaded cases of one scene never
/// share the cores (scenes of a report and convergence studies still run in parallel with each
/// other). The records do not depend on the order of running.
fn run_cases(cases: &[Case]) -> Result<Vec<CaseRecord>, RunError> {
    let threaded =
        |case: &Case| super::threads::with_setting(&case.integrator).threads(&case.model) > 1;
    let mut records: Vec<Option<Result<CaseRecord, RunError>>> = cases
        .par_iter()
        .map(|case| (!threaded(case)).then(|| super::stepping::run_case(case)))
        .collect();
    for (record, case) in records.iter_mut().zip(cases) {
        if record.is_none() {
            *record = Some(super::stepping::run_case(case));
        }
    }
    in_order(records.into_iter().flatten().collect())
}

/// A case the solver refused: a time-stepping, spectrum or dispersion case ([`RunError`]) or a
/// contact case ([`ContactRunError`], whose stability limit is the contact scheme's).
#[derive(Debug, thiserror::Error)]
pub enum RefusedRun {
    /// A time-stepping, spectrum, dispersion or sweep case.
    #[error(transparent)]
    Case(#[from] RunError),
    /// A contact case.
    #[error(transparent)]
    Contact(#[from] ContactRunError),
}

impl From<courant_solver::InputError> for RefusedRun {
    fn from(e: courant_solver::InputError) -> Self {
        Self::Case(RunError::Input(e))
    }
}
