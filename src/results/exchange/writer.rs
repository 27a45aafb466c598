//! Writing records in the exchange format: one CSV per case at round-trip precision (every
//! number reads back to the same f64), and `results.toml`.

use super::meta::render;
use super::reader::META_FILE;
use super::record::{CaseData, CaseFile, ExchangeSet, Positions};
use crate::results::table::{Cell, Precision, Table};

/// The table of one case file: `t, x_left, x_right, stress`, `t, x, stress`,
/// `t, force [, penetration] [, gap]` or `mode, omega [, mass]`, and a `reference` column when
/// the case names the reference that produced it.
pub fn case_table(case: &CaseFile) -> Table {
    let mut table = match &case.data {
        CaseData::Profiles(profiles) => {
            let points = matches!(
                profiles.first().map(|p| &p.positions),
                Some(Positions::Points(_))
            );
            let mut t = if points {
                Table::new(&["t", "x", "stress"])
            } else {
                Table::new(&["t", "x_left", "x_right", "stress"])
            };
            for p in profiles {
                for (i, &stress) in p.stress.iter().enumerate() {
                    let mut row: Vec<Cell> = vec![p.time.into()];
                    match &p.positions {
                        Positions::Elements { left, right } => {
                            row.extend([left[i].into(), right[i].into()]);
                        }
                        Positions::Points(x) => row.push(x[i].into()),
                    }
                    row.push(stress.into());
                    t.push(row);
                }
            }
            t
        }
        CaseData::Force(h) => {
            let mut columns = vec!["t", "force"];
            columns.extend(h.penetration.as_ref().map(|_| "penetration"));
            columns.extend(h.gap.as_ref().map(|_| "gap"));
            let mut t = Table::new(&columns);
            for i in 0..h.time.len() {
                let mut row: Vec<Cell> = vec![h.time[i].into(), h.force[i].into()];
                row.extend(h.penetration.as_ref().map(|p| Cell::from(p[i])));
                row.extend(h.gap.as_ref().map(|g| Cell::from(g[i])));
                t.push(row);
            }
            t
        }
        CaseData::Spectrum(rows) => {
            let with_mass = rows.iter().any(|r| r.mass.is_some());
            let mut t = if with_mass {
                Table::new(&["mode", "omega", "mass"])
            } else {
                Table::new(&["mode", "omega"])
            };
            for r in rows {
                let mut row: Vec<Cell> = vec![r.mode.into(), r.omega.into()];
                if with_mass {
                    row.push(r.mass.clone().into());
                }
                t.push(row);
            }
            t
        }
    };
    if let Some(reference) = &case.reference {
        table.columns.push("reference".into());
        for row in &mut table.rows {
            row.push(reference.as_str().into());
        }
    }
    table
}

/// The files of a result set, by name: `<case>.csv` for every case, and `results.toml` when the
/// set has metadata.
pub fn set_files(set: &ExchangeSet) -> Vec<(String, String)> {
    let mut files: Vec<(String, String)> = set
        .cases
        .iter()
        .map(|c| {
            (
                format!("{}.csv", c.case),
                case_table(c).to_csv(Precision::RoundTrip),
            )
        })
        .collect();
    if let Some(meta) = &set.meta {
        let cases: Vec<_> = meta
            .cases
            .iter()
            .map(|(n, m)| (n.clone(), m.clone()))
            .collect();
        files.push((
            META_FILE.into(),
            render(
                meta.code.as_deref().unwrap_or("-"),
                meta.version.as_deref().unwrap_or("-"),
                &cases,
            ),
        ));
    }
    files
}

#[cfg(test)]
mod tests {
    use super::super::columns::Want;
    use super::super::reader::read_case;
    use super::super::record::{ForceHistory, Profile, SpectrumRow};
    use super::super::set::read_set;
    use super::*;

    #[test]
    fn every_kind_reads_back_bit_for_bit() {
        let profiles = CaseFile {
            case: "co1".into(),
            file: String::new(),
            columns: Vec::new(),
            data: CaseData::Profiles(vec![Profile {
                time: 0.1 + 0.2,
                positions: Positions::Elements {
                    left: vec![0.0, 1.0 / 3.0],
                    right: vec![1.0 / 3.0, 1.0],
                },
                stress: vec![-1.0 / 7.0, 2.5e-14],
                lines: vec![2, 3],
            }]),
            reference: Some("dalembert".into()),
        };
        let force = CaseFile {
            case: "pc".into(),
            file: String::new(),
            columns: Vec::new(),
            data: CaseData::Force(ForceHistory {
                time: vec![0.0, 0.1],
                force: vec![0.0, 1.0 / 3.0],
                penetration: None,
                gap: Some(vec![0.0, -1e-9]),
                lines: vec![2, 3],
            }),
            reference: None,
        };
        let spectrum = CaseFile {
            case: "s".into(),
            file: String::new(),
            columns: Vec::new(),
            data: CaseData::Spectrum(vec![SpectrumRow {
                mode: 1,
                omega: std::f64::consts::PI,
                mass: Some("lmm".into()),
                line: 2,
            }]),
            reference: None,
        };
        for case in [profiles, force, spectrum] {
            let text = case_table(&case).to_csv(Precision::RoundTrip);
            let back = read_case("f.csv", &case.case, &text, Want::Results).unwrap();
            assert_eq!(back.data, case.data, "{text}");
        }
    }

    #[test]
    fn a_set_without_metadata_writes_only_its_cases() {
        let files = vec![("a.csv".to_string(), "t,force\n0,1\n".to_string())];
        let set = read_set("d", "d", &files).unwrap();
        let written = set_files(&set);
        assert_eq!(written.len(), 1);
        assert_eq!(written[0], ("a.csv".into(), "t,force\n0,1\n".into()));
    }
}
