//! Source of truth: what each committed result set of another code states of itself
//! (`external/<code>/results/**/stated.toml`: the checks courant fails that code on), and the
//! half-step start those codes match once corrected (OpenSees' CentralDifference with F(0) =
//! F0/2, ExplicitDifference with a^0 = M^-1 F0/2: courant's central difference to round-off).
//!
//! Proves: every committed set scores as stated: the sets that state nothing (SfePy, OpenSees
//! corrected) fail no check, their signatures apply and their time level reads on time
//! wherever it is resolved; each as-it-comes OpenSees set fails exactly its stated checks, its
//! time level reads the start its integrator has (+1/2 for CentralDifference, -1/2 for
//! ExplicitDifference); and a statement that no longer holds fails the set.

use courant::compare::score::outcome::{SkipKind, Stated, StatedOutcome};
use courant::compare::score::time_level::{StartImpulse, TimeLevel};
use courant::pipeline::score::score_committed;
use courant::scene::builtin::all;

#[test]
fn every_committed_set_scores_as_it_states() {
    let scenes = all().unwrap();
    let sets = score_committed(&scenes).unwrap();
    assert!(
        sets.len() >= 32,
        "SfePy's 7 and OpenSees' 25 sets: {}",
        sets.len()
    );
    for (set, _, scored) in &sets {
        assert!(scored.passed(), "{} on {}", set.label, set.scene);
        let failing = scored
            .diagnostic_rows()
            .into_iter()
            .filter(|(_, row, _)| row.verdict == Some(false))
            .count()
            + scored.verdicts.iter().filter(|v| v.finding).count();
        match set.stated {
            None => {
                assert_eq!(failing, 0, "{} on {}", set.label, set.scene);
                assert!(
                    scored
                        .skipped
                        .iter()
                        .all(|s| s.kind != SkipKind::NotApplicable),
                    "{} on {} declares its scheme and mass: every signature applies",
                    set.label,
                    set.scene
                );
            }
            Some(_) => {
                assert_eq!(
                    failing,
                    scored.stated.len(),
                    "{} on {}: exactly the stated checks fail",
                    set.label,
                    set.scene
                );
                assert!(scored.stated.iter().all(|s| s.holds));
            }
        }
        let start = if set.label.ends_with("central-difference-as-it-comes") {
            StartImpulse::Extra
        } else if set.label.ends_with("explicit-difference-as-it-comes") {
            StartImpulse::Missing
        } else {
            StartImpulse::Right
        };
        for case in &scored.cases {
            if let Ok(TimeLevel::Read { steps, start: read }) =
                case.diagnostics.shift.as_ref().map(|s| s.level())
            {
                assert_eq!(
                    (steps, read),
                    (0, start),
                    "{} on {} {}",
                    set.label,
                    set.scene,
                    case.case
                );
            }
        }
    }
}

#[test]
fn a_statement_that_no_longer_holds_fails_the_set() {
    let scenes = all().unwrap();
    let sets = score_committed(&scenes).unwrap();
    let (_, _, corrected) = sets
        .iter()
        .find(|(set, _, _)| {
            set.label == "opensees central-difference-corrected" && set.scene == "fig1"
        })
        .unwrap();
    let mut scored = corrected.clone();
    assert!(scored.passed());
    scored.stated = vec![StatedOutcome {
        stated: Stated {
            case: "co1".into(),
            check: "time_level".into(),
            finding: "three-level start".into(),
        },
        holds: false,
    }];
    assert!(!scored.passed(), "a stated finding that passes fails");
}
