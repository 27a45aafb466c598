//! The work-precision section of the report: for each study, the L1 error against work
//! (elements x steps) and against steps per method, as log-log figures and a table; the error
//! against CPU time goes to the timing page ([`cpu_chart`]).

use super::document::{Block, Page};
use super::plot::{Axes, Series, SeriesStyle, line_chart};
use crate::compare::work_precision::{WorkPoint, table};
use crate::scene::studies::work_precision::{WORK_PRECISION_STUDIES, WorkPrecisionStudy};

/// One series per label ([`WorkPoint::label`]), in order of first appearance, of the points
/// `(x(p), l1)` kept by `keep` (labels with no point kept are left out).
fn series_by_label(
    points: &[WorkPoint],
    keep: impl Fn(&WorkPoint) -> bool,
    x: impl Fn(&WorkPoint) -> f64,
    style: SeriesStyle,
) -> Vec<Series> {
    let mut labels: Vec<String> = Vec::new();
    for p in points {
        let label = p.label();
        if !labels.contains(&label) {
            labels.push(label);
        }
    }
    labels
        .into_iter()
        .map(|label| {
            let pts = points
                .iter()
                .filter(|p| p.label() == label && keep(p))
                .map(|p| (x(p), p.l1))
                .collect();
            Series::new(label, pts, style)
        })
        .filter(|s| !s.points.is_empty())
        .collect()
}

/// The abscissa of a work-precision chart.
type Abscissa = fn(&WorkPoint) -> f64;

/// The work-precision section: the introduction, then per study its figures and table.
pub fn section(work: &[Vec<WorkPoint>]) -> Page {
    let mut page = Page::default();
    page.push(Block::Heading(2, "Work and precision".into()));
    page.push(Block::Paragraph(
        "Error against work (elements x steps, machine-independent) per scheme or mass kind over a sequence \
         of meshes: the cheapest way to a given accuracy is the lowest curve. Stress studies measure the \
         normalised L1 error of the profile, the contact study the L1-in-time error of the contact force over \
         the exact impulse (elements of both bars). Each run's Courant number (relative to the stiffest \
         element) and its scheme's exact critical one are in the Co and Co_crit columns; a scheme whose stable \
         step is far below the others' runs at its own, stated in its label (CD with penalty at beta_s = 2500 \
         at 0.9 of its critical Courant number 0.0200). A node-step does not cost the same in every scheme: the \
         benchmark table in `timing.md` gives ns per node-step of each integrator (`cargo bench`), and the CPU \
         times of these runs are there too."
            .into(),
    ));
    for (study, points) in WORK_PRECISION_STUDIES.iter().zip(work) {
        page.extend(study_page(study, points));
    }
    page
}

/// One study: figures of the L1 error against elements x steps and against steps, per method,
/// and the table.
pub fn study_page(study: &WorkPrecisionStudy, points: &[WorkPoint]) -> Page {
    let mut page = Page::default();
    page.push(Block::Heading(3, study.title.into()));
    let settings = if study.variants.len() > 1 {
        "; each scheme at the Courant setting in its label (Co relative to the stiffest element, \
         Co_crit the exact critical Courant number of its scheme; both in the table)"
    } else {
        ""
    };
    let charts: [(&str, &str, Abscissa, &str); 2] = [
        (
            "",
            "work: elements x steps",
            |p| (p.elements * p.steps) as f64,
            "Error against work (elements x steps)",
        ),
        (
            ".steps",
            "steps",
            |p| p.steps as f64,
            "Error against the number of steps",
        ),
    ];
    for (suffix, x_label, x, what) in charts {
        // A line per label and its meshes as dots of the same colour.
        let lines = series_by_label(points, |_| true, x, SeriesStyle::Line);
        let dots: Vec<Series> = lines
            .iter()
            .enumerate()
            .map(|(i, line)| {
                Series::new(line.name.clone(), line.points.clone(), SeriesStyle::Points)
                    .with_colour(i)
                    .without_legend()
            })
            .collect();
        let series: Vec<Series> = lines.into_iter().chain(dots).collect();
        if let Ok(svg) = line_chart(&Axes::log_log(study.title, x_label, study.error), &series) {
            page.figure(
                format!("work_precision/{}{suffix}.svg", study.name),
                svg,
                format!("{what}: {}{settings}", study.title),
            );
        }
    }
    page.table(table(points), format!("work_precision/{}.csv", study.name));
    page
}

/// Machine-dependent companion of [`study_page`]: the error against the CPU time of each run (wall
/// time of the integration, one thread), as a log-log SVG per study, labelled as in [`study_page`];
/// `None` when no point has a positive time.
pub fn cpu_chart(study: &WorkPrecisionStudy, points: &[WorkPoint]) -> Option<String> {
    // Points, not a line: timings of short runs are noisy and need not grow with N.
    let series = series_by_label(
        points,
        |p| p.wall_time > 0.0,
        |p| p.wall_time,
        SeriesStyle::Points,
    );
    line_chart(
        &Axes::log_log(study.title, "CPU time of the run [s]", study.error),
        &series,
    )
    .ok()
}
