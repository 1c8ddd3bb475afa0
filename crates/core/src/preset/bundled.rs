//! The presets shipped with gaitlab (`presets/*.json`), embedded at compile time
//! so that the browser and the CLI need no files. Core does no I/O: a front end
//! that gets a name or a path asks [`bundled_json`] first and reads a file only
//! when the name is not bundled.

use std::sync::OnceLock;

use super::{Creature, Engine, PresetError};

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

/// What a menu shows of a bundled preset: its name, engine and description.
#[derive(Clone, Debug, PartialEq)]
pub struct BundledInfo {
    /// The preset's name.
    pub name: &'static str,
    /// The engine its scenario runs.
    pub engine: Engine,
    /// Its one-paragraph description.
    pub description: String,
}

/// Every bundled preset's [`BundledInfo`], in [`bundled`]'s order, parsed
/// once on first use. A preset that does not load (a build defect the
/// `presets` tests catch) is left out.
#[must_use]
pub fn bundled_catalog() -> &'static [BundledInfo] {
    static CATALOG: OnceLock<Vec<BundledInfo>> = OnceLock::new();
    CATALOG.get_or_init(|| {
        BUNDLED
            .iter()
            .filter_map(|(name, json)| {
                let creature = Creature::from_json(json).ok()?;
                Some(BundledInfo {
                    name,
                    engine: creature.scenario.engine,
                    description: creature.description,
                })
            })
            .collect()
    })
}

#[cfg(test)]
mod catalog_tests {
    use super::*;

    #[test]
    fn the_catalog_lists_every_bundled_preset_with_its_engine_and_description() {
        let catalog = bundled_catalog();
        assert_eq!(catalog.len(), BUNDLED.len());
        for (info, (name, _)) in catalog.iter().zip(BUNDLED) {
            assert_eq!(info.name, *name);
            assert!(!info.description.is_empty(), "{name} has no description");
        }
        let engine = |n: &str| catalog.iter().find(|i| i.name == n).map(|i| i.engine);
        assert_eq!(engine("human"), Some(Engine::Ik));
        assert_eq!(engine("poda-quadruped"), Some(Engine::Poda));
        assert_eq!(engine("raibert-kangaroo"), Some(Engine::Physics));
    }
}
