//! The stability verdict of every case of a stability scene, as verdicts beside the scene's
//! expectations: the run against what theory predicts for its step
//! ([`StabilityRow::verdict`]: a disagreement fails unless the scene states it as a finding).

use super::stability::StabilityRow;
use super::verdict::{Measured, Verdict};
use crate::scene::expectation::{Bound, Metric};

/// One verdict per row that carries a prediction or a stated finding.
pub fn stability_verdicts(rows: &[StabilityRow]) -> Vec<Verdict> {
    rows.iter()
        .filter_map(|row| {
            let (pass, finding, source) = row.verdict()?;
            Some(Verdict {
                case: row.case.clone(),
                metric: Metric::Stability,
                at: None,
                relative_to: None,
                masses: None,
                force: None,
                measured: Measured::Text(row.observed()),
                bound: Bound::Theory(row.predicted),
                pass,
                finding,
                source,
            })
        })
        .collect()
}
