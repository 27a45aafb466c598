//! `courant run`: validate every scene, then run each and print its results, and write the
//! files of all of them, or of none.

use crate::compare::case::CaseResult;
use crate::compare::files::scene_files;
use crate::compare::outcome::SceneOutcome;
use crate::io::atomic::stage_dir;
use crate::io::manifest::check_replaceable;
use crate::pipeline::evaluate_scene;
use crate::results::case::Status;
use crate::scene::builtin::{BUILTIN_SCENES, resolve};
use crate::scene::cases::Scene;
use std::process::ExitCode;

pub fn run(args: &[String], out: &std::path::Path) -> ExitCode {
    let names: Vec<String> = if args.is_empty() {
        BUILTIN_SCENES.iter().map(|(n, _)| n.to_string()).collect()
    } else {
        args.to_vec()
    };
    // Validate everything first: bad input writes nothing.
    let mut scenes = Vec::new();
    let mut bad = false;
    for name in &names {
        match resolve(name) {
            Ok(scene) => scenes.push(scene),
            Err(e) => {
                eprintln!("error: {e}");
                bad = true;
            }
        }
    }
    let dirs: Vec<_> = scenes.iter().map(|s| out.join(&s.name)).collect();
    for (i, dir) in dirs.iter().enumerate() {
        if dirs[..i].contains(dir) {
            eprintln!(
                "error: {}: two scenes would write it (scene {} given twice)",
                dir.display(),
                scenes[i].name
            );
            bad = true;
        } else if let Err(e) = check_replaceable(dir) {
            eprintln!("error: {e}");
            bad = true;
        }
    }
    if bad {
        return ExitCode::from(2);
    }
    // Run every scene before any is put in place: each is staged to a hidden sibling as it
    // completes (its files leave memory), and only when all are staged are they committed. A
    // scene that fails drops the staged ones: nothing is written.
    let out_existed = out.exists();
    let nothing_written = || {
        if !out_existed {
            let _ = std::fs::remove_dir(out);
        }
    };
    let mut failed = false;
    let mut staged = Vec::with_capacity(scenes.len());
    for (scene, dir) in scenes.iter().zip(&dirs) {
        let outcome = match evaluate_scene(scene) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("error: {}: {e} (nothing was written)", scene.name);
                drop(staged);
                nothing_written();
                return ExitCode::from(2);
            }
        };
        print_scene(scene, &outcome);
        failed |= !outcome.passed();
        match stage_dir(dir, &scene_files(&outcome)) {
            Ok(s) => staged.push(s),
            Err(e) => {
                eprintln!(
                    "error: cannot write {}: {e} (nothing was written)",
                    dir.display()
                );
                drop(staged);
                nothing_written();
                return ExitCode::from(2);
            }
        }
    }
    let mut written: Vec<String> = Vec::with_capacity(staged.len());
    for s in staged {
        let dir = s.dir().display().to_string();
        if let Err(e) = s.commit() {
            eprintln!(
                "error: cannot write {dir}: {e}{}",
                if written.is_empty() {
                    " (nothing was written)".to_string()
                } else {
                    format!(" (written before it: {})", written.join(", "))
                }
            );
            return ExitCode::from(2);
        }
        println!("  -> {dir}");
        written.push(dir);
    }
    if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

pub fn print_scene(scene: &Scene, outcome: &SceneOutcome) {
    println!("{}: {}", scene.name, scene.description);
    println!("  source: {}", scene.source);
    if !outcome.spectra.is_empty() {
        println!(
            "  {:<24} {:>7} {:>22} {:>10}",
            "case", "modes", "closed-form deviation", "wall [s]"
        );
        for s in &outcome.spectra {
            let deviation = s
                .closed_form_deviation()
                .map_or("-".to_string(), |d| format!("{d:.3e}"));
            println!(
                "  {:<24} {:>7} {:>22} {:>10.4}",
                s.case,
                s.modes.len(),
                deviation,
                s.wall_time.as_secs_f64()
            );
        }
    }
    if !outcome.dispersion.is_empty() {
        println!(
            "  {:<18} {:>10} {:>16} {:>12}",
            "case", "modes", "max deviation", "min order"
        );
        for d in &outcome.dispersion {
            let order = d.min_order().map_or("-".to_string(), |o| format!("{o:.3}"));
            println!(
                "  {:<18} {:>10} {:>16.3e} {:>12}",
                d.case.name,
                d.rows.len(),
                d.deviation(),
                order
            );
        }
    }
    if !outcome.contact.is_empty() {
        println!(
            "  {:<32} {:>8} {:>8} {:>10} {:>10} {:>10} {:>10} {:>10}  status",
            "case", "Co", "Co_crit", "plateau", "impulse", "duration", "force_l1", "energy"
        );
        for c in &outcome.contact {
            let status = match &c.diverged {
                None => "completed".to_string(),
                Some(d) => format!("DIVERGED: {d}"),
            };
            // Undefined figures (see the summary's documentation) print as `-`.
            let duration = c.duration_error.map_or("-".into(), |d| format!("{d:.3e}"));
            let energy = c.energy_ratio.map_or("-".into(), |e| format!("{e:.4}"));
            println!(
                "  {:<32} {:>8.4} {:>8.4} {:>10.3e} {:>10.3e} {:>10} {:>10.3e} {:>10}  {status}",
                c.case,
                c.run.courant,
                c.run.critical.critical_courant(),
                c.plateau_deviation,
                c.impulse_error,
                duration,
                c.force_l1_error,
                energy
            );
        }
    }
    for s in &outcome.sweeps {
        println!(
            "  stability sweep: {} points, largest deviation from the closed form {:.3e}",
            s.rows.len(),
            s.deviation()
        );
    }
    print_cases(&outcome.results);
    for v in &outcome.verdicts {
        println!("  {}", v.describe());
    }
}

pub fn print_cases(results: &[CaseResult]) {
    if results.is_empty() {
        return;
    }
    println!(
        "  {:<10} {:>7} {:>8} {:>11} {:>8} {:>10} {:>10} {:>10} {:>9} {:>10} {:>10}  status",
        "case", "N", "Co", "dt", "steps", "L1", "L2", "Linf", "overshoot", "energy", "wall [s]"
    );
    for r in results {
        let n = r.worst_norms();
        let f = |x: Option<f64>| x.map_or("-".to_string(), |x| format!("{x:.3e}"));
        let status = match &r.status {
            Status::Completed => "completed".to_string(),
            Status::Diverged(d) => format!("DIVERGED: {d}"),
        };
        println!(
            "  {:<10} {:>7} {:>8.4} {:>11.4e} {:>8} {:>10} {:>10} {:>10} {:>9} {:>10.2e} {:>10.4}  {status}",
            r.case,
            r.elements,
            r.courant,
            r.dt,
            r.steps,
            f(n.map(|n| n.l1)),
            f(n.map(|n| n.l2)),
            f(n.map(|n| n.linf)),
            n.map_or("-".into(), |n| format!("{:.4}", n.overshoot)),
            r.energy.relative_balance_error(),
            r.wall_time.as_secs_f64(),
        );
    }
}
