//! The subsection "Cost across codes" of "Other codes": for every case another code ran with a
//! measured cost (`external/<code>/cost.csv`), its error and courant's beside the ratio of their
//! wall times, both measured together on one machine and one thread by the code's regenerate
//! command. Only ratios are shown: wall times belong to the machine (the CSV keeps them, with
//! its date and CPU), the ratio to the comparison.

use super::document::{Block, Page};
use super::other_codes::OtherCode;
use crate::compare::outcome::SceneOutcome;
use crate::compare::score::tables::difference_from_courant;
use crate::results::exchange::committed::COSTS;
use crate::results::table::Table;
use crate::scene::cases::Scene;

/// One row of a cost table.
struct CostRow {
    scene: String,
    case: String,
    variant: String,
    steps: usize,
    courant_wall: f64,
    ratio: f64,
    repeat: usize,
    measured: String,
    cpu: String,
}

/// Read a `cost.csv` (columns scene, case, integrator, start, steps, opensees_wall_s or
/// `<code>_wall_s`, courant_wall_s, ratio, repeat, measured, cpu). Rows that do not read are
/// left out (the file is committed and written by the driver; the tests read it whole).
fn rows(text: &str) -> Vec<CostRow> {
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    reader
        .records()
        .flatten()
        .filter_map(|r| {
            let get = |i: usize| r.get(i).map(str::to_string);
            Some(CostRow {
                scene: get(0)?,
                case: get(1)?,
                variant: format!("{}-{}", get(2)?, get(3)?),
                steps: get(4)?.parse().ok()?,
                courant_wall: get(6)?.parse().ok()?,
                ratio: get(7)?.parse().ok()?,
                repeat: get(8)?.parse().ok()?,
                measured: get(9)?,
                cpu: get(10)?,
            })
        })
        .collect()
}

/// The subsection, or nothing when no code has a cost table.
pub fn section(scenes: &[Scene], outcomes: &[(SceneOutcome, f64)], others: &[OtherCode]) -> Page {
    let mut page = Page::default();
    for (code, text) in COSTS {
        let cost = rows(text);
        if cost.is_empty() {
            continue;
        }
        let mut table = Table::new(&[
            "scene",
            "case",
            "variant",
            "steps",
            "l1",
            "l1_courant",
            "time_over_courant",
        ]);
        let mut same_answer = Vec::new();
        // The largest stress difference from courant's run over the corrected cases.
        let mut largest_difference = 0.0_f64;
        for row in &cost {
            let label = format!("{code} {}", row.variant);
            let scene = scenes.iter().position(|s| s.name == row.scene);
            let file = others
                .iter()
                .find(|(set, index, _)| set.label == label && Some(*index) == scene)
                .and_then(|(_, _, scored)| scored.cases.iter().find(|c| c.case == row.case));
            let own = scene.and_then(|i| {
                outcomes[i]
                    .0
                    .results
                    .iter()
                    .find(|r| r.run.case == row.case)
            });
            let theirs = file.and_then(|c| c.worst_norms()).map(|n| n.l1);
            let ours = own.and_then(|r| r.worst_norms()).map(|n| n.l1);
            if row.variant.ends_with("corrected") {
                same_answer.push(row.ratio);
                let scale = scene
                    .and_then(|i| scenes[i].cases.first())
                    .and_then(|c| c.reference.as_ref())
                    .map_or(1.0, |r| r.stress_scale());
                let difference = file
                    .zip(own)
                    .and_then(|(f, o)| difference_from_courant(f, o, scale));
                largest_difference = largest_difference.max(difference.unwrap_or(f64::INFINITY));
            }
            table.push(vec![
                row.scene.as_str().into(),
                row.case.as_str().into(),
                row.variant.as_str().into(),
                row.steps.into(),
                theirs.into(),
                ours.into(),
                row.ratio.into(),
            ]);
        }
        same_answer.sort_by(f64::total_cmp);
        let first = &cost[0];
        let longest = cost.iter().map(|r| r.courant_wall).fold(0.0, f64::max);
        let summary = match (same_answer.first(), same_answer.last()) {
            (Some(lo), Some(hi)) => format!(
                " With the start corrected the two codes run the same scheme on the same mesh and \
                 step, and their stresses differ by at most {largest_difference:.1e} |sigma0| \
                 (`max_difference` in the tables above), so the ratio is the price of the same \
                 answer: {code} took {lo:.0} to {hi:.0} times courant's time (median {:.0}) on these \
                 bars of 100 elements, where no run of courant took more than {:.2} ms.",
                same_answer[same_answer.len() / 2],
                longest * 1e3
            ),
            _ => String::new(),
        };
        page.push(Block::Heading(3, format!("Cost across codes: {code}")));
        page.push(Block::Paragraph(format!(
            "Error against time for the cases {code} ran: the worst L1 error of each code over the \
             case's profile times and the ratio of {code}'s wall time (its time loop) to courant's \
             (`courant run` of the same case), both on one thread, median of {} runs, measured \
             together on {} ({}) by `bash external/{code}/regenerate.sh`; the wall times themselves \
             are in `external/{code}/cost.csv`.{summary}",
            first.repeat, first.measured, first.cpu
        )));
        page.table(table, format!("other_codes/{code}_cost.csv"));
    }
    page
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_committed_cost_table_reads_whole() {
        for (code, text) in COSTS {
            let lines = text.lines().filter(|l| !l.trim().is_empty()).count();
            let read = rows(text);
            assert_eq!(
                read.len() + 1,
                lines,
                "{code}: a row of cost.csv does not read"
            );
            assert!(read.iter().all(|r| r.ratio > 0.0 && r.steps > 0), "{code}");
        }
    }
}
