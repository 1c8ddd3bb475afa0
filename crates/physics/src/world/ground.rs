//! Ground contact (Raibert & Hodgins 1991, "Modeling"): one contact point per
//! foot with four spring-damper sets — vertical, two tangential and one
//! torsional about the surface normal — whose rest positions reset when the
//! foot first touches down, so a planted foot does not slip. The kangaroo's
//! paw pad is the non-linear vertical spring of eq. 6,
//! `f = k_gz·(k_r / (k_r + z) − 1)` for penetration `z < 0`.
//!
//! The terrain is flat ground at height 0 plus optional boxes (steps and
//! obstacles); only their tops carry feet.

use gaitlab_core::portable::Portable;
use glam::DVec3;

use crate::creatures::PhysicalCreature;
use crate::dynamics::data::Data;

/// The non-linear paw pad of eq. 6.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PawPad {
    /// Pad stiffness k_gz (N).
    pub stiffness_n: f64,
    /// Pad thickness k_r (m).
    pub thickness_m: f64,
}

/// Spring and damper constants of the ground model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GroundParams {
    /// Vertical stiffness (N/m), used unless `pad` is set.
    pub vertical_stiffness: f64,
    /// Vertical damping (N·s/m).
    pub vertical_damping: f64,
    /// Tangential stiffness, both directions (N/m).
    pub tangential_stiffness: f64,
    /// Tangential damping (N·s/m).
    pub tangential_damping: f64,
    /// Torsional stiffness about the normal (N·m/rad).
    pub torsional_stiffness: f64,
    /// Torsional damping (N·m·s/rad).
    pub torsional_damping: f64,
    /// The non-linear vertical pad of eq. 6, replacing the linear spring.
    pub pad: Option<PawPad>,
}

impl Default for GroundParams {
    fn default() -> Self {
        Self {
            vertical_stiffness: 50_000.0,
            vertical_damping: 500.0,
            tangential_stiffness: 50_000.0,
            tangential_damping: 500.0,
            torsional_stiffness: 500.0,
            torsional_damping: 2.0,
            pad: None,
        }
    }
}

impl GroundParams {
    /// The same ground for a creature scaled by `l` (Table 1: stiffness ×L²,
    /// damping ×L^2.5, torsional stiffness ×L⁴, torsional damping ×L^4.5,
    /// force ×L³, length ×L).
    #[must_use]
    pub fn scaled(&self, l: f64) -> Self {
        Self {
            vertical_stiffness: self.vertical_stiffness * l.powi(2),
            vertical_damping: self.vertical_damping * l.ppowf(2.5),
            tangential_stiffness: self.tangential_stiffness * l.powi(2),
            tangential_damping: self.tangential_damping * l.ppowf(2.5),
            torsional_stiffness: self.torsional_stiffness * l.powi(4),
            torsional_damping: self.torsional_damping * l.ppowf(4.5),
            pad: self.pad.map(|p| PawPad {
                stiffness_n: p.stiffness_n * l.powi(3),
                thickness_m: p.thickness_m * l,
            }),
        }
    }
}

/// An axis-aligned box standing on the ground: an obstacle or a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Obstacle {
    /// Lowest corner on the ground: x (lateral) and z (forward), m.
    pub min_xz: [f64; 2],
    /// Highest corner on the ground, m.
    pub max_xz: [f64; 2],
    /// Height of the top (m).
    pub height_m: f64,
}

impl Obstacle {
    /// Whether the ground point (x, z) is over the box.
    #[must_use]
    pub fn covers(&self, x: f64, z: f64) -> bool {
        x >= self.min_xz[0] && x <= self.max_xz[0] && z >= self.min_xz[1] && z <= self.max_xz[1]
    }
}

/// Flat ground plus boxes.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Terrain {
    /// Boxes on the ground.
    pub obstacles: Vec<Obstacle>,
}

impl Terrain {
    /// Height of the surface under (x, z) (m).
    #[must_use]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        self.obstacles
            .iter()
            .filter(|o| o.covers(x, z))
            .fold(0.0, |h, o| h.max(o.height_m))
    }
}

/// One foot's contact state and the force it carries.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FootContact {
    /// Whether the foot is on the ground.
    pub touching: bool,
    /// Where the tangential springs are anchored (world, m).
    pub anchor: DVec3,
    /// The foot's heading at touchdown (rad), the torsional spring's rest.
    pub yaw_anchor: f64,
    /// The ground reaction force on the foot (world, N).
    pub force: DVec3,
    /// The foot's world position this step (m).
    pub position: DVec3,
    /// The foot's world velocity this step (m/s).
    pub velocity: DVec3,
}

/// The heading of a body's forward (z) axis about the world vertical (rad).
fn yaw_of(data: &Data, body: usize) -> f64 {
    let fwd = data.world[body].rot.z_axis;
    fwd.x.patan2(fwd.z)
}

fn wrap_angle(a: f64) -> f64 {
    (a + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
}

/// The contact stage: reads kinematics, updates `contacts` (one per leg) and
/// adds the ground forces to `data.external`.
pub fn contact_forces(
    creature: &PhysicalCreature,
    data: &mut Data,
    params: &GroundParams,
    terrain: &Terrain,
    contacts: &mut [FootContact],
) {
    for (leg, contact) in creature.legs.iter().zip(contacts.iter_mut()) {
        let p = data.point_world(leg.foot_body, leg.foot_point);
        let v = data.point_velocity_world(leg.foot_body, leg.foot_point);
        contact.position = p;
        contact.velocity = v;
        let surface = terrain.height(p.x, p.z);
        let z = p.y - surface;
        if z >= 0.0 {
            contact.touching = false;
            contact.force = DVec3::ZERO;
            continue;
        }
        if !contact.touching {
            contact.touching = true;
            contact.anchor = DVec3::new(p.x, surface, p.z);
            contact.yaw_anchor = yaw_of(data, leg.foot_body);
        }
        let spring = match params.pad {
            Some(pad) => {
                let depth = z.max(-0.95 * pad.thickness_m);
                pad.stiffness_n * (pad.thickness_m / (pad.thickness_m + depth) - 1.0)
            }
            None => -params.vertical_stiffness * z,
        };
        let normal = (spring - params.vertical_damping * v.y).max(0.0);
        let fx = -params.tangential_stiffness * (p.x - contact.anchor.x)
            - params.tangential_damping * v.x;
        let fz = -params.tangential_stiffness * (p.z - contact.anchor.z)
            - params.tangential_damping * v.z;
        let force = DVec3::new(fx, normal, fz);
        contact.force = force;
        data.apply_world_force(leg.foot_body, p, force);
        let twist = wrap_angle(yaw_of(data, leg.foot_body) - contact.yaw_anchor);
        let spin = (data.world[leg.foot_body].rot * data.velocity[leg.foot_body].angular).y;
        let torque = -params.torsional_stiffness * twist - params.torsional_damping * spin;
        data.apply_world_torque(leg.foot_body, DVec3::new(0.0, torque, 0.0));
    }
}
