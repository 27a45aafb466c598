//! Reading a scene: TOML to a validated [`Scene`], dispatched by study kind.

use super::budget;
use super::cases::Scene;
use super::error::{SceneError, Source, collect_all};
use super::expectation::{ExpectContext, Study, expectation};
use super::finding::{Finding, finding};
use super::geometry::Geometry;
use super::limits::Limits;
use super::schema::{RawContactScene, RawFinding, RawHeader, RawScene};
use super::scheme_keys::{SchemeKey, split_off};
use super::work::Work;
use super::{contact, dispersion, names, spectrum, time_stepping};
use courant_solver::MassKind;
use serde::Deserialize;
use toml::Spanned;

/// Unknown keys and bad values reported in one pass, at most.
const MAX_UNKNOWN_KEYS: usize = 20;

/// `text` with line `line` (1-based) replaced by spaces: positions elsewhere stay the same.
fn blank_line(text: &str, line: usize) -> String {
    text.split_inclusive('\n')
        .enumerate()
        .map(|(i, l)| {
            if i + 1 == line {
                l.chars().map(|c| if c == '\n' { c } else { ' ' }).collect()
            } else {
                l.to_string()
            }
        })
        .collect()
}

/// Values that stand in for a bad one while the rest of the file is checked: the first one the
/// line accepts is used (a count, a Courant number, a length; a list of one).
const NEUTRAL_VALUES: &[&str] = &["1", "0.5", "[1]", "[0.5]"];

/// True when line `line` (1-based) of `text` is a table header (`[output]`, `[[expect]]`).
fn is_header(text: &str, line: usize) -> bool {
    text.lines()
        .nth(line.wrapping_sub(1))
        .is_some_and(|l| l.trim_start().starts_with('['))
}

/// The line (1-based) of the header of the table that line `line` is in (0 for the top level).
fn header_of(text: &str, line: usize) -> usize {
    text.lines()
        .take(line)
        .enumerate()
        .filter(|(_, l)| l.trim_start().starts_with('['))
        .map(|(i, _)| i + 1)
        .last()
        .unwrap_or(0)
}

/// `text` with the value of the `key = value` on line `line` replaced by `value`, when that
/// line holds a whole key and value (brackets and braces balanced); `None` otherwise.
fn replace_value(text: &str, line: usize, value: &str) -> Option<String> {
    let mut out = String::with_capacity(text.len());
    let mut replaced = false;
    for (i, l) in text.split_inclusive('\n').enumerate() {
        if i + 1 != line {
            out.push_str(l);
            continue;
        }
        let (key, old) = l.split_once('=')?;
        let balanced = |open: char, close: char| {
            old.chars().filter(|&c| c == open).count()
                == old.chars().filter(|&c| c == close).count()
        };
        if key.trim().is_empty() || key.contains('[') || !balanced('[', ']') || !balanced('{', '}')
        {
            return None;
        }
        out.push_str(key);
        out.push_str("= ");
        out.push_str(value);
        if l.ends_with('\n') {
            out.push('\n');
        }
        replaced = true;
    }
    replaced.then_some(out)
}

/// `text` with the key of the `key = value` on line `line` renamed to `to`; `None` when the line
/// holds no such pair.
fn rename_key(text: &str, line: usize, to: &str) -> Option<String> {
    let mut out = String::with_capacity(text.len());
    let mut renamed = false;
    for (i, l) in text.split_inclusive('\n').enumerate() {
        if i + 1 == line {
            let (key, value) = l.split_once('=')?;
            let indent = &key[..key.len() - key.trim_start().len()];
            out.push_str(&format!("{indent}{to} ={value}"));
            renamed = true;
        } else {
            out.push_str(l);
        }
    }
    renamed.then_some(out)
}

/// One reading of a scene: its first error.
fn parse_once(name: &str, file: &str, text: &str, limits: Limits) -> Result<Scene, SceneError> {
    let src = Source { file, text, limits };
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

impl Scene {
    /// Parse and validate a scene. `file` is the path or name shown in errors; `name` becomes the
    /// output directory.
    ///
    /// Every unknown key and every bad value of the file is reported in one pass: each unknown
    /// key is set aside and each bad value replaced by a neutral one ([`NEUTRAL_VALUES`]), and
    /// the file read again; an error that the setting aside or the replacement may have caused
    /// (a key missing from its table, an error on the replaced line) ends the pass unreported.
    /// Invalid `[[expect]]` tables are all reported too.
    pub fn parse(name: &str, file: &str, text: &str) -> Result<Scene, SceneError> {
        Self::parse_within(name, file, text, Limits::DEFAULT)
    }

    /// [`Scene::parse`] against `limits` ([`Limits::LARGE`] for `courant run --large`).
    pub fn parse_within(
        name: &str,
        file: &str,
        text: &str,
        limits: Limits,
    ) -> Result<Scene, SceneError> {
        let first = match parse_once(name, file, text, limits) {
            Ok(scene) => return Ok(scene),
            Err(e) => e,
        };
        // Flat: each error's `also` (its file's other `[[expect]]` tables) taken out, so that a
        // later reading that finds them again adds nothing twice.
        let mut errors = Vec::new();
        // Returns the index of the first of `e`'s errors.
        let push = |errors: &mut Vec<SceneError>, mut e: SceneError| -> usize {
            let also = std::mem::take(&mut e.also);
            let mut first = None;
            for e in std::iter::once(e).chain(also) {
                let same = |o: &SceneError| {
                    (o.line, o.column, &o.message) == (e.line, e.column, &e.message)
                };
                let index = errors.iter().position(same).unwrap_or_else(|| {
                    errors.push(e);
                    errors.len() - 1
                });
                first.get_or_insert(index);
            }
            first.unwrap_or(0)
        };
        let mut at = push(&mut errors, first);
        let mut rest = text.to_string();
        // The headers of the tables a line was set aside or replaced in.
        let mut touched = Vec::new();
        // Bounded: each round blanks or neutralises one line of the file.
        for _ in 0..MAX_UNKNOWN_KEYS {
            let Some(last) = errors.get(at) else { break };
            if last.line == 0 || is_header(&rest, last.line) {
                break;
            }
            let unknown = last.message.starts_with("unknown field");
            // An unknown key is read as the key it is nearest to (`profile_tims` as
            // `profile_times`, so that its absence causes nothing) or else set aside; a bad value
            // is replaced by a neutral one (the first the line accepts), so the next round finds
            // the next bad value.
            let candidates: Vec<String> = if unknown {
                let meant = last
                    .message
                    .split_once("(did you mean `")
                    .and_then(|(_, m)| m.split_once('`'))
                    .and_then(|(meant, _)| rename_key(&rest, last.line, meant));
                meant
                    .into_iter()
                    .chain(std::iter::once(blank_line(&rest, last.line)))
                    .collect()
            } else {
                NEUTRAL_VALUES
                    .iter()
                    .filter_map(|v| replace_value(&rest, last.line, v))
                    .collect()
            };
            let (line, message) = (last.line, last.message.clone());
            let next = candidates.into_iter().find_map(|candidate| {
                match parse_once(name, file, &candidate, limits) {
                    Ok(_) => Some((candidate, None)),
                    // The neutral value itself broke a rule of this line: try the next one.
                    Err(e) if e.line == line => None,
                    Err(e) => Some((candidate, Some(e))),
                }
            });
            let Some((candidate, next)) = next else { break };
            rest = candidate;
            touched.push(header_of(&rest, line));
            match next {
                None => break,
                Some(e) if e.line == line && e.message == message => break,
                // What a set-aside key or a replaced value may have caused, not what the file
                // says: an error on the line just replaced, or at the header of a table a line
                // was taken from (where a missing key is reported). Never reported, to mislead
                // no one; a real one shows once the errors above are mended.
                Some(e) if e.line == line || touched.contains(&e.line) => break,
                Some(e) => at = push(&mut errors, e),
            }
        }
        Err(SceneError::all(errors).expect("one error at least"))
    }

    /// Read a scene from a file; its name is the file stem.
    pub fn from_path(path: &std::path::Path) -> Result<Scene, SceneError> {
        Self::from_path_within(path, Limits::DEFAULT)
    }

    /// [`Scene::from_path`] against `limits`.
    pub fn from_path_within(path: &std::path::Path, limits: Limits) -> Result<Scene, SceneError> {
        let file = path.display().to_string();
        let whole_file = |message: String| SceneError {
            file: file.clone(),
            line: 0,
            column: 0,
            key: String::new(),
            message,
            also: Vec::new(),
        };
        // Never open a FIFO or a device: reading one may block forever or never end.
        if let Some(kind) = crate::io::file_kind::non_regular_kind(path) {
            return Err(whole_file(format!(
                "is a {kind}, not a scene file (a scene is a regular .toml file)"
            )));
        }
        let text = crate::io::bounded_read::read_text(path, crate::io::bounded_read::TEXT_CAP)
            .map_err(|e| {
                let (line, column) = e.location();
                SceneError {
                    line,
                    column,
                    ..whole_file(format!("the scene file {e}"))
                }
            })?;
        let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("scene");
        Scene::parse_within(name, &file, &text, limits)
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
        names::check(src, None, kind, &names)?;
        let masses: Vec<MassKind> = spectra.first().map_or(Vec::new(), |c| c.masses.clone());
        let ctx = ExpectContext {
            names: &names,
            has_reference: false,
            study,
            profile_times: &[],
            unit: 1.0,
            masses: &masses,
        };
        let expectations = collect_all(raw.expectations.iter().map(|e| expectation(src, e, &ctx)))?;
        let elements = (Some(raw.mesh.elements.span()), "mesh.elements");
        return within_budget(
            src,
            [&elements, &elements, &elements],
            Scene {
                name: name.to_string(),
                description: raw.scene.description.get_ref().clone(),
                source: raw.scene.source.get_ref().clone(),
                cases: Vec::new(),
                spectra,
                dispersion,
                contact: Vec::new(),
                contact_sweeps: Vec::new(),
                expectations,
                stability: raw.scene.stability,
                findings: findings(src, &raw.findings, &names, raw.scene.stability)?,
            },
        );
    }
    budget::time_stepping_validation(src, &raw, &geometry.element_counts, scheme_keys)?;
    let (cases, expectations) = time_stepping::build(src, &raw, &geometry, scheme_keys)?;
    let stepping = raw.integrator.as_ref().and_then(|i| {
        i.courant
            .as_ref()
            .map(|c| (c.span(), "integrator.courant"))
            .or(i.dt.as_ref().map(|d| (d.span(), "integrator.dt")))
    });
    let (stepping_span, stepping_key) = (
        stepping.as_ref().map(|s| s.0.clone()),
        stepping.as_ref().map_or("integrator", |s| s.1),
    );
    for case in &cases {
        super::magnitude::courant(
            src,
            stepping_span.clone(),
            stepping_key,
            &case.name,
            case.integrator.dt / case.critical.element_transit,
        )?;
    }
    let names: Vec<String> = cases.iter().map(|c| c.name.clone()).collect();
    names::check(src, stepping_span, stepping_key, &names)?;
    let findings = findings(src, &raw.findings, &names, raw.scene.stability)?;
    let output = &raw.output;
    let steps_blame = (Some(raw.mesh.elements.span()), "mesh.elements");
    let output_blame = match (
        &output.history_every,
        &output.energy_every,
        &output.profile_times,
    ) {
        (Some(h), _, _) => (Some(h.span()), "output.history_every"),
        (None, Some(e), _) => (Some(e.span()), "output.energy_every"),
        (None, None, Some(p)) => (Some(p.span()), "output.profile_times"),
        (None, None, None) => (Some(raw.mesh.elements.span()), "mesh.elements"),
    };
    let reference_blame = (
        raw.reference.kind.as_ref().map(|k| k.span()),
        "reference.kind",
    );
    within_budget(
        src,
        [&steps_blame, &output_blame, &reference_blame],
        Scene {
            name: name.to_string(),
            description: raw.scene.description.get_ref().clone(),
            source: raw.scene.source.get_ref().clone(),
            cases,
            spectra: Vec::new(),
            dispersion: Vec::new(),
            contact: Vec::new(),
            contact_sweeps: Vec::new(),
            expectations,
            stability: raw.scene.stability,
            findings,
        },
    )
}

/// `scene` when its work, output and reference stay within [`budget`]'s limits, else the error
/// at the key `blame` names for each (`[node-steps, output values, reference]`).
fn within_budget(
    src: &Source,
    blame: [&budget::Blame; 3],
    scene: Scene,
) -> Result<Scene, SceneError> {
    let work = Work::of(&scene).map_err(|why| src.error(blame[2].0.clone(), blame[2].1, why))?;
    work.check(src, blame)?;
    Ok(scene)
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
    let (steps_blame, names_blame) = match (&raw.contact, &raw.contact_stability) {
        (Some(c), _) => (
            (Some(c.end_time.span()), "contact.end_time"),
            (Some(c.schemes.span()), "contact.schemes"),
        ),
        (None, Some(s)) => (
            (Some(s.points.span()), "contact_stability.points"),
            (Some(s.points.span()), "contact_stability.points"),
        ),
        (None, None) => ((None, "contact"), (None, "contact")),
    };
    names::check(src, names_blame.0.clone(), names_blame.1, &names)?;
    let output_blame = match raw.contact.as_ref().and_then(|c| c.history_every.as_ref()) {
        Some(h) => (Some(h.span()), "contact.history_every"),
        None => steps_blame.clone(),
    };
    let ctx = ExpectContext {
        names: &names,
        has_reference: false,
        study,
        profile_times: &[],
        unit: 1.0,
        masses: &[],
    };
    let expectations = collect_all(raw.expectations.iter().map(|e| expectation(src, e, &ctx)))?;
    within_budget(
        src,
        [&steps_blame, &output_blame, &steps_blame],
        Scene {
            name: name.to_string(),
            description: raw.scene.description.get_ref().clone(),
            source: raw.scene.source.get_ref().clone(),
            cases: Vec::new(),
            spectra: Vec::new(),
            dispersion: Vec::new(),
            contact: cases,
            contact_sweeps: sweeps,
            expectations,
            stability: raw.scene.stability,
            findings: findings(src, &raw.findings, &names, raw.scene.stability)?,
        },
    )
}

/// The scene's `[[finding]]` tables.
fn findings(
    src: &Source,
    raw: &[Spanned<RawFinding>],
    names: &[String],
    stability: bool,
) -> Result<Vec<Finding>, SceneError> {
    collect_all(raw.iter().map(|f| finding(src, f, names, stability)))
}
