//! A compared courant run as an exchange set (`courant run --exchange DIR`): courant's own
//! results in the format another code writes, so that `courant score` grades them exactly as it
//! grades the others (and a test checks it gives the run's own norms).

use crate::compare::outcome::SceneOutcome;
use crate::results::exchange::FORMAT;
use crate::results::exchange::meta::{CaseMeta, Located, MetaValue, ResultsMeta};
use crate::results::exchange::record::{
    CaseData, CaseFile, ExchangeSet, ForceHistory, Positions, Profile, SpectrumRow,
};
use crate::scene::cases::Scene;
use courant_solver::integrator::ParameterValue;
use std::collections::BTreeMap;

/// One case file of an exported set.
fn case_file(case: &str, data: CaseData) -> CaseFile {
    CaseFile {
        case: case.to_string(),
        file: format!("{case}.csv"),
        columns: Vec::new(),
        data,
        reference: None,
    }
}

/// The set of a compared scene (`label` names it): element-average profiles on each case's
/// mesh (stress profiles), `t, force, gap` (contact: the force the scene grades), `mode, omega,
/// mass` (spectra), and a
/// `results.toml` with code `courant`, its version and per case scheme, mass, dt and elements.
/// `None` for a scene the format has no form for (dispersion, contact stability).
pub fn exchange_set(scene: &Scene, outcome: &SceneOutcome, label: &str) -> Option<ExchangeSet> {
    let mut cases = Vec::new();
    let mut meta = BTreeMap::new();
    for (case, r) in scene.cases.iter().zip(&outcome.results) {
        let nodes = case.model.bar().mesh().nodes();
        let n = nodes.len() - 1;
        let profiles = r
            .profiles
            .iter()
            .map(|p| Profile {
                time: p.time,
                positions: Positions::Elements {
                    left: nodes[..n].to_vec(),
                    right: nodes[1..].to_vec(),
                },
                stress: p.stress.clone(),
                lines: Vec::new(),
            })
            .collect();
        cases.push(case_file(&r.run.case, CaseData::Profiles(profiles)));
        meta.insert(
            r.run.case.clone(),
            CaseMeta {
                scheme: Some(case.integrator.scheme.name().to_string()),
                parameters: case
                    .parameters
                    .iter()
                    .map(|(k, v)| {
                        let value = match v {
                            ParameterValue::Number(x) => MetaValue::Number(*x),
                            ParameterValue::Text(word) => MetaValue::Text(word.clone()),
                        };
                        (k.clone(), Located::unplaced(value))
                    })
                    .collect(),
                mass: Some((r.run.critical.mass.label(), 0, 0)),
                dt: Some(r.run.dt),
                elements: Some((r.elements, 0)),
                ..CaseMeta::default()
            },
        );
    }
    for c in &outcome.contact {
        let h = &c.run.history;
        let history = ForceHistory {
            time: h.iter().map(|s| s.time).collect(),
            // The force the scene grades (the seed's eps_s x penetration, or the momentum
            // delivered over dt), so that the file is graded as the run is.
            force: h.iter().map(|s| c.measure.force(s)).collect(),
            penetration: None,
            gap: Some(h.iter().map(|s| s.gap).collect()),
            lines: Vec::new(),
        };
        cases.push(case_file(&c.case, CaseData::Force(history)));
        meta.insert(
            c.case.clone(),
            CaseMeta {
                scheme: Some(c.run.scheme.label().to_string()),
                parameters: contact_parameters(scene, &c.case),
                dt: Some(c.run.dt),
                ..CaseMeta::default()
            },
        );
    }
    for s in &outcome.spectra {
        let rows = s
            .masses
            .iter()
            .zip(&s.computed)
            .flat_map(|(m, omega)| {
                s.modes
                    .iter()
                    .zip(omega)
                    .map(|(&mode, &omega)| SpectrumRow {
                        mode,
                        omega,
                        mass: Some(m.label()),
                        line: 0,
                    })
            })
            .collect();
        cases.push(case_file(&s.case, CaseData::Spectrum(rows)));
    }
    if cases.is_empty() {
        return None;
    }
    cases.sort_by(|a, b| a.case.cmp(&b.case));
    Some(ExchangeSet {
        label: label.to_string(),
        cases,
        meta: Some(ResultsMeta {
            file: "results.toml".into(),
            format: FORMAT,
            code: Some("courant".into()),
            version: Some(env!("CARGO_PKG_VERSION").into()),
            cases: meta,
        }),
    })
}

/// The penalties of a contact case as `results.toml` declares them (`beta_s`, `beta_m`).
fn contact_parameters(scene: &Scene, case: &str) -> Vec<(String, Located<MetaValue>)> {
    let penalty = scene
        .contact
        .iter()
        .find(|c| c.name == case)
        .and_then(|c| c.penalty);
    penalty.map_or_else(Vec::new, |(beta_s, beta_m)| {
        vec![
            (
                "beta_s".into(),
                Located::unplaced(MetaValue::Number(beta_s)),
            ),
            (
                "beta_m".into(),
                Located::unplaced(MetaValue::Number(beta_m)),
            ),
        ]
    })
}
