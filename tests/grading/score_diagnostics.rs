//! Source of truth: the time levels and load convention of central difference (methods.md §1-2:
//! `sigma^n` lives at `t^n = n dt`, the step load has H(0) = 1 with the half-step start, tension
//! is positive) and what follows from them for a linear step-loaded model: a first step that
//! delivers the impulse `h0 F0 dt / 2` instead of `F0 dt / 2` runs ahead of the exact solution by
//! `(h0 - 1)/2` steps ever after; a file written one step late lags it by one step.
//!
//! ```text
//!   the file at t holds the exact state of t + s dt:
//!     s = 0     on time                 s = -1   one step late (labelled dt off)
//!     s = +1/2  h0 = 2: three-level start with the full F(0) (OpenSees CentralDifference)
//!     s = -1/2  h0 = 0: no impulse at t = 0 (a^0 = 0, OpenSees ExplicitDifference)
//!     s = -1/4  h0 = 1/2: H(0) = 1/2
//! ```
//!
//! Proves, on result sets made from courant's own runs of the Fig. 1 scenes with each start
//! (`value_at_start = h0`), written as element averages, as midpoint values and as nodal
//! averages, and on the real SfePy set read back after `pb.solve()`: each class is read with its
//! direction, cause and fix wherever dispersion leaves the shift resolved (Co = 1 and 0.5), and
//! no verdict is claimed where it does not (Co = 0.1); both file forms give the same shift; a
//! flipped sign, a mirrored bar, nodal averages and a diverged code are each named; courant's own
//! export passes every diagnostic; a scheme's phase error (Park's local stepping on the graded
//! bar) is no timing verdict; a contact force history gets a sign verdict and its shift as a
//! number only.

use crate::exchange;

use courant::compare::score::answers::exact_set;
use courant::compare::score::diagnostics::{DiagnosticRow, Diagnostics, Layout};
use courant::compare::score::outcome::{ScoredCase, ScoredSet};
use courant::compare::score::set::score_set;
use courant::compare::score::time_level::{StartImpulse, TimeLevel};
use courant::results::exchange::files::read_dir;
use courant::results::exchange::record::{CaseData, ExchangeSet};
use exchange::{
    PointForm, as_points, courant_set, mirrored, one_step_late, scaled, scene, sign_flipped,
    with_start_value,
};
use std::path::Path;

fn scored(scene_name: &str, set: &ExchangeSet) -> ScoredSet {
    score_set(&scene(scene_name), set).unwrap()
}

fn case<'a>(set: &'a ScoredSet, name: &str) -> &'a ScoredCase {
    set.cases.iter().find(|c| c.case == name).unwrap()
}

fn level(d: &Diagnostics) -> Option<TimeLevel> {
    d.shift.as_ref().ok().map(|s| s.level())
}

fn row(d: &Diagnostics, name: &str) -> DiagnosticRow {
    d.verdicts().into_iter().find(|r| r.name == name).unwrap()
}

/// The three forms of one set: element averages, midpoint values, nodal averages.
fn forms(set: &ExchangeSet) -> [(&'static str, ExchangeSet); 3] {
    [
        ("elements", set.clone()),
        ("midpoints", as_points(set, PointForm::Midpoints)),
        ("nodal averages", as_points(set, PointForm::NodalAverages)),
    ]
}

#[test]
fn courant_own_results_pass_every_diagnostic() {
    for name in ["fig1", "fig1_masses", "fig1_schemes", "fig2", "layered"] {
        let set = scored(name, &courant_set(&scene(name)).1);
        for c in &set.cases {
            let d = &c.diagnostics;
            assert_eq!(
                d.sign.as_ref().unwrap().matches(),
                Some(true),
                "{name} {}",
                c.case
            );
            assert_eq!(d.layout.as_ref().unwrap().layout, Layout::AsGiven);
            assert!(
                d.verdicts().iter().all(|v| v.verdict != Some(false)),
                "{name} {}: {:?}",
                c.case,
                d.verdicts()
            );
        }
        assert!(set.passed(), "{name}");
    }
}

#[test]
fn each_start_is_read_as_its_class_on_element_and_point_files() {
    let cases = [
        (
            2.0,
            StartImpulse::Extra,
            "the first step carries F0 dt/2 too much impulse",
        ),
        (0.0, StartImpulse::Missing, "no impulse at t = 0"),
        (
            0.5,
            StartImpulse::Half,
            "the first-step impulse is half of it",
        ),
    ];
    for (h0, start, words) in cases {
        let set = with_start_value("fig1", h0);
        for (form, set) in forms(&set) {
            let scored = scored("fig1", &set);
            for name in ["co1", "co0.5"] {
                let d = &case(&scored, name).diagnostics;
                assert_eq!(
                    level(d),
                    Some(TimeLevel::Read { steps: 0, start }),
                    "h0 = {h0}, {form}, {name}: {:?}",
                    d.shift
                );
                let r = row(d, "time_level");
                assert_eq!(r.verdict, Some(false));
                assert!(r.note.starts_with(words), "{}", r.note);
                let s = d.shift.as_ref().unwrap().steps;
                assert!(
                    (s - start.shift()).abs() <= 0.05,
                    "h0 = {h0}, {form}, {name}: shift {s} against {}",
                    start.shift()
                );
            }
            // At Co = 0.1 dispersion moves S by more than half a step: no class is claimed but
            // "on time to a step" or none at all.
            let d = &case(&scored, "co0.1").diagnostics;
            assert_ne!(row(d, "time_level").verdict, Some(false), "{form} co0.1");
            assert!(!scored.passed(), "h0 = {h0}, {form}: the set fails");
        }
    }
}

#[test]
fn element_and_point_files_of_one_run_give_the_same_shift() {
    let set = with_start_value("fig1", 2.0);
    let shifts: Vec<Vec<f64>> = forms(&set)
        .iter()
        .map(|(_, set)| {
            scored("fig1", set)
                .cases
                .iter()
                .filter(|c| c.case != "co0.1")
                .map(|c| c.diagnostics.shift.as_ref().unwrap().steps)
                .collect()
        })
        .collect();
    for form in &shifts[1..] {
        for (a, b) in form.iter().zip(&shifts[0]) {
            assert!((a - b).abs() <= 0.05, "{shifts:?}");
        }
    }
}

#[test]
fn a_set_written_one_step_late_is_caught_in_every_case() {
    for name in ["fig1", "fig1_masses"] {
        for (form, set) in forms(&one_step_late(&scene(name))) {
            let set = scored(name, &set);
            for c in &set.cases {
                let r = row(&c.diagnostics, "time_level");
                assert_eq!(
                    r.verdict,
                    Some(false),
                    "{name} {form} {}: {}",
                    c.case,
                    r.note
                );
                assert!(
                    r.note
                        .starts_with("1 step late: the values labelled t are those of t - 1 dt"),
                    "{name} {form} {}: {}",
                    c.case,
                    r.note
                );
            }
            assert!(!set.passed(), "{name} {form}: a lag fails the set");
        }
    }
}

#[test]
fn the_exact_answers_are_on_time_in_every_form() {
    // Midpoint values of the exact solution sample a front without smearing it: the shift is
    // still fitted on the integral, which is exact on the cells of the points.
    let exact = exact_set(&scene("fig1"), None, "exact").unwrap();
    for (form, set) in forms(&exact) {
        let set = scored("fig1", &set);
        for c in &set.cases {
            let r = row(&c.diagnostics, "time_level");
            assert_eq!(r.verdict, Some(true), "{form} {}: {}", c.case, r.note);
        }
    }
}

#[test]
fn a_sign_flipped_set_is_caught_and_its_shift_still_measured() {
    let set = scored("fig1", &sign_flipped(&scene("fig1")));
    for c in &set.cases {
        let d = &c.diagnostics;
        let r = row(d, "sign");
        assert_eq!((r.verdict, r.measured.as_str()), (Some(false), "flipped"));
        assert!(r.note.contains("write tension positive"), "{}", r.note);
        assert_ne!(
            row(d, "time_level").verdict,
            Some(false),
            "{}: measured on the negated file",
            c.case
        );
    }
    assert!(!set.passed());
}

#[test]
fn a_mirrored_bar_is_named_and_its_shift_measured_on_the_bar_put_back() {
    for h0 in [1.0, 2.0] {
        let set = scored("fig1", &mirrored(&with_start_value("fig1", h0)));
        for c in &set.cases {
            let r = row(&c.diagnostics, "layout");
            assert_eq!((r.verdict, r.measured.as_str()), (Some(false), "mirrored"));
            assert!(r.note.contains("write x from the loaded end"), "{}", r.note);
        }
        let d = &case(&set, "co0.5").diagnostics;
        let expected = if h0 == 1.0 {
            StartImpulse::Right
        } else {
            StartImpulse::Extra
        };
        assert_eq!(
            level(d),
            Some(TimeLevel::Read {
                steps: 0,
                start: expected
            }),
            "{:?}",
            d.shift
        );
    }
}

#[test]
fn nodal_averages_given_as_points_are_named() {
    // Where the run is exact (Co = 1) its nodal averages differ from the exact point values only
    // by half a jump at the front; the exact nodal averages match them to round-off.
    let (_, set) = courant_set(&scene("fig1"));
    let set = scored("fig1", &as_points(&set, PointForm::NodalAverages));
    let d = &case(&set, "co1").diagnostics;
    let r = row(d, "layout");
    assert_eq!(r.measured, "nodal averages", "{}", r.note);
    assert_eq!(r.verdict, None, "a form, not an error");
    assert!(r.note.contains("write element values"), "{}", r.note);
    assert_eq!(row(d, "time_level").verdict, Some(true));
    let midpoints = scored(
        "fig1",
        &as_points(&courant_set(&scene("fig1")).1, PointForm::Midpoints),
    );
    assert_eq!(
        case(&midpoints, "co1")
            .diagnostics
            .layout
            .as_ref()
            .unwrap()
            .layout,
        Layout::AsGiven
    );
}

#[test]
fn a_diverged_file_is_named_and_nothing_else_is_read_from_it() {
    // 1e10 |sigma0|: diverged, yet within the magnitude limit (beyond 1e50 a file is refused,
    // `tests/grading/score_and_io_regressions.rs`).
    let set = scored("fig1", &scaled(&courant_set(&scene("fig1")).1, 1e10));
    for c in &set.cases {
        let d = &c.diagnostics;
        let r = row(d, "magnitude");
        assert_eq!(r.verdict, Some(false));
        assert!(r.note.starts_with("the code diverged"), "{}", r.note);
        for name in ["time_level", "sign", "layout"] {
            let r = row(d, name);
            assert_eq!(r.verdict, None);
            assert!(r.note.contains("diverged"), "{name}: {}", r.note);
        }
    }
    assert!(!set.passed());
}

#[test]
fn a_phase_error_that_grows_with_time_is_no_timing_verdict() {
    // Park's local stepping on the Fig. 2 graded bar leads or lags the exact solution by a
    // fraction of a step that grows from the first profile to the second (its dispersion on the
    // graded mesh); courant's own run must not read as a wrong start.
    for name in ["fig2", "fig2_reversed"] {
        let set = scored(name, &courant_set(&scene(name)).1);
        let d = &case(&set, "park-lts-co0.5").diagnostics;
        let r = row(d, "time_level");
        assert_ne!(r.verdict, Some(false), "{name}: {}", r.note);
        assert!(set.passed(), "{name}");
    }
}

#[test]
fn sfepy_read_back_after_solve_is_one_step_late() {
    // SfePy 2026.3's pb.solve() returns the state one step before t1 (external/sfepy/README.md);
    // the driver's --naive-readback writes it as the naive user would.
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/sfepy_naive_readback/fig1");
    let set = scored("fig1", &read_dir(&dir).unwrap());
    assert_eq!(set.code, "sfepy");
    for c in &set.cases {
        let r = row(&c.diagnostics, "time_level");
        assert_eq!(r.verdict, Some(false), "{}: {}", c.case, r.note);
        assert!(r.note.starts_with("1 step late"), "{}: {}", c.case, r.note);
    }
    let co1 = case(&set, "co1");
    let shift = co1.diagnostics.shift.as_ref().unwrap();
    assert!(
        (shift.steps + 1.0).abs() < 0.01,
        "co1 is exact one step earlier: {shift:?}"
    );
}

#[test]
fn a_contact_force_history_gets_a_sign_verdict_and_no_offset_verdict() {
    // A force history one step late is not told apart from a scheme's start-up and impulse error
    // (compare::score::force): the shift is reported as a number, never as a verdict.
    let wall = scene("contact_wall");
    let (_, mut set) = courant_set(&wall);
    let own = scored("contact_wall", &set);
    for file in &mut set.cases {
        let CaseData::Force(h) = &mut file.data else {
            panic!()
        };
        h.force.rotate_right(1);
        h.force[0] = 0.0;
    }
    let late = scored("contact_wall", &set);
    let flipped = scored("contact_wall", &sign_flipped(&wall));
    for ((a, b), f) in own.cases.iter().zip(&late.cases).zip(&flipped.cases) {
        for c in [a, b] {
            let d = &c.diagnostics;
            let level = row(d, "time_level");
            assert_eq!(level.verdict, None, "{}: {}", c.case, level.note);
            assert!(level.note.starts_with("measured only"), "{}", level.note);
            assert_eq!(row(d, "sign").verdict, Some(true), "{}", c.case);
            assert_eq!(row(d, "layout").verdict, None);
        }
        assert_eq!(
            row(&f.diagnostics, "sign").verdict,
            Some(false),
            "{} flipped",
            f.case
        );
    }
}
