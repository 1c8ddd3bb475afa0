//! Finding presets: a bundled name or a file path. Files are size-checked
//! before they are read in full (DESIGN.md input limits: a preset ≤ 256 KiB).

use std::io::Read;

use gaitlab_core::preset::{
    MAX_PRESET_BYTES, Purpose, bundled, bundled_json, load_bundled, set_preset_value,
};
use gaitlab_core::{Creature, PresetError};
use gaitlab_engine::AnyDriver;

use crate::fail::Failure;
use crate::stdout::outln;

/// Reads at most `limit` bytes of `path` as UTF-8 text; a larger file is an error
/// that names the limit, and nothing past it is read.
pub fn read_limited(path: &str, limit: usize, what: &str) -> Result<String, Failure> {
    let file = std::fs::File::open(path).map_err(|e| Failure::io(path, e))?;
    let mut bytes = Vec::new();
    file.take(limit as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| Failure::io(path, e))?;
    if bytes.len() > limit {
        return Err(Failure::input(format!(
            "{path}: {what} is larger than {} KiB",
            limit / 1024
        )));
    }
    String::from_utf8(bytes).map_err(|e| Failure::input(format!("{path}: not UTF-8 text ({e})")))
}

/// A preset by bundled name, or else by file path, to run its scenario. Errors
/// are `<json path>: <reason>`.
pub fn creature(name_or_path: &str) -> Result<Creature, Failure> {
    creature_for(name_or_path, Purpose::Scenario)
}

/// A preset by bundled name, or else by file path, checked for `purpose`
/// (`track` loads for [`Purpose::Tracking`]: the thesis roles are not checked).
pub fn creature_for(name_or_path: &str, purpose: Purpose) -> Result<Creature, Failure> {
    creature_with(name_or_path, purpose, &[])
}

/// As [`creature_for`], with `edits` (`(dotted path, value)`, `gaitlab run
/// --set`) applied to the preset's JSON before it is parsed and checked, so
/// an edited value meets every rule a file's does.
pub fn creature_with(
    name_or_path: &str,
    purpose: Purpose,
    edits: &[(String, serde_json::Value)],
) -> Result<Creature, Failure> {
    creature_edited(name_or_path, purpose, edits, false)
}

/// As [`creature_with`]; with `paper` (`--paper-alone`), every lab addition
/// of the preset's engine is turned off first
/// ([`gaitlab_core::preset::paper_alone`]), then `edits` apply.
pub fn creature_edited(
    name_or_path: &str,
    purpose: Purpose,
    edits: &[(String, serde_json::Value)],
    paper: bool,
) -> Result<Creature, Failure> {
    let (text, bundled_name) = match bundled_json(name_or_path) {
        Some(json) => (json.to_owned(), true),
        None => (preset_file(name_or_path)?, false),
    };
    let text = if edits.is_empty() && !paper {
        text
    } else {
        let mut preset: serde_json::Value = serde_json::from_str(&text)
            .map_err(|e| Failure::input(format!("{name_or_path}: not JSON ({e})")))?;
        if paper {
            gaitlab_core::preset::paper_alone(&mut preset)
                .map_err(|e| Failure::input(format!("--paper-alone: {e}")))?;
        }
        for (path, value) in edits {
            set_preset_value(&mut preset, path, value.clone())
                .map_err(|e| Failure::input(format!("--set {e}")))?;
        }
        preset.to_string()
    };
    let creature = Creature::from_json_for(&text, purpose).map_err(|e: PresetError| {
        if bundled_name && edits.is_empty() && !paper {
            Failure::input(format!("bundled preset {name_or_path}: {e}"))
        } else {
            Failure::input(e)
        }
    })?;
    for deprecation in creature.deprecations() {
        eprintln!("warning: {deprecation}");
    }
    Ok(creature)
}

/// The JSON text of a bundled preset by name, or else of the preset file.
pub fn preset_text(name_or_path: &str) -> Result<String, Failure> {
    match bundled_json(name_or_path) {
        Some(json) => Ok(json.to_owned()),
        None => preset_file(name_or_path),
    }
}

/// The text of preset file `name_or_path`; a name that is no file is an
/// error that lists the bundled presets.
fn preset_file(name_or_path: &str) -> Result<String, Failure> {
    let looks_like_file = name_or_path.contains('/')
        || name_or_path.contains('.')
        || std::path::Path::new(name_or_path).exists();
    if !looks_like_file {
        let names: Vec<&str> = bundled().iter().map(|(name, _)| *name).collect();
        return Err(Failure::input(format!(
            "{name_or_path}: no such bundled preset (try one of: {}) and no such file",
            names.join(", ")
        )));
    }
    read_limited(name_or_path, MAX_PRESET_BYTES, "preset")
}

/// `gaitlab presets`.
pub fn print_presets() {
    for (name, _) in bundled() {
        match load_bundled(name) {
            Some(Ok(creature)) => outln!(
                "{name:<14} engine={:<4} joints={:<3} legs={}",
                creature.scenario.engine.name(),
                creature.skeleton.joint_count(),
                legs(&creature)
            ),
            Some(Err(error)) => outln!("{name:<14} invalid: {error}"),
            None => {}
        }
    }
}

/// Legs of a creature: a PODA creature's legs, otherwise effectors whose
/// name says foot, paw or hoof.
pub fn legs(creature: &Creature) -> usize {
    if let Some(poda) = &creature.scenario.poda {
        return poda.legs.len();
    }
    creature
        .skeleton
        .effectors()
        .iter()
        .filter(|e| {
            ["foot", "paw", "hoof", "toe"]
                .iter()
                .any(|w| e.name.contains(w))
        })
        .count()
}

/// `gaitlab validate FILE`: the preset's own checks, then the engine layer's
/// (a preset that validates is one `gaitlab run` takes).
pub fn validate(file: &str) -> Result<(), Failure> {
    let creature = creature(file)?;
    let driver = gaitlab_engine::check(&creature).map_err(Failure::input)?;
    if let Some(driver) = driver.as_ref().and_then(AnyDriver::poda) {
        outln!(
            "ok: {} — engine poda, {} joints, {} legs, gait {}, period {} s, duty factor {}, speed {} m/s",
            creature.name,
            creature.skeleton.joint_count(),
            legs(&creature),
            driver.gait_name(),
            driver.gait().period_s(),
            driver.gait().duty_factor(),
            driver.gait().speed_mps()
        );
        return Ok(());
    }
    outln!(
        "ok: {} — engine {}, {} joints, {} effectors, {} legs, mode {}, method {}",
        creature.name,
        creature.scenario.engine.name(),
        creature.skeleton.joint_count(),
        creature.skeleton.effector_count(),
        legs(&creature),
        creature.scenario.mode.name(),
        creature.scenario.method.name()
    );
    Ok(())
}
