//! Verdicts counted: what the report's headline and summary table say, and what its exit status
//! follows.

use crate::compare::convergence::ConvergenceResult;
use crate::compare::outcome::SceneOutcome;

/// Verdicts counted.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Tally {
    /// Passed (findings not included).
    pub passed: usize,
    /// Disagreements with stability theory the scenes state, with their sources.
    pub findings: usize,
    /// Failed.
    pub failed: usize,
}

impl Tally {
    /// Every verdict.
    pub fn total(self) -> usize {
        self.passed + self.findings + self.failed
    }

    /// Add another count.
    pub fn add(&mut self, other: Tally) {
        self.passed += other.passed;
        self.findings += other.findings;
        self.failed += other.failed;
    }

    /// The verdicts of a scene.
    pub fn of_scene(outcome: &SceneOutcome) -> Self {
        let mut t = Tally::default();
        for v in &outcome.verdicts {
            match (v.pass, v.finding) {
                (true, true) => t.findings += 1,
                (true, false) => t.passed += 1,
                (false, _) => t.failed += 1,
            }
        }
        t
    }

    /// The order verdicts of a convergence study (norms with a band).
    pub fn of_study(study: &ConvergenceResult) -> Self {
        let mut t = Tally::default();
        for v in study.verdicts() {
            match v.pass {
                Some(true) => t.passed += 1,
                Some(false) => t.failed += 1,
                None => {}
            }
        }
        t
    }
}

/// Every verdict of the scenes and studies, counted.
pub fn tally(outcomes: &[(SceneOutcome, f64)], convergence: &[ConvergenceResult]) -> Tally {
    let mut total = Tally::default();
    outcomes
        .iter()
        .for_each(|(o, _)| total.add(Tally::of_scene(o)));
    convergence
        .iter()
        .for_each(|c| total.add(Tally::of_study(c)));
    total
}
