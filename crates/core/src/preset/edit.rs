//! Setting one value of a preset by its dotted JSON path — the same paths the
//! preset's errors name (`scenario.physics.speed_mps`,
//! `skeleton.joints[3].gain`) — before the preset is parsed and checked, so a
//! changed value gets every rule a file gets (`gaitlab run --set`).

use serde_json::Value;

use super::PresetError;

/// Longest path accepted, characters.
pub const MAX_EDIT_PATH_CHARS: usize = 256;

/// One step of a path: an object key or an array index.
enum Step<'a> {
    Key(&'a str),
    Index(usize),
}

fn steps(path: &str) -> Result<Vec<Step<'_>>, PresetError> {
    let bad = |why: &str| PresetError::new(path, format!("not a preset path ({why})"));
    if path.is_empty() || path.len() > MAX_EDIT_PATH_CHARS {
        return Err(bad("empty or too long"));
    }
    let mut out = Vec::new();
    for part in path.split('.') {
        let (key, mut rest) = match part.find('[') {
            Some(at) => part.split_at(at),
            None => (part, ""),
        };
        if key.is_empty()
            || !key
                .chars()
                .all(|c| c.is_alphanumeric() || c == '_' || c == '$')
        {
            return Err(bad("each part is a key such as speed_mps or joints[3]"));
        }
        out.push(Step::Key(key));
        while let Some(inner) = rest.strip_prefix('[') {
            let close = inner.find(']').ok_or_else(|| bad("an unclosed ["))?;
            let index = inner[..close]
                .parse()
                .map_err(|_| bad("an index is a whole number"))?;
            out.push(Step::Index(index));
            rest = &inner[close + 1..];
        }
        if !rest.is_empty() {
            return Err(bad("text after ]"));
        }
    }
    Ok(out)
}

/// Sets the value at `path` in `preset` (a parsed preset file) to `value`.
/// The last key may be new (an optional field the file left out), and so may
/// an object on the way (an optional section, e.g. `scenario.ik` in
/// `scenario.ik.lambda`: created empty, so its other fields take their
/// defaults); a list on the way must exist.
///
/// # Errors
/// `path: reason` for a malformed path, a missing parent, or an index past
/// the end of an array.
pub fn set_preset_value(preset: &mut Value, path: &str, value: Value) -> Result<(), PresetError> {
    let steps = steps(path)?;
    let mut at = preset;
    let mut walked = String::new();
    let last = steps.len() - 1;
    for (i, step) in steps.iter().enumerate() {
        let here = if walked.is_empty() {
            "the preset"
        } else {
            walked.as_str()
        }
        .to_owned();
        match step {
            Step::Key(key) => {
                if !walked.is_empty() {
                    walked.push('.');
                }
                walked.push_str(key);
                let Value::Object(map) = at else {
                    return Err(PresetError::new(path, format!("{here} is not an object")));
                };
                if i == last {
                    map.insert((*key).to_owned(), value);
                    return Ok(());
                }
                if !map.contains_key(*key) && matches!(steps[i + 1], Step::Key(_)) {
                    map.insert((*key).to_owned(), Value::Object(serde_json::Map::new()));
                }
                at = map.get_mut(*key).ok_or_else(|| {
                    PresetError::new(path, format!("{walked} is not in the preset"))
                })?;
            }
            Step::Index(index) => {
                walked.push_str(&format!("[{index}]"));
                let Value::Array(items) = at else {
                    return Err(PresetError::new(path, format!("{here} is not a list")));
                };
                let len = items.len();
                let slot = items
                    .get_mut(*index)
                    .ok_or_else(|| PresetError::new(path, format!("{here} has {len} entries")))?;
                if i == last {
                    *slot = value;
                    return Ok(());
                }
                at = slot;
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn sets_keys_indices_and_new_optional_keys() {
        let mut preset =
            json!({"scenario": {"physics": {"speed_mps": 1.0}}, "legs": [{"x": 1}, {"x": 2}]});
        set_preset_value(&mut preset, "scenario.physics.speed_mps", json!(2.5)).expect("set");
        set_preset_value(&mut preset, "scenario.physics.hop_height_m", json!(0.2)).expect("new");
        set_preset_value(&mut preset, "legs[1].x", json!(7)).expect("index");
        assert_eq!(preset["scenario"]["physics"]["speed_mps"], json!(2.5));
        assert_eq!(preset["scenario"]["physics"]["hop_height_m"], json!(0.2));
        assert_eq!(preset["legs"][1]["x"], json!(7));
        // A missing section on the way is created empty.
        set_preset_value(&mut preset, "scenario.ik.jacobian_at", json!("targets"))
            .expect("section");
        assert_eq!(preset["scenario"]["ik"], json!({"jacobian_at": "targets"}));
    }

    #[test]
    fn bad_paths_name_what_is_missing() {
        let mut preset = json!({"scenario": {"physics": {}}, "legs": [{"x": 1}]});
        let reason = |path: &str, preset: &mut Value| {
            set_preset_value(preset, path, json!(1))
                .map(|()| String::new())
                .unwrap_or_else(|e| e.to_string())
        };
        assert_eq!(
            reason("legs2[0].x", &mut preset),
            "legs2[0].x: legs2 is not in the preset"
        );
        assert_eq!(
            reason("legs[3].x", &mut preset),
            "legs[3].x: legs has 1 entries"
        );
        assert_eq!(
            reason("scenario.physics[0]", &mut preset),
            "scenario.physics[0]: scenario.physics is not a list"
        );
        assert!(reason("a..b", &mut preset).starts_with("a..b: not a preset path"));
        assert!(reason("legs[x]", &mut preset).contains("whole number"));
        assert!(reason("", &mut preset).contains("empty"));
    }
}
