//! Whole runs of each scheme beside lumped central difference, alternating in one process (the
//! harness of benches/RESULTS.md, heading "2026-11-28: every scheme's run against lumped CD"):
//! on the graded seed bar of N elements at Co 0.5 of the element step (CD with a matrix mass at
//! half its own critical Courant number), an energy sample every step (as scenes take them),
//! through `Integration::run_assembled` with the mass assembled outside the timing. Each
//! repetition runs lumped CD, then the scheme; prints both medians over REPS repetitions in ns
//! per node-step and the median of the per-repetition ratios.
//!
//! With THREADS `1v2` each repetition runs the scheme on one thread, then on two (no lumped
//! run), and prints both medians and the medians of the per-repetition ratios one / two, of
//! wall and of main-thread CPU times.
//!
//! ```text
//! cargo run --release -p courant-solver --example scheme_timing -- N STEPS MASS SCHEME [REPS] [THREADS]
//!   MASS: cmm | amm | rmm | lmm; SCHEME: cd | noh-bathe | park-lts | park-global; REPS: 5;
//!   THREADS: 1 (both runs), or 1v2
//! ```

use courant_solver::integrator::OutputRequest;
use courant_solver::{CentralDifference, Integration, MassOperator, Model};
use std::time::Instant;

mod harness;

#[repr(C)]
struct Timespec {
    seconds: i64,
    nanoseconds: i64,
}

unsafe extern "C" {
    fn clock_gettime(clock: i32, time: *mut Timespec) -> i32;
}

/// CPU time of the calling thread (Linux `CLOCK_THREAD_CPUTIME_ID`), in seconds: on a shared
/// machine it leaves out the time the thread waited for a core.
fn thread_cpu_seconds() -> f64 {
    let mut time = Timespec {
        seconds: 0,
        nanoseconds: 0,
    };
    // SAFETY: `time` is a valid `struct timespec`; clock 3 is CLOCK_THREAD_CPUTIME_ID.
    let status = unsafe { clock_gettime(3, &mut time) };
    assert_eq!(status, 0, "clock_gettime");
    time.seconds as f64 + 1e-9 * time.nanoseconds as f64
}

/// `(wall, thread CPU)` seconds of one run.
fn time_run(
    model: &Model,
    integration: &Integration,
    steps: usize,
    request: &OutputRequest,
) -> (f64, f64) {
    let mass = MassOperator::new(model, integration.mass).expect("mass");
    let (clock, cpu) = (Instant::now(), thread_cpu_seconds());
    let out = integration
        .run_assembled(model, steps, request, mass)
        .expect("run");
    assert_eq!(out.steps, steps);
    (clock.elapsed().as_secs_f64(), thread_cpu_seconds() - cpu)
}

/// `reps` repetitions (at least one) of `a` then `b`, each returning `(wall, thread CPU)`
/// seconds: `[a's walls, b's walls, a's CPU times, b's CPU times]`, one entry per repetition.
fn alternate(
    reps: usize,
    mut a: impl FnMut() -> (f64, f64),
    mut b: impl FnMut() -> (f64, f64),
) -> [Vec<f64>; 4] {
    let mut out: [Vec<f64>; 4] = Default::default();
    for _ in 0..reps.max(1) {
        let ((a_wall, a_cpu), (b_wall, b_cpu)) = (a(), b());
        out[0].push(a_wall);
        out[1].push(b_wall);
        out[2].push(a_cpu);
        out[3].push(b_cpu);
    }
    out
}

/// Per-repetition ratios `top / bottom`.
fn ratios_of(top: &[f64], bottom: &[f64]) -> Vec<f64> {
    top.iter().zip(bottom).map(|(t, b)| t / b).collect()
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

fn main() {
    let (n, steps, kind, scheme) = harness::arguments(100_000, 400);
    let args: Vec<String> = std::env::args().collect();
    let reps = args.get(5).map_or(5, |s| harness::whole_number("REPS", s));
    let one_against_two = args.get(6).is_some_and(|s| s == "1v2");
    let threads = args
        .get(6)
        .filter(|_| !one_against_two)
        .map_or(1, |s| harness::whole_number("THREADS", s));
    let scheme = scheme.unwrap_or_else(|| "noh-bathe".into());
    let model = courant_solver::bench::graded_seed_bar(n).expect("bar");
    let element_dt = model.bar().stiffest_element().1;
    let request = OutputRequest {
        energy_every: 1,
        history_every: steps,
        ..OutputRequest::default()
    };
    let lumped = CentralDifference::new(0.5 * element_dt).integration();
    let dt = 0.5 * kind.critical_courant() * element_dt;
    let mut other = match scheme.as_str() {
        "cd" => CentralDifference {
            mass: kind,
            ..CentralDifference::new(dt)
        }
        .integration(),
        name => {
            let entry = courant_solver::schemes::find(name)
                .unwrap_or_else(|| harness::fail(&format!("SCHEME: {name} is not a scheme")));
            let mut integration = Integration::new(dt, entry.build_with(&[]).expect("defaults"));
            integration.mass = kind;
            integration
        }
    };
    let mut lumped = lumped;
    if one_against_two {
        let mut two = other.clone();
        (other.threads, two.threads) = (Some(1), Some(2));
        let [ones, twos, one_cpu, two_cpu] = alternate(
            reps,
            || time_run(&model, &other, steps, &request),
            || time_run(&model, &two, steps, &request),
        );
        let (ratios, cpu_ratios) = (ratios_of(&ones, &twos), ratios_of(&one_cpu, &two_cpu));
        let per = |s: f64| s * 1e9 / ((n + 1) * steps) as f64;
        // The main thread's CPU time on two threads leaves out its waits without CPU: for lumped
        // CD the join of each block's threads; with a matrix mass none (it spins, then yields,
        // while the worker of `kernels::matrix_mass::pair` runs the other chunk), so there the
        // CPU ratio is about the wall ratio on idle cores and above it when the thread waited
        // for a core (a busy machine).
        println!(
            "N = {n}, {steps} steps: {scheme} {kind:?} {:.3} ns on one thread, {:.3} ns on two per node-step (wall), one / two {:.2} wall, {:.2} main-thread CPU (medians of {} alternating)",
            per(median(ones)),
            per(median(twos)),
            median(ratios),
            median(cpu_ratios),
            reps.max(1)
        );
        return;
    }
    lumped.threads = Some(threads);
    other.threads = Some(threads);
    let [base, times, base_cpu, cpu] = alternate(
        reps,
        || time_run(&model, &lumped, steps, &request),
        || time_run(&model, &other, steps, &request),
    );
    let (ratios, cpu_ratios) = (ratios_of(&times, &base), ratios_of(&cpu, &base_cpu));
    let per = |s: f64| s * 1e9 / ((n + 1) * steps) as f64;
    // On one thread the CPU-time ratio is the robust one on a shared machine.
    println!(
        "N = {n}, {steps} steps, {threads} thread(s): lumped CD {:.3} ns, {scheme} {kind:?} {:.3} ns per node-step (wall), ratio {:.2} wall, {:.2} main-thread CPU (medians of {} alternating)",
        per(median(base)),
        per(median(times)),
        median(ratios),
        median(cpu_ratios),
        reps.max(1)
    );
}
