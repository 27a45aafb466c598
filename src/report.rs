//! `courant report`: every built-in scene and the convergence studies in one Markdown report
//! (`index.md`) with its CSV tables, written whole or not at all. Timings (wall times, machine)
//! go to `timing.md` and `timing.csv` only, so the rest of the report changes only when results
//! do (numbers in the Markdown are rounded to 4 significant digits, CSVs keep round-trip
//! precision).

use crate::builtin::{BUILTIN_SCENES, builtin_text};
use crate::document::{self, Block};
use crate::run::{SceneOutcome, run_scene};
use crate::scene::Scene;
use crate::table::{Cell, Precision, Table};
use courant_solver::RunError;
use rayon::prelude::*;
use std::time::Instant;

/// Display precision of the Markdown tables (values below 1e-12, round-off, shown as 0).
const SHOWN: Precision = Precision::Significant {
    digits: 4,
    floor: 1e-12,
};

/// Precision of the report's CSV tables: 10 significant digits, round-off below 1e-12 as 0, so
/// the committed report does not change with the last bits of a platform.
const STORED: Precision = Precision::Significant {
    digits: 10,
    floor: 1e-12,
};

/// An h-refinement study: one scene re-run on a sequence of meshes.
#[derive(Debug, Clone, PartialEq)]
pub struct ConvergenceStudy {
    /// File-friendly name.
    pub name: &'static str,
    /// Heading.
    pub title: &'static str,
    /// What theory predicts (stated beside the observed orders).
    pub expected: &'static str,
    /// The built-in scene it starts from.
    pub scene: &'static str,
    /// Text substitutions applied to the scene (one case per element count must remain).
    pub replacements: &'static [(&'static str, &'static str)],
    /// What theory allows for the L1, L2 and max errors (`None`: measured, no theory to check).
    pub bands: [Option<OrderBand>; 3],
}

/// What theory allows for one error norm of a convergence study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OrderBand {
    /// The order fitted on the finest [`FIT_LEVELS`] meshes lies in `[min, max]`.
    Order {
        /// Lowest order admitted.
        min: f64,
        /// Highest order admitted.
        max: f64,
    },
    /// Exact up to round-off: the error is at most `max_error` on every mesh.
    Exact {
        /// Largest error admitted.
        max_error: f64,
    },
}

/// What a convergence study's fitted order says of one norm.
#[derive(Debug, Clone, PartialEq)]
pub struct OrderVerdict {
    /// `l1`, `l2` or `linf`.
    pub norm: &'static str,
    /// Order fitted on the finest [`FIT_LEVELS`] meshes (`None` at round-off).
    pub fitted: Option<f64>,
    /// What theory allows, as text (`-` where it gives nothing).
    pub expected: String,
    /// `None` for a norm with no band (measured only).
    pub pass: Option<bool>,
}

/// Picks one error norm of a mesh level.
type NormOf = fn(&Level) -> f64;

/// Meshes the least-squares order is fitted on (the finest ones).
pub const FIT_LEVELS: usize = 3;

/// The orders of a dispersive step front (methods.md §3; the bands of
/// `tests/data/airy_front_convergence.csv`).
const AIRY_FRONT: [Option<OrderBand>; 3] = [
    Some(OrderBand::Order {
        min: 0.42,
        max: 0.56,
    }),
    Some(OrderBand::Order {
        min: 0.30,
        max: 0.37,
    }),
    Some(OrderBand::Order {
        min: -0.10,
        max: 0.10,
    }),
];

/// The dispersive step front of CD with a consistent, averaged or reciprocal mass: L1 and L2 as
/// [`AIRY_FRONT`]; the max error does not converge (order at most 0.1), but these masses reach
/// its bounded plateau (jump plus overshoot, below 1.3) from below on the meshes studied (AMM(1/2)
/// at 1/2 of its critical Courant number: 0.19 at N = 50, 0.62 at 6400, 0.66 at 12800), so the
/// fitted order may dip to -0.25.
const AIRY_FRONT_MASSES: [Option<OrderBand>; 3] = [
    AIRY_FRONT[0],
    AIRY_FRONT[1],
    Some(OrderBand::Order {
        min: -0.25,
        max: 0.10,
    }),
];

/// First order in every norm.
const FIRST_ORDER: Option<OrderBand> = Some(OrderBand::Order { min: 0.9, max: 1.1 });

/// The Fig. 1 bar with one mass kind at 1/2 of its critical Courant number, N = 50 … 12800, at
/// t = 0.5 T: `mass_kind_study!(name, mass key, mass label, its critical Courant number)`.
macro_rules! mass_kind_study {
    ($name:literal, $mass:literal, $label:literal, $critical:literal) => {
        ConvergenceStudy {
            name: $name,
            title: concat!(
                "Fig. 1 bar, CD with ",
                $label,
                " at Co = 1/2 of ",
                $critical,
                ", t = 0.5 T"
            ),
            expected: "as lumped CD at Co < 1: a dispersive step front (cubic leading dispersion error, methods.md §3 and §5), L1 ~ h^(1/2), L2 ~ h^(1/3), Linf does not converge",
            bands: AIRY_FRONT_MASSES,
            scene: "fig1_masses",
            replacements: &[
                (
                    "elements = 100",
                    "elements = [50, 100, 200, 400, 800, 1600, 3200, 6400, 12800]",
                ),
                (
                    "mass = [\"lmm\", \"cmm\", \"amm\", \"rmm\"]",
                    concat!("mass = \"", $mass, "\""),
                ),
                ("courant = [1.0, 0.5]", "courant = 0.5"),
                ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
                ("history_points = [0.0, 0.5]", "history_points = []"),
            ],
        }
    };
}

/// The built-in convergence studies.
pub const CONVERGENCE_STUDIES: &[ConvergenceStudy] = &[
    ConvergenceStudy {
        name: "fig1_co0.5",
        title: "Fig. 1 bar, lumped CD at Co = 0.5, t = 0.5 T",
        expected: "L1 ~ h^(1/2), L2 ~ h^(1/3), Linf does not converge (dispersive step front, methods.md §3)",
        bands: AIRY_FRONT,
        scene: "fig1",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600, 3200, 6400, 12800]",
            ),
            ("courant = [1.0, 0.5, 0.1]", "courant = 0.5"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
            ("history_points = [0.0, 0.5]", "history_points = []"),
        ],
    },
    ConvergenceStudy {
        name: "fig1_co1",
        title: "Fig. 1 bar, lumped CD at Co = 1, t = 0.5 T",
        expected: "exact to round-off on every mesh (methods.md §3)",
        bands: [Some(OrderBand::Exact { max_error: 1e-10 }); 3],
        scene: "fig1",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600, 3200, 6400, 12800]",
            ),
            ("courant = [1.0, 0.5, 0.1]", "courant = 1.0"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
            ("history_points = [0.0, 0.5]", "history_points = []"),
        ],
    },
    mass_kind_study!("fig1_cmm", "cmm", "CMM", "1/sqrt(3)"),
    mass_kind_study!("fig1_amm", "amm", "AMM(1/2)", "sqrt(2/3)"),
    mass_kind_study!("fig1_rmm", "rmm", "RMM(1/2)", "sqrt(2/3)"),
    ConvergenceStudy {
        name: "layered_co1",
        title: "Two-layer bar (impedance ratio 16) on equal-transit meshes, lumped CD at Co = 1, t = 0.5, 1.2 and 2.6 T",
        expected: "exact to round-off on every mesh: interfaces at nodes, every element at its own Courant number 1 (methods.md §4); round-off stays below the 1e-14 N^2 of methods.md §3 (3e-10 measured at N = 3200, where that bound is 1e-7)",
        bands: [Some(OrderBand::Exact { max_error: 1e-9 }); 3],
        scene: "layered",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600, 3200]",
            ),
            ("scheme = [\"cd\", \"park-lts\"]", "scheme = \"cd\""),
            ("courant = [1.0, 0.5]", "courant = 1.0"),
        ],
    },
    ConvergenceStudy {
        name: "fig2_park_lts",
        title: "Fig. 2 graded bar, Park with local stepping, Co = 0.5, t = 0.5 T",
        expected: "no closed-form order; compare with CD below",
        bands: [None; 3],
        scene: "fig2",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600]",
            ),
            (
                "scheme = [\"cd\", \"park-global\", \"park-lts\"]",
                "scheme = \"park-lts\"",
            ),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
    },
    ConvergenceStudy {
        name: "fig2_cd",
        title: "Fig. 2 graded bar, lumped CD, Co = 0.5, t = 0.5 T",
        expected: "step front: L1 ~ h^(1/2) at best; the soft part runs far below its own Courant limit",
        bands: [None; 3],
        scene: "fig2",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600]",
            ),
            (
                "scheme = [\"cd\", \"park-global\", \"park-lts\"]",
                "scheme = \"cd\"",
            ),
            ("theta = 0.5\npark_variant = \"free\"\n", ""),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
    },
    ConvergenceStudy {
        name: "fig2_equal_transit",
        title: "Fig. 2 graded bar on equal-transit-time meshes, lumped CD at Co = 1, t = 0.5 T",
        expected: "first order: the exact layered (Goupillaud) model of the graded bar (methods.md §4)",
        bands: [FIRST_ORDER; 3],
        scene: "fig2",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600]\nspacing = \"equal-transit\"",
            ),
            (
                "scheme = [\"cd\", \"park-global\", \"park-lts\"]",
                "scheme = \"cd\"",
            ),
            ("theta = 0.5\npark_variant = \"free\"\n", ""),
            ("courant = 0.5", "courant = 1.0"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
    },
];

/// One mesh of a convergence study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Level {
    /// Elements.
    pub elements: usize,
    /// Time step.
    pub dt: f64,
    /// Steps.
    pub steps: usize,
    /// Normalised L1, L2 and max errors.
    pub l1: f64,
    /// L2 error.
    pub l2: f64,
    /// Max error.
    pub linf: f64,
    /// Wall time of the run, in seconds.
    pub wall_time: f64,
}

/// Errors against the exact solution on each mesh of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct ConvergenceResult {
    /// The study.
    pub study: ConvergenceStudy,
    /// One entry per mesh, coarse to fine.
    pub levels: Vec<Level>,
}

impl ConvergenceResult {
    /// Observed order between level `i - 1` and `i` of the norm picked by `pick`.
    fn order(&self, i: usize, pick: fn(&Level) -> f64) -> Option<f64> {
        let (a, b) = (&self.levels[i - 1], &self.levels[i]);
        let (ea, eb) = (pick(a), pick(b));
        (ea > 1e-12 && eb > 1e-12)
            .then(|| (ea / eb).ln() / (b.elements as f64 / a.elements as f64).ln())
    }

    /// Least-squares order on the finest [`FIT_LEVELS`] meshes, `-slope` of `ln e` against
    /// `ln N`; `None` when an error there is at round-off level (below 1e-12).
    pub fn fitted_order(&self, pick: fn(&Level) -> f64) -> Option<f64> {
        let finest = &self.levels[self.levels.len().saturating_sub(FIT_LEVELS)..];
        if finest.len() < 2 || finest.iter().any(|l| pick(l) <= 1e-12) {
            return None;
        }
        let points: Vec<(f64, f64)> = finest
            .iter()
            .map(|l| ((l.elements as f64).ln(), pick(l).ln()))
            .collect();
        let count = points.len() as f64;
        let (mx, my) = points
            .iter()
            .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / count, b + y / count));
        let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
            (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
        });
        Some(-sxy / sxx)
    }

    /// One verdict per norm (L1, L2, max).
    pub fn verdicts(&self) -> Vec<OrderVerdict> {
        let picks: [(&str, NormOf); 3] = [("l1", |l| l.l1), ("l2", |l| l.l2), ("linf", |l| l.linf)];
        picks
            .iter()
            .zip(self.study.bands)
            .map(|(&(norm, pick), band)| {
                // Under an exactness band the errors are round-off: a slope fitted to them is
                // noise, not an order, and is left out.
                let fitted = match band {
                    Some(OrderBand::Exact { .. }) => None,
                    _ => self.fitted_order(pick),
                };
                let (expected, pass) = match band {
                    None => ("-".to_string(), None),
                    Some(OrderBand::Order { min, max }) => (
                        format!("order in [{min}, {max}]"),
                        Some(fitted.is_some_and(|p| (min..=max).contains(&p))),
                    ),
                    Some(OrderBand::Exact { max_error }) => (
                        format!("error <= {max_error:e} on every mesh"),
                        Some(self.levels.iter().all(|l| pick(l) <= max_error)),
                    ),
                };
                OrderVerdict {
                    norm,
                    fitted,
                    expected,
                    pass,
                }
            })
            .collect()
    }

    /// `norm, fitted_order, expected, verdict` (fitted on the finest [`FIT_LEVELS`] meshes).
    pub fn verdict_table(&self) -> Table {
        let mut t = Table::new(&["norm", "fitted_order", "expected", "verdict"]);
        for v in self.verdicts() {
            t.push(vec![
                v.norm.into(),
                v.fitted.into(),
                v.expected.into(),
                match v.pass {
                    None => "measured",
                    Some(true) => "pass",
                    Some(false) => "FAIL",
                }
                .into(),
            ]);
        }
        t
    }

    /// `N, dt, steps, l1, order_l1, l2, order_l2, linf, order_linf` (orders between successive
    /// meshes; empty where an error is at round-off level).
    pub fn table(&self) -> Table {
        let mut t = Table::new(&[
            "N",
            "dt",
            "steps",
            "l1",
            "order_l1",
            "l2",
            "order_l2",
            "linf",
            "order_linf",
        ]);
        for (i, level) in self.levels.iter().enumerate() {
            let order = |pick| {
                if i == 0 {
                    Cell::Empty
                } else {
                    self.order(i, pick).into()
                }
            };
            t.push(vec![
                level.elements.into(),
                level.dt.into(),
                level.steps.into(),
                level.l1.into(),
                order(|l| l.l1),
                level.l2.into(),
                order(|l| l.l2),
                level.linf.into(),
                order(|l| l.linf),
            ]);
        }
        t
    }
}

/// Parse a study's scene.
fn study_scene(study: &ConvergenceStudy) -> Result<Scene, String> {
    derived_scene(study.name, study.scene, study.replacements)
}

/// A study's scene: the built-in scene `scene` without its expectations, with each
/// `(from, to)` substitution applied once; an error names the study when a substitution no
/// longer matches (the built-in scene changed under the study).
pub fn derived_scene(
    name: &str,
    scene: &str,
    replacements: &[(&str, &str)],
) -> Result<Scene, String> {
    let mut text = builtin_text(scene)
        .ok_or_else(|| format!("no built-in scene {scene}"))?
        .to_string();
    if let Some(i) = text.find("[[expect]]") {
        text.truncate(i);
    }
    for (from, to) in replacements {
        if !text.contains(from) {
            return Err(format!(
                "study {name}: scene {scene} no longer contains {from:?}"
            ));
        }
        text = text.replacen(from, to, 1);
    }
    Scene::parse(name, &format!("study {name}"), &text).map_err(|e| e.to_string())
}

/// Run a convergence study.
pub fn run_study(study: &ConvergenceStudy) -> Result<ConvergenceResult, String> {
    let scene = study_scene(study)?;
    let levels = scene
        .cases
        .par_iter()
        .map(|case| {
            let r = crate::run_case(case).map_err(|e| e.to_string())?;
            let n = r
                .profiles
                .first()
                .and_then(|p| p.norms)
                .ok_or("no profile norms")?;
            Ok(Level {
                elements: r.elements,
                dt: r.dt,
                steps: r.steps,
                l1: n.l1,
                l2: n.l2,
                linf: n.linf,
                wall_time: r.wall_time.as_secs_f64(),
            })
        })
        .collect::<Vec<Result<_, String>>>();
    let levels = crate::run::in_order(levels)?;
    Ok(ConvergenceResult {
        study: study.clone(),
        levels,
    })
}

/// A generated report: files relative to the report directory.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// `(relative path, contents)`.
    pub files: Vec<(String, String)>,
    /// True when every expectation held.
    pub passed: bool,
}

/// Generate the report for `scenes` (all built-in ones from the CLI) and `studies`, running
/// scenes, studies and the cases inside each scene in parallel (the results do not depend on the
/// thread count: every case is independent and results are collected in order).
pub fn generate(scenes: &[Scene], studies: &[ConvergenceStudy]) -> Result<Report, String> {
    let started = Instant::now();
    // Progress on a terminal only (indicatif draws to stderr and hides itself otherwise).
    let progress = indicatif::ProgressBar::new((scenes.len() + studies.len()) as u64);
    progress.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let outcomes = scenes
        .par_iter()
        .map(|scene| {
            let t0 = Instant::now();
            let outcome = run_scene(scene)
                .map(|o| (o, t0.elapsed().as_secs_f64()))
                .map_err(|e: RunError| format!("{}: {e}", scene.name));
            progress.set_message(scene.name.clone());
            progress.inc(1);
            outcome
        })
        .collect::<Vec<Result<(SceneOutcome, f64), String>>>();
    let outcomes = crate::run::in_order(outcomes)?;
    let convergence = studies
        .par_iter()
        .map(|study| {
            let result = run_study(study);
            progress.set_message(study.name);
            progress.inc(1);
            result
        })
        .collect::<Vec<Result<ConvergenceResult, String>>>();
    let convergence = crate::run::in_order(convergence)?;
    progress.finish_and_clear();
    let work = crate::run::in_order(
        crate::work_precision::WORK_PRECISION_STUDIES
            .par_iter()
            .map(crate::work_precision::run)
            .collect(),
    )?;
    let total = started.elapsed().as_secs_f64();

    let mut files = Vec::new();
    let mut doc = vec![
        Block::Heading(1, "courant verification report".into()),
        Block::Paragraph(
            "Every built-in scene of courant (Kolman et al.'s Figs. 1, 2, 3, 5, 6 and companions) against its \
             analytic reference, with the verdict of every expectation, then h-refinement studies. Regenerate \
             with `cargo run --release -- report`; timings are in `timing.md`, every table also as CSV beside it."
                .into(),
        ),
    ];
    let failed: Vec<String> = outcomes
        .iter()
        .zip(scenes)
        .flat_map(|((o, _), s)| {
            o.verdicts
                .iter()
                .filter(|v| !v.pass)
                .map(move |v| format!("{}: {}", s.name, v.describe()))
        })
        .chain(convergence.iter().flat_map(|c| {
            c.verdicts()
                .into_iter()
                .filter(|v| v.pass == Some(false))
                .map(|v| {
                    format!(
                        "convergence {}: {} fitted order {}, expected {}",
                        c.study.name,
                        v.norm,
                        v.fitted.map_or("-".into(), |p| format!("{p:.3}")),
                        v.expected
                    )
                })
        }))
        .collect();
    let count: usize = outcomes
        .iter()
        .map(|(o, _)| o.verdicts.len())
        .sum::<usize>()
        + convergence
            .iter()
            .map(|c| c.verdicts().iter().filter(|v| v.pass.is_some()).count())
            .sum::<usize>();
    doc.push(Block::Paragraph(format!(
        "{count} expectations (scene expectations and convergence-order bands), {} failed.",
        failed.len()
    )));
    if !failed.is_empty() {
        doc.push(Block::List(failed.clone()));
    }
    doc.push(Block::Heading(2, "Contents".into()));
    let mut contents: Vec<String> = scenes
        .iter()
        .map(|s| format!("{} — {}", s.name, s.description))
        .collect();
    contents.push("Convergence studies".into());
    contents.push("Work and precision".into());
    contents.push("Stability at the extremes".into());
    doc.push(Block::List(contents));
    for ((outcome, _), scene) in outcomes.iter().zip(scenes) {
        doc.push(Block::Heading(2, scene.name.clone()));
        doc.push(Block::Paragraph(format!(
            "{} Source of truth: {}.",
            scene.description, scene.source
        )));
        for (svg_name, caption, svg) in crate::report_figures::scene_figures(scene, outcome) {
            let file = format!("{}/{svg_name}", scene.name);
            files.push((file.clone(), svg.clone()));
            doc.push(Block::Figure { svg, file, caption });
        }
        for (file, table) in scene_tables(outcome) {
            let csv = format!("{}/{file}", scene.name);
            files.push((csv.clone(), table.to_csv(STORED)));
            doc.push(Block::Table {
                table,
                precision: SHOWN,
                csv: Some(csv),
            });
        }
        if !outcome.verdicts.is_empty() {
            doc.push(Block::Paragraph("Expectations:".into()));
            doc.push(Block::List(
                outcome.verdicts.iter().map(|v| v.describe()).collect(),
            ));
        }
    }
    doc.push(Block::Heading(2, "Convergence studies".into()));
    doc.push(Block::Paragraph(
        "Errors of element stresses against the exact element averages, normalised by |sigma0| and L; \
         observed orders between successive meshes, and the order fitted by least squares on the finest \
         three meshes, checked against the band theory allows where it gives one."
            .into(),
    ));
    for c in &convergence {
        let table = c.table();
        doc.push(Block::Heading(3, c.study.title.into()));
        doc.push(Block::Paragraph(format!("Expected: {}", c.study.expected)));
        if let Some(svg) = crate::report_figures::convergence_figure(c) {
            let file = format!("convergence/{}.svg", c.study.name);
            files.push((file.clone(), svg.clone()));
            doc.push(Block::Figure {
                svg,
                file,
                caption: format!("Errors against N: {}", c.study.title),
            });
        }
        let csv = format!("convergence/{}.csv", c.study.name);
        files.push((csv.clone(), table.to_csv(STORED)));
        doc.push(Block::Table {
            table,
            precision: SHOWN,
            csv: Some(csv),
        });
        let verdicts = c.verdict_table();
        let csv = format!("convergence/{}.orders.csv", c.study.name);
        files.push((csv.clone(), verdicts.to_csv(STORED)));
        doc.push(Block::Table {
            table: verdicts,
            precision: SHOWN,
            csv: Some(csv),
        });
    }
    doc.push(Block::Heading(2, "Work and precision".into()));
    doc.push(Block::Paragraph(
        "Error against work (elements x steps, machine-independent) per scheme or mass kind over a sequence \
         of meshes: the cheapest way to a given accuracy is the lowest curve. Stress studies measure the \
         normalised L1 error of the profile, the contact study the L1-in-time error of the contact force over \
         the exact impulse (elements of both bars). Each run's Courant number (relative to the stiffest \
         element) and its scheme's exact critical one are in the Co and Co_crit columns; a scheme whose stable \
         step is far below the others' runs at its own, stated in its label (CD with penalty at beta_s = 2500 \
         at 0.9 of its critical Courant number 0.0200). A node-step does not cost the same in every scheme: the \
         benchmark table in `timing.md` gives ns per node-step of each integrator (`cargo bench`), and the CPU \
         times of these runs are there too."
            .into(),
    ));
    for (study, points) in crate::work_precision::WORK_PRECISION_STUDIES
        .iter()
        .zip(&work)
    {
        let (blocks, more) = crate::work_precision::blocks(study, points, SHOWN, STORED);
        doc.extend(blocks);
        files.extend(more);
    }
    let stability: Vec<crate::stability_table::StabilityRow> = outcomes
        .iter()
        .zip(scenes)
        .filter(|(_, s)| crate::stability_table::STABILITY_SCENES.contains(&s.name.as_str()))
        .flat_map(|((o, _), s)| {
            let stepping = o
                .results
                .iter()
                .map(|r| crate::stability_table::StabilityRow::new(&s.name, r));
            let contact = o
                .contact
                .iter()
                .map(|r| crate::stability_table::StabilityRow::from_contact(&s.name, r));
            stepping.chain(contact).collect::<Vec<_>>()
        })
        .collect();
    let agreeing = stability
        .iter()
        .filter(|r| r.agrees() == Some(true))
        .count();
    let predicted_rows = stability.iter().filter(|r| r.agrees().is_some()).count();
    let listed = |verdict: Option<bool>| -> Vec<String> {
        stability
            .iter()
            .filter(|r| r.agrees() == verdict)
            .map(|r| format!("{}/{} ({}, {})", r.scene, r.case, r.predicted, r.observed()))
            .collect()
    };
    let disagreeing = listed(Some(false));
    let unpredicted = listed(None);
    doc.push(Block::Heading(2, "Stability at the extremes".into()));
    doc.push(Block::Paragraph(format!(
        "Every time-stepping case of the stability scenes ({}): the step against the exact limit of its \
         scheme (column `limit`: 2/omega_max of the assembled system for central difference with any mass; \
         alpha_e = dt/dt_e <= 1 in every element for Park's scheme, whose runs above it use the true alpha; \
         that bound is the limit on a uniform mesh and only sufficient on a graded one, where a step above it \
         is `beyond bound`, not predicted), \
         the verdict theory predicts (marginal within 1e-9 of the limit), what the run did, and where \
         courant's divergence guard stopped it. Rows at 0.99, 1.00 and 1.01 of the closed-form critical Courant \
         number (stability_extremes, layered_1e4: 1.00 is a hair below the finite mesh's exact limit) stand \
         beside rows in units of the exact limit with the step kept exactly (stability_exact, stability_park, \
         graded_1e4), where dt/dt_crit reads 0.99, 1.00 and 1.01 to round-off. Contact rows \
         (contact_extremes, beta_s up to 1e8) take the exact critical step of their scheme; between it and the \
         contact-free limit linear theory of the closed contact predicts growth, which the unilateral contact \
         bounds by opening (`contact-unstable`: the run completes). `stable` promises bounded energy: a \
         completed run whose energy_ratio (contact: the energy central difference conserves, 1/2 v^{{n-1/2}} M v^{{n+1/2}} + 1/2 u K u, left in the bars at the end over the initial energy; \
         time stepping: largest T + U over the largest energy supplied) exceeds {} is observed as `energy \
         growth`, and disagrees where stability was predicted. Of {} rows, {} carry a prediction: {agreeing} agree \
         with it and {} disagree{}; {} {}. The contact stability sweep of the solver's eigenvalues against the \
         closed forms (beta_s up to 1e8) is in the fig3 section; the closed forms themselves up to beta_s = 1e12 \
         are in the last table below.",
        crate::stability_table::STABILITY_SCENES.join(", "),
        crate::stability_table::ENERGY_BAND,
        stability.len(),
        predicted_rows,
        disagreeing.len(),
        if disagreeing.is_empty() {
            String::new()
        } else {
            format!(": {}", disagreeing.join("; "))
        },
        unpredicted.len(),
        if unpredicted.is_empty() {
            "run beyond a sufficient bound".to_string()
        } else {
            format!(
                "ran beyond a sufficient bound, where nothing is predicted: {}",
                unpredicted.join("; ")
            )
        }
    )));
    let table = crate::stability_table::stability_table(&stability);
    files.push(("stability/extremes.csv".into(), table.to_csv(STORED)));
    doc.push(Block::Table {
        table,
        precision: SHOWN,
        csv: Some("stability/extremes.csv".into()),
    });
    doc.push(Block::Paragraph(CONTACT_CLOSED_FORMS_TEXT.into()));
    let table = contact_closed_form_table().map_err(|e| format!("contact closed forms: {e}"))?;
    files.push((
        "stability/contact_closed_forms.csv".into(),
        table.to_csv(STORED),
    ));
    doc.push(Block::Table {
        table,
        precision: SHOWN,
        csv: Some("stability/contact_closed_forms.csv".into()),
    });
    doc.push(Block::Heading(2, "How this report was made".into()));
    doc.push(Block::Paragraph(format!(
        "By `cargo run --release -- report` (courant {}): every built-in scene ({} of them) and {} \
         convergence studies, their scenes, studies and cases run in parallel; the content is identical whatever the thread count. The \
         commit, date, CPU, thread count and rustc of this run are in `timing.md`, with the wall times: \
         they change from run to run and machine to machine, while everything on this page changes only \
         when a result does (CI regenerates the report and fails when this page is out of date).",
        env!("CARGO_PKG_VERSION"),
        scenes.len(),
        convergence.len()
    )));
    files.push(("index.md".into(), document::markdown(&doc)));
    files.push((
        "index.html".into(),
        document::html("courant verification report", &doc),
    ));

    // Timings: everything that changes from run to run.
    let mut timing = Table::new(&["item", "wall_time_s"]);
    for ((_, seconds), scene) in outcomes.iter().zip(scenes) {
        timing.push(vec![
            format!("scene {}", scene.name).into(),
            (*seconds).into(),
        ]);
    }
    for c in &convergence {
        for level in &c.levels {
            timing.push(vec![
                format!("study {} N = {}", c.study.name, level.elements).into(),
                level.wall_time.into(),
            ]);
        }
    }
    timing.push(vec!["total (parallel)".into(), total.into()]);
    let mut tmd = String::from("# Timings\n\n");
    tmd += &format!(
        "Generated {} from commit `{}` on {}; {} threads; `{}`.\n\n",
        crate::clock::date(),
        commit(),
        cpu(),
        rayon::current_num_threads(),
        rustc()
    );
    tmd += &timing.to_markdown(Precision::Significant {
        digits: 3,
        floor: 0.0,
    });
    tmd += "\n## Error against CPU time\n\n\
            The work-precision runs of the report against the wall time of their integration (one thread \
            each, on this machine; short runs are noisy). The same points against elements x steps are in \
            `index.md`.\n\n";
    for (study, points) in crate::work_precision::WORK_PRECISION_STUDIES
        .iter()
        .zip(&work)
    {
        if let Some(svg) = crate::work_precision::cpu_chart(study, points) {
            let file = format!("timing.work_precision_{}.svg", study.name);
            tmd += &format!("![{}: error against CPU time]({file})\n\n", study.title);
            files.push((file, svg));
        }
    }
    let cpu =
        crate::work_precision::cpu_table(crate::work_precision::WORK_PRECISION_STUDIES, &work);
    tmd += &cpu.to_markdown(Precision::Significant {
        digits: 3,
        floor: 0.0,
    });
    files.push((
        "timing.work_precision.csv".into(),
        cpu.to_csv(Precision::RoundTrip),
    ));
    tmd += "\n## Benchmarks\n\n";
    match crate::bench_table::bench_table(std::path::Path::new("target/criterion")) {
        Some(bench) => {
            tmd += "Criterion medians from `target/criterion` (run `cargo bench` to refresh), per node-step, beside a \
                    bandwidth model: the bytes of arrays each node-step touches and the rate that implies, and the \
                    machine's reach at the same N, the STREAM triad `a = b + s c` (McCalpin 1995; `memory_triad`, \
                    24 B per element): `fraction_of_triad` is how close to this machine's limit each step runs. Up to \
                    N = 1e5 the arrays stay in cache; at 1e6 and beyond (triad at 4e6) the rate is the memory bandwidth's.\n\n";
            tmd += &bench.to_markdown(Precision::Significant {
                digits: 3,
                floor: 0.0,
            });
            files.push((
                "timing.benchmarks.csv".into(),
                bench.to_csv(Precision::RoundTrip),
            ));
        }
        None => {
            tmd += "No criterion results found in `target/criterion`: run `cargo bench` first.\n"
        }
    }
    files.push(("timing.md".into(), tmd));
    files.push(("timing.csv".into(), timing.to_csv(Precision::RoundTrip)));
    Ok(Report {
        files,
        passed: failed.is_empty(),
    })
}

/// The deterministic tables of a scene (wall-time columns dropped), by file name: what a report
/// keeps of `courant run`'s output, and what `courant check --baseline <report>` compares.
fn scene_tables(o: &SceneOutcome) -> Vec<(String, Table)> {
    use crate::baseline::report_tables as t;
    let drop = ["wall_time_s"];
    let mut tables = Vec::new();
    if !o.results.is_empty() {
        tables.push((
            t::SUMMARY.to_string(),
            crate::results::summary_table(&o.results).without(&drop),
        ));
        tables.push((
            t::NORMS.to_string(),
            crate::results::norms_table(&o.results),
        ));
    }
    if !o.spectra.is_empty() {
        tables.push((
            t::SUMMARY.to_string(),
            crate::results::spectrum_summary_table(&o.spectra).without(&drop),
        ));
    }
    if !o.dispersion.is_empty() {
        tables.push((
            t::DISPERSION.to_string(),
            crate::dispersion::dispersion_table(&o.dispersion),
        ));
    }
    if !o.contact.is_empty() {
        tables.push((
            t::SUMMARY.to_string(),
            crate::contact_study::contact_summary_table(&o.contact).without(&drop),
        ));
    }
    for s in &o.sweeps {
        tables.push((
            t::STABILITY.to_string(),
            crate::contact_study::sweep_table(s),
        ));
    }
    tables.push((
        t::EXPECTATIONS.to_string(),
        crate::results::expectations_table(&o.verdicts),
    ));
    tables
}

/// The built-in scenes, parsed.
pub fn builtin_scenes() -> Result<Vec<Scene>, String> {
    BUILTIN_SCENES
        .iter()
        .map(|(name, _)| {
            crate::builtin::builtin_scene(name)
                .unwrap_or_else(|| {
                    Err(crate::scene::SceneError {
                        file: name.to_string(),
                        line: 0,
                        column: 0,
                        key: String::new(),
                        message: "missing".into(),
                    })
                })
                .map_err(|e| e.to_string())
        })
        .collect()
}

fn cpu() -> String {
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "an unknown CPU".into());
    format!(
        "{model} ({} logical cores)",
        std::thread::available_parallelism().map_or(1, |n| n.get())
    )
}

/// The commit the report was made from (`git describe --always --dirty`), or "unknown".
fn commit() -> String {
    std::process::Command::new("git")
        .args(["describe", "--always", "--dirty"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|| "unknown".into())
}

fn rustc() -> String {
    std::process::Command::new("rustc")
        .arg("--version")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|| "rustc version unknown".into())
}

/// The text above the table of [`contact_closed_form_table`].
const CONTACT_CLOSED_FORMS_TEXT: &str = "Closed-form critical Courant numbers of contact with a rigid \
     wall (semi-infinite uniform lumped bar, central difference; `courant-references`, methods.md §7) at large \
     beta_s, each beside its large-beta_s limit: sqrt(2/beta_s) for penalty only (r = -), 1/sqrt(r) for bipenalty \
     with r > 1, 1 for r <= 1. scaled_difference = beta_s (Cr/limit - 1) stands beside scaled_first_order, \
     beta_s times the leading term of that difference in 1/beta_s: -1/2 for penalty only, r(1 - s)/(1 + s) \
     with s = 1/(sqrt(r) + sqrt(r - 1))^2 for r > 1, 0 for r <= 1. They agree up to beta_s = 1e12, where the \
     difference itself is below 1e-11: the closed forms stay accurate there, free of cancellation.";

/// The penalty stiffnesses of [`contact_closed_form_table`].
const CLOSED_FORM_BETAS: [f64; 4] = [1e6, 1e8, 1e10, 1e12];

/// The penalty ratios of [`contact_closed_form_table`] (`None`: penalty only).
const CLOSED_FORM_RATIOS: [Option<f64>; 4] = [None, Some(0.25), Some(1.0), Some(4.0)];

/// One row of [`contact_closed_form_table`], unrounded.
#[derive(Debug, Clone, Copy, PartialEq)]
struct ClosedFormRow {
    beta_s: f64,
    /// `None`: penalty only.
    r: Option<f64>,
    /// The closed-form critical Courant number.
    cr: f64,
    /// Its limit as beta_s -> inf at fixed r.
    limit: f64,
    /// The leading term of `cr/limit - 1` in 1/beta_s.
    first_order: f64,
}

/// The closed-form contact critical Courant numbers of `courant-references` at beta_s = 1e6 …
/// 1e12, penalty only and bipenalty r = 1/4, 1, 4, beside their large-beta_s limits.
fn contact_closed_form_rows() -> Result<Vec<ClosedFormRow>, courant_references::ReferenceError> {
    use courant_references::contact::{
        signorini_critical_courant_penalty, signorini_critical_courant_ratio,
    };
    let mut rows = Vec::new();
    for r in CLOSED_FORM_RATIOS {
        for beta_s in CLOSED_FORM_BETAS {
            let row = match r {
                None => ClosedFormRow {
                    beta_s,
                    r,
                    cr: signorini_critical_courant_penalty(beta_s)?,
                    limit: (2.0 / beta_s).sqrt(),
                    first_order: -1.0 / (2.0 * beta_s),
                },
                Some(r) if r > 1.0 => {
                    let s = 1.0 / (r.sqrt() + (r - 1.0).sqrt()).powi(2);
                    ClosedFormRow {
                        beta_s,
                        r: Some(r),
                        cr: signorini_critical_courant_ratio(beta_s, r)?,
                        limit: 1.0 / r.sqrt(),
                        first_order: r / beta_s * (1.0 - s) / (1.0 + s),
                    }
                }
                Some(r) => ClosedFormRow {
                    beta_s,
                    r: Some(r),
                    cr: signorini_critical_courant_ratio(beta_s, r)?,
                    limit: 1.0,
                    first_order: 0.0,
                },
            };
            rows.push(row);
        }
    }
    Ok(rows)
}

/// The table of [`contact_closed_form_rows`]: `beta_s, r, cr_closed_form, cr_limit,
/// scaled_difference, scaled_first_order`, the differences times beta_s (O(1) numbers: the
/// differences themselves fall below the report's display floor for round-off).
///
/// # Errors
/// A closed form refuses its parameters (it cannot for these fixed, valid values).
fn contact_closed_form_table() -> Result<Table, courant_references::ReferenceError> {
    let mut table = Table::new(&[
        "beta_s",
        "r",
        "cr_closed_form",
        "cr_limit",
        "scaled_difference",
        "scaled_first_order",
    ]);
    for row in contact_closed_form_rows()? {
        table.push(vec![
            row.beta_s.into(),
            row.r.into(),
            row.cr.into(),
            row.limit.into(),
            (row.beta_s * (row.cr / row.limit - 1.0)).into(),
            (row.beta_s * row.first_order).into(),
        ]);
    }
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn study_with(errors: &[(usize, f64)], bands: [Option<OrderBand>; 3]) -> ConvergenceResult {
        ConvergenceResult {
            study: ConvergenceStudy {
                bands,
                ..CONVERGENCE_STUDIES[0]
            },
            levels: errors
                .iter()
                .map(|&(elements, e)| Level {
                    elements,
                    dt: 1.0 / elements as f64,
                    steps: elements,
                    l1: e,
                    l2: e,
                    linf: 0.3,
                    wall_time: 0.0,
                })
                .collect(),
        }
    }

    #[test]
    fn fitted_order_is_the_least_squares_slope_of_the_finest_meshes() {
        // e = 2 N^(-1/2) on the finest three meshes; the coarse one is off the line and ignored.
        let c = study_with(
            &[
                (50, 1.0),
                (100, 2.0 / 10.0),
                (200, 2.0 / 200f64.sqrt()),
                (400, 2.0 / 20.0),
            ],
            AIRY_FRONT,
        );
        assert!((c.fitted_order(|l| l.l1).unwrap() - 0.5).abs() < 1e-12);
        let verdicts = c.verdicts();
        assert_eq!(
            verdicts[0].pass,
            Some(true),
            "L1 order 1/2 is in [0.42, 0.56]"
        );
        assert_eq!(
            verdicts[1].pass,
            Some(false),
            "L2 order 1/2 is outside [0.30, 0.37]"
        );
        assert_eq!(
            verdicts[2].pass,
            Some(true),
            "a constant max error has order 0"
        );
        let exact = study_with(
            &[(50, 0.0), (100, 1e-15)],
            [Some(OrderBand::Exact { max_error: 1e-10 }), None, None],
        );
        assert_eq!(exact.fitted_order(|l| l.l1), None, "round-off has no order");
        assert_eq!(exact.verdicts()[0].pass, Some(true));
        assert_eq!(exact.verdicts()[1].pass, None, "no band: measured only");
    }

    #[test]
    fn closed_forms_approach_their_limits_at_the_first_order_rate_up_to_1e12() {
        let rows = contact_closed_form_rows().unwrap();
        assert_eq!(rows.len(), 16);
        for row in &rows {
            let difference = row.cr / row.limit - 1.0;
            if row.r.is_some_and(|r| r <= 1.0) {
                assert_eq!(row.cr, 1.0, "{row:?}: no localized mode for r <= 1");
            } else {
                assert!(
                    (difference - row.first_order).abs() <= 1e-3 * row.first_order.abs(),
                    "{row:?}: Cr/limit - 1 = {difference:e}"
                );
            }
        }
        let last = rows
            .iter()
            .find(|r| r.beta_s == 1e12 && r.r.is_none())
            .unwrap();
        assert!((last.cr / 2e-12_f64.sqrt() - 1.0).abs() < 1e-12, "{last:?}");
    }

    #[test]
    fn table_lists_every_beta_and_ratio_with_readable_differences() {
        let table = contact_closed_form_table().unwrap();
        assert_eq!(table.rows.len(), 16);
        let csv = table.to_csv(STORED);
        assert!(csv.starts_with(
            "beta_s,r,cr_closed_form,cr_limit,scaled_difference,scaled_first_order\n"
        ));
        // Penalty only at beta_s = 1e12: beta_s (Cr/limit - 1) -> -1/2; the difference (5e-13)
        // carries round-off of about 1e-16/5e-13, so only three digits are asserted.
        let row = csv
            .lines()
            .find(|l| l.starts_with("1.000000000e12,,"))
            .expect("penalty row at 1e12");
        let cells: Vec<&str> = row.split(',').collect();
        assert_eq!(cells[5], "-0.5000000000", "{row}");
        let scaled: f64 = cells[4].parse().unwrap();
        assert!((scaled + 0.5).abs() < 1e-3, "{row}");
        assert!(
            csv.contains("\n1.000000000e12,0.2500000000,1.000000000,1.000000000,0,0\n"),
            "{csv}"
        );
    }
}
