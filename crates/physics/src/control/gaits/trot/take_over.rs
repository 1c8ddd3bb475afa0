//! The trot taking over from another gait at the next flight (Raibert &
//! Hodgins 1991, "Gaits": the quadruped changes gait), and what it hands a
//! gait taking over from it. The new controller starts from the state it
//! finds — the hip servos at the hips' angles, eq. 3's T_s the support the
//! running gait measured last, the pair nearer level landing first — in a
//! flight long enough for its landing pair to lengthen. The pace, the same
//! state machine on the lateral pairs, takes over the same way.

use crate::control::gaits::gait::{Gait, Handover};
use crate::control::gaits::origins::ControllerParam;
use crate::control::gaits::trot::QuadrupedRun;
use crate::control::gaits::trot::origins::ORIGINS;
use crate::control::laws::placement::time_to_fall;
use crate::world::sim::ControlInput;

/// How long (s at scale 1) before its first hip falls to landing height the
/// trot can still take over a flight: about the time its landing pair needs
/// to lengthen from short to its landing rest. The lab's reading of the
/// paper's "next flight", which names the take-over but not its timing (in
/// the bound's short extended flight the trot cannot land both legs of a
/// pair; in the gathered flight it can).
pub const TAKE_OVER_LEAD_S: f64 = 0.08;

impl Gait for QuadrupedRun {
    fn origins(&self) -> &'static [ControllerParam] {
        ORIGINS
    }

    /// The support period of the pair that lifted off last.
    fn handover(&self) -> Handover {
        Handover {
            stance_s: Some(self.stance_s[1 - self.active]),
        }
    }

    /// No hip falls to its landing height within [`TAKE_OVER_LEAD_S`] (×√L).
    fn can_take_over(&self, input: &ControlInput<'_>) -> bool {
        let landing = self.tuning().landing_rest_m * self.plan.scale.length();
        let lead = TAKE_OVER_LEAD_S * self.plan.scale.time();
        let trunk = input.creature.trunk;
        input
            .creature
            .legs
            .iter()
            .take(4)
            .enumerate()
            .all(|(i, leg)| {
                let hip = input.data.point_world(trunk, leg.hip_in_trunk).y;
                let vy = input.data.point_velocity_world(trunk, leg.hip_in_trunk).y;
                time_to_fall(hip, vy, self.plan.leg_m[i] + landing) >= lead
            })
    }

    /// The hip servos start from the hips' angles (from zero their targets
    /// would read as a jump, and the servo's rate term kick the legs), eq.
    /// 3's T_s from the support the running gait measured last, and the pair
    /// whose hips are nearer level lands first, so its feet strike in unison.
    fn take_over_from(&mut self, input: &ControlInput<'_>, found: &Handover) {
        let trunk = input.creature.trunk;
        for (i, leg) in input.creature.legs.iter().enumerate().take(4) {
            self.hip_target[i] = [input.data.q[leg.hip[0]], input.data.q[leg.hip[1]]];
        }
        if let Some(t) = found.stance_s {
            self.stance_s = [t; 2];
        }
        let hip_y = |i: usize| {
            let at = input.creature.legs[i].hip_in_trunk;
            input.data.point_world(trunk, at).y
        };
        let tilt = |p: usize| (hip_y(self.pairs[p][0]) - hip_y(self.pairs[p][1])).abs();
        self.active = usize::from(tilt(1) < tilt(0));
    }
}
