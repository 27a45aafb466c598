//! Terminal output that never panics: `println!` panics when stdout cannot be written (a full
//! disk, `courant list > /dev/full`), which ended the process with status 101 and, in `run`,
//! before its files were committed.
//!
//! Every line the commands print goes through [`out`] or [`err`]. A failed write is remembered
//! (the first one) and the command goes on, so that `run` still commits its files; [`finish`]
//! then prints one line to stderr and turns the exit status into 2. A closed pipe is such a
//! failure for every command that writes files (`courant run ... | head -1` finishes writing,
//! then says its lines were cut short); `list`, which only prints, ends quietly instead (see
//! [`super::exit_quietly_on_closed_pipe`]).

use std::fmt;
use std::io::Write;
use std::process::ExitCode;
use std::sync::Mutex;

/// The first write to the terminal that failed: which stream and why.
static FAILED: Mutex<Option<(&'static str, std::io::ErrorKind, String)>> = Mutex::new(None);

fn remember(stream: &'static str, error: &std::io::Error) {
    let mut failed = FAILED
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if failed.is_none() {
        *failed = Some((stream, error.kind(), error.to_string()));
    }
}

/// Write to stdout; a failure is remembered for [`finish`], never a panic.
pub fn out(args: fmt::Arguments<'_>) {
    let mut stdout = std::io::stdout().lock();
    if let Err(e) = stdout.write_fmt(args) {
        remember("stdout", &e);
    }
}

/// Write to stderr; a failure is remembered for [`finish`], never a panic.
pub fn err(args: fmt::Arguments<'_>) {
    let mut stderr = std::io::stderr().lock();
    if let Err(e) = stderr.write_fmt(args) {
        remember("stderr", &e);
    }
}

/// What a failed write to the terminal reads as (`None` when every write succeeded).
pub fn failure() -> Option<String> {
    let failed = FAILED
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    failed.as_ref().map(|(stream, kind, why)| {
        if *kind == std::io::ErrorKind::BrokenPipe {
            format!(
                "{stream} was closed before the output ended (a pipe's reader left); the command ran to its end (the files it writes are complete), but some of its lines were not printed"
            )
        } else {
            format!("cannot write to {stream}: {why}")
        }
    })
}

/// The exit status of a command whose status was `code`: flush stdout, and when any write to
/// the terminal failed, say so on stderr (if it can) and return 2 (files the command wrote are
/// kept).
pub fn finish(code: ExitCode) -> ExitCode {
    if let Err(e) = std::io::stdout().lock().flush() {
        remember("stdout", &e);
    }
    match failure() {
        None => code,
        Some(message) => {
            let _ = writeln!(std::io::stderr().lock(), "error: {message}");
            ExitCode::from(2)
        }
    }
}
