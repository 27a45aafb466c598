//! Whether a scene's signature rows apply to a result file: what its `results.toml` declares
//! (scheme, parameters, mass), checked against the registry's names, compared with the case.
//!
//! An error bound (`scene::expectation::RowKind::Bound`) applies to every file. A signature
//! (what the case's scheme and mass do: the overshoot band of lumped central difference, a lower
//! bound on the error of a dispersed front, a ratio of two cases) applies only where the file
//! declares the case's own scheme, parameters and mass; otherwise it is "not applicable", with
//! the reason, never a pass or a failure: a more accurate code must not fail a row that
//! describes a less accurate scheme, nor a wrong one pass it by chance.

use crate::results::exchange::error::ExchangeError;
use crate::results::exchange::meta::{CaseMeta, MetaValue};
use crate::scene::contact::ContactCase;
use courant_solver::MassKind;
use courant_solver::integrator::ParameterValue;
use courant_solver::schemes;

/// The contact schemes a `results.toml` may name for a contact case, and their parameters.
const CONTACT_SCHEMES: [&str; 4] = [
    "cd-penalty",
    "cd-bipenalty",
    "predictor-corrector",
    "lagrange-multiplier",
];

/// The penalty parameters a contact scheme is declared with.
const CONTACT_PARAMETERS: [&str; 2] = ["beta_s", "beta_m"];

/// What a file declares of the run that made it, in the words the scene's cases use.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Declared {
    /// The scheme with its parameters as courant labels it (`noh-bathe p=0.54`, or a contact
    /// scheme with `beta_s`, `beta_m`); `None` when `results.toml` names no scheme.
    pub scheme: Option<String>,
    /// The mass kind; `None` when not declared.
    pub mass: Option<MassKind>,
}

/// Whether the signature rows of a case apply to a file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Applies {
    /// The file declares the case's scheme, parameters and mass.
    Yes,
    /// Why not: `declared cmm; the case is lmm`, `scheme not declared`, ...
    No(String),
}

impl Declared {
    /// The time-stepping scheme `meta` declares, checked against the registry: its name, the
    /// parameters its entry declares and their rules.
    ///
    /// # Errors
    /// An unknown scheme name (the known ones listed), a parameter the scheme does not take, a
    /// value that breaks its rule; located at the key of `meta_file`.
    pub fn stepping(
        meta: Option<&CaseMeta>,
        mass: Option<MassKind>,
        case: &str,
        meta_file: &str,
    ) -> Result<Declared, ExchangeError> {
        let Some(meta) = meta else {
            return Ok(Declared { scheme: None, mass });
        };
        let Some(name) = &meta.scheme else {
            if let Some((key, at)) = meta.parameters.first() {
                return Err(ExchangeError::at(
                    meta_file,
                    at.line,
                    at.column,
                    &format!("cases.\"{case}\".parameters.{key}"),
                    "parameters without a `scheme`: name the scheme they belong to",
                ));
            }
            return Ok(Declared { scheme: None, mass });
        };
        let (line, column) = meta.scheme_at;
        let key = format!("cases.\"{case}\".scheme");
        let Some(entry) = schemes::find(name) else {
            return Err(ExchangeError::at(
                meta_file,
                line,
                column,
                &key,
                format!(
                    "\"{name}\" is not a scheme courant knows ({}); leave `scheme` out when yours is none of these: the scene's error bounds still apply, its signature rows (what a named scheme does) then do not",
                    schemes::names()
                ),
            ));
        };
        let mut given = Vec::new();
        for (k, at) in &meta.parameters {
            let param_key = format!("cases.\"{case}\".parameters.{k}");
            if entry.parameter(k).is_none() {
                let known: Vec<&str> = entry.parameters.iter().map(|p| p.key).collect();
                return Err(ExchangeError::at(
                    meta_file,
                    at.line,
                    at.column,
                    &param_key,
                    format!(
                        "{} takes no parameter `{k}` ({})",
                        entry.name,
                        if known.is_empty() {
                            "it takes none".to_string()
                        } else {
                            format!("its parameters: {}", known.join(", "))
                        }
                    ),
                ));
            }
            let value = match &at.value {
                MetaValue::Number(x) => ParameterValue::Number(*x),
                MetaValue::Text(word) => ParameterValue::Text(word.clone()),
            };
            given.push((k.clone(), value));
        }
        let scheme = entry.build_with(&given).map_err(|e| {
            let at = meta.parameters.iter().find(|(k, _)| k == e.key);
            ExchangeError::at(
                meta_file,
                at.map_or(line, |a| a.1.line),
                at.map_or(column, |a| a.1.column),
                &format!("cases.\"{case}\".parameters.{}", e.key),
                e.to_string(),
            )
        })?;
        Ok(Declared {
            scheme: Some(scheme.label()),
            mass,
        })
    }

    /// The contact scheme `meta` declares, with its penalties.
    ///
    /// # Errors
    /// A scheme that is not a contact scheme, a parameter other than `beta_s`, `beta_m`, a
    /// penalty that is not a positive number; located at the key of `meta_file`.
    pub fn contact(
        meta: Option<&CaseMeta>,
        case: &str,
        meta_file: &str,
    ) -> Result<Declared, ExchangeError> {
        let Some((meta, name)) = meta.and_then(|m| m.scheme.as_ref().map(|s| (m, s))) else {
            return Ok(Declared::default());
        };
        let (line, column) = meta.scheme_at;
        if !CONTACT_SCHEMES.contains(&name.as_str()) {
            return Err(ExchangeError::at(
                meta_file,
                line,
                column,
                &format!("cases.\"{case}\".scheme"),
                format!(
                    "\"{name}\" is not a contact scheme courant knows ({}); leave `scheme` out when yours is none of these",
                    CONTACT_SCHEMES.join(", ")
                ),
            ));
        }
        let mut label = name.clone();
        for (k, at) in &meta.parameters {
            let key = format!("cases.\"{case}\".parameters.{k}");
            let fail = |rule: String| ExchangeError::at(meta_file, at.line, at.column, &key, rule);
            if !CONTACT_PARAMETERS.contains(&k.as_str()) {
                return Err(fail(format!(
                    "a contact scheme's parameters are {}, not `{k}`",
                    CONTACT_PARAMETERS.join(", ")
                )));
            }
            match at.value {
                MetaValue::Number(x) if x.is_finite() && x >= 0.0 => {
                    label += &format!(" {k}={x}");
                }
                _ => return Err(fail("must be a number at least 0".into())),
            }
        }
        Ok(Declared {
            scheme: Some(label),
            mass: None,
        })
    }

    /// Whether the signature rows of a time-stepping case run with `scheme` (its label) and
    /// `mass` apply.
    pub fn applies_to_stepping(&self, scheme: &str, mass: MassKind) -> Applies {
        match (&self.scheme, self.mass) {
            (None, _) => Applies::No(format!("scheme not declared; the case is {scheme}")),
            (Some(s), _) if s != scheme => {
                Applies::No(format!("declared {s}; the case is {scheme}"))
            }
            (_, None) => Applies::No(format!("mass not declared; the case is {}", mass.label())),
            (_, Some(m)) if m != mass => Applies::No(format!(
                "declared {}; the case is {}",
                m.label(),
                mass.label()
            )),
            _ => Applies::Yes,
        }
    }

    /// Whether the signature rows of a contact case apply: the same contact scheme and, where
    /// it has penalties, the same `beta_s` and `beta_m`.
    pub fn applies_to_contact(&self, case: &ContactCase) -> Applies {
        let mut label = case.integrator.scheme.label().to_string();
        if let Some((beta_s, beta_m)) = case.penalty {
            label += &format!(" beta_s={beta_s} beta_m={beta_m}");
        }
        match &self.scheme {
            None => Applies::No(format!("scheme not declared; the case is {label}")),
            Some(s) if !same_contact(s, &label) => {
                Applies::No(format!("declared {s}; the case is {label}"))
            }
            Some(_) => Applies::Yes,
        }
    }
}

/// Two contact labels name the same scheme and penalties: the same name, `beta_s` equal,
/// `beta_m` equal (0 when not given), to 1e-12 relative.
fn same_contact(a: &str, b: &str) -> bool {
    let parse = |s: &str| {
        let mut words = s.split_whitespace();
        let name = words.next().unwrap_or_default().to_string();
        let mut penalties = [None, Some(0.0)];
        for w in words {
            if let Some((k, v)) = w.split_once('=') {
                let slot = CONTACT_PARAMETERS.iter().position(|p| *p == k);
                if let (Some(i), Ok(x)) = (slot, v.parse::<f64>()) {
                    penalties[i] = Some(x);
                }
            }
        }
        (name, penalties)
    };
    let ((na, pa), (nb, pb)) = (parse(a), parse(b));
    let close = |x: Option<f64>, y: Option<f64>| match (x, y) {
        (Some(x), Some(y)) => (x - y).abs() <= 1e-12 * x.abs().max(y.abs()),
        (None, None) => true,
        _ => false,
    };
    na == nb && close(pa[0], pb[0]) && close(pa[1], pb[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_signature_applies_only_to_the_declared_scheme_and_mass() {
        let d = Declared {
            scheme: Some("cd".into()),
            mass: Some(MassKind::Consistent),
        };
        assert_eq!(
            d.applies_to_stepping("cd", MassKind::Lumped),
            Applies::No("declared cmm; the case is lmm".into())
        );
        assert_eq!(
            d.applies_to_stepping("cd", MassKind::Consistent),
            Applies::Yes
        );
        assert_eq!(
            Declared::default().applies_to_stepping("cd", MassKind::Lumped),
            Applies::No("scheme not declared; the case is cd".into())
        );
        assert!(same_contact(
            "cd-bipenalty beta_s=25 beta_m=25",
            "cd-bipenalty beta_m=25 beta_s=25"
        ));
        assert!(same_contact(
            "cd-penalty beta_s=25",
            "cd-penalty beta_s=25 beta_m=0"
        ));
        assert!(!same_contact(
            "cd-penalty beta_s=25",
            "cd-penalty beta_s=2500"
        ));
        assert!(!same_contact("cd-penalty", "cd-penalty beta_s=25"));
    }
}
