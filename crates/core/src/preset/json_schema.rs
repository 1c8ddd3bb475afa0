//! The JSON Schema of the preset format `gaitlab-preset/2` (which reads `/1`
//! files too), generated with schemars from the serde types of [`Preset`]
//! (feature `schema`) and shipped as `docs/schema/preset.schema.json`, so that
//! editors can check and complete preset files. Each value with a row in the
//! engines' parameter tables takes its range (`minimum`, `maximum`, their
//! exclusive forms) and, in its description, its reference and origin from
//! the row: the tables are where ranges live.
//!
//! The schema follows the serde attributes: defaults (fields that may be left
//! out), renames, `deny_unknown_fields` (`additionalProperties: false`) and the
//! string enums. It checks the shape of a preset (keys, types, required
//! fields); the rules of [`Preset::validate`] (ranges, names that must exist,
//! cycles) stay with the parser, which names the JSON path of each error.

use serde_json::Value;

use super::{PHYSICS_PARAMS, PODA_PARAMS, Preset, THESIS_PARAMS};
use crate::ik::IK_PARAMS;
use crate::params::{Domain, Origin, ParamSpec, SCENARIO_PARAMS};

/// The schema's `$id`.
pub const SCHEMA_ID: &str = "https://example.invalid/gaitlab/docs/schema/preset.schema.json";

/// The schema's `title`.
pub const SCHEMA_TITLE: &str = "gaitlab preset (gaitlab-preset/2)";

/// The JSON Schema (draft-07, which most editors support) of a preset file.
#[must_use]
pub fn preset_schema() -> serde_json::Value {
    let generator = schemars::generate::SchemaSettings::draft07().into_generator();
    let mut schema = generator.into_root_schema_for::<Preset>();
    schema.insert("$id".to_owned(), SCHEMA_ID.into());
    schema.insert("title".to_owned(), SCHEMA_TITLE.into());
    let mut value = schema.to_value();
    plain_descriptions(&mut value);
    ranges_from_tables(&mut value);
    value
}

/// Every table row of a preset key: its range and, after the description,
/// its reference and origin.
fn ranges_from_tables(schema: &mut Value) {
    let tables: [&[ParamSpec]; 5] = [
        SCENARIO_PARAMS,
        IK_PARAMS,
        THESIS_PARAMS,
        PODA_PARAMS,
        PHYSICS_PARAMS,
    ];
    for row in tables.into_iter().flatten() {
        let path = row.key;
        if !path.starts_with("scenario.") {
            continue;
        }
        let Some(node) = property(schema, path) else {
            continue;
        };
        let Some(map) = node.as_object_mut() else {
            continue;
        };
        match row.domain {
            Domain::Real {
                min,
                max,
                min_open,
                max_open,
            } => {
                let low = if min_open {
                    "exclusiveMinimum"
                } else {
                    "minimum"
                };
                let high = if max_open {
                    "exclusiveMaximum"
                } else {
                    "maximum"
                };
                map.insert(low.to_owned(), min.into());
                map.insert(high.to_owned(), max.into());
            }
            Domain::Integer { min, max } => {
                map.insert("minimum".to_owned(), min.into());
                map.insert("maximum".to_owned(), max.into());
            }
            Domain::Bool | Domain::Choice { .. } | Domain::Structured { .. } => {}
        }
        let origin = match row.origin {
            Origin::Paper => "the paper's",
            Origin::Open => "a value the paper leaves open",
            Origin::Lab => "the lab's addition",
        };
        let note = format!("{} ({origin}: {}).", row.reference, row.why);
        let text = match map.get("description").and_then(Value::as_str) {
            Some(text) => format!("{text} {note}"),
            None => format!("{}. {note}", row.label),
        };
        map.insert("description".to_owned(), text.into());
    }
}

/// The schema of the property at dotted `path` (`scenario.ik.lambda`),
/// through `allOf`/`anyOf` wrappers and `$ref`s into `definitions`.
fn property<'a>(schema: &'a mut Value, path: &str) -> Option<&'a mut Value> {
    let mut pointer = String::new();
    for part in path.split('.') {
        let target = resolve(schema, &pointer)?;
        pointer = format!("{target}/properties/{part}");
        schema.pointer(&pointer)?;
    }
    schema.pointer_mut(&pointer)
}

/// Where the object schema at `pointer` really is: itself, or the
/// definition its `$ref` (directly or in an `allOf`/`anyOf` branch) names.
fn resolve(schema: &Value, pointer: &str) -> Option<String> {
    let node = schema.pointer(pointer)?;
    if node.get("properties").is_some() {
        return Some(pointer.to_owned());
    }
    let reference = node.get("$ref").and_then(Value::as_str).or_else(|| {
        ["allOf", "anyOf"].iter().find_map(|key| {
            node.get(key)?
                .as_array()?
                .iter()
                .find_map(|branch| branch.get("$ref").and_then(Value::as_str))
        })
    })?;
    reference.strip_prefix('#').map(str::to_owned)
}

/// Rewrites rustdoc links in every `description` (``[`Format::V1`]``,
/// ``[`a`](path)``) as plain code spans, for editors that show the text.
fn plain_descriptions(value: &mut serde_json::Value) {
    match value {
        serde_json::Value::Object(map) => {
            for (key, item) in map.iter_mut() {
                if let (true, serde_json::Value::String(text)) = (key == "description", &mut *item)
                {
                    *text = without_doc_links(text);
                } else {
                    plain_descriptions(item);
                }
            }
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(plain_descriptions),
        _ => {}
    }
}

/// ``[`x`]`` → `` `x` `` and ``[`x`](target)`` → `` `x` ``.
fn without_doc_links(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(start) = rest.find("[`") {
        let Some(end) = rest[start..].find("`]").map(|e| start + e) else {
            break;
        };
        out.push_str(&rest[..start]);
        out.push_str(&rest[start + 1..=end]);
        rest = &rest[end + 2..];
        if rest.starts_with('(')
            && let Some(close) = rest.find(')')
        {
            rest = &rest[close + 1..];
        }
    }
    out.push_str(rest);
    out
}

/// [`preset_schema`] as the text of `docs/schema/preset.schema.json`: pretty
/// printed with two-space indents and a final newline.
#[must_use]
pub fn preset_schema_text() -> String {
    format!("{:#}\n", preset_schema())
}
