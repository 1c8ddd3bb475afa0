//! The presets shipped with gaitlab (`presets/*.json`), embedded at compile time
//! so that the browser and the CLI need no files. Core does no I/O: a front end
//! that gets a name or a path asks [`bundled_json`] first and reads a file only
//! when the name is not bundled.

use super::{Creature, PresetError};

/// Every bundled preset as `(name, json)`, the default (`human`) first.
const BUNDLED: &[(&str, &str)] = &[
    ("human", include_str!("../../../../presets/human.json")),
    (
        "she-2006",
        include_str!("../../../../presets/she-2006.json"),
    ),
    (
        "ik-quadruped",
        include_str!("../../../../presets/ik-quadruped.json"),
    ),
    (
        "poda-quadruped",
        include_str!("../../../../presets/poda-quadruped.json"),
    ),
    (
        "poda-biped",
        include_str!("../../../../presets/poda-biped.json"),
    ),
    ("hexapod", include_str!("../../../../presets/hexapod.json")),
    (
        "insect-14",
        include_str!("../../../../presets/insect-14.json"),
    ),
    (
        "raibert-biped",
        include_str!("../../../../presets/raibert-biped.json"),
    ),
    (
        "raibert-quadruped",
        include_str!("../../../../presets/raibert-quadruped.json"),
    ),
    (
        "raibert-kangaroo",
        include_str!("../../../../presets/raibert-kangaroo.json"),
    ),
];

/// Name of the preset a front end opens when none is asked for.
pub const DEFAULT_PRESET: &str = "human";

/// Every bundled preset as `(name, json)`, the default first. Each name equals the
/// `name` field inside its JSON.
#[must_use]
pub fn bundled() -> &'static [(&'static str, &'static str)] {
    BUNDLED
}

/// Names of the bundled presets, the default first.
pub fn bundled_names() -> impl Iterator<Item = &'static str> {
    BUNDLED.iter().map(|(name, _)| *name)
}

/// The JSON of the bundled preset called `name`, if there is one.
#[must_use]
pub fn bundled_json(name: &str) -> Option<&'static str> {
    BUNDLED
        .iter()
        .find(|(bundled, _)| *bundled == name)
        .map(|(_, json)| *json)
}

/// Parses, validates and builds the bundled preset called `name`; `None` when no
/// bundled preset has that name.
#[must_use]
pub fn load_bundled(name: &str) -> Option<Result<Creature, PresetError>> {
    bundled_json(name).map(Creature::from_json)
}
