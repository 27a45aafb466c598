//! Result sets for the `courant score` tests, made from courant's own runs: as exported
//! (`courant run --exchange`), and deliberately wrong in one way each (written one step late,
//! with the sign flipped, with H(0) = 1/2), the bugs a code wired to a harness typically has.

#![allow(dead_code)]

use courant::compare::outcome::SceneOutcome;
use courant::compare::score::export::exchange_set;
use courant::pipeline::{evaluate_case, evaluate_scene};
use courant::results::exchange::reader::read_dir;
use courant::results::exchange::record::{CaseData, ExchangeSet};
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
    let scene = derived(
        name,
        "time = \"step\"         # H(t) with H(0) = 1",
        "time = \"step\"\nvalue_at_start = 0.5",
    );
    courant_set(&scene).1
}

/// Write `set` to `dir` and read it back, as `courant score` reads a directory.
pub fn through_files(set: &ExchangeSet, dir: &Path) -> ExchangeSet {
    for (name, text) in set_files(set) {
        std::fs::write(dir.join(name), text).unwrap();
    }
    read_dir(dir).unwrap()
}
