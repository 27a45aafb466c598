//! The commands behind the command line (`main.rs` only parses it): each validates its input
//! first (bad input writes nothing, exit status 2), runs, prints, and writes whole directories.
//!
//! Enters: parsed arguments. Leaves: terminal output, files, exit status. The top of the
//! pipeline: it may use every stage, and no stage uses it.

/// `println!` that never panics: see [`console`].
macro_rules! outln {
    () => { $crate::cli::console::out(format_args!("\n")) };
    ($($arg:tt)*) => { $crate::cli::console::out(format_args!("{}\n", format_args!($($arg)*))) };
}
/// `print!` that never panics: see [`console`].
macro_rules! out {
    ($($arg:tt)*) => { $crate::cli::console::out(format_args!($($arg)*)) };
}
/// `eprintln!` that never panics: see [`console`].
macro_rules! errln {
    ($($arg:tt)*) => { $crate::cli::console::err(format_args!("{}\n", format_args!($($arg)*))) };
}

pub mod bench;
mod bench_schemes;
pub mod check;
pub mod console;
pub mod reference;
pub mod run;
pub mod schemes;
pub mod score;

/// Read `COURANT_THREADS` once and keep it for every run of the process
/// ([`crate::run::threads`]); a value that is set but not a positive integer is refused, naming
/// the variable, the value and the rule.
///
/// # Errors
/// The message to print; the caller exits with status 2.
pub fn read_thread_setting() -> Result<(), String> {
    crate::run::threads::set(crate::run::threads::from_environment()?);
    Ok(())
}

/// Let a closed pipe end the process quietly, as Unix tools do (`courant list | head`): Rust
/// ignores SIGPIPE, so printing to a closed pipe would panic; the default action ends the
/// process without a message.
pub fn exit_quietly_on_closed_pipe() {
    #[cfg(unix)]
    // SAFETY: restoring the default disposition of SIGPIPE at start-up, before any thread is
    // spawned, touches no Rust state.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

use crate::io::atomic::{WriteError, write_dir_atomically};

/// Why `dir` was not written, naming the path once (a refusal names it already).
pub fn write_failure(dir: &std::path::Path, e: &WriteError) -> String {
    match e {
        WriteError::Refused(refusal) => refusal.to_string(),
        WriteError::Io(io) => format!("cannot write {}: {io}", dir.display()),
    }
}
use crate::pipeline::report_runs::run_for_report;
use crate::report::render;
use crate::scene::builtin::{self, BUILTIN_SCENES, builtin_scene, resolve_all};
use crate::scene::cases::Scene;
use crate::scene::studies::convergence::CONVERGENCE_STUDIES;
use crate::scene::studies::convergence::ConvergenceStudy;
use std::process::ExitCode;

/// `courant list`: the built-in scenes with a line each; `--schemes`: the schemes; with scene
/// names or paths: each scene's description and its case names, one a line (the names
/// `[[expect]] cases`, `courant score`'s files and `results.toml` use).
pub fn list(scenes: &[String], schemes: bool) -> ExitCode {
    if schemes {
        out!("{}", schemes::listing());
        return ExitCode::SUCCESS;
    }
    if !scenes.is_empty() {
        let resolved = match resolve_all(scenes) {
            Ok(resolved) => resolved,
            Err(errors) => {
                for e in errors {
                    errln!("error: {e}");
                }
                return ExitCode::from(2);
            }
        };
        for scene in &resolved {
            outln!("{}: {}", scene.name, scene.description);
            let names = case_names(scene);
            if names.is_empty() {
                outln!("(no cases: a sweep of critical Courant numbers, written as stability.csv)");
            }
            for name in names {
                outln!("{name}");
            }
        }
        return ExitCode::SUCCESS;
    }
    let width = BUILTIN_SCENES
        .iter()
        .map(|(n, _)| n.len())
        .max()
        .unwrap_or(0);
    for (name, _) in BUILTIN_SCENES {
        match builtin_scene(name) {
            Some(Ok(scene)) => outln!("{name:width$}  {}", scene.description),
            Some(Err(e)) => outln!("{name:width$}  (invalid: {e})"),
            None => {}
        }
    }
    outln!("(`courant list SCENE` names a scene's cases)");
    ExitCode::SUCCESS
}

/// The case names of a scene, in file order, whatever its study kind (a contact stability
/// sweep has none).
pub fn case_names(scene: &Scene) -> Vec<String> {
    let mut names: Vec<String> = scene.cases.iter().map(|c| c.name.clone()).collect();
    names.extend(scene.spectra.iter().map(|c| c.name.clone()));
    names.extend(scene.dispersion.iter().map(|c| c.name.clone()));
    names.extend(scene.contact.iter().map(|c| c.name.clone()));
    names
}

pub fn report(args: &[String], out: Option<&std::path::Path>) -> ExitCode {
    let (scenes, studies): (Vec<Scene>, &[ConvergenceStudy]) = if args.is_empty() {
        match builtin::all() {
            Ok(scenes) => (scenes, CONVERGENCE_STUDIES),
            Err(e) => {
                errln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        match resolve_all(args) {
            Ok(scenes) => (scenes, &[]),
            Err(errors) => {
                for e in errors {
                    errln!("error: {e}");
                }
                return ExitCode::from(2);
            }
        }
    };
    let out = match (out, args.is_empty()) {
        (Some(out), _) => out,
        (None, true) => std::path::Path::new("reports"),
        (None, false) => {
            errln!(
                "error: --out DIR is required with scene names, so that a report of some scenes never replaces the built-in report in reports/"
            );
            return ExitCode::from(2);
        }
    };
    // Refused before minutes of work: only an absent, empty or courant-written directory is
    // replaced.
    if let Err(e) = crate::io::manifest::check_replaceable(out) {
        errln!("error: {e}");
        return ExitCode::from(2);
    }
    let generated =
        run_for_report(&scenes, studies, !args.is_empty()).and_then(|runs| render(&scenes, &runs));
    let report = match generated {
        Ok(r) => r,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if let Err(e) = write_dir_atomically(out, &report.files) {
        errln!("error: {}", write_failure(out, &e));
        return ExitCode::from(2);
    }
    let t = report.tally;
    outln!(
        "report written to {} ({} files): {} verdicts, {} pass, {} finding(s), {} FAILED{}\nopen {}",
        out.display(),
        report.files.len(),
        t.total(),
        t.passed,
        t.findings,
        t.failed,
        if report.passed {
            ""
        } else {
            " (listed on the first screen)"
        },
        out.join("index.html").display()
    );
    if report.passed {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
