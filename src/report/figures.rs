//! The report's figures of a scene, as SVG strings (plotted by [`super::plot`]): profiles
//! against the exact solution, spectra errors, contact force histories and the contact
//! stability graph. A figure with nothing plottable (e.g. errors that are exactly zero on a
//! log axis) is left out. Scenes with more cases than one legible figure holds get several
//! figures, split by scheme and mass kind ([`split`]); a case that is not drawn is named in a
//! caption with the reason.

use super::figure_parts::{
    MAX_CASES, caption, chart_naming_omissions, names, numbered, part_file, split,
};
use super::plot::{Axes, PALETTE_SIZE, Series, SeriesStyle, line_chart};
use crate::compare::case::CaseResult;
use crate::compare::contact::ContactResult;
use crate::compare::growth::ENERGY_BAND;
use crate::compare::outcome::SceneOutcome;
use crate::compare::sweep::{SweepResult, SweepRow};
use crate::results::case::Status;
use crate::scene::cases::Scene;

/// `(file name, caption, svg)` figures of a scene. Every case appears in some figure or is named
/// in a caption as not shown, with the reason (diverged before that time, energy blow-up, or no
/// drawable point).
pub fn scene_figures(scene: &Scene, outcome: &SceneOutcome) -> Vec<(String, String, String)> {
    let mut figures = Vec::new();
    // A parameter sweep's summary first: the profiles of its many cases follow.
    figures.extend(super::parameter_figures::parameter_figures(scene, outcome));
    profile_figures(scene, outcome, &mut figures);
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
        // The closed form each spectrum is checked against, dashed in the same colour.
        let closed: Vec<Series> = s
            .closed_form
            .iter()
            .flatten()
            .enumerate()
            .map(|(i, w)| {
                let points = s
                    .modes
                    .iter()
                    .zip(w)
                    .zip(exact)
                    .filter(|(_, e)| **e > 0.0)
                    .map(|((&mode, w), e)| (mode as f64 / n, w / e - 1.0))
                    .collect();
                let line =
                    Series::new("closed form (dashed)", points, SeriesStyle::Dashed).with_colour(i);
                if i == 0 { line } else { line.without_legend() }
            })
            .collect();
        let series: Vec<Series> = series.into_iter().chain(closed).collect();
        let title = format!("{}: relative frequency error, {}", scene.name, s.case);
        if let Ok(svg) = line_chart(
            &Axes::new(title.clone(), "mode n / modes", "omega_n,h / omega_n - 1"),
            &series,
        ) {
            let caption = format!(
                "{title}: the computed frequencies of each mass kind against the continuum (solid) \
                 and the closed-form discrete spectrum of methods.md §5 (dashed, same colour)"
            );
            figures.push((format!("spectrum_{}.svg", s.case), caption, svg));
        }
    }
    force_figures(scene, outcome, &mut figures);
    stability_figures(scene, outcome, &mut figures);
    figures
}

/// Stress profiles at each profile time, every case beside the exact element averages, split by
/// scheme and mass kind into figures of at most [`MAX_CASES`] cases; runs that diverged after
/// the profile time come last, in figures of their own.
fn profile_figures(
    scene: &Scene,
    outcome: &SceneOutcome,
    figures: &mut Vec<(String, String, String)>,
) {
    let Some(longest) = outcome.results.iter().max_by_key(|r| r.profiles.len()) else {
        return;
    };
    for (k, profile) in longest.profiles.iter().enumerate() {
        let (shown, missing): (Vec<_>, Vec<_>) = outcome
            .results
            .iter()
            .partition(|r| r.profiles.get(k).is_some());
        // Runs that diverged later grow without bound and would flatten every other curve:
        // they get figures of their own, after the others.
        let (completed, diverged): (Vec<_>, Vec<_>) = shown
            .into_iter()
            .partition(|r| !matches!(r.run.status, Status::Diverged(_)));
        let key = |r: &&CaseResult| format!("{} {}", r.run.scheme, r.run.critical.mass.label());
        let calm = split(completed.iter().map(|r| (key(r), *r)).collect(), MAX_CASES);
        let calm_parts = calm.len();
        let mut parts = calm;
        parts.extend(split(
            diverged.iter().map(|r| (key(r), *r)).collect(),
            MAX_CASES,
        ));
        let title = format!(
            "{}: stress at {}",
            scene.name,
            time_label(scene, longest, profile.time)
        );
        for (j, part) in parts.iter().enumerate() {
            let scaled = |r: &CaseResult, values: &[f64]| -> Vec<(f64, f64)> {
                let (length, stress) = scales(scene, r);
                let p = &r.profiles[k];
                p.x.iter()
                    .zip(values)
                    .map(|(x, s)| (x / length, s / stress))
                    .collect()
            };
            let cases: Vec<Series> = part
                .iter()
                .map(|r| {
                    Series::new(
                        case_label(r),
                        scaled(r, &r.profiles[k].stress),
                        SeriesStyle::Line,
                    )
                })
                .collect();
            let exact: Vec<Series> = part
                .iter()
                .find_map(|r| {
                    r.profiles[k].reference.as_ref().map(|reference| {
                        Series::new("exact", scaled(r, reference), SeriesStyle::Dashed)
                    })
                })
                .into_iter()
                .collect();
            let mut notes = Vec::new();
            if j >= calm_parts {
                notes.push("these runs diverged later (status in the summary)".to_string());
            }
            if j == 0 && !missing.is_empty() {
                notes.push(format!(
                    "not shown, diverged before {}: {}",
                    time_label(scene, longest, profile.time),
                    names(missing.iter().map(|r| r.run.case.as_str()))
                ));
            }
            let part_title = numbered(&title, j, parts.len());
            let y_label = if exact.is_empty() {
                "stress"
            } else {
                "stress / |sigma0|"
            };
            let axes = Axes::new(part_title.clone(), "x / L", y_label);
            if let Some(svg) = chart_naming_omissions(&axes, cases, exact, &mut notes) {
                let file = part_file(&format!("profile_{k}"), j, parts.len());
                let caption = caption(
                    &part_title,
                    part.iter().map(|r| r.run.case.as_str()),
                    &parts,
                    outcome.results.len(),
                    &notes,
                );
                figures.push((file, caption, svg));
            }
        }
    }
}

/// Contact force histories beside 1D wave theory, one figure per scheme or group of schemes of
/// at most [`MAX_CASES`] cases. Diverged runs and runs that pumped energy into the bars (more
/// than [`ENERGY_BAND`] times the initial energy left in them, the
/// measure of the stability table) would swamp the axis: the caption names them instead.
fn force_figures(
    scene: &Scene,
    outcome: &SceneOutcome,
    figures: &mut Vec<(String, String, String)>,
) {
    if outcome.contact.is_empty() {
        return;
    }
    let (shown, unstable): (Vec<_>, Vec<_>) = outcome
        .contact
        .iter()
        .partition(|c| c.energy_ratio_conserved.is_some_and(|e| e <= ENERGY_BAND));
    let keyed = shown
        .into_iter()
        .map(|c| (c.run.scheme.label().to_string(), c))
        .collect();
    let parts = split(keyed, MAX_CASES);
    let title = format!("{}: contact force", scene.name);
    let transit = |c: &ContactResult| {
        scene
            .contact
            .iter()
            .find(|k| k.name == c.case)
            .map_or(1.0, |k| k.striker_transit)
    };
    let mut first_notes = Vec::new();
    if !unstable.is_empty() {
        first_notes.push(format!(
            "not shown, diverged or left with more than {} times the initial energy (see \
             energy_ratio_conserved and status in the summary): {}",
            ENERGY_BAND,
            names(unstable.iter().map(|c| c.case.as_str()))
        ));
    }
    // Nothing stable: one figure of the reference alone, whose caption names the cases.
    let parts = if parts.is_empty() {
        vec![Vec::new()]
    } else {
        parts
    };
    for (j, part) in parts.iter().enumerate() {
        let cases: Vec<Series> = part
            .iter()
            .map(|c| {
                Series::new(
                    c.case.clone(),
                    c.run
                        .history
                        .iter()
                        .map(|s| (s.time / transit(c), c.measure.force(s) / c.plateau))
                        .collect(),
                    SeriesStyle::Line,
                )
            })
            .collect();
        // The reference sampled as finely as any case of the figure.
        let finest = part
            .iter()
            .copied()
            .max_by_key(|c| c.run.history.len())
            .or(outcome.contact.first());
        let label = scene
            .contact
            .first()
            .map_or_else(|| "1D wave theory".into(), |c| c.reference.label());
        let exact: Vec<Series> = finest
            .map(|c| {
                Series::new(
                    label.as_str(),
                    c.run
                        .history
                        .iter()
                        .map(|s| s.time / transit(c))
                        .zip(c.reference.iter().map(|f| f / c.plateau))
                        .collect(),
                    SeriesStyle::Dashed,
                )
            })
            .into_iter()
            .collect();
        let mut notes = if j == 0 {
            std::mem::take(&mut first_notes)
        } else {
            Vec::new()
        };
        let part_title = numbered(&title, j, parts.len());
        // Peaks over several decades (the seed's CD force grows with beta_s): a log force axis,
        // on which the open contact (force 0) is not drawn.
        let peaks = part.iter().map(|c| c.errors.max_force).filter(|f| *f > 0.0);
        let (lo, hi) = peaks.fold((f64::INFINITY, 0.0_f64), |(lo, hi), f| {
            (lo.min(f), hi.max(f))
        });
        let log = hi > 100.0 * lo;
        if log {
            notes.push("log force axis: the peaks span several decades; an open contact (force 0) is not drawn".into());
        }
        let measures: Vec<&str> = part.iter().map(|c| c.measure.label()).collect();
        let measure = if measures.iter().all(|m| *m == measures[0]) && !measures.is_empty() {
            measures[0]
        } else {
            "force_measure in the summary"
        };
        let axes = Axes::new(
            part_title.clone(),
            "t / T1 (striker transit L1/c1)",
            format!("force / F1 ({measure}; F1 first plateau)"),
        )
        .log_y(log);
        if let Some(svg) = chart_naming_omissions(&axes, cases, exact, &mut notes) {
            let file = part_file("force", j, parts.len());
            let caption = caption(
                &part_title,
                part.iter().map(|c| c.case.as_str()),
                &parts,
                outcome.contact.len(),
                &notes,
            );
            figures.push((file, caption, svg));
        }
    }
}

/// The contact stability graph (seed Fig. 3), one figure per part of [`stability_charts`].
fn stability_figures(
    scene: &Scene,
    outcome: &SceneOutcome,
    figures: &mut Vec<(String, String, String)>,
) {
    for (s, sweep) in outcome.sweeps.iter().enumerate() {
        let title = format!(
            "{}: critical Courant number (closed form within {:.1e})",
            scene.name,
            sweep.deviation()
        );
        let parts = stability_charts(sweep);
        for (j, (curves, series)) in parts.iter().enumerate() {
            let part_title = numbered(&title, j, parts.len());
            let Ok(svg) = line_chart(&Axes::log_log(part_title.clone(), "beta_s", "Cr"), series)
            else {
                continue;
            };
            let file = if parts.len() == 1 && s == 0 {
                "stability.svg".to_string()
            } else {
                format!("stability_{}_{}.svg", s + 1, j + 1)
            };
            let overlap = if sweep.rows.iter().any(|r| r.ratio.is_some_and(|r| r <= 1.0)) {
                "; the curves of r <= 1 coincide (Cr = 1) and overlap"
            } else {
                ""
            };
            let caption = format!(
                "{part_title}: the solver's eigenvalues of the contact-active system (points) and \
                 the closed form of courant-references (dashed line of the same colour) for {}{overlap}.",
                names(curves.iter().map(String::as_str))
            );
            figures.push((file, caption, svg));
        }
    }
}

/// The series of the contact stability graph (seed Fig. 3), in parts of at most the palette's
/// 8 curves: per curve (penalty only, each ratio r, named as in the legend) the solver's critical
/// Courant numbers as points and the closed form of `courant-references` (methods.md §7) as a
/// dashed line, both in the curve's palette colour. The points are hollow and shrink from curve
/// to curve, so curves that coincide (every r <= 1 sits at Cr = 1) stay visible as concentric
/// rings; the closed forms are drawn last, over the points, and share one legend entry,
/// `closed form (dashed)`.
pub fn stability_charts(sweep: &SweepResult) -> Vec<(Vec<String>, Vec<Series>)> {
    let mut curves: Vec<(String, Vec<&SweepRow>)> = Vec::new();
    for row in &sweep.rows {
        let name = row
            .ratio
            .map_or("penalty only".to_string(), |r| format!("r = {r}"));
        match curves.iter_mut().find(|c| c.0 == name) {
            Some(c) => c.1.push(row),
            None => curves.push((name, vec![row])),
        }
    }
    let parts = split(
        curves.into_iter().map(|c| (c.0.clone(), c)).collect(),
        PALETTE_SIZE,
    );
    parts
        .into_iter()
        .map(|part| {
            let closed = part.iter().enumerate().map(|(colour, (_, rows))| {
                let closed = Series::new(
                    "closed form (dashed)",
                    rows.iter().map(|r| (r.beta_s, r.closed_form)).collect(),
                    SeriesStyle::Dashed,
                )
                .with_colour(colour);
                if colour == 0 {
                    closed
                } else {
                    closed.without_legend()
                }
            });
            let solver = part.iter().enumerate().map(|(colour, (name, rows))| {
                Series::new(
                    name.clone(),
                    rows.iter().map(|r| (r.beta_s, r.courant)).collect(),
                    SeriesStyle::Points,
                )
                .with_colour(colour)
            });
            let series = solver.chain(closed).collect();
            (part.into_iter().map(|(name, _)| name).collect(), series)
        })
        .collect()
}

/// A profile time as the scene states it: `t = 0.5 T` (transit times) or `t = 0.005`.
fn time_label(scene: &Scene, result: &CaseResult, t: f64) -> String {
    match scene.cases.iter().find(|c| c.name == result.run.case) {
        Some(case) if case.times_in_transits => {
            format!("t = {:.4} T", t / case.transit_time)
        }
        _ => format!("t = {t:.4}"),
    }
}

/// `(L, |sigma0|)` of a case: its bar's length and its reference's stress scale (1 without a
/// reference), so profiles are drawn as `x / L` against `stress / |sigma0|` (methods.md §1).
fn scales(scene: &Scene, r: &CaseResult) -> (f64, f64) {
    scene
        .cases
        .iter()
        .find(|c| c.name == r.run.case)
        .map_or((1.0, 1.0), |c| {
            (
                c.model.bar().mesh().length(),
                c.reference.as_ref().map_or(1.0, |r| r.stress_scale()),
            )
        })
}

/// A case's legend label: its name, with the Courant number it ran at when the name states
/// another unit (`cmm-co1 (Co = 0.5747)`: 1 of CMM's critical Courant number).
fn case_label(r: &CaseResult) -> String {
    let named = r
        .run
        .case
        .rsplit_once("co")
        .and_then(|(_, v)| v.parse::<f64>().ok());
    match named {
        Some(v) if (v - r.run.courant).abs() <= 1e-6 * v.abs() => r.run.case.clone(),
        _ => format!("{} (Co = {:.4})", r.run.case, r.run.courant),
    }
}
