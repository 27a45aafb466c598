//! The keys of a scene's `[integrator]` that are not the table's own: the parameters of its
//! schemes (`theta`, `park_variant`, `p`, ...), taken out of the document before it is read into
//! [`RawScene`](super::schema::RawScene) and checked against the registry's declarations in
//! [`super::stepping`] (a key no listed scheme declares is an error naming its line). A key given
//! as a list (`theta = [0, 0.25, 0.5]`) is a sweep: one case per value.

use super::error::{SceneError, Source};
use super::schema::INTEGRATOR_KEYS;
use courant_solver::integrator::ParameterValue;
use std::ops::Range;
use toml::de::{DeTable, DeValue};

/// One scheme parameter as the scene gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct SchemeKey {
    /// The key, e.g. `p`.
    pub key: String,
    /// Where it is (the key's span).
    pub span: Range<usize>,
    /// Its values: one, or the values of a list (a sweep, one case each).
    pub values: Vec<ParameterValue>,
    /// Given as a list: the value is part of each case's name (`theta0.25`).
    pub listed: bool,
}

/// Remove from `document`'s `[integrator]` every key that is not one of [`INTEGRATOR_KEYS`] and
/// return them with their values (read from `table`, the same text parsed without spans).
///
/// # Errors
/// A [`SceneError`] at the value when it is neither a number nor a string.
pub fn split_off(
    src: &Source,
    table: &toml::Table,
    document: &mut DeTable<'_>,
) -> Result<Vec<SchemeKey>, SceneError> {
    let (Some(values), Some(integrator)) = (
        table.get("integrator").and_then(|v| v.as_table()),
        document
            .get_mut("integrator")
            .and_then(|v| match v.get_mut() {
                DeValue::Table(t) => Some(t),
                _ => None,
            }),
    ) else {
        return Ok(Vec::new());
    };
    let mut keys = Vec::new();
    for (key, spanned) in integrator.iter() {
        let name: &str = key.get_ref();
        if INTEGRATOR_KEYS.contains(&name) {
            continue;
        }
        let bad = |rule: &str| src.error(Some(spanned.span()), &format!("integrator.{name}"), rule);
        let (values, listed) = match values.get(name) {
            Some(toml::Value::Array(list)) => {
                let values: Option<Vec<ParameterValue>> = list.iter().map(scalar).collect();
                match values {
                    None => {
                        return Err(bad(
                            "a list of scheme parameter values holds numbers or words in quotes",
                        ));
                    }
                    Some(v) if v.is_empty() => {
                        return Err(bad("the list is empty; give at least one value"));
                    }
                    Some(v) => (v, true),
                }
            }
            value => match value.and_then(scalar) {
                Some(v) => (vec![v], false),
                None => {
                    return Err(bad(
                        "a scheme parameter is a number, a word in quotes, or a list of them (one case each)",
                    ));
                }
            },
        };
        keys.push(SchemeKey {
            key: name.to_string(),
            span: key.span(),
            values,
            listed,
        });
    }
    for key in &keys {
        integrator.remove(key.key.as_str());
    }
    keys.sort_by_key(|k| k.span.start);
    Ok(keys)
}

/// A number or a word, else `None`.
fn scalar(value: &toml::Value) -> Option<ParameterValue> {
    match value {
        toml::Value::Float(x) => Some(ParameterValue::Number(*x)),
        toml::Value::Integer(i) => Some(ParameterValue::Number(*i as f64)),
        toml::Value::String(s) => Some(ParameterValue::Text(s.clone())),
        _ => None,
    }
}
