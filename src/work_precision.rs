//! Work-precision studies: for each scheme, the error against the work it cost (steps and
//! node-steps, deterministic; CPU time in the report's timing section), over a sequence of
//! meshes — "which scheme gives me this accuracy cheapest". Time-stepping studies measure the
//! normalised L1 error of a stress profile; contact studies the L1-in-time error of the contact
//! force over the exact impulse (1D wave theory, methods.md §7).
//!
//! A scheme whose stable step is far below the others' runs at its own Courant number: a study
//! may split its schemes into [`CourantVariant`]s, each with its own Courant setting, and the
//! labels of the points state the setting (CD with penalty at 0.9 of its exact critical step
//! beside the bipenalty schemes at Co = 0.5, so the reader sees what the penalty costs in steps
//! for the same error).

use crate::document::Block;
use crate::plot::{Axes, Series, SeriesStyle, line_chart};
use crate::table::{Precision, Table};
use rayon::prelude::*;

/// A work-precision study: a scene whose cases are schemes (or mass kinds) times meshes.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPrecisionStudy {
    /// File-friendly name.
    pub name: &'static str,
    /// Heading.
    pub title: &'static str,
    /// The built-in scene it starts from.
    pub scene: &'static str,
    /// Text substitutions making the mesh a list (cases `n<N>-<scheme>-...`); in a contact
    /// study `{n}` and `{2n}` take each of `contact_meshes` in turn.
    pub replacements: &'static [(&'static str, &'static str)],
    /// Contact studies: the striker's element counts, one derived scene each (a contact scene
    /// has one mesh). Empty for time-stepping studies.
    pub contact_meshes: &'static [usize],
    /// Schemes run at their own Courant setting, one derived scene each (per mesh in a contact
    /// study); empty: the scene's schemes at the scene's (or the study's) Courant number.
    pub variants: &'static [CourantVariant],
    /// What the error column measures.
    pub error: &'static str,
}

/// Schemes of a study run at one Courant setting.
#[derive(Debug, Clone, PartialEq)]
pub struct CourantVariant {
    /// The setting as the labels of its points state it, e.g. `Co = 0.5` (relative to the
    /// stiffest element) or `Co = 0.9 Co_crit` (of each case's exact critical step).
    pub courant: &'static str,
    /// Substitutions applied after the study's: the scheme list and its Courant number.
    pub replacements: &'static [(&'static str, &'static str)],
}

/// Error label of time-stepping studies.
const STRESS_L1: &str = "L1 error / |sigma0|";

/// The built-in work-precision studies.
pub const WORK_PRECISION_STUDIES: &[WorkPrecisionStudy] = &[
    WorkPrecisionStudy {
        name: "fig1_masses",
        title: "Fig. 1 bar at t = 0.5 T, each mass kind at its own critical Courant number",
        scene: "fig1_masses",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600]",
            ),
            ("courant = [1.0, 0.5]", "courant = 0.9"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
            ("history_points = [0.0, 0.5]", "history_points = []"),
        ],
        contact_meshes: &[],
        variants: &[],
        error: STRESS_L1,
    },
    WorkPrecisionStudy {
        name: "fig2_schemes",
        title: "Fig. 2 graded bar at t = 0.5 T, CD and Park (Co = 0.5)",
        scene: "fig2",
        replacements: &[
            ("elements = 100", "elements = [50, 100, 200, 400]"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
        contact_meshes: &[],
        variants: &[],
        error: STRESS_L1,
    },
    WorkPrecisionStudy {
        name: "fig5_contact",
        title: "Fig. 5 impact, contact schemes (beta_s = 2500, r = 1)",
        scene: "fig5",
        replacements: &[
            (
                "striker = { length = 1.0, elements = 100 }",
                "striker = { length = 1.0, elements = {n} }",
            ),
            (
                "target = { length = 2.0, elements = 200 }",
                "target = { length = 2.0, elements = {2n} }",
            ),
            ("beta_s = [0.25, 25.0, 2500.0, 2.5e7]", "beta_s = 2500.0"),
            // Every variant runs below its critical step: refuse it otherwise.
            ("allow_unstable = true", "allow_unstable = false"),
        ],
        contact_meshes: &[25, 50, 100, 200, 400, 800],
        variants: &[
            CourantVariant {
                courant: "Co = 0.5",
                replacements: &[(
                    FIG5_SCHEMES,
                    "schemes = [\"cd-bipenalty\", \"predictor-corrector\", \"lagrange-multiplier\"]",
                )],
            },
            // Penalty only: Cr = 0.0200 at beta_s = 2500 (two bars, methods.md §7), unstable at
            // Co = 0.5; at 0.9 of its exact critical step it needs about 28 times the steps.
            CourantVariant {
                courant: "Co = 0.9 Co_crit",
                replacements: &[
                    (FIG5_SCHEMES, "schemes = [\"cd-penalty\"]"),
                    (
                        "courant = 0.5",
                        "courant = 0.9\ncourant_unit = \"critical\"",
                    ),
                ],
            },
        ],
        error: "L1 force error / impulse",
    },
];

/// The scheme list of the built-in fig5 scene.
const FIG5_SCHEMES: &str = "schemes = [\"cd-penalty\", \"cd-bipenalty\", \"predictor-corrector\", \"lagrange-multiplier\"]";

/// One run of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPoint {
    /// Scheme or mass label (the case name without its mesh and Courant parts).
    pub method: String,
    /// The Courant setting of its variant ([`CourantVariant::courant`]), when the study has
    /// several.
    pub setting: Option<&'static str>,
    /// Courant number of the run relative to the stiffest element, `c dt / h_min`.
    pub courant: f64,
    /// The critical Courant number of the case's scheme (exact, methods.md §5 and §7).
    pub critical_courant: f64,
    /// Elements.
    pub elements: usize,
    /// Steps.
    pub steps: usize,
    /// Normalised L1 error of the stress.
    pub l1: f64,
    /// Wall time of the integration, in seconds.
    pub wall_time: f64,
}

impl WorkPoint {
    /// Legend label: the method, with its Courant setting when the study's schemes run at
    /// different ones.
    pub fn label(&self) -> String {
        match self.setting {
            Some(setting) => format!("{} ({setting})", self.method),
            None => self.method.clone(),
        }
    }
}

/// A study's derived scenes: one per contact mesh (one in all for a time-stepping study) and
/// Courant variant, each with the variant's setting when the study has several.
fn study_scenes(
    study: &WorkPrecisionStudy,
) -> Result<Vec<(Option<&'static str>, crate::Scene)>, String> {
    let meshes: Vec<Option<usize>> = if study.contact_meshes.is_empty() {
        vec![None]
    } else {
        study.contact_meshes.iter().copied().map(Some).collect()
    };
    let no_variant = [CourantVariant {
        courant: "",
        replacements: &[],
    }];
    let variants = if study.variants.is_empty() {
        &no_variant[..]
    } else {
        study.variants
    };
    let mut scenes = Vec::new();
    for n in meshes {
        for variant in variants {
            let replacements: Vec<(&str, String)> = study
                .replacements
                .iter()
                .chain(variant.replacements)
                .map(|(from, to)| {
                    let to = match n {
                        Some(n) => to
                            .replace("{2n}", &(2 * n).to_string())
                            .replace("{n}", &n.to_string()),
                        None => to.to_string(),
                    };
                    (*from, to)
                })
                .collect();
            let borrowed: Vec<(&str, &str)> =
                replacements.iter().map(|(f, t)| (*f, t.as_str())).collect();
            let scene = crate::report::derived_scene(study.name, study.scene, &borrowed)?;
            let setting = (study.variants.len() > 1).then_some(variant.courant);
            scenes.push((setting, scene));
        }
    }
    Ok(scenes)
}

/// Run a study: every case of its derived scenes, in parallel, in order.
pub fn run(study: &WorkPrecisionStudy) -> Result<Vec<WorkPoint>, String> {
    let scenes = study_scenes(study)?;
    if !study.contact_meshes.is_empty() {
        return run_contact(study, &scenes);
    }
    let cases: Vec<(Option<&'static str>, &crate::scene::Case)> = scenes
        .iter()
        .flat_map(|(setting, scene)| scene.cases.iter().map(move |c| (*setting, c)))
        .collect();
    let points = cases
        .par_iter()
        .map(|&(setting, case)| {
            let r = crate::run_case(case).map_err(|e| e.to_string())?;
            let l1 = r
                .profiles
                .first()
                .and_then(|p| p.norms)
                .map(|n| n.l1)
                .ok_or("no profile norms")?;
            // n<N>-<method>-co<Co>: keep the method.
            let method = case
                .name
                .split('-')
                .skip(1)
                .take_while(|part| !part.starts_with("co"))
                .collect::<Vec<_>>()
                .join("-");
            Ok(WorkPoint {
                method,
                setting,
                courant: r.courant,
                // Co_crit = Co dt_crit/dt with dt_crit the limit of the case's scheme (CD:
                // 2/omega_max; Park: alpha_e <= 1).
                critical_courant: r.courant * r.limit.dt() / r.dt,
                elements: r.elements,
                steps: r.steps,
                l1,
                wall_time: r.wall_time.as_secs_f64(),
            })
        })
        .collect::<Vec<Result<_, String>>>();
    crate::run::in_order(points)
}

/// A contact study: one derived scene per striker mesh and variant, every case of each;
/// `elements` counts the elements of all bodies, the error is
/// [`crate::contact_study::ContactResult::force_l1_error`].
fn run_contact(
    study: &WorkPrecisionStudy,
    scenes: &[(Option<&'static str>, crate::Scene)],
) -> Result<Vec<WorkPoint>, String> {
    let cases: Vec<(Option<&'static str>, &crate::scene::contact::ContactCase)> = scenes
        .iter()
        .flat_map(|(setting, scene)| scene.contact.iter().map(move |c| (*setting, c)))
        .collect();
    let points = cases
        .par_iter()
        .map(|&(setting, case)| {
            let r = crate::contact_study::run_contact(case).map_err(|e| e.to_string())?;
            if let Some(d) = &r.diverged {
                return Err(format!(
                    "study {}: case {} diverged: {d}",
                    study.name, case.name
                ));
            }
            Ok(WorkPoint {
                method: case.name.clone(),
                setting,
                courant: r.run.courant,
                critical_courant: r.run.critical.critical_courant(),
                elements: case
                    .problem
                    .bodies()
                    .iter()
                    .map(|b| b.bar().element_count())
                    .sum(),
                steps: r.run.steps,
                l1: r.force_l1_error,
                wall_time: r.wall_time.as_secs_f64(),
            })
        })
        .collect::<Vec<Result<_, String>>>();
    crate::run::in_order(points)
}

/// Deterministic table: `method, Co, Co_crit, N, steps, node_steps, l1` (`Co` relative to the
/// stiffest element, `Co_crit` the exact critical Courant number of the case's scheme).
pub fn table(points: &[WorkPoint]) -> Table {
    let mut t = Table::new(&["method", "Co", "Co_crit", "N", "steps", "node_steps", "l1"]);
    for p in points {
        t.push(vec![
            p.method.as_str().into(),
            p.courant.into(),
            p.critical_courant.into(),
            p.elements.into(),
            p.steps.into(),
            (p.elements * p.steps).into(),
            p.l1.into(),
        ]);
    }
    t
}

/// One series per label ([`WorkPoint::label`]), in order of first appearance, of the points
/// `(x(p), l1)` kept by `keep` (labels with no point kept are left out).
fn series_by_label(
    points: &[WorkPoint],
    keep: impl Fn(&WorkPoint) -> bool,
    x: impl Fn(&WorkPoint) -> f64,
    style: SeriesStyle,
) -> Vec<Series> {
    let mut labels: Vec<String> = Vec::new();
    for p in points {
        let label = p.label();
        if !labels.contains(&label) {
            labels.push(label);
        }
    }
    labels
        .into_iter()
        .map(|label| {
            let pts = points
                .iter()
                .filter(|p| p.label() == label && keep(p))
                .map(|p| (x(p), p.l1))
                .collect();
            Series::new(label, pts, style)
        })
        .filter(|s| !s.points.is_empty())
        .collect()
}

/// The abscissa of a work-precision chart.
type Abscissa = fn(&WorkPoint) -> f64;

/// Report blocks (figures of the L1 error against elements x steps and against steps, per
/// method, and the table) and files.
pub fn blocks(
    study: &WorkPrecisionStudy,
    points: &[WorkPoint],
    shown: Precision,
    stored: Precision,
) -> (Vec<Block>, Vec<(String, String)>) {
    let mut blocks = vec![Block::Heading(3, study.title.into())];
    let mut files = Vec::new();
    let settings = if study.variants.len() > 1 {
        "; each scheme at the Courant setting in its label (Co relative to the stiffest element, \
         Co_crit the exact critical Courant number of its scheme; both in the table)"
    } else {
        ""
    };
    let charts: [(&str, &str, Abscissa, &str); 2] = [
        (
            "",
            "work: elements x steps",
            |p| (p.elements * p.steps) as f64,
            "Error against work (elements x steps)",
        ),
        (
            ".steps",
            "steps",
            |p| p.steps as f64,
            "Error against the number of steps",
        ),
    ];
    for (suffix, x_label, x, what) in charts {
        // A line per label and its meshes as dots of the same colour.
        let lines = series_by_label(points, |_| true, x, SeriesStyle::Line);
        let dots: Vec<Series> = lines
            .iter()
            .enumerate()
            .map(|(i, line)| {
                Series::new(line.name.clone(), line.points.clone(), SeriesStyle::Points)
                    .with_colour(i)
                    .without_legend()
            })
            .collect();
        let series: Vec<Series> = lines.into_iter().chain(dots).collect();
        if let Ok(svg) = line_chart(&Axes::log_log(study.title, x_label, study.error), &series) {
            let file = format!("work_precision/{}{suffix}.svg", study.name);
            files.push((file.clone(), svg.clone()));
            blocks.push(Block::Figure {
                svg,
                file,
                caption: format!("{what}: {}{settings}", study.title),
            });
        }
    }
    let t = table(points);
    let csv = format!("work_precision/{}.csv", study.name);
    files.push((csv.clone(), t.to_csv(stored)));
    blocks.push(Block::Table {
        table: t,
        precision: shown,
        csv: Some(csv),
    });
    (blocks, files)
}

/// Machine-dependent companion of [`blocks`]: the error against the CPU time of each run (wall
/// time of the integration, one thread), as a log-log SVG per study, labelled as in [`blocks`];
/// `None` when no point has a positive time.
pub fn cpu_chart(study: &WorkPrecisionStudy, points: &[WorkPoint]) -> Option<String> {
    // Points, not a line: timings of short runs are noisy and need not grow with N.
    let series = series_by_label(
        points,
        |p| p.wall_time > 0.0,
        |p| p.wall_time,
        SeriesStyle::Points,
    );
    line_chart(
        &Axes::log_log(study.title, "CPU time of the run [s]", study.error),
        &series,
    )
    .ok()
}

/// `study, method, Co, N, steps, l1, wall_time_s` of every study's runs (machine-dependent).
pub fn cpu_table(studies: &[WorkPrecisionStudy], work: &[Vec<WorkPoint>]) -> Table {
    let mut t = Table::new(&["study", "method", "Co", "N", "steps", "l1", "wall_time_s"]);
    for (study, points) in studies.iter().zip(work) {
        for p in points {
            t.push(vec![
                study.name.into(),
                p.method.as_str().into(),
                p.courant.into(),
                p.elements.into(),
                p.steps.into(),
                p.l1.into(),
                p.wall_time.into(),
            ]);
        }
    }
    t
}
