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
    /// Name the built-in scenes with a one-line description each.
    List,
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
        /// Also write each scene's results in the exchange format (what `courant score` reads)
        /// to DIR/<scene>/.
        #[arg(long, value_name = "DIR")]
        exchange: Option<PathBuf>,
    },
    /// Grade another code's results (the exchange format: DIR/<case>.csv, results.toml) against
    /// a scene's references, with the norms and expectations of `run`, plus diagnostics
    /// (time-level offset, sign, load convention) and, for several directories of one case at
    /// different N, its convergence orders.
    ///
    /// Prints one row per check as `check` does. Exit status: 0 when every check holds, 1 when
    /// one fails, 2 on bad input (file, line, column named; nothing is written then).
    Score {
        /// Scene name or path.
        scene: String,
        /// Result directories, one per set (e.g. one per mesh for a convergence study).
        #[arg(long, value_name = "DIR", num_args = 1.., required = true)]
        results: Vec<PathBuf>,
        /// Write summary.csv, norms.csv, expectations.csv, diagnostics.csv (and convergence.csv)
        /// to DIR/<scene>/.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Write a JUnit XML report here.
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
    },
    /// Write a scene's exact answers in the exchange format to DIR/<scene>/: at its own mesh
    /// and output times, or at the rows of a query file (t, x_left, x_right | t, x | t | mode).
    /// Every file has a `reference` column naming the reference that produced it.
    Reference {
        /// Scene name or path.
        scene: String,
        /// Query file: the positions and times (or modes) to evaluate at.
        #[arg(long, value_name = "POINTS.csv")]
        at: Option<PathBuf>,
        /// Output directory.
        #[arg(long, value_name = "DIR")]
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
        Command::List => courant::cli::list(),
        Command::Run {
            scenes,
            out,
            exchange,
        } => courant::cli::run::run(&scenes, &out, exchange.as_deref()),
        Command::Score {
            scene,
            results,
            out,
            junit,
        } => courant::cli::score::score(&scene, &results, out.as_deref(), junit.as_deref()),
        Command::Reference { scene, at, out } => {
            courant::cli::reference::reference(&scene, at.as_deref(), &out)
        }
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
