//! Shared test fixtures: the bundled human preset the thesis drivers are tuned on.

#![allow(dead_code)]

use gaitlab_core::Skeleton;
use gaitlab_core::preset::thesis::ThesisParams;
use gaitlab_core::preset::{Creature, load_bundled};

/// The bundled `human` preset (presets/human.json: 20 one-DOF joints, 4 effectors).
pub fn creature() -> Creature {
    match load_bundled("human") {
        Some(Ok(creature)) => creature,
        Some(Err(error)) => panic!("human preset: {error}"),
        None => panic!("no bundled human preset"),
    }
}

/// The human's skeleton.
pub fn human() -> Skeleton {
    creature().skeleton
}

/// The human's thesis parameters (the defaults plus the preset's wounded joints).
pub fn human_params() -> ThesisParams {
    creature().scenario.thesis
}
