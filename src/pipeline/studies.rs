//! The report's studies, run and compared: each case of a study's derived scenes runs once, in
//! parallel; results keep the study's order.

use super::evaluate_case;
use crate::compare::contact::compare_contact;
use crate::compare::convergence::{ConvergenceResult, Level};
use crate::compare::work_precision::WorkPoint;
use crate::io::parallel::in_order;
use crate::run::contact::run_contact;
use crate::scene::cases::{Case, Scene};
use crate::scene::contact::ContactCase;
use crate::scene::studies::convergence::ConvergenceStudy;
use crate::scene::studies::work_precision::{WorkPrecisionStudy, study_scenes};
use courant_solver::contact::combined::BulkScheme;
use rayon::prelude::*;

/// Run a convergence study: every mesh of its scene, in parallel, errors at its first profile
/// time.
///
/// # Errors
/// The study's scene no longer derives from its built-in scene, or a case fails to run.
pub fn run_convergence(study: &ConvergenceStudy) -> Result<ConvergenceResult, String> {
    let scene = study.scene()?;
    let levels = scene
        .cases
        .par_iter()
        .map(|case| {
            let r = evaluate_case(case).map_err(|e| e.to_string())?;
            let n = r
                .profiles
                .first()
                .and_then(|p| p.norms)
                .ok_or("no profile norms")?;
            Ok(Level {
                elements: r.elements,
                dt: r.run.dt,
                steps: r.run.steps,
                l1: n.l1,
                l2: n.l2,
                linf: n.linf,
                wall_time: r.run.wall_time.as_secs_f64(),
            })
        })
        .collect::<Vec<Result<_, String>>>();
    Ok(ConvergenceResult {
        study: study.clone(),
        levels: in_order(levels)?,
    })
}

/// Run a work-precision study: every case of its derived scenes, in parallel, in order.
///
/// # Errors
/// A derived scene does not parse, a case fails to run, or a contact case diverges.
pub fn run_work_precision(study: &WorkPrecisionStudy) -> Result<Vec<WorkPoint>, String> {
    let scenes = study_scenes(study)?;
    if !study.contact_meshes.is_empty() {
        return run_contact_study(study, &scenes);
    }
    let cases: Vec<(Option<&'static str>, &Case)> = scenes
        .iter()
        .flat_map(|(setting, scene)| scene.cases.iter().map(move |c| (*setting, c)))
        .collect();
    let points = cases
        .par_iter()
        .map(|&(setting, case)| {
            let r = evaluate_case(case).map_err(|e| e.to_string())?;
            let l1 = r
                .profiles
                .first()
                .and_then(|p| p.norms)
                .map(|n| n.l1)
                .ok_or("no profile norms")?;
            // n<N>-<method>-co<Co>: keep the method.
            let method = case
                .name
                .split('-')
                .skip(1)
                .take_while(|part| !part.starts_with("co"))
                .collect::<Vec<_>>()
                .join("-");
            Ok(WorkPoint {
                method,
                setting,
                courant: r.run.courant,
                // Co_crit = Co dt_crit/dt with dt_crit the limit of the case's scheme (CD:
                // 2/omega_max; Park: alpha_e <= 1; Noh-Bathe: Omega_crit(p)/omega_max).
                critical_courant: r.run.courant * r.run.limit.dt() / r.run.dt,
                elements: r.elements,
                steps: r.run.steps,
                force_evaluations: case.integrator.scheme.force_evaluations(),
                l1,
                wall_time: r.run.wall_time.as_secs_f64(),
            })
        })
        .collect::<Vec<Result<_, String>>>();
    in_order(points)
}

/// A contact study: one derived scene per striker mesh and variant, every case of each;
/// `elements` counts the elements of all bodies, the error is
/// [`crate::compare::contact::ForceErrors::force_l1_error`] of the graded force.
fn run_contact_study(
    study: &WorkPrecisionStudy,
    scenes: &[(Option<&'static str>, Scene)],
) -> Result<Vec<WorkPoint>, String> {
    let cases: Vec<(Option<&'static str>, &ContactCase)> = scenes
        .iter()
        .flat_map(|(setting, scene)| scene.contact.iter().map(move |c| (*setting, c)))
        .collect();
    let points = cases
        .par_iter()
        .map(|&(setting, case)| {
            let record = run_contact(case).map_err(|e| e.to_string())?;
            let r = compare_contact(record, case.reference.history(), case.force);
            if let Some(d) = &r.diverged {
                return Err(format!(
                    "study {}: case {} diverged: {d}",
                    study.name, case.name
                ));
            }
            Ok(WorkPoint {
                method: case.name.clone(),
                setting,
                courant: r.run.courant,
                critical_courant: r.run.critical.critical_courant(),
                elements: case
                    .problem
                    .bodies()
                    .iter()
                    .map(|b| b.bar().element_count())
                    .sum(),
                steps: r.run.steps,
                // Central difference on the bulk: one K u per step; Park's scheme two (the
                // element predictions and the step's internal force, methods.md §6), every
                // element stepping each global step; the contact update is O(1).
                force_evaluations: match case.bulk.map(|b| b.scheme) {
                    Some(BulkScheme::Park(_)) => 2,
                    _ => 1,
                },
                l1: r.errors.force_l1_error,
                wall_time: r.wall_time.as_secs_f64(),
            })
        })
        .collect::<Vec<Result<_, String>>>();
    in_order(points)
}
