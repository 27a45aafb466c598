//! What an exchange file holds once read: plain data with the line each value came from (so that
//! a check made later, against the scene, can still name the line).

use super::meta::ResultsMeta;

/// Where the stresses of a profile live.
#[derive(Debug, Clone, PartialEq)]
pub enum Positions {
    /// Element averages: element `i` spans `[left[i], right[i]]`, sorted, contiguous.
    Elements {
        /// Left ends, increasing.
        left: Vec<f64>,
        /// Right ends.
        right: Vec<f64>,
    },
    /// Point values at increasing, distinct positions.
    Points(Vec<f64>),
}

impl Positions {
    /// Number of elements or points.
    pub fn len(&self) -> usize {
        match self {
            Positions::Elements { left, .. } => left.len(),
            Positions::Points(x) => x.len(),
        }
    }

    /// True when there is no element or point.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Element midpoints, or the points.
    pub fn centres(&self) -> Vec<f64> {
        match self {
            Positions::Elements { left, right } => {
                left.iter().zip(right).map(|(a, b)| 0.5 * (a + b)).collect()
            }
            Positions::Points(x) => x.clone(),
        }
    }

    /// `(first, last)` position covered: the first left end and the last right end, or the
    /// first and last point.
    pub fn span(&self) -> (f64, f64) {
        match self {
            Positions::Elements { left, right } => (left[0], right[right.len() - 1]),
            Positions::Points(x) => (x[0], x[x.len() - 1]),
        }
    }
}

/// One stress profile: the rows of one output time.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    /// Output time.
    pub time: f64,
    /// Elements or points, sorted by position.
    pub positions: Positions,
    /// Stress per element or point (empty in a query file).
    pub stress: Vec<f64>,
    /// The line of each row, in the sorted order.
    pub lines: Vec<usize>,
}

/// A contact force history.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceHistory {
    /// Sample times, increasing.
    pub time: Vec<f64>,
    /// Contact force, compression positive (empty in a query file).
    pub force: Vec<f64>,
    /// Penetration, if given.
    pub penetration: Option<Vec<f64>>,
    /// Gap, if given.
    pub gap: Option<Vec<f64>>,
    /// The line of each sample.
    pub lines: Vec<usize>,
}

/// One row of a spectrum.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumRow {
    /// Mode number (as the scene's closed forms count them: free-free from 0, the rigid mode).
    pub mode: usize,
    /// Angular frequency (NaN in a query file).
    pub omega: f64,
    /// Mass label, if the file has a `mass` column.
    pub mass: Option<String>,
    /// Line of the row.
    pub line: usize,
}

/// What one case file holds.
#[derive(Debug, Clone, PartialEq)]
pub enum CaseData {
    /// Stress profiles, in time order.
    Profiles(Vec<Profile>),
    /// A contact force history.
    Force(ForceHistory),
    /// A spectrum, in file order.
    Spectrum(Vec<SpectrumRow>),
}

impl CaseFile {
    /// The 1-based field number of `column` (1 when the file has no such column).
    pub fn column(&self, column: &str) -> usize {
        self.columns
            .iter()
            .find(|(name, _)| *name == column)
            .map_or(1, |&(_, i)| i)
    }
}

impl CaseData {
    /// What the data is, for messages.
    pub fn describe(&self) -> &'static str {
        match self {
            CaseData::Profiles(p)
                if matches!(p.first().map(|p| &p.positions), Some(Positions::Points(_))) =>
            {
                "stress profiles (point values)"
            }
            CaseData::Profiles(_) => "stress profiles (element averages)",
            CaseData::Force(_) => "a contact force history",
            CaseData::Spectrum(_) => "a spectrum",
        }
    }
}

/// One case file.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseFile {
    /// Case name (the file stem).
    pub case: String,
    /// Path of the file, for messages.
    pub file: String,
    /// `(column name, 1-based field number)` of its columns, for messages.
    pub columns: Vec<(&'static str, usize)>,
    /// Its data.
    pub data: CaseData,
    /// The reference that produced the values, written as a `reference` column (`courant
    /// reference`); `None` for results.
    pub reference: Option<String>,
}

/// A results directory: its case files (sorted by name) and its `results.toml`.
#[derive(Debug, Clone, PartialEq)]
pub struct ExchangeSet {
    /// How the set is named in tables and messages (the directory as given).
    pub label: String,
    /// The case files, sorted by case name.
    pub cases: Vec<CaseFile>,
    /// `results.toml`, if the directory has one.
    pub meta: Option<ResultsMeta>,
}

impl ExchangeSet {
    /// The producing code named in `results.toml`, or `-`.
    pub fn code(&self) -> String {
        self.meta
            .as_ref()
            .and_then(|m| m.code.clone())
            .unwrap_or_else(|| "-".into())
    }
}
