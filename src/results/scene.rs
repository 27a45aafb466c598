//! Every record of one scene.

use super::case::CaseRecord;
use super::contact::ContactRecord;
use super::dispersion::DispersionRecord;
use super::spectrum::SpectrumRecord;
use super::sweep::SweepRecord;

/// The records of a scene, each list in case order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SceneRecords {
    /// Time-stepping cases.
    pub cases: Vec<CaseRecord>,
    /// Spectrum cases.
    pub spectra: Vec<SpectrumRecord>,
    /// Dispersion cases.
    pub dispersion: Vec<DispersionRecord>,
    /// Contact cases.
    pub contact: Vec<ContactRecord>,
    /// Contact stability sweeps.
    pub sweeps: Vec<SweepRecord>,
}
