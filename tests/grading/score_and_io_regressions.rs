//! Source of truth: the reproducers of a hostile-user round on `courant score`, `reference`,
//! `check --baseline`, `--junit`, `bench --out` and stdout, copied in
//! `tests/data/score_and_io/` with their `INDEX.txt`, and the guide's "Limits" (docs/guide/running.md) and "Exit
//! status".
//!
//! Proves, one test per INDEX line: each reproducer now gives what its line says it should (no
//! panic, no hang, no unbounded read, no special file replaced, no infinity or NaN, no silent
//! pass), within a stated time.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::cli;
use cli::scratch;

/// Status 2 (or a verdict) comes within this, whatever the input.
const PROMPT: Duration = Duration::from_secs(10);

fn data(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/score_and_io")
        .join(file)
}

/// `courant ARGS --out DIR` (DIR in a fresh scratch directory named `label`): refused with
/// status 2, promptly, naming every one of `expected`, writing nothing.
fn refused(label: &str, args: &[&str], expected: &[&str]) {
    let dir = scratch(label);
    let out = dir.join("o");
    let mut args = args.to_vec();
    args.extend(["--out", s(&out)]);
    let (code, _, stderr, took) = courant(&args);
    assert_eq!(code, Some(2), "{label}: {stderr}");
    assert!(took < PROMPT, "{label}: took {took:?}");
    assert!(!out.exists(), "{label}: exit 2 wrote {}", out.display());
    for e in expected {
        assert!(stderr.contains(e), "{label}: message lacks {e:?}: {stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `courant score SCENE --results SET --out DIR`: [`refused`].
fn score_refused(scene: &str, set: &str, expected: &[&str]) {
    refused(set, &["score", scene, "--results", s(&data(set))], expected);
}

/// `courant ARGS` with stdout sent to `stdout`: exit code, stdout, stderr, wall time.
fn courant_to(args: &[&str], stdout: Stdio) -> (Option<i32>, String, String, Duration) {
    let started = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(stdout)
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        started.elapsed(),
    )
}

/// `courant ARGS`: exit code, stdout, stderr, wall time.
fn courant(args: &[&str]) -> (Option<i32>, String, String, Duration) {
    courant_to(args, Stdio::piped())
}

fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

#[cfg(unix)]
fn mkfifo(path: &Path) {
    let status = Command::new("mkfifo").arg(path).status().unwrap();
    assert!(status.success());
}

#[cfg(target_os = "linux")]
#[test]
fn stdout_write_error_is_a_message_and_status_2_and_run_still_writes() {
    let dev_full = || {
        std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap()
    };
    let (code, _, stderr, _) = courant_to(&["list"], dev_full().into());
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("cannot write to stdout"), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    let dir = scratch("stdout_full");
    let out = dir.join("o");
    let (code, _, stderr, _) = courant_to(&["run", "fig1", "--out", s(&out)], dev_full().into());
    assert_eq!(code, Some(2), "{stderr}");
    assert!(out.join("fig1/summary.csv").is_file(), "run wrote nothing");
    let (code, _, stderr, _) = courant_to(&["check", "fig1"], dev_full().into());
    assert_eq!(code, Some(2), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A run output of fig1 in `dir/bl`, to break one of its files.
fn baseline(dir: &Path) -> PathBuf {
    let bl = dir.join("bl");
    let (code, _, stderr, _) = courant(&["run", "fig1", "--out", s(&bl)]);
    assert_eq!(code, Some(0), "{stderr}");
    bl
}

/// `check fig1 --baseline BL` with `BL/fig1/co1.csv` replaced by what `make` puts there: that
/// file fails (status 1), named with `word`, promptly (never opened or read).
#[cfg(unix)]
fn special_baseline(name: &str, make: impl Fn(&Path), word: &str) {
    let dir = scratch(name);
    let bl = baseline(&dir);
    let co1 = bl.join("fig1/co1.csv");
    std::fs::remove_file(&co1).unwrap();
    make(&co1);
    let (code, stdout, stderr, took) = courant(&["check", "fig1", "--baseline", s(&bl)]);
    assert_eq!(code, Some(1), "{stdout}{stderr}");
    assert!(took < PROMPT, "took {took:?}");
    assert!(
        stdout.contains("co1.csv") && stdout.contains(word),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[cfg(unix)]
#[test]
fn check_baseline_fifo_is_named_and_fails_that_file_without_opening_it() {
    special_baseline("baseline_fifo", mkfifo, "FIFO");
}

#[cfg(unix)]
#[test]
fn bench_out_fifo_is_refused_at_once() {
    let dir = scratch("bench_fifo");
    let fifo = dir.join("b.csv");
    mkfifo(&fifo);
    let (code, _, stderr, took) = courant(&[
        "bench",
        "--sizes",
        "1000",
        "--reps",
        "1",
        "--node-steps",
        "1000",
        "--no-c",
        "--out",
        s(&fifo),
    ]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(took < PROMPT, "took {took:?}");
    assert!(stderr.contains("FIFO"), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[cfg(unix)]
#[test]
fn check_baseline_dev_zero_is_named_and_not_read() {
    special_baseline(
        "baseline_zero",
        |p| std::os::unix::fs::symlink("/dev/zero", p).unwrap(),
        "device",
    );
}

#[cfg(unix)]
#[test]
fn junit_replaces_special_files_no_more_nor_a_link_or_a_foreign_file() {
    let dir = scratch("junit_special");
    let fifo = dir.join("fifo");
    mkfifo(&fifo);
    let stdout_link = dir.join("stdout");
    std::os::unix::fs::symlink("/dev/null", &stdout_link).unwrap();
    let notes = dir.join("notes");
    std::fs::write(&notes, "notes").unwrap();
    let link = dir.join("link");
    std::os::unix::fs::symlink(&notes, &link).unwrap();
    for (path, kind) in [
        (&fifo, "FIFO"),
        (&stdout_link, "device"),
        (&link, "not a file"),
        (&notes, "not a file"),
    ] {
        for command in [
            vec!["check", "fig1", "--junit", s(path)],
            vec![
                "score",
                "fig1",
                "--results",
                env!("CARGO_MANIFEST_DIR"),
                "--junit",
                s(path),
            ],
        ] {
            let before = std::fs::symlink_metadata(path).unwrap().file_type();
            let (code, _, stderr, took) = courant(&command);
            assert_eq!(code, Some(2), "{command:?}: {stderr}");
            assert!(took < PROMPT, "took {took:?}");
            assert!(stderr.contains(kind), "{command:?}: {stderr}");
            assert_eq!(std::fs::symlink_metadata(path).unwrap().file_type(), before);
        }
    }
    assert_eq!(std::fs::read_to_string(&notes).unwrap(), "notes");
    // A JUnit file courant wrote is replaced, through a link too.
    let junit = dir.join("j.xml");
    for _ in 0..2 {
        let (code, _, stderr, _) = courant(&["check", "fig1", "--junit", s(&junit)]);
        assert_eq!(code, Some(0), "{stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn score_200mb_one_line_stops_at_the_line_cap_with_a_short_message() {
    let dir = scratch("one_line");
    let set = dir.join("set");
    std::fs::create_dir_all(&set).unwrap();
    let mut line = b"t,".to_vec();
    line.extend(std::iter::repeat_n(b'x', 200_000_000));
    std::fs::write(set.join("co1.csv"), &line).unwrap();
    drop(line);
    let (code, _, stderr, took) = courant(&["score", "fig1", "--results", s(&set)]);
    assert_eq!(code, Some(2), "{}", &stderr[..stderr.len().min(300)]);
    assert!(took < PROMPT, "took {took:?}");
    assert!(stderr.len() < 1000, "{} bytes of message", stderr.len());
    assert!(
        stderr.contains("co1.csv:1:1") && stderr.contains("longer than"),
        "{stderr}"
    );
    // A long name within the line cap is echoed short.
    let name = "y".repeat(10_000);
    std::fs::write(set.join("co1.csv"), format!("t,{name}\n0,1\n")).unwrap();
    let (code, _, stderr, _) = courant(&["score", "fig1", "--results", s(&set)]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.len() < 1000, "{} bytes of message", stderr.len());
    assert!(stderr.contains("more bytes"), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn score_inf_l2_1e200_is_refused_at_the_cell_beyond_the_magnitude_limit() {
    score_refused(
        "fig1",
        "score_inf_l2_1e200",
        &["co1.csv:2:4", "`stress`", "1e200", "magnitude limit 1e50"],
    );
}

#[test]
fn score_inf_force_1e308_is_refused_at_the_cell_beyond_the_magnitude_limit() {
    score_refused(
        "fig5",
        "score_inf_force_1e308",
        &["cd-penalty-bs25.csv:2:2", "`force`", "magnitude limit"],
    );
}

#[test]
fn score_force_truncated_passes_plateau_no_more_the_window_is_not_measurable() {
    let (code, stdout, stderr, took) = courant(&[
        "score",
        "fig5",
        "--results",
        s(&data("score_force_truncated_passes_plateau")),
    ]);
    assert_eq!(code, Some(1), "{stdout}{stderr}");
    assert!(took < PROMPT, "took {took:?}");
    let row = stdout
        .lines()
        .find(|l| l.contains("cd-bipenalty-bs0.25") && l.contains("plateau_deviation"))
        .unwrap_or_else(|| panic!("no plateau row: {stdout}"));
    assert!(
        row.contains("FAIL") && row.contains("inside the first plateau"),
        "{row}"
    );
}

#[test]
fn score_nan_fig2_t1000_is_refused_at_t_with_the_reference_limit() {
    score_refused(
        "fig2",
        "score_nan_fig2_t1000",
        &["cd-co0.5.csv:2:1", "`t`", "1000 transit times", "t <= 4"],
    );
}

/// `courant reference SCENE --at FILE --out DIR`: refused with status 2 naming `expected`.
fn reference_refused(scene: &str, file: &str, expected: &[&str]) {
    refused(
        file,
        &["reference", scene, "--at", s(&data(file))],
        expected,
    );
}

#[test]
fn reference_at_fig2_t1000_is_refused_at_t_with_the_reference_limit() {
    reference_refused(
        "fig2",
        "reference_at_fig2_t1000.csv",
        &[
            "reference_at_fig2_t1000.csv:2:1",
            "`t`",
            "1000 transit times",
        ],
    );
}

#[test]
fn reference_at_layered_t1e6_is_refused_at_t() {
    reference_refused(
        "layered",
        "reference_at_layered_t1e6.csv",
        &[
            "reference_at_layered_t1e6.csv:2:1",
            "`t`",
            "layered reference",
        ],
    );
}

#[test]
fn score_slow_fig2_t50_is_refused_by_the_reference_work_bound_at_once() {
    score_refused(
        "fig2",
        "score_slow_fig2_t50",
        &["cd-co0.5.csv:2:1", "`t`", "2e10"],
    );
}

#[test]
fn score_dt_hides_lag_no_more_the_declared_dt_is_refused_at_its_table() {
    score_refused(
        "fig1",
        "score_dt_hides_lag",
        &[
            "results.toml:5:1",
            "`cases.\"co1\".dt`",
            "larger than the scene case's step on this mesh, 1e-2",
        ],
    );
}

#[test]
fn reference_replaces_run_output_no_more_without_force() {
    let dir = scratch("replaces_run");
    let results = dir.join("results");
    let (code, _, stderr, _) = courant(&["run", "fig1", "--out", s(&results)]);
    assert_eq!(code, Some(0), "{stderr}");
    let files = || std::fs::read_dir(results.join("fig1")).unwrap().count();
    let before = files();
    for command in [
        vec!["reference", "fig1", "--out", s(&results)],
        vec![
            "score",
            "fig1",
            "--results",
            s(&Path::new(env!("CARGO_MANIFEST_DIR")).join("external/sfepy/results/fig1")),
            "--out",
            s(&results),
        ],
    ] {
        let (code, _, stderr, _) = courant(&command);
        assert_eq!(code, Some(2), "{command:?}: {stderr}");
        assert!(
            stderr.contains("holds the output of `courant run`") && stderr.contains("--force"),
            "{stderr}"
        );
        assert_eq!(
            stderr.matches(s(&results.join("fig1"))).count(),
            1,
            "the path once: {stderr}"
        );
        assert_eq!(files(), before, "{command:?} touched the run's output");
    }
    let (code, _, stderr, _) = courant(&["reference", "fig1", "--out", s(&results), "--force"]);
    assert_eq!(code, Some(0), "{stderr}");
    // And the reverse: run does not replace the references without --force.
    let (code, _, stderr, _) = courant(&["run", "fig1", "--out", s(&results)]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("holds the output of `courant reference`"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Run `courant run FILE` (a scene reproducer): status 2 within [`PROMPT`], nothing written,
/// the message holding every one of `expected`.
fn scene_refused(file: &str, expected: &[&str]) {
    refused(
        file.trim_end_matches(".toml"),
        &["run", s(&data(file))],
        expected,
    );
}

#[test]
fn fuzz_m64_fig6_empty_material_points_at_the_material_header() {
    // `[material]` is on line 16 of the file.
    scene_refused(
        "fuzz_m64_fig6_empty_material_at_1_1.toml",
        &["fuzz_m64_fig6_empty_material_at_1_1.toml:16:1: `material`: needs `modulus`"],
    );
}

#[test]
fn fuzz_m224_fig1_masses_no_profile_times_points_at_the_output_header() {
    // `[output]` is on line 44 of the file.
    scene_refused(
        "fuzz_m224_fig1_masses_no_profile_times_at_1_1.toml",
        &["fuzz_m224_fig1_masses_no_profile_times_at_1_1.toml:44:1: `output.end_time`"],
    );
}

/// The guide's statement (docs/guide/running.md, "Limits") of what the node-step cap means in
/// time for the slowest scheme.
fn readme_states_the_cap_for_the_slowest_scheme() {
    let guide = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/guide/running.md"),
    )
    .unwrap();
    assert!(
        guide.contains("up to about 12 minutes for the slowest measured, Noh-Bathe"),
        "the guide's Limits no longer state the cap's time for Noh-Bathe"
    );
    // ~7 ns per node-step (measured on the m4757 reproducer: 5.7e10 node-steps in ~7 min).
    let minutes = courant::scene::budget::MAX_NODE_STEPS * 7e-9 / 60.0;
    assert!(
        minutes <= 12.0,
        "the cap means {minutes:.1} minutes at 7 ns"
    );
}

/// A reproducer that is slow within the caps: accepted in under a second, within the node-step
/// cap, and its time covered by the guide's statement of the cap.
fn slow_within_caps(file: &str) {
    let text = std::fs::read_to_string(data(file)).unwrap();
    let started = Instant::now();
    let scene = courant::scene::Scene::parse("r", file, &text).unwrap();
    assert!(started.elapsed() < Duration::from_secs(1), "{file}");
    let work = courant::scene::work::Work::of(&scene).unwrap();
    assert!(
        work.node_steps <= courant::scene::budget::MAX_NODE_STEPS,
        "{file}"
    );
    readme_states_the_cap_for_the_slowest_scheme();
}

#[test]
fn fuzz_m4757_stability_noh_bathe_is_within_the_cap_the_readme_states_in_time() {
    slow_within_caps("fuzz_m4757_stability_noh_bathe_end_time_1e6.toml");
}

#[test]
fn fuzz_m125_courant_sweep_is_within_the_cap_the_readme_states_in_time() {
    slow_within_caps("fuzz_m125_courant_sweep_co_1e-6.toml");
}

/// The kill-test line: a killed `run` leaves `.SCENE.partial-PID` siblings; the next write
/// removes those of processes that are no longer running (documented best effort).
#[cfg(target_os = "linux")]
#[test]
fn kill_test_leftovers_of_a_killed_run_go_at_the_next_write() {
    let dir = scratch("kill_leftovers");
    let out = dir.join("o");
    let (code, _, stderr, _) = courant(&["run", "fig1", "--out", s(&out)]);
    assert_eq!(code, Some(0), "{stderr}");
    // A pid above the kernel's maximum is never running.
    let leftover = out.join(".fig1.partial-4194305");
    std::fs::create_dir_all(&leftover).unwrap();
    std::fs::write(leftover.join("co1.csv"), "t\n").unwrap();
    let (code, _, stderr, _) = courant(&["run", "fig1", "--out", s(&out)]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!leftover.exists(), "the leftover of a dead run stayed");
    assert!(out.join("fig1/summary.csv").is_file());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn every_index_line_has_its_test() {
    let index = std::fs::read_to_string(data("INDEX.txt")).unwrap();
    let source = include_str!("score_and_io_regressions.rs");
    let mut entries = 0;
    for line in index
        .lines()
        .filter(|l| l.contains(" | ") && !l.starts_with("file |"))
    {
        let file = line.split(" | ").next().unwrap().trim();
        let stem = if file.starts_with("(kill test)") {
            "kill_test".to_string()
        } else {
            let stem = file.trim_end_matches('/').split('.').next().unwrap();
            stem.split('_').take(3).collect::<Vec<_>>().join("_")
        };
        assert!(
            source.contains(&format!("fn {}", stem.to_lowercase())),
            "no test for {file} (a test named `{}...`)",
            stem.to_lowercase()
        );
        entries += 1;
    }
    assert_eq!(entries, 20, "INDEX.txt lines");
}

/// Beyond the INDEX: files a set cannot use are named (not "no case files"), and a linked file
/// that is no CSV is not echoed into the message.
#[cfg(unix)]
#[test]
fn special_misnamed_and_foreign_case_files_are_named_not_skipped_or_echoed() {
    let dir = scratch("special_case_files");
    let set = dir.join("set");
    std::fs::create_dir_all(set.join("co0.1.csv")).unwrap();
    mkfifo(&set.join("co1.csv"));
    std::os::unix::fs::symlink(dir.join("nothing"), set.join("co0.5.csv")).unwrap();
    std::fs::write(set.join("co1.CSV"), "t,x,stress\n0.5,0.5,1\n").unwrap();
    let (code, _, stderr, took) = courant(&["score", "fig1", "--results", s(&set)]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(took < PROMPT, "took {took:?}");
    for expected in [
        "co1.csv:0:0: is a FIFO",
        "co0.5.csv:0:0: does not exist (a symbolic link to nothing)",
        "co0.1.csv:0:0: is a directory",
        "co1.CSV:0:0: not read: names are case-sensitive",
    ] {
        assert!(stderr.contains(expected), "lacks {expected:?}: {stderr}");
    }
    assert!(!stderr.contains("no case files"), "{stderr}");
    let other = dir.join("other");
    std::fs::create_dir_all(&other).unwrap();
    let secret = dir.join("secret.txt");
    std::fs::write(&secret, "root:x:0:0:root:/root:/bin/bash\n").unwrap();
    std::os::unix::fs::symlink(&secret, other.join("co1.csv")).unwrap();
    let (code, _, stderr, _) = courant(&["score", "fig1", "--results", s(&other)]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        !stderr.contains("root:x"),
        "the file's text is echoed: {stderr}"
    );
    assert!(stderr.contains("no column name"), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}
