//! `courant`: the command line. Only parsing: the commands are in `courant::cli`.

use clap::{Parser, Subcommand};
use courant::cli::check::CheckOptions;
use courant::io::manifest::set_writer;
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
    /// List the built-in scenes, a scene's cases, or the schemes.
    ///
    /// Without arguments: the built-in scenes with a one-line description each. With scene names
    /// or .toml paths: each scene's description and its case names, one a line. With --schemes:
    /// the schemes scenes may name, their parameters, masses and sources.
    List {
        /// Scene names or paths whose cases to list.
        scenes: Vec<String>,
        /// List the schemes instead of the scenes.
        #[arg(long)]
        schemes: bool,
    },
    /// Run scenes and write their results as CSV.
    ///
    /// Scenes are built-in names or paths to .toml files (all built-in scenes when none given).
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
        /// Opt in to one large run: up to 10^7 elements per bar (the solver's mesh cap) and per
        /// scene, and the output of one profile time of such a bar, instead of the default 5x10^5
        /// (chosen so any scene validates in about a second). The node-step limit stays.
        #[arg(long)]
        large: bool,
        /// Replace DIR/<scene> even when another command (`courant run`, `reference`, `score`)
        /// wrote it (its manifest says which); without it that is refused.
        #[arg(long)]
        force: bool,
    },
    /// Grade another code's results against a scene's exact answers.
    ///
    /// The results are in the exchange format (DIR/<case>.csv, results.toml); they are graded
    /// with the norms and expectations of `run`, plus diagnostics
    /// (magnitude, time level, sign, layout) and, for several directories of one case at
    /// different N, its convergence orders.
    ///
    /// Error bounds apply to every code; a scene's signature rows (what its case's scheme and
    /// mass do) only where results.toml declares that scheme, its parameters and the mass.
    /// Prints one row per check as `check` does. Exit status: 0 when every check holds, 1 when
    /// one fails, 2 on bad input (every bad file, line and key named; nothing is written then).
    Score {
        /// Scene name or path.
        scene: String,
        /// A result directory: DIR or DIR/<scene> (as `reference --out DIR` writes it). Repeat
        /// the flag for several sets (e.g. one per mesh for a convergence study).
        #[arg(long, value_name = "DIR", action = clap::ArgAction::Append, required = true)]
        results: Vec<PathBuf>,
        /// Fail when a case of the scene has no file, or an expectation's time no profile (by
        /// default these are "not supplied" and skipped).
        #[arg(long)]
        require_all: bool,
        /// Findings stated for the sets (a `stated.toml`: case, check, finding): a stated check
        /// that fails is a finding of that code, not a failure; one that passes fails.
        #[arg(long, value_name = "FILE")]
        stated: Option<PathBuf>,
        /// Write summary.csv, norms.csv, expectations.csv, diagnostics.csv (and convergence.csv)
        /// to DIR/<scene>/.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Write a JUnit XML report here.
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
        /// Replace DIR/<scene> even when another command (`courant run`, `reference`, `score`)
        /// wrote it (its manifest says which); without it that is refused.
        #[arg(long)]
        force: bool,
    },
    /// Write a scene's exact answers in the exchange format.
    ///
    /// To DIR/<scene>/: at its own mesh and output times, or at the rows of a query file (t, x_left, x_right | t, x | t | mode).
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
        /// Replace DIR/<scene> even when another command (`courant run`, `reference`, `score`)
        /// wrote it (its manifest says which); without it that is refused.
        #[arg(long)]
        force: bool,
    },
    /// Regenerate the verification report (HTML, Markdown, CSV, SVG).
    ///
    /// Every built-in scene, the convergence and
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
    /// Verdicts (the report counts the same, and adds the committed results of other codes): every expectation, the stability verdict of every case of a stability scene,
    /// and (with no scene named) the convergence-order bands of the report's studies. Prints a
    /// line per scene and every failure with how far past its bound (`--verbose`: every
    /// verdict). Exit status: 0 when every check holds (findings a scene states pass), 1 when
    /// one fails (a verdict, or a file beyond its baseline tolerance), 2 on bad input (nothing
    /// is written then).
    Check(CheckOptions),
    /// Time courant's step and run loop against a C reference on this machine.
    ///
    /// The C reference is the lumped central-difference step (its fastest variant, built with $CC, default gcc, and $CFLAGS, default -O3 -march=native), courant's kernel and
    /// courant's run loop side by side on this machine, and write their ratios (CSV) to FILE.
    ///
    /// Medians of wall time (ns per node-step) on the graded bar of the benchmarks; a shared
    /// machine is noisy: repeat when in doubt. Exit status: 0, or 2 on bad options. Without a C
    /// compiler the C columns stay empty.
    Bench {
        /// Element counts, comma-separated.
        #[arg(long, value_delimiter = ',', default_value = "1000,100000,1000000")]
        sizes: Vec<usize>,
        /// Node-steps per repetition.
        #[arg(long, default_value_t = 5e7)]
        node_steps: f64,
        /// Repetitions (the median is reported).
        #[arg(long, default_value_t = 9)]
        reps: usize,
        /// The CSV file written.
        #[arg(long, value_name = "FILE", default_value = "bench.csv")]
        out: PathBuf,
        /// Skip the C reference.
        #[arg(long)]
        no_c: bool,
        /// Skip the other schemes' runs (every scheme and mass beside lumped CD, written to
        /// FILE's sibling `<stem>.schemes.csv`).
        #[arg(long)]
        no_schemes: bool,
    },
}

fn main() -> ExitCode {
    let command = Cli::parse().command;
    // `list` only prints: a closed pipe (`courant list | head`) ends it quietly, as Unix tools
    // end. Every other command writes files: it finishes them, and a closed stdout is then one
    // line on stderr and exit status 2 (`courant::cli::console`), never a silent 141.
    if matches!(command, Command::List { .. }) {
        courant::cli::exit_quietly_on_closed_pipe();
    }
    if let Err(message) = courant::cli::read_thread_setting() {
        courant::cli::console::err(format_args!("error: {message}\n"));
        return courant::cli::console::finish(ExitCode::from(2));
    }
    let code = match command {
        Command::List { scenes, schemes } => courant::cli::list(&scenes, schemes),
        Command::Run {
            scenes,
            out,
            exchange,
            large,
            force,
        } => {
            set_writer("courant run", force);
            courant::cli::run::run(
                &scenes,
                &out,
                exchange.as_deref(),
                if large {
                    courant::scene::limits::Limits::LARGE
                } else {
                    courant::scene::limits::Limits::DEFAULT
                },
            )
        }
        Command::Score {
            scene,
            results,
            require_all,
            stated,
            out,
            junit,
            force,
        } => {
            set_writer("courant score", force);
            courant::cli::score::score(
                &scene,
                &results,
                &courant::cli::score::Options {
                    require_all,
                    stated: stated.as_deref(),
                },
                out.as_deref(),
                junit.as_deref(),
            )
        }
        Command::Reference {
            scene,
            at,
            out,
            force,
        } => {
            set_writer("courant reference", force);
            courant::cli::reference::reference(&scene, at.as_deref(), &out)
        }
        Command::Report { scenes, out } => courant::cli::report(&scenes, out.as_deref()),
        Command::Check(options) => {
            // `check --out` writes what `run` writes (and may replace a run's output).
            set_writer("courant run", false);
            courant::cli::check::check(&options)
        }
        Command::Bench {
            sizes,
            node_steps,
            reps,
            out,
            no_c,
            no_schemes,
        } => courant::cli::bench::bench(&courant::cli::bench::BenchOptions {
            sizes,
            node_steps,
            reps,
            out,
            skip_c: no_c,
            skip_schemes: no_schemes,
        }),
    };
    // A failed write to the terminal turns the status into 2, with one line on stderr.
    courant::cli::console::finish(code)
}
