//! `courant check`: validate the arguments, run the checks, print them, write what was asked.

use crate::check::baseline::kind::BaselineKind;
use crate::check::gate::CheckReport;
use crate::check::junit_report::xml;
use crate::check::render::terminal;
use crate::io::atomic::write_dir_atomically;
use crate::io::owned_file::{JUNIT, check_file_replaceable, write_owned_file};
use crate::scene::builtin::resolve_all;
use crate::scene::studies::convergence::{CONVERGENCE_STUDIES, ConvergenceStudy};
use std::path::PathBuf;
use std::process::ExitCode;

/// Baseline tolerances (only with --baseline); unset ones keep their defaults.
#[derive(clap::Args)]
pub struct ToleranceOptions {
    /// Relative tolerance of numeric columns: |a - b| <= max(ABS, REL |b|) [default 1e-9].
    #[arg(long, value_name = "REL", allow_negative_numbers = true)]
    pub rel: Option<f64>,
    /// Absolute floor of numeric columns [default 1e-12].
    #[arg(long, value_name = "ABS", allow_negative_numbers = true)]
    pub abs: Option<f64>,
    /// Relative tolerance of stress-profile columns, relative to the column's peak |b|
    /// [default 1e-9].
    #[arg(long, value_name = "REL", allow_negative_numbers = true)]
    pub peak_rel: Option<f64>,
    /// Absolute floor of stress-profile columns [default 1e-12].
    #[arg(long, value_name = "ABS", allow_negative_numbers = true)]
    pub peak_abs: Option<f64>,
    /// A rule for one column, ahead of every other rule (repeatable):
    /// `COLUMN=ignore | exact | rel:REL[:ABS] | peak:REL[:ABS]`.
    #[arg(long = "column", value_name = "COLUMN=RULE")]
    pub columns: Vec<String>,
}

impl ToleranceOptions {
    /// The first tolerance flag given, with its value, if any.
    pub fn first_given(&self) -> Option<(&'static str, String)> {
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
    pub fn tolerances(
        &self,
    ) -> Result<
        crate::check::baseline::tolerance::Tolerances,
        crate::check::baseline::tolerance::ToleranceError,
    > {
        use crate::check::baseline::tolerance::{ColumnRule, tolerance_value};
        let mut t = crate::check::baseline::tolerance::Tolerances::default();
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

/// The options of `courant check`.
#[derive(clap::Args)]
pub struct CheckOptions {
    /// Scene names or paths (every built-in scene and the convergence studies when none given).
    pub scenes: Vec<String>,
    /// Write a JUnit XML report here (one testsuite per scene or study, one testcase per check).
    #[arg(long, value_name = "FILE")]
    pub junit: Option<PathBuf>,
    /// Compare the fresh CSVs with a previous report (`courant report --out DIR`, e.g. the
    /// committed `reports/`: each scene's tables) or a previous `courant run --out DIR`
    /// (every result file), DIR/<scene>/*.csv.
    #[arg(long, value_name = "DIR")]
    pub baseline: Option<PathBuf>,
    #[command(flatten)]
    pub tolerances: ToleranceOptions,
    /// Also write the result directories, as `courant run --out DIR` does.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Print every verdict with its measured value, bound and source, and every changed
    /// baseline column.
    #[arg(long, short)]
    pub verbose: bool,
}

/// `courant check`.
pub fn check(options: &CheckOptions) -> ExitCode {
    let args = &options.scenes;
    let junit = options.junit.as_deref();
    let baseline = options.baseline.as_deref();
    let tolerance_args = &options.tolerances;
    let out = options.out.as_deref();
    let studies: &[ConvergenceStudy] = if args.is_empty() {
        CONVERGENCE_STUDIES
    } else {
        &[]
    };
    // Validate everything first: bad input writes nothing.
    let scenes = match resolve_all(args) {
        Ok(scenes) => scenes,
        Err(errors) => {
            for e in errors {
                errln!("error: {e}");
            }
            return ExitCode::from(2);
        }
    };
    if let Some(dir) = baseline.filter(|d| !d.is_dir()) {
        errln!("error: --baseline {}: not a directory", dir.display());
        return ExitCode::from(2);
    }
    if let (None, Some((flag, value))) = (baseline, tolerance_args.first_given()) {
        errln!(
            "error: {flag} {value:?}: a baseline tolerance needs --baseline DIR (--rel, --abs, --peak-rel, --peak-abs and --column only act on a baseline comparison)"
        );
        return ExitCode::from(2);
    }
    // A report baseline keeps figures and pages beside its scene tables: writing run output over
    // it would replace those scene directories.
    if let (Some(base), Some(out)) = (baseline, out)
        && BaselineKind::detect(base) == BaselineKind::Report
        && same_directory(base, out)
    {
        errln!(
            "error: --out {}: is the report baseline; run output would replace its scene directories (figures included). --out may name a run-output baseline only",
            out.display()
        );
        return ExitCode::from(2);
    }
    if let Some(out) = out {
        for scene in &scenes {
            if let Err(e) = crate::io::manifest::check_replaceable(&out.join(&scene.name)) {
                errln!("error: --out {}: {e}", out.display());
                return ExitCode::from(2);
            }
        }
    }
    let tolerances = match tolerance_args.tolerances() {
        Ok(t) => t,
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
    // Everything runs and is compared before anything is written (so --out may be a run-output
    // baseline).
    let report = match CheckReport::run(&scenes, studies, baseline, tolerances) {
        Ok(report) => report,
        Err((scene, e)) => {
            errln!("error: {scene}: {e}");
            return ExitCode::from(2);
        }
    };
    let unmatched = report.unmatched_overrides();
    if !unmatched.is_empty() {
        errln!(
            "error: --column {}: no compared file has such a column; the rule would loosen nothing",
            unmatched.join(", --column ")
        );
        return ExitCode::from(2);
    }
    let counts = (report.expectation_counts(), report.baseline_counts());
    if counts.0.total == 0 && counts.1.total == 0 {
        errln!(
            "error: nothing to check: the scenes have no expectations and no --baseline was given"
        );
        return ExitCode::from(2);
    }
    out!("{}", terminal(&report, options.verbose));
    if let Some(out) = out {
        for scene in &report.scenes {
            let dir = out.join(&scene.name);
            if let Err(e) = write_dir_atomically(&dir, &scene.files) {
                errln!("error: {}", super::write_failure(&dir, &e));
                return ExitCode::from(2);
            }
            outln!("  -> {}", dir.display());
        }
    }
    if let Some(file) = junit {
        if let Err(e) = write_owned_file(file, &xml(&report), JUNIT) {
            errln!("error: cannot write --junit {e}");
            return ExitCode::from(2);
        }
        outln!("  -> {}", file.display());
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
