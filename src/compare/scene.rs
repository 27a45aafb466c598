//! Comparing every record of a scene.

use super::cache::ProfileCache;
use super::case::compare_case;
use super::contact::compare_contact;
use super::dispersion::compare_dispersion;
use super::expect::evaluate;
use super::outcome::SceneOutcome;
use super::spectrum::compare_spectrum;
use super::stability::stability_rows;
use super::stability_verdicts::stability_verdicts;
use super::sweep::compare_sweep;
use crate::results::scene::SceneRecords;
use crate::scene::cases::Scene;
use courant_references::ReferenceError;
use rayon::prelude::*;

/// Compare every record of `scene` (in case order, as `run::scene::run_scene` returns them) with
/// its reference and check the scene's expectations. The exact profiles the cases share are
/// evaluated once, in parallel, before the cases are compared in parallel; every value is a pure
/// function of its inputs, so the outcome does not depend on the thread count.
///
/// # Errors
/// A closed form of the contact stability sweep refuses its parameters.
pub fn compare_scene(scene: &Scene, records: SceneRecords) -> Result<SceneOutcome, ReferenceError> {
    let SceneRecords {
        cases,
        spectra,
        dispersion,
        contact,
        sweeps,
    } = records;
    let needed: Vec<_> = scene
        .cases
        .iter()
        .zip(&cases)
        .filter_map(|(case, record)| {
            case.reference.as_ref().map(|r| {
                let times = record.profiles.iter().map(|p| p.time).collect();
                (r, &record.mesh, times)
            })
        })
        .collect();
    let cache = ProfileCache::for_runs(&needed);
    let results = scene
        .cases
        .par_iter()
        .zip(cases)
        .map(|(case, record)| compare_case(record, case.reference.as_ref(), &cache))
        .collect();
    let mut outcome = SceneOutcome {
        results,
        spectra: scene
            .spectra
            .iter()
            .zip(spectra)
            .map(|(case, record)| compare_spectrum(record, case))
            .collect(),
        dispersion: scene
            .dispersion
            .iter()
            .zip(dispersion)
            .map(|(case, record)| compare_dispersion(record, case))
            .collect(),
        contact: scene
            .contact
            .iter()
            .zip(contact)
            .map(|(case, record)| compare_contact(record, case.reference.history(), case.force))
            .collect(),
        sweeps: sweeps
            .into_iter()
            .map(compare_sweep)
            .collect::<Result<_, _>>()?,
        verdicts: Vec::new(),
    };
    outcome.verdicts = evaluate(scene, &outcome);
    let rows = stability_rows(scene, &outcome);
    outcome.verdicts.extend(stability_verdicts(&rows));
    Ok(outcome)
}
