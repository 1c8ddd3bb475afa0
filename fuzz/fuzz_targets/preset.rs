//! Preset text → parse, validate, build the skeleton (DESIGN.md "Presets"),
//! then forward kinematics of the rest pose. Any input must give `Ok` or a
//! `PresetError` with a JSON path, never a panic, and a built creature's rest
//! pose must be finite.
#![no_main]

use gaitlab_core::{Creature, Kinematics};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match Creature::from_json(text) {
        Ok(creature) => {
            let pose = creature.rest_pose();
            let fk = Kinematics::of(&creature.skeleton, &pose);
            for (i, p) in fk.joint_position.iter().enumerate() {
                assert!(p.is_finite(), "rest pose joint {i} is not finite: {p}");
            }
            for (i, p) in fk.effector_position.iter().enumerate() {
                assert!(p.is_finite(), "rest pose effector {i} is not finite: {p}");
            }
        }
        Err(error) => assert!(!error.to_string().is_empty()),
    }
});
