//! `courant`: the command line. Only parsing: the commands are in `courant::cli`.

use clap::{Parser, Subcommand};
use courant::cli::check::CheckOptions;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "courant",
    version,
    about = "Verification benchmarks and reference solutions for explicit FE dynamics of bars"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Name the built-in scenes with a one-line description each (with --schemes: the schemes
    /// scenes may name, their parameters, masses and sources).
    List {
        /// List the schemes instead of the scenes.
        #[arg(long)]
        schemes: bool,
    },
    /// Run scenes (built-in names or paths to .toml files; all built-in scenes when none given).
    ///
    /// Writes DIR/<scene>/<case>.csv (stress profiles), <case>.history.csv, <case>.energy.csv,
    /// summary.csv, norms.csv and expectations.csv. Exit status: 0 when every expectation holds,
    /// 1 when one fails, 2 on bad input (nothing is written then).
    Run {
        /// Scene names or paths.
        scenes: Vec<String>,
        /// Output directory.
        #[arg(long, default_value = "results")]
        out: PathBuf,
    },
    /// Regenerate the verification report: every built-in scene, the convergence and
    /// work-precision studies and the stability table, run in parallel, written whole (staged,
    /// then renamed) to DIR: index.html (open it in a browser; its first screen counts every
    /// verdict and links to it), index.md, every table as CSV and every figure as SVG, and the
    /// machine's timings in timing.md. With scene names or .toml paths: a report of those
    /// scenes alone (figures, tables, verdicts), which needs --out. Exit status 0 when every
    /// verdict holds, 1 when one fails, 2 on errors (the previous report is then kept).
    Report {
        /// Scene names or paths (every built-in scene and the studies when none given).
        scenes: Vec<String>,
        /// Output directory (default `reports` for the built-in report; required with scenes).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Check scenes for CI: run them and gate on their verdicts (and on a baseline).
    ///
    /// Verdicts: every expectation, the stability verdict of every case of a stability scene,
    /// and (with no scene named) the convergence-order bands of the report's studies. Prints a
    /// line per scene and every failure with how far past its bound (`--verbose`: every
    /// verdict). Exit status: 0 when every check holds (findings a scene states pass), 1 when
    /// one fails (a verdict, or a file beyond its baseline tolerance), 2 on bad input (nothing
    /// is written then).
    Check(CheckOptions),
}

fn main() -> ExitCode {
    courant::cli::exit_quietly_on_closed_pipe();
    match Cli::parse().command {
        Command::List { schemes } => courant::cli::list(schemes),
        Command::Run { scenes, out } => courant::cli::run::run(&scenes, &out),
        Command::Report { scenes, out } => courant::cli::report(&scenes, out.as_deref()),
        Command::Check(options) => courant::cli::check::check(&options),
    }
}
