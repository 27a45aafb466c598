//! Verdicts counted: what the report's headline and summary table say, and what its exit status
//! follows.

use crate::compare::convergence::ConvergenceResult;
use crate::compare::outcome::SceneOutcome;
use crate::compare::verdict::Verdict;

/// Verdicts counted.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Tally {
    /// Passed (findings not included).
    pub passed: usize,
    /// Disagreements with stability theory or with a claim of the seed that the scenes state,
    /// with their sources.
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
        Tally::of_verdicts(&outcome.verdicts)
    }

    /// Expectation verdicts: a pass that is a stated finding counts as a finding.
    pub fn of_verdicts(verdicts: &[Verdict]) -> Self {
        let mut t = Tally::default();
        for v in verdicts {
            match (v.pass, v.finding) {
                (true, true) => t.findings += 1,
                (true, false) => t.passed += 1,
                (false, _) => t.failed += 1,
            }
        }
        t
    }

    /// Checks that may decide nothing (`None`: no verdict, not counted).
    pub fn of_decisions(decisions: impl IntoIterator<Item = Option<bool>>) -> Self {
        let mut t = Tally::default();
        for pass in decisions {
            match pass {
                Some(true) => t.passed += 1,
                Some(false) => t.failed += 1,
                None => {}
            }
        }
        t
    }

    /// The order verdicts of a convergence study (norms with a band).
    pub fn of_study(study: &ConvergenceResult) -> Self {
        Tally::of_decisions(study.verdicts().into_iter().map(|v| v.pass))
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
