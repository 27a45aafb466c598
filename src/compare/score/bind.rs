//! Binding a result set to its scene: each file to the case its stem names, checked against
//! that case before anything is compared (the kind of data the scene's cases produce, a mesh
//! that covers the bar, points on it, mass labels the scene knows, modes the closed forms have),
//! every error naming file, line, column and key.

use super::applies::{Applies, Declared};
use super::outcome::ScoreError;
use super::reference_work::check_reference_work;
use crate::results::exchange::error::short_number;
use crate::results::exchange::error::{ExchangeError, ExchangeErrors};
use crate::results::exchange::meta::CaseMeta;
use crate::results::exchange::reader::TOUCH;
use crate::results::exchange::record::{CaseData, CaseFile, ExchangeSet, Positions};
use crate::scene::cases::{Case, Scene};
use crate::scene::contact::ContactCase;
use crate::scene::magnitude::MAGNITUDE_MAX;
use crate::scene::mass::parse_mass;
use crate::scene::reference::Reference;
use crate::scene::spectrum::SpectrumCase;
use courant_solver::MassKind;

/// What the cases of a scene produce, i.e. what its result files hold.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SceneKind {
    /// Time-stepping cases: stress profiles.
    Stepping,
    /// Contact cases: force histories.
    Contact,
    /// Spectrum cases: spectra.
    Spectrum,
}

impl SceneKind {
    /// The kind of a scene with an exchange form.
    ///
    /// # Errors
    /// A dispersion or contact-stability scene (format 1 has no form for them), or a
    /// time-stepping scene without an analytic reference.
    pub fn of(scene: &Scene) -> Result<SceneKind, ScoreError> {
        if !scene.cases.is_empty() {
            if scene.cases.iter().any(|c| c.reference.is_none()) {
                return Err(ScoreError::Scene(format!(
                    "scene `{}` has no analytic reference: a result file's stress profiles are graded against one",
                    scene.name
                )));
            }
            Ok(SceneKind::Stepping)
        } else if !scene.contact.is_empty() {
            Ok(SceneKind::Contact)
        } else if !scene.spectra.is_empty() {
            Ok(SceneKind::Spectrum)
        } else {
            Err(ScoreError::Scene(format!(
                "scene `{}` is a dispersion or contact-stability study: the exchange format (format 1) carries stress profiles, contact force histories and spectra",
                scene.name
            )))
        }
    }

    /// What a file of this scene holds, for messages.
    pub fn holds(self) -> &'static str {
        match self {
            SceneKind::Stepping => "stress profiles (t, x_left, x_right, stress or t, x, stress)",
            SceneKind::Contact => "contact force histories (t, force)",
            SceneKind::Spectrum => "spectra (mode, omega)",
        }
    }

    /// Case names of the scene, in order.
    pub fn case_names(self, scene: &Scene) -> Vec<String> {
        match self {
            SceneKind::Stepping => scene.cases.iter().map(|c| c.name.clone()).collect(),
            SceneKind::Contact => scene.contact.iter().map(|c| c.name.clone()).collect(),
            SceneKind::Spectrum => scene.spectra.iter().map(|c| c.name.clone()).collect(),
        }
    }
}

/// The scene case a file answers.
#[derive(Debug, Clone, Copy)]
pub enum Target<'a> {
    /// A time-stepping case and its reference.
    Stepping(&'a Case, &'a Reference),
    /// A contact case.
    Contact(&'a ContactCase),
    /// A spectrum case.
    Spectrum(&'a SpectrumCase),
}

/// A file bound to its case, with what `results.toml` says of it.
#[derive(Debug, Clone)]
pub struct Bound<'a> {
    /// The file.
    pub file: &'a CaseFile,
    /// The case it answers.
    pub target: Target<'a>,
    /// `results.toml`'s table of the case.
    pub meta: Option<&'a CaseMeta>,
    /// The mass kind `results.toml` names.
    pub mass: Option<MassKind>,
    /// The time step: `results.toml`'s, else the scene case's.
    pub dt: Option<(f64, &'static str)>,
    /// Mass kind of each spectrum row (spectra only).
    pub row_masses: Vec<MassKind>,
    /// Whether the case's signature rows apply (what `results.toml` declares against the case).
    pub applies: Applies,
}

/// The profile times of a time-stepping case: its profile steps times `dt`, as the solver
/// computes them (`t^n = n dt`).
pub fn profile_times(case: &Case) -> Vec<f64> {
    let mut steps = case.request.profile_steps.clone();
    steps.sort_unstable();
    steps.dedup();
    steps
        .into_iter()
        .map(|n| n as f64 * case.integrator.dt)
        .collect()
}

/// `(start, end)` of a case's bar.
pub fn bar_extent(case: &Case) -> (f64, f64) {
    let mesh = case.model.bar().mesh();
    (mesh.start(), mesh.start() + mesh.length())
}

/// Bind every file of `set` to the case of `scene` its stem names.
///
/// # Errors
/// A scene without an exchange form ([`SceneKind::of`]); a file whose stem names no case, whose
/// data is not what the scene's cases produce, whose mesh does not cover the bar or whose points
/// leave it, whose modes the closed forms do not have; a mass label the scene does not know;
/// `elements` in `results.toml` that disagree with the file.
pub fn bind<'a>(scene: &'a Scene, set: &'a ExchangeSet) -> Result<Vec<Bound<'a>>, ScoreError> {
    let kind = SceneKind::of(scene)?;
    let names = kind.case_names(scene);
    let mut bound = Vec::new();
    let mut errors = Vec::new();
    for file in &set.cases {
        let meta = set.meta.as_ref().and_then(|m| m.case(&file.case));
        let meta_file = set.meta.as_ref().map_or("", |m| m.file.as_str());
        match bind_file(scene, kind, &names, file, meta, meta_file) {
            Ok(b) => bound.push(b),
            Err(ScoreError::Input(e)) => errors.extend(e.0),
            Err(other) => return Err(other),
        }
    }
    if errors.is_empty() {
        Ok(bound)
    } else {
        Err(ScoreError::Input(ExchangeErrors(errors)))
    }
}

fn bind_file<'a>(
    scene: &'a Scene,
    kind: SceneKind,
    names: &[String],
    file: &'a CaseFile,
    meta: Option<&'a CaseMeta>,
    meta_file: &str,
) -> Result<Bound<'a>, ScoreError> {
    let refuse = |message: String| ExchangeError::at(&file.file, 1, 1, "", message);
    if !names.contains(&file.case) {
        return Err(refuse(format!(
            "no case `{}` in scene `{}` (cases: {}): a result file is named after the case it answers",
            file.case,
            scene.name,
            names.join(", ")
        ))
        .into());
    }
    let mass = match meta.and_then(|m| m.mass.as_ref()) {
        Some((label, line, column)) => Some(parse_mass(label).map_err(|rule| {
            ExchangeError::at(
                meta_file,
                *line,
                *column,
                &format!("cases.\"{}\".mass", file.case),
                rule,
            )
        })?),
        None => None,
    };
    let meta_dt = meta.and_then(|m| m.dt).map(|dt| (dt, "results.toml"));
    let mut row_masses = Vec::new();
    // A spectrum's rows name their mass kinds, and its signatures are of those masses.
    let mut applies = Applies::Yes;
    let (target, dt) = match (kind, &file.data) {
        (SceneKind::Stepping, CaseData::Profiles(profiles)) => {
            let case = scene
                .cases
                .iter()
                .find(|c| c.name == file.case)
                .expect("the stem names a case");
            let reference = case.reference.as_ref().expect("checked by SceneKind::of");
            for p in profiles {
                check_magnitudes(file, "stress", &p.stress, &p.lines)?;
            }
            check_on_bar(file, profiles, bar_extent(case))?;
            check_reference_work(file, profiles, reference, bar_extent(case))?;
            if let (Some((n, line)), Some(first)) =
                (meta.and_then(|m| m.elements), profiles.first())
                && matches!(first.positions, Positions::Elements { .. })
                && first.positions.len() != n
            {
                return Err(ExchangeError::at(
                    meta_file,
                    line,
                    1,
                    &format!("cases.\"{}\".elements", file.case),
                    format!(
                        "elements = {n}, but {} has {} elements at t = {}",
                        file.file,
                        first.positions.len(),
                        first.time
                    ),
                )
                .into());
            }
            // The file's mesh: declared, or its elements (a point file's is unknown).
            let file_elements = meta.and_then(|m| m.elements).map(|(n, _)| n).or_else(|| {
                profiles.first().and_then(|p| match p.positions {
                    Positions::Elements { .. } => Some(p.positions.len()),
                    Positions::Points(_) => None,
                })
            });
            let declared = Declared::stepping(meta, mass, &file.case, meta_file)?;
            applies =
                declared.applies_to_stepping(&case.integrator.scheme.label(), case.integrator.mass);
            (
                Target::Stepping(case, reference),
                declared_dt(
                    meta,
                    meta_dt,
                    meta_file,
                    &file.case,
                    file_elements.map(|n| {
                        case.integrator.dt * case.model.bar().element_count() as f64 / n as f64
                    }),
                    case.integrator.dt,
                )?,
            )
        }
        (SceneKind::Contact, CaseData::Force(history)) => {
            check_magnitudes(file, "force", &history.force, &history.lines)?;
            let case = scene
                .contact
                .iter()
                .find(|c| c.name == file.case)
                .expect("the stem names a case");
            applies = Declared::contact(meta, &file.case, meta_file)?.applies_to_contact(case);
            (
                Target::Contact(case),
                declared_dt(
                    meta,
                    meta_dt,
                    meta_file,
                    &file.case,
                    Some(case.integrator.dt),
                    case.integrator.dt,
                )?,
            )
        }
        (SceneKind::Spectrum, CaseData::Spectrum(rows)) => {
            let case = scene
                .spectra
                .iter()
                .find(|c| c.name == file.case)
                .expect("the stem names a case");
            let Some(bar) = &case.closed_form else {
                return Err(ScoreError::Scene(format!(
                    "case `{}` of scene `{}` has no closed-form spectrum (its bar is not uniform and homogeneous): nothing to grade {} against",
                    case.name, scene.name, file.file
                )));
            };
            let modes = bar.modes();
            for row in rows {
                let row_mass = match (&row.mass, mass, case.masses.as_slice()) {
                    (Some(label), _, _) => parse_mass(label).map_err(|rule| {
                        ExchangeError::at(&file.file, row.line, file.column("mass"), "mass", rule)
                    })?,
                    (None, Some(m), _) => m,
                    (None, None, [only]) => *only,
                    (None, None, _) => {
                        return Err(ExchangeError::at(
                            &file.file,
                            row.line,
                            file.column("mode"),
                            "mass",
                            format!(
                                "which mass kind? case `{}` has several ({}): add a `mass` column or `mass` in results.toml",
                                case.name,
                                case.masses.iter().map(|m| m.label()).collect::<Vec<_>>().join(", ")
                            ),
                        )
                        .into());
                    }
                };
                if !modes.contains(&row.mode) {
                    return Err(ExchangeError::at(
                        &file.file,
                        row.line,
                        file.column("mode"),
                        "mode",
                        format!(
                            "mode {} is not a mode of this bar ({}..={})",
                            row.mode,
                            modes.start(),
                            modes.end()
                        ),
                    )
                    .into());
                }
                row_masses.push(row_mass);
            }
            (Target::Spectrum(case), None)
        }
        (_, data) => {
            return Err(refuse(format!(
                "scene `{}` answers with {}; this file holds {}",
                scene.name,
                kind.holds(),
                data.describe()
            ))
            .into());
        }
    };
    Ok(Bound {
        file,
        target,
        meta,
        mass,
        dt,
        row_masses,
        applies,
    })
}

/// The step the diagnostics measure in: the declared `dt` of `results.toml`, else the scene
/// case's. A declared step larger than the case's step on the file's mesh (`case_dt`, the
/// case's Courant number: its dt times its elements over the file's) is refused at its case
/// table: the time-level diagnostic measures lags in steps, so a larger declared step would hide
/// a lag of a step the code really took. A smaller one (a lower Courant number) only makes the
/// diagnostic stricter.
fn declared_dt(
    meta: Option<&CaseMeta>,
    declared: Option<(f64, &'static str)>,
    meta_file: &str,
    case: &str,
    case_dt: Option<f64>,
    scene_dt: f64,
) -> Result<Option<(f64, &'static str)>, ExchangeError> {
    match (declared, case_dt) {
        (Some((dt, _)), Some(expected)) if dt > expected * (1.0 + 1e-6) => Err(ExchangeError::at(
            meta_file,
            meta.map_or(0, |m| m.line),
            1,
            &format!("cases.\"{case}\".dt"),
            format!(
                "dt = {dt:e} is larger than the scene case's step on this mesh, {expected:e} (its Courant \
                     number): the time-level diagnostic measures lags in steps, and a larger declared step would \
                     hide one; declare the step the code took"
            ),
        )),
        (Some(declared), _) => Ok(Some(declared)),
        (None, _) => Ok(Some((scene_dt, "scene"))),
    }
}

/// Every value of `column` (with its line) within the magnitude limit scenes have
/// ([`MAGNITUDE_MAX`]): beyond it a result has diverged, and its norms would overflow to
/// infinity in the tables.
fn check_magnitudes(
    file: &CaseFile,
    column: &str,
    values: &[f64],
    lines: &[usize],
) -> Result<(), ExchangeError> {
    for (i, v) in values.iter().enumerate() {
        // Sets built in memory have no lines: 0 then.
        let line = lines.get(i).copied().unwrap_or(0);
        if v.abs() > MAGNITUDE_MAX {
            return Err(ExchangeError::at(
                &file.file,
                line,
                file.column(column),
                column,
                format!(
                    "{v:e} is beyond the magnitude limit {MAGNITUDE_MAX:e} of every value courant grades (docs/guide/running.md, \"Limits\"); \
                     a result this large has diverged"
                ),
            ));
        }
    }
    Ok(())
}

/// Every profile of `file` on the bar `[start, end]`: elements from `start` to `end`, points
/// within it (to [`TOUCH`] of the bar's length).
pub fn check_on_bar(
    file: &CaseFile,
    profiles: &[crate::results::exchange::record::Profile],
    (start, end): (f64, f64),
) -> Result<(), ExchangeError> {
    let tol = TOUCH * (end - start);
    let bar = format!("[{start}, {end}]");
    for p in profiles {
        let last = p.positions.len() - 1;
        // Sets built in memory (not read from files) have no lines: 0 then.
        let line = |i: usize| p.lines.get(i).copied().unwrap_or(0);
        match &p.positions {
            Positions::Elements { left, right } => {
                if (left[0] - start).abs() > tol {
                    return Err(ExchangeError::at(
                        &file.file,
                        line(0),
                        file.column("x_left"),
                        "x_left",
                        format!(
                            "the mesh does not cover the bar {bar}: at t = {} it starts at x = {}",
                            short_number(p.time),
                            short_number(left[0])
                        ),
                    ));
                }
                if (right[last] - end).abs() > tol {
                    return Err(ExchangeError::at(
                        &file.file,
                        line(last),
                        file.column("x_right"),
                        "x_right",
                        format!(
                            "the mesh does not cover the bar {bar}: at t = {} it ends at x = {}",
                            short_number(p.time),
                            short_number(right[last])
                        ),
                    ));
                }
            }
            Positions::Points(x) => {
                if let Some(i) = x.iter().position(|&x| x < start - tol || x > end + tol) {
                    return Err(ExchangeError::at(
                        &file.file,
                        line(i),
                        file.column("x"),
                        "x",
                        format!("x = {} lies outside the bar {bar}", short_number(x[i])),
                    ));
                }
            }
        }
    }
    Ok(())
}
