//! The commands behind the command line (`main.rs` only parses it): each validates its input
//! first (bad input writes nothing, exit status 2), runs, prints, and writes whole directories.
//!
//! Enters: parsed arguments. Leaves: terminal output, files, exit status. The top of the
//! pipeline: it may use every stage, and no stage uses it.

pub mod check;
pub mod run;
pub mod schemes;

use crate::io::atomic::write_dir_atomically;
use crate::pipeline::report_runs::run_for_report;
use crate::report::render;
use crate::scene::builtin::{self, BUILTIN_SCENES, builtin_scene};
use crate::scene::studies::convergence::CONVERGENCE_STUDIES;
use std::process::ExitCode;

pub fn list(schemes: bool) -> ExitCode {
    if schemes {
        print!("{}", schemes::listing());
        return ExitCode::SUCCESS;
    }
    for (name, _) in BUILTIN_SCENES {
        match builtin_scene(name) {
            Some(Ok(scene)) => println!("{name:16} {}", scene.description),
            Some(Err(e)) => println!("{name:16} (invalid: {e})"),
            None => {}
        }
    }
    ExitCode::SUCCESS
}

pub fn report(out: &std::path::Path) -> ExitCode {
    let generated = builtin::all()
        .map_err(|e| e.to_string())
        .and_then(|scenes| {
            let runs = run_for_report(&scenes, CONVERGENCE_STUDIES)?;
            render(&scenes, &runs)
        });
    let report = match generated {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if let Err(e) = write_dir_atomically(out, &report.files) {
        eprintln!("error: cannot write {}: {e}", out.display());
        return ExitCode::from(2);
    }
    println!(
        "report written to {} ({} files){}",
        out.display(),
        report.files.len(),
        if report.passed {
            ""
        } else {
            "; some expectations FAILED (see index.md)"
        }
    );
    if report.passed {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
