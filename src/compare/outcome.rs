//! A whole scene compared: every record beside its reference, and the verdicts of the scene's
//! expectations.

use super::case::CaseResult;
use super::contact::ContactResult;
use super::dispersion::DispersionResult;
use super::spectrum::SpectrumResult;
use super::sweep::SweepResult;
use super::verdict::Verdict;

/// Everything a scene produced, compared: time-stepping results, spectra, dispersion, contact,
/// sweeps, and the expectation verdicts.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneOutcome {
    /// Time-stepping case results, in case order.
    pub results: Vec<CaseResult>,
    /// Spectrum case results, in case order.
    pub spectra: Vec<SpectrumResult>,
    /// Dispersion case results, in case order.
    pub dispersion: Vec<DispersionResult>,
    /// Contact case results, in case order.
    pub contact: Vec<ContactResult>,
    /// Contact stability sweeps.
    pub sweeps: Vec<SweepResult>,
    /// Verdicts of the scene's expectations.
    pub verdicts: Vec<Verdict>,
}

impl SceneOutcome {
    /// True when every expectation holds.
    pub fn passed(&self) -> bool {
        self.verdicts.iter().all(|v| v.pass)
    }
}
