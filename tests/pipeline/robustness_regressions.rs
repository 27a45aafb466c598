//! Source of truth: a 3,738-mutant fuzz of the scene files and a round of misuse, and the
//! guide's promises on bad input (docs/guide/running.md, "Exit status", "Limits"); the reproducers are copied
//! in `tests/data/robustness/` with their `INDEX.txt`.
//!
//! Proves, one test per reproducer: what hung in validation (a Sturm bisection on beta_s = 1e300
//! or an area of 1e300), ran past its caps (a 10^7-element striker, N = 1e5 sweeps and
//! dispersion), aborted out of memory (history_every = 1 over 9e7 steps), hung in the graded
//! reference (modulus 16 -> 1e12, 1e11 -> 1), wrote NaN (one element) or misled (a density or
//! beta_s of 5e-324, min = nan, a comment shown as the key, file names from 1e300) now exits
//! with status 2 within a second, naming file, line, key and the rule (and the value it was
//! given), writing nothing, or (one element) runs with no NaN in any table; a directory, a
//! device or a FIFO as the scene path is named without being opened; `--baseline` names a cell
//! that is not a number.

use courant::scene::Scene;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::cli;
use cli::scratch;

/// Status 2 comes within this, whatever the input (validation only).
const REFUSAL_LIMIT: Duration = Duration::from_secs(5);

fn data(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/robustness")
        .join(file)
}

/// `courant ARGS`: exit code, stdout, stderr, wall time.
fn courant(args: &[&str]) -> (Option<i32>, String, String, Duration) {
    let started = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        started.elapsed(),
    )
}

/// Run a reproducer; it must be refused with status 2, quickly, with a message holding every
/// one of `expected`, having written nothing. Validation in-process takes under a second.
fn refused(file: &str, expected: &[&str]) -> String {
    let path = data(file);
    let text = std::fs::read_to_string(&path).unwrap();
    let started = Instant::now();
    assert!(Scene::parse("r", file, &text).is_err(), "{file} validates");
    assert!(
        started.elapsed() < Duration::from_secs(1),
        "{file}: validation took {:?}",
        started.elapsed()
    );
    let dir = scratch(file.trim_end_matches(".toml"));
    let out = dir.join("out");
    let (code, _, stderr, took) = courant(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2), "{file}: {stderr}");
    assert!(took < REFUSAL_LIMIT, "{file}: refused after {took:?}");
    assert!(!out.exists(), "{file}: exit 2 wrote {}", out.display());
    for e in expected {
        assert!(stderr.contains(e), "{file}: message lacks {e:?}: {stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
    stderr
}

#[test]
fn hang_two_bars_beta_s_1e300_is_refused_at_its_key_before_the_bisection() {
    refused(
        "hang_two_bars_beta_s_1e300.toml",
        &[
            "hang_two_bars_beta_s_1e300.toml:11:10: `contact.beta_s`",
            "beta_s = 1e300",
            "1e50",
        ],
    );
}

#[test]
fn hang_contact_bar_area_1e300_is_refused_at_its_key() {
    refused(
        "hang_contact_bar_area_1e300.toml",
        &[":6:8: `bar.area`", "area = 1e300"],
    );
}

#[test]
fn not_refused_contact_striker_1e7_is_refused_by_the_element_cap() {
    refused(
        "not_refused_contact_striker_1e7.toml",
        &[
            ":7:11: `contact.striker.elements`",
            "10000000 must lie in 1..=500000",
        ],
    );
}

#[test]
fn timeout_graded_reference_modulus_16_to_1e12_is_refused_saying_why_and_the_limit() {
    refused(
        "timeout_graded_reference_modulus_16_to_1e12.toml",
        &[
            ":41:8: `reference.kind`",
            "ratio 6.250e10",
            "more than the 2e10",
        ],
    );
}

#[test]
fn timeout_graded_reference_modulus_1e11_to_1_is_refused_saying_why_and_the_limit() {
    refused(
        "timeout_graded_reference_modulus_1e11_to_1.toml",
        &[
            ":38:8: `reference.kind`",
            "ratio 1.000e11",
            "more than the 2e10",
        ],
    );
}

#[test]
fn timeout_within_caps_courant_sweep_n1e5_is_refused_as_a_whole_scene() {
    refused(
        "timeout_within_caps_courant_sweep_n1e5.toml",
        &[
            ":28:11: `integrator.courant`",
            "24 cases",
            "elements to validate",
        ],
    );
}

#[test]
fn timeout_dispersion_n1e5_is_refused_by_the_node_step_cap_of_the_whole_study() {
    refused(
        "timeout_dispersion_n1e5.toml",
        &[
            ":21:12: `mesh.elements`",
            "1.69e11 node-steps in all",
            "1e11",
        ],
    );
}

#[test]
fn oom_history_energy_every_1_is_refused_by_the_output_budget() {
    refused(
        "oom_history_energy_every_1.toml",
        &[":18:17: `output.history_every`", "1.62e9 numbers", "2e7"],
    );
}

#[test]
fn weak_filename_too_long_beta_s_1e300_is_refused_before_running() {
    refused(
        "weak_filename_too_long_beta_s_1e300.toml",
        &[":11:10: `contact.beta_s`", "beta_s = 1e300"],
    );
}

#[test]
fn weak_filename_too_long_beta_s_1e_minus_300_is_refused_before_running() {
    refused(
        "weak_filename_too_long_beta_s_1e-300.toml",
        &[":11:10: `contact.beta_s`", "beta_s = 1e-300"],
    );
}

#[test]
fn a_case_name_built_from_a_long_number_is_short_and_a_file_name() {
    let text = std::fs::read_to_string(data("weak_filename_too_long_beta_s_1e-300.toml"))
        .unwrap()
        .replace("1e-300", "1.2345678912345e-40");
    let scene = Scene::parse("s", "s.toml", &text).unwrap();
    assert_eq!(
        scene.contact[0].name,
        "predictor-corrector-bs1.2345678912345e-40"
    );
}

#[test]
fn weak_cmm_not_positive_definite_density_5e_minus_324_names_file_line_key_and_value() {
    refused(
        "weak_cmm_not_positive_definite_density_5e-324.toml",
        &[":18:11: `material.density`", "density = 5e-324"],
    );
}

#[test]
fn weak_beta_s_inf_fig3_reports_the_input_not_a_derived_infinity() {
    let stderr = refused(
        "weak_beta_s_inf_fig3.toml",
        &[
            ":18:16: `contact_stability.beta_s_range`",
            "beta_s = 5e-324",
        ],
    );
    assert!(!stderr.contains("= inf"), "{stderr}");
}

#[test]
fn at1_1_comment_as_key_no_scene_names_the_missing_table_not_a_comment() {
    let stderr = refused(
        "at1-1_comment_as_key_no_scene.toml",
        &["`scene`: missing: the file has no `[scene]` table"],
    );
    assert!(
        !stderr.contains("# The seed") && !stderr.contains(":1:1:"),
        "{stderr}"
    );
}

#[test]
fn accepted_expect_min_nan_is_a_located_input_error() {
    refused(
        "accepted_expect_min_nan.toml",
        &[":64:7: `expect.min`", "min = NaN is not a finite number"],
    );
}

#[test]
fn nan_outputs_elements_1_runs_with_no_nan_in_any_table() {
    let dir = scratch("one-element");
    let out = dir.join("out");
    let (code, _, stderr, _) = courant(&[
        "run",
        data("nan_outputs_elements_1.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(
        code,
        Some(1),
        "expectations sized for N = 100 fail: {stderr}"
    );
    let scene = out.join("nan_outputs_elements_1");
    for entry in std::fs::read_dir(&scene).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        for cell in text.split([',', '\n']) {
            assert!(
                !cell.trim().parse::<f64>().is_ok_and(|x| !x.is_finite()),
                "{}: {cell}",
                path.display()
            );
        }
    }
    // The TV ratio of a one-element profile is undefined: an empty cell, explained in docs/guide/running.md.
    let summary = std::fs::read_to_string(scene.join("summary.csv")).unwrap();
    let header: Vec<&str> = summary.lines().next().unwrap().split(',').collect();
    let tv = header.iter().position(|c| *c == "tv_ratio").unwrap();
    for row in summary.lines().skip(1) {
        assert_eq!(row.split(',').nth(tv), Some(""), "{row}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_directory_a_device_or_a_fifo_as_the_scene_path_is_named_never_opened() {
    let dir = scratch("paths");
    let out = dir.join("out");
    let fifo = dir.join("pipe.toml");
    let made = Command::new("mkfifo").arg(&fifo).status();
    let mut cases = vec![
        (
            dir.to_str().unwrap().to_string(),
            "is a directory, not a scene file",
        ),
        ("/dev/null".to_string(), "is a device, not a scene file"),
    ];
    if made.is_ok_and(|s| s.success()) {
        cases.push((
            fifo.to_str().unwrap().to_string(),
            "is a FIFO (named pipe), not a scene file",
        ));
    }
    for (path, expected) in cases {
        let (code, _, stderr, took) = courant(&["run", &path, "--out", out.to_str().unwrap()]);
        assert_eq!(code, Some(2), "{path}: {stderr}");
        assert!(took < REFUSAL_LIMIT, "{path}: {took:?}");
        assert!(stderr.contains(expected), "{path}: {stderr}");
        assert!(!stderr.contains(":0:0"), "{stderr}");
    }
    assert!(!out.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_baseline_cell_that_is_not_a_number_is_named_so() {
    let dir = scratch("baseline-nan");
    let base = dir.join("base");
    let (code, _, stderr, _) = courant(&["run", "fig1", "--out", base.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{stderr}");
    let summary = base.join("fig1/summary.csv");
    let text = std::fs::read_to_string(&summary).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let l1 = lines[0].split(',').position(|c| c == "l1").unwrap();
    let mut cells: Vec<&str> = lines[1].split(',').collect();
    cells[l1] = "abc";
    lines[1] = cells.join(",");
    std::fs::write(&summary, lines.join("\n") + "\n").unwrap();
    let (code, stdout, _, _) = courant(&["check", "fig1", "--baseline", base.to_str().unwrap()]);
    assert_eq!(code, Some(1));
    assert!(
        stdout.contains("l1: 1 cell(s) not a number") && stdout.contains("vs baseline \"abc\""),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
