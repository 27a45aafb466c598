//! The head of the report, its first screen: what it is, every verdict it contains counted
//! (passed, findings, failed) and linked, one row per scene and study, and the contents.
//!
//! The counts are those of the verdict cells below: each scene's expectations table (its
//! `[[expect]]` rows and, in stability scenes, the stability verdict of every case) and each
//! convergence study's order table (rows with a band; `measured` rows are not verdicts).

use super::document::{Block, Inline, Page, anchor};
use super::other_codes::{OtherCode, checks_anchor, stem, tally as other_tally};
use super::tally::Tally;
use crate::compare::convergence::ConvergenceResult;
use crate::compare::outcome::SceneOutcome;
use crate::scene::cases::Scene;
use crate::scene::expectation::Metric;

/// The anchor of a scene's expectations table.
pub fn expectations_anchor(scene: &str) -> String {
    format!("{scene}-expectations")
}

/// Every failed verdict of the report, one line each: scene expectations, then convergence-order
/// bands.
pub fn failures(
    scenes: &[Scene],
    outcomes: &[(SceneOutcome, f64)],
    convergence: &[ConvergenceResult],
    others: &[OtherCode],
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
        .chain(others.iter().flat_map(|(set, index, scored)| {
            let scene = &scenes[*index].name;
            let label = set.label;
            scored
                .verdicts
                .iter()
                .filter(|v| !v.pass)
                .map(move |v| format!("other code {label} on {scene}: {}", v.describe()))
                .chain(scored.diagnostic_rows().into_iter().filter_map(
                    move |(case, row, stated)| {
                        (row.verdict == Some(false) && !stated).then(|| {
                            format!(
                                "other code {label} on {scene}: {case}/{} = {} ({})",
                                row.name, row.measured, row.note
                            )
                        })
                    },
                ))
                .chain(scored.stated.iter().filter(|s| !s.holds).map(move |s| {
                    format!(
                        "other code {label} on {scene}: {}/{} passes, but is stated as a finding ({})",
                        s.stated.case, s.stated.check, s.stated.finding
                    )
                }))
        }))
        .collect()
}

/// What the report is: the built-in report (every built-in scene and the studies), or a report
/// of the scenes it was given, named.
pub fn opening(scenes: &[Scene], builtin: bool) -> String {
    if builtin {
        return "Every built-in scene of courant (Kolman et al.'s Figs. 1, 2, 3, 5, 6 and companions) against its \
         analytic reference, with the verdict of every expectation, then h-refinement studies. Regenerate \
         with `cargo run --release -- report`; timings are in `timing.md`, every table also as CSV beside it."
            .into();
    }
    let names: Vec<&str> = scenes.iter().map(|s| s.name.as_str()).collect();
    format!(
        "A report of {} scene(s) given to `courant report`: {}. Each against its reference, with \
         the verdict of every expectation; the built-in studies are not part of it. Regenerate \
         with `courant report` and the same scene names or files, `--out DIR`; timings are in \
         `timing.md`, every table also as CSV beside it.",
        scenes.len(),
        names.join(", ")
    )
}

/// The findings of one code and variant: its label, the scenes, and each check with its count.
type OtherFindings<'a> = (&'a str, Vec<&'a str>, Vec<(String, usize)>);

/// One summary row: a linked name, its counts (coloured where not zero) and where to look.
fn row(name: Inline, tally: Tally, look: Inline) -> Vec<Inline> {
    let count = |n: usize, verdict: &'static str| {
        let cell = Inline::text(n.to_string());
        if n > 0 { cell.verdict(verdict) } else { cell }
    };
    vec![
        name,
        Inline::text(tally.total().to_string()),
        count(tally.passed, "pass"),
        count(tally.findings, "finding"),
        count(tally.failed, "fail"),
        look,
    ]
}

/// The title, the headline (every verdict counted, failures and findings listed), the summary
/// table and the contents.
pub fn head(
    scenes: &[Scene],
    outcomes: &[(SceneOutcome, f64)],
    convergence: &[ConvergenceResult],
    others: &[OtherCode],
    failed: &[String],
) -> Page {
    let mut page = Page::default();
    page.push(Block::Heading(1, "courant verification report".into()));
    page.push(Block::Paragraph(opening(scenes, !convergence.is_empty())));
    let mut total = Tally::default();
    let mut rows = Vec::new();
    for ((outcome, _), scene) in outcomes.iter().zip(scenes) {
        let tally = Tally::of_scene(outcome);
        total.add(tally);
        rows.push(row(
            Inline::link(&scene.name, format!("#{}", anchor(&scene.name))),
            tally,
            Inline::link(
                "expectations",
                format!("#{}", expectations_anchor(&scene.name)),
            ),
        ));
    }
    for c in convergence {
        let tally = Tally::of_study(c);
        total.add(tally);
        rows.push(row(
            Inline::text(format!("convergence: {}", c.study.name)),
            tally,
            Inline::link("orders", format!("#{}", anchor(c.study.title))),
        ));
    }
    for (set, index, scored) in others {
        let tally = other_tally(scored);
        total.add(tally);
        let scene = &scenes[*index].name;
        rows.push(row(
            Inline::text(format!("other code: {} on {scene}", set.label)),
            tally,
            Inline::link("checks", format!("#{}", checks_anchor(&stem(set)))),
        ));
    }
    let stability = if scenes.iter().any(|s| s.stability) || !convergence.is_empty() {
        Inline::link("stability table", "#stability-at-the-extremes")
    } else {
        Inline::text("-")
    };
    rows.push(row(Inline::text("all"), total, stability));
    // courant's findings, one list item per scene: `scene (k): case (measure); ...`.
    let findings: Vec<(String, Vec<String>)> = outcomes
        .iter()
        .zip(scenes)
        .map(|((o, _), s)| {
            let cases = o
                .verdicts
                .iter()
                .filter(|v| v.finding)
                .map(|v| match v.metric {
                    // A stability finding's measure names itself ("energy growth x5.3"); a
                    // stated row's is a number, shown with its metric.
                    Metric::Stability => format!("{} ({})", v.case, v.measured),
                    metric => format!("{} ({} {})", v.case, metric.name(), v.measured),
                })
                .collect();
            (s.name.clone(), cases)
        })
        .filter(|(_, cases): &(String, Vec<String>)| !cases.is_empty())
        .collect();
    let finding_count: usize = findings.iter().map(|(_, cases)| cases.len()).sum();
    // Findings of other codes, one line per code and variant: how many, on which scenes, of
    // which checks (each finding's words are in its set's section).
    let mut other_findings: Vec<OtherFindings> = Vec::new();
    let mut other_count = 0;
    for (set, index, scored) in others {
        for s in scored.stated.iter().filter(|s| s.holds) {
            other_count += 1;
            let at = match other_findings.iter().position(|f| f.0 == set.label) {
                Some(i) => i,
                None => {
                    other_findings.push((set.label, Vec::new(), Vec::new()));
                    other_findings.len() - 1
                }
            };
            let entry = &mut other_findings[at];
            let scene = scenes[*index].name.as_str();
            if !entry.1.contains(&scene) {
                entry.1.push(scene);
            }
            match entry.2.iter_mut().find(|c| c.0 == s.stated.check) {
                Some(c) => c.1 += 1,
                None => entry.2.push((s.stated.check.clone(), 1)),
            }
        }
    }
    let other_findings: Vec<String> = other_findings
        .into_iter()
        .map(|(label, scenes, checks)| {
            let n: usize = checks.iter().map(|c| c.1).sum();
            let checks: Vec<String> = checks.iter().map(|(c, k)| format!("{c} x{k}")).collect();
            format!(
                "{label}: {n} on {} ({})",
                scenes.join(", "),
                checks.join(", ")
            )
        })
        .collect();
    page.push(Block::Paragraph(format!(
        "{} verdicts: {} pass, {} findings ({} verdicts on courant's runs that their scene states as \
         findings, each with its source: a disagreement with stability theory, or a claim of the seed \
         that does not hold as stated; {} findings of other codes, stated beside their \
         results), {} FAIL. Verdicts are the scenes' expectations, the stability verdict of every case \
         of a stability scene, the convergence-order bands and the checks of other codes' committed \
         results.",
        total.total(),
        total.passed,
        total.findings,
        finding_count,
        other_count,
        total.failed
    )));
    if !failed.is_empty() {
        page.push(Block::Paragraph("Failed:".into()));
        page.push(Block::List(failed.to_vec()));
    }
    if !findings.is_empty() {
        page.push(Block::Paragraph(format!(
            "courant's findings, by scene ({finding_count}):"
        )));
        page.push(Block::List(
            findings
                .iter()
                .map(|(scene, cases)| format!("{scene} ({}): {}", cases.len(), cases.join("; ")))
                .collect(),
        ));
    }
    if !other_findings.is_empty() {
        page.push(Block::Paragraph(format!(
            "Findings of other codes, each as its set states it (section Other codes): {}.",
            other_findings.join("; ")
        )));
    }
    page.push(Block::Summary {
        columns: [
            "scene or study",
            "verdicts",
            "pass",
            "finding",
            "FAIL",
            "rows",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    });
    page.push(Block::Heading(2, "Contents".into()));
    let mut contents: Vec<Inline> = scenes
        .iter()
        .map(|s| {
            Inline::link(
                format!("{} — {}", s.name, s.description),
                format!("#{}", anchor(&s.name)),
            )
        })
        .collect();
    let mut sections = Vec::new();
    if !convergence.is_empty() {
        sections.push("Convergence studies");
        sections.push("Work and precision");
    }
    if scenes.iter().any(|s| s.stability) || !convergence.is_empty() {
        sections.push("Stability at the extremes");
    }
    // The built-in report (the one with studies) grades the committed results of other codes.
    if !convergence.is_empty() {
        sections.push("Other codes");
    }
    sections.push("How this report was made");
    for section in sections {
        contents.push(Inline::link(section, format!("#{}", anchor(section))));
    }
    page.push(Block::Links(contents));
    page
}
