//! The files of a compared scene: what `courant run` writes into `OUT/<scene>/` (every table at
//! round-trip precision), and the deterministic tables a report keeps of them, which
//! `courant check --baseline <report>` compares.

use super::case::CaseResult;
use super::contact::{contact_summary_table, force_table};
use super::dispersion::dispersion_table;
use super::outcome::SceneOutcome;
use super::spectrum::{spectrum_summary_table, spectrum_table};
use super::sweep::sweep_table;
use super::tables::{
    PROFILE_COLUMNS, energy_table, expectations_table, history_table, norms_table, profile_rows,
    summary_table,
};
use crate::results::table::{Precision, Table, csv_text, write_csv};

/// The names of the scene tables a report keeps: `courant report` writes each scene's
/// deterministic tables under these names (and no others), and a report baseline compares them.
pub mod report_tables {
    /// Cases (wall times dropped), or the spectra of a spectrum scene, or the contact runs.
    pub const SUMMARY: &str = "summary.csv";
    /// Norms per case and profile time.
    pub const NORMS: &str = "norms.csv";
    /// Phase speeds of a dispersion scene.
    pub const DISPERSION: &str = "dispersion.csv";
    /// A contact stability sweep.
    pub const STABILITY: &str = "stability.csv";
    /// The expectation verdicts.
    pub const EXPECTATIONS: &str = "expectations.csv";
}

/// Every name of [`report_tables`]; a fresh file of another name is not kept by a report
/// baseline.
pub const REPORT_TABLES: &[&str] = &[
    report_tables::SUMMARY,
    report_tables::NORMS,
    report_tables::DISPERSION,
    report_tables::STABILITY,
    report_tables::EXPECTATIONS,
];

/// All files of a scene's output directory, as (file name, CSV text).
pub fn scene_files(outcome: &SceneOutcome) -> Vec<(String, String)> {
    files(outcome, true)
}

/// The files of [`scene_files`] split in two: every file but the cases' profile files, as
/// (file name, CSV text), and the profile files as (file name, case), to be streamed into place
/// by [`write_profile_csv`] (a profile of 10^7 elements is never held as text). Together the same
/// names and bytes as [`scene_files`].
pub fn scene_files_streamed(outcome: &SceneOutcome) -> StreamedFiles<'_> {
    StreamedFiles {
        texts: files(outcome, false),
        profiles: outcome
            .results
            .iter()
            .map(|r| (profile_file(r), r))
            .collect(),
    }
}

/// A scene's files with the profiles left to stream ([`scene_files_streamed`]).
#[derive(Debug)]
pub struct StreamedFiles<'a> {
    /// Every file but the profiles: (file name, CSV text).
    pub texts: Vec<(String, String)>,
    /// The profile files: (file name, case), written by [`write_profile_csv`].
    pub profiles: Vec<(String, &'a CaseResult)>,
}

/// A case's profile file: `time, element, x, stress, reference, error`, every row.
///
/// # Errors
/// Any I/O error of `out`.
pub fn write_profile_csv(result: &CaseResult, out: &mut dyn std::io::Write) -> std::io::Result<()> {
    write_csv(
        out,
        &PROFILE_COLUMNS,
        profile_rows(result),
        Precision::RoundTrip,
    )
}

fn profile_file(result: &CaseResult) -> String {
    format!("{}.csv", result.run.case)
}

fn files(outcome: &SceneOutcome, with_profiles: bool) -> Vec<(String, String)> {
    let full = Precision::RoundTrip;
    let (results, verdicts) = (&outcome.results, &outcome.verdicts);
    let mut files = Vec::new();
    for r in results {
        if with_profiles {
            files.push((
                profile_file(r),
                csv_text(&PROFILE_COLUMNS, profile_rows(r), full),
            ));
        }
        if !r.histories.is_empty() {
            files.push((
                format!("{}.history.csv", r.run.case),
                history_table(r).to_csv(full),
            ));
        }
        files.push((
            format!("{}.energy.csv", r.run.case),
            energy_table(r).to_csv(full),
        ));
    }
    for s in &outcome.spectra {
        files.push((format!("{}.csv", s.case), spectrum_table(s).to_csv(full)));
    }
    for c in &outcome.contact {
        files.push((format!("{}.csv", c.case), force_table(c).to_csv(full)));
    }
    if !outcome.contact.is_empty() {
        files.push((
            "summary.csv".into(),
            contact_summary_table(&outcome.contact).to_csv(full),
        ));
    }
    for sweep in &outcome.sweeps {
        files.push(("stability.csv".into(), sweep_table(sweep).to_csv(full)));
    }
    if !outcome.contact.is_empty() || !outcome.sweeps.is_empty() {
        files.push((
            "expectations.csv".into(),
            expectations_table(verdicts).to_csv(full),
        ));
        return files;
    }
    if !outcome.spectra.is_empty() {
        files.push((
            "summary.csv".into(),
            spectrum_summary_table(&outcome.spectra).to_csv(full),
        ));
    } else if !outcome.dispersion.is_empty() {
        files.push((
            "dispersion.csv".into(),
            dispersion_table(&outcome.dispersion).to_csv(full),
        ));
    } else {
        files.push(("summary.csv".into(), summary_table(results).to_csv(full)));
        files.push(("norms.csv".into(), norms_table(results).to_csv(full)));
    }
    files.push((
        "expectations.csv".into(),
        expectations_table(verdicts).to_csv(full),
    ));
    files
}

/// The deterministic tables of a scene (wall-time columns dropped), by file name: what a report
/// keeps of `courant run`'s output, and what `courant check --baseline <report>` compares.
pub fn scene_tables(o: &SceneOutcome) -> Vec<(String, Table)> {
    use report_tables as t;
    let drop = ["wall_time_s"];
    let mut tables = Vec::new();
    if !o.results.is_empty() {
        tables.push((
            t::SUMMARY.to_string(),
            summary_table(&o.results).without(&drop),
        ));
        tables.push((t::NORMS.to_string(), norms_table(&o.results)));
    }
    if !o.spectra.is_empty() {
        tables.push((
            t::SUMMARY.to_string(),
            spectrum_summary_table(&o.spectra).without(&drop),
        ));
    }
    if !o.dispersion.is_empty() {
        tables.push((t::DISPERSION.to_string(), dispersion_table(&o.dispersion)));
    }
    if !o.contact.is_empty() {
        tables.push((
            t::SUMMARY.to_string(),
            contact_summary_table(&o.contact).without(&drop),
        ));
    }
    for s in &o.sweeps {
        tables.push((t::STABILITY.to_string(), sweep_table(s)));
    }
    tables.push((t::EXPECTATIONS.to_string(), expectations_table(&o.verdicts)));
    tables
}
