//! The head of the report: what it is, how many expectations it checks and which failed, and
//! its contents.

use super::document::{Block, Page};
use crate::compare::convergence::ConvergenceResult;
use crate::compare::outcome::SceneOutcome;
use crate::scene::cases::Scene;

/// Every failed verdict of the report, one line each: scene expectations, then convergence-order
/// bands.
pub fn failures(
    scenes: &[Scene],
    outcomes: &[(SceneOutcome, f64)],
    convergence: &[ConvergenceResult],
) -> Vec<String> {
    outcomes
        .iter()
        .zip(scenes)
        .flat_map(|((o, _), s)| {
            o.verdicts
                .iter()
                .filter(|v| !v.pass)
                .map(move |v| format!("{}: {}", s.name, v.describe()))
        })
        .chain(convergence.iter().flat_map(|c| {
            c.verdicts()
                .into_iter()
                .filter(|v| v.pass == Some(false))
                .map(|v| {
                    format!(
                        "convergence {}: {} fitted order {}, expected {}",
                        c.study.name,
                        v.norm,
                        v.fitted.map_or("-".into(), |p| format!("{p:.3}")),
                        v.expected
                    )
                })
        }))
        .collect()
}

/// The title, the count of expectations with the failures listed, and the contents.
pub fn head(
    scenes: &[Scene],
    outcomes: &[(SceneOutcome, f64)],
    convergence: &[ConvergenceResult],
    failed: &[String],
) -> Page {
    let mut page = Page::default();
    page.push(Block::Heading(1, "courant verification report".into()));
    page.push(Block::Paragraph(
        "Every built-in scene of courant (Kolman et al.'s Figs. 1, 2, 3, 5, 6 and companions) against its \
         analytic reference, with the verdict of every expectation, then h-refinement studies. Regenerate \
         with `cargo run --release -- report`; timings are in `timing.md`, every table also as CSV beside it."
            .into(),
    ));
    let count: usize = outcomes
        .iter()
        .map(|(o, _)| o.verdicts.len())
        .sum::<usize>()
        + convergence
            .iter()
            .map(|c| c.verdicts().iter().filter(|v| v.pass.is_some()).count())
            .sum::<usize>();
    page.push(Block::Paragraph(format!(
        "{count} expectations (scene expectations and convergence-order bands), {} failed.",
        failed.len()
    )));
    if !failed.is_empty() {
        page.push(Block::List(failed.to_vec()));
    }
    page.push(Block::Heading(2, "Contents".into()));
    let mut contents: Vec<String> = scenes
        .iter()
        .map(|s| format!("{} — {}", s.name, s.description))
        .collect();
    contents.push("Convergence studies".into());
    contents.push("Work and precision".into());
    contents.push("Stability at the extremes".into());
    contents.push("Other codes".into());
    page.push(Block::List(contents));
    page
}
