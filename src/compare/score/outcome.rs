//! What scoring produces: every case file of a result set beside its reference (norms, force
//! or spectrum measures), its diagnostics, the verdicts of the scene's expectations (and those
//! that cannot be measured from files), and convergence studies across sets.

use super::applies::Applies;
use super::diagnostics::{DiagnosticRow, Diagnostics};
use crate::compare::contact::ForceErrors;
use crate::compare::convergence::ConvergenceResult;
use crate::compare::norms::ErrorNorms;
use crate::compare::verdict::Verdict;
use crate::results::exchange::error::{ExchangeError, ExchangeErrors};
use crate::scene::expectation::Metric;
use serde::Deserialize;
use thiserror::Error;

/// Why a result set cannot be scored.
#[derive(Debug, Error)]
pub enum ScoreError {
    /// Files that are not valid exchange data, or do not fit the scene (each with file, line,
    /// column, key), all of them.
    #[error(transparent)]
    Input(#[from] ExchangeErrors),
    /// The scene has nothing a result file could be graded against.
    #[error("{0}")]
    Scene(String),
}

impl From<ExchangeError> for ScoreError {
    fn from(e: ExchangeError) -> Self {
        ScoreError::Input(e.into())
    }
}

/// One stress profile beside the exact solution.
#[derive(Debug, Clone, PartialEq)]
pub struct ScoredProfile {
    /// Output time.
    pub time: f64,
    /// Element midpoints or points.
    pub x: Vec<f64>,
    /// The file's stresses.
    pub stress: Vec<f64>,
    /// Exact element averages or point values.
    pub reference: Vec<f64>,
    /// Norms against them (those of `courant run`).
    pub norms: ErrorNorms,
}

/// A contact force history beside 1D wave theory.
#[derive(Debug, Clone, PartialEq)]
pub struct ScoredForce {
    /// Sample times.
    pub time: Vec<f64>,
    /// The file's forces.
    pub force: Vec<f64>,
    /// Exact forces at the sample times.
    pub reference: Vec<f64>,
    /// Impulse of the samples (trapezoid rule).
    pub impulse: f64,
    /// `|impulse - exact| / exact`.
    pub impulse_error: f64,
    /// First-plateau force of the reference.
    pub plateau: f64,
    /// Plateau, duration and L1 errors, largest force (those of `courant run`).
    pub errors: ForceErrors,
}

/// A spectrum beside the closed forms.
#[derive(Debug, Clone, PartialEq)]
pub struct ScoredSpectrum {
    /// `(mass label, mode, omega, closed form)` per row, in file order.
    pub rows: Vec<(String, usize, f64, f64)>,
    /// Largest `|omega - closed| / closed` over the elastic modes.
    pub deviation: f64,
}

/// What a case file holds, beside its reference.
#[derive(Debug, Clone, PartialEq)]
pub enum Scored {
    /// Stress profiles (`points`: point values rather than element averages).
    Profiles {
        /// Profiles in time order.
        profiles: Vec<ScoredProfile>,
        /// Point values (weighted by their cells) rather than element averages.
        points: bool,
    },
    /// A force history.
    Force(ScoredForce),
    /// A spectrum.
    Spectrum(ScoredSpectrum),
}

/// What was read from a case file: counted from its rows, never taken from `results.toml`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Read {
    /// Values per profile (elements or points; the most of any profile), samples of a force
    /// history, rows of a spectrum.
    pub values: usize,
    /// Output times (profiles; 1 for a force history or a spectrum).
    pub times: usize,
    /// Data rows.
    pub rows: usize,
}

/// One case file of a set, scored.
#[derive(Debug, Clone, PartialEq)]
pub struct ScoredCase {
    /// Case name.
    pub case: String,
    /// Path of the file.
    pub file: String,
    /// Scheme named in `results.toml`.
    pub scheme: Option<String>,
    /// Whether the case's signature rows apply to the file.
    pub applies: Applies,
    /// Mass label named in `results.toml` (as the scene writes it, e.g. `amm(0.5)`).
    pub mass: Option<String>,
    /// Elements (of the file's first profile, or from `results.toml` for point values); `None`
    /// for a force history.
    pub elements: Option<usize>,
    /// What was read from the file.
    pub read: Read,
    /// The time step the diagnostics count in and where it came from.
    pub dt: Option<(f64, &'static str)>,
    /// The reference that produced the exact values.
    pub reference: &'static str,
    /// The file beside its reference.
    pub scored: Scored,
    /// Time level, sign and load convention.
    pub diagnostics: Diagnostics,
}

impl ScoredCase {
    /// Worst norms over the profiles (stress profiles only).
    pub fn worst_norms(&self) -> Option<ErrorNorms> {
        match &self.scored {
            Scored::Profiles { profiles, .. } => {
                ErrorNorms::worst(profiles.iter().map(|p| p.norms))
            }
            _ => None,
        }
    }
}

/// Why an expectation gives no verdict on a set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SkipKind {
    /// A signature row of a scheme, parameters or mass the file does not declare.
    NotApplicable,
    /// The set has no file for the case, or the file no profile at the time (`--require-all`
    /// makes these failures).
    NotSupplied,
    /// Files cannot carry it (energies, divergence, critical steps) or the data cannot decide
    /// it.
    NotMeasurable,
}

impl SkipKind {
    /// How the row's verdict column reads.
    pub fn word(self) -> &'static str {
        match self {
            SkipKind::NotApplicable => "n/a",
            SkipKind::NotSupplied => "missing",
            SkipKind::NotMeasurable => "skip",
        }
    }
}

/// An expectation that gives no verdict on a set: not applicable to the file, not supplied,
/// or not measurable from files.
#[derive(Debug, Clone, PartialEq)]
pub struct Skipped {
    /// Why there is no verdict.
    pub kind: SkipKind,
    /// Case name.
    pub case: String,
    /// Metric.
    pub metric: Metric,
    /// The metric as the verdict would name it (`l1 / co0.5`, `mass_deviation rmm0.5 vs amm0.5`).
    pub label: String,
    /// Profile time, if the expectation names one.
    pub at: Option<f64>,
    /// Why it is not measured.
    pub reason: String,
    /// Source of truth of the expectation.
    pub source: String,
}

/// A result set scored against a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct ScoredSet {
    /// The set's label (its directory as given).
    pub label: String,
    /// Producing code (`-` when unknown).
    pub code: String,
    /// Its version (`-` when unknown).
    pub version: String,
    /// Every case file, in case order of the scene.
    pub cases: Vec<ScoredCase>,
    /// Verdicts of the scene's expectations on the set's files.
    pub verdicts: Vec<Verdict>,
    /// Expectations not measured, with the reason.
    pub skipped: Vec<Skipped>,
    /// Cases of the scene with no file in this set.
    pub missing_cases: Vec<String>,
    /// Whether what is not supplied fails the set (`courant score --require-all`).
    pub require_all: bool,
    /// Findings stated for the set (`super::stated`), each with whether it holds.
    pub stated: Vec<StatedOutcome>,
}

impl ScoredSet {
    /// Expectations skipped because their case or time is not supplied.
    pub fn not_supplied(&self) -> usize {
        self.skipped
            .iter()
            .filter(|s| s.kind == SkipKind::NotSupplied)
            .count()
    }

    /// True when diagnostic `name` of `case` is a stated finding that holds.
    pub fn diagnostic_is_stated(&self, case: &str, name: &str) -> bool {
        self.stated
            .iter()
            .any(|s| s.holds && s.stated.case == case && s.stated.check == name)
    }

    /// Every diagnostic row of every case: `(case, row, stated)`, `stated` true for a failing
    /// row that is a stated finding (counted as a finding, not a failure).
    pub fn diagnostic_rows(&self) -> Vec<(&str, DiagnosticRow, bool)> {
        self.cases
            .iter()
            .flat_map(|c| {
                c.diagnostics.verdicts().into_iter().map(move |row| {
                    let stated =
                        row.verdict == Some(false) && self.diagnostic_is_stated(&c.case, row.name);
                    (c.case.as_str(), row, stated)
                })
            })
            .collect()
    }

    /// True when nothing could be checked on the set: no expectation gave a verdict and no
    /// diagnostic decided. Such a set never reads "pass".
    pub fn nothing_checked(&self) -> bool {
        self.verdicts.is_empty()
            && self
                .cases
                .iter()
                .all(|c| c.diagnostics.verdicts().iter().all(|v| v.verdict.is_none()))
    }

    /// True when something was checked, every expectation holds, no diagnostic fails but as
    /// stated, every stated finding holds (and, with `require_all`, every case and time is
    /// supplied).
    pub fn passed(&self) -> bool {
        !self.nothing_checked()
            && (!self.require_all || (self.not_supplied() == 0 && self.missing_cases.is_empty()))
            && self.verdicts.iter().all(|v| v.pass)
            && self
                .diagnostic_rows()
                .iter()
                .all(|(_, row, stated)| row.verdict != Some(false) || *stated)
            && self.stated.iter().all(|s| s.holds)
    }
}

/// One stated finding.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Stated {
    /// The case.
    pub case: String,
    /// An expectation's metric label (`linf`, `overshoot / co0.5`) or a diagnostic's name
    /// (`time_level`, `sign`, `layout`, `magnitude`).
    pub check: String,
    /// What it says of the code, in words.
    pub finding: String,
}

/// A stated finding and whether the set bears it out.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StatedOutcome {
    /// The finding as stated.
    pub stated: Stated,
    /// True when the stated check fails on the set, as stated.
    pub holds: bool,
}

/// Orders of one case across result sets at different N.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseConvergence {
    /// Case name.
    pub case: String,
    /// The levels and the band (the report's study of this case, or measured only).
    pub result: ConvergenceResult,
    /// Why no band applies, if none does.
    pub note: Option<String>,
}

impl CaseConvergence {
    /// True when no fitted order is outside its band.
    pub fn passed(&self) -> bool {
        self.result.verdicts().iter().all(|v| v.pass != Some(false))
    }
}

/// Every result set scored against one scene.
#[derive(Debug, Clone, PartialEq)]
pub struct ScoreOutcome {
    /// Scene name.
    pub scene: String,
    /// The sets, in argument order.
    pub sets: Vec<ScoredSet>,
    /// Convergence of each case given at several N.
    pub convergence: Vec<CaseConvergence>,
}

impl ScoreOutcome {
    /// True when every set passes and every fitted order is in its band.
    pub fn passed(&self) -> bool {
        self.sets.iter().all(ScoredSet::passed)
            && self.convergence.iter().all(CaseConvergence::passed)
    }
}
