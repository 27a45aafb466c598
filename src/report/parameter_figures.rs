//! Figures of a parameter sweep (a scheme parameter given as a list, `theta = [0, 0.25, ...]`):
//! for each swept numeric parameter, the L1 error and the total-variation ratio of every case
//! against the parameter, one curve per group of cases that differ only in it (and per profile
//! time), with the scene's cases that do not take the parameter (e.g. central difference beside
//! Park's theta) as dashed horizontal lines. The same numbers are in the scene's `norms.csv`.

use super::plot::{Axes, PALETTE_SIZE, Series, SeriesStyle, line_chart};
use crate::compare::case::CaseResult;
use crate::compare::norms::ErrorNorms;
use crate::compare::outcome::SceneOutcome;
use crate::scene::cases::Scene;
use courant_solver::integrator::ParameterValue;

/// A measure drawn against the parameter: file stem, axis label, log axis (legend room never
/// pushes a log axis below zero), its value from a profile's norms.
type Measure = (
    &'static str,
    &'static str,
    bool,
    fn(&ErrorNorms) -> Option<f64>,
);

const MEASURES: [Measure; 2] = [
    ("l1", "L1 error / |sigma0|", true, |n| Some(n.l1)),
    ("tv_ratio", "TV / TV exact", true, |n| n.tv_ratio),
];

/// `(file name, caption, svg)` of every swept numeric parameter of the scene (none when no
/// parameter is a list).
pub fn parameter_figures(scene: &Scene, outcome: &SceneOutcome) -> Vec<(String, String, String)> {
    let mut keys: Vec<&str> = Vec::new();
    for case in &scene.cases {
        for (key, value) in &case.swept {
            if matches!(value, ParameterValue::Number(_)) && !keys.contains(&key.as_str()) {
                keys.push(key);
            }
        }
    }
    let mut figures = Vec::new();
    for key in keys {
        for measure in MEASURES {
            if let Some(figure) = figure(scene, outcome, key, measure) {
                figures.push(figure);
            }
        }
    }
    figures
}

/// A case's value of `key`, if it takes it as a swept number.
fn value_of(scene: &Scene, case: &str, key: &str) -> Option<f64> {
    let case = scene.cases.iter().find(|c| c.name == case)?;
    case.swept.iter().find_map(|(k, v)| match v {
        ParameterValue::Number(x) if k == key => Some(*x),
        _ => None,
    })
}

/// A case's name without its `key` token: the group its curve belongs to.
fn group_of(case: &str, key: &str, value: f64) -> String {
    let token = format!("{key}{}", crate::scene::names::number(value));
    case.split('-')
        .filter(|part| *part != token)
        .collect::<Vec<_>>()
        .join("-")
}

fn figure(
    scene: &Scene,
    outcome: &SceneOutcome,
    key: &str,
    (stem, label, log, pick): Measure,
) -> Option<(String, String, String)> {
    let times: Vec<f64> = outcome
        .results
        .iter()
        .max_by_key(|r| r.profiles.len())?
        .profiles
        .iter()
        .map(|p| p.time)
        .collect();
    let at = |r: &CaseResult, k: usize| -> Option<f64> {
        r.profiles
            .get(k)
            .and_then(|p| p.norms.as_ref())
            .and_then(pick)
    };
    let transit = scene
        .cases
        .first()
        .filter(|c| c.times_in_transits)
        .map(|c| c.transit_time);
    let time_label = |t: f64| match transit {
        Some(tt) => format!("t = {:.4} T", t / tt),
        None => format!("t = {t:.4}"),
    };
    // Curves: (group, profile index) -> points sorted by the parameter.
    let mut groups: Vec<String> = Vec::new();
    for r in &outcome.results {
        if let Some(v) = value_of(scene, &r.run.case, key) {
            let g = group_of(&r.run.case, key, v);
            if !groups.contains(&g) {
                groups.push(g);
            }
        }
    }
    let range = outcome
        .results
        .iter()
        .filter_map(|r| value_of(scene, &r.run.case, key))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    let mut series = Vec::new();
    let mut colour = 0;
    for group in &groups {
        for (k, &t) in times.iter().enumerate() {
            let mut points: Vec<(f64, f64)> = outcome
                .results
                .iter()
                .filter_map(|r| {
                    let v = value_of(scene, &r.run.case, key)?;
                    (group_of(&r.run.case, key, v) == *group).then_some((v, at(r, k)?))
                })
                .collect();
            if points.is_empty() {
                continue;
            }
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            let name = format!("{group}, {}", time_label(t));
            series.push(Series::new(name, points.clone(), SeriesStyle::Line).with_colour(colour));
            series.push(
                Series::new("", points, SeriesStyle::Points)
                    .with_colour(colour)
                    .without_legend(),
            );
            colour = (colour + 1) % PALETTE_SIZE;
        }
    }
    if series.is_empty() {
        return None;
    }
    // The cases without the parameter, as horizontal lines across the swept range.
    for r in outcome
        .results
        .iter()
        .filter(|r| value_of(scene, &r.run.case, key).is_none())
    {
        for (k, &t) in times.iter().enumerate() {
            if let Some(y) = at(r, k) {
                series.push(
                    Series::new(
                        format!("{} (no {key}), {}", r.run.case, time_label(t)),
                        vec![(range.0, y), (range.1, y)],
                        SeriesStyle::Dashed,
                    )
                    .with_colour(colour),
                );
                colour = (colour + 1) % PALETTE_SIZE;
            }
        }
    }
    let title = format!("{}: {label} against {key}", scene.name);
    let svg = line_chart(&Axes::new(title.clone(), key, label).log_y(log), &series).ok()?;
    let caption = format!(
        "{title}: each case of the sweep at each profile time (points joined in order of {key}); \
         dashed, the scene's cases that do not take {key}. The numbers are in norms.csv."
    );
    Some((format!("sweep_{key}_{stem}.svg"), caption, svg))
}
