//! The reference work a result file or a query file asks for, estimated and bounded before any
//! evaluation, as scene validation bounds a scene's (`scene::work`): a file's times are its own,
//! so a line with `t = 999` on the graded bar (an hour of characteristics, or beyond where the
//! reference is defined, NaN) is refused at its line and `t` column, naming the reference's
//! limit, instead of being evaluated.

use crate::results::exchange::error::ExchangeError;
use crate::results::exchange::record::{CaseFile, Positions, Profile};
use crate::scene::budget::MAX_REFERENCE_WORK;
use crate::scene::reference::Reference;
use courant_references::Evaluation;

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
        let exact = reference.exact();
        let one = exact.evaluation_work(t).map_err(|e| {
            at(format!(
                "t = {t:e} is beyond what the {} reference can reach: {e}",
                reference.name()
            ))
        })?;
        let nodes: Vec<f64>;
        let values = match &p.positions {
            Positions::Elements { left, right } => {
                nodes = left.iter().chain(right.last()).map(|x| x - start).collect();
                Evaluation::Averages(&nodes)
            }
            Positions::Points(x) => Evaluation::Points(x),
        };
        let evaluations = exact.evaluations(values, t) + exact.evaluations(Evaluation::Extreme, t);
        let per_evaluation = evaluations as f64 * one;
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
