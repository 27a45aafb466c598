//! The subsection "Cost across codes" of "Other codes": per scene that another code ran with its
//! own time recorded (`wall_s` in its committed `results.toml`), the error of every code on each
//! case against its wall time over courant's on the same case, as a table and a figure, and a
//! paragraph that says what the trade is. courant's time for each code's ratios is the one that
//! code's driver measured right after its own, on the same machine and one thread
//! (`external/<code>/courant_times.csv`). Only ratios are shown: wall times belong to the
//! machine (the files keep them, with the date and the CPU), the ratio to the comparison.

use super::document::{Block, Page};
use super::other_codes::OtherCode;
use super::plot::{Axes, Series, SeriesStyle, line_chart};
use crate::compare::outcome::SceneOutcome;
use crate::compare::score::tables::difference_from_courant;
use crate::results::exchange::committed::COURANT_TIMES;
use crate::results::exchange::meta;
use crate::results::table::Table;
use crate::scene::cases::Scene;

/// One row of a `courant_times.csv`.
#[derive(Debug, Clone, PartialEq)]
struct CourantTime {
    scene: String,
    case: String,
    wall: f64,
    repeat: usize,
    measured: String,
    cpu: String,
}

/// Read a `courant_times.csv` (columns scene, case, steps, courant_wall_s, repeat, measured,
/// cpu). Rows that do not read are left out (the file is committed and written by a driver; the
/// tests read every one whole).
fn courant_times(text: &str) -> Vec<CourantTime> {
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    reader
        .records()
        .flatten()
        .filter_map(|r| {
            let get = |i: usize| r.get(i).map(str::to_string);
            let wall: f64 = get(3)?.parse().ok()?;
            (wall.is_finite() && wall > 0.0).then_some(())?;
            Some(CourantTime {
                scene: get(0)?,
                case: get(1)?,
                wall,
                repeat: get(4)?.parse().ok()?,
                measured: get(5)?,
                cpu: get(6)?,
            })
        })
        .collect()
}

/// One code's point on a case: its label, steps, worst L1 error over the case's profile times,
/// its wall time over courant's, and its largest stress difference from courant's run.
struct Point {
    label: String,
    steps: Option<usize>,
    l1: Option<f64>,
    ratio: f64,
    difference: Option<f64>,
}

/// A case of a scene: courant's steps and worst L1 error, and the other codes' points.
struct CaseRow {
    case: String,
    steps: Option<usize>,
    l1: Option<f64>,
    points: Vec<Point>,
}

/// Every timed case of a committed set: `(case, steps, wall_s)` from its `results.toml`.
fn timed_cases(
    set: &crate::results::exchange::committed::CommittedSet,
) -> Vec<(String, Option<usize>, f64)> {
    let Some((_, text)) = set.files.iter().find(|(name, _)| *name == "results.toml") else {
        return Vec::new();
    };
    let Ok(m) = meta::parse(set.dir, text) else {
        return Vec::new();
    };
    m.cases
        .iter()
        .filter_map(|(case, c)| c.wall_s.map(|w| (case.clone(), c.steps, w)))
        .collect()
}

/// Ratios' minimum, median and maximum.
fn spread(mut values: Vec<f64>) -> Option<(f64, f64, f64)> {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    (n > 0).then(|| (values[0], values[n / 2], values[n - 1]))
}

/// The subsection, or nothing when no committed set records its code's time.
pub fn section(scenes: &[Scene], outcomes: &[(SceneOutcome, f64)], others: &[OtherCode]) -> Page {
    let times: Vec<(&str, Vec<CourantTime>)> = COURANT_TIMES
        .iter()
        .map(|(code, text)| (*code, courant_times(text)))
        .collect();
    let courant_wall = |code: &str, scene: &str, case: &str| {
        times
            .iter()
            .filter(|(c, _)| *c == code)
            .flat_map(|(_, rows)| rows)
            .find(|r| r.scene == scene && r.case == case)
            .map(|r| r.wall)
    };
    let mut page = Page::default();
    let mut blocks = Page::default();
    // Per code label, over every scene: (ratio, difference from courant) of its timed cases.
    let mut by_label: Vec<(String, Vec<f64>, Vec<f64>)> = Vec::new();
    for (index, scene) in scenes.iter().enumerate() {
        let outcome = &outcomes[index].0;
        let scale = scene
            .cases
            .first()
            .and_then(|c| c.reference.as_ref())
            .map_or(1.0, |r| r.stress_scale());
        // In the scene's case order.
        let mut rows: Vec<CaseRow> = Vec::new();
        for (set, _, scored) in others.iter().filter(|(_, i, _)| *i == index) {
            for (case, steps, wall) in timed_cases(set) {
                let Some(own_wall) = courant_wall(set.code, &scene.name, &case) else {
                    continue;
                };
                let own = outcome.results.iter().find(|r| r.run.case == case);
                let file = scored.cases.iter().find(|c| c.case == case);
                let point = Point {
                    label: set.label.to_string(),
                    steps,
                    l1: file.and_then(|c| c.worst_norms()).map(|n| n.l1),
                    ratio: wall / own_wall,
                    difference: file
                        .zip(own)
                        .and_then(|(f, o)| difference_from_courant(f, o, scale)),
                };
                match rows.iter_mut().find(|r| r.case == case) {
                    Some(row) => row.points.push(point),
                    None => rows.push(CaseRow {
                        steps: own.map(|r| r.run.steps),
                        l1: own.and_then(|r| r.worst_norms()).map(|n| n.l1),
                        case,
                        points: vec![point],
                    }),
                }
            }
        }
        if rows.is_empty() {
            continue;
        }
        let order = |case: &str| scene.cases.iter().position(|c| c.name == case);
        rows.sort_by_key(|r| order(&r.case));
        let mut table = Table::new(&[
            "case",
            "code",
            "steps",
            "l1",
            "max_difference",
            "time_over_courant",
        ]);
        let mut series: Vec<(String, Vec<(f64, f64)>)> = vec![("courant".into(), Vec::new())];
        for CaseRow {
            case,
            steps,
            l1,
            points,
        } in &rows
        {
            table.push(vec![
                case.as_str().into(),
                "courant".into(),
                (*steps).into(),
                (*l1).into(),
                Some(0.0).into(),
                1.0.into(),
            ]);
            if let Some(l1) = l1 {
                series[0].1.push((1.0, *l1));
            }
            for p in points {
                table.push(vec![
                    case.as_str().into(),
                    p.label.as_str().into(),
                    p.steps.into(),
                    p.l1.into(),
                    p.difference.into(),
                    p.ratio.into(),
                ]);
                if let Some(l1) = p.l1 {
                    match series.iter_mut().find(|s| s.0 == p.label) {
                        Some(s) => s.1.push((p.ratio, l1)),
                        None => series.push((p.label.clone(), vec![(p.ratio, l1)])),
                    }
                }
                match by_label.iter_mut().find(|b| b.0 == p.label) {
                    Some(b) => {
                        b.1.push(p.ratio);
                        b.2.push(p.difference.unwrap_or(f64::INFINITY));
                    }
                    None => by_label.push((
                        p.label.clone(),
                        vec![p.ratio],
                        vec![p.difference.unwrap_or(f64::INFINITY)],
                    )),
                }
            }
        }
        blocks.push(Block::Heading(
            4,
            format!("Cost across codes: {}", scene.name),
        ));
        blocks.table(table, format!("other_codes/cost_{}.csv", scene.name));
        let title = format!("{}: error against wall time, every code", scene.name);
        let drawn: Vec<Series> = series
            .into_iter()
            .filter(|(_, points)| !points.is_empty())
            .map(|(label, points)| Series::new(label, points, SeriesStyle::Points))
            .collect();
        let axes = Axes::log_log(
            title.clone(),
            "wall time / courant's on the same case",
            "worst L1 / |sigma0|",
        );
        if let Ok(svg) = line_chart(&axes, &drawn) {
            blocks.figure(
                format!("other_codes/cost_{}.svg", scene.name),
                svg,
                format!(
                    "{title}: each point a case of the scene, its worst L1 error over the profile \
                     times against its wall time over courant's on the same case (courant at 1)"
                ),
            );
        }
    }
    if by_label.is_empty() {
        return page;
    }
    page.push(Block::Heading(3, "Cost across codes".into()));
    let measured: Vec<String> = times
        .iter()
        .filter_map(|(code, rows)| {
            rows.first().map(|r| {
                format!(
                    "the {code} driver measured courant on {} ({}, median of {} runs)",
                    r.measured, r.cpu, r.repeat
                )
            })
        })
        .collect();
    page.push(Block::Paragraph(format!(
        "Error against time for every case another code ran and timed: each code's worst L1 error \
         over the case's profile times against its wall time over courant's on the same case. A \
         code's time is its own time loop as its driver measured it (`wall_s` in the set's \
         `results.toml`, the median of at least 3 runs: SfePy's `pb.solve()`, with M and K assembled \
         in its first step; OpenSees' `analyze` calls); courant's is the run time that `courant \
         run` reports for the same case on one thread, measured by the same driver right after, on the same \
         machine (`external/<code>/courant_times.csv`; {}). Only ratios are shown: the times \
         themselves belong to the machine. `max_difference` is the largest difference of the \
         code's element stresses from courant's at the same times, over |sigma0|.",
        measured.join("; ")
    )));
    let mut trade = Vec::new();
    for (label, ratios, differences) in &by_label {
        let largest = differences.iter().copied().fold(0.0, f64::max);
        let Some((lo, median, hi)) = spread(ratios.clone()) else {
            continue;
        };
        let answer = if largest <= 1e-8 {
            format!("the same answer (stresses within {largest:.1e} |sigma0| of courant's)")
        } else {
            format!("a different answer (stresses up to {largest:.2} |sigma0| from courant's)")
        };
        trade.push(format!(
            "{label} took {} to {} times courant's time (median {}) for {answer}",
            ratio_text(lo),
            ratio_text(hi),
            ratio_text(median)
        ));
    }
    page.push(Block::Paragraph(format!(
        "The trade: a code that runs courant's scheme and mass on courant's mesh and step gets \
         courant's error to round-off, so on the same case the time is all that differs and more \
         time buys no accuracy; the error moves with the scheme, the mass and the Courant number, \
         the same way in every code (lumped mass at Co = 1 exact on these meshes, the dispersive \
         cases at the same error), and a code's place on the figures is its distance to the right \
         of courant at the same height. {}. Where a code's answer differs on the same case, its set's \
         diagnostics and stated findings (section Other codes) name the cause.",
        trade.join("; ")
    )));
    page.extend(blocks);
    page
}

/// A time ratio with three significant digits (`0.412`, `7.35`, `763`), never a bare 0 for a
/// code faster than courant.
fn ratio_text(ratio: f64) -> String {
    if ratio >= 100.0 {
        format!("{ratio:.0}")
    } else if ratio >= 10.0 {
        format!("{ratio:.1}")
    } else if ratio >= 1.0 {
        format!("{ratio:.2}")
    } else {
        format!("{ratio:.3}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::results::exchange::committed::COMMITTED;

    /// Every committed `courant_times.csv` reads whole, and every timed case of a committed set
    /// has courant's time beside it (the ratios the report shows are all defined).
    #[test]
    fn every_timed_case_has_courant_time_beside_it() {
        for (code, text) in COURANT_TIMES {
            let lines = text.lines().filter(|l| !l.trim().is_empty()).count();
            assert_eq!(
                courant_times(text).len() + 1,
                lines,
                "{code}: a row does not read"
            );
        }
        let mut timed = 0;
        for set in COMMITTED {
            for (case, steps, wall) in timed_cases(set) {
                timed += 1;
                assert!(
                    wall > 0.0 && steps.is_some_and(|s| s > 0),
                    "{} {case}",
                    set.dir
                );
                let found = COURANT_TIMES
                    .iter()
                    .filter(|(c, _)| *c == set.code)
                    .flat_map(|(_, t)| courant_times(t))
                    .any(|r| r.scene == set.scene && r.case == case);
                assert!(
                    found,
                    "{} {case}: no courant time in courant_times.csv",
                    set.dir
                );
            }
        }
        assert!(timed > 0, "no committed set records its code's time");
    }
}
