//! Result sets for the `courant score` tests, made from courant's own runs: as exported
//! (`courant run --exchange`), and deliberately wrong in one way each (written one step late,
//! with the sign flipped, with H(0) = 1/2), the bugs a code wired to a harness typically has.

#![allow(dead_code)]

use courant::compare::outcome::SceneOutcome;
use courant::compare::score::export::exchange_set;
use courant::pipeline::{evaluate_case, evaluate_scene};
use courant::results::exchange::files::read_dir;
use courant::results::exchange::record::{CaseData, ExchangeSet, Positions};
use courant::results::exchange::writer::set_files;
use courant::scene::Scene;
use courant::scene::builtin::{builtin_scene, builtin_text};
use std::path::{Path, PathBuf};

/// A fresh scratch directory.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("courant-score-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A built-in scene.
pub fn scene(name: &str) -> Scene {
    builtin_scene(name).unwrap().unwrap()
}

/// A built-in scene with one substitution in its text (keeping its name).
pub fn derived(name: &str, find: &str, replace: &str) -> Scene {
    let text = builtin_text(name).unwrap();
    assert!(text.contains(find), "test set-up: {find:?} not in {name}");
    Scene::parse(name, "derived.toml", &text.replacen(find, replace, 1)).unwrap()
}

/// courant's run of `scene`, compared, and its results as an exchange set.
pub fn courant_set(scene: &Scene) -> (SceneOutcome, ExchangeSet) {
    let outcome = evaluate_scene(scene).unwrap();
    let set = exchange_set(scene, &outcome, &scene.name).unwrap();
    (outcome, set)
}

/// The set with every profile replaced by the state one step earlier, still labelled with the
/// time it claims: a code that writes `u^{n-1}` as `u^n` (SfePy's `pb.solve()` read back).
pub fn one_step_late(scene: &Scene) -> ExchangeSet {
    let (_, mut set) = courant_set(scene);
    for case in &scene.cases {
        let mut early = case.clone();
        early.request.profile_steps = case.request.profile_steps.iter().map(|s| s - 1).collect();
        let result = evaluate_case(&early).unwrap();
        let file = set.cases.iter_mut().find(|c| c.case == case.name).unwrap();
        let CaseData::Profiles(profiles) = &mut file.data else {
            panic!()
        };
        for (p, late) in profiles.iter_mut().zip(&result.profiles) {
            p.stress = late.stress.clone();
        }
    }
    set
}

/// The set with every stress (or force) negated: compression positive.
pub fn sign_flipped(scene: &Scene) -> ExchangeSet {
    let (_, mut set) = courant_set(scene);
    for file in &mut set.cases {
        match &mut file.data {
            CaseData::Profiles(profiles) => {
                for p in profiles {
                    p.stress.iter_mut().for_each(|s| *s = -*s);
                }
            }
            CaseData::Force(h) => h.force.iter_mut().for_each(|f| *f = -*f),
            CaseData::Spectrum(_) => {}
        }
    }
    set
}

/// The Fig. 1 scene run with the step load at H(0) = 1/2 (`value_at_start = 0.5`).
pub fn heaviside_half(name: &str) -> ExchangeSet {
    with_start_value(name, 0.5)
}

/// A Fig. 1 scene run with the step load's value at t = 0 set to `h0` times the load: with the
/// half-step start the first step delivers the impulse `h0 F0 dt / 2`. `h0 = 2` is the
/// three-level start with the full F(0) (OpenSees' `CentralDifference`: `u^1 = dt^2 M^-1 F0`),
/// `h0 = 0` no impulse at t = 0 (`a^0 = 0`, OpenSees' `ExplicitDifference`), `h0 = 1/2` the
/// H(0) = 1/2 convention.
pub fn with_start_value(name: &str, h0: f64) -> ExchangeSet {
    let scene = derived(
        name,
        "time = \"step\"         # H(t) with H(0) = 1",
        &format!("time = \"step\"\nvalue_at_start = {h0:?}"),
    );
    courant_set(&scene).1
}

/// How a set's element values are turned into a point file.
#[derive(Debug, Clone, Copy)]
pub enum PointForm {
    /// Each element's value at its midpoint.
    Midpoints,
    /// At every node the mean of the values of the elements beside it (one at an end).
    NodalAverages,
}

/// The set with every element profile written as points (`t, x, stress`).
pub fn as_points(set: &ExchangeSet, form: PointForm) -> ExchangeSet {
    let mut set = set.clone();
    for file in &mut set.cases {
        let CaseData::Profiles(profiles) = &mut file.data else {
            continue;
        };
        for p in profiles {
            let Positions::Elements { left, right } = &p.positions else {
                continue;
            };
            let n = left.len();
            let (x, stress): (Vec<f64>, Vec<f64>) = match form {
                PointForm::Midpoints => (
                    left.iter().zip(right).map(|(a, b)| 0.5 * (a + b)).collect(),
                    p.stress.clone(),
                ),
                PointForm::NodalAverages => (0..=n)
                    .map(|i| match i {
                        0 => (left[0], p.stress[0]),
                        i if i == n => (right[n - 1], p.stress[n - 1]),
                        i => (left[i], 0.5 * (p.stress[i - 1] + p.stress[i])),
                    })
                    .unzip(),
            };
            p.positions = Positions::Points(x);
            p.stress = stress;
            p.lines = Vec::new();
        }
    }
    set
}

/// The set written from the far end: the value of `[a, b]` given for `[L - b, L - a]` (the bar
/// starting at 0).
pub fn mirrored(set: &ExchangeSet) -> ExchangeSet {
    let mut set = set.clone();
    for file in &mut set.cases {
        let CaseData::Profiles(profiles) = &mut file.data else {
            continue;
        };
        for p in profiles {
            let Positions::Elements { left, right } = &p.positions else {
                continue;
            };
            let end = right[right.len() - 1];
            let new_left: Vec<f64> = right.iter().rev().map(|b| end - b).collect();
            let new_right: Vec<f64> = left.iter().rev().map(|a| end - a).collect();
            p.positions = Positions::Elements {
                left: new_left,
                right: new_right,
            };
            p.stress.reverse();
        }
    }
    set
}

/// The set with every stress multiplied by `factor` (1e125: a code that diverged).
pub fn scaled(set: &ExchangeSet, factor: f64) -> ExchangeSet {
    let mut set = set.clone();
    for file in &mut set.cases {
        if let CaseData::Profiles(profiles) = &mut file.data {
            for p in profiles {
                p.stress.iter_mut().for_each(|s| *s *= factor);
            }
        }
    }
    set
}

/// Write `set` to `dir` and read it back, as `courant score` reads a directory.
pub fn through_files(set: &ExchangeSet, dir: &Path) -> ExchangeSet {
    for (name, text) in set_files(set) {
        std::fs::write(dir.join(name), text).unwrap();
    }
    read_dir(dir).unwrap()
}
