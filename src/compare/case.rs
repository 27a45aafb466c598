//! A time-stepping record beside its reference: exact element averages and error norms at each
//! profile time, exact nodal histories and energies.

use super::cache::ProfileCache;
use super::exact::ExactOnMesh;
use super::norms::ErrorNorms;
use crate::results::case::{CaseRecord, RunFacts};
use crate::scene::reference::Reference;
use courant_references::Energies;
use courant_solver::{EnergyLog, NodeHistory};

/// A stress profile beside its reference.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileComparison {
    /// Time of the profile.
    pub time: f64,
    /// Step index.
    pub step: usize,
    /// Element midpoints.
    pub x: Vec<f64>,
    /// Element stresses.
    pub stress: Vec<f64>,
    /// Exact element averages, if there is a reference.
    pub reference: Option<Vec<f64>>,
    /// Error norms, if there is a reference.
    pub norms: Option<ErrorNorms>,
}

/// A nodal history beside its reference.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryComparison {
    /// The recorded history.
    pub history: NodeHistory,
    /// Exact `(u, v)` at each sample, if there is a reference.
    pub reference: Option<Vec<(f64, f64)>>,
}

/// A time-stepping case's record compared with its reference.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseResult {
    /// The case, scheme, step, cost and end of the run (as recorded).
    pub run: RunFacts,
    /// Number of elements.
    pub elements: usize,
    /// Profiles recorded (fewer than requested when the run diverged first).
    pub profiles: Vec<ProfileComparison>,
    /// Histories.
    pub histories: Vec<HistoryComparison>,
    /// Energy log.
    pub energy: EnergyLog,
    /// Exact energies at each energy sample, if there is a reference.
    pub energy_reference: Option<Vec<Energies>>,
    /// Reference name, if any.
    pub reference: Option<&'static str>,
}

impl CaseResult {
    /// Energy dissipated by the end of the run relative to the energy scale,
    /// `-(balance error at the last sample) / scale`: round-off for CD, the scheme's numerical
    /// dissipation for Park.
    pub fn energy_lost(&self) -> f64 {
        let last = self.energy.samples.last().map_or(0.0, |s| s.balance_error);
        if self.energy.scale > 0.0 {
            -last / self.energy.scale
        } else {
            0.0
        }
    }

    /// Worst norms over all profiles.
    pub fn worst_norms(&self) -> Option<ErrorNorms> {
        ErrorNorms::worst(self.profiles.iter().filter_map(|p| p.norms))
    }
}

/// Compare a record with its reference (`None`: nothing to compare with; the result then carries
/// the record alone). Exact profiles come from `cache` when it has them.
pub fn compare_case(
    record: CaseRecord,
    reference: Option<&Reference>,
    cache: &ProfileCache,
) -> CaseResult {
    let CaseRecord {
        run,
        mesh,
        profiles,
        histories,
        energy,
    } = record;
    // The midpoints are made per profile (not one array cloned): with one profile a run holds
    // them once.
    let midpoints = || {
        (0..mesh.element_count())
            .map(|e| mesh.midpoint(e))
            .collect()
    };
    let profiles = profiles
        .into_iter()
        .map(|p| {
            let exact = reference.map(|r| cache.exact(r, &mesh, p.time));
            let norms = reference.zip(exact.as_ref()).map(|(r, (avg, env))| {
                ErrorNorms::of(&mesh, &p.stress, avg, *env, r.stress_scale(), r.load_sign())
            });
            ProfileComparison {
                time: p.time,
                step: p.step,
                x: midpoints(),
                stress: p.stress,
                reference: exact.map(|e| e.0),
                norms,
            }
        })
        .collect();
    let histories = histories
        .into_iter()
        .map(|h| {
            let exact = reference.map(|r: &Reference| {
                h.samples
                    .iter()
                    .map(|s| {
                        (
                            r.displacement(&mesh, h.x, s.time).unwrap_or(f64::NAN),
                            r.velocity(&mesh, h.x, s.time).unwrap_or(f64::NAN),
                        )
                    })
                    .collect()
            });
            HistoryComparison {
                history: h,
                reference: exact,
            }
        })
        .collect();
    let energy_reference = reference.and_then(|r| {
        energy
            .samples
            .iter()
            .map(|s| r.energies(s.time))
            .collect::<Option<Vec<_>>>()
    });
    CaseResult {
        run,
        elements: mesh.element_count(),
        profiles,
        histories,
        energy,
        energy_reference,
        reference: reference.map(|r| r.name()),
    }
}
