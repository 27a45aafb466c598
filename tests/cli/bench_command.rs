//! Source of truth: the speed measurements of benches/RESULTS.md ("2026-11-27, AMD: `courant
//! bench`, blocked steps on one and two threads, memory": a `courant bench` command that times the C reference,
//! courant's kernel and its run loop side by side and writes the ratios) and the guide's
//! benchmarks chapter (docs/guide/benchmarks.md), which tells a user to run it.
//!
//! ```text
//!   courant bench --sizes 200,1000 --out FILE  ->  stdout table + FILE (CSV, one row per N)
//! ```
//!
//! Proves the command's shape, never a time (no timed tests): it writes one CSV row per size
//! with the columns the guide names, every measured time positive and every ratio the quotient
//! of its two columns (to the 4 significant digits written); without the C reference the C
//! columns stay empty; bad options are refused with exit status 2, naming the option; a file
//! `courant bench` did not write is never replaced.

use crate::cli;
use cli::{courant, scratch};

/// `courant bench ARGS --no-c --out OUT` (no C compiler needed: courant's columns only).
fn bench(out: &std::path::Path, args: &[&str]) -> std::process::Output {
    let mut all = vec!["bench"];
    all.extend(args);
    all.extend(["--no-c", "--out", out.to_str().unwrap()]);
    courant(&all)
}

#[test]
fn bench_writes_one_row_per_size_with_consistent_ratios() {
    let out = scratch("rows").join("bench.csv");
    let run = bench(
        &out,
        &["--sizes", "200,1000", "--node-steps", "2e4", "--reps", "3"],
    );
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let text = std::fs::read_to_string(&out).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "N,threads,c_variant,c_ns,kernel_ns,kernel_over_c,kernel_energy_ns,blocked_ns,\
         blocked_energy_ns,loop_1t_ns,loop_ns,loop_1t_over_kernel,loop_1t_over_blocked_energy,\
         loop_1t_over_blocked,loop_speedup,loop_1t_over_c"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 2);
    // A second run replaces the file it wrote.
    let again = bench(
        &out,
        &["--sizes", "200", "--node-steps", "1e3", "--reps", "1"],
    );
    assert!(
        again.status.success(),
        "{}",
        String::from_utf8_lossy(&again.stderr)
    );
    let replaced = std::fs::read_to_string(&out).unwrap();
    assert_eq!(replaced.lines().count(), 2, "{replaced}");
    assert!(
        replaced.lines().nth(1).unwrap().starts_with("200,"),
        "{replaced}"
    );
    for (row, n) in rows.iter().zip(["200", "1000"]) {
        assert_eq!(row[0], n);
        // Below 1e5 nodes a run takes one thread.
        assert_eq!(row[1], "1");
        // No C reference: its columns and ratios are empty.
        assert!(row[2].is_empty() && row[3].is_empty() && row[5].is_empty() && row[15].is_empty());
        let value = |i: usize| row[i].parse::<f64>().unwrap();
        for column in [4, 6, 7, 8] {
            assert!(value(column) > 0.0, "column {column}: {row:?}");
        }
        // The loop times are differences of two runs: they may be noise-small, never the
        // ratios' inconsistency. Each is written to 4 significant digits (half a unit in the
        // last place: 5e-4 relative), so a written ratio may differ by 1.5e-3 from the
        // quotient of the written columns.
        for (ratio, over, under) in [(11, 9, 4), (12, 9, 8), (13, 9, 7), (14, 9, 10)] {
            let quotient = value(over) / value(under);
            assert!(
                (value(ratio) - quotient).abs() <= 1.5e-3 * quotient.abs() + 1e-12,
                "column {ratio}: {row:?}"
            );
        }
    }
}

/// The second table (every scheme and mass beside lumped CD, `<stem>.schemes.csv`): one row per
/// (size, scheme, mass), each time positive, each ratio to the lumped run of the first table
/// the quotient of the written columns; `--no-schemes` leaves it out.
#[test]
fn bench_times_every_scheme_and_mass_beside_lumped_cd() {
    let dir = scratch("schemes");
    let out = dir.join("bench.csv");
    let run = bench(
        &out,
        &["--sizes", "200", "--node-steps", "2e4", "--reps", "1"],
    );
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let lumped: f64 = std::fs::read_to_string(&out)
        .unwrap()
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(9)
        .unwrap()
        .parse()
        .unwrap();
    let text = std::fs::read_to_string(dir.join("bench.schemes.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "N,scheme,mass,threads,loop_ns,over_lumped_cd,over_c"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let runs: Vec<(&str, &str)> = rows.iter().map(|r| (r[1], r[2])).collect();
    assert_eq!(
        runs,
        [
            ("cd", "cmm"),
            ("cd", "amm(0.5)"),
            ("cd", "rmm(0.5)"),
            ("noh-bathe", "lmm"),
            ("noh-bathe", "cmm"),
            ("noh-bathe", "amm(0.5)"),
            ("noh-bathe", "rmm(0.5)"),
            ("park-lts", "lmm"),
            ("park-global", "lmm"),
        ]
    );
    for row in &rows {
        assert_eq!((row[0], row[3], row[6]), ("200", "1", ""), "{row:?}");
        let (ns, ratio): (f64, f64) = (row[4].parse().unwrap(), row[5].parse().unwrap());
        assert!(ns.is_finite(), "{row:?}");
        assert!(
            (ratio - ns / lumped).abs() <= 1.5e-3 * (ns / lumped).abs() + 1e-12,
            "{row:?}"
        );
    }
    let skipped = scratch("no_schemes").join("bench.csv");
    let run = bench(
        &skipped,
        &[
            "--sizes",
            "200",
            "--node-steps",
            "1e3",
            "--reps",
            "1",
            "--no-schemes",
        ],
    );
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(!skipped.with_extension("schemes.csv").exists());
}

#[test]
fn bad_bench_options_are_refused_naming_the_option() {
    let out = scratch("bad").join("bench.csv");
    let run = bench(&out, &["--sizes", "1"]);
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("--sizes: 1 must lie in"));
    assert!(!out.exists());
}

#[test]
fn a_file_bench_did_not_write_is_not_replaced() {
    let out = scratch("foreign").join("bench.csv");
    std::fs::write(&out, "my own notes\n").unwrap();
    let run = bench(
        &out,
        &["--sizes", "200", "--node-steps", "1e3", "--reps", "1"],
    );
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("is not a file `courant bench` wrote"));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "my own notes\n");
}
