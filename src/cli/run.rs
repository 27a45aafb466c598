//! `courant run`: validate every scene, then run each, print its results and write its files.

use crate::compare::case::CaseResult;
use crate::compare::files::scene_files;
use crate::compare::outcome::SceneOutcome;
use crate::io::atomic::write_dir_atomically;
use crate::pipeline::evaluate_scene;
use crate::report::numbers::shown;
use crate::results::case::Status;
use crate::results::table::{Cell, Table};
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
    if bad {
        return ExitCode::from(2);
    }
    let mut failed = false;
    for scene in &scenes {
        let outcome = match evaluate_scene(scene) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("error: {}: {e}", scene.name);
                return ExitCode::from(2);
            }
        };
        print_scene(scene, &outcome);
        failed |= !outcome.passed();
        let dir = out.join(&scene.name);
        if let Err(e) = write_dir_atomically(&dir, &scene_files(&outcome)) {
            eprintln!("error: cannot write {}: {e}", dir.display());
            return ExitCode::from(2);
        }
        println!("  -> {}\n", dir.display());
    }
    if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// A table for the terminal: numbers as the report shows them (one notation per column), text
/// left-aligned, numbers right-aligned, columns as wide as their widest cell, no trailing
/// spaces.
pub fn aligned(table: &Table, indent: &str) -> String {
    let cells = shown(table);
    let mut widths: Vec<usize> = table.columns.iter().map(|c| c.chars().count()).collect();
    for row in &cells {
        for (w, c) in widths.iter_mut().zip(row) {
            *w = (*w).max(c.chars().count());
        }
    }
    let right: Vec<bool> = (0..table.columns.len())
        .map(|c| {
            table
                .rows
                .iter()
                .all(|r| matches!(r[c], Cell::Num(_) | Cell::Int(_) | Cell::Empty))
        })
        .collect();
    let line = |row: &[String]| {
        let mut out = indent.to_string();
        for (i, (cell, w)) in row.iter().zip(&widths).enumerate() {
            if i > 0 {
                out.push_str("  ");
            }
            if right[i] {
                out.push_str(&format!("{cell:>w$}"));
            } else {
                out.push_str(&format!("{cell:<w$}"));
            }
        }
        out.trim_end().to_string() + "\n"
    };
    let mut out = line(&table.columns);
    for row in &cells {
        out.push_str(&line(row));
    }
    out
}

/// A scene's results on the terminal: its cases (cost beside error), its spectra, dispersion
/// runs, contact runs or sweep, then its verdicts.
pub fn print_scene(scene: &Scene, outcome: &SceneOutcome) {
    println!("{}: {}", scene.name, scene.description);
    println!("  source: {}", scene.source);
    if !outcome.spectra.is_empty() {
        let mut t = Table::new(&["case", "modes", "closed_form_deviation", "wall_s"]);
        for s in &outcome.spectra {
            t.push(vec![
                s.case.as_str().into(),
                s.modes.len().into(),
                s.closed_form_deviation().into(),
                s.wall_time.as_secs_f64().into(),
            ]);
        }
        print!("{}", aligned(&t, "  "));
    }
    if !outcome.dispersion.is_empty() {
        let mut t = Table::new(&["case", "modes", "max_deviation", "min_order"]);
        for d in &outcome.dispersion {
            t.push(vec![
                d.case.name.as_str().into(),
                d.rows.len().into(),
                d.deviation().into(),
                d.min_order().into(),
            ]);
        }
        print!("{}", aligned(&t, "  "));
    }
    if !outcome.contact.is_empty() {
        let mut t = Table::new(&[
            "case",
            "Co",
            "Co_crit",
            "plateau_dev",
            "impulse_err",
            "duration_err",
            "force_l1_err",
            "energy_ratio",
            "status",
        ]);
        for c in &outcome.contact {
            let status = match &c.diverged {
                None => "completed".to_string(),
                Some(d) => format!("DIVERGED: {d}"),
            };
            t.push(vec![
                c.case.as_str().into(),
                c.run.courant.into(),
                c.run.critical.critical_courant().into(),
                c.errors.plateau_deviation.into(),
                c.impulse_error.into(),
                c.errors.duration_error.into(),
                c.errors.force_l1_error.into(),
                c.energy_ratio.into(),
                status.into(),
            ]);
        }
        print!("{}", aligned(&t, "  "));
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

/// Time-stepping cases: cost (N, Co, dt, steps, wall time) beside error (worst norms, energy
/// balance) and how the run ended.
pub fn print_cases(results: &[CaseResult]) {
    if results.is_empty() {
        return;
    }
    let mut t = Table::new(&[
        "case",
        "N",
        "Co",
        "dt",
        "steps",
        "l1",
        "l2",
        "linf",
        "overshoot",
        "energy_balance",
        "wall_s",
        "status",
    ]);
    for r in results {
        let n = r.worst_norms();
        let status = match &r.status {
            Status::Completed => "completed".to_string(),
            Status::Diverged(d) => format!("DIVERGED: {d}"),
        };
        t.push(vec![
            r.case.as_str().into(),
            r.elements.into(),
            r.courant.into(),
            r.dt.into(),
            r.steps.into(),
            n.map(|n| n.l1).into(),
            n.map(|n| n.l2).into(),
            n.map(|n| n.linf).into(),
            n.map(|n| n.overshoot).into(),
            r.energy.relative_balance_error().into(),
            r.wall_time.as_secs_f64().into(),
            status.into(),
        ]);
    }
    print!("{}", aligned(&t, "  "));
}
