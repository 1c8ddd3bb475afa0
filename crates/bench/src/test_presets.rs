//! Bundled presets for the unit tests of this crate (tests only).

use gaitlab_core::Creature;

/// The bundled preset `name`, built; panics with the reason if it is not.
pub fn bundled(name: &str) -> Creature {
    match gaitlab_core::preset::load_bundled(name) {
        Some(Ok(creature)) => creature,
        other => panic!("bundled preset {name}: {other:?}"),
    }
}
