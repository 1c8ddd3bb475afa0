//! The ground each creature runs on: the ground springs of eq. 6 (Raibert
//! & Hodgins 1991, "Modeling"), the quadruped's the default ones, the
//! kangaroo's with a paw pad.

use crate::world::ground::{GroundParams, PawPad};

/// The ground the quadruped runs on at scale `l`: the default springs scaled.
#[must_use]
pub fn quadruped_ground(l: f64) -> GroundParams {
    GroundParams::default().scaled(l)
}

/// The kangaroo's paw-pad ground (eq. 6) at scale 1; scale it with
/// [`GroundParams::scaled`].
#[must_use]
pub fn kangaroo_ground() -> GroundParams {
    GroundParams {
        vertical_stiffness: 30_000.0,
        vertical_damping: 150.0,
        tangential_stiffness: 20_000.0,
        tangential_damping: 100.0,
        torsional_stiffness: 50.0,
        torsional_damping: 0.5,
        pad: Some(PawPad {
            stiffness_n: 600.0,
            thickness_m: 0.02,
        }),
    }
}
