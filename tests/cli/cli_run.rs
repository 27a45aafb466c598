//! Source of truth: the command-line contract in docs/guide/running.md: `courant list`
//! names every built-in scene; `courant run` writes `<case>.csv` profiles with the columns
//! `t, element, x, stress, reference, error`, histories, energy logs and a `summary.csv` with cost and
//! error per case; exit status 0 when every expectation holds, 1 when one fails.
//!
//! Proves: the files exist with their headers; the same scenes give bit-identical results on a
//! second run with another thread count (1 and 4 rayon threads: the cases of a scene, the
//! distinct exact profiles and the rows of a stability sweep run in parallel, so this catches
//! any result that depends on scheduling) — fig1 (shared d'Alembert profiles), fig2 (graded
//! reference, Park), fig5 (13 contact cases) and fig3 (the stability sweep), only the wall-time
//! column differs; and a failed expectation fails the command.

use std::path::Path;

use crate::cli;
use cli::{courant, scratch};

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
    for (name, _) in courant::scene::builtin::BUILTIN_SCENES {
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
fn run_writes_profiles_histories_energy_and_summary_identically_with_1_and_4_threads() {
    let dir = scratch("fig1");
    let (a, b) = (dir.join("a"), dir.join("b"));
    let scenes = ["fig1", "fig2", "fig5", "fig3"];
    for (out, threads) in [(&a, "1"), (&b, "4")] {
        let mut args = vec!["run"];
        args.extend(scenes);
        args.extend(["--out", out.to_str().unwrap()]);
        let status = cli::courant_with_env(&args, &[("RAYON_NUM_THREADS", threads)]);
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
    for name in scenes {
        let mut files: Vec<_> = std::fs::read_dir(a.join(name))
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        files.sort();
        let mut others: Vec<_> = std::fs::read_dir(b.join(name))
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        others.sort();
        assert_eq!(files, others, "{name}: different files");
        assert!(files.len() >= 2, "{name}: {files:?}");
        for file in files {
            let (x, y) = (
                std::fs::read_to_string(a.join(name).join(&file)).unwrap(),
                std::fs::read_to_string(b.join(name).join(&file)).unwrap(),
            );
            if file == "summary.csv" {
                // Everything but the last column (wall time) must match.
                assert!(x.lines().next().unwrap().ends_with(",wall_time_s"));
                let strip = |s: &str| {
                    s.lines()
                        .map(|l| l.rsplit_once(',').unwrap().0.to_string())
                        .collect::<Vec<_>>()
                };
                assert_eq!(strip(&x), strip(&y), "{name}/summary.csv");
            } else {
                assert_eq!(x, y, "{name}/{file:?} differs between 1 and 4 threads");
            }
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_failed_expectation_fails_the_run_with_status_1_and_is_recorded() {
    let dir = scratch("strict");
    std::fs::create_dir_all(&dir).unwrap();
    let text = courant::scene::builtin::builtin_text("fig1")
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
