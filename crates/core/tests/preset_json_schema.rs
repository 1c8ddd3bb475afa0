//! The shipped JSON Schema of the preset format (`docs/schema/preset.schema.json`)
//! is the one the serde types generate, and a `"$schema"` key in a preset (how an
//! editor is pointed at it) is accepted and ignored.
//!
//! Regenerate the file after changing a preset type:
//! `GAITLAB_UPDATE_SCHEMA=1 cargo test -p gaitlab-core --test preset_json_schema`.

use std::path::PathBuf;

use gaitlab_core::preset::{self, Preset, SCHEMA_ID, preset_schema, preset_schema_text};
use serde_json::{Value, json};

fn shipped_path() -> PathBuf {
    [
        env!("CARGO_MANIFEST_DIR"),
        "..",
        "..",
        "docs",
        "schema",
        "preset.schema.json",
    ]
    .iter()
    .collect()
}

#[test]
fn shipped_schema_is_current() {
    let path = shipped_path();
    let generated = preset_schema_text();
    if std::env::var_os("GAITLAB_UPDATE_SCHEMA").is_some() {
        std::fs::write(&path, &generated)
            .unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
    }
    let shipped = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        shipped == generated,
        "{} is not the schema the preset types generate; regenerate it with\n  \
         GAITLAB_UPDATE_SCHEMA=1 cargo test -p gaitlab-core --test preset_json_schema\n\
         and commit the file",
        path.display()
    );
}

#[test]
fn schema_names_itself_and_reflects_the_serde_attributes() {
    let schema = preset_schema();
    assert_eq!(schema["$id"], SCHEMA_ID);
    assert_eq!(schema["$schema"], "http://json-schema.org/draft-07/schema#");
    assert!(
        schema["title"]
            .as_str()
            .is_some_and(|t| t.contains("gaitlab"))
    );
    // deny_unknown_fields, and required fields are exactly those without a default.
    assert_eq!(schema["additionalProperties"], false);
    let required: Vec<&str> = schema["required"]
        .as_array()
        .expect("required")
        .iter()
        .filter_map(Value::as_str)
        .collect();
    assert_eq!(required, ["format", "name", "skeleton", "scenario"]);
    let properties = schema["properties"].as_object().expect("properties");
    assert!(
        properties.contains_key("$schema"),
        "the $schema key is allowed"
    );
    let definitions = schema["definitions"].as_object().expect("definitions");
    // Renames: a joint's `type`, the format tag, kebab-case modes.
    assert!(definitions["JointSpec"]["properties"].get("type").is_some());
    assert!(
        definitions["Format"]
            .to_string()
            .contains("gaitlab-preset/1")
    );
    assert!(
        definitions["ThesisMode"]
            .to_string()
            .contains("wounded-walk")
    );
    // `scenario.ik` is the mirror without `method` (the parser refuses one there).
    let ik = &definitions["IkSection"];
    assert!(ik["properties"].get("method").is_none());
    assert_eq!(ik["additionalProperties"], false);
    // Descriptions are the types' doc comments, rustdoc links made plain.
    assert!(
        definitions["RootSpec"]["description"]
            .as_str()
            .is_some_and(|d| d.contains("root node"))
    );
    assert!(!schema.to_string().contains("[`"), "a rustdoc link is left");
    // Defaults are written in for editors.
    assert_eq!(
        definitions["Scenario"]["properties"]["fps"]["default"],
        json!(60)
    );
}

#[test]
fn a_schema_key_is_accepted_ignored_and_kept() {
    let mut value: Value =
        serde_json::from_str(preset::bundled_json("human").expect("bundled")).expect("JSON");
    let plain = Preset::from_json(&value.to_string()).expect("human is valid");
    value.as_object_mut().expect("object").insert(
        "$schema".to_owned(),
        json!("../docs/schema/preset.schema.json"),
    );
    let with_schema = Preset::from_json(&value.to_string()).expect("$schema is accepted");
    assert_eq!(
        with_schema.schema.as_deref(),
        Some("../docs/schema/preset.schema.json")
    );
    assert_eq!(
        with_schema.build().expect("builds"),
        plain.build().expect("builds"),
        "$schema changes nothing"
    );
    let written = serde_json::to_value(&with_schema).expect("serialises");
    assert_eq!(written["$schema"], "../docs/schema/preset.schema.json");
    // Only at the top level, and only as a string.
    value["$schema"] = json!(3);
    let error = Preset::from_json(&value.to_string()).expect_err("not a string");
    assert_eq!(error.path, "$schema");
    value["$schema"] = json!("x");
    value["skeleton"]["$schema"] = json!("x");
    let error = Preset::from_json(&value.to_string()).expect_err("not in the skeleton");
    assert_eq!(error.path, "skeleton.$schema");
}
