//! The contact stability sweep (seed Fig. 3): the critical Courant number of a bar against a
//! rigid wall with its contact active, from the solver's exact eigenvalue bisection.

use crate::io::parallel::in_order;
use crate::results::sweep::{SweepPoint, SweepRecord};
use crate::scene::contact::StabilitySweep;
use courant_solver::contact::{ContactCriticalStep, ContactProblem, ContactScheme, MassPenalty};
use courant_solver::{Bar, End, InputError, Mesh};
use rayon::prelude::*;
use std::time::Instant;

/// Evaluate the sweep: a unit free bar (E = rho = A = 1) of `elements` elements against a rigid
/// wall; the critical Courant number of its contact-active system (`(K + K_p, M + M_p)`,
/// exact bisection). The points are independent and evaluated in parallel (rayon), kept in
/// curve order; an error is that of the first failing point in that order.
///
/// # Errors
/// The solver refuses a penalty (e.g. a `beta_s` that is not positive and finite).
pub fn run_sweep(sweep: &StabilitySweep) -> Result<SweepRecord, InputError> {
    let started = Instant::now();
    let bar = Bar::homogeneous(Mesh::uniform(1.0, sweep.elements)?, 1.0, 1.0, 1.0)?;
    let problem = ContactProblem::wall_impact(bar, End::Right, 1.0, 0.0)?;
    let grid: Vec<(Option<f64>, f64)> = sweep
        .ratios
        .iter()
        .flat_map(|&ratio| sweep.beta_s.iter().map(move |&beta_s| (ratio, beta_s)))
        .collect();
    let points = in_order(
        grid.par_iter()
            .map(|&(ratio, beta_s)| sweep_point(&problem, ratio, beta_s))
            .collect(),
    )?;
    Ok(SweepRecord {
        points,
        wall_time: started.elapsed(),
    })
}

/// One point of [`run_sweep`]: penalty only (`ratio` `None`) or bipenalty with penalty ratio `r`.
fn sweep_point(
    problem: &ContactProblem,
    ratio: Option<f64>,
    beta_s: f64,
) -> Result<SweepPoint, InputError> {
    let mass = ratio.map_or(MassPenalty::None, MassPenalty::Ratio);
    let penalty = problem.penalty(beta_s, mass)?;
    let scheme = if ratio.is_some() {
        ContactScheme::Bipenalty(penalty)
    } else {
        ContactScheme::Penalty {
            stiffness: penalty.stiffness,
        }
    };
    let critical = ContactCriticalStep::of(problem, &scheme)?;
    Ok(SweepPoint {
        beta_s,
        ratio,
        courant: critical.contact_active / critical.stiffest_transit,
    })
}
