//! Whole-system energy and momentum: what the dynamics tests check, and what
//! the blow-up guard watches for runaway energy.
//!
//! All functions read the kinematics (`world`, `velocity`); run
//! [`kinematics`](crate::dynamics::kinematics::kinematics) first.

use glam::DVec3;

use crate::dynamics::data::Data;
use crate::dynamics::model::Model;

/// Kinetic energy Σ ½ vᵀ I v (J).
#[must_use]
pub fn kinetic_energy(model: &Model, data: &Data) -> f64 {
    model
        .bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let v = data.velocity[i];
            0.5 * v.dot(b.spatial_inertia().mul(v))
        })
        .sum()
}

/// Gravitational potential energy −Σ m g·c relative to the world origin (J).
#[must_use]
pub fn potential_energy(model: &Model, data: &Data) -> f64 {
    model
        .bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| -b.mass * model.gravity.dot(data.point_world(i, b.com)))
        .sum()
}

/// Centre of mass of the whole system in the world (m).
#[must_use]
pub fn center_of_mass(model: &Model, data: &Data) -> DVec3 {
    let total = model.total_mass();
    let sum: DVec3 = model
        .bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| data.point_world(i, b.com) * b.mass)
        .sum();
    sum / total
}

/// Linear momentum (kg·m/s) and angular momentum about the world origin
/// (kg·m²/s), both in world coordinates.
#[must_use]
pub fn momentum(model: &Model, data: &Data) -> (DVec3, DVec3) {
    let mut linear = DVec3::ZERO;
    let mut angular = DVec3::ZERO;
    for (i, b) in model.bodies().iter().enumerate() {
        let h = b.spatial_inertia().mul(data.velocity[i]);
        let w = data.world[i];
        let p = w.rot * h.force;
        linear += p;
        angular += w.rot * h.moment + w.pos.cross(p);
    }
    (linear, angular)
}
