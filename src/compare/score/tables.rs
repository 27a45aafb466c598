//! The tables of scored result sets, one row per case (or per profile, expectation, mesh):
//! `summary.csv`, `norms.csv`, `expectations.csv`, `diagnostics.csv` and, for several sets of one
//! case at different N, `convergence.csv` and `convergence.orders.csv`. Every table starts with
//! the set (its directory as given).

use super::outcome::{CaseConvergence, ScoreOutcome, Scored, ScoredCase, ScoredSet};
use crate::compare::case::CaseResult;
use crate::compare::outcome::SceneOutcome;
use crate::compare::tables::{norms_cells, verdict_cells};
use crate::results::table::{Cell, Precision, Table};

fn verdict_cell(v: Option<bool>) -> Cell {
    match v {
        Some(true) => "pass".into(),
        Some(false) => "FAIL".into(),
        None => Cell::Empty,
    }
}

/// One row per case: its size and step, then the worst norms over its profiles (stress
/// profiles), the force measures (contact) or the closed-form deviation (spectra).
pub fn summary_table(sets: &[ScoredSet]) -> Table {
    let first = sets.iter().flat_map(|s| &s.cases).next().map(|c| &c.scored);
    let mut table = match first {
        Some(Scored::Force(_)) => Table::new(&[
            "set",
            "code",
            "case",
            "scheme",
            "samples",
            "dt",
            "impulse",
            "plateau",
            "plateau_deviation",
            "impulse_error",
            "duration_error",
            "force_l1_error",
            "max_force",
        ]),
        Some(Scored::Spectrum(_)) => Table::new(&[
            "set",
            "code",
            "case",
            "masses",
            "modes",
            "closed_form_deviation",
        ]),
        _ => Table::new(&[
            "set",
            "code",
            "case",
            "N",
            "values",
            "scheme",
            "mass",
            "dt",
            "dt_source",
            "profiles",
            "l1",
            "l2",
            "linf",
            "overshoot",
            "tv_ratio",
        ]),
    };
    for set in sets {
        for c in &set.cases {
            let head: Vec<Cell> = vec![
                set.label.as_str().into(),
                set.code.as_str().into(),
                c.case.as_str().into(),
            ];
            let rest: Vec<Cell> = match &c.scored {
                Scored::Profiles { profiles, points } => {
                    let n = c.worst_norms();
                    vec![
                        c.elements.into(),
                        (if *points { "points" } else { "elements" }).into(),
                        c.scheme.clone().into(),
                        c.mass.clone().into(),
                        c.dt.map(|d| d.0).into(),
                        c.dt.map(|d| d.1).into(),
                        profiles.len().into(),
                        n.map(|n| n.l1).into(),
                        n.map(|n| n.l2).into(),
                        n.map(|n| n.linf).into(),
                        n.map(|n| n.overshoot).into(),
                        n.map(|n| n.tv_ratio).into(),
                    ]
                }
                Scored::Force(f) => vec![
                    c.scheme.clone().into(),
                    f.time.len().into(),
                    c.dt.map(|d| d.0).into(),
                    f.impulse.into(),
                    f.plateau.into(),
                    f.errors.plateau_deviation.into(),
                    f.impulse_error.into(),
                    f.errors.duration_error.into(),
                    f.errors.force_l1_error.into(),
                    f.errors.max_force.into(),
                ],
                Scored::Spectrum(s) => {
                    let mut masses: Vec<&str> = s.rows.iter().map(|r| r.0.as_str()).collect();
                    masses.dedup();
                    vec![
                        masses.join(" ").into(),
                        s.rows.len().into(),
                        s.deviation.into(),
                    ]
                }
            };
            table.push(head.into_iter().chain(rest).collect());
        }
    }
    table
}

/// Norms per case and profile time: `set, case, t, l1, l2, linf, overshoot, tv_ratio`.
pub fn norms_table(sets: &[ScoredSet]) -> Table {
    let mut table = Table::new(&[
        "set",
        "case",
        "t",
        "l1",
        "l2",
        "linf",
        "overshoot",
        "tv_ratio",
    ]);
    for set in sets {
        for c in &set.cases {
            if let Scored::Profiles { profiles, .. } = &c.scored {
                for p in profiles {
                    let mut row: Vec<Cell> = vec![set.label.as_str().into()];
                    row.extend(norms_cells(&c.case, p.time, &p.norms));
                    table.push(row);
                }
            }
        }
    }
    table
}

/// The scene's expectations on each set: `set` and the columns of `courant run`'s
/// `expectations.csv`; expectations files cannot answer have the verdict `skip` and the reason.
pub fn expectations_table(sets: &[ScoredSet]) -> Table {
    let mut table = Table::new(&[
        "set", "case", "metric", "at", "measured", "min", "max", "equals", "verdict", "source",
    ]);
    for set in sets {
        for v in &set.verdicts {
            let mut row: Vec<Cell> = vec![set.label.as_str().into()];
            row.extend(verdict_cells(v));
            table.push(row);
        }
        for s in &set.skipped {
            table.push(vec![
                set.label.as_str().into(),
                s.case.as_str().into(),
                s.label.as_str().into(),
                s.at.into(),
                s.reason.as_str().into(),
                Cell::Empty,
                Cell::Empty,
                Cell::Empty,
                s.kind.word().into(),
                s.source.as_str().into(),
            ]);
        }
    }
    table
}

/// The diagnostics of every case: the step they count in and its source, the time shift (in
/// steps) and its residual, the time level read from it, the sign and the layout, the largest
/// stress over the load's scale, each with its verdict; `notes` says why a diagnostic has no
/// verdict or how it failed.
pub fn diagnostics_table(sets: &[ScoredSet]) -> Table {
    let mut table = Table::new(&[
        "set",
        "case",
        "dt",
        "dt_source",
        "time_shift_steps",
        "shift_residual",
        "time_level",
        "time_level_verdict",
        "sign_error",
        "sign_error_flipped",
        "sign",
        "sign_verdict",
        "layout",
        "layout_verdict",
        "max_stress_over_scale",
        "magnitude_verdict",
        "notes",
    ]);
    for set in sets {
        for c in &set.cases {
            let d = &c.diagnostics;
            let [magnitude, level, sign, layout] = d.verdicts();
            let notes: Vec<String> = [&magnitude, &level, &sign, &layout]
                .iter()
                .filter(|r| r.verdict != Some(true))
                .map(|r| format!("{}: {}", r.name, r.note))
                .collect();
            let text = |v: &String| {
                if v == "-" {
                    Cell::Empty
                } else {
                    Cell::Text(v.clone())
                }
            };
            table.push(vec![
                set.label.as_str().into(),
                c.case.as_str().into(),
                c.dt.map(|d| d.0).into(),
                c.dt.map(|d| d.1).into(),
                d.shift.as_ref().ok().map(|s| s.steps).into(),
                d.shift.as_ref().ok().map(|s| s.residual).into(),
                text(&level.measured),
                verdict_cell(level.verdict),
                d.sign.as_ref().ok().map(|s| s.error).into(),
                d.sign.as_ref().ok().map(|s| s.error_flipped).into(),
                text(&sign.measured),
                verdict_cell(sign.verdict),
                text(&layout.measured),
                verdict_cell(layout.verdict),
                d.magnitude.as_ref().ok().map(|m| m.max / m.scale).into(),
                verdict_cell(magnitude.verdict),
                notes.join("; ").into(),
            ]);
        }
    }
    table
}

/// The largest difference of a file's stresses from courant's run of the same case, over
/// `scale`, at the profile times both have (to 1e-9 relative) and on the same number of
/// values; `None` when they share no profile.
pub fn difference_from_courant(case: &ScoredCase, own: &CaseResult, scale: f64) -> Option<f64> {
    let Scored::Profiles { profiles, .. } = &case.scored else {
        return None;
    };
    let differences: Vec<f64> = profiles
        .iter()
        .filter_map(|p| {
            let q = own
                .profiles
                .iter()
                .find(|q| (q.time - p.time).abs() <= 1e-9 * p.time.abs().max(1.0))?;
            (q.stress.len() == p.stress.len()).then(|| {
                p.stress
                    .iter()
                    .zip(&q.stress)
                    .map(|(a, b)| (a - b).abs() / scale)
                    .fold(0.0, f64::max)
            })
        })
        .collect();
    (!differences.is_empty()).then(|| differences.into_iter().fold(0.0, f64::max))
}

/// `case` and the convergence table of each study (N, dt, steps, errors and observed orders).
pub fn convergence_table(studies: &[CaseConvergence]) -> Table {
    let mut table: Option<Table> = None;
    for c in studies {
        let t = c.result.table();
        let out = table.get_or_insert_with(|| {
            let mut columns = vec!["case".to_string()];
            columns.extend(t.columns.iter().cloned());
            Table {
                columns,
                rows: Vec::new(),
            }
        });
        for row in t.rows {
            out.rows.push(
                std::iter::once(Cell::from(c.case.as_str()))
                    .chain(row)
                    .collect(),
            );
        }
    }
    table.unwrap_or_else(|| Table::new(&["case"]))
}

/// `case, study, norm, fitted_order, expected, verdict` of each study.
pub fn orders_table(studies: &[CaseConvergence]) -> Table {
    let mut table = Table::new(&[
        "case",
        "study",
        "norm",
        "fitted_order",
        "expected",
        "verdict",
    ]);
    for c in studies {
        for row in c.result.verdict_table().rows {
            let mut cells = vec![c.case.as_str().into(), c.result.study.name.into()];
            cells.extend(row);
            table.push(cells);
        }
    }
    table
}

/// The files `courant score --out DIR` writes into `DIR/<scene>/`, at round-trip precision.
pub fn score_files(outcome: &ScoreOutcome) -> Vec<(String, String)> {
    let full = Precision::RoundTrip;
    let profiles = outcome
        .sets
        .iter()
        .flat_map(|s| &s.cases)
        .any(|c| matches!(c.scored, Scored::Profiles { .. }));
    let mut files = vec![(
        "summary.csv".to_string(),
        summary_table(&outcome.sets).to_csv(full),
    )];
    if profiles {
        files.push(("norms.csv".into(), norms_table(&outcome.sets).to_csv(full)));
    }
    files.push((
        "expectations.csv".into(),
        expectations_table(&outcome.sets).to_csv(full),
    ));
    files.push((
        "diagnostics.csv".into(),
        diagnostics_table(&outcome.sets).to_csv(full),
    ));
    if !outcome.convergence.is_empty() {
        files.push((
            "convergence.csv".into(),
            convergence_table(&outcome.convergence).to_csv(full),
        ));
        files.push((
            "convergence.orders.csv".into(),
            orders_table(&outcome.convergence).to_csv(full),
        ));
    }
    files
}

/// A scored set beside courant's own run of the same cases (`courant`: the scene's compared
/// outcome), one row per case: the worst L1, max and overshoot of each (`*_courant`), the
/// largest difference of the two stress profiles at their common times relative to `|sigma0|`
/// (same elements only), and the diagnostics (time level, sign, layout; the fitted shifts are
/// in `diagnostics.csv`). Cases courant did not run have empty
/// `*_courant` cells.
pub fn beside_courant_table(set: &ScoredSet, courant: &SceneOutcome, scale: f64) -> Table {
    let mut table = Table::new(&[
        "case",
        "mass",
        "N",
        "dt",
        "l1",
        "l1_courant",
        "linf",
        "linf_courant",
        "overshoot",
        "overshoot_courant",
        "max_difference",
        "time_level",
        "sign",
        "layout",
    ]);
    for c in &set.cases {
        let Scored::Profiles { .. } = &c.scored else {
            continue;
        };
        let own = courant.results.iter().find(|r| r.run.case == c.case);
        let (n, m) = (c.worst_norms(), own.and_then(|r| r.worst_norms()));
        let difference = own.and_then(|r| difference_from_courant(c, r, scale));
        let [_, level, sign, layout] = c.diagnostics.verdicts();
        table.push(vec![
            c.case.as_str().into(),
            c.mass.clone().into(),
            c.elements.into(),
            c.dt.map(|d| d.0).into(),
            n.map(|n| n.l1).into(),
            m.map(|n| n.l1).into(),
            n.map(|n| n.linf).into(),
            m.map(|n| n.linf).into(),
            n.map(|n| n.overshoot).into(),
            m.map(|n| n.overshoot).into(),
            difference.into(),
            level.measured.into(),
            sign.measured.into(),
            layout.measured.into(),
        ]);
    }
    table
}
