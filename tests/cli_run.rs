//! Source of truth: the command-line contract in the README ("Running scenes"): `courant list`
//! names every built-in scene; `courant run` writes `<case>.csv` profiles with the columns
//! `t, element, x, stress, reference, error`, histories, energy logs and a `summary.csv` with cost and
//! error per case; exit status 0 when every expectation holds, 1 when one fails.
//!
//! Proves: the files exist with their headers, the same scene gives bit-identical results on a
//! second run (only the wall-time column differs), and a failed expectation fails the command.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn courant(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(args)
        .output()
        .unwrap()
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("courant-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn header(path: &Path) -> String {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .next()
        .unwrap_or_default()
        .to_string()
}

#[test]
fn list_names_every_built_in_scene_with_its_description() {
    let out = courant(&["list"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for (name, _) in courant::builtin::BUILTIN_SCENES {
        let line = text
            .lines()
            .find(|l| l.starts_with(name))
            .unwrap_or_else(|| panic!("{name} not listed"));
        assert!(
            line.len() > name.len() + 10,
            "{name} needs a description: {line}"
        );
    }
}

#[test]
fn run_writes_profiles_histories_energy_and_summary_and_is_deterministic() {
    let dir = scratch("fig1");
    let (a, b) = (dir.join("a"), dir.join("b"));
    for out in [&a, &b] {
        let status = courant(&["run", "fig1", "--out", out.to_str().unwrap()]);
        assert!(
            status.status.success(),
            "{}",
            String::from_utf8_lossy(&status.stderr)
        );
    }
    let scene = a.join("fig1");
    for case in ["co1", "co0.5", "co0.1"] {
        assert_eq!(
            header(&scene.join(format!("{case}.csv"))),
            "t,element,x,stress,reference,error"
        );
        assert_eq!(
            header(&scene.join(format!("{case}.history.csv"))),
            "node,x,t,u,u_reference,v,v_reference,a"
        );
        assert!(
            header(&scene.join(format!("{case}.energy.csv")))
                .starts_with("step,t,kinetic,kinetic_staggered,strain,work,balance_error")
        );
    }
    assert_eq!(
        header(&scene.join("summary.csv")),
        "case,N,scheme,mass,Co,Co_crit,dt,dt_crit,dt_crit_element,dt_crit_gershgorin,steps,l1,l2,linf,overshoot,tv_ratio,energy_balance,energy_lost,status,wall_time_s"
    );
    let mut files: Vec<_> = std::fs::read_dir(&scene)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    files.sort();
    for file in files {
        let (x, y) = (
            std::fs::read_to_string(scene.join(&file)).unwrap(),
            std::fs::read_to_string(b.join("fig1").join(&file)).unwrap(),
        );
        if file == "summary.csv" {
            // Everything but the last column (wall time) must match.
            let strip = |s: &str| {
                s.lines()
                    .map(|l| l.rsplit_once(',').unwrap().0.to_string())
                    .collect::<Vec<_>>()
            };
            assert_eq!(strip(&x), strip(&y));
        } else {
            assert_eq!(x, y, "{file:?} differs between two runs");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_failed_expectation_fails_the_run_with_status_1_and_is_recorded() {
    let dir = scratch("strict");
    std::fs::create_dir_all(&dir).unwrap();
    let text = courant::builtin::builtin_text("fig1")
        .unwrap()
        .replace("max = 1e-10", "max = 1e-30");
    let path = dir.join("strict.toml");
    std::fs::write(&path, text).unwrap();
    let out = courant(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    let verdicts = std::fs::read_to_string(dir.join("out/strict/expectations.csv")).unwrap();
    assert!(
        verdicts
            .lines()
            .any(|l| l.starts_with("co1,linf,") && l.contains(",FAIL,")),
        "{verdicts}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
