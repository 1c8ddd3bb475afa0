//! The biped of Table 3: a 23.1 kg trunk and two telescoping legs on ball hips
//! (Raibert & Hodgins 1991, Figure 1). Each ball hip is roll (about the
//! forward axis), pitch (about the lateral axis) and yaw (about the leg),
//! and the lower leg slides in the upper leg.

use glam::DVec3;

use super::build::{Builder, paper, paper_inertia};
use super::physical_creature::{Leg, PhysicalCreature, Species};
use crate::dynamics::model::{Joint, Model, ModelError};

/// Table 3, biped: trunk mass (kg) and inertia `[x y z]` (kg·m²).
const TRUNK_MASS_KG: f64 = 23.1;
const TRUNK_INERTIA: [f64; 3] = [0.17, 0.17, 0.30];
/// Hip lateral offset from the trunk's centre of mass (m).
const HIP_LATERAL_M: f64 = 0.072;
/// Upper leg: length, mass centre from the hip (m), mass (kg), inertia.
const UPPER_LENGTH_M: f64 = 0.20;
const UPPER_COM_M: f64 = 0.095;
const UPPER_MASS_KG: f64 = 1.4;
const UPPER_INERTIA: [f64; 3] = [0.018, 0.017, 0.0014];
/// Lower leg: length, mass centre from its top (m), mass (kg), inertia.
const LOWER_LENGTH_M: f64 = 0.63;
const LOWER_COM_M: f64 = 0.22;
const LOWER_MASS_KG: f64 = 0.64;
const LOWER_INERTIA: [f64; 3] = [0.02, 0.02, 0.00018];

/// Hip-to-foot length with the leg spring at zero (m at scale 1).
pub const LEG_LENGTH_M: f64 = UPPER_LENGTH_M + LOWER_LENGTH_M;

/// The biped at dynamic scale `l` (1 = the paper's robot). The leg length
/// from hip to foot is `(0.20 + 0.63)·l + q_spring`.
///
/// # Errors
/// Never for a positive finite `l`; the model check's error otherwise.
pub fn biped(l: f64) -> Result<PhysicalCreature, ModelError> {
    let mut b = Builder::new(l);
    let [ix, iy, iz] = TRUNK_INERTIA;
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
    for (name, side) in [("left", 1.0), ("right", -1.0)] {
        let hip_at = paper(0.0, side * HIP_LATERAL_M, 0.0);
        let roll = b.link(
            &format!("{name}-hip-roll"),
            Some(trunk),
            Joint::Revolute(DVec3::Z),
            hip_at,
        );
        let pitch = b.link(
            &format!("{name}-hip-pitch"),
            Some(roll),
            Joint::Revolute(DVec3::X),
            DVec3::ZERO,
        );
        let [ux, uy, uz] = UPPER_INERTIA;
        let upper = b.body(
            &format!("{name}-upper-leg"),
            Some(pitch),
            Joint::Revolute(DVec3::Y),
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
            hip: vec![dof, dof + 1, dof + 2],
            spring: dof + 3,
            knee: None,
            foot_body: lower,
            foot_point: paper(0.0, 0.0, -LOWER_LENGTH_M) * l,
            hip_in_trunk: hip_at * l,
            length_m: 0.0,
        });
        dof += 4;
    }
    Ok(PhysicalCreature::new(
        Species::Biped,
        l,
        Model::new(b.bodies)?,
        trunk,
        legs,
        Vec::new(),
        None,
    ))
}
