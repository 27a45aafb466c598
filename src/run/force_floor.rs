//! The force-evaluation floor of the work-precision runs: the measured time of one lumped
//! element force evaluation, so that each run's wall time can be stated as a multiple of what its
//! element force evaluations cost at the fastest kernel's rate (the timing page's
//! `time_over_floor`; docs/guide/report.md, the timing files).
//!
//! ```text
//!   t_f   = median over 5 repeats of  T(S steps of the lumped CD kernel) / (N S)
//!   floor = (K u per step) x elements x steps x t_f        time_over_floor = wall time / floor
//! ```
//!
//! The kernel is `courant_solver::bench::LumpedStep::step_with_energy` (one sweep: one element
//! force evaluation per element and step, the update and the energies) on the graded seed bar of
//! `N = 10^4` elements (in cache, like the studies' meshes), `S = 1000` steps at Co 0.5, from
//! a smooth velocity field over the whole bar (no subnormal values ahead of a front). It is
//! timed after the studies have run, alone on the machine's threads.

use courant_solver::bench::{LumpedStep, graded_seed_bar, smooth_half_velocity};
use std::time::Instant;

/// Elements of the timed bar.
pub const FLOOR_ELEMENTS: usize = 10_000;
/// Steps per timing.
pub const FLOOR_STEPS: usize = 1_000;
/// Timings whose median is taken.
pub const FLOOR_REPEATS: usize = 5;

/// `t_f`, seconds per element force evaluation (module docs); `None` if the bar cannot be built
/// or a timing is not positive.
pub fn element_force_seconds() -> Option<f64> {
    let model = graded_seed_bar(FLOOR_ELEMENTS).ok()?;
    let dt = 0.5 * model.bar().stiffest_element().1;
    let u0 = vec![0.0; FLOOR_ELEMENTS + 1];
    let v_half = smooth_half_velocity(FLOOR_ELEMENTS);
    let forces = [(0usize, 0.0f64)];
    let mut times: Vec<f64> = (0..FLOOR_REPEATS)
        .map(|_| {
            let mut kernel = LumpedStep::new(&model, dt, &u0, &v_half);
            let started = Instant::now();
            for _ in 0..FLOOR_STEPS {
                std::hint::black_box(kernel.step_with_energy(&forces));
            }
            started.elapsed().as_secs_f64() / (FLOOR_ELEMENTS * FLOOR_STEPS) as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    let median = times[FLOOR_REPEATS / 2];
    (median > 0.0 && median.is_finite()).then_some(median)
}
