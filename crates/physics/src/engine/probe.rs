//! What the page's live plots read from a running simulation (Raibert &
//! Hodgins 1991's quantities of Figures 7–9): trunk height, pitch and roll,
//! the first leg's length, the ground force in body weights, the state
//! machine's state (Figure 4), forward speed; and the trunk drawn as a capsule.

use glam::DVec3;

use crate::world::sim::Sim;

/// What the live plots show each frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PhysicsProbe {
    /// Trunk height above the ground (m).
    pub height_m: f64,
    /// Trunk pitch (deg, positive nose down).
    pub pitch_deg: f64,
    /// Trunk roll (deg).
    pub roll_deg: f64,
    /// First leg's hip-to-foot length (m).
    pub leg_length_m: f64,
    /// Total vertical ground force over body weight.
    pub ground_force_bw: f64,
    /// The state machine's state as its Figure-4 index (0 flight … 4 unloading).
    pub phase_index: usize,
    /// Forward speed of the centre of mass (m/s).
    pub speed_mps: f64,
}

/// The trunk of a free-floating creature as a capsule `(a, b, radius)` in
/// the world: along the long axis of the uniform box with the trunk's mass
/// and principal moments. `None` for a planar model (its trunk is a link).
#[must_use]
pub fn trunk_capsule(sim: &Sim) -> Option<(DVec3, DVec3, f64)> {
    let model = &sim.creature.model;
    let body = model
        .bodies()
        .first()
        .filter(|b| model.free_base() && b.mass > 0.0)?;
    let i = body.inertia_com;
    let (ix, iy, iz) = (i.x_axis.x, i.y_axis.y, i.z_axis.z);
    let half = |a: f64, b: f64, c: f64| (6.0 * (b + c - a) / body.mass).max(0.0).sqrt() / 2.0;
    let h = DVec3::new(half(ix, iy, iz), half(iy, ix, iz), half(iz, ix, iy));
    let (axis, long, radius) = if h.x >= h.y && h.x >= h.z {
        (DVec3::X, h.x, (h.y + h.z) / 2.0)
    } else if h.y >= h.z {
        (DVec3::Y, h.y, (h.x + h.z) / 2.0)
    } else {
        (DVec3::Z, h.z, (h.x + h.y) / 2.0)
    };
    let w = sim.data.world[0];
    let centre = w.rot * body.com + w.pos;
    let reach = w.rot * axis * (long - radius).max(0.0);
    Some((centre - reach, centre + reach, radius))
}

/// The Figure-4 index of the state named `phase_name` (0 flight … 4
/// unloading), 0 for a state outside Figure 4.
#[must_use]
pub fn phase_index(phase_name: &str) -> usize {
    crate::control::Phase::ALL
        .iter()
        .position(|p| p.name() == phase_name)
        .unwrap_or(0)
}

/// A snapshot of the trunk, first leg, ground force and the state machine's
/// state (`phase_name`, Figure 4) for plots.
#[must_use]
pub fn probe(sim: &Sim, phase_name: &str) -> PhysicsProbe {
    let c = &sim.creature;
    let d = &sim.data;
    let err = crate::control::laws::attitude::attitude_error(c, d, 0.0, 0.0);
    let trunk = d.world[c.trunk];
    let leg_length_m = c.legs.first().map_or(0.0, |leg| {
        let hip = trunk.rot * leg.hip_in_trunk + trunk.pos;
        (d.point_world(leg.foot_body, leg.foot_point) - hip).length()
    });
    let weight = c.model.total_mass() * crate::dynamics::model::GRAVITY_MPS2;
    let force: f64 = sim.contacts.iter().map(|k| k.force.y).sum();
    let name = phase_name;
    PhysicsProbe {
        height_m: trunk.pos.y,
        pitch_deg: err.x.to_degrees(),
        roll_deg: err.z.to_degrees(),
        leg_length_m,
        ground_force_bw: force / weight,
        phase_index: phase_index(name),
        speed_mps: crate::control::laws::attitude::com_velocity(c, d).z,
    }
}
