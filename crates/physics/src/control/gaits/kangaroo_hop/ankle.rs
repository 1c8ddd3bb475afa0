//! The kangaroo's ankle: the leg spring of eq. 1 (Raibert & Hodgins 1991,
//! "Kangaroo control": "the ankle is the leg's energy store"), a torsional
//! spring-damper whose rest angle eq. 2's thrust steps; stiffer for a jump's
//! take-off, more damped on its landing.

use super::{JumpStage, KangarooHop};
use crate::control::laws::phase::Phase;
use crate::control::laws::scale::Scale;
use crate::world::actuator::Stops;
use crate::world::sim::Drive;

impl KangarooHop {
    /// The ankle spring's stiffness (N·m/rad) and damping (N·m·s/rad) at scale `l`.
    pub(super) fn ankle_gains(&self, l: f64) -> (f64, f64) {
        let p = &self.params;
        let (mut k, mut b) = Scale::new(l).torsional_gains(p.ankle_stiffness, p.ankle_damping);
        match self.jump {
            JumpStage::Takeoff => k *= p.jump_stiffness_factor,
            JumpStage::Landing if self.phase != Phase::Flight => b *= p.landing_damping_factor,
            _ => {}
        }
        (k, b)
    }

    /// Set the ankle's drive `d` to the spring of eq. 1 at the current rest,
    /// with stops 1.3 rad below and 1.2 rad above the standing rest.
    pub(super) fn drive_ankle(&self, d: &mut Drive, l: f64) {
        let p = &self.params;
        let (ak, ab) = self.ankle_gains(l);
        d.spring.stiffness = ak;
        d.spring.damping = ab;
        d.spring.rest = self.ankle_rest;
        d.spring.max_force = f64::INFINITY;
        d.feedforward = 0.0;
        d.stops = Some(Stops {
            min: p.ankle_rest_rad - 1.3,
            max: p.ankle_rest_rad + 1.2,
            stiffness: 50.0 * ak,
            damping: 20.0 * ab,
        });
    }
}
