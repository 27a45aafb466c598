//! Source of truth: the reproducers of a hostile-user round on `courant score`, `reference`,
//! `check --baseline`, `--junit`, `bench --out` and stdout, copied in
//! `tests/data/score_and_io/` with their `INDEX.txt`, and the README's "Limits" and "Exit
//! status".
//!
//! Proves, one test per INDEX line: each reproducer now gives what its line says it should (no
//! panic, no hang, no unbounded read, no special file replaced, no infinity or NaN, no silent
//! pass), within a stated time.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[path = "common/cli.rs"]
mod cli;
use cli::scratch;

/// Status 2 (or a verdict) comes within this, whatever the input.
const PROMPT: Duration = Duration::from_secs(10);

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

#[cfg(unix)]
#[test]
fn check_baseline_fifo_is_named_and_fails_that_file_without_opening_it() {
    let dir = scratch("baseline_fifo");
    let bl = baseline(&dir);
    let co1 = bl.join("fig1/co1.csv");
    std::fs::remove_file(&co1).unwrap();
    mkfifo(&co1);
    let (code, stdout, stderr, took) = courant(&["check", "fig1", "--baseline", s(&bl)]);
    assert_eq!(code, Some(1), "{stdout}{stderr}");
    assert!(took < PROMPT, "took {took:?}");
    assert!(
        stdout.contains("co1.csv") && stdout.contains("FIFO"),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
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
    let dir = scratch("baseline_zero");
    let bl = baseline(&dir);
    let co1 = bl.join("fig1/co1.csv");
    std::fs::remove_file(&co1).unwrap();
    std::os::unix::fs::symlink("/dev/zero", &co1).unwrap();
    let (code, stdout, stderr, took) = courant(&["check", "fig1", "--baseline", s(&bl)]);
    assert_eq!(code, Some(1), "{stdout}{stderr}");
    assert!(took < PROMPT, "took {took:?}");
    assert!(
        stdout.contains("co1.csv") && stdout.contains("device"),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[cfg(unix)]
#[test]
fn junit_never_replaces_a_special_file_a_link_or_a_foreign_file() {
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
