//! `courant run`: validate every scene, then run each and print its results, and write the
//! files of all of them, or of none.

use crate::compare::case::CaseResult;
use crate::compare::files::{StreamedFiles, scene_files_streamed, write_profile_csv};
use crate::compare::outcome::SceneOutcome;
use crate::compare::score::export::exchange_set;
use crate::io::atomic::{Stream, stage_dir_streamed};
use crate::io::manifest::check_replaceable;
use crate::pipeline::evaluate_scene;
use crate::report::numbers::shown;
use crate::results::case::Status;
use crate::results::exchange::writer::set_files;
use crate::results::table::{Cell, Table};
use crate::scene::builtin::{BUILTIN_SCENES, resolve_within};
use crate::scene::cases::Scene;
use crate::scene::limits::Limits;
use std::process::ExitCode;

/// Run scenes and write their files to `out/<scene>/`; with `exchange`, also their results in the
/// exchange format to `exchange/<scene>/` (what `courant score` reads). Scenes are validated
/// against `limits` ([`Limits::LARGE`] for `courant run --large`).
pub fn run(
    args: &[String],
    out: &std::path::Path,
    exchange: Option<&std::path::Path>,
    limits: Limits,
) -> ExitCode {
    let names: Vec<String> = if args.is_empty() {
        BUILTIN_SCENES.iter().map(|(n, _)| n.to_string()).collect()
    } else {
        args.to_vec()
    };
    // Validate everything first: bad input writes nothing.
    let mut scenes = Vec::new();
    let mut bad = false;
    for name in &names {
        match resolve_within(name, limits) {
            Ok(scene) => scenes.push(scene),
            Err(e) => {
                errln!("error: {e}");
                bad = true;
            }
        }
    }
    let dirs: Vec<_> = scenes.iter().map(|s| out.join(&s.name)).collect();
    let exchange_dirs: Vec<_> = exchange
        .map(|root| scenes.iter().map(|s| root.join(&s.name)).collect())
        .unwrap_or_default();
    for dir in &exchange_dirs {
        if dirs.contains(dir) {
            errln!(
                "error: {}: both the results and the exchange files would go there (give --exchange another directory)",
                dir.display()
            );
            bad = true;
        } else if let Err(e) = check_replaceable(dir) {
            errln!("error: {e}");
            bad = true;
        }
    }
    for (i, dir) in dirs.iter().enumerate() {
        if dirs[..i].contains(dir) {
            errln!(
                "error: {}: two scenes would write it (scene {} given twice)",
                dir.display(),
                scenes[i].name
            );
            bad = true;
        } else if let Err(e) = check_replaceable(dir) {
            errln!("error: {e}");
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
    let exchange_existed = exchange.is_some_and(|root| root.exists());
    let nothing_written = || {
        if !out_existed {
            let _ = std::fs::remove_dir(out);
        }
        if let (Some(root), false) = (exchange, exchange_existed) {
            let _ = std::fs::remove_dir(root);
        }
    };
    let mut failed = false;
    let mut staged = Vec::with_capacity(scenes.len());
    for (scene, dir) in scenes.iter().zip(&dirs) {
        let outcome = match evaluate_scene(scene) {
            Ok(r) => r,
            Err(e) => {
                errln!("error: {}: {e} (nothing was written)", scene.name);
                drop(staged);
                nothing_written();
                return ExitCode::from(2);
            }
        };
        print_scene(scene, &outcome);
        failed |= !outcome.passed();
        // The cases' profile files are streamed into the staged directory row by row.
        let StreamedFiles { texts, profiles } = scene_files_streamed(&outcome);
        let writers: Vec<_> = profiles
            .iter()
            .map(|(_, r)| move |out: &mut dyn std::io::Write| write_profile_csv(r, out))
            .collect();
        let streams: Vec<Stream<'_>> = profiles
            .iter()
            .zip(&writers)
            .map(|((name, _), w)| (name.clone(), w as &dyn Fn(&mut dyn std::io::Write) -> _))
            .collect();
        let mut files = vec![(dir.clone(), texts, &streams[..], "")];
        if let Some(root) = exchange {
            let xdir = root.join(&scene.name);
            match exchange_set(scene, &outcome, &xdir.display().to_string()) {
                Some(set) => files.push((xdir, set_files(&set), &[], " (exchange format)")),
                None => outln!(
                    "  (no exchange form of {}: a dispersion or contact-stability study)",
                    scene.name
                ),
            }
        }
        for (dir, files, streams, label) in files {
            match stage_dir_streamed(&dir, &files, streams) {
                Ok(s) => staged.push((s, label)),
                Err(e) => {
                    errln!(
                        "error: {} (nothing was written)",
                        super::write_failure(&dir, &e)
                    );
                    drop(staged);
                    nothing_written();
                    return ExitCode::from(2);
                }
            }
        }
    }
    let mut written: Vec<String> = Vec::with_capacity(staged.len());
    for (s, label) in staged {
        let path = s.dir().to_path_buf();
        let dir = path.display().to_string();
        if let Err(e) = s.commit() {
            errln!(
                "error: {}{}",
                super::write_failure(&path, &e),
                if written.is_empty() {
                    " (nothing was written)".to_string()
                } else {
                    format!(" (written before it: {})", written.join(", "))
                }
            );
            return ExitCode::from(2);
        }
        outln!("  -> {dir}{label}");
        written.push(dir);
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
    outln!("{}: {}", scene.name, scene.description);
    outln!("  source: {}", scene.source);
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
        out!("{}", aligned(&t, "  "));
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
        out!("{}", aligned(&t, "  "));
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
        out!("{}", aligned(&t, "  "));
    }
    for s in &outcome.sweeps {
        outln!(
            "  stability sweep: {} points, largest deviation from the closed form {:.3e}",
            s.rows.len(),
            s.deviation()
        );
    }
    print_cases(&outcome.results);
    for v in &outcome.verdicts {
        outln!("  {}", v.describe());
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
        let status = match &r.run.status {
            Status::Completed => "completed".to_string(),
            Status::Diverged(d) => format!("DIVERGED: {d}"),
        };
        t.push(vec![
            r.run.case.as_str().into(),
            r.elements.into(),
            r.run.courant.into(),
            r.run.dt.into(),
            r.run.steps.into(),
            n.map(|n| n.l1).into(),
            n.map(|n| n.l2).into(),
            n.map(|n| n.linf).into(),
            n.map(|n| n.overshoot).into(),
            r.energy.relative_balance_error().into(),
            r.run.wall_time.as_secs_f64().into(),
            status.into(),
        ]);
    }
    out!("{}", aligned(&t, "  "));
}
