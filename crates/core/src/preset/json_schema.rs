//! The JSON Schema of the preset format `gaitlab-preset/1`, generated with
//! schemars from the serde types of [`Preset`] (feature `schema`) and shipped as
//! `docs/schema/preset.schema.json`, so that editors can check and complete
//! preset files.
//!
//! The schema follows the serde attributes: defaults (fields that may be left
//! out), renames, `deny_unknown_fields` (`additionalProperties: false`) and the
//! string enums. It checks the shape of a preset (keys, types, required
//! fields); the rules of [`Preset::validate`] (ranges, names that must exist,
//! cycles) stay with the parser, which names the JSON path of each error.

use super::Preset;

/// The schema's `$id`.
pub const SCHEMA_ID: &str = "https://example.invalid/gaitlab/docs/schema/preset.schema.json";

/// The schema's `title`.
pub const SCHEMA_TITLE: &str = "gaitlab preset (gaitlab-preset/1)";

/// The JSON Schema (draft-07, which most editors support) of a preset file.
#[must_use]
pub fn preset_schema() -> serde_json::Value {
    let generator = schemars::generate::SchemaSettings::draft07().into_generator();
    let mut schema = generator.into_root_schema_for::<Preset>();
    schema.insert("$id".to_owned(), SCHEMA_ID.into());
    schema.insert("title".to_owned(), SCHEMA_TITLE.into());
    let mut value = schema.to_value();
    plain_descriptions(&mut value);
    value
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
