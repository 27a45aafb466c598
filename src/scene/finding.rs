//! Findings: a disagreement between stability theory and a run that a stability scene states
//! (`[[finding]]`), with its source, so that the check reads it as a known result, not a
//! failure.

use super::error::{SceneError, Source};
use super::schema::RawFinding;
use toml::Spanned;

/// What a stability run does, as a finding states it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Observed {
    /// Completed with bounded energy.
    Stable,
    /// Completed, its energy beyond the stability band.
    EnergyGrowth,
    /// Completed, but the scheme created energy beyond round-off (its balance `T + U - W` grew).
    EnergyCreated,
    /// The divergence guard stopped it.
    Diverged,
}

impl Observed {
    /// Scene-file name.
    pub fn name(self) -> &'static str {
        match self {
            Observed::Stable => "stable",
            Observed::EnergyGrowth => "energy growth",
            Observed::EnergyCreated => "energy created",
            Observed::Diverged => "diverged",
        }
    }

    fn parse(s: &str) -> Option<Self> {
        [
            Observed::Stable,
            Observed::EnergyGrowth,
            Observed::EnergyCreated,
            Observed::Diverged,
        ]
        .into_iter()
        .find(|o| o.name() == s)
    }
}

/// A disagreement between stability theory and a run that the scene states, with its source.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// Cases it applies to.
    pub cases: Vec<String>,
    /// What those runs do against the prediction.
    pub observed: Observed,
    /// Where the finding is established.
    pub source: String,
}

/// Read a `[[finding]]` table of a scene (`stability`: whether the scene is a stability scene).
pub(super) fn finding(
    src: &Source,
    spanned: &Spanned<RawFinding>,
    names: &[String],
    stability: bool,
) -> Result<Finding, SceneError> {
    let raw = spanned.get_ref();
    let fail = |msg: String| src.error(Some(spanned.span()), "finding", msg);
    if !stability {
        return Err(fail(
            "a finding states a disagreement with stability theory: only a stability scene (`[scene] stability = true`) has one".into(),
        ));
    }
    if raw.cases.is_empty() {
        return Err(fail("`cases` is empty".into()));
    }
    if let Some(unknown) = raw.cases.iter().find(|c| !names.contains(c)) {
        return Err(fail(format!(
            "case \"{unknown}\" does not exist (cases: {})",
            names.join(", ")
        )));
    }
    let observed = Observed::parse(&raw.observed).ok_or_else(|| {
        fail(format!(
            "observed = \"{}\" is not one of stable, energy growth, energy created, diverged",
            raw.observed
        ))
    })?;
    if raw.source.trim().is_empty() {
        return Err(fail(
            "`source` must say where the finding is established".into(),
        ));
    }
    Ok(Finding {
        cases: raw.cases.clone(),
        observed,
        source: raw.source.clone(),
    })
}
