//! The tables of compared time-stepping cases: one profile table per case (`<case>.csv`), its
//! histories (`<case>.history.csv`) and energy log (`<case>.energy.csv`), and per scene
//! `summary.csv`, `norms.csv` and `expectations.csv`. Tests and snapshots render the same
//! tables.

use super::case::CaseResult;
use super::norms::ErrorNorms;
use super::verdict::{Measured, Verdict};
use crate::results::case::Status;
use crate::results::table::{Cell, Table};

/// Columns of [`profile_table`].
pub const PROFILE_COLUMNS: [&str; 6] = ["t", "element", "x", "stress", "reference", "error"];

/// Element stress profiles: `t, element, x, stress, reference, error` (all profile times of
/// the case, in time order; `reference` and `error` empty without a reference).
pub fn profile_table(result: &CaseResult) -> Table {
    let mut table = Table::new(&PROFILE_COLUMNS);
    profile_rows(result).for_each(|row| table.push(row));
    table
}

/// The rows of [`profile_table`], one at a time (`courant run` writes them without holding
/// the table: at 10^7 elements its cells would take 144 bytes per element).
pub fn profile_rows(result: &CaseResult) -> impl Iterator<Item = Vec<Cell>> + '_ {
    result.profiles.iter().flat_map(|p| {
        (0..p.stress.len()).map(move |e| {
            let reference = p.reference.as_ref().map(|r| r[e]);
            vec![
                p.time.into(),
                e.into(),
                p.x[e].into(),
                p.stress[e].into(),
                reference.into(),
                reference.map(|r| p.stress[e] - r).into(),
            ]
        })
    })
}

/// Nodal histories: `node, x, t, u, u_reference, v, v_reference, a`.
pub fn history_table(result: &CaseResult) -> Table {
    let mut table = Table::new(&[
        "node",
        "x",
        "t",
        "u",
        "u_reference",
        "v",
        "v_reference",
        "a",
    ]);
    for h in &result.histories {
        for (i, s) in h.history.samples.iter().enumerate() {
            let exact = h.reference.as_ref().map(|r| r[i]);
            table.push(vec![
                h.history.node.into(),
                h.history.x.into(),
                s.time.into(),
                s.displacement.into(),
                exact.map(|e| e.0).filter(|v| !v.is_nan()).into(),
                s.velocity.into(),
                exact.map(|e| e.1).filter(|v| !v.is_nan()).into(),
                s.acceleration.into(),
            ]);
        }
    }
    table
}

/// Energy log: `step, t, kinetic, kinetic_staggered, strain, work, balance_error` and the exact
/// `kinetic_reference, strain_reference, work_reference` when there is a reference.
pub fn energy_table(result: &CaseResult) -> Table {
    let mut table = Table::new(&[
        "step",
        "t",
        "kinetic",
        "kinetic_staggered",
        "strain",
        "work",
        "balance_error",
        "kinetic_reference",
        "strain_reference",
        "work_reference",
    ]);
    for (i, s) in result.energy.samples.iter().enumerate() {
        let exact = result.energy_reference.as_ref().map(|r| r[i]);
        table.push(vec![
            s.step.into(),
            s.time.into(),
            s.kinetic.into(),
            s.kinetic_staggered.into(),
            s.strain.into(),
            s.work.into(),
            s.balance_error.into(),
            exact.map(|e| e.kinetic).into(),
            exact.map(|e| e.strain).into(),
            exact.map(|e| e.work).into(),
        ]);
    }
    table
}

/// One row per case: the scheme that ran (Park's variant and theta named), cost (dt, steps, wall
/// time) beside accuracy (worst norms over the profile times, energy balance) and how the run
/// ended. `dt_crit` is the exact critical step the run
/// was checked against; the element (Fried) and nodal Gershgorin estimates stand beside it.
pub fn summary_table(results: &[CaseResult]) -> Table {
    let mut table = Table::new(&[
        "case",
        "N",
        "scheme",
        "mass",
        "Co",
        "Co_crit",
        "dt",
        "dt_crit",
        "dt_crit_element",
        "dt_crit_gershgorin",
        "steps",
        "l1",
        "l2",
        "linf",
        "overshoot",
        "tv_ratio",
        "energy_balance",
        "energy_lost",
        "status",
        "wall_time_s",
    ]);
    for r in results {
        let norms = r.worst_norms();
        let status = match &r.run.status {
            Status::Completed => "completed".to_string(),
            Status::Diverged(d) => format!("diverged at step {}", d.step),
        };
        table.push(vec![
            r.run.case.as_str().into(),
            r.elements.into(),
            r.run.scheme.as_str().into(),
            r.run.critical.mass.label().into(),
            r.run.courant.into(),
            (r.run.courant * r.run.critical.exact / r.run.dt).into(),
            r.run.dt.into(),
            r.run.critical.exact.into(),
            r.run.critical.element.into(),
            r.run.critical.gershgorin.into(),
            r.run.steps.into(),
            norms.map(|n| n.l1).into(),
            norms.map(|n| n.l2).into(),
            norms.map(|n| n.linf).into(),
            norms.map(|n| n.overshoot).into(),
            norms.and_then(|n| n.tv_ratio).into(),
            r.energy.relative_balance_error().into(),
            r.energy_lost().into(),
            status.into(),
            r.run.wall_time.as_secs_f64().into(),
        ]);
    }
    table
}

/// Norms per case and profile time: `case, t, l1, l2, linf, overshoot, tv_ratio`.
pub fn norms_table(results: &[CaseResult]) -> Table {
    let mut table = Table::new(&["case", "t", "l1", "l2", "linf", "overshoot", "tv_ratio"]);
    for r in results {
        for p in &r.profiles {
            if let Some(n) = p.norms {
                table.push(norms_cells(&r.run.case, p.time, &n));
            }
        }
    }
    table
}

/// One row of norms: `case, t, l1, l2, linf, overshoot, tv_ratio`.
pub fn norms_cells(case: &str, time: f64, n: &ErrorNorms) -> Vec<Cell> {
    vec![
        case.into(),
        time.into(),
        n.l1.into(),
        n.l2.into(),
        n.linf.into(),
        n.overshoot.into(),
        n.tv_ratio.into(),
    ]
}

/// Expectation verdicts: `case, metric, at, measured, min, max, equals, verdict, source`.
pub fn expectations_table(verdicts: &[Verdict]) -> Table {
    let mut table = Table::new(&[
        "case", "metric", "at", "measured", "min", "max", "equals", "verdict", "source",
    ]);
    for v in verdicts {
        table.push(verdict_cells(v));
    }
    table
}

/// The cells of one verdict: `case, metric, at, measured, min, max, equals, verdict, source`.
pub fn verdict_cells(v: &Verdict) -> Vec<Cell> {
    let (min, max, equals) = v.bound_cells();
    let measured = match &v.measured {
        Measured::Value(x) => Cell::Num(*x),
        Measured::Flag(b) => Cell::Text(b.to_string()),
        Measured::Text(t) => Cell::Text(t.clone()),
        Measured::Missing(why) => Cell::Text(format!("missing: {why}")),
    };
    vec![
        v.case.as_str().into(),
        v.metric_label().into(),
        v.at.into(),
        measured,
        min,
        max,
        equals,
        v.word().into(),
        v.source.as_str().into(),
    ]
}
