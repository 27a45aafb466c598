//! The bodies of a contact scene and the force its cases are graded against: the striker and
//! the target bar (or the rigid wall) as a `ContactProblem`, with the exact impact force of
//! homogeneous bars (`ImpactForce`, methods.md §7) or of layered and graded ones (`LayeredImpact`
//! of their layers; a graded bar's equal-travel-time layering, not exact for it), and the
//! striker's transit time, the unit of the scene's times.

use super::budget;
use super::contact_bar::{ContactReference, bar, homogeneous, reference_layers, transit};
use super::error::{SceneError, Source, positive};
use super::magnitude;
use super::schema::{RawContact, RawContactScene, RawField};
use courant_references::contact::{ImpactForce, LayeredImpact};
use courant_solver::End;
use courant_solver::contact::ContactProblem;

/// What [`bodies`] builds.
pub(super) struct Bodies {
    /// The bars (or the bar and the wall), the impact velocity and the gap.
    pub(super) problem: ContactProblem,
    /// The force the cases are graded against.
    pub(super) reference: ContactReference,
    /// The striker's transit time `sum h/c` over its layers, the unit of `end_time`.
    pub(super) striker_transit: f64,
}

/// The problem, its reference force and the striker's transit time of a `[contact]` study, each
/// input checked and located (key and line).
pub(super) fn bodies(
    src: &Source,
    raw: &RawContactScene,
    study: &RawContact,
) -> Result<Bodies, SceneError> {
    let area = match &raw.bar.area {
        Some(a) => {
            let area = positive(src, a, "bar.area")?;
            magnitude::input(src, Some(a.span()), "bar.area", "area", area)?;
            area
        }
        None => 1.0,
    };
    let velocity = positive(src, &study.velocity, "contact.velocity")?;
    magnitude::input(
        src,
        Some(study.velocity.span()),
        "contact.velocity",
        "velocity",
        velocity,
    )?;
    let gap = match &study.gap {
        None => 0.0,
        Some(g) if g.get_ref().is_finite() && *g.get_ref() >= 0.0 => *g.get_ref(),
        Some(g) => {
            return Err(src.error(
                Some(g.span()),
                "contact.gap",
                format!("{} must be finite and not negative", g.get_ref()),
            ));
        }
    };
    let layers = reference_layers(src, study)?;
    let (striker, striker_impact) = bar(src, &study.striker, "contact.striker", area, layers)?;
    let (problem, reference) = match (study.problem.get_ref().as_str(), &study.target) {
        ("two-bars", Some(target)) => {
            let (target, target_impact) = bar(src, target, "contact.target", area, layers)?;
            let problem = ContactProblem::bar_impact(striker, target, velocity, gap)
                .map_err(|e| src.error(Some(study.problem.span()), "contact", e.to_string()))?;
            let end =
                positive(src, &study.end_time, "contact.end_time")? * transit(&striker_impact);
            let reference = match (homogeneous(&striker_impact), homogeneous(&target_impact)) {
                (Some(s), Some(t)) => {
                    ImpactForce::new(s, t, velocity).map(ContactReference::Homogeneous)
                }
                _ => LayeredImpact::with_cap(
                    &striker_impact,
                    &target_impact,
                    velocity,
                    1.05 * end,
                    budget::MAX_LAYERED_IMPACT_EVENTS,
                )
                .map(|impact| {
                    let graded = std::iter::once(&study.striker)
                        .chain(study.target.as_ref())
                        .any(|b| matches!(b.get_ref().modulus, Some(RawField::Linear(_))));
                    if graded {
                        ContactReference::GradedLayering { impact, layers }
                    } else {
                        ContactReference::Layered(impact)
                    }
                }),
            };
            (problem, reference)
        }
        ("two-bars", None) => {
            return Err(src.error(
                Some(study.problem.span()),
                "contact.target",
                "problem = \"two-bars\" needs a `target`",
            ));
        }
        ("wall", None) => {
            let problem = ContactProblem::wall_impact(striker, End::Right, velocity, gap)
                .map_err(|e| src.error(Some(study.problem.span()), "contact", e.to_string()))?;
            let reference = match homogeneous(&striker_impact) {
                Some(s) => ImpactForce::rigid_wall(s, velocity).map(ContactReference::Homogeneous),
                None => {
                    return Err(src.error(
                        Some(study.striker.span()),
                        "contact.striker.layers",
                        "a wall problem takes a homogeneous striker (its exact force is for one layer)",
                    ));
                }
            };
            (problem, reference)
        }
        ("wall", Some(t)) => {
            return Err(src.error(
                Some(t.span()),
                "contact.target",
                "a wall problem has no target",
            ));
        }
        (other, _) => {
            return Err(src.error(
                Some(study.problem.span()),
                "contact.problem",
                format!("\"{other}\" is not one of two-bars, wall"),
            ));
        }
    };
    let reference =
        reference.map_err(|e| src.error(Some(study.problem.span()), "contact", e.to_string()))?;
    if let Some(g) = &study.gap {
        magnitude::input(src, Some(g.span()), "contact.gap", "gap", gap)?;
    }
    for (body, key) in problem
        .bodies()
        .iter()
        .zip(["contact.striker", "contact.target"])
    {
        let span = if key == "contact.striker" {
            Some(study.striker.span())
        } else {
            study.target.as_ref().map(|t| t.span())
        };
        magnitude::model(src, |_| (span.clone(), key), body)?;
    }
    Ok(Bodies {
        problem,
        reference,
        striker_transit: transit(&striker_impact),
    })
}
