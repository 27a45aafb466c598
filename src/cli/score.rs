//! `courant score`: read result directories (the exchange format), grade them against a scene,
//! print the checks as `courant check` does, write the tables and JUnit XML when asked.

use crate::check::score_junit::xml;
use crate::check::score_render::terminal;
use crate::compare::score::outcome::Stated;
use crate::compare::score::stated::{apply, parse};
use crate::compare::score::tables::score_files;
use crate::io::atomic::write_dir_atomically;
use crate::io::clock::date;
use crate::io::owned_file::{JUNIT, check_file_replaceable, write_owned_file};
use crate::pipeline::score::score_dirs;
use crate::scene::builtin::resolve;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// How `courant score` judges what it reads.
#[derive(Debug, Clone, Copy, Default)]
pub struct Options<'a> {
    /// What is not supplied fails (`--require-all`).
    pub require_all: bool,
    /// Findings stated for the sets (`--stated FILE`).
    pub stated: Option<&'a Path>,
}

/// Read a `stated.toml` (`compare::score::stated`).
fn read_stated(path: &Path) -> Result<Vec<Stated>, String> {
    let shown = path.display().to_string();
    if !path.is_file() {
        return Err(format!("--stated {shown}: not a regular file"));
    }
    let text = std::fs::read_to_string(path).map_err(|e| format!("--stated {shown}: {e}"))?;
    parse(&shown, &text)
}

/// Score `results` (one or more directories) against `scene`. Exit status 0 when every check
/// holds (with `require_all`, every case and time supplied), 1 when one fails, 2 on bad input
/// (nothing is written then).
pub fn score(
    scene: &str,
    results: &[PathBuf],
    options: &Options,
    out: Option<&Path>,
    junit: Option<&Path>,
) -> ExitCode {
    let started = date();
    let clock = std::time::Instant::now();
    let scene = match resolve(scene) {
        Ok(scene) => scene,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    // Refused before any work: only a new file or a JUnit report courant wrote is replaced.
    if let Some(Err(e)) = junit.map(|file| check_file_replaceable(file, JUNIT)) {
        errln!("error: --junit {e}");
        return ExitCode::from(2);
    }
    // Everything is read, checked and compared before anything is written.
    let stated = match options.stated.map(read_stated).transpose() {
        Ok(stated) => stated,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let outcome = match score_dirs(&scene, results) {
        Ok(mut outcome) => {
            for set in &mut outcome.sets {
                set.require_all = options.require_all;
                if let Some(stated) = &stated {
                    apply(set, stated.clone());
                }
            }
            outcome
        }
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    out!("{}", terminal(&scene, &outcome));
    if let Some(out) = out {
        let dir = out.join(&scene.name);
        if let Err(e) = write_dir_atomically(&dir, &score_files(&outcome)) {
            errln!("error: {}", super::write_failure(&dir, &e));
            return ExitCode::from(2);
        }
        outln!("  -> {}", dir.display());
    }
    if let Some(file) = junit {
        let text = xml(&scene, &outcome, &started, clock.elapsed().as_secs_f64());
        if let Err(e) = write_owned_file(file, &text, JUNIT) {
            errln!("error: cannot write --junit {e}");
            return ExitCode::from(2);
        }
        outln!("  -> {}", file.display());
    }
    if outcome.passed() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
