//! Source of truth: the guide's promises on bad input (docs/guide/running.md: "Exit status",
//! "Limits", "Output directories"); a mutation fuzz of the scene files found hangs, lost files,
//! aborts and NaN tables; this harness keeps them away.
//!
//! ```text
//!   built-in scenes ─┐            ┌─> Scene::parse (in-process): no panic, < 1 s of CPU
//!   reproducers ─────┴─ mutate ───┤
//!   (tests/data/robustness)       └─> courant run (the binary): exit 0/1/2 only, nothing
//!                                     written on 2, no NaN/inf in any CSV it writes
//! ```
//!
//! Proves, for `COURANT_FUZZ_CASES` mutants (default 500; fixed seed `COURANT_FUZZ_SEED`,
//! default below) of every built-in scene and every robustness reproducer, each 1 to 3 edits
//! (numbers replaced by extremes or scaled by up to 1e±300, strings swapped for other keywords,
//! lists emptied, lines deleted, duplicated or inserted, the file truncated;
//! `tests/common/mutate.rs`): validation never panics and takes under a second of CPU whatever the
//! magnitudes; `courant run` exits 0, 1 or 2 (never a panic, abort or signal) within a bound;
//! on exit 2 it wrote nothing; on 0 or 1 every number in every CSV it wrote is finite. Mutants
//! whose estimated work is large (validated only: they are within the limits but would run for
//! long) are counted, not run.
//!
//! Soak (documented in docs/guide/tests.md): `COURANT_FUZZ_CASES=1000000 COURANT_FUZZ_SECONDS=600
//! COURANT_FUZZ_SEED=<any> cargo test --release --test fuzz_scenes -- --nocapture` runs for ten
//! minutes and prints how many mutants it checked; `COURANT_FUZZ_LOG=FILE` appends the first
//! line of every refusal to FILE, `COURANT_FUZZ_SLOWEST=FILE` writes the mutant that took
//! longest to validate.

use crate::mutate;

use courant::scene::Scene;
use courant::scene::builtin::BUILTIN_SCENES;
use courant::scene::work::Work;
use mutate::{Mutation, apply, mutation};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestCaseError, TestRunner};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// The seed of the CI run.
const DEFAULT_SEED: u64 = 0x00c0_0a47_0016;
/// Mutants of the CI run.
const DEFAULT_CASES: u32 = 500;
/// Validation of any scene, whatever its magnitudes, takes less than this CPU time of the
/// validating thread (in-process; validation runs on one thread). CPU time, not wall time: the
/// rule bounds the work validation does, which a loaded machine must not make look larger.
const VALIDATION_LIMIT: Duration = Duration::from_secs(1);
/// A mutant is run when its estimated work is below these (else validated only).
const RUN_NODE_STEPS: f64 = 3e7;
const RUN_OUTPUT_VALUES: f64 = 2e6;
const RUN_REFERENCE_WORK: f64 = 3e8;
const RUN_SPECTRUM_NODES: usize = 300;
/// A run that is started must end within this.
const RUN_LIMIT: Duration = Duration::from_secs(120);

/// The robustness reproducers (copies of the issue's files; `tests/data/robustness/INDEX.txt`).
const REPRODUCERS: &[(&str, &str)] = &[
    (
        "accepted_expect_min_nan",
        include_str!("../data/robustness/accepted_expect_min_nan.toml"),
    ),
    (
        "at1-1_comment_as_key_no_scene",
        include_str!("../data/robustness/at1-1_comment_as_key_no_scene.toml"),
    ),
    (
        "hang_contact_bar_area_1e300",
        include_str!("../data/robustness/hang_contact_bar_area_1e300.toml"),
    ),
    (
        "hang_two_bars_beta_s_1e300",
        include_str!("../data/robustness/hang_two_bars_beta_s_1e300.toml"),
    ),
    (
        "nan_outputs_elements_1",
        include_str!("../data/robustness/nan_outputs_elements_1.toml"),
    ),
    (
        "not_refused_contact_striker_1e7",
        include_str!("../data/robustness/not_refused_contact_striker_1e7.toml"),
    ),
    (
        "oom_history_energy_every_1",
        include_str!("../data/robustness/oom_history_energy_every_1.toml"),
    ),
    (
        "timeout_dispersion_n1e5",
        include_str!("../data/robustness/timeout_dispersion_n1e5.toml"),
    ),
    (
        "timeout_graded_reference_modulus_16_to_1e12",
        include_str!("../data/robustness/timeout_graded_reference_modulus_16_to_1e12.toml"),
    ),
    (
        "timeout_graded_reference_modulus_1e11_to_1",
        include_str!("../data/robustness/timeout_graded_reference_modulus_1e11_to_1.toml"),
    ),
    (
        "timeout_within_caps_courant_sweep_n1e5",
        include_str!("../data/robustness/timeout_within_caps_courant_sweep_n1e5.toml"),
    ),
    (
        "weak_beta_s_inf_fig3",
        include_str!("../data/robustness/weak_beta_s_inf_fig3.toml"),
    ),
    (
        "weak_cmm_not_positive_definite_density_5e-324",
        include_str!("../data/robustness/weak_cmm_not_positive_definite_density_5e-324.toml"),
    ),
    (
        "weak_filename_too_long_beta_s_1e-300",
        include_str!("../data/robustness/weak_filename_too_long_beta_s_1e-300.toml"),
    ),
    (
        "weak_filename_too_long_beta_s_1e300",
        include_str!("../data/robustness/weak_filename_too_long_beta_s_1e300.toml"),
    ),
];

/// Every text mutants start from.
fn seeds() -> Vec<&'static str> {
    BUILTIN_SCENES
        .iter()
        .chain(REPRODUCERS)
        .map(|(_, text)| *text)
        .collect()
}

/// What happened to the mutants, for the summary line.
#[derive(Default)]
struct Tally {
    checked: AtomicUsize,
    refused: AtomicUsize,
    ran: AtomicUsize,
    validated_only: AtomicUsize,
    refused_at_run: AtomicUsize,
    slowest_validation_us: AtomicUsize,
    slowest_mutant: std::sync::Mutex<String>,
}

fn env<T: std::str::FromStr>(name: &str, default: T) -> T {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Run the binary on `file` with `out` as output directory, within [`RUN_LIMIT`]: its exit code
/// (`None` for a signal) and its stderr.
fn run_binary(file: &Path, out: &Path) -> Result<(Option<i32>, String), String> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_courant"))
        .arg("run")
        .arg(file)
        .arg("--out")
        .arg(out)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| e.to_string())?;
    let started = Instant::now();
    loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            let mut stderr = String::new();
            if let Some(mut pipe) = child.stderr.take() {
                use std::io::Read;
                let _ = pipe.read_to_string(&mut stderr);
            }
            return Ok((status.code(), stderr));
        }
        if started.elapsed() > RUN_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("courant run did not end within {RUN_LIMIT:?}"));
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// The first non-finite number in a CSV file under `dir`, as `file:line: cell`.
fn non_finite_cell(dir: &Path) -> Option<String> {
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).ok()?.flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "csv") {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            let mut reader = csv::ReaderBuilder::new().from_reader(text.as_bytes());
            for (i, record) in reader.records().enumerate() {
                let Ok(record) = record else { continue };
                for cell in record.iter() {
                    if cell.trim().parse::<f64>().is_ok_and(|x| !x.is_finite()) {
                        return Some(format!("{}:{}: {cell}", path.display(), i + 2));
                    }
                }
            }
        }
    }
    None
}

/// True when a scene is cheap enough to run in the harness.
fn cheap(scene: &Scene) -> bool {
    let Ok(work) = Work::of(scene) else {
        return false;
    };
    work.node_steps <= RUN_NODE_STEPS
        && work.output_values <= RUN_OUTPUT_VALUES
        && work.reference <= RUN_REFERENCE_WORK
        && scene
            .spectra
            .iter()
            .all(|s| s.model.bar().node_count() <= RUN_SPECTRUM_NODES)
}

/// CPU time consumed by the calling thread (`CLOCK_THREAD_CPUTIME_ID`).
#[cfg(unix)]
fn thread_cpu_time() -> Duration {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid, writable timespec; the clock id is a constant of the platform.
    let status = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    assert_eq!(status, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
    Duration::new(t.tv_sec as u64, t.tv_nsec as u32)
}

/// Wall time since the first call, where no thread CPU clock is available.
#[cfg(not(unix))]
fn thread_cpu_time() -> Duration {
    static START: std::sync::OnceLock<Instant> = std::sync::OnceLock::new();
    START.get_or_init(Instant::now).elapsed()
}

/// The oracle on one mutant (module docs).
fn check_mutant(text: &str, dir: &Path, tally: &Tally) -> Result<(), String> {
    let started = thread_cpu_time();
    let parsed = std::panic::catch_unwind(|| Scene::parse("mutant", "mutant.toml", text))
        .map_err(|_| "Scene::parse panicked".to_string())?;
    let took = thread_cpu_time().saturating_sub(started);
    let micros = took.as_micros() as usize;
    if tally
        .slowest_validation_us
        .fetch_max(micros, Ordering::Relaxed)
        < micros
    {
        *tally.slowest_mutant.lock().unwrap() = text.to_string();
    }
    if took > VALIDATION_LIMIT {
        return Err(format!(
            "validation took {took:?}, more than {VALIDATION_LIMIT:?}"
        ));
    }
    if let Ok(scene) = &parsed
        && !cheap(scene)
    {
        tally.validated_only.fetch_add(1, Ordering::Relaxed);
        return Ok(());
    }
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    let file = dir.join("mutant.toml");
    std::fs::write(&file, text).map_err(|e| e.to_string())?;
    let out = dir.join("out");
    let (code, stderr) = run_binary(&file, &out)?;
    match code {
        Some(2) => {
            let written = std::fs::read_dir(&out).map(|d| d.count()).unwrap_or(0);
            if written > 0 {
                return Err(format!("exit 2 but {written} entries written: {stderr}"));
            }
            if parsed.is_ok() {
                tally.refused_at_run.fetch_add(1, Ordering::Relaxed);
            } else {
                tally.refused.fetch_add(1, Ordering::Relaxed);
            }
            if let Ok(log) = std::env::var("COURANT_FUZZ_LOG") {
                use std::io::Write;
                if let Ok(mut f) = std::fs::OpenOptions::new()
                    .create(true)
                    .append(true)
                    .open(log)
                {
                    let _ = writeln!(f, "{}", stderr.lines().next().unwrap_or(""));
                }
            }
        }
        Some(0 | 1) => {
            if parsed.is_err() {
                return Err("validation refused the scene but courant run accepted it".into());
            }
            if let Some(cell) = non_finite_cell(&out) {
                return Err(format!("a non-finite number in an output table: {cell}"));
            }
            tally.ran.fetch_add(1, Ordering::Relaxed);
        }
        other => {
            return Err(format!(
                "courant run ended with {other:?} (not 0, 1 or 2): {stderr}"
            ));
        }
    }
    let _ = std::fs::remove_dir_all(dir);
    Ok(())
}

#[test]
fn mutated_scenes_are_refused_or_run_cleanly() {
    let cases: u32 = env("COURANT_FUZZ_CASES", DEFAULT_CASES);
    let seed: u64 = env("COURANT_FUZZ_SEED", DEFAULT_SEED);
    let budget = Duration::from_secs(env("COURANT_FUZZ_SECONDS", u64::MAX / 4));
    let config = Config {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: None,
        max_shrink_iters: 200,
        ..Config::default()
    };
    let texts = seeds();
    let strategy = (0..texts.len(), prop::collection::vec(mutation(), 1..=3));
    let tally = Tally::default();
    let root: PathBuf = std::env::temp_dir().join(format!("courant-fuzz-{}", std::process::id()));
    let started = Instant::now();
    let result = TestRunner::new(config).run(
        &strategy,
        |(seed_index, mutations): (usize, Vec<Mutation>)| {
            if started.elapsed() > budget {
                return Ok(());
            }
            let text = mutations
                .iter()
                .fold(texts[seed_index].to_string(), |t, m| apply(&t, m));
            let n = tally.checked.fetch_add(1, Ordering::Relaxed);
            let dir = root.join(n.to_string());
            check_mutant(&text, &dir, &tally).map_err(|why| {
                TestCaseError::fail(format!(
                    "{why}\n--- mutant of seed {seed_index} ({mutations:?}) ---\n{text}"
                ))
            })
        },
    );
    let _ = std::fs::remove_dir_all(&root);
    println!(
        "fuzz: seed {seed:#x}, {} mutants in {:.1} s: {} refused (exit 2, nothing written), {} ran (no NaN in any table), \
         {} validated only (large work), {} refused at run time; slowest validation {:.1} ms",
        tally.checked.load(Ordering::Relaxed),
        started.elapsed().as_secs_f64(),
        tally.refused.load(Ordering::Relaxed),
        tally.ran.load(Ordering::Relaxed),
        tally.validated_only.load(Ordering::Relaxed),
        tally.refused_at_run.load(Ordering::Relaxed),
        tally.slowest_validation_us.load(Ordering::Relaxed) as f64 / 1e3
    );
    if let Ok(path) = std::env::var("COURANT_FUZZ_SLOWEST") {
        let _ = std::fs::write(path, tally.slowest_mutant.lock().unwrap().as_str());
    }
    if let Err(e) = result {
        panic!("{e}");
    }
}
