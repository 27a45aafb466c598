//! Work-precision studies: for each scheme, the error against the work it cost (steps and
//! node-steps, deterministic; CPU time in the report's timing section), over a sequence of
//! meshes — "which scheme gives me this accuracy cheapest".

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
    /// Text substitutions making the mesh a list (cases `n<N>-<scheme>-...`).
    pub replacements: &'static [(&'static str, &'static str)],
}

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
    },
    WorkPrecisionStudy {
        name: "fig2_schemes",
        title: "Fig. 2 graded bar at t = 0.5 T, CD and Park (Co = 0.5)",
        scene: "fig2",
        replacements: &[
            ("elements = 100", "elements = [50, 100, 200, 400]"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
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
        &Axes::log_log(study.title, "work: elements x steps", "L1 error / |sigma0|"),
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
