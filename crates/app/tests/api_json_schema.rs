//! The shipped JSON Schemas of the JS API (`docs/schema/command.schema.json`,
//! `docs/schema/state.schema.json`) are the ones the serde types generate, and
//! they describe what the lab reads and writes: the command schema refuses
//! unknown keys, and every state key appears in the state schema.
//!
//! Regenerate the files after changing an API type:
//! `GAITLAB_UPDATE_SCHEMA=1 cargo test -p gaitlab-app --test api_json_schema`.

use std::path::PathBuf;

use gaitlab_app::api::schema::{
    COMMAND_SCHEMA_ID, STATE_SCHEMA_ID, command_schema, schema_text, state_schema,
};
use gaitlab_app::{App, Settings};
use serde_json::Value;

fn shipped(name: &str) -> PathBuf {
    [
        env!("CARGO_MANIFEST_DIR"),
        "..",
        "..",
        "docs",
        "schema",
        name,
    ]
    .iter()
    .collect()
}

#[track_caller]
fn assert_current(name: &str, schema: &Value) {
    let path = shipped(name);
    let generated = schema_text(schema);
    if std::env::var_os("GAITLAB_UPDATE_SCHEMA").is_some() {
        std::fs::write(&path, &generated)
            .unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
    }
    let text = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        text == generated,
        "{} is not the schema the API types generate; regenerate it with\n  \
         GAITLAB_UPDATE_SCHEMA=1 cargo test -p gaitlab-app --test api_json_schema\n\
         and commit the file",
        path.display()
    );
}

#[test]
fn shipped_schemas_are_current() {
    assert_current("command.schema.json", &command_schema());
    assert_current("state.schema.json", &state_schema());
}

#[test]
fn the_command_schema_names_itself_and_refuses_unknown_keys() {
    let schema = command_schema();
    assert_eq!(schema["$id"], COMMAND_SCHEMA_ID);
    assert_eq!(schema["$schema"], "http://json-schema.org/draft-07/schema#");
    assert_eq!(schema["additionalProperties"], false);
    assert!(schema["required"].as_array().is_none_or(|r| r.is_empty()));
    let keys = schema["properties"].as_object().expect("properties");
    for key in [
        "engine",
        "compare",
        "camera",
        "save",
        "gain",
        "path",
        "show_link",
    ] {
        assert!(keys.contains_key(key), "{key}");
    }
}

#[test]
fn every_state_key_is_in_the_state_schema() {
    let schema = state_schema();
    assert_eq!(schema["$id"], STATE_SCHEMA_ID);
    let state: Value =
        serde_json::from_str(&App::new(Settings::default()).state_json()).expect("state is JSON");
    let properties = schema["properties"].as_object().expect("properties");
    let keys = state.as_object().expect("object");
    assert_eq!(
        properties.keys().collect::<Vec<_>>(),
        keys.keys().collect::<Vec<_>>()
    );
}
