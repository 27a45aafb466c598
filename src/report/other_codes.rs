//! The section "Other codes": every result set of another code committed in this repository
//! (`external/<code>/results/<scene>/`, compiled in), graded as `courant score` grades it, beside
//! courant's own run of the same cases: a table of norms and diagnostics, the checks, and per
//! case one figure overlaying the other code, courant and the exact solution.

use super::document::{Block, Page};
use super::plot::{Axes, Series, SeriesStyle, line_chart};
use super::tally::Tally;
use crate::compare::outcome::SceneOutcome;
use crate::compare::score::outcome::{Scored, ScoredSet, SkipKind};
use crate::compare::score::tables::beside_courant_table;
use crate::compare::verdict::Measured;
use crate::results::exchange::committed::CommittedSet;
use crate::results::table::{Cell, Table};
use crate::scene::cases::Scene;

/// One scored committed set: the set, the index of its scene, the scored set.
pub type OtherCode<'a> = (&'a CommittedSet, usize, ScoredSet);

/// The anchor of a set's checks table.
pub fn checks_anchor(stem: &str) -> String {
    format!("{stem}-checks")
}

/// The verdicts of a set: the scene's expectations on its files and each case's decided
/// diagnostics (an undecided diagnostic is no verdict); a failure stated for the set is a
/// finding of that code, a stated finding that does not hold a failure.
pub fn tally(scored: &ScoredSet) -> Tally {
    let mut t = Tally::of_verdicts(&scored.verdicts);
    for (_, row, stated) in scored.diagnostic_rows() {
        match (row.verdict, stated) {
            (Some(false), true) => t.findings += 1,
            (Some(false), false) => t.failed += 1,
            (Some(true), _) => t.passed += 1,
            (None, _) => {}
        }
    }
    t.failed += scored.stated.iter().filter(|s| !s.holds).count();
    t
}

/// The file stem of a set's tables and figures: its label and scene, as a file name.
pub fn stem(set: &CommittedSet) -> String {
    format!("{}_{}", set.label.replace(' ', "_"), set.scene)
}

/// Every check of a set, one row each: `case, check, measured, bound, verdict, source` (a
/// diagnostic's note as its source; `n/a` where it decides nothing).
fn checks_table(scored: &ScoredSet) -> Table {
    let mut t = Table::new(&["case", "check", "measured", "bound", "verdict", "source"]);
    for v in &scored.verdicts {
        t.push(vec![
            v.case.as_str().into(),
            v.metric_label().into(),
            match &v.measured {
                Measured::Value(x) => Cell::Num(*x),
                other => other.to_string().into(),
            },
            v.bound.to_string().into(),
            v.word().into(),
            v.source.as_str().into(),
        ]);
    }
    for (case, row, stated) in scored.diagnostic_rows() {
        if row.note.starts_with("not applicable") {
            continue;
        }
        t.push(vec![
            case.into(),
            row.name.into(),
            row.measured.into(),
            row.expected.into(),
            match (row.verdict, stated) {
                (Some(false), true) => "finding",
                (Some(true), _) => "pass",
                (Some(false), false) => "FAIL",
                (None, _) => "n/a",
            }
            .into(),
            row.note.into(),
        ]);
    }
    for s in scored.stated.iter().filter(|s| !s.holds) {
        t.push(vec![
            s.stated.case.as_str().into(),
            s.stated.check.as_str().into(),
            "passes".into(),
            "stated to fail".into(),
            "FAIL".into(),
            format!("stated finding no longer holds: {}", s.stated.finding).into(),
        ]);
    }
    t
}

/// The section.
pub fn section(scenes: &[Scene], outcomes: &[(SceneOutcome, f64)], others: &[OtherCode]) -> Page {
    let mut page = Page::default();
    page.push(Block::Heading(2, "Other codes".into()));
    page.push(Block::Paragraph(
        "Results of other codes on courant's scenes, written in the results exchange format (README) \
         and committed under `external/<code>/results/<scene>/`, graded with exactly the norms and \
         expectations of courant's own runs (`courant score <scene> --results DIR`), beside courant's \
         run of the same case. How they are graded is at the end of this section."
            .into(),
    ));
    let grading = Block::Paragraph(
        "`max_difference` is the largest difference of the two codes' element \
         stresses at the same times over |sigma0|; `time_level` what the time shift that best fits the \
         exact solution says (on time, whole steps late or early, or a start that gives the first step \
         the wrong impulse; the shift itself is in the checks below). Error bounds apply to every code; \
         a scene's signature rows (what its case's scheme and mass do) only where the set's \
         `results.toml` declares that scheme, its parameters and the mass, and are not applicable \
         otherwise; expectations on energies are not measurable (the format carries none). A set may \
         state what courant finds in that code (`stated.toml`: OpenSees' integrators as they come): a \
         stated failure counts as a finding of that code, and a verdict that differs from what is \
         stated fails. Each code's driver, its pinned requirements and the command that regenerates its \
         results are in `external/<code>/` (SfePy, OpenSees)."
            .into(),
    );
    for (set, index, scored) in others {
        let (scene, (outcome, _)) = (&scenes[*index], &outcomes[*index]);
        let stem = stem(set);
        page.push(Block::Heading(
            3,
            format!("{} {} on {}", set.label, scored.version, scene.name),
        ));
        let checks = checks_table(scored);
        let tally = tally(scored);
        let count = |kind| scored.skipped.iter().filter(|s| s.kind == kind).count();
        page.push(Block::Paragraph(format!(
            "`{}`: {} case file(s) of scene {}; {} verdict(s) (the scene's expectations and each case's \
             diagnostics), {} finding(s) of this code stated in `stated.toml`, {} failed; {} expectation(s) \
             not applicable, {} not supplied, {} not measurable from files.",
            set.dir,
            scored.cases.len(),
            scene.name,
            tally.total(),
            tally.findings,
            tally.failed,
            count(SkipKind::NotApplicable),
            count(SkipKind::NotSupplied),
            count(SkipKind::NotMeasurable),
        )));
        let scale = scene
            .cases
            .first()
            .and_then(|c| c.reference.as_ref())
            .map_or(1.0, |r| r.stress_scale());
        // Stress profiles beside courant's run (a set of spectra has none: no empty table).
        if scored
            .cases
            .iter()
            .any(|c| matches!(c.scored, Scored::Profiles { .. }))
        {
            page.table(
                beside_courant_table(scored, outcome, scale),
                format!("other_codes/{stem}.csv"),
            );
        }
        page.table_with_id(
            checks,
            format!("other_codes/{stem}.checks.csv"),
            checks_anchor(&stem),
        );
        for case in &scored.cases {
            if let Some((svg, caption)) = overlay(scene, outcome, &scored.code, case) {
                page.figure(
                    format!("other_codes/{stem}_{}.svg", case.case),
                    svg,
                    caption,
                );
            }
        }
    }
    page.push(Block::Heading(3, "How other codes are graded".into()));
    page.push(grading);
    page
}

/// The other code's stresses (points), courant's (line) and the exact solution (dashed) at the
/// case's last profile time, drawn as `x / L` against `stress / |sigma0|` like the scenes'
/// profiles.
fn overlay(
    scene: &Scene,
    outcome: &SceneOutcome,
    code: &str,
    case: &crate::compare::score::outcome::ScoredCase,
) -> Option<(String, String)> {
    let Scored::Profiles { profiles, .. } = &case.scored else {
        return None;
    };
    let p = profiles.last()?;
    let scene_case = scene.cases.iter().find(|c| c.name == case.case)?;
    let length = scene_case.model.bar().mesh().length();
    let scale = scene_case
        .reference
        .as_ref()
        .map_or(1.0, |r| r.stress_scale());
    let scaled = |x: &[f64], v: &[f64]| -> Vec<(f64, f64)> {
        x.iter()
            .zip(v)
            .map(|(x, v)| (x / length, v / scale))
            .collect()
    };
    let mut series = vec![Series::new(
        format!("{code} {}", case.case),
        scaled(&p.x, &p.stress),
        SeriesStyle::Points,
    )];
    let own = outcome
        .results
        .iter()
        .find(|r| r.run.case == case.case)
        .and_then(|r| {
            r.profiles
                .iter()
                .find(|q| (q.time - p.time).abs() <= 1e-9 * p.time.abs().max(1.0))
        });
    if let Some(q) = own {
        series.push(Series::new(
            format!("courant {}", case.case),
            scaled(&q.x, &q.stress),
            SeriesStyle::Line,
        ));
    }
    series.push(Series::new(
        "exact",
        scaled(&p.x, &p.reference),
        SeriesStyle::Dashed,
    ));
    let time = if scene_case.times_in_transits {
        format!("t = {:.4} T", p.time / scene_case.transit_time)
    } else {
        format!("t = {:.4}", p.time)
    };
    let title = format!("{}: {code} and courant, {}, {time}", scene.name, case.case);
    let axes = Axes::new(title.clone(), "x / L", "stress / |sigma0|");
    let svg = line_chart(&axes, &series).ok()?;
    let caption = format!(
        "{title}: {code}'s element stresses (points), courant's run of the same case{} (line) and the exact element averages (dashed)",
        if own.is_some() { "" } else { " (not run)" }
    );
    Some((svg, caption))
}
