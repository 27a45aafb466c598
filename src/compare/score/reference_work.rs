//! The reference work a result file or a query file asks for, estimated and bounded before any
//! evaluation, as scene validation bounds a scene's (`scene::work`): a file's times are its own,
//! so a line with `t = 999` on the graded bar (an hour of characteristics, or beyond where the
//! reference is defined, NaN) is refused at its line and `t` column, naming the reference's
//! limit, instead of being evaluated.

use crate::results::exchange::error::ExchangeError;
use crate::results::exchange::record::{CaseFile, Positions, Profile};
use crate::scene::budget::{LAYERED_WAVE_WORK, MAX_REFERENCE_WORK};
use crate::scene::reference::{GRADED_EXTREME_SAMPLES, Reference};
use courant_references::graded::CHARACTERISTIC_TRANSITS_MAX;

/// Evaluations of the reference per profile when a file is graded: the exact values, their
/// mirror image (the layout diagnostic) and the time-level fit's evaluations at shifted times.
/// An upper bound of what `compare::score` does, counted like the scene budget's work.
pub const EVALUATIONS_PER_PROFILE: f64 = 8.0;

/// Check that `reference` is defined at every profile time of `file` and that evaluating it
/// there stays within [`MAX_REFERENCE_WORK`] in all (`extent` is the bar's).
///
/// # Errors
/// The first line whose time the reference does not reach, or at which the work summed so far
/// passes the limit, at its `t` column, with the limit.
pub fn check_reference_work(
    file: &CaseFile,
    profiles: &[Profile],
    reference: &Reference,
    (start, _end): (f64, f64),
) -> Result<(), ExchangeError> {
    let mut work = 0.0;
    for p in profiles {
        let t = p.time;
        let at = |message: String| {
            ExchangeError::at(
                &file.file,
                p.lines.first().copied().unwrap_or(0),
                file.column("t"),
                "t",
                message,
            )
        };
        let per_evaluation = match reference {
            Reference::Dalembert(_) => 0.0,
            Reference::Graded(g) => {
                let Some(one) = g.evaluation_work(t) else {
                    return Err(at(format!(
                        "t = {t:e} is beyond where the graded reference is defined: {CHARACTERISTIC_TRANSITS_MAX} transit \
                         times (t <= {:.6e} on this bar)",
                        CHARACTERISTIC_TRANSITS_MAX * g.transit_time()
                    )));
                };
                let evaluations = match &p.positions {
                    Positions::Elements { left, right } => {
                        let mut nodes: Vec<f64> = left.iter().map(|x| x - start).collect();
                        nodes.extend(right.last().map(|x| x - start));
                        g.average_evaluations(&nodes, t) as f64
                    }
                    Positions::Points(x) => x.len() as f64,
                } + (GRADED_EXTREME_SAMPLES + 1) as f64
                    + 2.0 * g.front_positions(t).len() as f64;
                evaluations * one
            }
            Reference::Layered(l) => match l.field(t) {
                Ok(field) => 2.0 * field.wave_count() as f64 * LAYERED_WAVE_WORK,
                Err(e) => {
                    return Err(at(format!(
                        "t = {t:e} is beyond what the layered reference can reach: {e}"
                    )));
                }
            },
        };
        work += EVALUATIONS_PER_PROFILE * per_evaluation;
        if work > MAX_REFERENCE_WORK || work.is_nan() {
            return Err(at(format!(
                "evaluating the {} reference up to this line (t = {t:e}) would take {work:.2e} units of work \
                 (~7 ns each; it grows with the time and the number of values), more than the \
                 {MAX_REFERENCE_WORK:.0e} a file may ask for, as for a scene; give earlier times or fewer rows",
                reference.name()
            )));
        }
    }
    Ok(())
}
