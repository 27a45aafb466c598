//! The convergence section: per study its expected behaviour, a log-log figure of the errors
//! against N, the table of errors and observed orders, and the fitted orders with their verdicts.

use super::document::{Block, Page};
use super::plot::{Axes, Series, SeriesStyle, line_chart};
use crate::compare::convergence::{ConvergenceResult, Level};

/// The section of every study.
pub fn section(convergence: &[ConvergenceResult]) -> Page {
    let mut page = Page::default();
    page.push(Block::Heading(2, "Convergence studies".into()));
    page.push(Block::Paragraph(
        "Errors of element stresses against the exact element averages, normalised by |sigma0| and L; \
         observed orders between successive meshes, and the order fitted by least squares on the finest \
         three meshes, checked against the band theory allows where it gives one."
            .into(),
    ));
    for c in convergence {
        page.push(Block::Heading(3, c.study.title.into()));
        page.push(Block::Paragraph(format!("Expected: {}", c.study.expected)));
        if let Some(svg) = convergence_figure(c) {
            page.figure(
                format!("convergence/{}.svg", c.study.name),
                svg,
                format!("Errors against N: {}", c.study.title),
            );
        }
        page.table(c.table(), format!("convergence/{}.csv", c.study.name));
        page.table(
            c.verdict_table(),
            format!("convergence/{}.orders.csv", c.study.name),
        );
    }
    page
}

/// The log-log error figure of a convergence study (`None` when the errors are at round-off).
pub fn convergence_figure(result: &ConvergenceResult) -> Option<String> {
    let pick = |name: &str, f: fn(&Level) -> f64| {
        Series::new(
            name,
            result
                .levels
                .iter()
                .map(|l| (l.elements as f64, f(l)))
                .filter(|p| p.1 > 1e-12)
                .collect(),
            SeriesStyle::Line,
        )
    };
    let series = vec![
        pick("L1", |l| l.l1),
        pick("L2", |l| l.l2),
        pick("Linf", |l| l.linf),
    ];
    if series.iter().any(|s| s.points.len() < 2) {
        return None;
    }
    line_chart(
        &Axes::log_log(result.study.title, "N", "error / |sigma0|"),
        &series,
    )
    .ok()
}
