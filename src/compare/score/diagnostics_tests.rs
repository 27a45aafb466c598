//! Unit tests of [`super`], kept beside it so that the module stays short.
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

#[test]
fn the_sign_is_decided_only_by_a_clear_margin() {
    let s = |error, error_flipped| {
        SignCheck {
            error,
            error_flipped,
        }
        .matches()
    };
    assert_eq!(s(0.05, 1.0), Some(true));
    assert_eq!(s(1.0, 0.05), Some(false));
    assert_eq!(s(1.0, 1.5), None);
}

#[test]
fn a_failing_row_says_direction_cause_and_fix() {
    let d = Diagnostics {
        magnitude: Ok(Magnitude {
            max: 1.0,
            scale: 1.0,
        }),
        shift: Ok(TimeShift {
            steps: -1.0,
            residual: 0.0,
            profiles: 2,
            spread: 0.0,
        }),
        sign: Err("-".into()),
        layout: Err("-".into()),
    };
    let [_, level, ..] = d.verdicts();
    assert_eq!(level.verdict, Some(false));
    assert!(
        level
            .note
            .starts_with("1 step late: the values labelled t are those of t - 1 dt")
    );
    let m = Magnitude {
        max: 1e125,
        scale: 1.0,
    };
    assert!(m.diverged());
    assert!(
        Magnitude {
            max: f64::NAN,
            scale: 1.0
        }
        .diverged()
    );
}
