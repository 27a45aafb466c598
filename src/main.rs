//! `courant`: the command line. Only parsing: the commands are in `courant::cli`.

use clap::{Parser, Subcommand};
use courant::cli::check::ToleranceOptions;
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
    /// Regenerate the verification report: every built-in scene and the convergence studies,
    /// run in parallel, written whole (staged, then renamed) to DIR: index.md, per-scene CSV
    /// tables, convergence/*.csv, timing.md and timing.csv. Exit status 0 when every
    /// expectation holds, 1 when one fails, 2 on errors (the previous report is then kept).
    Report {
        /// Output directory.
        #[arg(long, default_value = "reports")]
        out: PathBuf,
    },
    /// Check scenes for CI: run them and gate on their expectations (and on a baseline).
    ///
    /// Prints every expectation with case, metric, measured value, bound, verdict and source.
    /// Exit status: 0 when every check holds, 1 when one fails (an expectation, or a file
    /// beyond its baseline tolerance), 2 on bad input (nothing is written then).
    Check {
        /// Scene names or paths (all built-in scenes when none given).
        scenes: Vec<String>,
        /// Write a JUnit XML report here (one testsuite per scene, one testcase per check).
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
        /// Compare the fresh CSVs with a previous report (`courant report --out DIR`, e.g. the
        /// committed `reports/`: each scene's tables) or a previous `courant run --out DIR`
        /// (every result file), DIR/<scene>/*.csv.
        #[arg(long, value_name = "DIR")]
        baseline: Option<PathBuf>,
        #[command(flatten)]
        tolerances: ToleranceOptions,
        /// Also write the result directories, as `courant run --out DIR` does.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
    },
}

fn main() -> ExitCode {
    match Cli::parse().command {
        Command::List { schemes } => courant::cli::list(schemes),
        Command::Run { scenes, out } => courant::cli::run::run(&scenes, &out),
        Command::Report { out } => courant::cli::report(&out),
        Command::Check {
            scenes,
            junit,
            baseline,
            tolerances,
            out,
        } => courant::cli::check::check(
            &scenes,
            junit.as_deref(),
            baseline.as_deref(),
            &tolerances,
            out.as_deref(),
        ),
    }
}
