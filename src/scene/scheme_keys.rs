//! The keys of a scene's `[integrator]` that are not the table's own: the parameters of its
//! schemes (`theta`, `park_variant`, `p`, ...), taken out of the document before it is read into
//! [`RawScene`](super::schema::RawScene) and checked against the registry's declarations in
//! [`super::stepping`] (a key no listed scheme declares is an error naming its line).

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
    /// Its value.
    pub value: ParameterValue,
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
        let value = match values.get(name) {
            Some(toml::Value::Float(x)) => ParameterValue::Number(*x),
            Some(toml::Value::Integer(i)) => ParameterValue::Number(*i as f64),
            Some(toml::Value::String(s)) => ParameterValue::Text(s.clone()),
            _ => {
                return Err(src.error(
                    Some(spanned.span()),
                    &format!("integrator.{name}"),
                    "a scheme parameter is a number or a word in quotes",
                ));
            }
        };
        keys.push(SchemeKey {
            key: name.to_string(),
            span: key.span(),
            value,
        });
    }
    for key in &keys {
        integrator.remove(key.key.as_str());
    }
    keys.sort_by_key(|k| k.span.start);
    Ok(keys)
}
