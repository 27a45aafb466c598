//! Source of truth: docs/guide/grading.md ("Results exchange format", "Grading another code")
//! and the README's grading example:
//! `courant run --exchange DIR` writes the format, `courant score <scene> --results DIR...
//! [--out DIR] [--junit FILE]` grades it, prints one row per check as `courant check` does and
//! exits 0 when every check holds, 1 when one fails, 2 on bad input naming file, line, column
//! and key, writing nothing; `courant reference <scene> [--at POINTS.csv] --out DIR` writes the
//! exact answers with a `reference` column.
//!
//! Proves, with the built binary on the fig1 scene: courant's own export scores 0 with its
//! tables (summary, norms, expectations, diagnostics) and a well-formed JUnit file; a set one
//! step late exits 1 with the offset as a JUnit failure; every class of bad input (a missing,
//! misspelt or repeated column, a non-numeric, non-finite or empty cell, a row of the wrong
//! length, times that decrease, a mesh
//! that stops short of the bar, leaves a gap or overlaps itself, a header of no case kind, a
//! file named after no case or holding another kind of data, an unknown or bad `results.toml`
//! key, a scene without an exchange form) exits 2 naming file, line, column and key, and writes
//! neither the tables nor the JUnit file; `courant reference` writes every built-in kind's
//! answers with the reference that produced them, at a query's rows too; `score` takes the
//! directory `reference --out` writes, one set per `--results`, counts what it read, fails what
//! is not supplied only with `--require-all`, and with `--stated` passes a stated failure as a
//! finding and fails a stated one that passes.

use crate::exchange;
use crate::xml;

use exchange::{one_step_late, scene, scratch};
use rstest::rstest;
use std::path::Path;
use std::process::{Command, Output};

fn courant(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(args)
        .output()
        .unwrap()
}

fn text(out: &Output) -> String {
    format!(
        "stdout:\n{}\nstderr:\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// courant's fig1 results in the exchange format, in `dir/fig1`.
fn exported(dir: &Path) -> std::path::PathBuf {
    let out = courant(&[
        "run",
        "fig1",
        "--out",
        s(&dir.join("run")),
        "--exchange",
        s(dir),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    dir.join("fig1")
}

#[test]
fn an_exported_run_scores_0_with_its_tables_and_junit() {
    let dir = scratch("cli-ok");
    let results = exported(&dir);
    assert!(results.join("results.toml").is_file());
    let (out_dir, junit) = (dir.join("out"), dir.join("score.xml"));
    let out = courant(&[
        "score",
        "fig1",
        "--results",
        s(&results),
        "--out",
        s(&out_dir),
        "--junit",
        s(&junit),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains(" verdict case  metric"), "{stdout}");
    assert!(stdout.contains("pass    co1   linf"), "{stdout}");
    assert!(stdout.contains("skip    co1   energy_balance"), "{stdout}");
    assert!(
        !stdout.contains("n/a     co1   energy_balance"),
        "declared: it applies"
    );
    assert!(stdout.contains("pass    co1   time_level"), "{stdout}");
    assert!(stdout.contains("0 failed: pass"), "{stdout}");
    for (file, header) in [
        (
            "summary.csv",
            "set,code,case,N,values,scheme,mass,dt,dt_source,profiles,l1,l2,linf,overshoot,tv_ratio",
        ),
        ("norms.csv", "set,case,t,l1,l2,linf,overshoot,tv_ratio"),
        (
            "expectations.csv",
            "set,case,metric,at,measured,min,max,equals,verdict,source",
        ),
        (
            "diagnostics.csv",
            "set,case,dt,dt_source,time_shift_steps,shift_residual,time_level,time_level_verdict,sign_error,sign_error_flipped,sign,sign_verdict,layout,layout_verdict,max_stress_over_scale,magnitude_verdict,notes",
        ),
    ] {
        let content = std::fs::read_to_string(out_dir.join("fig1").join(file)).unwrap();
        assert_eq!(content.lines().next().unwrap(), header, "{file}");
    }
    let doc = std::fs::read_to_string(&junit).unwrap();
    let root = xml::parse_xml(&doc).unwrap();
    assert_eq!(root.name, "testsuites");
    assert_eq!(root.value("failures"), "0");
    assert!(
        root.value("skipped").parse::<usize>().unwrap() >= 3,
        "energy_balance skipped"
    );
}

#[test]
fn a_set_one_step_late_exits_1_with_the_offset_as_a_junit_failure() {
    let dir = scratch("cli-late");
    let results = dir.join("fig1");
    std::fs::create_dir_all(&results).unwrap();
    exchange::through_files(&one_step_late(&scene("fig1")), &results);
    let junit = dir.join("late.xml");
    let out = courant(&[
        "score",
        "fig1",
        "--results",
        s(&results),
        "--junit",
        s(&junit),
    ]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("FAIL    co1   time_level"),
        "{}",
        text(&out)
    );
    let root = xml::parse_xml(&std::fs::read_to_string(&junit).unwrap()).unwrap();
    let failures: Vec<&str> = root
        .descendants()
        .into_iter()
        .filter(|e| e.name == "testcase" && e.child("failure").is_some())
        .map(|e| e.value("name"))
        .collect();
    assert!(failures.contains(&"co1 time_level"), "{failures:?}");
}

/// One edit of an exported fig1 set: (file, text to find, replacement).
type Edit = (&'static str, &'static str, &'static str);

#[rstest]
#[case::missing_column(("co1.csv", "t,x_left,x_right,stress", "t,x_left,stress"), "co1.csv:1:1: `x_right`: missing column")]
#[case::misspelt_column(("co1.csv", "t,x_left,x_right,stress", "t,x_left,x_right,stres"), "co1.csv:1:4: `stres`: unknown column (did you mean `stress`?)")]
#[case::repeated_column(("co1.csv", "t,x_left,x_right,stress", "t,x_left,x_right,stress,t"), "co1.csv:1:5: `t`: the column appears twice")]
#[case::no_case_kind(("co1.csv", "t,x_left,x_right,stress", "t,a,b,stress"), "co1.csv:1:2: `a`: unknown column")]
#[case::header_of_no_kind(("co1.csv", "t,x_left,x_right,stress", "t,stress,reference,reference"), "matches no case kind")]
#[case::non_numeric(("co1.csv", "0.5,0,0.01,", "0.5,0,0.01,abc"), "co1.csv:2:4: `stress`: `abc")]
#[case::non_finite(("co1.csv", "0.5,0,0.01,", "0.5,0,0.01,NaN"), "co1.csv:2:4: `stress`: `NaN")]
#[case::empty_cell(("co1.csv", "\n0.5,0,0.01,", "\n0.5,0,,"), "co1.csv:2:3: `x_right`: the cell is empty")]
#[case::short_row(("co1.csv", "0.5,0,0.01,", "0.5,0,0.01,1,"), "co1.csv:2:1: the row has 5 cells, the header 4")]
#[case::times_decrease(("co1.csv", "\n1.5,0.99,1,", "\n0.4,0.99,1,"), "co1.csv:201:1: `t`: t = 0.4 after t = 1.5")]
#[case::mesh_short_of_the_bar(("co1.csv", "\n0.5,0.99,1,", "\n0.5,0.99,0.995,"), "co1.csv:101:3: `x_right`: the mesh does not cover the bar [0, 1]")]
#[case::mesh_with_a_gap(("co1.csv", "\n0.5,0.5,0.51,", "\n0.5,0.502,0.51,"), "co1.csv:52:2: `x_left`: the mesh does not cover the bar: a gap")]
#[case::mesh_overlapping(("co1.csv", "\n0.5,0.5,0.51,", "\n0.5,0.498,0.51,"), "`x_left`: the mesh overlaps itself")]
#[case::unknown_meta_key(("results.toml", "scheme = \"cd\"", "sheme = \"cd\""), "results.toml:6:1: `sheme`: unknown field")]
#[case::bad_mass(("results.toml", "mass = \"lmm\"", "mass = \"lumpy\""), "results.toml:7:8: `cases.\"co0.1\".mass`: \"lumpy\" is not a mass kind")]
#[case::bad_dt(("results.toml", "dt = 0.001", "dt = -0.001"), "results.toml:8:6: `cases.\"co0.1\".dt`: -0.001 must be a positive finite number")]
fn bad_input_exits_2_naming_file_line_column_and_writes_nothing(
    #[case] edit: Edit,
    #[case] expected: &str,
) {
    static CASE: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = CASE.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = scratch(&format!("cli-bad-{n}"));
    let results = exported(&dir);
    let (file, find, replace) = edit;
    let path = results.join(file);
    let content = std::fs::read_to_string(&path).unwrap();
    assert!(
        content.contains(find),
        "test set-up: {find:?} not in {file}"
    );
    std::fs::write(&path, content.replacen(find, replace, 1)).unwrap();
    let (out_dir, junit) = (dir.join("out"), dir.join("j.xml"));
    let out = courant(&[
        "score",
        "fig1",
        "--results",
        s(&results),
        "--out",
        s(&out_dir),
        "--junit",
        s(&junit),
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(expected),
        "expected {expected:?} in:\n{stderr}"
    );
    assert!(
        stderr.contains(s(&results)),
        "the message names the file: {stderr}"
    );
    assert!(
        !out_dir.exists() && !junit.exists(),
        "nothing written on bad input"
    );
}

#[test]
fn files_that_do_not_fit_the_scene_exit_2() {
    let dir = scratch("cli-misfit");
    let results = exported(&dir);
    std::fs::rename(results.join("co1.csv"), results.join("co2.csv")).unwrap();
    let toml = std::fs::read_to_string(results.join("results.toml")).unwrap();
    std::fs::write(
        results.join("results.toml"),
        toml.replace("cases.\"co1\"", "cases.\"co2\""),
    )
    .unwrap();
    let out = courant(&["score", "fig1", "--results", s(&results)]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(
        text(&out)
            .contains("co2.csv:1:1: no case `co2` in scene `fig1` (cases: co1, co0.5, co0.1)"),
        "{}",
        text(&out)
    );
    std::fs::write(results.join("co2.csv"), "t,force\n0,1\n").unwrap();
    std::fs::rename(results.join("co2.csv"), results.join("co1.csv")).unwrap();
    std::fs::write(results.join("results.toml"), toml).unwrap();
    let out = courant(&["score", "fig1", "--results", s(&results)]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out).contains("this file holds a contact force history"),
        "{}",
        text(&out)
    );
    let out = courant(&["score", "dispersion", "--results", s(&results)]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out).contains("dispersion or contact-stability study"),
        "{}",
        text(&out)
    );
    let out = courant(&["score", "fig1", "--results", s(&dir.join("missing"))]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out).contains("cannot read the results directory"),
        "{}",
        text(&out)
    );
}

#[test]
fn reference_writes_the_exact_answers_with_the_reference_that_made_them() {
    let dir = scratch("cli-reference");
    for (scene, file, reference) in [
        ("fig1", "co1.csv", "dalembert"),
        ("fig2", "cd-co0.5.csv", "graded"),
        ("layered", "cd-co1.csv", "layered"),
        ("contact_wall", "lagrange-multiplier.csv", "impact"),
        ("fig6", "free-free-n20.csv", "closed-form"),
    ] {
        let out = courant(&["reference", scene, "--out", s(&dir)]);
        assert!(out.status.success(), "{}", text(&out));
        let content = std::fs::read_to_string(dir.join(scene).join(file)).unwrap();
        let header = content.lines().next().unwrap();
        assert!(header.ends_with(",reference"), "{scene}: {header}");
        assert!(
            content
                .lines()
                .skip(1)
                .all(|l| l.ends_with(&format!(",{reference}"))),
            "{scene}"
        );
        let scored = courant(&["score", scene, "--results", s(&dir.join(scene))]);
        assert_ne!(
            scored.status.code(),
            Some(2),
            "{scene}: the answers read back: {}",
            text(&scored)
        );
    }
    let query = dir.join("points.csv");
    std::fs::write(&query, "t,x\n0.25,0.1\n0.25,0.4\n").unwrap();
    let out = courant(&[
        "reference",
        "fig1",
        "--at",
        s(&query),
        "--out",
        s(&dir.join("at")),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    let content = std::fs::read_to_string(dir.join("at/fig1/co1.csv")).unwrap();
    assert_eq!(
        content,
        "t,x,stress,reference\n0.25,0.1,-1,dalembert\n0.25,0.4,0,dalembert\n"
    );
    std::fs::write(&query, "t,xx\n0.25,0.1\n").unwrap();
    let bad = dir.join("bad");
    let out = courant(&["reference", "fig1", "--at", s(&query), "--out", s(&bad)]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out).contains("points.csv:1:2: `xx`: unknown column (did you mean `x`?)"),
        "{}",
        text(&out)
    );
    assert!(!bad.exists(), "nothing written on bad input");
}

#[test]
fn the_readme_example_scores_as_documented() {
    let readme =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    let block = |file: &str| -> String {
        let start = format!(" file=myresults/fig1/{file}\n");
        let at = readme
            .find(&start)
            .unwrap_or_else(|| panic!("README has no {file}"))
            + start.len();
        let end = readme[at..].find("\n```\n").unwrap();
        format!("{}\n", &readme[at..at + end])
    };
    let dir = scratch("cli-readme").join("myresults/fig1");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("co1.csv"), block("co1.csv")).unwrap();
    std::fs::write(dir.join("results.toml"), block("results.toml")).unwrap();
    let out = courant(&["score", "fig1", "--results", s(&dir)]);
    assert!(out.status.success(), "{}", text(&out));
    // Rows compared with their spacing collapsed (column widths follow the longest cell).
    let rows: Vec<String> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect();
    for row in [
        "pass co1 linf 0.0000e0 <= 1e-10",
        "skip co1 energy_balance",
        "missing co0.5 overshoot",
        "pass co1 time_level on time on time",
        "pass co1 sign tension positive",
        "pass co1 layout as given as given",
    ] {
        assert!(
            rows.iter().any(|r| r.starts_with(row)),
            "{row:?} in:\n{rows:#?}"
        );
    }
}

#[test]
fn score_takes_the_directory_reference_writes_and_one_set_per_flag() {
    // `reference --out R` writes R/<scene>/; `score --results R` finds it there.
    let dir = scratch("cli-layout");
    let out = courant(&["reference", "fig1", "--out", s(&dir)]);
    assert!(out.status.success(), "{}", text(&out));
    let out = courant(&["score", "fig1", "--results", s(&dir)]);
    assert!(out.status.success(), "{}", text(&out));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("co1: 100 elements x 2 time(s) read (200 rows)"),
        "the values and times read are counted: {stdout}"
    );
    // Two directories after one flag: the second is not swallowed as a set (nor as the scene).
    let out = courant(&["score", "fig1", "--results", s(&dir), s(&dir)]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
}

#[test]
fn require_all_fails_what_is_not_supplied_and_stated_findings_pass_only_as_stated() {
    let dir = scratch("cli-require");
    let results = exported(&dir);
    std::fs::remove_file(results.join("co0.1.csv")).unwrap();
    let toml = std::fs::read_to_string(results.join("results.toml")).unwrap();
    let cut = toml.find("[cases.\"co0.1\"]").unwrap();
    let end = toml[cut..].find("\n\n").map_or(toml.len(), |e| cut + e + 2);
    std::fs::write(
        results.join("results.toml"),
        format!("{}{}", &toml[..cut], &toml[end..]),
    )
    .unwrap();
    let out = courant(&["score", "fig1", "--results", s(&results)]);
    assert!(
        out.status.success(),
        "not supplied is no failure: {}",
        text(&out)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("missing co0.1"), "{stdout}");
    let out = courant(&["score", "fig1", "--results", s(&results), "--require-all"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    // A set one step late fails its time level; stated, it is a finding and the score passes;
    // the same statement on the on-time set fails (a verdict that differs from the statement).
    let late = dir.join("late/fig1");
    std::fs::create_dir_all(&late).unwrap();
    exchange::through_files(&one_step_late(&scene("fig1")), &late);
    let stated = dir.join("stated.toml");
    let mut text_stated = String::new();
    for (case, check) in [("co1", "linf"), ("co0.1", "tv_ratio / co0.5")] {
        text_stated += &format!(
            "[[finding]]\ncase = \"{case}\"\ncheck = \"{check}\"\nfinding = \"one step late\"\n\n"
        );
    }
    for case in ["co1", "co0.5", "co0.1"] {
        text_stated += &format!(
            "[[finding]]\ncase = \"{case}\"\ncheck = \"time_level\"\nfinding = \"one step late\"\n\n"
        );
    }
    std::fs::write(&stated, text_stated).unwrap();
    let out = courant(&[
        "score",
        "fig1",
        "--results",
        s(&late),
        "--stated",
        s(&stated),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("5 stated finding(s), 0 failed"),
        "{}",
        text(&out)
    );
    let out = courant(&[
        "score",
        "fig1",
        "--results",
        s(&exported(&dir.join("again"))),
        "--stated",
        s(&stated),
    ]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("stated as a finding, but it does not fail"),
        "{}",
        text(&out)
    );
}
