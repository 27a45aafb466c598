//! Source of truth: the guide's "Limits" (docs/guide/running.md) (files courant reads, the magnitude limit, the
//! reference work a file may ask for) and its promise of no NaN or infinity in any table; the
//! reproducers in `tests/data/score_and_io/` (`INDEX.txt`) are the seeds.
//!
//! ```text
//!   result files ──┐            ┌─> read_set_partial + score: no panic, bounded time, errors
//!   query files ───┼─ mutate ───┤   short and located, no NaN/inf in any table
//!   baselines ─────┘            ├─> read_case (query) + exact_set: no NaN/inf in any answer
//!                               └─> compare_csv: no panic
//! ```
//!
//! Proves, for `COURANT_FUZZ_CASES` mutants (default 150 per reader; fixed seed
//! `COURANT_FUZZ_SEED`) of each seed, 1 to 3 CSV edits each (`tests/common/mutate_csv.rs`):
//! the exchange reader, the scorer, the `--at` query path and the baseline comparison never
//! panic; every error message is short (under 2,000 bytes: values are echoed cut) and names a
//! line within the file; a set that scores gives tables with only finite numbers; a query that
//! is answered gives only finite values; each mutant takes under [`MUTANT_LIMIT`].

use crate::mutate_csv;

use courant::check::baseline::csv_diff::{FileOutcome, compare_csv};
use courant::check::baseline::tolerance::Tolerances;
use courant::compare::score::answers::exact_set;
use courant::compare::score::set::score;
use courant::compare::score::tables::score_files;
use courant::results::exchange::columns::Want;
use courant::results::exchange::reader::read_case;
use courant::results::exchange::set::read_set_partial;
use courant::scene::builtin::builtin_scene;
use mutate_csv::{CsvMutation, apply_csv, csv_mutation};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestCaseError, TestRunner};
use std::time::{Duration, Instant};

const DEFAULT_SEED: u64 = 0x00c0_0a47_0034;
const DEFAULT_CASES: u32 = 150;
/// Reading, binding and scoring (or answering) one mutant takes less than this (debug build).
const MUTANT_LIMIT: Duration = Duration::from_secs(30);
/// No error message is longer than this.
const MESSAGE_LIMIT: usize = 2000;

/// (scene, file name, text): result files the scorer reads.
const RESULT_SEEDS: &[(&str, &str, &str)] = &[
    (
        "fig1",
        "co1.csv",
        include_str!("../data/score_and_io/score_dt_hides_lag/co1.csv"),
    ),
    (
        "fig5",
        "cd-bipenalty-bs0.25.csv",
        include_str!(
            "../data/score_and_io/score_force_truncated_passes_plateau/cd-bipenalty-bs0.25.csv"
        ),
    ),
    (
        "fig1",
        "co1.csv",
        include_str!("../data/score_and_io/score_inf_l2_1e200/co1.csv"),
    ),
    (
        "fig2",
        "cd-co0.5.csv",
        include_str!("../data/score_and_io/score_nan_fig2_t1000/cd-co0.5.csv"),
    ),
];

/// (scene, text): `--at` query files.
const QUERY_SEEDS: &[(&str, &str)] = &[
    (
        "fig2",
        include_str!("../data/score_and_io/reference_at_fig2_t1000.csv"),
    ),
    (
        "layered",
        include_str!("../data/score_and_io/reference_at_layered_t1e6.csv"),
    ),
    ("fig1", "t,x_left,x_right\n0.5,0,0.5\n0.5,0.5,1\n"),
];

/// Baseline tables (the committed report's).
const BASELINE_SEEDS: &[&str] = &[
    include_str!("../../reports/fig1/summary.csv"),
    include_str!("../../reports/fig1/norms.csv"),
];

fn env<T: std::str::FromStr>(name: &str, default: T) -> T {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn runner() -> TestRunner {
    TestRunner::new(Config {
        cases: env("COURANT_FUZZ_CASES", DEFAULT_CASES),
        rng_seed: RngSeed::Fixed(env("COURANT_FUZZ_SEED", DEFAULT_SEED)),
        failure_persistence: None,
        ..Config::default()
    })
}

fn mutated(text: &str, edits: &[CsvMutation]) -> String {
    edits.iter().fold(text.to_string(), |t, m| apply_csv(&t, m))
}

/// A short message that names a line of the file (0: the whole file).
fn check_message(message: &str, line: usize, lines: usize) -> Result<(), TestCaseError> {
    prop_assert!(
        message.len() < MESSAGE_LIMIT,
        "{} bytes: {}",
        message.len(),
        &message[..300.min(message.len())]
    );
    prop_assert!(line <= lines + 1, "line {line} of {lines}: {message}");
    Ok(())
}

/// Every cell that parses as a number is finite.
fn all_finite(name: &str, text: &str) -> Result<(), TestCaseError> {
    for (i, line) in text.lines().enumerate() {
        for cell in line.split(',') {
            let cell = cell.trim().trim_matches('"');
            prop_assert!(
                !cell.parse::<f64>().is_ok_and(|x| !x.is_finite()),
                "{name}:{}: {cell}",
                i + 1
            );
        }
    }
    Ok(())
}

#[test]
fn mutated_result_files_are_refused_briefly_or_scored_with_finite_tables() {
    let strategy = (
        0..RESULT_SEEDS.len(),
        proptest::collection::vec(csv_mutation(), 1..=3),
    );
    runner()
        .run(&strategy, |(seed, edits)| {
            let (scene_name, file, text) = RESULT_SEEDS[seed];
            let scene = builtin_scene(scene_name).unwrap().unwrap();
            let text = mutated(text, &edits);
            let lines = text.lines().count();
            let started = Instant::now();
            let (set, errors) = read_set_partial("set", "set", &[(file.into(), text.clone())]);
            for e in &errors {
                check_message(&e.to_string(), e.line, lines)?;
            }
            if let Some(set) = set.filter(|_| errors.is_empty()) {
                match score(&scene, &[set]) {
                    Ok(outcome) => {
                        for (name, csv) in score_files(&outcome) {
                            all_finite(&name, &csv)?;
                        }
                    }
                    Err(e) => check_message(&e.to_string(), 0, lines)?,
                }
            }
            prop_assert!(
                started.elapsed() < MUTANT_LIMIT,
                "{:?} for {edits:?}",
                started.elapsed()
            );
            Ok(())
        })
        .unwrap();
}

#[test]
fn mutated_query_files_are_refused_briefly_or_answered_with_finite_values() {
    let strategy = (
        0..QUERY_SEEDS.len(),
        proptest::collection::vec(csv_mutation(), 1..=3),
    );
    runner()
        .run(&strategy, |(seed, edits)| {
            let (scene_name, text) = QUERY_SEEDS[seed];
            let scene = builtin_scene(scene_name).unwrap().unwrap();
            let text = mutated(text, &edits);
            let lines = text.lines().count();
            let started = Instant::now();
            match read_case("q.csv", "query", &text, Want::Query) {
                Err(e) => check_message(&e.to_string(), e.line, lines)?,
                Ok(query) => match exact_set(&scene, Some(&query), "answers") {
                    Err(e) => check_message(&e.to_string(), 0, lines)?,
                    Ok(set) => {
                        for (name, csv) in courant::results::exchange::writer::set_files(&set) {
                            all_finite(&name, &csv)?;
                        }
                    }
                },
            }
            prop_assert!(
                started.elapsed() < MUTANT_LIMIT,
                "{:?} for {edits:?}",
                started.elapsed()
            );
            Ok(())
        })
        .unwrap();
}

#[test]
fn mutated_baselines_are_compared_without_panic() {
    let strategy = (
        0..BASELINE_SEEDS.len(),
        proptest::collection::vec(csv_mutation(), 1..=3),
    );
    runner()
        .run(&strategy, |(seed, edits)| {
            let fresh = BASELINE_SEEDS[seed];
            let baseline = mutated(fresh, &edits);
            let outcome = compare_csv(fresh, &baseline, &Tolerances::default());
            // An unchanged baseline compares equal in every column.
            if baseline.trim_end() == fresh.trim_end() {
                let FileOutcome::Compared { columns, .. } = &outcome else {
                    return Err(TestCaseError::fail(format!("{outcome:?}")));
                };
                prop_assert!(columns.iter().all(|c| c.passed()));
            }
            Ok(())
        })
        .unwrap();
}
