//! Running a case and comparing it with its reference.

use crate::metrics::ErrorNorms;
use crate::reference::Reference;
use crate::scene::Case;
use courant_references::Energies;
use courant_solver::Mesh;
use courant_solver::{
    CentralDifference, CriticalStep, DivergenceError, EnergyLog, NodeHistory, RunError, RunOutput,
    SchemeLimit,
};
use rayon::prelude::*;
use std::time::{Duration, Instant};

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

/// How a case ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Status {
    /// All steps taken.
    Completed,
    /// An allowed unstable run blew up; outputs hold what was recorded before.
    Diverged(DivergenceError),
}

/// Everything a case produced.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseResult {
    /// Case name.
    pub case: String,
    /// The time-stepping scheme that ran: `cd`, or Park's with its stepping, element-acceleration
    /// variant and blend, e.g. `park-lts-free theta=0.5` (methods.md §6).
    pub scheme: String,
    /// Number of elements.
    pub elements: usize,
    /// Courant number relative to the stiffest element.
    pub courant: f64,
    /// Time step.
    pub dt: f64,
    /// Steps planned.
    pub steps_planned: usize,
    /// Steps taken.
    pub steps: usize,
    /// Critical-step estimates.
    pub critical: CriticalStep,
    /// The stability limit of the scheme that ran (CD's `2/omega_max`, Park's `alpha_e <= 1`).
    pub limit: SchemeLimit,
    /// Number of distinct profile times requested.
    pub profiles_requested: usize,
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
    /// Completed or diverged.
    pub status: Status,
    /// Wall time of the integration (not of the comparison).
    pub wall_time: Duration,
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

/// A case's integration before its comparison with the reference.
struct Integration {
    output: RunOutput,
    status: Status,
    wall_time: Duration,
}

/// Integrate a case. A divergence (allowed unstable runs only) is a status, not an error: its
/// partial outputs are kept.
fn integrate(case: &Case) -> Result<Integration, RunError> {
    let started = Instant::now();
    let outcome = case
        .integrator
        .run(&case.model, case.plan.steps, &case.request);
    let wall_time = started.elapsed();
    let (output, status) = match outcome {
        Ok(output) => (output, Status::Completed),
        Err(RunError::Diverged { error, partial }) => (*partial, Status::Diverged(error)),
        Err(other) => return Err(other),
    };
    Ok(Integration {
        output,
        status,
        wall_time,
    })
}

/// One exact profile: a reference on a mesh at a time, compared by value (the reference's
/// parameters, the node coordinates and the time bit for bit).
struct ProfileKey<'a> {
    reference: &'a Reference,
    mesh: &'a Mesh,
    time: f64,
}

impl ProfileKey<'_> {
    fn matches(&self, reference: &Reference, mesh: &Mesh, time: f64) -> bool {
        let (a, b) = (self.mesh.nodes(), mesh.nodes());
        self.time.to_bits() == time.to_bits()
            && a.len() == b.len()
            && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
            && self.reference == reference
    }
}

/// Exact profiles (element averages and extreme) evaluated once for all cases of a scene: the
/// cases share their reference, so a Courant or scheme sweep needs each exact profile once. The
/// cache is filled before any comparison, every distinct profile evaluated in parallel, and only
/// read afterwards; each value is a pure function of its key (the references use no threads),
/// so results are bit-identical whatever the thread count and whether or not a value came from
/// the cache.
#[derive(Default)]
struct ProfileCache<'a> {
    entries: Vec<(ProfileKey<'a>, (Vec<f64>, f64))>,
}

impl<'a> ProfileCache<'a> {
    /// Evaluate every distinct exact profile that `runs` recorded, in parallel, in the order of
    /// first appearance.
    fn for_runs(runs: &[(&'a Case, &Integration)]) -> Self {
        let mut keys: Vec<ProfileKey<'a>> = Vec::new();
        for (case, run) in runs {
            let Some(reference) = case.reference.as_ref() else {
                continue;
            };
            let mesh = case.model.bar().mesh();
            for p in &run.output.profiles {
                if !keys.iter().any(|k| k.matches(reference, mesh, p.time)) {
                    keys.push(ProfileKey {
                        reference,
                        mesh,
                        time: p.time,
                    });
                }
            }
        }
        let values: Vec<(Vec<f64>, f64)> = keys
            .par_iter()
            .map(|k| evaluate(k.reference, k.mesh, k.time))
            .collect();
        Self {
            entries: keys.into_iter().zip(values).collect(),
        }
    }

    /// The exact profile: from the cache, or evaluated now when it is not there.
    fn exact(&self, reference: &Reference, mesh: &Mesh, t: f64) -> (Vec<f64>, f64) {
        self.entries
            .iter()
            .find(|(k, _)| k.matches(reference, mesh, t))
            .map_or_else(|| evaluate(reference, mesh, t), |(_, v)| v.clone())
    }
}

/// Exact element averages of the stress at `t` and the extreme stress of the field.
fn evaluate(reference: &Reference, mesh: &Mesh, t: f64) -> (Vec<f64>, f64) {
    (reference.element_averages(mesh, t), reference.extreme(t))
}

/// Run a case and compare it with its reference. A divergence (allowed unstable runs only) is a
/// status, not an error: its partial outputs are kept.
pub fn run_case(case: &Case) -> Result<CaseResult, RunError> {
    let run = integrate(case)?;
    Ok(compare(case, run, &ProfileCache::default()))
}

/// What [`CaseResult::scheme`] says of an integrator.
pub fn scheme_label(integrator: &CentralDifference) -> String {
    integrator.park.map_or_else(
        || "cd".to_string(),
        |park| format!("{} theta={}", park.label(), park.theta),
    )
}

fn compare(case: &Case, run: Integration, cache: &ProfileCache<'_>) -> CaseResult {
    let Integration {
        output,
        status,
        wall_time,
    } = run;
    let mesh = case.model.bar().mesh();
    let reference = case.reference.as_ref();
    let x: Vec<f64> = (0..mesh.element_count())
        .map(|e| mesh.midpoint(e))
        .collect();
    let profiles = output
        .profiles
        .into_iter()
        .map(|p| {
            let exact = reference.map(|r| cache.exact(r, mesh, p.time));
            let norms = reference.zip(exact.as_ref()).map(|(r, (avg, env))| {
                ErrorNorms::of(mesh, &p.stress, avg, *env, r.stress_scale(), r.load_sign())
            });
            ProfileComparison {
                time: p.time,
                step: p.step,
                x: x.clone(),
                stress: p.stress,
                reference: exact.map(|e| e.0),
                norms,
            }
        })
        .collect();
    let histories = output
        .histories
        .into_iter()
        .map(|h| {
            let exact = reference.map(|r: &Reference| {
                h.samples
                    .iter()
                    .map(|s| {
                        (
                            r.displacement(mesh, h.x, s.time).unwrap_or(f64::NAN),
                            r.velocity(mesh, h.x, s.time).unwrap_or(f64::NAN),
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
        output
            .energy
            .samples
            .iter()
            .map(|s| r.energies(s.time))
            .collect::<Option<Vec<_>>>()
    });
    CaseResult {
        case: case.name.clone(),
        scheme: scheme_label(&case.integrator),
        elements: mesh.element_count(),
        courant: output.courant,
        dt: output.dt,
        steps_planned: case.plan.steps,
        steps: output.steps,
        critical: case.critical,
        limit: case.limit,
        profiles_requested: {
            let mut steps = case.request.profile_steps.clone();
            steps.sort_unstable();
            steps.dedup();
            steps.len()
        },
        profiles,
        histories,
        energy: output.energy,
        energy_reference,
        reference: reference.map(|r| r.name()),
        status,
        wall_time,
    }
}

/// Everything a scene produced: time-stepping results, spectra, expectation verdicts.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneOutcome {
    /// Time-stepping case results, in case order.
    pub results: Vec<CaseResult>,
    /// Spectrum case results, in case order.
    pub spectra: Vec<crate::spectra::SpectrumResult>,
    /// Dispersion case results, in case order.
    pub dispersion: Vec<crate::dispersion::DispersionResult>,
    /// Contact case results, in case order.
    pub contact: Vec<crate::contact_study::ContactResult>,
    /// Contact stability sweeps.
    pub sweeps: Vec<crate::contact_study::SweepResult>,
    /// Verdicts of the scene's expectations.
    pub verdicts: Vec<crate::expect::Verdict>,
}

impl SceneOutcome {
    /// True when every expectation holds.
    pub fn passed(&self) -> bool {
        self.verdicts.iter().all(|v| v.pass)
    }
}

/// Run every case of a scene and check its expectations. The cases are independent: each list
/// (time-stepping cases, spectra, dispersion, contact cases, sweeps) runs in parallel (rayon),
/// results keep the case order, and an error is that of the first failing case in that order,
/// so the outcome does not depend on the thread count.
pub fn run_scene(scene: &crate::Scene) -> Result<SceneOutcome, RunError> {
    let runs = in_order(scene.cases.par_iter().map(integrate).collect())?;
    let pairs: Vec<(&Case, &Integration)> = scene.cases.iter().zip(&runs).collect();
    let cache = ProfileCache::for_runs(&pairs);
    let results = scene
        .cases
        .par_iter()
        .zip(runs)
        .map(|(case, run)| compare(case, run, &cache))
        .collect();
    let spectra = in_order(
        scene
            .spectra
            .par_iter()
            .map(crate::spectra::run_spectrum)
            .collect(),
    )?;
    let dispersion = in_order(
        scene
            .dispersion
            .par_iter()
            .map(crate::dispersion::run_dispersion)
            .collect(),
    )?;
    let contact = in_order(
        scene
            .contact
            .par_iter()
            .map(crate::contact_study::run_contact)
            .collect(),
    )?;
    let sweeps = in_order(
        scene
            .contact_sweeps
            .par_iter()
            .map(crate::contact_study::run_sweep)
            .collect(),
    )?;
    let mut outcome = SceneOutcome {
        results,
        spectra,
        dispersion,
        contact,
        sweeps,
        verdicts: Vec::new(),
    };
    outcome.verdicts = crate::expect::evaluate(scene, &outcome);
    Ok(outcome)
}

/// The values in order, or the first error in order (not whichever thread failed first): collect
/// a parallel map into a `Vec` of results first, then this.
pub(crate) fn in_order<T, E>(results: Vec<Result<T, E>>) -> Result<Vec<T>, E> {
    results.into_iter().collect()
}
