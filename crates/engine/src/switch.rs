//! The bundled creature that shows an engine when a person switches engine
//! in the page: the thesis human and the PODA biped share a skeleton, as do
//! the IK and PODA quadrupeds; a physics runner goes to the PODA creature of
//! its shape; anything else to the engine's own biped or quadruped.

use gaitlab_core::preset::Engine;

/// The bundled preset to load for `engine`, coming from preset `current`.
#[must_use]
pub fn bundled_for_engine(engine: Engine, current: &str) -> &'static str {
    match (engine, current) {
        (Engine::Poda, "human" | "raibert-biped" | "raibert-kangaroo") => "poda-biped",
        (Engine::Poda, _) => "poda-quadruped",
        (Engine::Ik, "poda-quadruped" | "raibert-quadruped") => "ik-quadruped",
        (Engine::Ik, _) => "human",
        (Engine::Physics, "poda-quadruped" | "ik-quadruped" | "hexapod" | "insect-14") => {
            "raibert-quadruped"
        }
        (Engine::Physics, _) => "raibert-biped",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_switch_lands_on_a_bundled_preset_of_that_engine() {
        for (current, _) in gaitlab_core::preset::bundled() {
            for engine in [Engine::Ik, Engine::Poda, Engine::Physics] {
                let name = bundled_for_engine(engine, current);
                let creature = match gaitlab_core::preset::load_bundled(name) {
                    Some(Ok(creature)) => creature,
                    other => panic!("{current} -> {name}: {other:?}"),
                };
                assert_eq!(creature.scenario.engine, engine, "{current} -> {name}");
            }
        }
    }
}
