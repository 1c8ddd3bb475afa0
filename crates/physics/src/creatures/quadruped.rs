//! The quadruped of Table 3: a 10 kg trunk and four telescoping legs on
//! gimbal hips (Raibert & Hodgins 1991, Figure 1). Each gimbal is roll
//! (about the forward axis) then pitch (about the lateral axis); the lower
//! leg slides in the upper leg.
//!
//! The trunk's inertia row of Table 3 is garbled in the source text
//! ("[54 2 35 2 39]"). Two readings are kept: the digits with the decimal
//! points the other rows have, `[0.54 2.35 2.39]` kg·m² ([`quadruped`]'s),
//! and every figure a tenth of that, `[0.054 0.235 0.239]` kg·m², where
//! Murphy & Raibert's pitch inertia j is below 1 and the passive pitching
//! bound exists (the bundled preset's since 2026-12-04; docs/physics.md,
//! "The trunk's pitch inertia decides the bound").

use glam::DVec3;

use super::build::{Builder, paper, paper_inertia};
use super::physical_creature::{Leg, PhysicalCreature, Species};
use crate::dynamics::model::{Joint, Model, ModelError};

const TRUNK_MASS_KG: f64 = 10.0;
/// Table 3's trunk inertia as printed, with the other rows' decimal points
/// (kg·m², the paper's roll, pitch, yaw).
pub const TRUNK_INERTIA_LITERAL_KGM2: [f64; 3] = [0.54, 2.35, 2.39];
/// The other reading: every figure a tenth (kg·m²).
pub const TRUNK_INERTIA_TENTH_KGM2: [f64; 3] = [0.054, 0.235, 0.239];
/// Hip position from the trunk's centre of mass: ±forward, ±lateral (m).
const HIP_FORWARD_M: f64 = 0.39;
const HIP_LATERAL_M: f64 = 0.12;
const UPPER_LENGTH_M: f64 = 0.41;
const UPPER_COM_M: f64 = 0.2;
const UPPER_MASS_KG: f64 = 1.5;
const UPPER_INERTIA: [f64; 3] = [0.043, 0.043, 0.0];
const LOWER_LENGTH_M: f64 = 0.4;
const LOWER_COM_M: f64 = 0.2;
const LOWER_MASS_KG: f64 = 1.0;
const LOWER_INERTIA: [f64; 3] = [0.0035, 0.0035, 0.0];

/// Hip-to-foot length with the leg spring at zero (m at scale 1).
pub const LEG_LENGTH_M: f64 = UPPER_LENGTH_M + LOWER_LENGTH_M;

/// The legs in order: front-left, front-right, rear-left, rear-right.
pub const LEG_NAMES: [&str; 4] = ["front-left", "front-right", "rear-left", "rear-right"];

/// The quadruped at dynamic scale `l`. Leg length from hip to foot is
/// `(0.41 + 0.40)·l + q_spring`.
///
/// # Errors
/// The model check's error for a non-positive or non-finite `l`.
pub fn quadruped(l: f64) -> Result<PhysicalCreature, ModelError> {
    quadruped_with_trunk(l, TRUNK_INERTIA_LITERAL_KGM2)
}

/// The quadruped at dynamic scale `l` with the trunk's inertia
/// `trunk_inertia_kgm2` (the paper's roll, pitch, yaw at scale 1): one of
/// the two readings above.
///
/// # Errors
/// As [`quadruped`].
pub fn quadruped_with_trunk(
    l: f64,
    trunk_inertia_kgm2: [f64; 3],
) -> Result<PhysicalCreature, ModelError> {
    let mut b = Builder::new(l);
    let [ix, iy, iz] = trunk_inertia_kgm2;
    let trunk = b.body(
        "trunk",
        None,
        Joint::Free,
        DVec3::ZERO,
        TRUNK_MASS_KG,
        DVec3::ZERO,
        paper_inertia(ix, iy, iz),
    );
    let mut legs = Vec::new();
    let mut dof = 0;
    for name in LEG_NAMES {
        let forward = if name.starts_with("front") {
            HIP_FORWARD_M
        } else {
            -HIP_FORWARD_M
        };
        let left = if name.ends_with("left") {
            HIP_LATERAL_M
        } else {
            -HIP_LATERAL_M
        };
        let hip_at = paper(forward, left, 0.0);
        let roll = b.link(
            &format!("{name}-hip-roll"),
            Some(trunk),
            Joint::Revolute(DVec3::Z),
            hip_at,
        );
        let [ux, uy, uz] = UPPER_INERTIA;
        let upper = b.body(
            &format!("{name}-upper-leg"),
            Some(roll),
            Joint::Revolute(DVec3::X),
            DVec3::ZERO,
            UPPER_MASS_KG,
            paper(0.0, 0.0, -UPPER_COM_M),
            paper_inertia(ux, uy, uz),
        );
        let [lx, ly, lz] = LOWER_INERTIA;
        let lower = b.body(
            &format!("{name}-lower-leg"),
            Some(upper),
            Joint::Prismatic(DVec3::NEG_Y),
            paper(0.0, 0.0, -UPPER_LENGTH_M),
            LOWER_MASS_KG,
            paper(0.0, 0.0, -LOWER_COM_M),
            paper_inertia(lx, ly, lz),
        );
        legs.push(Leg {
            name: name.to_owned(),
            hip: vec![dof, dof + 1],
            spring: dof + 2,
            knee: None,
            foot_body: lower,
            foot_point: paper(0.0, 0.0, -LOWER_LENGTH_M) * l,
            hip_in_trunk: hip_at * l,
            length_m: 0.0,
        });
        dof += 3;
    }
    Ok(PhysicalCreature::new(
        Species::Quadruped,
        l,
        Model::new(b.bodies)?,
        trunk,
        legs,
        Vec::new(),
        None,
    ))
}
