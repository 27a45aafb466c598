//! Work-precision studies: for each scheme, the error against the work it cost (steps and
//! node-steps, deterministic; CPU time in the report's timing section), over a sequence of
//! meshes — "which scheme gives me this accuracy cheapest". Time-stepping studies measure the
//! normalised L1 error of a stress profile; contact studies the L1-in-time error of the contact
//! force over the exact impulse (1D wave theory, methods.md §7).

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
    /// What the error column measures.
    pub error: &'static str,
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
        error: STRESS_L1,
    },
    WorkPrecisionStudy {
        name: "fig5_contact",
        title: "Fig. 5 impact, contact schemes (beta_s = 2500, r = 1, Co = 0.5)",
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
            (
                "schemes = [\"cd-penalty\", \"cd-bipenalty\", \"predictor-corrector\", \"lagrange-multiplier\"]",
                "schemes = [\"cd-bipenalty\", \"predictor-corrector\", \"lagrange-multiplier\"]",
            ),
            ("beta_s = [0.25, 25.0, 2500.0, 2.5e7]", "beta_s = 2500.0"),
        ],
        contact_meshes: &[25, 50, 100, 200, 400, 800],
        error: "L1 force error / impulse",
    },
];

/// One run of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPoint {
    /// Scheme or mass label (the case name without its mesh and Courant parts).
    pub method: String,
    /// Elements.
    pub elements: usize,
    /// Steps.
    pub steps: usize,
    /// Normalised L1 error of the stress.
    pub l1: f64,
    /// Wall time of the integration [s].
    pub wall_time: f64,
}

/// Run a study.
pub fn run(study: &WorkPrecisionStudy) -> Result<Vec<WorkPoint>, String> {
    if !study.contact_meshes.is_empty() {
        return run_contact(study);
    }
    let scene = crate::report::derived_scene(study.name, study.scene, study.replacements)?;
    scene
        .cases
        .par_iter()
        .map(|case| {
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
                elements: r.elements,
                steps: r.steps,
                l1,
                wall_time: r.wall_time.as_secs_f64(),
            })
        })
        .collect()
}

/// A contact study: one derived scene per striker mesh, every case of each; `elements` counts
/// the elements of all bodies, the error is [`crate::contact_study::ContactResult::force_l1_error`].
fn run_contact(study: &WorkPrecisionStudy) -> Result<Vec<WorkPoint>, String> {
    let scenes = study
        .contact_meshes
        .iter()
        .map(|n| {
            let (n, n2) = (n.to_string(), (2 * n).to_string());
            let replacements: Vec<(&str, String)> = study
                .replacements
                .iter()
                .map(|(from, to)| (*from, to.replace("{2n}", &n2).replace("{n}", &n)))
                .collect();
            let borrowed: Vec<(&str, &str)> =
                replacements.iter().map(|(f, t)| (*f, t.as_str())).collect();
            crate::report::derived_scene(study.name, study.scene, &borrowed)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let cases: Vec<&crate::scene::contact::ContactCase> =
        scenes.iter().flat_map(|s| &s.contact).collect();
    cases
        .par_iter()
        .map(|case| {
            let r = crate::contact_study::run_contact(case).map_err(|e| e.to_string())?;
            if let Some(d) = &r.diverged {
                return Err(format!(
                    "study {}: case {} diverged: {d}",
                    study.name, case.name
                ));
            }
            Ok(WorkPoint {
                method: case.name.clone(),
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
        .collect()
}

/// Deterministic table: `method, N, steps, node_steps, l1`.
pub fn table(points: &[WorkPoint]) -> Table {
    let mut t = Table::new(&["method", "N", "steps", "node_steps", "l1"]);
    for p in points {
        t.push(vec![
            p.method.as_str().into(),
            p.elements.into(),
            p.steps.into(),
            (p.elements * p.steps).into(),
            p.l1.into(),
        ]);
    }
    t
}

/// Report blocks (figure of L1 against node-steps per method, and the table) and files.
pub fn blocks(
    study: &WorkPrecisionStudy,
    points: &[WorkPoint],
    shown: Precision,
    stored: Precision,
) -> (Vec<Block>, Vec<(String, String)>) {
    let mut methods: Vec<String> = Vec::new();
    for p in points {
        if !methods.contains(&p.method) {
            methods.push(p.method.clone());
        }
    }
    let series: Vec<Series> = methods
        .iter()
        .map(|m| {
            let pts = points
                .iter()
                .filter(|p| &p.method == m)
                .map(|p| ((p.elements * p.steps) as f64, p.l1))
                .collect();
            Series::new(m.clone(), pts, SeriesStyle::Line)
        })
        .collect();
    let mut blocks = vec![Block::Heading(3, study.title.into())];
    let mut files = Vec::new();
    if let Ok(svg) = line_chart(
        &Axes::log_log(study.title, "work: elements x steps", study.error),
        &series,
    ) {
        let file = format!("work_precision/{}.svg", study.name);
        files.push((file.clone(), svg.clone()));
        blocks.push(Block::Figure {
            svg,
            file,
            caption: format!("Error against work: {}", study.title),
        });
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
/// time of the integration, one thread), as a log-log SVG per study; `None` when no point has a
/// positive time.
pub fn cpu_chart(study: &WorkPrecisionStudy, points: &[WorkPoint]) -> Option<String> {
    let mut methods: Vec<&str> = Vec::new();
    for p in points {
        if !methods.contains(&p.method.as_str()) {
            methods.push(&p.method);
        }
    }
    let series: Vec<Series> = methods
        .iter()
        .map(|m| {
            let pts = points
                .iter()
                .filter(|p| p.method == *m && p.wall_time > 0.0)
                .map(|p| (p.wall_time, p.l1))
                .collect();
            // Points, not a line: timings of short runs are noisy and need not grow with N.
            Series::new(m.to_string(), pts, SeriesStyle::Points)
        })
        .collect();
    line_chart(
        &Axes::log_log(study.title, "CPU time of the run [s]", study.error),
        &series,
    )
    .ok()
}

/// `study, method, N, steps, l1, wall_time_s` of every study's runs (machine-dependent).
pub fn cpu_table(studies: &[WorkPrecisionStudy], work: &[Vec<WorkPoint>]) -> Table {
    let mut t = Table::new(&["study", "method", "N", "steps", "l1", "wall_time_s"]);
    for (study, points) in studies.iter().zip(work) {
        for p in points {
            t.push(vec![
                study.name.into(),
                p.method.as_str().into(),
                p.elements.into(),
                p.steps.into(),
                p.l1.into(),
                p.wall_time.into(),
            ]);
        }
    }
    t
}
