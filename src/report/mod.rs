//! `courant report`: every built-in scene, the convergence and work-precision studies and the
//! stability table in one document, rendered as Markdown (`index.md`) and self-contained HTML
//! (`index.html`) with every table as CSV and every figure as SVG beside it. Timings go to
//! `timing.md` and `timing.*` only ([`timing`]), so the rest changes only when results do
//! (numbers in the document are rounded to 4 significant digits, CSVs keep every digit).
//!
//! ```text
//!   scene ──> run ──> results ──> compare ──> report / check
//!                                             ^^^^^^
//! ```
//!
//! - [`document`]: the document model ([`document::Block`], [`document::Page`]), rendered by
//!   [`markdown`] and [`html`] with numbers as [`numbers`] shows them and columns in [`layout`]'s
//!   order (verdict or status first); [`plot`]: SVG line charts; [`figures`] and [`figure_parts`]: a scene's figures,
//!   split so that each stays legible;
//! - sections: [`summary`], [`scenes`], [`convergence`], [`work_precision`], [`stability`],
//!   [`other_codes`] (another code's committed results beside courant's), [`timing`] (with
//!   [`bench_table`]); [`citations`]: the methods page and reference list carried beside the
//!   report, and every `methods.md §N` linked to its section.
//!
//! Enters: compared outcomes (`compare`, run by `pipeline`). Leaves: the report's files, in
//! memory (written whole by `io::atomic`). Must not know: how outcomes are run or compared, the
//! command line.

pub mod bench_table;
pub mod citations;
pub mod convergence;
pub mod cost_across_codes;
pub mod document;
pub mod figure_parts;
pub mod figures;
pub mod html;
pub mod layout;
pub mod markdown;
pub mod numbers;
pub mod other_codes;
pub mod parameter_figures;
pub mod plot;
pub mod scenes;
pub mod stability;
pub mod summary;
pub mod tally;
pub mod timing;
pub mod work_precision;

use crate::compare::stability::stability_rows;
use crate::pipeline::report_runs::ReportRuns;
use crate::scene::cases::Scene;
use document::{Block, Page};

/// A generated report: files relative to the report directory.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// `(relative path, contents)`.
    pub files: Vec<(String, String)>,
    /// True when every verdict held.
    pub passed: bool,
    /// Every verdict of the report, counted.
    pub tally: tally::Tally,
}

/// Render the report of `scenes` from their runs (`runs.scenes` in the same order).
///
/// # Errors
/// A contact closed form of the stability section refuses its parameters.
pub fn render(scenes: &[Scene], runs: &ReportRuns) -> Result<Report, String> {
    let failed = summary::failures(scenes, &runs.scenes, &runs.convergence, &runs.other_codes);
    let mut page = summary::head(
        scenes,
        &runs.scenes,
        &runs.convergence,
        &runs.other_codes,
        &failed,
    );
    for ((outcome, _), scene) in runs.scenes.iter().zip(scenes) {
        page.extend(scenes::section(scene, outcome));
    }
    if !runs.convergence.is_empty() {
        page.extend(convergence::section(&runs.convergence));
    }
    if !runs.work.is_empty() {
        page.extend(work_precision::section(&runs.work));
    }
    let rows: Vec<_> = runs
        .scenes
        .iter()
        .zip(scenes)
        .flat_map(|((o, _), s)| stability_rows(s, o))
        .collect();
    // The built-in report (with its studies) always has the section: it also holds the contact
    // closed forms; a report of some scenes has it when one is a stability scene.
    if !rows.is_empty() || !runs.convergence.is_empty() {
        page.extend(stability::section(&rows)?);
    }
    if !runs.other_codes.is_empty() {
        page.extend(other_codes::section(
            scenes,
            &runs.scenes,
            &runs.other_codes,
        ));
        page.extend(cost_across_codes::section(
            scenes,
            &runs.scenes,
            &runs.other_codes,
        ));
    }
    page.push(Block::Heading(2, "Sources".into()));
    page.push(Block::Paragraph(
        "Every `source` above names what says it: a formula of courant's methods page (cited as \
         methods.md §N and linked to its section), a figure or equation of the seed or another \
         paper or book (full citations in the reference list), or \"measured here\" with what was \
         measured. Both pages are copied beside this report from the repository's `docs/`."
            .into(),
    ));
    page.push(Block::Links(vec![
        document::Inline::link(
            "methods.md: conventions and formulas, with derivations",
            citations::METHODS_FILE,
        ),
        document::Inline::link(
            "references.md: the seed and every paper or book a source names",
            citations::REFERENCES_FILE,
        ),
    ]));
    page.push(Block::Heading(2, "How this report was made".into()));
    let (command, ci) = if runs.convergence.is_empty() {
        ("`courant report` with scene names or files", "")
    } else {
        (
            "`cargo run --release -- report`",
            " (CI regenerates the report and fails when this page is out of date)",
        )
    };
    page.push(Block::Paragraph(format!(
        "By {command} (courant {}): {} scene(s) and {} \
         convergence studies, their scenes, studies and cases run in parallel; the content is identical whatever the thread count. The \
         commit, date, CPU, thread count and rustc of this run are in `timing.md`, with the wall times: \
         they change from run to run and machine to machine, while everything on this page changes only \
         when a result does{ci}.",
        env!("CARGO_PKG_VERSION"),
        scenes.len(),
        runs.convergence.len()
    )));
    let Page { blocks, mut files } = page;
    files.push((citations::METHODS_FILE.into(), citations::METHODS.into()));
    files.push((
        citations::REFERENCES_FILE.into(),
        citations::REFERENCES.into(),
    ));
    files.push(("index.md".into(), markdown::markdown(&blocks)));
    files.push((
        "index.html".into(),
        html::html("courant verification report", &blocks),
    ));
    files.extend(timing::timing_files(scenes, runs));
    Ok(Report {
        files,
        passed: failed.is_empty(),
        tally: runs.other_codes.iter().fold(
            tally::tally(&runs.scenes, &runs.convergence),
            |mut t, (_, _, scored)| {
                t.add(other_codes::tally(scored));
                t
            },
        ),
    })
}
