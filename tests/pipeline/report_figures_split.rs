//! Source of truth: the report contract "no case is left out of a figure without its caption
//! saying so; every plot is a well-formed SVG" (docs/guide/report.md), and the closed-form
//! critical Courant numbers of contact with a rigid wall of `courant-references` (methods.md §7)
//! for the seed's Fig. 3 graph.
//!
//! Proves: `split` puts every item in exactly one figure of at most `max` items, keeps a group
//! that fits in one figure and uses no more figures than needed; for scenes with more cases than
//! one legible figure holds (courant_sweep 24, fig1_masses 8, fig5 13, contact_extremes 36, and a
//! Fig. 1 variant with two unstable runs) every case is in the
//! legend of exactly one figure of each kind (profile at each time, contact force) or named
//! exactly once in a caption as not shown, a run that diverges after a profile time is drawn apart
//! from the stable ones, no figure draws more than `MAX_CASES` cases, and every
//! SVG is well-formed XML (`tests/common/xml.rs`); fig3's graph pairs each solver curve (points)
//! with a dashed closed-form curve of the same colour whose values are those of
//! `courant-references` at every beta_s.

use courant::pipeline::evaluate_scene as run_scene;
use courant::report::figure_parts::{MAX_CASES, split};
use courant::report::figures::{scene_figures, stability_charts};
use courant::report::plot::SeriesStyle;
use courant::scene::Scene;
use courant_references::contact::{
    signorini_critical_courant_penalty, signorini_critical_courant_ratio,
};

use crate::xml;

/// A legend text names `case`: the case name, or the name with the Courant number it ran at when
/// that differs from the one in the name (`co1.12 (Co = 1.1111)`: the step shrunk to hit the
/// output time).
fn names(text: &str, case: &str) -> bool {
    text == case || text.starts_with(&format!("{case} (Co = "))
}

/// Sizes of the figures `split` makes of groups of the given sizes (keys in order).
fn figure_sizes(groups: &[usize], max: usize) -> Vec<Vec<(usize, usize)>> {
    let items: Vec<(String, (usize, usize))> = groups
        .iter()
        .enumerate()
        .flat_map(|(g, &n)| (0..n).map(move |i| (format!("g{g}"), (g, i))))
        .collect();
    split(items, max)
}

#[test]
fn split_places_every_item_once_keeps_fitting_groups_whole_and_uses_few_figures() {
    let sizes = |f: &[Vec<(usize, usize)>]| f.iter().map(Vec::len).collect::<Vec<_>>();
    assert_eq!(sizes(&figure_sizes(&[6, 6, 6, 6], 6)), [6, 6, 6, 6]);
    assert_eq!(sizes(&figure_sizes(&[2, 2, 2, 2], 6)), [4, 4], "balanced");
    assert_eq!(sizes(&figure_sizes(&[13], 6)), [5, 4, 4], "cut evenly");
    assert_eq!(sizes(&figure_sizes(&[3], 6)), [3]);
    assert!(figure_sizes(&[], 6).is_empty());
    // Items of one key stay together even when they are not consecutive.
    let f = split(
        vec![
            ("a".to_string(), 0),
            ("b".to_string(), 1),
            ("a".to_string(), 2),
        ],
        2,
    );
    assert_eq!(f, vec![vec![0, 2], vec![1]]);
    // Invariants over many configurations.
    let mut seed = 12345u64;
    let mut next = |m: u64| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 33) % m
    };
    for _ in 0..500 {
        let max = 1 + next(8) as usize;
        let groups: Vec<usize> = (0..next(7)).map(|_| 1 + next(15) as usize).collect();
        let figures = figure_sizes(&groups, max);
        let total: usize = groups.iter().sum();
        let mut seen: Vec<(usize, usize)> = figures.iter().flatten().copied().collect();
        seen.sort_unstable();
        let expected: Vec<(usize, usize)> = groups
            .iter()
            .enumerate()
            .flat_map(|(g, &n)| (0..n).map(move |i| (g, i)))
            .collect();
        assert_eq!(
            seen, expected,
            "{groups:?} max {max}: every item exactly once"
        );
        assert!(figures.iter().all(|f| !f.is_empty() && f.len() <= max));
        let chunks: usize = groups.iter().map(|n| n.div_ceil(max)).sum();
        assert!(figures.len() >= total.div_ceil(max) && figures.len() <= chunks.max(1));
        for (g, &n) in groups.iter().enumerate() {
            let holding = figures
                .iter()
                .filter(|f| f.iter().any(|&(h, _)| h == g))
                .count();
            assert_eq!(holding, n.div_ceil(max), "{groups:?} max {max}: group {g}");
        }
    }
}

/// The texts of an SVG's `<text>` elements.
fn texts(svg: &str, file: &str) -> Vec<String> {
    let root = xml::parse_xml(svg).unwrap_or_else(|e| panic!("{file}: {e}"));
    assert_eq!(root.name, "svg", "{file}");
    root.descendants()
        .into_iter()
        .filter(|e| e.name == "text")
        .map(|e| e.text.trim().to_string())
        .collect()
}

/// The cases a caption names as not shown.
fn not_shown(caption: &str) -> Vec<String> {
    caption
        .split("; ")
        .filter(|part| part.starts_with("not shown"))
        .flat_map(|part| {
            let (_, list) = part.split_once(": ").expect("a list after the reason");
            list.split(", ").map(str::to_string).collect::<Vec<_>>()
        })
        .collect()
}

/// The kind of a figure file: `profile_<k>` or `force` (parts `_<j>` stripped).
fn kind(file: &str) -> String {
    let stem = file.trim_end_matches(".svg");
    let parts: Vec<&str> = stem.split('_').collect();
    match parts[0] {
        "profile" => format!("profile_{}", parts[1]),
        other => other.to_string(),
    }
}

fn assert_every_case_accounted_for(scene: &Scene, expected_kinds: &[&str]) {
    let outcome = run_scene(scene).unwrap();
    let cases: Vec<&str> = outcome
        .results
        .iter()
        .map(|r| r.run.case.as_str())
        .chain(outcome.contact.iter().map(|c| c.case.as_str()))
        .collect();
    assert!(cases.len() > MAX_CASES, "{}: too few cases", scene.name);
    let figures = scene_figures(scene, &outcome);
    let mut kinds: Vec<String> = figures.iter().map(|f| kind(&f.0)).collect();
    kinds.dedup();
    assert_eq!(kinds, expected_kinds, "{}", scene.name);
    for k in &kinds {
        let of_kind: Vec<_> = figures.iter().filter(|f| &kind(&f.0) == k).collect();
        let mut drawn_total = 0;
        for (file, caption, svg) in &of_kind {
            let texts = texts(svg, file);
            let drawn = cases
                .iter()
                .filter(|c| texts.iter().any(|t| names(t, c)))
                .count();
            assert!(drawn <= MAX_CASES, "{}/{file}: {drawn} cases", scene.name);
            drawn_total += drawn;
            if of_kind.len() > 1 {
                assert!(
                    caption.contains("cases drawn in") && caption.contains("this one: "),
                    "{}/{file}: a split figure names its cases: {caption}",
                    scene.name
                );
            }
        }
        for case in &cases {
            let in_legend = of_kind
                .iter()
                .filter(|(file, _, svg)| texts(svg, file).iter().any(|t| names(t, case)))
                .count();
            let named = of_kind
                .iter()
                .map(|(_, caption, _)| not_shown(caption).iter().filter(|c| c == case).count())
                .sum::<usize>();
            assert_eq!(
                in_legend + named,
                1,
                "{}/{k}: case {case} drawn {in_legend} times, named as not shown {named} times",
                scene.name
            );
        }
        assert!(drawn_total > 0, "{}/{k}: nothing drawn", scene.name);
    }
}

#[test]
fn every_case_of_a_large_scene_is_drawn_or_named_as_not_shown() {
    for (name, kinds) in [
        ("courant_sweep", &["profile_0"][..]),
        ("fig1_masses", &["profile_0", "profile_1"][..]),
        ("fig5", &["force"][..]),
        ("contact_extremes", &["force"][..]),
    ] {
        let scene = courant::scene::builtin::builtin_scene(name)
            .unwrap()
            .unwrap();
        assert_every_case_accounted_for(&scene, kinds);
    }
    // Fig. 1 at eight Courant numbers, two above the limit (dt shrunk to hit t = 0.1 T: Co =
    // 1.111 and 1.429), profiles at 0.1 T and 1.5 T: both runs diverge before 1.5 T, so the late
    // profile cannot show them and its captions must say so; the early profile that draws them
    // (co1.12 diverges at step 17, after 0.1 T) keeps them apart from the stable runs, whose
    // curves their growing sawtooth would flatten.
    let text = courant::scene::builtin::builtin_text("fig1")
        .unwrap()
        .replace(
            "courant = [1.0, 0.5, 0.1]",
            "courant = [1.0, 0.9, 0.75, 0.5, 0.25, 0.1, 1.12, 1.5]\nallow_unstable = true",
        )
        .replace("profile_times = [0.5, 1.5]", "profile_times = [0.1, 1.5]");
    let text = &text[..text.find("[[expect]]").unwrap()];
    let scene = Scene::parse("fig1_unstable", "test", text).unwrap();
    assert_every_case_accounted_for(&scene, &["profile_0", "profile_1"]);
    let outcome = run_scene(&scene).unwrap();
    let figures = scene_figures(&scene, &outcome);
    let late: Vec<String> = figures
        .iter()
        .filter(|f| kind(&f.0) == "profile_1")
        .flat_map(|f| not_shown(&f.1))
        .collect();
    assert!(
        late.contains(&"co1.12".to_string()) && late.contains(&"co1.5".to_string()),
        "{late:?}"
    );
    let (file, caption, svg) = figures
        .iter()
        .find(|f| kind(&f.0) == "profile_0" && texts(&f.2, &f.0).iter().any(|t| names(t, "co1.12")))
        .expect("co1.12 drawn at t = 0.1 T");
    let cases: Vec<String> = texts(svg, file)
        .into_iter()
        .filter(|t| t.starts_with("co"))
        .collect();
    assert!(
        cases
            .iter()
            .all(|c| names(c, "co1.12") || names(c, "co1.5")),
        "{file}: only the diverging runs, not {cases:?}"
    );
    assert!(caption.contains("diverged later"), "{caption}");
}

#[test]
fn fig3_graph_draws_the_closed_form_dashed_in_the_colour_of_each_solver_curve() {
    let text = courant::scene::builtin::builtin_text("fig3")
        .unwrap()
        .replace("elements = 6400", "elements = 400");
    let scene = Scene::parse("fig3", "test", &text).unwrap();
    let outcome = run_scene(&scene).unwrap();
    let sweep = &outcome.sweeps[0];
    let parts = stability_charts(sweep);
    assert_eq!(parts.len(), 1, "six curves fit the palette");
    let (curves, series) = &parts[0];
    assert_eq!(
        curves,
        &[
            "penalty only",
            "r = 0.25",
            "r = 1",
            "r = 2",
            "r = 4",
            "r = 16"
        ]
    );
    let ratios = [
        None,
        Some(0.25),
        Some(1.0),
        Some(2.0),
        Some(4.0),
        Some(16.0),
    ];
    let dashed: Vec<_> = series
        .iter()
        .filter(|s| s.style == SeriesStyle::Dashed)
        .collect();
    let points: Vec<_> = series
        .iter()
        .filter(|s| s.style == SeriesStyle::Points)
        .collect();
    assert_eq!((dashed.len(), points.len()), (6, 6));
    assert_eq!(
        dashed.iter().filter(|s| s.in_legend).count(),
        1,
        "one legend entry for all closed forms"
    );
    for (i, ratio) in ratios.iter().enumerate() {
        let (closed, solver) = (dashed[i], points[i]);
        assert_eq!(solver.name, curves[i]);
        assert_eq!(closed.colour, solver.colour, "{}: same colour", curves[i]);
        assert_eq!(closed.points.len(), 41);
        for (&(beta_s, cr), &(beta_solver, cr_solver)) in closed.points.iter().zip(&solver.points) {
            assert_eq!(beta_s, beta_solver);
            let exact = match ratio {
                None => signorini_critical_courant_penalty(beta_s),
                Some(r) => signorini_critical_courant_ratio(beta_s, *r),
            }
            .unwrap();
            assert_eq!(cr, exact, "{} at beta_s = {beta_s}", curves[i]);
            // 400 elements instead of the scene's 6400: the finite bar's highest mode differs
            // from the semi-infinite bar's by O(1/N^2) (measured 1.6e-6 at r <= 1).
            assert!(
                (cr_solver - exact).abs() <= 1e-5 * exact,
                "{} at beta_s = {beta_s}: solver {cr_solver} vs closed form {exact}",
                curves[i]
            );
        }
    }
    let colours: Vec<Option<usize>> = points.iter().map(|s| s.colour).collect();
    let mut distinct = colours.clone();
    distinct.dedup();
    assert_eq!(distinct.len(), 6, "one colour per curve: {colours:?}");
    // The SVG: well-formed, every solver point a circle, dashes in each curve's colour.
    let figures = scene_figures(&scene, &outcome);
    let (file, caption, svg) = figures
        .iter()
        .find(|f| f.0 == "stability.svg")
        .expect("stability.svg");
    assert!(caption.contains("closed form"), "{caption}");
    let root = xml::parse_xml(svg).unwrap_or_else(|e| panic!("{file}: {e}"));
    let all = root.descendants();
    let circles = all.iter().filter(|e| e.name == "circle").count();
    assert_eq!(circles, 6 * 41 + 6, "246 points and 6 legend markers");
    let dash_colours: Vec<&str> = all
        .iter()
        .filter(|e| e.name == "polyline" && e.attr("stroke-width") == Some("2"))
        .filter_map(|e| e.attr("stroke"))
        .collect();
    // Hollow points: the colour is the circle's stroke.
    let point_colours: Vec<&str> = all
        .iter()
        .filter(|e| e.name == "circle")
        .filter_map(|e| e.attr("stroke"))
        .collect();
    assert_eq!(point_colours.len(), circles, "every point is a hollow ring");
    for colour in &point_colours {
        assert!(
            dash_colours.iter().filter(|c| *c == colour).count() >= 10,
            "points of colour {colour} have no dashed closed form beside them"
        );
    }
}
