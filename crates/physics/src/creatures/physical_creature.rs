//! A physically modelled creature: its articulated [`Model`] plus where its
//! legs, feet and tail are, so controllers and contacts can find them
//! (Raibert & Hodgins 1991, Figure 1 and Table 3).

use glam::DVec3;

use crate::dynamics::data::Data;
use crate::dynamics::kinematics::kinematics;
use crate::dynamics::model::Model;

/// One leg's joints (coordinate indices into `Data::q`) and its foot.
#[derive(Clone, Debug, PartialEq)]
pub struct Leg {
    /// Name ("left", "front-right", …).
    pub name: String,
    /// Hip joint coordinates, proximal first: `[roll, pitch]` for a gimbal,
    /// `[roll, pitch, yaw]` for a ball hip, `[pitch]` for the planar kangaroo.
    pub hip: Vec<usize>,
    /// The leg's springy joint: the telescoping (prismatic) joint of the
    /// robots, the ankle of the kangaroo.
    pub spring: usize,
    /// The kangaroo's knee (posture servo in stance); `None` for the robots.
    pub knee: Option<usize>,
    /// The body carrying the foot.
    pub foot_body: usize,
    /// The contact point in the foot body's coordinates (m).
    pub foot_point: DVec3,
    /// The hip's position in trunk coordinates (m).
    pub hip_in_trunk: DVec3,
    /// Hip-to-foot length with every joint at zero (m, at the creature's
    /// scale): for the telescoping legs, the leg at full length. Set by
    /// [`PhysicalCreature::new`] from the model; controllers place feet
    /// with it, so a preset with other leg lengths runs without code
    /// changes.
    pub length_m: f64,
}

/// Which of the paper's models a creature is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Species {
    /// The 3-D biped with telescoping legs and ball hips.
    Biped,
    /// The 3-D quadruped with telescoping legs and gimbal hips.
    Quadruped,
    /// The planar one-legged kangaroo with tail and head.
    Kangaroo,
}

/// A creature ready to simulate: the physical counterpart of the preset it
/// was built from (`gaitlab_core::Creature`, the parsed preset; see
/// [`creature_from_preset`](crate::engine::preset::creature_from_preset)).
#[derive(Clone, Debug, PartialEq)]
pub struct PhysicalCreature {
    /// Which model.
    pub species: Species,
    /// The dynamic scale factor L it was built at (Table 1); 1 is the paper's size.
    pub scale: f64,
    /// Bodies and joints.
    pub model: Model,
    /// The trunk body.
    pub trunk: usize,
    /// The legs.
    pub legs: Vec<Leg>,
    /// The kangaroo's tail joints, base first.
    pub tail: Vec<usize>,
    /// The kangaroo's neck joint.
    pub neck: Option<usize>,
}

impl PhysicalCreature {
    /// A creature from its parts, each leg's [`Leg::length_m`] measured on
    /// the model with every joint at zero.
    #[must_use]
    pub fn new(
        species: Species,
        scale: f64,
        model: Model,
        trunk: usize,
        mut legs: Vec<Leg>,
        tail: Vec<usize>,
        neck: Option<usize>,
    ) -> Self {
        let mut data = Data::new(&model);
        kinematics(&model, &mut data);
        let at = data.world[trunk];
        for leg in &mut legs {
            let hip = at.rot * leg.hip_in_trunk + at.pos;
            leg.length_m = (data.point_world(leg.foot_body, leg.foot_point) - hip).length();
        }
        Self {
            species,
            scale,
            model,
            trunk,
            legs,
            tail,
            neck,
        }
    }

    /// Each leg's [`Leg::length_m`] (m).
    pub fn leg_lengths_m(&self) -> impl Iterator<Item = f64> + '_ {
        self.legs.iter().map(|leg| leg.length_m)
    }

    /// Leg `i`'s [`Leg::length_m`] (m), 0 for a leg it does not have.
    #[must_use]
    pub fn leg_length_m(&self, i: usize) -> f64 {
        self.legs.get(i).map_or(0.0, |leg| leg.length_m)
    }
}
