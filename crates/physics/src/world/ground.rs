//! Ground contact (Raibert & Hodgins 1991, "Modeling"): one contact point per
//! foot with four spring-damper sets — vertical, two tangential and one
//! torsional about the surface normal — whose rest positions reset when the
//! foot first touches down, so a planted foot does not slip. The kangaroo's
//! paw pad is the non-linear vertical spring of eq. 6,
//! `f = k_gz·(k_r / (k_r + z) − 1)` for penetration `z < 0`.
//!
//! The terrain is flat ground at height 0 plus optional boxes (steps and
//! obstacles); only their tops carry feet. On core's terrain model (a slope,
//! stairs, a height field: issue 45) the same springs act along the
//! surface's normal at the contact point and in its tangent plane
//! ([`contact_force_on_surface`]); the floor keeps the paper's vertical and
//! horizontal springs exactly.

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

/// The ground (the floor, or core's terrain model) plus boxes.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Terrain {
    /// The ground's shape (`scenario.terrain`; the floor by default).
    pub surface: gaitlab_core::terrain::Terrain,
    /// Boxes on the ground.
    pub obstacles: Vec<Obstacle>,
}

impl Terrain {
    /// Height of the surface under (x, z) (m).
    #[must_use]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        let ground = self.surface.height_m(x, z);
        self.obstacles
            .iter()
            .filter(|o| o.covers(x, z))
            .fold(ground, |h, o| h.max(o.height_m))
    }

    /// The surface's height and unit normal under (x, z): a box's top is
    /// level.
    #[must_use]
    pub fn surface_at(&self, x: f64, z: f64) -> (f64, DVec3) {
        let ground = self.surface.height_m(x, z);
        let on_box = self
            .obstacles
            .iter()
            .filter(|o| o.covers(x, z))
            .map(|o| o.height_m)
            .fold(f64::NEG_INFINITY, f64::max);
        if on_box >= ground {
            (on_box, DVec3::Y)
        } else {
            (ground, self.surface.normal(x, z))
        }
    }
}

/// The ground force on a foot at `p` moving at `v` over a surface of
/// `height` and unit `normal` under it, on ground that is not flat: the
/// four spring-damper sets of Raibert & Hodgins 1991's model acting along
/// the normal and in the tangent plane at the contact point (issue 45 item
/// 3). The penetration is the vertical gap times the normal's vertical part
/// (the distance to the surface's plane); the spring pushes along the normal,
/// never pulls; the tangential springs pull the foot back toward where it
/// touched down, within the tangent plane. `None` when the foot is above the
/// surface (and `contact` lets go).
pub fn contact_force_on_surface(
    params: &GroundParams,
    height: f64,
    normal: DVec3,
    p: DVec3,
    v: DVec3,
    contact: &mut FootContact,
) -> Option<DVec3> {
    let gap = p.y - height;
    if gap >= 0.0 {
        contact.touching = false;
        return None;
    }
    if !contact.touching {
        contact.touching = true;
        contact.anchor = DVec3::new(p.x, height, p.z);
    }
    let depth = gap * normal.y;
    let spring = match params.pad {
        Some(pad) => {
            let depth = depth.max(-0.95 * pad.thickness_m);
            pad.stiffness_n * (pad.thickness_m / (pad.thickness_m + depth) - 1.0)
        }
        None => -params.vertical_stiffness * depth,
    };
    let along = (spring - params.vertical_damping * v.dot(normal)).max(0.0);
    let offset = p - contact.anchor;
    let offset_t = offset - offset.dot(normal) * normal;
    let v_t = v - v.dot(normal) * normal;
    let tangential = -params.tangential_stiffness * offset_t - params.tangential_damping * v_t;
    Some(along * normal + tangential)
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
        if !terrain.surface.is_flat() {
            // Along the normal at the contact point (issue 45 item 3).
            let (height, normal) = terrain.surface_at(p.x, p.z);
            let was_touching = contact.touching;
            let Some(force) = contact_force_on_surface(params, height, normal, p, v, contact)
            else {
                contact.force = DVec3::ZERO;
                continue;
            };
            if !was_touching {
                contact.yaw_anchor = yaw_of(data, leg.foot_body);
            }
            contact.force = force;
            data.apply_world_force(leg.foot_body, p, force);
            let twist = wrap_angle(yaw_of(data, leg.foot_body) - contact.yaw_anchor);
            let spin =
                (data.world[leg.foot_body].rot * data.velocity[leg.foot_body].angular).dot(normal);
            let torque = -params.torsional_stiffness * twist - params.torsional_damping * spin;
            data.apply_world_torque(leg.foot_body, torque * normal);
            continue;
        }
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

#[cfg(test)]
mod tests {
    use super::*;
    use gaitlab_core::terrain::{Plane, Terrain as Surface};

    const EPS: f64 = 1e-9;

    fn params() -> GroundParams {
        GroundParams::default()
    }

    /// The floor's own formula (the paper's vertical and horizontal springs).
    fn floor_force(p: DVec3, v: DVec3, anchor: DVec3) -> DVec3 {
        let g = params();
        let normal = (-g.vertical_stiffness * p.y - g.vertical_damping * v.y).max(0.0);
        DVec3::new(
            -g.tangential_stiffness * (p.x - anchor.x) - g.tangential_damping * v.x,
            normal,
            -g.tangential_stiffness * (p.z - anchor.z) - g.tangential_damping * v.z,
        )
    }

    #[test]
    fn with_the_normal_up_it_is_the_floors_model() {
        let mut state = 3_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1_u64 << 53) as f64 - 0.5
        };
        for _ in 0..200 {
            let anchor = DVec3::new(next(), 0.0, next());
            let p = anchor + DVec3::new(0.01 * next(), -0.004 * (next() + 0.5), 0.01 * next());
            let v = DVec3::new(next(), next(), next());
            let mut contact = FootContact {
                touching: true,
                anchor,
                ..FootContact::default()
            };
            let got = contact_force_on_surface(&params(), 0.0, DVec3::Y, p, v, &mut contact)
                .expect("in contact");
            let want = floor_force(p, v, anchor);
            assert!(
                (got - want).length() < 1e-9 * want.length().max(1.0),
                "{got} {want}"
            );
        }
    }

    #[test]
    fn on_a_slope_the_spring_pushes_along_the_normal_and_holds_in_the_tangent_plane() {
        let surface = Surface::Plane(Plane {
            slope_deg: 10.0,
            direction_deg: 90.0,
        });
        let terrain = Terrain {
            surface: surface.clone(),
            obstacles: Vec::new(),
        };
        let s = DVec3::new(0.3, surface.height_m(0.3, 1.2), 1.2);
        let (height, n) = terrain.surface_at(s.x, s.z);
        assert!((height - s.y).abs() < EPS && (n.y - 10f64.to_radians().pcos()).abs() < EPS);
        let g = params();
        // Touching down at s, then pressed 5 mm in along the normal.
        let mut contact = FootContact::default();
        let touch = s - 1e-12 * DVec3::Y;
        let (h, n) = terrain.surface_at(touch.x, touch.z);
        contact_force_on_surface(&g, h, n, touch, DVec3::ZERO, &mut contact).expect("touching");
        let pressed = s - 0.005 * n;
        let (h, n) = terrain.surface_at(pressed.x, pressed.z);
        let force = contact_force_on_surface(&g, h, n, pressed, DVec3::ZERO, &mut contact)
            .expect("in contact");
        let want = g.vertical_stiffness * 0.005 * n;
        assert!((force - want).length() < 1e-6, "{force} against {want}");
        // Slid 2 mm down the slope in the tangent plane: held back up it.
        let down = (DVec3::new(0.0, 0.0, -1.0) - DVec3::new(0.0, 0.0, -1.0).dot(n) * n).normalize();
        let slid = pressed + 0.002 * down;
        let (h, n) = terrain.surface_at(slid.x, slid.z);
        let force = contact_force_on_surface(&g, h, n, slid, DVec3::ZERO, &mut contact)
            .expect("in contact");
        let want = g.vertical_stiffness * 0.005 * n - g.tangential_stiffness * 0.002 * down;
        assert!((force - want).length() < 1e-6, "{force} against {want}");
        // Leaving fast along the normal: the damper never pulls.
        let force =
            contact_force_on_surface(&g, h, n, slid, 100.0 * n, &mut contact).expect("in contact");
        assert!(force.dot(n) >= 0.0, "{force}");
        // Above the surface: no force, and the contact lets go.
        assert!(
            contact_force_on_surface(&g, h, n, s + 0.01 * n, DVec3::ZERO, &mut contact).is_none()
        );
        assert!(!contact.touching);
    }

    #[test]
    fn a_box_on_a_slope_is_level() {
        let terrain = Terrain {
            surface: Surface::Plane(Plane {
                slope_deg: 10.0,
                direction_deg: 90.0,
            }),
            obstacles: vec![Obstacle {
                min_xz: [-0.5, 0.5],
                max_xz: [0.5, 1.0],
                height_m: 0.5,
            }],
        };
        assert_eq!(terrain.surface_at(0.0, 0.7), (0.5, DVec3::Y));
        let (h, n) = terrain.surface_at(0.0, 2.0);
        assert!((h - 2.0 * 10f64.to_radians().ptan()).abs() < EPS && n.y < 1.0);
        assert!((terrain.height(0.0, 2.0) - h).abs() < EPS);
    }
}
