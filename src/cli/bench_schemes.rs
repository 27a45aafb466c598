//! `courant bench`'s second table: every scheme and mass kind's run loop beside lumped central
//! difference's and the C loop, so that a user sees the speed-for-accuracy trade of the schemes
//! on their own machine (benches/RESULTS.md, heading "2026-11-28: every scheme's run against
//! lumped CD").
//!
//! Per element count N and (scheme, mass): `loop_ns`, the run loop per node-step on one thread
//! (the difference of runs of `2 S` and `S` steps over `S (N + 1)`, median over the
//! repetitions, as the lumped run of the first table, with `S` from `--node-steps` and no
//! whole block imposed: these runs step singly), at half the mass's critical Courant number of
//! the stiffest element (Co 0.5 for the lumped mass, as the lumped CD run); `over_lumped_cd`,
//! its ratio to the lumped CD run on one thread of the first table (`loop_1t_ns`);
//! `over_c`, to the C loop. Nothing here is a test; no test asserts a time.

use crate::io::owned_file::{Owner, check_file_replaceable, write_owned_file};
use crate::results::table::{Precision, Table};
use courant_solver::{Integration, MassKind, Model};
use std::path::{Path, PathBuf};

/// The columns of the schemes' CSV.
const COLUMNS: [&str; 7] = [
    "N",
    "scheme",
    "mass",
    "threads",
    "loop_ns",
    "over_lumped_cd",
    "over_c",
];

/// Every (scheme, mass) timed beside lumped central difference: central difference with each
/// matrix mass, Noh-Bathe with every mass, Park with local stepping and with the global step.
const RUNS: [(&str, MassKind); 9] = [
    ("cd", MassKind::Consistent),
    ("cd", MassKind::Averaged { beta: 0.5 }),
    ("cd", MassKind::Reciprocal { beta: 0.5 }),
    ("noh-bathe", MassKind::Lumped),
    ("noh-bathe", MassKind::Consistent),
    ("noh-bathe", MassKind::Averaged { beta: 0.5 }),
    ("noh-bathe", MassKind::Reciprocal { beta: 0.5 }),
    ("park-lts", MassKind::Lumped),
    ("park-global", MassKind::Lumped),
];

/// A CSV of this table: its header starts with `N,scheme,mass,`.
const SCHEMES_CSV: Owner = Owner {
    what: "`courant bench`",
    recognises: |head| {
        head.lines()
            .next()
            .is_some_and(|line| line.starts_with("N,scheme,mass,"))
    },
};

/// Where the schemes' table goes: beside `out`, `<stem>.schemes.csv`.
pub fn schemes_path(out: &Path) -> PathBuf {
    out.with_extension("schemes.csv")
}

/// Whether the schemes' file may be written (absent, or written by `courant bench`).
pub fn check_schemes_file(out: &Path) -> Result<(), String> {
    check_file_replaceable(&schemes_path(out), SCHEMES_CSV)
        .map(|_| ())
        .map_err(|e| format!("--out {e}"))
}

/// The rows of the schemes' table.
pub struct SchemesTable(Table);

impl SchemesTable {
    /// An empty table.
    pub fn new() -> Self {
        Self(Table::new(&COLUMNS))
    }

    /// Time every run of [`RUNS`] on `model` with `time_loop` (ns per node-step of an
    /// integration's run loop) and add its rows; `lumped_cd`: the lumped CD run on one thread,
    /// `c_ns`: the C loop, if measured.
    pub fn measure(
        &mut self,
        model: &Model,
        lumped_cd: f64,
        c_ns: Option<f64>,
        mut time_loop: impl FnMut(&Integration) -> Result<f64, String>,
    ) -> Result<(), String> {
        let element_dt = model.bar().stiffest_element().1;
        for (name, mass) in RUNS {
            let entry = courant_solver::schemes::find(name)
                .ok_or_else(|| format!("no scheme {name} in the registry"))?;
            let scheme = entry.build_with(&[]).map_err(|e| e.rule)?;
            let integration = Integration {
                mass,
                threads: Some(1),
                ..Integration::new(0.5 * mass.critical_courant() * element_dt, scheme)
            };
            let ns = time_loop(&integration)?;
            self.0.push(vec![
                model.bar().element_count().into(),
                name.to_string().into(),
                mass.label().into(),
                integration.threads(model).into(),
                ns.into(),
                (ns / lumped_cd).into(),
                c_ns.map(|c| ns / c).into(),
            ]);
        }
        Ok(())
    }

    /// Print the table and write it beside `out` ([`schemes_path`]).
    pub fn finish(&self, out: &Path) -> Result<PathBuf, String> {
        outln!(
            "every scheme's run loop on one thread, ns per node-step (medians), over lumped CD's:"
        );
        out!("{}", super::run::aligned(&self.0, "  "));
        let path = schemes_path(out);
        let csv = self.0.to_csv(Precision::Significant {
            digits: 4,
            floor: 0.0,
        });
        write_owned_file(&path, &csv, SCHEMES_CSV).map_err(|e| format!("cannot write {e}"))?;
        Ok(path)
    }
}
