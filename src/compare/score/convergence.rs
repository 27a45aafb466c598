//! Several result sets of one case at different N: a convergence study (observed orders between
//! meshes, the order fitted on the finest three) against the band of the report's study of the
//! same case (`scene::studies::convergence`), as `courant report` judges courant's own runs.

use super::bind::profile_times;
use super::outcome::{CaseConvergence, Scored, ScoredSet};
use crate::compare::convergence::{ConvergenceResult, Level};
use crate::compare::expect::at_time;
use crate::scene::cases::{Case, Scene};
use crate::scene::studies::convergence::{CONVERGENCE_STUDIES, ConvergenceStudy};

/// A study without a band: orders measured only.
const MEASURED: ConvergenceStudy = ConvergenceStudy {
    name: "measured",
    title: "measured only",
    expected: "no band: no report study runs this case",
    scene: "",
    replacements: &[],
    bands: [None; 3],
};

/// The report's study of `case` of `scene`: same scene, mass kind, scheme (its label, with its parameters),
/// Courant number and first profile time.
pub fn study_of(scene: &Scene, case: &Case) -> Option<ConvergenceStudy> {
    let courant = |c: &Case| c.integrator.dt / c.critical.element_transit;
    let first = |c: &Case| profile_times(c).first().copied();
    CONVERGENCE_STUDIES
        .iter()
        .filter(|s| s.scene == scene.name)
        .find(|s| {
            let Ok(derived) = s.scene() else { return false };
            derived.cases.first().is_some_and(|c| {
                c.integrator.mass == case.integrator.mass
                    && c.integrator.scheme.label() == case.integrator.scheme.label()
                    && (courant(c) - courant(case)).abs() <= 1e-9 * courant(case)
                    && first(c)
                        .zip(first(case))
                        .is_some_and(|(a, b)| (a - b).abs() <= 1e-9 * b.abs())
            })
        })
        .cloned()
}

/// A study per case of `scene` that two or more sets give at distinct element counts, levels
/// sorted by N, errors at the case's first profile time.
pub fn convergence(scene: &Scene, sets: &[ScoredSet]) -> Vec<CaseConvergence> {
    let mut out = Vec::new();
    for case in &scene.cases {
        let Some(&t) = profile_times(case).first() else {
            continue;
        };
        let mut levels: Vec<Level> = sets
            .iter()
            .flat_map(|s| s.cases.iter().filter(|c| c.case == case.name))
            .filter_map(|c| {
                let Scored::Profiles { profiles, .. } = &c.scored else {
                    return None;
                };
                let dt = c.dt.map_or(f64::NAN, |d| d.0);
                let p = profiles
                    .iter()
                    .find(|p| at_time(Some(t), p.time, dt.max(0.0)))?;
                Some(Level {
                    elements: c.elements?,
                    dt,
                    steps: (p.time / dt).round() as usize,
                    l1: p.norms.l1,
                    l2: p.norms.l2,
                    linf: p.norms.linf,
                    wall_time: 0.0,
                })
            })
            .collect();
        levels.sort_by_key(|l| l.elements);
        let distinct = levels.windows(2).all(|w| w[0].elements < w[1].elements);
        if levels.len() < 2 || !distinct {
            continue;
        }
        let masses_agree = sets
            .iter()
            .flat_map(|s| s.cases.iter().filter(|c| c.case == case.name))
            .all(|c| {
                c.mass
                    .as_ref()
                    .is_none_or(|m| *m == case.integrator.mass.label())
            });
        let (study, note) = match study_of(scene, case) {
            Some(study) if masses_agree => (study, None),
            Some(_) => (
                MEASURED,
                Some(format!(
                    "results.toml names another mass than the case's {}: no band",
                    case.integrator.mass.label()
                )),
            ),
            None => (MEASURED, Some(MEASURED.expected.to_string())),
        };
        out.push(CaseConvergence {
            case: case.name.clone(),
            result: ConvergenceResult { study, levels },
            note,
        });
    }
    out
}
