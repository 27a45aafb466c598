//! Source of truth: what an error bound is. The exact answer has zero error, so an upper bound
//! on an error (`l1`, `linf`, `overshoot`, a force or spectrum deviation) holds for it and for
//! every result at least as accurate; a band, a lower bound on an error or a ratio of two cases
//! describes one scheme and mass (lumped central difference's dispersed front: overshoot about
//! 27 %, `linf >= 0.3`), and holds for another code only if it runs that scheme and mass.
//!
//! Proves: for every built-in scene with an exchange form, the exact answers (`courant
//! reference`) meet every error bound and every signature row reads "not applicable", never FAIL
//! and never pass (a spectrum's rows name their masses, so its signatures apply, and pass); courant's own export declares its scheme, parameters and mass, so both kinds
//! apply and pass; a set that declares another mass, or no scheme, gets its signatures as not
//! applicable with the reason; an unknown scheme, parameter or value in `results.toml` is a
//! located error with the known names; a sign-flipped exact file fails the bound (it passed
//! `linf >= 0.3` when every row applied); a missing case and a missing time are both "not
//! supplied", failures only with `--require-all`; a scene may declare `kind`, and a bound that
//! the exact answer would fail is refused when the scene is read.

use crate::exchange;

use courant::compare::score::answers::exact_set;
use courant::compare::score::bind::SceneKind;
use courant::compare::score::outcome::{ScoreError, ScoredSet, SkipKind};
use courant::compare::score::set::score_set;
use courant::results::exchange::meta::{Located, MetaValue};
use courant::results::exchange::record::{CaseData, ExchangeSet};
use courant::scene::Scene;
use courant::scene::builtin::BUILTIN_SCENES;
use courant::scene::expectation::RowKind;
use exchange::{courant_set, scene, sign_flipped};
use rstest::rstest;

/// Every (case, metric label) of the scene's rows of `kind`.
fn rows(scene: &Scene, kind: RowKind) -> Vec<(String, String)> {
    scene
        .expectations
        .iter()
        .filter(|e| e.kind == kind)
        .flat_map(|e| {
            let label = e.metric.name().to_string();
            e.cases.iter().map(move |c| (c.clone(), label.clone()))
        })
        .collect()
}

fn assert_signatures_not_applicable(scene: &Scene, set: &ScoredSet) {
    for (case, metric) in rows(scene, RowKind::Signature) {
        let skip = set.skipped.iter().find(|s| {
            s.case == case && s.metric.name() == metric && s.kind == SkipKind::NotApplicable
        });
        assert!(
            skip.is_some(),
            "{}: signature {metric} of {case} is not 'not applicable': {:?}",
            scene.name,
            set.skipped
                .iter()
                .filter(|s| s.case == case)
                .collect::<Vec<_>>()
        );
    }
}

#[rstest]
fn the_exact_answers_meet_every_bound_and_no_signature_applies(
    #[values(
        "fig1",
        "fig1_masses",
        "fig1_schemes",
        "fig2",
        "fig2_theta",
        "fig2_reversed",
        "layered",
        "fig3",
        "fig5",
        "fig6",
        "contact_wall",
        "contact_unequal",
        "impact_layered",
        "impact_layered_combined",
        "impact_layered_stability",
        "impact_layered_below_limits",
        "impact_layered_park_free",
        "impact_graded",
        "impact_graded_penalty",
        "impact_graded_stability",
        "dispersion",
        "courant_sweep",
        "courant_sweep_schemes",
        "courant_sweep_own_limits",
        "stability_extremes",
        "stability_exact",
        "stability_park",
        "stability_noh_bathe",
        "fig1_si",
        "long_run",
        "graded_1e4",
        "graded_1e4_long",
        "layered_1e4",
        "contact_courant_sweep",
        "contact_extremes",
        "pc_ratio",
        "contact_impact_stability",
        "fig2_park_printed",
        "fig1_airy"
    )]
    name: &str,
) {
    let scene = scene(name);
    let exact = match exact_set(&scene, None, "exact") {
        Ok(set) => set,
        Err(ScoreError::Scene(why)) => {
            // Dispersion and contact-stability scenes, and scenes without an analytic
            // reference, have no exchange form: nothing to grade.
            assert!(SceneKind::of(&scene).is_err(), "{name}: {why}");
            return;
        }
        Err(e) => panic!("{name}: {e}"),
    };
    let set = score_set(&scene, &exact).unwrap();
    for v in &set.verdicts {
        assert!(
            v.pass,
            "{name}: bound {} of {} fails: {v:?}",
            v.metric_label(),
            v.case
        );
    }
    let not_measurable = set
        .skipped
        .iter()
        .filter(|s| s.kind == SkipKind::NotMeasurable)
        .count();
    if SceneKind::of(&scene).unwrap() == SceneKind::Spectrum {
        // A spectrum file names the mass kind of every row: the closed forms are those of the
        // masses, and so are its signatures (`mass_deviation`), which apply and pass.
        assert_eq!(
            set.verdicts.len() + not_measurable,
            rows(&scene, RowKind::Bound).len() + rows(&scene, RowKind::Signature).len()
        );
    } else {
        assert_eq!(
            set.verdicts.len() + not_measurable,
            rows(&scene, RowKind::Bound).len(),
            "{name}: every bound row is judged or not measurable from files"
        );
        assert_signatures_not_applicable(&scene, &set);
    }
    assert!(set.passed(), "{name}");
}

#[test]
fn the_builtin_list_above_is_complete() {
    let listed = 39;
    assert_eq!(
        BUILTIN_SCENES.len(),
        listed,
        "add the new scene to the #[values] list"
    );
}

#[test]
fn courant_own_export_declares_its_scheme_so_both_kinds_apply() {
    for name in ["fig1", "fig1_masses", "fig1_schemes", "fig5"] {
        let scene = scene(name);
        let set = score_set(&scene, &courant_set(&scene).1).unwrap();
        assert!(
            set.skipped
                .iter()
                .all(|s| s.kind != SkipKind::NotApplicable),
            "{name}: {:?}",
            set.skipped
        );
        let signatures = set
            .verdicts
            .iter()
            .filter(|v| {
                scene
                    .expectations
                    .iter()
                    .any(|e| e.kind == RowKind::Signature && e.metric == v.metric)
            })
            .count();
        assert!(signatures > 0, "{name}: signatures judged");
        assert!(set.passed(), "{name}");
    }
}

/// `set` with `results.toml`'s case `case` edited.
fn declare(
    set: &ExchangeSet,
    edit: impl Fn(&mut courant::results::exchange::meta::CaseMeta),
) -> ExchangeSet {
    let mut set = set.clone();
    for meta in set.meta.as_mut().unwrap().cases.values_mut() {
        edit(meta);
    }
    set
}

#[test]
fn a_set_that_declares_another_mass_or_no_scheme_gets_its_signatures_as_not_applicable() {
    let scene = scene("fig1");
    let own = courant_set(&scene).1;
    let cmm = declare(&own, |m| m.mass = Some(("cmm".into(), 0, 0)));
    let set = score_set(&scene, &cmm).unwrap();
    let overshoot = set
        .skipped
        .iter()
        .find(|s| s.case == "co0.5" && s.metric.name() == "overshoot")
        .unwrap();
    assert_eq!(overshoot.kind, SkipKind::NotApplicable);
    assert!(
        overshoot.reason.contains("declared cmm; the case is lmm"),
        "{}",
        overshoot.reason
    );
    let undeclared = declare(&own, |m| {
        m.scheme = None;
        m.parameters.clear();
    });
    let set = score_set(&scene, &undeclared).unwrap();
    let linf = set
        .skipped
        .iter()
        .find(|s| s.case == "co0.5" && s.metric.name() == "linf")
        .unwrap();
    assert!(
        linf.reason.contains("scheme not declared"),
        "{}",
        linf.reason
    );
    // The bound still applies.
    assert!(
        set.verdicts
            .iter()
            .any(|v| v.case == "co1" && v.metric.name() == "linf")
    );
    let other_p = declare(&courant_set(&scene_named("fig1_schemes")).1, |m| {
        if m.scheme.as_deref() == Some("noh-bathe") {
            m.parameters = vec![("p".into(), Located::unplaced(MetaValue::Number(0.6)))];
        }
    });
    let set = score_set(&scene_named("fig1_schemes"), &other_p).unwrap();
    assert!(
        set.skipped
            .iter()
            .any(|s| s.kind == SkipKind::NotApplicable
                && s.reason.contains("declared noh-bathe p=0.6")),
        "{:?}",
        set.skipped
    );
}

fn scene_named(name: &str) -> Scene {
    scene(name)
}

#[test]
fn unknown_schemes_parameters_and_values_are_located_errors_naming_the_known_ones() {
    let scene = scene("fig1");
    let own = courant_set(&scene).1;
    let mut fancy = declare(&own, |m| m.scheme = Some("my-fancy-scheme".into()));
    fancy
        .meta
        .as_mut()
        .unwrap()
        .cases
        .get_mut("co1")
        .unwrap()
        .scheme_at = (7, 10);
    let Err(ScoreError::Input(e)) = score_set(&scene, &fancy) else {
        panic!("an unknown scheme is refused");
    };
    let first = e.first();
    assert_eq!(first.key, "cases.\"co0.1\".scheme", "{e}");
    assert!(
        first
            .message
            .contains("\"my-fancy-scheme\" is not a scheme courant knows"),
        "{e}"
    );
    assert!(first.message.contains("noh-bathe"), "the known names: {e}");
    assert_eq!(e.0.len(), 3, "every case reported: {e}");
    assert!(e.0.iter().any(|x| (x.line, x.column) == (7, 10)), "{e}");
    let bad_key = declare(&own, |m| {
        m.parameters = vec![("q".into(), Located::unplaced(MetaValue::Number(1.0)))];
    });
    let Err(ScoreError::Input(e)) = score_set(&scene, &bad_key) else {
        panic!("a parameter the scheme does not take is refused");
    };
    assert!(e.first().message.contains("takes no parameter `q`"), "{e}");
    let schemes = scene_named("fig1_schemes");
    let bad_value = declare(&courant_set(&schemes).1, |m| {
        if m.scheme.as_deref() == Some("noh-bathe") {
            m.parameters = vec![("p".into(), Located::unplaced(MetaValue::Number(0.9)))];
        }
    });
    let Err(ScoreError::Input(e)) = score_set(&schemes, &bad_value) else {
        panic!("a value that breaks its rule is refused");
    };
    assert!(e.first().message.contains("must lie in"), "{e}");
}

#[test]
fn a_sign_flipped_exact_file_fails_the_bound_and_is_judged_by_no_signature() {
    let scene = scene("fig1");
    let exact = exact_set(&scene, None, "exact").unwrap();
    let mut flipped = exact.clone();
    for file in &mut flipped.cases {
        if let CaseData::Profiles(profiles) = &mut file.data {
            for p in profiles {
                p.stress.iter_mut().for_each(|s| *s = -*s);
            }
        }
    }
    let set = score_set(&scene, &flipped).unwrap();
    let linf = set.verdicts.iter().find(|v| v.case == "co1").unwrap();
    assert!(!linf.pass, "linf of a flipped file is 2, not <= 1e-10");
    assert!(
        !set.verdicts.iter().any(|v| v.case == "co0.5"),
        "no signature judged: `linf >= 0.3` no longer passes a flipped file"
    );
    assert!(!set.passed());
    // courant's own flipped run declares its scheme: its signatures apply, and the sign fails.
    let own = score_set(&scene, &sign_flipped(&scene)).unwrap();
    assert!(!own.passed());
}

#[test]
fn a_missing_case_and_a_missing_time_are_both_not_supplied() {
    let scene = scene("fig1");
    let mut set = exact_set(&scene, None, "exact").unwrap();
    set.cases.retain(|c| c.case != "co0.1");
    set.meta.as_mut().unwrap().cases.remove("co0.1");
    for file in &mut set.cases {
        if let CaseData::Profiles(profiles) = &mut file.data {
            profiles.truncate(1);
        }
    }
    let exact_at = |t: f64| {
        let mut scene = scene.clone();
        for e in &mut scene.expectations {
            e.at = Some(t);
        }
        scene
    };
    let at_late = exact_at(1.5);
    let mut scored = score_set(&at_late, &set).unwrap();
    assert_eq!(scored.missing_cases, vec!["co0.1".to_string()]);
    let co1 = scored
        .skipped
        .iter()
        .find(|s| s.case == "co1" && s.metric.name() == "linf")
        .unwrap();
    assert_eq!(co1.kind, SkipKind::NotSupplied);
    assert!(
        co1.reason.contains("no profile at t = 1.5"),
        "{}",
        co1.reason
    );
    let co01 = scored.skipped.iter().find(|s| s.case == "co0.1").unwrap();
    assert_eq!(co01.kind, SkipKind::NotSupplied);
    assert!(co01.reason.contains("no co0.1.csv"), "{}", co01.reason);
    assert!(scored.passed(), "not supplied is no failure by default");
    scored.require_all = true;
    assert!(!scored.passed(), "--require-all fails it");
}

#[test]
fn a_scene_declares_kind_and_a_bound_the_exact_answer_fails_is_refused() {
    let text = courant::scene::builtin::builtin_text("fig1").unwrap();
    let signature = text.replacen(
        "metric = \"linf\"\nmax = 1e-10",
        "metric = \"linf\"\nmax = 1e-10\nkind = \"signature\"",
        1,
    );
    let scene = Scene::parse("fig1", "fig1.toml", &signature).unwrap();
    assert_eq!(scene.expectations[0].kind, RowKind::Signature);
    let bad = text.replacen(
        "metric = \"linf\"\nmin = 0.3",
        "metric = \"linf\"\nmin = 0.3\nkind = \"bound\"",
        1,
    );
    let e = Scene::parse("fig1", "fig1.toml", &bad)
        .unwrap_err()
        .to_string();
    assert!(e.contains("kind = \"bound\" needs an error metric"), "{e}");
    assert!(e.contains("expect.kind"), "{e}");
    let typo = text.replacen("max = 1e-10", "max = 1e-10\nkind = \"bond\"", 1);
    let e = Scene::parse("fig1", "fig1.toml", &typo)
        .unwrap_err()
        .to_string();
    assert!(e.contains("is not one of bound, signature"), "{e}");
}
