//! The report's figures, as SVG strings (plotted by [`crate::plot`]): profiles against the exact
//! solution, spectra errors, contact force histories, the contact stability graph and the
//! convergence plots. A figure with nothing plottable (e.g. errors that are exactly zero on a
//! log axis) is left out.

use crate::plot::{Axes, Series, SeriesStyle, line_chart};
use crate::report::ConvergenceResult;
use crate::run::SceneOutcome;
use crate::scene::Scene;

/// At most this many cases per figure (the palette has 8 colours; the legend stays readable).
const MAX_CASES: usize = 5;

/// `(file name, caption, svg)` figures of a scene.
pub fn scene_figures(scene: &Scene, outcome: &SceneOutcome) -> Vec<(String, String, String)> {
    let mut figures = Vec::new();
    // Stress profiles at each profile time, every case beside the exact element averages.
    if let Some(first) = outcome.results.first() {
        for (k, profile) in first.profiles.iter().enumerate() {
            let mut series: Vec<Series> = outcome
                .results
                .iter()
                .take(MAX_CASES)
                .filter_map(|r| {
                    r.profiles.get(k).map(|p| {
                        Series::new(
                            r.case.clone(),
                            p.x.iter().copied().zip(p.stress.iter().copied()).collect(),
                            SeriesStyle::Line,
                        )
                    })
                })
                .collect();
            if let Some(reference) = &profile.reference {
                series.push(Series::new(
                    "exact",
                    profile
                        .x
                        .iter()
                        .copied()
                        .zip(reference.iter().copied())
                        .collect(),
                    SeriesStyle::Dashed,
                ));
            }
            let title = format!("{}: stress at t = {:.4}", scene.name, profile.time);
            if let Ok(svg) = line_chart(&Axes::new(title.clone(), "x", "stress"), &series) {
                figures.push((format!("profile_{k}.svg"), title, svg));
            }
        }
    }
    // Spectra: relative frequency error per mode for each mass kind.
    for s in &outcome.spectra {
        let Some(exact) = &s.continuum else { continue };
        let n = s.modes.len() as f64;
        let series: Vec<Series> = s
            .masses
            .iter()
            .zip(&s.computed)
            .map(|(m, w)| {
                let points = s
                    .modes
                    .iter()
                    .zip(w)
                    .zip(exact)
                    .filter(|(_, e)| **e > 0.0)
                    .map(|((&mode, w), e)| (mode as f64 / n, w / e - 1.0))
                    .collect();
                Series::new(m.label(), points, SeriesStyle::Line)
            })
            .collect();
        let title = format!("{}: relative frequency error, {}", scene.name, s.case);
        if let Ok(svg) = line_chart(
            &Axes::new(title.clone(), "mode / modes", "omega_h / omega - 1"),
            &series,
        ) {
            figures.push((format!("spectrum_{}.svg", s.case), title, svg));
        }
    }
    // Contact force histories beside 1D wave theory.
    if let Some(first) = outcome.contact.first() {
        // Stable, energy-conserving cases, the predictor-corrector and Lagrange-multiplier ones
        // first (CD bipenalty chatters at large beta_s and would hide the others).
        let mut shown: Vec<&crate::contact_study::ContactResult> = outcome
            .contact
            .iter()
            .filter(|c| c.diverged.is_none() && c.energy_ratio < 2.0)
            .collect();
        shown.sort_by_key(|c| {
            !matches!(
                c.run.scheme.label(),
                "predictor-corrector" | "lagrange-multiplier"
            )
        });
        let mut series: Vec<Series> = shown
            .into_iter()
            .take(MAX_CASES)
            .map(|c| {
                Series::new(
                    c.case.clone(),
                    c.run.history.iter().map(|s| (s.time, s.force)).collect(),
                    SeriesStyle::Line,
                )
            })
            .collect();
        series.push(Series::new(
            "1D wave theory",
            first
                .run
                .history
                .iter()
                .map(|s| s.time)
                .zip(first.reference.iter().copied())
                .collect(),
            SeriesStyle::Dashed,
        ));
        let title = format!(
            "{}: contact force (stable, energy-conserving cases)",
            scene.name
        );
        if let Ok(svg) = line_chart(&Axes::new(title.clone(), "t", "force"), &series) {
            figures.push(("force.svg".into(), title, svg));
        }
    }
    // Contact stability graph.
    for sweep in &outcome.sweeps {
        let mut curves: Vec<Series> = Vec::new();
        for row in &sweep.rows {
            let name = row
                .ratio
                .map_or("penalty only".to_string(), |r| format!("r = {r}"));
            match curves.iter_mut().find(|c| c.name == name) {
                Some(c) => c.points.push((row.beta_s, row.courant)),
                None => curves.push(Series::new(
                    name,
                    vec![(row.beta_s, row.courant)],
                    SeriesStyle::Line,
                )),
            }
        }
        let title = format!(
            "{}: critical Courant number (solver eigenvalues; closed form within {:.1e})",
            scene.name,
            sweep.deviation()
        );
        if let Ok(svg) = line_chart(&Axes::log_log(title.clone(), "beta_s", "Cr"), &curves) {
            figures.push(("stability.svg".into(), title, svg));
        }
    }
    figures
}

/// The log-log error figure of a convergence study (`None` when the errors are at round-off).
pub fn convergence_figure(result: &ConvergenceResult) -> Option<String> {
    let pick = |name: &str, f: fn(&crate::report::Level) -> f64| {
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
