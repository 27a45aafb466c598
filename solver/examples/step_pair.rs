//! The matrix-mass step and the lumped step timed alternately in one process (the harness of
//! benches/RESULTS.md, heading "... the run's start, the mass check, where the state lives ..."
//! and later): both on the graded seed bar of N elements at half their
//! critical Courant numbers, nine repetitions of STEPS/9 steps each, medians in ns per
//! node-step and their ratio. Alternating in one process puts both under the same machine load;
//! criterion (`cargo bench --bench cd_step`) remains the reference.
//!
//! ```text
//! cargo run --release -p courant-solver --example step_pair -- N STEPS MASS [WHICH]
//!   MASS: cmm | amm | rmm | lmm (amm, rmm with beta = 1/2)
//!   WHICH: both (default) | matrix | lumped | check (the mass check alone, ms)
//! ```

use courant_solver::bench::LumpedStep;
use courant_solver::bench::smooth_half_velocity;
use std::time::Instant;

mod harness;

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times.get(times.len() / 2).copied().unwrap_or(f64::NAN)
}

fn main() {
    let (n, steps, kind, which) = harness::arguments(100_000, 2000);
    let which = which.as_deref().unwrap_or("both");
    if !["both", "matrix", "lumped", "check"].contains(&which) {
        harness::fail(&format!(
            "WHICH: {which} is not one of both, matrix, lumped, check"
        ));
    }
    let model = courant_solver::bench::graded_seed_bar(n).expect("bar");
    let element_dt = model.bar().stiffest_element().1;
    let mut matrix = courant_solver::bench::matrix_step(&model, kind).expect("mass");
    let (v, zeros) = (smooth_half_velocity(n), vec![0.0; n + 1]);
    let mut lumped = LumpedStep::new(&model, 0.5 * element_dt, &zeros, &v);
    let forces = [(0usize, 1.0f64)];
    for _ in 0..steps / 10 {
        matrix.step_with_energy(&forces);
        lumped.step_with_energy(&forces);
    }
    if which == "check" {
        let times = (0..21).map(|_| {
            let clock = Instant::now();
            std::hint::black_box(matrix.staggered_kinetic_from_mass());
            clock.elapsed().as_secs_f64() * 1e3
        });
        println!(
            "{kind:?} N = {n}: mass check {:.3} ms",
            median(times.collect())
        );
        return;
    }
    let per = (steps / 9).max(1);
    let node_steps = (per * (n + 1)) as f64;
    let (mut matrix_times, mut lumped_times) = (Vec::new(), Vec::new());
    for _ in 0..9 {
        if which != "lumped" {
            let clock = Instant::now();
            for _ in 0..per {
                std::hint::black_box(matrix.step_with_energy(&forces));
            }
            matrix_times.push(clock.elapsed().as_secs_f64() * 1e9 / node_steps);
        }
        if which != "matrix" {
            let clock = Instant::now();
            for _ in 0..per {
                std::hint::black_box(lumped.step_with_energy(&forces));
            }
            lumped_times.push(clock.elapsed().as_secs_f64() * 1e9 / node_steps);
        }
    }
    let (m, l) = (median(matrix_times), median(lumped_times));
    let timed = match which {
        "matrix" => format!("matrix {m:.3} ns per node-step"),
        "lumped" => format!("lumped {l:.3} ns per node-step"),
        _ => format!(
            "matrix {m:.3}, lumped {l:.3} ns per node-step, ratio {:.2}",
            m / l
        ),
    };
    println!("{kind:?} N = {n}: {timed}");
}
