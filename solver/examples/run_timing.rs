//! Whole runs timed (the harness of benches/RESULTS.md, heading "... the run's start, the mass
//! check, where the state lives ..."): central difference with
//! one mass on the graded seed bar of N elements at half its critical Courant number, an energy
//! sample every step (as scenes take them), through `Integration::run_assembled`; the mass is
//! assembled outside the timing, the run's start inside, as in criterion's `run_loop_large`.
//! Prints the median and least of REPS runs. With STEPS = 1 it times a run's start (the start,
//! one step and the final mass check).
//!
//! ```text
//! cargo run --release -p courant-solver --example run_timing -- N STEPS MASS [REPS]
//!   MASS: cmm | amm | rmm | lmm (amm, rmm with beta = 1/2); REPS: 5
//! ```

use courant_solver::integrator::OutputRequest;
use courant_solver::{CentralDifference, MassOperator};
use std::time::Instant;

mod harness;

fn main() {
    let (n, steps, kind, reps) = harness::arguments(1_000_000, 300);
    let reps = reps.map_or(5, |s| harness::whole_number("REPS", &s));
    let model = courant_solver::bench::graded_seed_bar(n).expect("bar");
    let element_dt = model.bar().stiffest_element().1;
    let request = OutputRequest {
        energy_every: 1,
        history_every: steps,
        ..OutputRequest::default()
    };
    let integration = CentralDifference {
        mass: kind,
        ..CentralDifference::new(0.5 * kind.critical_courant() * element_dt)
    }
    .integration();
    let mut times: Vec<f64> = (0..reps.max(1))
        .map(|_| {
            let mass = MassOperator::new(&model, integration.mass).expect("mass");
            let clock = Instant::now();
            let out = (integration.run_assembled(&model, steps, &request, mass)).expect("run");
            assert_eq!(out.steps, steps);
            clock.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    let median = times[times.len() / 2];
    println!(
        "{kind:?} N = {n}, {steps} steps: median {:.1} ms, least {:.1} ms, {:.3} ns per node-step",
        median * 1e3,
        times[0] * 1e3,
        median * 1e9 / ((n + 1) * steps) as f64
    );
}
