//! Running every case of a scene.

use crate::io::parallel::in_order;
use crate::results::scene::SceneRecords;
use crate::scene::cases::Scene;
use courant_solver::RunError;
use rayon::prelude::*;

/// Run every case of a scene. The cases are independent: each list (time-stepping cases,
/// spectra, dispersion, contact cases, sweeps) runs in parallel (rayon), records keep the case
/// order, and an error is that of the first failing case in that order, so the records do not
/// depend on the thread count.
///
/// # Errors
/// The first case (in order) the solver refuses.
pub fn run_scene(scene: &Scene) -> Result<SceneRecords, RunError> {
    Ok(SceneRecords {
        cases: in_order(
            scene
                .cases
                .par_iter()
                .map(super::stepping::run_case)
                .collect(),
        )?,
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
