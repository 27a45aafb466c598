//! Source of truth: the project's determinism rule ("the same scene gives bit-identical output
//! whatever the thread count") and the speed target that a case of N >= 1e5 uses both cores
//! (benches/RESULTS.md, "2026-11-25, Intel: blocks of steps (temporal blocking) and both cores").
//!
//! ```text
//!   COURANT_THREADS=1  courant run bar.toml --out A ┐
//!   COURANT_THREADS=2  courant run bar.toml --out B ├─ every file byte for byte equal
//!   COURANT_THREADS=3  courant run bar.toml --out C ┘   (but the wall-time column)
//! ```
//!
//! Proves: a `COURANT_THREADS` that is not a positive integer is refused (exit 2, naming it);
//! a lumped Fig. 1 bar of 10^5 elements (2 223 steps: blocks of up to 1024 steps, each pipelined
//! across the threads' regions; node histories at the loaded end, mid-bar, and 6-10 nodes left of
//! the region seams of two threads (node 50 176) and three (32 768, 66 560), where a node's
//! values pass from one thread to the next during a sub-block; profiles between blocks) writes
//! the same profiles, histories, energies
//! and errors on one, two and three threads. The kernel-level proof (states, energies and
//! probes against single steps, loads on region edges) is `kernels::lumped::pipeline`'s unit test.

use crate::cli;

use std::path::Path;

const SCENE: &str = r#"
[scene]
description = "Fig. 1 bar at N = 1e5, Co 0.9: the same output on any thread count."
source = "Kolman et al. (seed), Fig. 1; d'Alembert solution, methods.md §3"
[bar]
length = 1.0
area = 1.0
[material]
modulus = 1.0
density = 1.0
[mesh]
elements = 100000
[supports]
left = "free"
right = "fixed"
[[load]]
kind = "traction"
end = "left"
value = -1.0
time = "step"
[integrator]
scheme = "central-difference"
mass = "lumped"
courant = 0.9
[output]
time_unit = "transit"
profile_times = [0.005, 0.02]
history_points = [0.0, 0.5, 0.33333, 0.3276, 0.5017, 0.6655]
history_every = 7
[reference]
kind = "dalembert"
"#;

/// Every file under `dir`, by relative path, with the `wall_time_s` column of summaries blanked.
fn files(dir: &Path) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else {
                let text = std::fs::read_to_string(&path).unwrap_or_default();
                let name = path.strip_prefix(dir).unwrap().display().to_string();
                out.push((name, without_wall_time(&text)));
            }
        }
    }
    out.sort();
    out
}

/// `text` with every cell of a `wall_time_s` column emptied (the only thing a run may not repeat).
fn without_wall_time(text: &str) -> String {
    let mut lines = text.lines();
    let Some(header) = lines.next() else {
        return String::new();
    };
    let column = header.split(',').position(|c| c == "wall_time_s");
    let mut out = vec![header.to_string()];
    for line in lines {
        let mut cells: Vec<&str> = line.split(',').collect();
        if let Some(c) = column.filter(|&c| c < cells.len()) {
            cells[c] = "";
        }
        out.push(cells.join(","));
    }
    out.join("\n")
}

#[test]
fn a_1e5_element_run_writes_the_same_files_on_one_two_and_three_threads() {
    let dir = cli::scratch("threads");
    let scene = dir.join("bar1e5.toml");
    std::fs::write(&scene, SCENE).unwrap();
    let run = |threads: &str| {
        let out = dir.join(format!("t{threads}"));
        let status = cli::courant_with_env(
            &[
                "run",
                scene.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
            ],
            &[("COURANT_THREADS", threads)],
        );
        assert!(
            status.status.success(),
            "{}",
            String::from_utf8_lossy(&status.stderr)
        );
        files(&out)
    };
    let one = run("1");
    assert!(
        one.iter()
            .any(|(name, text)| name.contains("histor") && text.lines().count() > 300),
        "the run wrote histories of every 7th step: {:?}",
        one.iter().map(|f| &f.0).collect::<Vec<_>>()
    );
    for threads in ["2", "3"] {
        let other = run(threads);
        assert_eq!(one.len(), other.len());
        for ((name, a), (_, b)) in one.iter().zip(&other) {
            assert!(a == b, "{name} differs between 1 and {threads} threads");
        }
    }
}

#[test]
fn a_thread_count_that_is_not_a_positive_integer_is_refused_naming_the_variable() {
    for bad in ["0", "two", "-1", ""] {
        let out = cli::courant_with_env(&["list"], &[("COURANT_THREADS", bad)]);
        assert_eq!(out.status.code(), Some(2), "COURANT_THREADS={bad:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.contains("COURANT_THREADS") && stderr.contains("positive integer"),
            "{stderr}"
        );
    }
    let fine = cli::courant_with_env(&["list"], &[("COURANT_THREADS", "3")]);
    assert!(fine.status.success());
}
