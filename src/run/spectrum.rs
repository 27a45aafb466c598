//! Computing the spectra of a spectrum case (the seed's Fig. 6) with courant's solver.

use crate::results::spectrum::SpectrumRecord;
use crate::scene::spectrum::SpectrumCase;
use courant_solver::InputError;
use std::time::Instant;

/// The angular frequencies of the case's bar for each of its mass kinds (dense generalized
/// eigen-solution, ascending).
///
/// # Errors
/// The mass matrix cannot be built (e.g. not positive definite).
pub fn run_spectrum(case: &SpectrumCase) -> Result<SpectrumRecord, InputError> {
    let started = Instant::now();
    let computed = case
        .masses
        .iter()
        .map(|&kind| courant_solver::analysis::angular_frequencies(&case.model, kind))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(SpectrumRecord {
        case: case.name.clone(),
        masses: case.masses.clone(),
        computed,
        wall_time: started.elapsed(),
    })
}
