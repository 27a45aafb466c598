//! Source of truth: the guide's contract (docs/guide/running.md, docs/guide/report.md) for `courant report` and `courant run` ("output
//! directories are written whole or not at all (staged, then renamed into place)") and the
//! recovery rules documented in `courant::io::atomic`.
//!
//! Proves: killing `courant report` while it computes leaves the previous report directory
//! exactly as it was (nothing set aside, nothing partial in it), and the leftovers a writer
//! killed later would leave (its staging directory, or the previous report set aside between
//! two renames) are recovered by the next write: the previous report is put back, stale
//! directories of the dead process are removed (on Linux, where liveness is known).

use courant::io::atomic::{recover_interrupted, write_dir_atomically};
use courant::io::manifest::{MANIFEST, manifest_text};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Duration;

use crate::cli;
use cli::scratch;

const MARKER: &str = "# previous report (marker)\n";

/// Entry names of a directory, sorted.
fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    names
}

#[test]
fn a_killed_report_run_keeps_the_previous_report_and_its_leftovers_are_recovered() {
    let base = scratch("report-killed");
    let out = base.join("reports");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("index.md"), MARKER).unwrap();
    // A previous courant report: marked by its manifest (an unmarked directory is refused).
    std::fs::write(out.join(MANIFEST), manifest_text(["index.md"])).unwrap();

    let mut child = Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(["report", "--out", out.to_str().unwrap()])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(300));
    assert!(
        child.try_wait().unwrap().is_none(),
        "the report finished within 300 ms: killing it would prove nothing"
    );
    child.kill().unwrap();
    let status = child.wait().unwrap();
    assert!(!status.success(), "the run was killed: {status:?}");
    let pid = child.id();

    // The previous report is untouched: same files, same content, nothing set aside.
    assert_eq!(entries(&out), [MANIFEST, "index.md"]);
    assert_eq!(
        std::fs::read_to_string(out.join("index.md")).unwrap(),
        MARKER
    );
    let others: Vec<String> = entries(&base)
        .into_iter()
        .filter(|n| n != "reports")
        .collect();
    assert!(
        others
            .iter()
            .all(|n| *n == format!(".reports.partial-{pid}")),
        "only a staging directory of the killed run may be left: {others:?}"
    );

    // Had it been killed while writing its files: a half-written staging directory.
    let staging = base.join(format!(".reports.partial-{pid}"));
    std::fs::create_dir_all(staging.join("fig1")).unwrap();
    std::fs::write(staging.join("fig1/summary.csv"), "case,N\nco1,").unwrap();
    recover_interrupted(&out).unwrap();
    assert_eq!(
        std::fs::read_to_string(out.join("index.md")).unwrap(),
        MARKER
    );
    if cfg!(target_os = "linux") {
        assert!(
            !staging.exists(),
            "the dead run's staging directory is removed"
        );
    }

    // Had it been killed between moving the previous report aside and renaming its own into
    // place (the fallback where directories cannot be exchanged): no `reports` at all.
    let _ = std::fs::remove_dir_all(&staging);
    let set_aside = base.join(format!(".reports.old-{pid}"));
    std::fs::rename(&out, &set_aside).unwrap();
    recover_interrupted(&out).unwrap();
    assert_eq!(
        std::fs::read_to_string(out.join("index.md")).unwrap(),
        MARKER,
        "the previous report is put back"
    );
    assert!(!set_aside.exists());

    // The next write replaces it whole and leaves nothing beside it.
    std::fs::create_dir_all(&staging).unwrap();
    write_dir_atomically(&out, &[("index.md".into(), "# new report\n".into())]).unwrap();
    assert_eq!(
        std::fs::read_to_string(out.join("index.md")).unwrap(),
        "# new report\n"
    );
    if cfg!(target_os = "linux") {
        assert_eq!(entries(&base), ["reports"]);
    }
    std::fs::remove_dir_all(&base).unwrap();
}
