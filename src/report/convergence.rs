//! The convergence section: per study its expected behaviour, a log-log figure of the errors
//! against N, the table of errors and observed orders, and the fitted orders with their verdicts.

use super::document::{Block, Page};
use super::plot::{Axes, Series, SeriesStyle, line_chart};
use crate::compare::convergence::{ConvergenceResult, Level};
use crate::scene::studies::convergence::OrderBand;

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
    let lines = vec![
        pick("L1", |l| l.l1),
        pick("L2", |l| l.l2),
        pick("Linf", |l| l.linf),
    ];
    if lines.iter().any(|s| s.points.len() < 2) {
        return None;
    }
    // A marker at every mesh, in the colour of its norm.
    let markers: Vec<Series> = lines
        .iter()
        .enumerate()
        .map(|(i, s)| {
            Series::new(s.name.clone(), s.points.clone(), SeriesStyle::Points)
                .with_colour(i)
                .without_legend()
        })
        .collect();
    // For each norm with an order band, a dashed guide in the norm's colour through the finest
    // mesh at the band's middle slope, labelled with the band itself (the middle alone would
    // read as a prediction: "slope -0.07" for a max error that theory says does not converge).
    let guides: Vec<Series> = lines
        .iter()
        .zip(result.study.bands)
        .enumerate()
        .filter_map(|(i, (line, band))| match band {
            Some(OrderBand::Order { min, max }) => {
                let order = 0.5 * (min + max);
                let &(n_f, e_f) = line.points.last()?;
                let &(n_0, _) = line.points.first()?;
                Some(
                    Series::new(
                        format!("{} expected order {min:.2} to {max:.2}", line.name),
                        [n_0, n_f]
                            .iter()
                            .map(|&n| (n, e_f * (n / n_f).powf(-order)))
                            .collect(),
                        SeriesStyle::Dashed,
                    )
                    .with_colour(i),
                )
            }
            _ => None,
        })
        .collect();
    let series: Vec<Series> = lines.into_iter().chain(markers).chain(guides).collect();
    line_chart(
        &Axes::log_log(result.study.title, "N", "error / |sigma0|"),
        &series,
    )
    .ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::studies::convergence::CONVERGENCE_STUDIES;

    /// The dashed guides are labelled with the band the verdict checks (the Fig. 1 CMM study:
    /// L1 0.42-0.56, max error -0.25 to 0.10, methods.md §3), not with the band's middle alone,
    /// which for a max error that does not converge read as a predicted slope of -0.07.
    #[test]
    fn convergence_guides_are_labelled_with_their_order_bands() {
        let study = CONVERGENCE_STUDIES
            .iter()
            .find(|s| s.name == "fig1_cmm")
            .expect("the Fig. 1 CMM study")
            .clone();
        let levels = [50, 100, 200]
            .iter()
            .map(|&elements| {
                let h = 1.0 / elements as f64;
                Level {
                    elements,
                    dt: h,
                    steps: elements,
                    l1: h.sqrt(),
                    l2: h.cbrt(),
                    linf: 0.6,
                    wall_time: 0.0,
                }
            })
            .collect();
        let svg = convergence_figure(&ConvergenceResult { study, levels }).expect("a figure");
        assert!(svg.contains("L1 expected order 0.42 to 0.56"), "{svg}");
        assert!(svg.contains("Linf expected order -0.25 to 0.10"), "{svg}");
        assert!(!svg.contains("slope"), "{svg}");
    }
}
