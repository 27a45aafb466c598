//! Source of truth: the guide's promises "no data loss" and "nothing written on bad input"
//! (docs/guide/running.md, "Output directories") and `courant::io::manifest`; a round of misuse
//! found that `courant report --out DIR` deleted a user's files in DIR.
//!
//! ```text
//!   DIR absent or empty ─────────────> written
//!   DIR with .courant-manifest,
//!       nothing else than it lists ──> replaced whole
//!   anything else (thesis.tex) ──────> refused, exit 2, nothing touched
//! ```
//!
//! Proves: `report --out`, `run --out` and `check --out` over a directory holding a user's files
//! exit 2, name the first foreign file and leave every file as it was; the directories courant
//! writes carry a manifest listing exactly what was written, and are replaced by the next run;
//! a file added by hand to an output directory makes it foreign too; `courant run` of several
//! scenes writes nothing when one of its destinations is refused (all or nothing).

use courant::io::manifest::MANIFEST;
use std::path::Path;
use std::process::Command;

use crate::cli;
use cli::scratch;

fn courant(args: &[&str]) -> (Option<i32>, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// A user's directory: a thesis and data in a subdirectory.
fn users_files(dir: &Path) {
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::write(dir.join("thesis.tex"), "\\chapter{Results}").unwrap();
    std::fs::write(dir.join("sub/data.csv"), "x,y\n1,2\n").unwrap();
}

fn assert_untouched(dir: &Path) {
    assert_eq!(
        std::fs::read_to_string(dir.join("thesis.tex")).unwrap(),
        "\\chapter{Results}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("sub/data.csv")).unwrap(),
        "x,y\n1,2\n"
    );
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, ["sub", "thesis.tex"], "nothing added or removed");
}

#[test]
fn report_run_and_check_refuse_a_directory_of_a_users_files_and_touch_nothing() {
    let base = scratch("users");
    let users = base.join("mine");
    users_files(&users);
    let path = users.to_str().unwrap();
    let (code, stderr) = courant(&["report", "--out", path]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("refusing to replace it: it holds `sub`")
            && stderr.contains("has no manifest"),
        "{stderr}"
    );
    assert_untouched(&users);
    // run and check replace OUT/<scene>: a user's directory there is refused the same way.
    let fig1 = base.join("out/fig1");
    users_files(&fig1);
    let out = base.join("out");
    for args in [
        vec!["run", "fig1", "--out", out.to_str().unwrap()],
        vec!["check", "fig1", "--out", out.to_str().unwrap()],
    ] {
        let (code, stderr) = courant(&args);
        assert_eq!(code, Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains("it holds `sub`"), "{stderr}");
        assert_untouched(&fig1);
    }
    std::fs::remove_dir_all(&base).unwrap();
}

#[test]
fn outputs_carry_a_manifest_of_what_was_written_and_are_replaced_by_the_next_run() {
    let base = scratch("manifest");
    let out = base.join("out");
    let (code, stderr) = courant(&["run", "fig1", "--out", out.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{stderr}");
    let dir = out.join("fig1");
    let manifest = std::fs::read_to_string(dir.join(MANIFEST)).unwrap();
    let mut listed: Vec<&str> = manifest.lines().filter(|l| !l.starts_with('#')).collect();
    listed.sort();
    let mut written: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n != MANIFEST)
        .collect();
    written.sort();
    assert_eq!(
        listed, written,
        "the manifest lists exactly the files written"
    );
    let (code, stderr) = courant(&["run", "fig1", "--out", out.to_str().unwrap()]);
    assert_eq!(code, Some(0), "a courant output is replaced: {stderr}");
    // A file added by hand would be lost with the directory: it is refused.
    std::fs::write(dir.join("notes.txt"), "mine").unwrap();
    let (code, stderr) = courant(&["run", "fig1", "--out", out.to_str().unwrap()]);
    assert_eq!(code, Some(2));
    assert!(
        stderr.contains("it holds `notes.txt`") && stderr.contains("its manifest does not list it"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("notes.txt")).unwrap(),
        "mine"
    );
    std::fs::remove_dir_all(&base).unwrap();
}

#[test]
fn run_writes_no_scene_when_one_destination_is_refused() {
    let base = scratch("all-or-nothing");
    let out = base.join("mo");
    users_files(&out.join("fig6"));
    let (code, stderr) = courant(&["run", "fig1", "fig6", "--out", out.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(!out.join("fig1").exists(), "fig1 was written: {stderr}");
    assert_untouched(&out.join("fig6"));
    std::fs::remove_dir_all(&base).unwrap();
}
