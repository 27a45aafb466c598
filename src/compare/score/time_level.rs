//! The time level of a file read from its time shift (`shift_fit`): on time, whole steps late
//! or early, or a start whose first step delivers the wrong impulse, each a class of the shift
//! `s` (in steps: the file holds the exact state of `t + s dt`). The classes, their causes and
//! fixes are in `super::diagnostics`.

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

#[cfg(test)]
mod tests {
    use super::*;

    fn level(steps: f64, residual: f64) -> TimeLevel {
        TimeShift {
            steps,
            residual,
            profiles: 1,
            spread: 0.0,
        }
        .level()
    }

    #[test]
    fn each_shift_is_read_as_its_class() {
        let read = |steps, start| TimeLevel::Read { steps, start };
        assert_eq!(level(0.02, 0.1), read(0, StartImpulse::Right));
        assert_eq!(level(-1.01, 0.1), read(-1, StartImpulse::Right));
        assert_eq!(level(2.0, 0.1), read(2, StartImpulse::Right));
        assert_eq!(level(0.47, 0.1), read(0, StartImpulse::Extra));
        assert_eq!(level(0.57, 0.1), read(0, StartImpulse::Extra));
        assert_eq!(level(-0.52, 0.1), read(0, StartImpulse::Missing));
        assert_eq!(level(-0.26, 0.1), read(0, StartImpulse::Half));
        assert_eq!(level(-1.25, 0.1), read(-1, StartImpulse::Half));
        assert_eq!(level(-1.5, 0.1), read(-1, StartImpulse::Missing));
        assert_eq!(level(0.2, 0.1), TimeLevel::Unexplained);
        assert_eq!(level(0.1, 0.9), TimeLevel::WholeStepsOnly { steps: 0 });
        assert_eq!(
            level(0.5, 0.5),
            TimeLevel::Read {
                steps: 0,
                start: StartImpulse::Extra
            }
        );
        assert_eq!(level(-0.95, 2.0), TimeLevel::WholeStepsOnly { steps: -1 });
        assert_eq!(level(0.5, 0.9), TimeLevel::Unexplained);
        assert_eq!(level(4.0, 0.1), TimeLevel::NotAShift);
        let drifting = TimeShift {
            steps: -0.19,
            residual: 0.43,
            profiles: 2,
            spread: 0.27,
        };
        assert_eq!(drifting.level(), TimeLevel::Drifting);
        assert_eq!(level(0.0, 3.5), TimeLevel::NotAShift);
    }
}
