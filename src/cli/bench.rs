//! `courant bench`: the C reference of the lumped central-difference step, courant's kernels and
//! courant's run loop, timed side by side in one process on the machine at hand, and their
//! ratios (benches/RESULTS.md, heading "2026-11-27, AMD: `courant bench`, blocked steps on one and
//! two threads, memory"), so that a user sees on their own machine what those tables measured.
//!
//! What is timed, per element count N (node-steps = steps x (N + 1)), each the median over
//! `reps` repetitions of about `node_steps` node-steps:
//! - `c_ns`: the fastest variant (`two_pass`, `fused`, `blocked`) of
//!   `benches/c_reference/cd_step.c` (compiled into the binary as text, built here with `$CC`,
//!   default `gcc`, and `$CFLAGS`, default `-O3 -march=native`: the flags of
//!   `benches/c_reference/run.sh`), which prints its own medians: one step per sweep;
//! - `kernel_ns`: `LumpedStep::step`, one step per sweep, on the same graded bar
//!   and start state (`fixtures::graded_seed_bar`, Co 0.5, `fixtures::smooth_half_velocity`,
//!   F = 1 on node 0); `kernel_energy_ns`: `step_with_energy`;
//! - `blocked_ns`, `blocked_energy_ns`: `advance_block` (temporal blocking: blocks of 1024
//!   steps, 64 per pass over a tile) on one thread, without and with the energy sums;
//! - `loop_1t_ns`, `loop_ns`: the run loop per step, `Scheme::run` of lumped CD on that bar from
//!   rest under its load (energy balance and blow-up guard every step, the work of the load), on
//!   one thread and on `threads` (the default of a run: every core from 1e5 nodes on), as the
//!   difference of runs of `2 S` and `S` steps over `S (N + 1)` (start and mass drop out).
//!   From 1e5 nodes on, the blocked kernel and the loop run at least 1024 steps (one block) per
//!   repetition whatever `node_steps` says.
//!
//! Ratios, each of two single-threaded times but `loop_speedup`: `loop_1t_over_kernel` (the
//! run against the one-step kernel the issue measured), `loop_1t_over_blocked_energy` (against
//! what the run steps with: the blocked kernel with its energy sums, the loop's own overhead),
//! `loop_1t_over_blocked` (against the fastest bare kernel), `loop_speedup` (one thread over
//! all: target 4), `kernel_over_c` and `loop_1t_over_c` (courant's run against the one-step C
//! loop, both on one thread).
//!
//! Timings are medians of wall time on a possibly shared machine: repeat when in doubt. Nothing
//! here is a test; no test asserts a time.

use super::bench_schemes::{SchemesTable, check_schemes_file};
use crate::io::owned_file::{Owner, check_file_replaceable, write_owned_file};
use crate::results::table::{Precision, Table};
use crate::run::threads;
use courant_solver::bench::LumpedStep;
use courant_solver::bench::{MAX_BLOCK_STEPS, StepBlock};
use courant_solver::bench::{graded_seed_bar, smooth_half_velocity};
use courant_solver::integrator::OutputRequest;
use courant_solver::{CentralDifference, Integration, MassOperator, Model};
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use std::time::Instant;

/// The C reference, compiled into the binary so that `courant bench` runs from anywhere.
const C_SOURCE: &str = include_str!("../../benches/c_reference/cd_step.c");

/// The columns of the CSV `courant bench` writes.
const COLUMNS: [&str; 16] = [
    "N",
    "threads",
    "c_variant",
    "c_ns",
    "kernel_ns",
    "kernel_over_c",
    "kernel_energy_ns",
    "blocked_ns",
    "blocked_energy_ns",
    "loop_1t_ns",
    "loop_ns",
    "loop_1t_over_kernel",
    "loop_1t_over_blocked_energy",
    "loop_1t_over_blocked",
    "loop_speedup",
    "loop_1t_over_c",
];

/// How the kernel is timed.
#[derive(Debug, Clone, Copy, PartialEq)]
enum KernelMode {
    Step,
    StepWithEnergy,
    Blocked,
    BlockedWithEnergy,
}

/// What `courant bench` measures and where it writes.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchOptions {
    /// Element counts.
    pub sizes: Vec<usize>,
    /// Node-steps per repetition (steps = ceil(node_steps / (N + 1))).
    pub node_steps: f64,
    /// Repetitions (the median is reported).
    pub reps: usize,
    /// The CSV file written.
    pub out: PathBuf,
    /// Skip the C reference.
    pub skip_c: bool,
    /// Skip the other schemes' runs (the second table, [`super::bench_schemes`]).
    pub skip_schemes: bool,
}

impl Default for BenchOptions {
    fn default() -> Self {
        Self {
            sizes: vec![1_000, 100_000, 1_000_000],
            node_steps: 5e7,
            reps: 9,
            out: PathBuf::from("bench.csv"),
            skip_c: false,
            skip_schemes: false,
        }
    }
}

/// The C reference's medians: `(N, fastest variant, ns per node-step)`, and the compiler line.
struct CReference {
    compiler: String,
    flags: String,
    rows: Vec<(usize, String, f64)>,
}

/// Run the benchmark, print the table and write it as CSV to `options.out`.
pub fn bench(options: &BenchOptions) -> ExitCode {
    if let Err(e) = check(options) {
        errln!("error: {e}");
        return ExitCode::from(2);
    }
    outln!("cpu:        {}", crate::report::timing::cpu());
    outln!(
        "node-steps: {:.3e} per repetition, {} repetitions, median reported",
        options.node_steps,
        options.reps
    );
    let c = if options.skip_c {
        Err("skipped (--no-c)".to_string())
    } else {
        measure_c(options)
    };
    match &c {
        Ok(c) => outln!("C:          {} {}", c.compiler, c.flags),
        Err(e) => outln!("C:          not measured: {e}"),
    }
    let mut table = Table::new(&COLUMNS);
    let mut schemes = SchemesTable::new();
    for &n in &options.sizes {
        let measured = graded_seed_bar(n)
            .map_err(|e| e.to_string())
            .and_then(|model| {
                let modes = [
                    KernelMode::Step,
                    KernelMode::StepWithEnergy,
                    KernelMode::Blocked,
                    KernelMode::BlockedWithEnergy,
                ];
                let mut kernel = [0.0; 4];
                for (time, mode) in kernel.iter_mut().zip(modes) {
                    *time = time_kernel(&model, options, mode)?;
                }
                let steps = block_steps_for(n, options);
                let one = time_run_loop(
                    &model,
                    options,
                    &run_loop_integration(&model, Some(1)),
                    steps,
                )?;
                let all = time_run_loop(
                    &model,
                    options,
                    &run_loop_integration(&model, threads::setting()),
                    steps,
                )?;
                Ok((model, kernel, one, all))
            });
        let (model, [kernel, energy, blocked, blocked_energy], loop_one, run_loop) = match measured
        {
            Ok(m) => m,
            Err(e) => {
                errln!("error: N = {n}: {e}");
                return ExitCode::from(2);
            }
        };
        let c_row = c
            .as_ref()
            .ok()
            .and_then(|c| c.rows.iter().find(|r| r.0 == n));
        let ratio = |x: f64| c_row.map(|r| x / r.2);
        if !options.skip_schemes {
            let steps = steps_for(n, options);
            let timed = schemes.measure(&model, loop_one, c_row.map(|r| r.2), |integration| {
                time_run_loop(&model, options, integration, steps)
            });
            if let Err(e) = timed {
                errln!("error: N = {n}: {e}");
                return ExitCode::from(2);
            }
        }
        table.push(vec![
            n.into(),
            run_loop_integration(&model, threads::setting())
                .threads(&model)
                .into(),
            c_row.map(|r| r.1.clone()).into(),
            c_row.map(|r| r.2).into(),
            kernel.into(),
            ratio(kernel).into(),
            energy.into(),
            blocked.into(),
            blocked_energy.into(),
            loop_one.into(),
            run_loop.into(),
            (loop_one / kernel).into(),
            (loop_one / blocked_energy).into(),
            (loop_one / blocked).into(),
            (loop_one / run_loop).into(),
            ratio(loop_one).into(),
        ]);
    }
    outln!("ns per node-step (medians):");
    out!("{}", super::run::aligned(&table, "  "));
    let csv = table.to_csv(Precision::Significant {
        digits: 4,
        floor: 0.0,
    });
    if let Err(e) = write_owned_file(&options.out, &csv, BENCH_CSV) {
        errln!("error: cannot write --out {e}");
        return ExitCode::from(2);
    }
    outln!("-> {}", options.out.display());
    if !options.skip_schemes {
        match schemes.finish(&options.out) {
            Ok(path) => outln!("-> {}", path.display()),
            Err(e) => {
                errln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    }
    ExitCode::SUCCESS
}

/// The options' rules, each naming the option.
fn check(options: &BenchOptions) -> Result<(), String> {
    if options.sizes.is_empty() {
        return Err("--sizes: give at least one element count".into());
    }
    if let Some(n) = options
        .sizes
        .iter()
        .find(|&&n| !(2..=courant_solver::model::MAX_ELEMENTS).contains(&n))
    {
        return Err(format!(
            "--sizes: {n} must lie in 2..={} (elements of the bar)",
            courant_solver::model::MAX_ELEMENTS
        ));
    }
    if !(options.node_steps.is_finite() && (1.0..=1e12).contains(&options.node_steps)) {
        return Err(format!(
            "--node-steps: {} must lie in 1..=1e12",
            options.node_steps
        ));
    }
    if !(1..=1000).contains(&options.reps) {
        return Err(format!("--reps: {} must lie in 1..=1000", options.reps));
    }
    // Only a new file or one `courant bench` wrote (its header line) is replaced: never a
    // user's file, a FIFO (which would block) or a device.
    check_file_replaceable(&options.out, BENCH_CSV).map_err(|e| format!("--out {e}"))?;
    if !options.skip_schemes {
        check_schemes_file(&options.out)?;
    }
    Ok(())
}

/// A CSV `courant bench` wrote: any version's header starts with `N,` and has `c_variant`.
const BENCH_CSV: Owner = Owner {
    what: "`courant bench`",
    recognises: |head| {
        head.lines()
            .next()
            .is_some_and(|line| line.starts_with("N,") && line.contains(",c_variant,"))
    },
};

/// Steps of one repetition at `n` elements.
fn steps_for(n: usize, options: &BenchOptions) -> usize {
    ((options.node_steps / (n + 1) as f64).ceil() as usize).max(1)
}

/// Steps of one repetition of the blocked kernel and of the run loop: [`steps_for`], at least
/// one whole block ([`MAX_BLOCK_STEPS`]) from 1e5 nodes on, so that the threads' pipeline runs
/// as in a real run (with fewer steps it would mostly fill and drain).
fn block_steps_for(n: usize, options: &BenchOptions) -> usize {
    let steps = steps_for(n, options);
    if n + 1 >= courant_solver::bench::PARALLEL_FROM_NODES {
        steps.max(MAX_BLOCK_STEPS)
    } else {
        steps
    }
}

/// The median of `times` (the upper one for an even count, as the C reference takes it).
fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// ns per node-step of the bare lumped kernel in `mode` (blocks on one thread).
fn time_kernel(model: &Model, options: &BenchOptions, mode: KernelMode) -> Result<f64, String> {
    let n = model.bar().element_count();
    let dt = 0.5 * model.bar().stiffest_element().1;
    let mut kernel = LumpedStep::new(model, dt, &vec![0.0; n + 1], &smooth_half_velocity(n));
    kernel.set_threads(1);
    let forces = [(0usize, 1.0f64)];
    let mut block = StepBlock::new(&[0], &[], &[]);
    block.forces.fill(1.0);
    let steps = match mode {
        KernelMode::Step | KernelMode::StepWithEnergy => steps_for(n, options),
        KernelMode::Blocked | KernelMode::BlockedWithEnergy => block_steps_for(n, options),
    };
    // Blocks of up to MAX_BLOCK_STEPS steps adding up to `steps`.
    let mut run = |kernel: &mut LumpedStep, steps: usize| match mode {
        KernelMode::Step => (0..steps).for_each(|_| kernel.step(black_box(&forces))),
        KernelMode::StepWithEnergy => (0..steps).for_each(|_| {
            black_box(kernel.step_with_energy(black_box(&forces)));
        }),
        KernelMode::Blocked | KernelMode::BlockedWithEnergy => {
            let mut left = steps;
            while left > 0 {
                let size = left.min(MAX_BLOCK_STEPS);
                if mode == KernelMode::Blocked {
                    kernel.advance_block::<false>(black_box(&mut block), size);
                } else {
                    kernel.advance_block::<true>(black_box(&mut block), size);
                }
                left -= size;
            }
        }
    };
    run(&mut kernel, steps.min(10));
    let mut times = Vec::with_capacity(options.reps);
    for _ in 0..options.reps {
        let start = Instant::now();
        run(&mut kernel, steps);
        times.push(start.elapsed().as_secs_f64() * 1e9 / (steps * (n + 1)) as f64);
    }
    if kernel.displacement().iter().all(|x| x.is_finite()) {
        Ok(median(times))
    } else {
        Err("the kernel's state blew up".into())
    }
}

/// The run the run loop is timed with: lumped central difference at half the critical step of
/// `model`, on `threads` threads (`None`: every core) when it takes blocks of steps.
fn run_loop_integration(model: &Model, threads: Option<usize>) -> Integration {
    Integration {
        threads,
        ..CentralDifference::new(0.5 * model.bar().stiffest_element().1).integration()
    }
}

/// ns per node-step of the run loop of `integration`: runs of `2 S` and `S` steps (`S =
/// steps`), their difference per node-step, median over the repetitions.
fn time_run_loop(
    model: &Model,
    options: &BenchOptions,
    integration: &Integration,
    steps: usize,
) -> Result<f64, String> {
    let n = model.bar().element_count();
    let run = |steps: usize| -> Result<f64, String> {
        let request = OutputRequest {
            energy_every: steps,
            history_every: steps,
            ..OutputRequest::default()
        };
        let mass = MassOperator::new(model, integration.mass).map_err(|e| e.to_string())?;
        let start = Instant::now();
        let out = integration
            .run_assembled(model, steps, &request, mass)
            .map_err(|e| e.to_string())?;
        black_box(out.energy.max_balance_error);
        Ok(start.elapsed().as_secs_f64())
    };
    run(steps.min(10))?;
    let mut times = Vec::with_capacity(options.reps);
    for _ in 0..options.reps {
        let (short, long) = (run(steps)?, run(2 * steps)?);
        times.push((long - short) * 1e9 / (steps * (n + 1)) as f64);
    }
    Ok(median(times))
}

/// Build the C reference in a private temporary directory, run it, and read its medians.
fn measure_c(options: &BenchOptions) -> Result<CReference, String> {
    let dir = std::env::temp_dir().join(format!("courant-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let result = build_and_run_c(&dir, options);
    let _ = std::fs::remove_dir_all(&dir);
    result
}

fn build_and_run_c(dir: &Path, options: &BenchOptions) -> Result<CReference, String> {
    let source = dir.join("cd_step.c");
    let binary = dir.join("cd_step");
    std::fs::write(&source, C_SOURCE).map_err(|e| format!("{}: {e}", source.display()))?;
    let cc = std::env::var("CC").unwrap_or_else(|_| "gcc".into());
    let flags = std::env::var("CFLAGS").unwrap_or_else(|_| "-O3 -march=native".into());
    let compiled = Command::new(&cc)
        .args(flags.split_whitespace())
        .args(["-Wall", "-Wextra", "-o"])
        .arg(&binary)
        .arg(&source)
        .arg("-lm")
        .output()
        .map_err(|e| format!("cannot run the C compiler `{cc}` (set CC): {e}"))?;
    if !compiled.status.success() {
        return Err(format!(
            "`{cc} {flags}` failed: {}",
            String::from_utf8_lossy(&compiled.stderr).trim()
        ));
    }
    let compiler = Command::new(&cc)
        .arg("--version")
        .output()
        .ok()
        .and_then(|o| {
            String::from_utf8_lossy(&o.stdout)
                .lines()
                .next()
                .map(String::from)
        })
        .unwrap_or_else(|| cc.clone());
    let ran = Command::new(&binary)
        .arg(format!("{}", options.node_steps))
        .arg(options.reps.to_string())
        .args(options.sizes.iter().map(|n| n.to_string()))
        .output()
        .map_err(|e| format!("cannot run the C reference: {e}"))?;
    if !ran.status.success() {
        return Err(format!(
            "the C reference failed: {}",
            String::from_utf8_lossy(&ran.stderr).trim()
        ));
    }
    Ok(CReference {
        compiler,
        flags,
        rows: fastest_variants(&String::from_utf8_lossy(&ran.stdout)),
    })
}

/// From the C reference's lines `<variant> N=<n> steps/rep=.. reps=.. median <ns> ...`: the
/// fastest variant and its median per N, in the order the sizes first appear.
fn fastest_variants(output: &str) -> Vec<(usize, String, f64)> {
    let mut rows: Vec<(usize, String, f64)> = Vec::new();
    for line in output.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        let parsed = match words.as_slice() {
            [variant, size, _, _, "median", ns, ..] => size
                .strip_prefix("N=")
                .and_then(|s| s.parse::<usize>().ok())
                .zip(ns.parse::<f64>().ok())
                .map(|(n, ns)| (n, variant.to_string(), ns)),
            _ => None,
        };
        let Some((n, variant, ns)) = parsed else {
            continue;
        };
        match rows.iter_mut().find(|r| r.0 == n) {
            Some(row) if ns < row.2 => *row = (n, variant, ns),
            Some(_) => {}
            None => rows.push((n, variant, ns)),
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fastest_c_variant_is_read_per_size() {
        let output = "self-check: ok\n\
            two_pass  N=1000     steps/rep=19981     reps=3  median 0.402 ns/node-step  (min 0.394, max 0.410)  checksum -2.6e+04\n\
            blocked   N=1000     steps/rep=19981     reps=3  median 0.424 ns/node-step  (min 0.418, max 0.426)  checksum -2.6e+04\n\
            two_pass  N=100000   steps/rep=200       reps=3  median 1.185 ns/node-step  (min 1.172, max 1.189)  checksum 1.4e+05\n\
            blocked   N=100000   steps/rep=200       reps=3  median 1.029 ns/node-step  (min 1.026, max 1.049)  checksum 1.4e+05\n\
              N=100000 fastest: blocked (fused/two_pass = 0.92, blocked/two_pass = 0.87)\n";
        assert_eq!(
            fastest_variants(output),
            vec![
                (1000, "two_pass".to_string(), 0.402),
                (100_000, "blocked".to_string(), 1.029)
            ]
        );
    }

    #[test]
    fn bad_options_name_the_option_and_the_rule() {
        let bad = |o: BenchOptions| check(&o).unwrap_err();
        assert!(
            bad(BenchOptions {
                sizes: vec![1],
                ..BenchOptions::default()
            })
            .contains("--sizes: 1")
        );
        assert!(
            bad(BenchOptions {
                reps: 0,
                ..BenchOptions::default()
            })
            .contains("--reps")
        );
        assert!(
            bad(BenchOptions {
                node_steps: f64::NAN,
                ..BenchOptions::default()
            })
            .contains("--node-steps")
        );
    }
}
