//! The work-precision section of the report: for each study, the L1 error against work
//! (elements x steps) and against steps per method, as log-log figures and a table; the error
//! against CPU time goes to the timing page ([`cpu_chart`]).

use super::document::{Block, Page};
use super::plot::{Axes, Series, SeriesStyle, line_chart};
use crate::compare::work_precision::{WorkPoint, equal_error_saving, table};
use crate::scene::studies::work_precision::{
    COMBINATION_FAST, COMBINATION_SLOW, COMBINATION_STUDY, WORK_PRECISION_STUDIES,
    WorkPrecisionStudy,
};

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
         of meshes: the cheapest way to a given accuracy is the lowest curve. How the error and the work \
         are measured is at the end of this section."
            .into(),
    ));
    page.extend(noh_bathe_beside_the_seed(work));
    for (study, points) in WORK_PRECISION_STUDIES.iter().zip(work) {
        page.extend(study_page(study, points));
    }
    page.push(Block::Heading(
        3,
        "How the error and the work are measured".into(),
    ));
    page.push(Block::Paragraph(
        "Stress studies measure the \
         normalised L1 error of the profile, the contact study the L1-in-time error of the contact force over \
         the exact impulse (elements of both bars). Each run's Courant number (relative to the stiffest \
         element) and its scheme's exact critical one are in the Co and Co_crit columns; a scheme whose stable \
         step is far below the others' runs at its own, stated in its label (CD with penalty at beta_s = 2500 \
         at 0.9 of its critical Courant number 0.0200). A node-step does not cost the same in every scheme: the \
         benchmark table in `timing.md` gives ns per node-step of each integrator (`cargo bench`), and the CPU \
         times of these runs are there too. The third figure of each study counts element force \
         evaluations (elements x steps x K u per step: one for CD and the contact schemes, two for Park \
         and Noh-Bathe), the work that does not depend on how fast a kernel is written. So that a comparison \
         of CPU times is one of methods, `timing.md` states each run's time over its force-evaluation \
         floor (`time_over_floor`): its wall time over K u per step x elements x steps x t_f, t_f the time \
         of one lumped element force evaluation measured in the same report run (the lumped CD kernel on a \
         graded bar of 10^4 elements, median of 5); per scheme, the median and the least over its \
         runs."
            .into(),
    ));
    page
}

/// Where Noh-Bathe beats the seed's schemes and where it loses: the framing (each claim held by
/// an expectation of the scene named), then, per study that runs it, its L1 error and cost on
/// the finest mesh against every other method's, computed from the points.
fn noh_bathe_beside_the_seed(work: &[Vec<WorkPoint>]) -> Page {
    let mut page = Page::default();
    page.push(Block::Heading(
        3,
        "Noh-Bathe beside the seed's schemes".into(),
    ));
    page.push(Block::Paragraph(
        "The Noh-Bathe scheme (p = 0.54) costs two internal-force evaluations per step and may take \
         1.8725 times central difference's step. Its error and cost on the finest mesh of each study \
         that runs it, against every other method's; where it wins and where it loses below."
            .into(),
    ));
    let mut lines = Vec::new();
    for (study, points) in WORK_PRECISION_STUDIES.iter().zip(work) {
        let finest = points.iter().map(|p| p.elements).max().unwrap_or(0);
        let at_finest: Vec<&WorkPoint> = points.iter().filter(|p| p.elements == finest).collect();
        let Some(nb) = at_finest.iter().find(|p| p.method == "noh-bathe") else {
            continue;
        };
        let others: Vec<String> = at_finest
            .iter()
            .filter(|p| p.method != nb.method)
            .map(|p| {
                format!(
                    "{:.2} x {}'s L1 ({:.3e}) for {:.2} x its force evaluations",
                    nb.l1 / p.l1,
                    p.method,
                    p.l1,
                    nb.element_force_evaluations() as f64 / p.element_force_evaluations() as f64
                )
            })
            .collect();
        lines.push(format!(
            "{} (N = {finest}): Noh-Bathe's L1 error {:.3e} is {}.",
            study.name,
            nb.l1,
            others.join(", ")
        ));
    }
    page.push(Block::List(lines));
    page.push(Block::Paragraph(
        "Where it wins: at its own limit it damps the \
         unresolved modes, so the step front of the Fig. 1 and Fig. 2 bars has no trailing ringing \
         (total variation 1.4 and 1.6, no overshoot on the graded bar: scenes fig1_schemes and \
         courant_sweep_own_limits), and at 0.9 of each scheme's own limit it reaches about a third of \
         CD's L1 error for about the same number of force evaluations (below). Where it loses: to \
         CD wherever CD is exact (Co = 1 on the uniform and on the equal-transit layered mesh: \
         fig1_schemes, and layered, where it rings with total variation 23 at Co = 1); at the seed's \
         step Co = 0.5 on the graded bar, 0.27 of its own limit, where its damping barely acts: it \
         rings like CD (total variation 6.3 against 5.9 in fig2) and gains little over CD for twice \
         the force evaluations (fig2_schemes, below); and to Park's scheme with local stepping on \
         both bars, which reaches Noh-Bathe's error with about half the force evaluations (Park at \
         N = 800 against Noh-Bathe at N = 1600 on the Fig. 1 bar, at N = 200 against N = 400 on the \
         graded bar, in the tables of fig1_schemes and fig2_own_limits)."
            .into(),
    ));
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
    let charts: [(&str, &str, Abscissa, &str); 3] = [
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
        (
            ".force_evaluations",
            "element force evaluations: elements x steps x K u per step",
            |p| p.element_force_evaluations() as f64,
            "Error against element force evaluations (a step of Park or Noh-Bathe costs two K u, of CD one)",
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
    if study.name == COMBINATION_STUDY {
        page.push(Block::Paragraph(combination_saving(points)));
    }
    page
}

/// What Park's local stepping with the bipenalty saves against the global step with the
/// penalty at equal error, computed from the study's points (machine-independent work only;
/// the CPU times are on the timing page).
fn combination_saving(points: &[WorkPoint]) -> String {
    let mut text = String::from(
        "At equal error, from the rows above (the error both reach: the larger of the two \
         methods' smallest L1 force errors over these meshes; each method's cheapest run within it):",
    );
    for slow in COMBINATION_SLOW {
        let Some(s) = equal_error_saving(points, COMBINATION_FAST, slow) else {
            continue;
        };
        text.push_str(&format!(
            " Against {slow}, both within {:.3}: {} (N = {}, error {:.3}) takes {} steps and {} \
             element force evaluations, {slow} (N = {}, error {:.3}) {} and {}, {:.0} times the \
             steps and {:.0} times the element force evaluations.",
            s.error,
            s.fast.method,
            s.fast.elements,
            s.fast.l1,
            s.fast.steps,
            s.fast.element_force_evaluations(),
            s.slow.elements,
            s.slow.l1,
            s.slow.steps,
            s.slow.element_force_evaluations(),
            s.step_ratio(),
            s.evaluation_ratio()
        ));
    }
    let best = |method: &str| {
        points
            .iter()
            .filter(|p| p.method == method)
            .min_by(|a, b| a.l1.total_cmp(&b.l1))
    };
    if let Some(fast) = best(COMBINATION_FAST) {
        text.push_str(&format!(
            " {}'s smallest error is {:.3} (N = {});",
            fast.method, fast.l1, fast.elements
        ));
    }
    for slow in COMBINATION_SLOW {
        if let Some(p) = best(slow) {
            text.push_str(&format!(" {slow}'s {:.3} (N = {});", p.l1, p.elements));
        }
    }
    if text.ends_with(';') {
        text.pop();
    }
    // "Does not converge": on the finest mesh the error is not below half the coarsest mesh's,
    // for every penalty run shown (read off the rows, not assumed).
    let stalls = |method: &str| {
        let mut runs: Vec<_> = points.iter().filter(|p| p.method == method).collect();
        runs.sort_by_key(|p| p.elements);
        match (runs.first(), runs.last()) {
            (Some(coarse), Some(fine)) if runs.len() > 1 => fine.l1 > 0.5 * coarse.l1,
            _ => false,
        }
    };
    if COMBINATION_SLOW.iter().all(|m| stalls(m)) {
        text.push_str(
            ": on the finest mesh no penalty run's error is below half its coarsest mesh's (the \
             transferred force rings at the contact spring's period), so the saving grows as the \
             error asked for falls.",
        );
    } else {
        text.push('.');
    }
    text
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
