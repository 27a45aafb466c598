//! Findings stated for a committed result set of another code: the checks courant fails that
//! code on, each with what it means (`stated.toml` beside the set's files). A stated check that
//! fails counts as a finding of that code, not as a failure of courant's; a stated check that
//! no longer fails, and any failure not stated, is a failure: CI then fails only when a verdict
//! differs from what is stated.
//!
//! ```toml
//! [[finding]]
//! case = "co1"
//! check = "time_level"   # an expectation's metric label (`linf`) or a diagnostic's name
//! finding = "the first step carries F0 dt/2 too much impulse (three-level start)"
//! ```

use super::outcome::{ScoredSet, Stated, StatedOutcome};
use serde::Deserialize;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StatedFile {
    #[serde(default)]
    finding: Vec<Stated>,
}

/// Read `stated.toml` (`file` names it in messages).
///
/// # Errors
/// TOML that does not parse or has an unknown key, with the parser's message.
pub fn parse(file: &str, text: &str) -> Result<Vec<Stated>, String> {
    toml::from_str::<StatedFile>(text)
        .map(|f| f.finding)
        .map_err(|e| format!("{file}: {}", e.message().trim()))
}

/// Mark the set's stated checks: an expectation verdict that fails and is stated becomes a
/// finding (it passes, counted as a finding); a diagnostic that fails and is stated is counted
/// as a finding by [`ScoredSet::diagnostic_is_stated`]. Every stated finding is kept with whether
/// it holds.
pub fn apply(set: &mut ScoredSet, stated: Vec<Stated>) {
    let mut outcomes = Vec::new();
    for s in stated {
        let mut holds = false;
        for v in &mut set.verdicts {
            if v.case == s.case && v.metric_label() == s.check && !v.pass {
                v.pass = true;
                v.finding = true;
                holds = true;
            }
        }
        for c in set.cases.iter().filter(|c| c.case == s.case) {
            holds |= c
                .diagnostics
                .verdicts()
                .iter()
                .any(|r| r.name == s.check && r.verdict == Some(false));
        }
        outcomes.push(StatedOutcome { stated: s, holds });
    }
    set.stated = outcomes;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stated_file_reads_and_refuses_unknown_keys() {
        let s = parse(
            "stated.toml",
            "[[finding]]\ncase = \"co1\"\ncheck = \"linf\"\nfinding = \"checkerboard\"\n",
        )
        .unwrap();
        assert_eq!(s[0].check, "linf");
        let e = parse("stated.toml", "[[finding]]\ncase = \"co1\"\nchek = \"x\"\n").unwrap_err();
        assert!(e.contains("chek"), "{e}");
    }
}
