//! What a registry entry declares: a scheme's name, its parameters (keys of a scene's
//! `[integrator]`, with defaults and rules), the masses it runs with, its source, and how it is
//! built from the parameter values. The registry itself is [`crate::schemes::REGISTRY`].

use super::scheme::Scheme;
use std::sync::Arc;
use thiserror::Error;

/// A parameter's value as a scene gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum ParameterValue {
    /// A number.
    Number(f64),
    /// A word.
    Text(String),
}

impl std::fmt::Display for ParameterValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParameterValue::Number(x) => write!(f, "{x}"),
            ParameterValue::Text(s) => write!(f, "\"{s}\""),
        }
    }
}

/// A parameter's default.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ParameterDefault {
    /// A number.
    Number(f64),
    /// A word.
    Text(&'static str),
}

/// One parameter a scheme declares.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameter {
    /// The key in `[integrator]`, e.g. `p`.
    pub key: &'static str,
    /// Its default.
    pub default: ParameterDefault,
    /// The rule its value must follow, phrased to follow the value (`must lie in [1/2, 3/4]`).
    pub rule: &'static str,
    /// What it sets.
    pub meaning: &'static str,
}

/// A parameter value that breaks its rule.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{value} {rule}")]
pub struct ParameterError {
    /// The key.
    pub key: &'static str,
    /// The value given.
    pub value: ParameterValue,
    /// The rule it breaks.
    pub rule: String,
}

/// A registry entry: everything a scene, `courant list --schemes` and a run need of a scheme.
#[derive(Debug, Clone, Copy)]
pub struct SchemeEntry {
    /// The name scenes use, e.g. `noh-bathe`.
    pub name: &'static str,
    /// Other names it answers to (`central-difference` for `cd`).
    pub aliases: &'static [&'static str],
    /// One line: what it is.
    pub summary: &'static str,
    /// Where its equations and its analysis come from.
    pub source: &'static str,
    /// The masses it runs with (as `courant list --schemes` says it).
    pub masses: &'static str,
    /// Its parameters.
    pub parameters: &'static [Parameter],
    /// Build the scheme from its parameter values.
    pub build: fn(&ParameterValues<'_>) -> Result<Arc<dyn Scheme>, ParameterError>,
}

impl SchemeEntry {
    /// True for its name or one of its aliases.
    pub fn answers_to(&self, name: &str) -> bool {
        self.name == name || self.aliases.contains(&name)
    }

    /// The declared parameter `key`.
    pub fn parameter(&self, key: &str) -> Option<&'static Parameter> {
        self.parameters.iter().find(|p| p.key == key)
    }

    /// Build with the values `given` (keys this scheme does not declare are left to the schemes
    /// that do) and the defaults for the rest.
    ///
    /// # Errors
    /// [`ParameterError`] naming the key whose value breaks its rule.
    pub fn build_with(
        &self,
        given: &[(String, ParameterValue)],
    ) -> Result<Arc<dyn Scheme>, ParameterError> {
        (self.build)(&ParameterValues { entry: self, given })
    }
}

/// The parameter values a scheme is built from: the given ones, else the declared defaults.
#[derive(Debug, Clone, Copy)]
pub struct ParameterValues<'a> {
    entry: &'a SchemeEntry,
    given: &'a [(String, ParameterValue)],
}

impl ParameterValues<'_> {
    fn declared(&self, key: &'static str) -> &'static Parameter {
        self.entry.parameter(key).unwrap_or_else(|| {
            panic!(
                "scheme {} reads parameter {key} it does not declare",
                self.entry.name
            )
        })
    }

    fn given(&self, key: &str) -> Option<&ParameterValue> {
        self.given.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }

    /// The number `key` (a declared numeric parameter).
    ///
    /// # Errors
    /// [`ParameterError`] when the scene gave a word.
    pub fn number(&self, key: &'static str) -> Result<f64, ParameterError> {
        let declared = self.declared(key);
        match (self.given(key), declared.default) {
            (Some(ParameterValue::Number(x)), _) => Ok(*x),
            (Some(other), _) => Err(ParameterError {
                key,
                value: other.clone(),
                rule: "must be a number".into(),
            }),
            (None, ParameterDefault::Number(x)) => Ok(x),
            (None, ParameterDefault::Text(_)) => {
                panic!("parameter {key} of {} is not a number", self.entry.name)
            }
        }
    }

    /// The word `key` (a declared word parameter).
    ///
    /// # Errors
    /// [`ParameterError`] when the scene gave a number.
    pub fn text(&self, key: &'static str) -> Result<&str, ParameterError> {
        let declared = self.declared(key);
        match (self.given(key), declared.default) {
            (Some(ParameterValue::Text(s)), _) => Ok(s),
            (Some(other), _) => Err(ParameterError {
                key,
                value: other.clone(),
                rule: "must be a word in quotes".into(),
            }),
            (None, ParameterDefault::Text(s)) => Ok(s),
            (None, ParameterDefault::Number(_)) => {
                panic!("parameter {key} of {} is not a word", self.entry.name)
            }
        }
    }

    /// A number `key` that must lie in `[min, max]`.
    ///
    /// # Errors
    /// [`ParameterError`] with the declared rule when it does not.
    pub fn number_in(&self, key: &'static str, min: f64, max: f64) -> Result<f64, ParameterError> {
        let x = self.number(key)?;
        if (min..=max).contains(&x) {
            Ok(x)
        } else {
            Err(ParameterError {
                key,
                value: ParameterValue::Number(x),
                rule: self.declared(key).rule.into(),
            })
        }
    }

    /// A word `key` that must be one of `choices`.
    ///
    /// # Errors
    /// [`ParameterError`] naming the choices when it is not.
    pub fn choice<T: Copy>(
        &self,
        key: &'static str,
        choices: &[(&str, T)],
    ) -> Result<T, ParameterError> {
        let word = self.text(key)?;
        choices
            .iter()
            .find(|(name, _)| *name == word)
            .map(|(_, value)| *value)
            .ok_or_else(|| ParameterError {
                key,
                value: ParameterValue::Text(word.to_string()),
                rule: self.declared(key).rule.into(),
            })
    }
}
