//! The machine-dependent part of the report, kept apart so that the rest changes only when
//! results do: wall times (`timing.md`, `timing.csv`), the error of the work-precision runs
//! against CPU time, and the criterion benchmark table (`timing.benchmarks.csv`), stamped with
//! commit, date, CPU, threads and rustc.

use super::bench_table::{bench_table, empty_bench_table};
use super::work_precision::cpu_chart;
use crate::compare::work_precision::{cpu_table, equal_error_saving, floor_table};
use crate::io::clock::date;
use crate::pipeline::report_runs::ReportRuns;
use crate::results::table::{Precision, Table};
use crate::scene::cases::Scene;
use crate::scene::studies::work_precision::{
    COMBINATION_FAST, COMBINATION_SLOW, COMBINATION_STUDY, WORK_PRECISION_STUDIES,
};

/// The timing files: `timing.md` and what it links (`timing.csv`, `timing.work_precision.csv`,
/// its SVGs, `timing.benchmarks.csv`, with its header only when there are no criterion results).
pub fn timing_files(scenes: &[Scene], runs: &ReportRuns) -> Vec<(String, String)> {
    let mut files = Vec::new();
    // Timings: everything that changes from run to run.
    let mut timing = Table::new(&["item", "wall_time_s"]);
    for ((_, seconds), scene) in runs.scenes.iter().zip(scenes) {
        timing.push(vec![
            format!("scene {}", scene.name).into(),
            (*seconds).into(),
        ]);
    }
    for c in &runs.convergence {
        for level in &c.levels {
            timing.push(vec![
                format!("study {} N = {}", c.study.name, level.elements).into(),
                level.wall_time.into(),
            ]);
        }
    }
    timing.push(vec!["total (parallel)".into(), runs.wall_time.into()]);
    let mut tmd = String::from("# Timings\n\n");
    tmd += &format!(
        "Generated {} from commit `{}` on {}; {} threads; `{}`.\n\n",
        date(),
        commit(),
        cpu(),
        rayon::current_num_threads(),
        rustc()
    );
    tmd += &timing.to_markdown(Precision::Significant {
        digits: 3,
        floor: 0.0,
    });
    tmd += "\n## Error against CPU time\n\n\
            The work-precision runs of the report against the wall time of their integration (one thread \
            each, on this machine; short runs are noisy). The same points against elements x steps are in \
            `index.md`.\n\n";
    for (study, points) in WORK_PRECISION_STUDIES.iter().zip(&runs.work) {
        if let Some(svg) = cpu_chart(study, points) {
            let file = format!("timing.work_precision_{}.svg", study.name);
            tmd += &format!("![{}: error against CPU time]({file})\n\n", study.title);
            files.push((file, svg));
        }
        if study.name == COMBINATION_STUDY {
            for slow in COMBINATION_SLOW {
                if let Some(s) = equal_error_saving(points, COMBINATION_FAST, slow) {
                    tmd += &format!(
                        "{}: at equal error ({:.3}, the runs of `index.md`'s sentence) {slow} takes \
                         {:.3e} s and {COMBINATION_FAST} {:.3e} s: {:.0} times the wall time.\n\n",
                        study.name,
                        s.error,
                        s.slow.wall_time,
                        s.fast.wall_time,
                        s.time_ratio()
                    );
                }
            }
        }
    }
    let floor = runs.element_force_seconds;
    tmd += "\n## Time over the force-evaluation floor\n\n\
            Each run's wall time over its floor, `time_over_floor = wall time / (K u per step x elements x \
            steps x t_f)`, `t_f` the time of one lumped element force evaluation measured in this run (the \
            lumped CD kernel, one sweep per step, on the graded bar of 10^4 elements for 1000 steps, median \
            of 5): 1 would be a run that costs no more than its force evaluations at CD's rate; what a \
            scheme takes beyond is its other work per step (updates, solves) and the run's own (output, \
            checks), so the comparison of schemes is one of methods, not of how fast each is written \
            (a lumped CD run, which takes blocks of steps, can go below 1). The studies' runs share the \
            machine's threads and last 0.03-20 ms, so a preempted run reads several times too slow; the \
            floor runs alone.\n\n";
    tmd += &match floor {
        Some(t_f) => format!(
            "t_f = {:.3} ns per element force evaluation. Per study and method, the median and the least \
             over its runs (the least: the run the machine disturbed least):\n\n",
            t_f * 1e9
        ),
        None => "No floor measured (scenes only).\n\n".into(),
    };
    let per_method = floor_table(WORK_PRECISION_STUDIES, &runs.work, floor);
    tmd += &per_method.to_markdown(Precision::Significant {
        digits: 3,
        floor: 0.0,
    });
    tmd += "\nEvery run, with its wall time:\n\n";
    let cpu = cpu_table(WORK_PRECISION_STUDIES, &runs.work, floor);
    tmd += &cpu.to_markdown(Precision::Significant {
        digits: 3,
        floor: 0.0,
    });
    files.push((
        "timing.work_precision.csv".into(),
        cpu.to_csv(Precision::RoundTrip),
    ));
    tmd += "\n## Benchmarks\n\n";
    match bench_table(std::path::Path::new("target/criterion")) {
        Some(bench) => {
            tmd += "Criterion medians from `target/criterion` (run `cargo bench` to refresh), per node-step, beside a \
                    bandwidth model: the bytes of arrays each node-step touches and the rate that implies, and the \
                    machine's reach at the same N, the STREAM triad `a = b + s c` (McCalpin 1995; `memory_triad`, \
                    24 B per element): `fraction_of_triad` is how close to this machine's limit each step runs. Up to \
                    N = 1e5 the arrays stay in cache; at 1e6 and beyond (triad at 4e6) a one-step kernel runs at the \
                    memory bandwidth's rate, while a block of steps (`lumped_cd_block`, one pass over memory per 64 \
                    steps) runs at the in-cache rate.\n\n";
            tmd += &bench.to_markdown(Precision::Significant {
                digits: 3,
                floor: 0.0,
            });
            files.push((
                "timing.benchmarks.csv".into(),
                bench.to_csv(Precision::RoundTrip),
            ));
        }
        None => {
            tmd += "No criterion results found in `target/criterion`: run `cargo bench` first.\n";
            // Written with its header only: the report's files (and its manifest) do not
            // depend on whether benchmarks were run.
            files.push((
                "timing.benchmarks.csv".into(),
                empty_bench_table().to_csv(Precision::RoundTrip),
            ));
        }
    }
    files.push(("timing.md".into(), tmd));
    files.push(("timing.csv".into(), timing.to_csv(Precision::RoundTrip)));
    files
}

/// The CPU model and core count, from `/proc/cpuinfo` where there is one.
pub fn cpu() -> String {
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "an unknown CPU".into());
    format!(
        "{model} ({} logical cores)",
        std::thread::available_parallelism().map_or(1, |n| n.get())
    )
}

/// The commit the report was made from (`git describe --always --dirty`), or "unknown".
fn commit() -> String {
    std::process::Command::new("git")
        .args(["describe", "--always", "--dirty"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|| "unknown".into())
}

fn rustc() -> String {
    std::process::Command::new("rustc")
        .arg("--version")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|| "rustc version unknown".into())
}
