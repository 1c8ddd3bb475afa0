//! Serde's errors as the API's `key: reason` texts: the key path where the
//! value went wrong (`gain.value`, `phases[2]`) and a short reason in the
//! words the hand-written checks used before the types (`expected a number`).

use gaitlab_core::preset::json_path;
use serde::de::{Deserialize, Deserializer, MapAccess, Visitor};
use serde_path_to_error::Path;

/// Writes a serde path as `a.b[3].c` under `prefix` (empty for the command
/// itself), in the preset errors' notation (core's [`json_path`]).
fn json_path_under(prefix: &str, path: &Path) -> String {
    let inner = json_path(path);
    if prefix.is_empty() || inner.is_empty() || inner.starts_with('[') {
        format!("{prefix}{inner}")
    } else {
        format!("{prefix}.{inner}")
    }
}

/// What an unknown key is called under `path` (the command's own words).
fn unknown_key(path: &str, expected: &str) -> String {
    match path.rsplit_once('.').map_or(path, |(_, last)| last) {
        "" => "unknown command".to_owned(),
        "views" => "unknown view option".to_owned(),
        "camera" => "unknown camera field".to_owned(),
        _ if path.starts_with("compare.options[") => "unknown option".to_owned(),
        _ => format!("unknown key ({expected})"),
    }
}

/// serde's name of an expected type, in the API's words.
fn expected(what: &str) -> &str {
    match what {
        "f64" | "f32" => "a number",
        "a boolean" => "true or false",
        "a sequence" => "an array",
        "a map" => "an object",
        other => other,
    }
}

/// The `key: reason` text of a typed-deserialization error under `prefix`.
pub(crate) fn describe(
    prefix: &str,
    error: &serde_path_to_error::Error<serde_json::Error>,
) -> String {
    let path = json_path_under(prefix, error.path());
    let message = error.inner().to_string();
    let join = |field: &str| {
        if path.is_empty() {
            field.to_owned()
        } else {
            format!("{path}.{field}")
        }
    };
    if let Some((field, rest)) = message
        .strip_prefix("unknown field `")
        .and_then(|rest| rest.split_once('`'))
    {
        let list = rest
            .split_once("expected ")
            .map_or("", |(_, list)| list)
            .trim_start_matches("one of ")
            .replace('`', "");
        // serde_path_to_error puts an unknown key on the path already.
        let (key, parent) = match path.strip_suffix(field) {
            Some(parent) => (path.clone(), parent.trim_end_matches('.').to_owned()),
            None => (join(field), path.clone()),
        };
        return format!("{key}: {}", unknown_key(&parent, &list));
    }
    if let Some((field, _)) = message
        .strip_prefix("missing field `")
        .and_then(|rest| rest.split_once('`'))
    {
        return format!("{}: missing", join(field));
    }
    let reason = match message
        .strip_prefix("invalid type: ")
        .and_then(|rest| rest.split_once(", expected "))
    {
        Some((_, what)) => format!("expected {}", expected(what)),
        None => message,
    };
    let key = if path.is_empty() { "command" } else { &path };
    format!("{key}: {reason}")
}

/// Reads `T` from JSON `value` with every error as `prefix.path: reason`.
///
/// # Errors
/// The first value that does not fit `T`, named by its key path.
pub fn from_value<T: serde::de::DeserializeOwned>(
    prefix: &str,
    value: serde_json::Value,
) -> Result<T, String> {
    serde_path_to_error::deserialize(value).map_err(|e| describe(prefix, &e))
}

/// `deserialize_with` for object-valued keys: an object only (serde's derived
/// structs would also take an array, by position), wrapped in `Some`.
pub(crate) fn object<'de, D, T>(deserializer: D) -> Result<Option<T>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    struct Object<T>(std::marker::PhantomData<T>);
    impl<'de, T: Deserialize<'de>> Visitor<'de> for Object<T> {
        type Value = T;
        fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            f.write_str("an object")
        }
        fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<T, A::Error> {
            T::deserialize(serde::de::value::MapAccessDeserializer::new(map))
        }
    }
    deserializer
        .deserialize_map(Object(std::marker::PhantomData))
        .map(Some)
}

/// `deserialize_with` for keys whose `null` means something (`narrow`,
/// `compare`): the value as read, `null` included, wrapped in `Some`.
pub(crate) fn present<'de, D, T>(deserializer: D) -> Result<Option<T>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    T::deserialize(deserializer).map(Some)
}
