//! Diagnostics of a result file, each with its own verdict and, where it fails, the usual cause
//! and the fix: the magnitude (a diverged code), the time level (a file written at the wrong
//! time, or a start that gives the first step the wrong impulse), the sign convention (tension
//! positive) and the layout (a bar written from its far end, nodal averages given as points).
//!
//! **Time level.** The file's profiles are compared with the exact solution at shifted times:
//! the shift `s` (real, in steps of the file's `dt`) is the one that makes the exact solution at
//! `t + s dt` fit the file best (`shift_fit`), so `s < 0` means the file holds an older state
//! than its label says (late), `s > 0` a newer one (early). A linear step-loaded model whose
//! first step delivers the impulse `(1 + 2a) F0 dt / 2` instead of `F0 dt / 2` (the half-step
//! start with H(0) = 1, courant's convention, methods.md §2) runs ahead of the exact
//! solution by `a` steps for ever after, so the fractional part of `s` names the start:
//!
//! | `s` | class | usual cause | fix |
//! |---|---|---|---|
//! | 0 | on time | | |
//! | k (whole, not 0) | k steps late/early | the file's times are labelled k dt off (e.g. written before the step's update) | write the state of `t^n = n dt` labelled `t^n` |
//! | +1/2 | extra start impulse | a three-level start (`u^-1 = u^0`) with the full F(0), as OpenSees' `CentralDifference`: the first step gives `u^1 = dt^2 M^-1 F0` | use F(0) = F0/2 in the first step |
//! | -1/2 | no start impulse | H(0) = 0, or a^0 = 0 (as OpenSees' `ExplicitDifference`) | H(0) = 1 with the half-step start, or a^0 = M^-1 F0 / 2 |
//! | -1/4 | half start impulse | H(0) = 1/2 with the half-step start | H(0) = 1 |
//!
//! and their sums (`-1.25`: one step late and H(0) = 1/2). A class is read when the fit
//! explains the file as a shift: residual `r <= RESOLVED` for the fractions, `r <=
//! MAX_RESIDUAL` for whole steps only, and within [`MATCH`] steps of the class; otherwise the
//! shift is reported without a verdict. Dispersion leaves a residual (lumped central difference
//! on the Fig. 1 bar: `r` about 0.3 at Co = 0.5, 1 to 2 at Co = 0.1), which is why the fractions
//! need `r` small.
//!
//! **Sign** and **layout.** The L1 error of the file against the reference and those of the
//! file negated and mirrored (`x -> start + end - x`): the file's form is the one whose error is
//! below half of the negated one (the sign) or two thirds of the one as given (the layout). For point files, exact nodal averages (the mean of the two exact
//! element averages beside each point) are tried too: a code that averages its element stresses
//! to the nodes is told so (its front reads half a jump off the point values it is graded
//! against).
//!
//! **Magnitude.** A file whose largest `|stress|` exceeds [`DIVERGED`] times the load's scale
//! `|sigma0|` diverged; the other diagnostics are not measured on it.

/// Largest residual `r` (steps) with which the fractional part of a shift is read.
pub const RESOLVED: f64 = 0.75;

/// Largest `|s|` (steps) read as a time-level shift.
pub const MAX_OFFSET: f64 = 2.5;

/// Largest residual `r` (steps) with which a shift is read at all (whole steps only above
/// [`RESOLVED`]).
pub const MAX_RESIDUAL: f64 = 3.0;

/// How close (steps) a shift must be to a class to be read as it: half the distance between
/// the nearest classes (-1/4 and -1/2).
pub const MATCH: f64 = 0.125;

/// Largest difference (steps) between single profiles' shifts with which a fraction is read:
/// a start's impulse shifts every later profile alike, a scheme's phase error grows with time
/// (Park's local stepping on the Fig. 2 graded bar: 0.16 and 0.27 steps between t = 0.5 and 1.5
/// transits, measured here, against at most 0.02 for a start error at Co = 1 and 0.5).
pub const SPREAD: f64 = 0.1;

/// As [`SPREAD`], for a shift read in whole steps.
pub const SPREAD_WHOLE: f64 = 0.5;

/// Largest `|stress| / |sigma0|` of a file that has not diverged.
pub const DIVERGED: f64 = 1e3;

/// What the first step's impulse says of the start, from the fractional part of the shift.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StartImpulse {
    /// `F0 dt / 2`: the half-step start with H(0) = 1.
    Right,
    /// `F0 dt`: `F0 dt / 2` too much (shift +1/2).
    Extra,
    /// None (shift -1/2).
    Missing,
    /// `F0 dt / 4`: half of it (shift -1/4).
    Half,
}

impl StartImpulse {
    /// The shift (steps) this start gives.
    pub fn shift(self) -> f64 {
        match self {
            StartImpulse::Right => 0.0,
            StartImpulse::Extra => 0.5,
            StartImpulse::Missing => -0.5,
            StartImpulse::Half => -0.25,
        }
    }

    /// The cause and the fix, as a diagnostic says them.
    pub fn words(self) -> &'static str {
        match self {
            StartImpulse::Right => "the first step's impulse is right",
            StartImpulse::Extra => {
                "the first step carries F0 dt/2 too much impulse: a three-level start (u^-1 = u^0) with the full F(0), as OpenSees' CentralDifference; use F(0) = F0/2 in the first step"
            }
            StartImpulse::Missing => {
                "no impulse at t = 0: H(0) = 0, or a^0 = 0 (as OpenSees' ExplicitDifference); use H(0) = 1 with the half-step start, or a^0 = M^-1 F0/2"
            }
            StartImpulse::Half => {
                "the first-step impulse is half of it: H(0) = 1/2 with a half-step start; use H(0) = 1"
            }
        }
    }
}

/// What a time shift is read as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TimeLevel {
    /// Whole steps off (0: on time) and the start's impulse.
    Read {
        /// Whole steps: negative late, positive early.
        steps: i64,
        /// The start, from the fraction.
        start: StartImpulse,
    },
    /// Whole steps only: the fraction is not resolved (residual above [`RESOLVED`]).
    WholeStepsOnly {
        /// Whole steps: negative late, positive early.
        steps: i64,
    },
    /// No class within [`MATCH`] of the shift.
    Unexplained,
    /// The profiles' own shifts differ by more than [`SPREAD`] (whole steps: [`SPREAD_WHOLE`]):
    /// a phase error of the scheme, not a timing.
    Drifting,
    /// The error is not a shift of a few steps (beyond [`MAX_OFFSET`] or [`MAX_RESIDUAL`]).
    NotAShift,
}

/// The time shift of a file, in steps of its `dt`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeShift {
    /// The shift `s` (steps) that fits the file best: the file holds the exact state of
    /// `t + s dt`.
    pub steps: f64,
    /// The residual `r`: the part of the error no shift explains, in steps.
    pub residual: f64,
    /// Profiles the shift was fitted on.
    pub profiles: usize,
    /// Largest difference between the shifts of single profiles (steps).
    pub spread: f64,
}

impl TimeShift {
    /// Whole steps nearest to the shift.
    pub fn offset(&self) -> i64 {
        self.steps.round() as i64
    }

    /// The class of the shift.
    pub fn level(&self) -> TimeLevel {
        let (s, r) = (self.steps, self.residual);
        if !(s.abs() <= MAX_OFFSET && r <= MAX_RESIDUAL) {
            return TimeLevel::NotAShift;
        }
        if r > RESOLVED {
            let steps = s.round();
            return if (s - steps).abs() > 2.0 * MATCH {
                TimeLevel::Unexplained
            } else if steps != 0.0 && self.spread > SPREAD_WHOLE {
                TimeLevel::Drifting
            } else {
                TimeLevel::WholeStepsOnly {
                    steps: steps as i64,
                }
            };
        }
        // Candidates k + f, nearest first; on a tie the smaller |k| (+1/2 rather than 1 - 1/2).
        let starts = [
            StartImpulse::Right,
            StartImpulse::Extra,
            StartImpulse::Missing,
            StartImpulse::Half,
        ];
        let mut best: Option<(f64, i64, StartImpulse)> = None;
        for start in starts {
            let k = (s - start.shift()).round();
            let distance = (s - k - start.shift()).abs();
            let better = best.is_none_or(|(d, bk, _)| {
                distance < d - 1e-12 || (distance <= d + 1e-12 && (k as i64).abs() < bk.abs())
            });
            if better {
                best = Some((distance, k as i64, start));
            }
        }
        let Some((distance, steps, start)) = best else {
            return TimeLevel::Unexplained;
        };
        let limit = if start == StartImpulse::Right {
            SPREAD_WHOLE
        } else {
            SPREAD
        };
        let on_time = steps == 0 && start == StartImpulse::Right;
        match (distance <= MATCH, on_time) {
            (true, true) => TimeLevel::Read { steps, start },
            (true, false) if self.spread <= limit => TimeLevel::Read { steps, start },
            (false, _) if self.spread <= SPREAD => TimeLevel::Unexplained,
            _ => TimeLevel::Drifting,
        }
    }
}

/// `k step(s) late` / `early`, with what it means.
fn whole_steps(k: i64) -> String {
    let n = k.unsigned_abs();
    let plural = if n == 1 { "" } else { "s" };
    if k < 0 {
        format!(
            "{n} step{plural} late: the values labelled t are those of t - {n} dt (the file's times are labelled {n} dt off; write the state of t^n = n dt labelled t^n)"
        )
    } else {
        format!(
            "{n} step{plural} early: the values labelled t are those of t + {n} dt (the file's times are labelled {n} dt off; write the state of t^n = n dt labelled t^n)"
        )
    }
}

/// The L1 errors of the file, negated, mirrored and (points) as nodal averages, against the
/// reference.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SignCheck {
    /// Error of the file as given.
    pub error: f64,
    /// Error of the negated file.
    pub error_flipped: f64,
}

impl SignCheck {
    /// `Some(true)`: the file's sign is the reference's; `Some(false)`: flipped; `None`: the two
    /// errors are within a factor 2.
    pub fn matches(&self) -> Option<bool> {
        if self.error < 0.5 * self.error_flipped {
            Some(true)
        } else if self.error > 2.0 * self.error_flipped {
            Some(false)
        } else {
            None
        }
    }
}

/// How the file lays its values out on the bar, as read from its errors.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layout {
    /// As the format says: x from the loaded end (the bar's start), element averages or point
    /// values.
    AsGiven,
    /// `x` runs from the far end: the values at `x` are those of `start + end - x`.
    Mirrored,
    /// Point values that are nodal averages of element values.
    NodalAverages,
}

/// The layout and the errors it was read from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LayoutCheck {
    /// The layout.
    pub layout: Layout,
    /// L1 error as given.
    pub error: f64,
    /// L1 error of the layout read (equal to `error` when as given).
    pub error_read: f64,
}

/// The largest stress of a file against the load's scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Magnitude {
    /// `max |stress|` over the file.
    pub max: f64,
    /// The load's scale `|sigma0|`.
    pub scale: f64,
}

impl Magnitude {
    /// True when `max |stress|` exceeds [`DIVERGED`] `|sigma0|` (or is not a number).
    pub fn diverged(&self) -> bool {
        !matches!(
            self.max.partial_cmp(&(DIVERGED * self.scale)),
            Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
        )
    }
}

/// The diagnostics of one case file; `Err` says why one is not measured.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostics {
    /// Largest stress against the load's scale.
    pub magnitude: Result<Magnitude, String>,
    /// Time shift.
    pub shift: Result<TimeShift, String>,
    /// Sign.
    pub sign: Result<SignCheck, String>,
    /// Layout on the bar.
    pub layout: Result<LayoutCheck, String>,
}

/// One diagnostic as a check: name, verdict (`None`: measured only or not measurable), what was
/// measured, what is expected, and a note (the cause and the fix where it fails).
#[derive(Debug, Clone, PartialEq)]
pub struct DiagnosticRow {
    /// `magnitude`, `time_level`, `sign` or `layout`.
    pub name: &'static str,
    /// `Some(pass)`, or `None` when not judged.
    pub verdict: Option<bool>,
    /// What was read.
    pub measured: String,
    /// What a correct file reads.
    pub expected: &'static str,
    /// Why, and what to do.
    pub note: String,
}

impl DiagnosticRow {
    fn new(
        name: &'static str,
        verdict: Option<bool>,
        measured: impl Into<String>,
        expected: &'static str,
        note: impl Into<String>,
    ) -> Self {
        Self {
            name,
            verdict,
            measured: measured.into(),
            expected,
            note: note.into(),
        }
    }
}

impl Diagnostics {
    /// Nothing measurable, for the same reason each.
    pub fn none(why: &str) -> Self {
        Self {
            magnitude: Err(why.into()),
            shift: Err(why.into()),
            sign: Err(why.into()),
            layout: Err(why.into()),
        }
    }

    /// `magnitude`, `time_level`, `sign`, `layout` as checks.
    pub fn verdicts(&self) -> [DiagnosticRow; 4] {
        let magnitude = match &self.magnitude {
            Ok(m) if m.diverged() => DiagnosticRow::new(
                "magnitude",
                Some(false),
                format!("{:.3e}", m.max / m.scale),
                "<= 1e3 |sigma0|",
                format!(
                    "the code diverged: max |stress| = {:.3e}, {:.1e} times the load's scale |sigma0| = {}; reduce the step below the scheme's limit (the other diagnostics are not measured)",
                    m.max,
                    m.max / m.scale,
                    m.scale
                ),
            ),
            Ok(m) => DiagnosticRow::new(
                "magnitude",
                Some(true),
                format!("{:.3e}", m.max / m.scale),
                "<= 1e3 |sigma0|",
                format!("max |stress| / |sigma0| = {:.3e}", m.max / m.scale),
            ),
            Err(why) => DiagnosticRow::new("magnitude", None, "-", "<= 1e3 |sigma0|", why.clone()),
        };
        let expected = "on time";
        let shift = match &self.shift {
            Err(why) => DiagnosticRow::new("time_level", None, "-", expected, why.clone()),
            Ok(s) => {
                let fit = format!(
                    "best shift {:+.3} steps (residual {:.2}, spread {:.2}) over {} profile(s)",
                    s.steps, s.residual, s.spread, s.profiles
                );
                match s.level() {
                    TimeLevel::Read {
                        steps: 0,
                        start: StartImpulse::Right,
                    } => DiagnosticRow::new("time_level", Some(true), "on time", expected, fit),
                    TimeLevel::Read { steps, start } => {
                        let mut why = Vec::new();
                        if steps != 0 {
                            why.push(whole_steps(steps));
                        }
                        if start != StartImpulse::Right {
                            why.push(start.words().to_string());
                        }
                        DiagnosticRow::new(
                            "time_level",
                            Some(false),
                            format!("{:+.2} steps", s.steps),
                            expected,
                            format!("{}; {fit}", why.join("; and ")),
                        )
                    }
                    TimeLevel::WholeStepsOnly { steps: 0 } => DiagnosticRow::new(
                        "time_level",
                        Some(true),
                        "on time (to a step)",
                        expected,
                        format!(
                            "{fit}: within a quarter step of 0, the fraction not resolved (residual above {RESOLVED})"
                        ),
                    ),
                    TimeLevel::WholeStepsOnly { steps } => DiagnosticRow::new(
                        "time_level",
                        Some(false),
                        format!("{steps:+} steps"),
                        expected,
                        format!(
                            "{}; {fit} (the fraction not resolved: residual above {RESOLVED})",
                            whole_steps(steps)
                        ),
                    ),
                    TimeLevel::Unexplained => DiagnosticRow::new(
                        "time_level",
                        None,
                        format!("{:+.2} steps", s.steps),
                        expected,
                        format!(
                            "a shift no known convention explains (whole steps, +1/2, -1/2, -1/4, each within {MATCH}); {fit}"
                        ),
                    ),
                    TimeLevel::Drifting => DiagnosticRow::new(
                        "time_level",
                        None,
                        format!("{:+.2} steps", s.steps),
                        expected,
                        format!(
                            "the profiles' own shifts differ by {:.2} steps: a phase error of the scheme grows with time, a timing or start error shifts every profile alike; no verdict ({fit})",
                            s.spread
                        ),
                    ),
                    TimeLevel::NotAShift => DiagnosticRow::new(
                        "time_level",
                        None,
                        "-",
                        expected,
                        format!(
                            "not a time-level shift: {fit} (a shift is read within {MAX_OFFSET} steps and residual {MAX_RESIDUAL}); the file differs from the reference by more than its timing"
                        ),
                    ),
                }
            }
        };
        let sign = match &self.sign {
            Ok(s) => DiagnosticRow::new(
                "sign",
                s.matches(),
                match s.matches() {
                    Some(true) => "tension positive",
                    Some(false) => "flipped",
                    None => "undecided",
                },
                "tension positive",
                match s.matches() {
                    Some(false) => format!(
                        "the file's stresses are negated (compression positive): L1 error {:.3e} as given, {:.3e} negated; write tension positive",
                        s.error, s.error_flipped
                    ),
                    _ => format!(
                        "L1 error {:.3e} as given, {:.3e} negated",
                        s.error, s.error_flipped
                    ),
                },
            ),
            Err(why) => DiagnosticRow::new("sign", None, "-", "tension positive", why.clone()),
        };
        let expected = "as given";
        let layout = match &self.layout {
            Ok(l) => match l.layout {
                Layout::AsGiven => DiagnosticRow::new(
                    "layout",
                    Some(true),
                    expected,
                    expected,
                    format!("L1 error {:.3e}", l.error),
                ),
                Layout::Mirrored => DiagnosticRow::new(
                    "layout",
                    Some(false),
                    "mirrored",
                    expected,
                    format!(
                        "the bar is mirrored: x runs from the far end (L1 error {:.3e} as given, {:.3e} with x -> L - x); write x from the loaded end",
                        l.error, l.error_read
                    ),
                ),
                Layout::NodalAverages => DiagnosticRow::new(
                    "layout",
                    None,
                    "nodal averages",
                    expected,
                    format!(
                        "point values that are nodal averages of element values (L1 error {:.3e} against exact point values, {:.3e} against exact nodal averages): a front then reads half a jump off; write element values (t, x_left, x_right, stress) to be graded as element averages",
                        l.error, l.error_read
                    ),
                ),
            },
            Err(why) => DiagnosticRow::new("layout", None, "-", expected, why.clone()),
        };
        [magnitude, shift, sign, layout]
    }
}

#[cfg(test)]
#[path = "diagnostics_tests.rs"]
mod tests;
