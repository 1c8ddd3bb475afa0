//! The mutable state of a simulated [`Model`]: coordinates, velocities,
//! applied forces, and every stage's workspace (allocated once, so stepping
//! allocates nothing).

use glam::{DQuat, DVec3};

use crate::dynamics::model::Model;
use crate::dynamics::spatial::{Force, Inertia, Motion, ParentLink};

/// State and workspace for one model.
#[derive(Clone, Debug)]
pub struct Data {
    /// Free base: origin of body 0 in the world (m).
    pub base_position: DVec3,
    /// Free base: orientation of body 0 in the world.
    pub base_orientation: DQuat,
    /// Free base: spatial velocity of body 0 in its own coordinates.
    pub base_velocity: Motion,
    /// Free base: spatial acceleration of body 0 in its own coordinates
    /// (written by the dynamics; its time derivative of `base_velocity`).
    pub base_acceleration: Motion,
    /// Joint coordinates (rad or m), one per single-DOF joint.
    pub q: Vec<f64>,
    /// Joint velocities (rad/s or m/s).
    pub qd: Vec<f64>,
    /// Joint accelerations (written by the dynamics).
    pub qdd: Vec<f64>,
    /// Joint torques or forces applied by actuators (N·m or N).
    pub tau: Vec<f64>,
    /// External forces on each body (contacts), body coordinates; gravity is
    /// added by the dynamics.
    pub external: Vec<Force>,
    /// Each body's frame in its parent's (joint included). Written by kinematics.
    pub link: Vec<ParentLink>,
    /// Each body's frame in the world. Written by kinematics.
    pub world: Vec<ParentLink>,
    /// Each body's spatial velocity, body coordinates. Written by kinematics.
    pub velocity: Vec<Motion>,
    /// Each body's spatial acceleration, body coordinates. Written by the dynamics.
    pub acceleration: Vec<Motion>,
    pub(crate) velocity_product: Vec<Motion>,
    pub(crate) art_inertia: Vec<Inertia>,
    pub(crate) art_bias: Vec<Force>,
    pub(crate) u_force: Vec<Force>,
    pub(crate) d: Vec<f64>,
    pub(crate) u: Vec<f64>,
}

impl Data {
    /// Zero state for `model`: base at the origin, joints at zero.
    #[must_use]
    pub fn new(model: &Model) -> Self {
        let n = model.bodies().len();
        let nj = model.joint_count();
        Self {
            base_position: DVec3::ZERO,
            base_orientation: DQuat::IDENTITY,
            base_velocity: Motion::ZERO,
            base_acceleration: Motion::ZERO,
            q: vec![0.0; nj],
            qd: vec![0.0; nj],
            qdd: vec![0.0; nj],
            tau: vec![0.0; nj],
            external: vec![Force::ZERO; n],
            link: vec![ParentLink::default(); n],
            world: vec![ParentLink::default(); n],
            velocity: vec![Motion::ZERO; n],
            acceleration: vec![Motion::ZERO; n],
            velocity_product: vec![Motion::ZERO; n],
            art_inertia: vec![Inertia::ZERO; n],
            art_bias: vec![Force::ZERO; n],
            u_force: vec![Force::ZERO; n],
            d: vec![0.0; n],
            u: vec![0.0; n],
        }
    }

    /// Whether every coordinate and velocity is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.base_position.is_finite()
            && self.base_orientation.is_finite()
            && self.base_velocity.is_finite()
            && self.q.iter().chain(&self.qd).all(|x| x.is_finite())
    }

    /// World position of a point given in body coordinates (kinematics must have run).
    #[must_use]
    pub fn point_world(&self, body: usize, local: DVec3) -> DVec3 {
        let w = &self.world[body];
        w.rot * local + w.pos
    }

    /// World velocity of a point given in body coordinates (kinematics must have run).
    #[must_use]
    pub fn point_velocity_world(&self, body: usize, local: DVec3) -> DVec3 {
        let v = self.velocity[body];
        self.world[body].rot * (v.linear + v.angular.cross(local))
    }

    /// Add a world-frame force `force` (N) acting at world point `at` (m) to
    /// `body`'s external force (kinematics must have run).
    pub fn apply_world_force(&mut self, body: usize, at: DVec3, force: DVec3) {
        let w = self.world[body];
        let rt = w.rot.transpose();
        self.external[body] += Force::at_point(rt * (at - w.pos), rt * force);
    }

    /// Add a world-frame torque (N·m) to `body`'s external force.
    pub fn apply_world_torque(&mut self, body: usize, torque: DVec3) {
        let rt = self.world[body].rot.transpose();
        self.external[body] += Force::new(rt * torque, DVec3::ZERO);
    }
}
