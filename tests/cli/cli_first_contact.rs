//! Source of truth: what a newcomer meets first at the command line, as the README's tour and
//! docs/guide promise it, and the conventions of Unix tools (a closed pipe, a terminal) and of
//! JUnit consumers.
//!
//! Proves: `courant run` whose stdout is closed still writes every scene and says on stderr
//! that its lines were cut short (exit 2, never a silent 141); `courant list SCENE` lists the
//! scene's cases; a misspelt scene (`fgi1`, a swap) or metric (`lnif`) gets the nearest name; every
//! command's `--help` summary is one short line and `check --help` shows `rel:REL[:ABS]` without
//! backslashes; every bad value of a scene is reported in one pass, each with the value given,
//! and a misspelt `profile_times` adds no second, misleading error; `check` is silent on stderr
//! when stderr is not a terminal, shows its progress when it is, and says what its verdicts
//! count; its JUnit has no suite for a scene that checks nothing and real (sub-millisecond)
//! times.

use std::process::{Command, Stdio};

use crate::cli;
use cli::{courant, scratch};

fn text(out: &std::process::Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

#[test]
fn run_with_a_closed_stdout_writes_every_scene_and_says_so() {
    let dir = scratch("closed-stdout");
    let out_dir = dir.join("D");
    let mut child = Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(["run", "fig1", "fig2", "--out", out_dir.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // The reader leaves before the first line, as `| head -0` would: every write fails.
    drop(child.stdout.take());
    let output = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("stdout was closed before the output ended"),
        "{stderr}"
    );
    for scene in ["fig1", "fig2"] {
        assert!(
            out_dir.join(scene).join("summary.csv").is_file(),
            "{scene} written"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn list_names_a_scenes_cases_and_misspellings_get_the_nearest_name() {
    let out = courant(&["list", "fig1"]);
    assert!(out.status.success(), "{}", text(&out));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<&str> = stdout.lines().collect();
    assert!(lines[0].starts_with("fig1: "), "{stdout}");
    assert_eq!(&lines[1..], ["co1", "co0.5", "co0.1"]);

    for command in ["list", "check", "run"] {
        let out = courant(&[command, "fgi1"]);
        assert_eq!(out.status.code(), Some(2), "{command}");
        assert!(
            text(&out).contains("did you mean fig1?"),
            "{command}: {}",
            text(&out)
        );
    }
}

#[test]
fn help_summaries_are_one_short_line_and_show_no_escapes() {
    let out = courant(&["--help"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let commands = &stdout[stdout.find("Commands:").unwrap()..stdout.find("Options:").unwrap()];
    assert!(commands.lines().count() >= 8, "{commands}");
    for line in commands.lines() {
        assert!(line.chars().count() <= 100, "a long summary: {line:?}");
    }
    let out = courant(&["check", "--help"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("rel:REL[:ABS]"), "{stdout}");
    assert!(!stdout.contains("\\["), "a literal backslash: {stdout}");
}

/// A scene with five mistakes, each of another kind.
const FIVE_MISTAKES: &str = r#"[scene]
description = "five mistakes"
source = "d'Alembert solution"

[material]
modulus = -4.0

[mesh]
elements = "100"

[[load]]
kind = "traction"
end = "left"
value = -1.0

[integrator]
courant = [1.0, -0.5]

[output]
time_unit = "transit"
profile_tims = [0.5]

[reference]
kind = "dalembert"

[[expect]]
cases = ["co1"]
metric = "lnif"
max = 1e-10
source = "methods.md §3"
"#;

#[test]
fn every_bad_value_is_reported_in_one_pass_with_the_value_given() {
    let dir = scratch("five-mistakes");
    let path = dir.join("five.toml");
    std::fs::write(&path, FIVE_MISTAKES).unwrap();
    let out = courant(&["check", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    for (key, echoed) in [
        ("material.modulus", "-4"),
        ("mesh.elements", "\"100\""),
        ("integrator.courant", "-0.5"),
        ("output.profile_tims", "did you mean `profile_times`?"),
        ("expect.metric", "\"lnif\""),
    ] {
        let line = stderr
            .lines()
            .find(|l| l.contains(&format!("`{key}`")))
            .unwrap_or_else(|| panic!("no error for {key}:\n{stderr}"));
        assert!(line.contains(echoed), "{key} echoes {echoed}: {line}");
    }
    assert!(stderr.contains("did you mean linf?"), "{stderr}");
    assert_eq!(stderr.lines().count(), 5, "five errors, no more:\n{stderr}");
    assert!(
        !stderr.contains("`output.end_time`"),
        "no misleading error:\n{stderr}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn check_is_quiet_off_a_terminal_and_says_what_it_counts() {
    let out = courant(&["check", "fig1"]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(
        out.stderr.is_empty(),
        "no progress when stderr is not a terminal: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("check: 1 scene(s), 10 verdict(s): 10 pass"),
        "{stdout}"
    );
    assert!(
        stdout.contains("verdicts: the scenes' expectations")
            && stdout.contains("the report counts these and the committed results of other codes"),
        "{stdout}"
    );
}

/// `script` (util-linux) runs the command on a pseudo-terminal, as a user's shell would.
#[test]
fn check_shows_its_progress_on_a_terminal() {
    if Command::new("script").arg("--version").output().is_err() {
        eprintln!("no `script` on this machine: the terminal case is not run");
        return;
    }
    let command = format!("{} check fig1 fig6 layered", env!("CARGO_BIN_EXE_courant"));
    let out = Command::new("script")
        .args(["-qec", &command, "/dev/null"])
        .output()
        .unwrap();
    let shown = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{shown}");
    assert!(shown.contains("checking "), "a progress bar: {shown}");
    assert!(shown.contains("/3"), "counts the scenes: {shown}");
}

#[test]
fn junit_has_no_empty_suite_and_real_times() {
    let dir = scratch("junit");
    let text_of_fig1 = courant::scene::builtin::builtin_text("fig1").unwrap();
    let quiet = &text_of_fig1[..text_of_fig1.find("[[expect]]").unwrap()];
    let path = dir.join("no_checks.toml");
    std::fs::write(&path, quiet).unwrap();
    let junit = dir.join("j.xml");
    let out = courant(&[
        "check",
        "fig1",
        path.to_str().unwrap(),
        "--junit",
        junit.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert_eq!(xml.matches("<testsuite ").count(), 1, "{xml}");
    assert!(!xml.contains("name=\"no_checks\""), "{xml}");
    let times: Vec<f64> = xml
        .split("<testcase ")
        .skip(1)
        .filter_map(|c| c.split("time=\"").nth(1)?.split('"').next()?.parse().ok())
        .collect();
    assert_eq!(times.len(), 10, "every verdict's case has a time: {xml}");
    assert!(times.iter().all(|&t| t > 0.0), "{times:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}
