//! The exact answers of a scene as an exchange set (`courant reference`): the reference of each
//! case at the scene's own mesh and output times, or at the rows of a query file; every file
//! names the reference that produced its values (its `reference` column).

use super::bind::{SceneKind, bar_extent, check_on_bar, profile_times};
use super::outcome::ScoreError;
use super::profiles::exact_values;
use super::reference_work::check_reference_work;
use super::spectrum::closed_form;
use crate::results::exchange::FORMAT;
use crate::results::exchange::error::ExchangeError;
use crate::results::exchange::meta::{CaseMeta, ResultsMeta};
use crate::results::exchange::record::{
    CaseData, CaseFile, ExchangeSet, ForceHistory, Positions, Profile, SpectrumRow,
};
use crate::scene::cases::Scene;
use crate::scene::mass::parse_mass;
use std::collections::BTreeMap;

/// The exact answers of `scene` (labelled `label`): per case, element averages on its mesh at
/// its profile times (d'Alembert, graded, layered), the analytic contact force at its sample
/// times (1D wave theory), or the closed-form frequencies of every mode and mass kind; or, with
/// a `query`, at the query's rows (`t, x_left, x_right`, `t, x`, `t` or `mode [, mass]`).
///
/// # Errors
/// A scene without an exchange form, a query of another kind than the scene's files, positions
/// off the bar, a mode the bar does not have, an unknown mass label, a spectrum case without
/// closed forms.
pub fn exact_set(
    scene: &Scene,
    query: Option<&CaseFile>,
    label: &str,
) -> Result<ExchangeSet, ScoreError> {
    let kind = SceneKind::of(scene)?;
    if let Some(q) = query {
        let fits = matches!(
            (kind, &q.data),
            (SceneKind::Stepping, CaseData::Profiles(_))
                | (SceneKind::Contact, CaseData::Force(_))
                | (SceneKind::Spectrum, CaseData::Spectrum(_))
        );
        if !fits {
            return Err(ExchangeError::at(
                &q.file,
                1,
                1,
                "",
                format!(
                    "scene `{}` answers with {}; this query asks for {}",
                    scene.name,
                    kind.holds(),
                    q.data.describe()
                ),
            )
            .into());
        }
    }
    let mut cases = Vec::new();
    let mut meta = BTreeMap::new();
    let file = |case: &str, data, reference: &str| CaseFile {
        case: case.to_string(),
        file: format!("{case}.csv"),
        columns: Vec::new(),
        data,
        reference: Some(reference.to_string()),
    };
    for case in &scene.cases {
        let reference = case.reference.as_ref().expect("checked by SceneKind::of");
        let extent = bar_extent(case);
        let queried: Vec<(f64, Positions)> = match query.map(|q| (q, &q.data)) {
            Some((q, CaseData::Profiles(profiles))) => {
                check_on_bar(q, profiles, extent)?;
                check_reference_work(q, profiles, reference, extent)?;
                profiles
                    .iter()
                    .map(|p| (p.time, p.positions.clone()))
                    .collect()
            }
            _ => {
                let nodes = case.model.bar().mesh().nodes();
                let n = nodes.len() - 1;
                profile_times(case)
                    .into_iter()
                    .map(|t| {
                        let positions = Positions::Elements {
                            left: nodes[..n].to_vec(),
                            right: nodes[1..].to_vec(),
                        };
                        (t, positions)
                    })
                    .collect()
            }
        };
        let profiles = queried
            .into_iter()
            .map(|(time, positions)| {
                // `+ 0.0` writes an exact zero as 0, not -0 (sigma0 < 0 times no front).
                let stress: Vec<f64> = exact_values(&positions, extent, reference, time)
                    .map_err(|why| ScoreError::Scene(format!("{}: {why}", case.name)))?
                    .into_iter()
                    .map(|v| v + 0.0)
                    .collect();
                // Never a NaN in a file: a time the reference does not reach is refused.
                if stress.iter().any(|v| !v.is_finite()) {
                    return Err(ScoreError::Scene(format!(
                        "{}: the {} reference is not defined at t = {time:e} (no value written)",
                        case.name,
                        reference.name()
                    )));
                }
                Ok(Profile {
                    time,
                    positions,
                    stress,
                    lines: Vec::new(),
                })
            })
            .collect::<Result<Vec<_>, ScoreError>>()?;
        cases.push(file(
            &case.name,
            CaseData::Profiles(profiles),
            reference.name(),
        ));
        meta.insert(
            case.name.clone(),
            CaseMeta {
                dt: Some(case.integrator.dt),
                // The scene's mesh; a query's rows are its own.
                elements: query
                    .is_none()
                    .then(|| (case.model.bar().element_count(), 0)),
                ..CaseMeta::default()
            },
        );
    }
    for case in &scene.contact {
        let dt = case.integrator.dt;
        let time: Vec<f64> = match query.map(|q| &q.data) {
            Some(CaseData::Force(h)) => h.time.clone(),
            _ => (0..=case.steps)
                .filter(|&n| n % case.history_every == 0 || n == case.steps)
                .map(|n| n as f64 * dt)
                .collect(),
        };
        let force = time
            .iter()
            .map(|&t| case.reference.history().contact_force(t) + 0.0)
            .collect();
        let history = ForceHistory {
            time,
            force,
            penetration: None,
            gap: None,
            lines: Vec::new(),
        };
        cases.push(file(&case.name, CaseData::Force(history), "impact"));
        meta.insert(
            case.name.clone(),
            CaseMeta {
                dt: Some(dt),
                ..CaseMeta::default()
            },
        );
    }
    for case in &scene.spectra {
        let Some(bar) = &case.closed_form else {
            return Err(ScoreError::Scene(format!(
                "case `{}` of scene `{}` has no closed-form spectrum (its bar is not uniform and homogeneous)",
                case.name, scene.name
            )));
        };
        let mut rows = Vec::new();
        let wanted: Vec<(usize, Option<&str>, usize)> = match query.map(|q| (q, &q.data)) {
            Some((_, CaseData::Spectrum(q))) => q
                .iter()
                .map(|r| (r.mode, r.mass.as_deref(), r.line))
                .collect(),
            _ => bar.modes().map(|n| (n, None, 0)).collect(),
        };
        for (mode, mass, line) in wanted {
            let masses = match mass {
                Some(label) => vec![parse_mass(label).map_err(|rule| {
                    let q = query.expect("a mass label comes from a query");
                    ExchangeError::at(&q.file, line, q.column("mass"), "mass", rule)
                })?],
                None => case.masses.clone(),
            };
            for kind in masses {
                let omega = closed_form(case, kind, mode).ok_or_else(|| {
                    let q = query.expect("the scene's own modes exist");
                    ExchangeError::at(
                        &q.file,
                        line,
                        q.column("mode"),
                        "mode",
                        format!(
                            "mode {mode} is not a mode of this bar ({}..={})",
                            bar.modes().start(),
                            bar.modes().end()
                        ),
                    )
                })?;
                rows.push(SpectrumRow {
                    mode,
                    omega,
                    mass: Some(kind.label()),
                    line: 0,
                });
            }
        }
        cases.push(file(&case.name, CaseData::Spectrum(rows), "closed-form"));
    }
    cases.sort_by(|a, b| a.case.cmp(&b.case));
    Ok(ExchangeSet {
        label: label.to_string(),
        cases,
        meta: Some(ResultsMeta {
            file: "results.toml".into(),
            format: FORMAT,
            code: Some("courant-reference".into()),
            version: Some(env!("CARGO_PKG_VERSION").into()),
            cases: meta,
        }),
    })
}
