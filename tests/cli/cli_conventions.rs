//! Source of truth: the conventions of Unix command-line tools and of test runners CI people
//! use (pytest's one line per module, failures repeated at the end): what `courant` owes a user
//! at a terminal and in a pipe.
//!
//! Proves: a closed pipe ends `courant list` quietly (no panic, no backtrace, SIGPIPE's exit
//! status); a misspelt scene name is refused without a fake file position and with the nearest
//! built-in name; every unknown key and every bad `[[expect]]` of a file is reported in one
//! pass; `courant check` prints one line per scene by default and repeats each failure at the
//! end with how far it is past its bound; `courant report` of a user's scene needs `--out`,
//! writes its figures and tables and says what it found and where `index.html` is.

use std::io::Read;
use std::process::{Command, Stdio};

use crate::cli;
use cli::{courant, scratch};

#[test]
fn a_closed_pipe_ends_the_listing_quietly() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_courant"))
        .arg("list")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Read one byte, then close the pipe, as `head -c 1` would.
    let mut first = [0u8; 1];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    let mut stderr = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut stderr)
        .unwrap();
    let status = child.wait().unwrap();
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(stderr.is_empty(), "nothing on stderr: {stderr}");
    assert_ne!(status.code(), Some(101), "not a panic");
}

#[test]
fn a_misspelt_scene_gets_the_nearest_name_and_no_fake_position() {
    let out = courant(&["run", "fig_1", "--out", "/nonexistent"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.starts_with("error: fig_1: no such scene file"),
        "{stderr}"
    );
    assert!(!stderr.contains(":0:0"), "{stderr}");
    assert!(stderr.contains("did you mean fig1?"), "{stderr}");
}

#[test]
fn every_unknown_key_and_bad_expectation_is_reported_in_one_pass() {
    let dir = scratch("keys");
    let text = courant::scene::builtin::builtin_text("fig1")
        .unwrap()
        .replace("modulus = 1.0", "modulus = 1.0\nmodulo = 3")
        .replace("elements = 100", "elements = 100\nelementz = 5")
        .replace("metric = \"linf\"", "metric = \"linff\"");
    let path = dir.join("typos.toml");
    std::fs::write(&path, text).unwrap();
    let out = courant(&["run", path.to_str().unwrap(), "--out", "/nonexistent"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let errors: Vec<&str> = stderr
        .lines()
        .filter(|l| l.starts_with("error: "))
        .collect();
    assert!(
        errors.iter().any(|e| e.contains("`material.modulo`")),
        "{stderr}"
    );
    assert!(
        errors.iter().any(|e| e.contains("`mesh.elementz`")),
        "{stderr}"
    );
    assert!(
        errors.iter().filter(|e| e.contains("\"linff\"")).count() >= 2,
        "each bad [[expect]]: {stderr}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn check_prints_a_line_per_scene_and_repeats_failures_with_their_excess() {
    let dir = scratch("check");
    let text = courant::scene::builtin::builtin_text("fig1")
        .unwrap()
        .replace("max = 1e-10", "max = 1e-30");
    let path = dir.join("strict.toml");
    std::fs::write(&path, text).unwrap();
    let out = courant(&["check", "fig1", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let fig1 = stdout.lines().find(|l| l.starts_with("fig1 ")).unwrap();
    assert!(
        fig1.contains("pass") && fig1.contains("10 verdict(s) .........."),
        "{fig1}"
    );
    let strict = stdout.lines().find(|l| l.starts_with("strict ")).unwrap();
    assert!(
        strict.contains("1 FAILED") && strict.contains('F'),
        "{strict}"
    );
    let tail = &stdout[stdout.find("failures:").expect("failures repeated")..];
    assert!(tail.contains("strict: FAIL     co1 linf"), "{tail}");
    assert!(
        tail.contains("co1 linf = 8.9706e-14 > 1e-30"),
        "a failure reads as one: {tail}"
    );
    assert!(
        tail.contains("8.9706e-14 > 1e-30: 9e16 x the bound"),
        "{tail}"
    );
    assert!(!tail.contains(" %"), "no percentage of 1e16: {tail}");
    assert!(stdout.lines().count() < 12, "short by default: {stdout}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn report_of_a_user_scene_needs_out_and_says_what_it_found() {
    let dir = scratch("report");
    let text = courant::scene::builtin::builtin_text("fig1").unwrap();
    let text = &text[..text.find("[[expect]]").unwrap()];
    let path = dir.join("mine.toml");
    std::fs::write(&path, text).unwrap();
    let out = courant(&["report", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "no --out: refused");
    assert!(String::from_utf8_lossy(&out.stderr).contains("--out DIR is required"));
    let target = dir.join("rep");
    let out = courant(&[
        "report",
        path.to_str().unwrap(),
        "--out",
        target.to_str().unwrap(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("0 verdicts, 0 pass, 0 finding(s), 0 FAILED"),
        "{stdout}"
    );
    assert!(stdout.contains(&format!("open {}", target.join("index.html").display())));
    for file in [
        "index.html",
        "index.md",
        "mine/profile_0.svg",
        "mine/summary.csv",
    ] {
        assert!(target.join(file).is_file(), "{file}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
