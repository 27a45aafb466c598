//! Reading a scene: TOML to a validated [`Scene`], dispatched by study kind.

use super::cases::Scene;
use super::error::{SceneError, Source};
use super::expectation::{Study, expectation};
use super::geometry::Geometry;
use super::schema::{RawContactScene, RawHeader, RawScene};
use super::scheme_keys::{SchemeKey, split_off};
use super::{contact, dispersion, spectrum, time_stepping};
use serde::Deserialize;

impl Scene {
    /// Parse and validate a scene. `file` is the path or name shown in errors; `name` becomes the
    /// output directory.
    pub fn parse(name: &str, file: &str, text: &str) -> Result<Scene, SceneError> {
        let src = Source { file, text };
        let table: toml::Table = toml::from_str(text).map_err(|e| src.from_toml(&e))?;
        if table.contains_key("contact") || table.contains_key("contact_stability") {
            let raw: RawContactScene = toml::from_str(text).map_err(|e| src.from_toml(&e))?;
            return build_contact(name, &src, raw);
        }
        // The schemes' parameters leave [integrator] first; the rest is read with its spans.
        let mut document = toml::de::DeTable::parse(text).map_err(|e| src.from_toml(&e))?;
        let scheme_keys = split_off(&src, &table, document.get_mut())?;
        let raw = RawScene::deserialize(toml::de::Deserializer::from(document))
            .map_err(|e| src.from_toml(&e))?;
        build(name, &src, raw, &scheme_keys)
    }

    /// Read a scene from a file; its name is the file stem.
    pub fn from_path(path: &std::path::Path) -> Result<Scene, SceneError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| SceneError {
            file: file.clone(),
            line: 0,
            column: 0,
            key: String::new(),
            message: format!("cannot read the file: {e}"),
        })?;
        let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("scene");
        Scene::parse(name, &file, &text)
    }
}

/// The `[scene]` table: a description and a source of truth, neither empty.
fn check_header(src: &Source, header: &RawHeader) -> Result<(), SceneError> {
    for (value, key) in [
        (&header.description, "scene.description"),
        (&header.source, "scene.source"),
    ] {
        if value.get_ref().trim().is_empty() {
            return Err(src.error(Some(value.span()), key, "must not be empty"));
        }
    }
    Ok(())
}

fn build(
    name: &str,
    src: &Source,
    raw: RawScene,
    scheme_keys: &[SchemeKey],
) -> Result<Scene, SceneError> {
    check_header(src, &raw.scene)?;
    let geometry = Geometry::read(src, &raw)?;
    if raw.spectrum.is_some() || raw.dispersion.is_some() {
        let (kind, study) = if raw.spectrum.is_some() {
            ("spectrum", Study::Spectrum)
        } else {
            ("dispersion", Study::Dispersion)
        };
        if raw.integrator.is_some() || (raw.spectrum.is_some() && raw.dispersion.is_some()) {
            return Err(src.error(
                None,
                kind,
                "a spectrum or dispersion scene has no [integrator] and is one study only",
            ));
        }
        let (spectra, dispersion) = match (&raw.spectrum, &raw.dispersion) {
            (Some(s), _) => (spectrum::build(src, &raw, s, &geometry)?, Vec::new()),
            (None, Some(d)) => (Vec::new(), dispersion::build(src, d, &geometry)?),
            (None, None) => (Vec::new(), Vec::new()),
        };
        let names: Vec<String> = spectra
            .iter()
            .map(|c| c.name.clone())
            .chain(dispersion.iter().map(|c| c.name.clone()))
            .collect();
        let mut seen = std::collections::HashSet::new();
        if let Some(dup) = names.iter().find(|n| !seen.insert(*n)) {
            return Err(src.error(None, kind, format!("case {dup} appears twice")));
        }
        let expectations = raw
            .expectations
            .iter()
            .map(|e| expectation(src, e, &names, false, study, &[], 1.0))
            .collect::<Result<Vec<_>, _>>()?;
        return Ok(Scene {
            name: name.to_string(),
            description: raw.scene.description.get_ref().clone(),
            source: raw.scene.source.get_ref().clone(),
            cases: Vec::new(),
            spectra,
            dispersion,
            contact: Vec::new(),
            contact_sweeps: Vec::new(),
            expectations,
        });
    }
    let (cases, expectations) = time_stepping::build(src, &raw, &geometry, scheme_keys)?;
    Ok(Scene {
        name: name.to_string(),
        description: raw.scene.description.into_inner(),
        source: raw.scene.source.into_inner(),
        cases,
        spectra: Vec::new(),
        dispersion: Vec::new(),
        contact: Vec::new(),
        contact_sweeps: Vec::new(),
        expectations,
    })
}

fn build_contact(name: &str, src: &Source, raw: RawContactScene) -> Result<Scene, SceneError> {
    check_header(src, &raw.scene)?;
    let (cases, sweeps, study) = match (&raw.contact, &raw.contact_stability) {
        (Some(study), None) => (
            contact::cases(src, &raw, study)?,
            Vec::new(),
            Study::Contact,
        ),
        (None, Some(study)) => (
            Vec::new(),
            vec![contact::sweep(src, study)?],
            Study::ContactStability,
        ),
        _ => {
            return Err(src.error(
                None,
                "contact",
                "a contact scene has either [contact] or [contact_stability], not both",
            ));
        }
    };
    let names: Vec<String> = if study == Study::Contact {
        cases.iter().map(|c| c.name.clone()).collect()
    } else {
        vec!["stability".into()]
    };
    let expectations = raw
        .expectations
        .iter()
        .map(|e| expectation(src, e, &names, false, study, &[], 1.0))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Scene {
        name: name.to_string(),
        description: raw.scene.description.get_ref().clone(),
        source: raw.scene.source.get_ref().clone(),
        cases: Vec::new(),
        spectra: Vec::new(),
        dispersion: Vec::new(),
        contact: cases,
        contact_sweeps: sweeps,
        expectations,
    })
}
