//! The bulk scheme of a contact case (`[contact] bulk`): central difference with the lumped mass
//! (`cd-lmm`, the default: the contact stepper of `courant_solver::contact`), or a combined run
//! (`courant_solver::contact::combined`): central difference with the reciprocal mass (`cd-rmm`,
//! beta `rmm_beta`, default 1/2; methods.md §5) or Park's scheme (theta = 1/2, `park_variant`
//! `incremental` by default or `free`) with local stepping (`park-lts`) or the global step
//! (`park-global`) (methods.md §6), the contact nodes stepping by central difference
//! (`docs/contact_with_local_stepping.md`). With `courant_unit = "measured"` every bulk, `cd-lmm`
//! included, runs combined against its measured limit.

use super::error::{SceneError, Source};
use super::schema::{RawContact, RawContactCourantUnit};
use super::spelling::closest;
use courant_solver::contact::combined::amplification::MAX_NODES;
use courant_solver::contact::combined::{BulkScheme, CombinedIntegrator};
use courant_solver::contact::{ContactCriticalStep, ContactProblem, ContactScheme};
use courant_solver::{ParkOptions, ParkVariant};

/// The bulk names a scene may give.
pub const BULKS: [&str; 4] = ["cd-lmm", "cd-rmm", "park-lts", "park-global"];

/// A contact case run by the combined stepper: its bulk and the limit its steps are measured
/// against (the measured `rho(G) <= 1` of the combination, or Park's rule `alpha_e <= 1`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CombinedBulk {
    /// What steps the bulk.
    pub scheme: BulkScheme,
    /// The limit the case is checked and reported against; `None` when it is measured as the
    /// case runs (a measured limit whose steps are not counted in it: validation stays fast, and
    /// the run refuses a step above it before stepping).
    pub critical: Option<ContactCriticalStep>,
}

/// The bulks of a study: `(case-name prefix, bulk)`, `None` for today's lumped CD stepper.
pub(super) fn bulks(
    src: &Source,
    study: &RawContact,
) -> Result<Vec<(String, Option<BulkScheme>)>, SceneError> {
    let measured = study.courant_unit == RawContactCourantUnit::Measured;
    let beta = match &study.rmm_beta {
        None => 0.5,
        Some(b) if b.get_ref().is_finite() && *b.get_ref() >= 0.0 => *b.get_ref(),
        Some(b) => {
            return Err(src.error(
                Some(b.span()),
                "contact.rmm_beta",
                format!("{} must be finite and not negative", b.get_ref()),
            ));
        }
    };
    let variant = match study
        .park_variant
        .as_ref()
        .map(|v| (v.get_ref().as_str(), v.span()))
    {
        None | Some(("incremental", _)) => ParkVariant::Incremental,
        Some(("free", _)) => ParkVariant::Free,
        Some((other, span)) => {
            return Err(src.error(
                Some(span),
                "contact.park_variant",
                unknown(other, &["incremental", "free"]),
            ));
        }
    };
    let park = |local_stepping| {
        BulkScheme::Park(ParkOptions {
            theta: 0.5,
            variant,
            local_stepping,
        })
    };
    let Some(raw) = &study.bulk else {
        let lumped = measured.then_some(BulkScheme::CentralDifference);
        return Ok(vec![(String::new(), lumped)]);
    };
    let names = raw.get_ref().values();
    if names.is_empty() {
        return Err(src.error(
            Some(raw.span()),
            "contact.bulk",
            "the list is empty; give at least one bulk",
        ));
    }
    let mut out: Vec<(String, Option<BulkScheme>)> = Vec::new();
    for name in names {
        let bulk = match name.as_str() {
            "cd-lmm" if measured => Some(BulkScheme::CentralDifference),
            "cd-lmm" => None,
            "cd-rmm" => Some(BulkScheme::Reciprocal { beta }),
            "park-lts" => Some(park(true)),
            "park-global" => Some(park(false)),
            other => {
                return Err(src.error(Some(raw.span()), "contact.bulk", unknown(other, &BULKS)));
            }
        };
        let prefix = if name == "cd-lmm" {
            String::new()
        } else {
            format!("{name}-")
        };
        if out.iter().any(|(p, _)| *p == prefix) {
            return Err(src.error(
                Some(raw.span()),
                "contact.bulk",
                format!("\"{name}\" appears twice"),
            ));
        }
        out.push((prefix, bulk));
    }
    Ok(out)
}

/// `"x" is not one of a, b (did you mean a?)`.
fn unknown(value: &str, names: &[&str]) -> String {
    let hint = closest(value, names)
        .map(|n| format!(" (did you mean {n}?)"))
        .unwrap_or_default();
    format!("\"{value}\" is not one of {}{hint}", names.join(", "))
}

/// The limit a combined case is checked against: measured (`courant_unit = "measured"`, or a
/// `cd-rmm` bulk, whose contact pencil is not the lumped one) or Park's rule `alpha_e <= 1`.
/// The measurement is dense: at most [`MAX_NODES`] nodes. The contact-free limit does not
/// depend on the contact scheme: `free` keeps it per bulk, measured once for all the study's
/// contact schemes.
pub(super) fn critical(
    problem: &ContactProblem,
    bulk: BulkScheme,
    scheme: ContactScheme,
    unit: RawContactCourantUnit,
    free: &mut Vec<(BulkScheme, f64)>,
) -> Result<CombinedBulk, String> {
    let critical = match bulk {
        BulkScheme::Park(_) if unit != RawContactCourantUnit::Measured => {
            CombinedIntegrator::park_rule_critical(problem, scheme).map_err(|e| e.to_string())?
        }
        _ if unit == RawContactCourantUnit::StiffestElement => {
            if problem.node_count() > MAX_NODES {
                return Err(too_large(bulk, problem));
            }
            return Ok(CombinedBulk {
                scheme: bulk,
                critical: None,
            });
        }
        _ => {
            if problem.node_count() > MAX_NODES {
                return Err(too_large(bulk, problem));
            }
            let contact_free = match free.iter().find(|(b, _)| *b == bulk) {
                Some(&(_, limit)) => limit,
                None => {
                    let limit = CombinedIntegrator::measured_contact_free(problem, bulk, scheme)
                        .map_err(|e| e.to_string())?;
                    free.push((bulk, limit));
                    limit
                }
            };
            CombinedIntegrator::measured_critical_given_free(problem, bulk, scheme, contact_free)
                .map_err(|e| e.to_string())?
        }
    };
    Ok(CombinedBulk {
        scheme: bulk,
        critical: Some(critical),
    })
}

fn too_large(bulk: BulkScheme, problem: &ContactProblem) -> String {
    format!(
        "the {} bulk's step limit is measured from the dense amplification matrix, limited to \
         {MAX_NODES} nodes; this problem has {} (use a coarser mesh)",
        bulk.label(),
        problem.node_count()
    )
}

/// Refuse a step above the combination's limit (with the time plan's relative allowance) unless
/// unstable runs are allowed; Park's `alpha_e > 1` is refused with it.
pub(super) fn check(bulk: &CombinedBulk, dt: f64, allow_unstable: bool) -> Result<(), String> {
    // A limit measured as the case runs is checked there.
    let Some(critical) = bulk.critical else {
        return Ok(());
    };
    let limit = critical.applicable;
    if allow_unstable || dt <= limit * (1.0 + courant_solver::analysis::ROUNDING_SLACK) {
        return Ok(());
    }
    Err(format!(
        "dt = {dt:.6e} exceeds the {} limit {limit:.6e} ({}) by {:.3e} relative; lower the \
         Courant number or set allow_unstable = true",
        bulk.scheme.label(),
        critical.binding,
        dt / limit - 1.0
    ))
}

#[cfg(test)]
mod tests {
    use crate::scene::cases::Scene;
    use courant_solver::contact::StepLimit;
    use courant_solver::contact::combined::BulkScheme;

    fn scene(extra: &str, elements: usize) -> String {
        format!(
            "[scene]\ndescription = \"d\"\nsource = \"s\"\n\n[contact]\nproblem = \"two-bars\"\n\
             striker = {{ length = 1.0, elements = {elements} }}\n\
             target = {{ length = 1.0, elements = {elements}, modulus = 4.0 }}\n\
             velocity = 1.0\nschemes = [\"cd-bipenalty\", \"lagrange-multiplier\"]\n\
             beta_s = 100.0\ncourant = 0.5\nend_time = 1.0\n{extra}\n"
        )
    }

    /// Source of truth: the scene rules (README, "Scene files": errors name key and line, with a
    /// did-you-mean for a misspelt value). Proves: a misspelt bulk or Park variant is refused at
    /// its own key and line with the nearest name; a measured limit on a mesh above the dense
    /// analysis's 400 nodes is refused at `contact.bulk`; Park above `alpha_e = 1` is refused
    /// at `contact.courant` unless unstable runs are allowed.
    #[test]
    fn bulk_keys_are_checked_where_they_are_written() {
        let e = Scene::parse("t", "t.toml", &scene("bulk = \"park-lst\"", 4)).unwrap_err();
        assert_eq!((e.key.as_str(), e.line), ("contact.bulk", 14), "{e}");
        assert!(e.message.contains("did you mean park-lts?"), "{e}");
        let text = scene("bulk = \"park-lts\"\npark_variant = \"fre\"", 4);
        let e = Scene::parse("t", "t.toml", &text).unwrap_err();
        assert_eq!(
            (e.key.as_str(), e.line),
            ("contact.park_variant", 15),
            "{e}"
        );
        assert!(e.message.contains("did you mean free?"), "{e}");
        let e = Scene::parse("t", "t.toml", &scene("bulk = \"cd-rmm\"", 250)).unwrap_err();
        assert_eq!(e.key, "contact.bulk", "{e}");
        assert!(e.message.contains("400 nodes"), "{e}");
        let above = scene("bulk = \"park-lts\"", 4).replace("courant = 0.5", "courant = 1.2");
        let e = Scene::parse("t", "t.toml", &above).unwrap_err();
        assert_eq!(e.key, "contact.courant", "{e}");
        let allowed = format!("{above}allow_unstable = true\n");
        if let Err(e) = Scene::parse("t", "t.toml", &allowed) {
            panic!("{e}");
        }
    }

    /// Source of truth: the meaning of `bulk` (module docs). Proves: without `bulk` the cases
    /// keep their names and the lumped contact stepper (the report of existing scenes does not
    /// change); each named bulk prefixes its cases and carries its limit: Park's rule for
    /// `park-*`; `cd-rmm`'s measured limit is left to the run when the steps are counted in the
    /// stiffest element's transit (validation stays fast); with `courant_unit = "measured"` every
    /// bulk carries its measured limit (with the Lagrange multiplier CD-LMM's limit is its contact-free one, the stiffest
    /// element's transit time to the bisection's tolerance).
    #[test]
    fn bulks_name_their_cases_and_carry_their_limits() {
        let plain = Scene::parse("t", "t.toml", &scene("", 4)).unwrap();
        let names: Vec<_> = plain.contact.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["cd-bipenalty-bs100", "lagrange-multiplier"]);
        assert!(plain.contact.iter().all(|c| c.bulk.is_none()));
        let text = scene("bulk = [\"cd-lmm\", \"park-global\", \"cd-rmm\"]", 4);
        let mixed = Scene::parse("t", "t.toml", &text).unwrap();
        let limits: Vec<_> = mixed
            .contact
            .iter()
            .map(|c| {
                (
                    c.name.as_str(),
                    c.bulk.and_then(|b| b.critical).map(|c| c.binding),
                )
            })
            .collect();
        assert_eq!(
            limits,
            [
                ("cd-bipenalty-bs100", None),
                ("park-global-cd-bipenalty-bs100", Some(StepLimit::ParkRule)),
                ("cd-rmm-cd-bipenalty-bs100", None),
                ("lagrange-multiplier", None),
                ("park-global-lagrange-multiplier", Some(StepLimit::ParkRule)),
                ("cd-rmm-lagrange-multiplier", None),
            ]
        );
        let text = scene("courant_unit = \"measured\"", 4);
        let measured = Scene::parse("t", "t.toml", &text).unwrap();
        for case in &measured.contact {
            let bulk = case.bulk.expect("measured cases run combined");
            assert_eq!(bulk.scheme, BulkScheme::CentralDifference);
            let critical = bulk
                .critical
                .expect("a measured unit is measured at validation");
            assert_eq!(critical.binding, StepLimit::Measured);
            assert!(case.integrator.dt == 0.5 * critical.applicable);
        }
        let lm = measured.contact[1].bulk.unwrap().critical.unwrap();
        assert!(
            lm.applicable == lm.contact_free && lm.applicable >= 0.999 * lm.stiffest_transit,
            "{lm:?}"
        );
    }
}
