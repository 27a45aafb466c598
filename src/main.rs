//! `courant`: list and run verification scenes.

use clap::{Parser, Subcommand};
use courant::builtin::{BUILTIN_SCENES, builtin_scene, resolve};
use courant::results::scene_files;
use courant::write::write_dir_atomically;
use courant::{CaseResult, Scene, SceneOutcome, Status, run_scene};
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
        tolerances: ToleranceArgs,
        /// Also write the result directories, as `courant run --out DIR` does.
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
    },
}

/// Baseline tolerances (only with --baseline); unset ones keep their defaults.
#[derive(clap::Args)]
struct ToleranceArgs {
    /// Relative tolerance of numeric columns: |a - b| <= max(ABS, REL |b|) [default 1e-9].
    #[arg(long, value_name = "REL", allow_negative_numbers = true)]
    rel: Option<f64>,
    /// Absolute floor of numeric columns [default 1e-12].
    #[arg(long, value_name = "ABS", allow_negative_numbers = true)]
    abs: Option<f64>,
    /// Relative tolerance of stress-profile columns, relative to the column's peak |b|
    /// [default 1e-9].
    #[arg(long, value_name = "REL", allow_negative_numbers = true)]
    peak_rel: Option<f64>,
    /// Absolute floor of stress-profile columns [default 1e-12].
    #[arg(long, value_name = "ABS", allow_negative_numbers = true)]
    peak_abs: Option<f64>,
    /// A rule for one column, ahead of every other rule (repeatable):
    /// COLUMN=ignore | exact | rel:REL[:ABS] | peak:REL[:ABS].
    #[arg(long = "column", value_name = "COLUMN=RULE")]
    columns: Vec<String>,
}

impl ToleranceArgs {
    /// The first tolerance flag given, with its value, if any.
    fn first_given(&self) -> Option<(&'static str, String)> {
        let numbers = [
            ("--rel", self.rel),
            ("--abs", self.abs),
            ("--peak-rel", self.peak_rel),
            ("--peak-abs", self.peak_abs),
        ];
        numbers
            .into_iter()
            .find_map(|(flag, v)| v.map(|v| (flag, v.to_string())))
            .or_else(|| self.columns.first().map(|c| ("--column", c.clone())))
    }

    /// The tolerances: the defaults with every given value checked and applied.
    fn tolerances(
        &self,
    ) -> Result<courant::baseline::Tolerances, courant::baseline::ToleranceError> {
        use courant::baseline::{ColumnRule, tolerance_value};
        let mut t = courant::baseline::Tolerances::default();
        let set = |flag, given: Option<f64>, value: &mut f64| {
            given
                .map(|v| tolerance_value(flag, v).map(|v| *value = v))
                .transpose()
        };
        set("--rel", self.rel, &mut t.rel)?;
        set("--abs", self.abs, &mut t.abs)?;
        set("--peak-rel", self.peak_rel, &mut t.peak_rel)?;
        set("--peak-abs", self.peak_abs, &mut t.peak_abs)?;
        for spec in &self.columns {
            t.overrides
                .push(ColumnRule::parse_override(spec, t.abs, t.peak_abs)?);
        }
        Ok(t)
    }
}

fn main() -> ExitCode {
    match Cli::parse().command {
        Command::List => list(),
        Command::Run { scenes, out } => run(&scenes, &out),
        Command::Report { out } => report(&out),
        Command::Check {
            scenes,
            junit,
            baseline,
            tolerances,
            out,
        } => check(
            &scenes,
            junit.as_deref(),
            baseline.as_deref(),
            &tolerances,
            out.as_deref(),
        ),
    }
}

fn check(
    args: &[String],
    junit: Option<&std::path::Path>,
    baseline: Option<&std::path::Path>,
    tolerance_args: &ToleranceArgs,
    out: Option<&std::path::Path>,
) -> ExitCode {
    use courant::check::{CheckReport, resolve_scenes};
    // Validate everything first: bad input writes nothing.
    let scenes = match resolve_scenes(args) {
        Ok(scenes) => scenes,
        Err(errors) => {
            for e in errors {
                eprintln!("error: {e}");
            }
            return ExitCode::from(2);
        }
    };
    if let Some(dir) = baseline.filter(|d| !d.is_dir()) {
        eprintln!("error: --baseline {}: not a directory", dir.display());
        return ExitCode::from(2);
    }
    if let (None, Some((flag, value))) = (baseline, tolerance_args.first_given()) {
        eprintln!(
            "error: {flag} {value:?}: a baseline tolerance needs --baseline DIR (--rel, --abs, --peak-rel, --peak-abs and --column only act on a baseline comparison)"
        );
        return ExitCode::from(2);
    }
    // A report baseline keeps figures and pages beside its scene tables: writing run output over
    // it would replace those scene directories.
    if let (Some(base), Some(out)) = (baseline, out)
        && courant::baseline::BaselineKind::detect(base) == courant::baseline::BaselineKind::Report
        && same_directory(base, out)
    {
        eprintln!(
            "error: --out {}: is the report baseline; run output would replace its scene directories (figures included). --out may name a run-output baseline only",
            out.display()
        );
        return ExitCode::from(2);
    }
    let tolerances = match tolerance_args.tolerances() {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(file) = junit.filter(|f| f.is_dir()) {
        eprintln!("error: --junit {}: is a directory", file.display());
        return ExitCode::from(2);
    }
    // Everything runs and is compared before anything is written (so --out may be a run-output
    // baseline).
    let report = match CheckReport::run(&scenes, baseline, tolerances) {
        Ok(report) => report,
        Err((scene, e)) => {
            eprintln!("error: {scene}: {e}");
            return ExitCode::from(2);
        }
    };
    let unmatched = report.unmatched_overrides();
    if !unmatched.is_empty() {
        eprintln!(
            "error: --column {}: no compared file has such a column; the rule would loosen nothing",
            unmatched.join(", --column ")
        );
        return ExitCode::from(2);
    }
    let counts = (report.expectation_counts(), report.baseline_counts());
    if counts.0.total == 0 && counts.1.total == 0 {
        eprintln!(
            "error: nothing to check: the scenes have no expectations and no --baseline was given"
        );
        return ExitCode::from(2);
    }
    print!("{}", report.render());
    if let Some(out) = out {
        for scene in &report.scenes {
            let dir = out.join(&scene.name);
            if let Err(e) = write_dir_atomically(&dir, &scene.files) {
                eprintln!("error: cannot write {}: {e}", dir.display());
                return ExitCode::from(2);
            }
            println!("  -> {}", dir.display());
        }
    }
    if let Some(file) = junit {
        if let Err(e) = courant::junit::write_atomically(file, &report.junit()) {
            eprintln!("error: cannot write {}: {e}", file.display());
            return ExitCode::from(2);
        }
        println!("  -> {}", file.display());
    }
    if report.passed() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// True when `a` and `b` name the same existing directory (or the same path, when `b` does not
/// exist yet).
fn same_directory(a: &std::path::Path, b: &std::path::Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => a == b,
    }
}

fn list() -> ExitCode {
    for (name, _) in BUILTIN_SCENES {
        match builtin_scene(name) {
            Some(Ok(scene)) => println!("{name:16} {}", scene.description),
            Some(Err(e)) => println!("{name:16} (invalid: {e})"),
            None => {}
        }
    }
    ExitCode::SUCCESS
}

fn run(args: &[String], out: &std::path::Path) -> ExitCode {
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
        let outcome = match run_scene(scene) {
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

fn report(out: &std::path::Path) -> ExitCode {
    let generated = courant::report::builtin_scenes().and_then(|scenes| {
        courant::report::generate(&scenes, courant::report::CONVERGENCE_STUDIES)
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

fn print_scene(scene: &Scene, outcome: &SceneOutcome) {
    println!("{}: {}", scene.name, scene.description);
    println!("  source: {}", scene.source);
    if !outcome.spectra.is_empty() {
        println!(
            "  {:<24} {:>7} {:>22} {:>10}",
            "case", "modes", "closed-form deviation", "wall [s]"
        );
        for s in &outcome.spectra {
            let deviation = s
                .closed_form_deviation()
                .map_or("-".to_string(), |d| format!("{d:.3e}"));
            println!(
                "  {:<24} {:>7} {:>22} {:>10.4}",
                s.case,
                s.modes.len(),
                deviation,
                s.wall_time.as_secs_f64()
            );
        }
    }
    if !outcome.dispersion.is_empty() {
        println!(
            "  {:<18} {:>10} {:>16} {:>12}",
            "case", "modes", "max deviation", "min order"
        );
        for d in &outcome.dispersion {
            let order = d.min_order().map_or("-".to_string(), |o| format!("{o:.3}"));
            println!(
                "  {:<18} {:>10} {:>16.3e} {:>12}",
                d.case.name,
                d.rows.len(),
                d.deviation(),
                order
            );
        }
    }
    if !outcome.contact.is_empty() {
        println!(
            "  {:<32} {:>8} {:>8} {:>10} {:>10} {:>10} {:>10} {:>10}  status",
            "case", "Co", "Co_crit", "plateau", "impulse", "duration", "force_l1", "energy"
        );
        for c in &outcome.contact {
            let status = match &c.diverged {
                None => "completed".to_string(),
                Some(d) => format!("DIVERGED: {d}"),
            };
            println!(
                "  {:<32} {:>8.4} {:>8.4} {:>10.3e} {:>10.3e} {:>10.3e} {:>10.3e} {:>10.4}  {status}",
                c.case,
                c.run.courant,
                c.run.critical.critical_courant(),
                c.plateau_deviation,
                c.impulse_error,
                c.duration_error,
                c.force_l1_error,
                c.energy_ratio
            );
        }
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

fn print_cases(results: &[CaseResult]) {
    if results.is_empty() {
        return;
    }
    println!(
        "  {:<10} {:>7} {:>8} {:>11} {:>8} {:>10} {:>10} {:>10} {:>9} {:>10} {:>10}  status",
        "case", "N", "Co", "dt", "steps", "L1", "L2", "Linf", "overshoot", "energy", "wall [s]"
    );
    for r in results {
        let n = r.worst_norms();
        let f = |x: Option<f64>| x.map_or("-".to_string(), |x| format!("{x:.3e}"));
        let status = match &r.status {
            Status::Completed => "completed".to_string(),
            Status::Diverged(d) => format!("DIVERGED: {d}"),
        };
        println!(
            "  {:<10} {:>7} {:>8.4} {:>11.4e} {:>8} {:>10} {:>10} {:>10} {:>9} {:>10.2e} {:>10.4}  {status}",
            r.case,
            r.elements,
            r.courant,
            r.dt,
            r.steps,
            f(n.map(|n| n.l1)),
            f(n.map(|n| n.l2)),
            f(n.map(|n| n.linf)),
            n.map_or("-".into(), |n| format!("{:.4}", n.overshoot)),
            r.energy.relative_balance_error(),
            r.wall_time.as_secs_f64(),
        );
    }
}
