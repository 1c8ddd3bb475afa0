//! The bound or the gallop taking over from another gait at the next
//! flight (Raibert & Hodgins 1991, "Gaits": the quadruped changes gait), and
//! what it hands a gait taking over from it. The new controller starts from
//! the state it finds: the hip servos at the hips' angles, eq. 3's T_s the
//! support the running gait measured last, and the pair whose hips will
//! fall to landing height first armed to land (its own start arms the rear).
//! The bound and the gallop change into each other this way too, each
//! style's controller with its own gains.

use crate::control::gaits::bound::origins::ORIGINS;
use crate::control::gaits::bound::{FRONT, PAIRS, QuadrupedBound, REAR};
use crate::control::gaits::gait::{Gait, Handover};
use crate::control::gaits::origins::ControllerParam;
use crate::control::laws::placement::time_to_fall;
use crate::world::sim::ControlInput;

impl Gait for QuadrupedBound {
    fn origins(&self) -> &'static [ControllerParam] {
        ORIGINS
    }

    /// The support period of the pair that lifted off last.
    fn handover(&self) -> Handover {
        let last = if self.pairs[FRONT].liftoff_s >= self.pairs[REAR].liftoff_s {
            FRONT
        } else {
            REAR
        };
        Handover {
            stance_s: Some(self.pairs[last].stance_s),
        }
    }

    /// The hip servos start from the hips' angles, eq. 3's T_s from the
    /// support the running gait measured last, and the pair whose hips,
    /// moving as they move now, fall to landing height first is the one
    /// armed to lengthen for it.
    fn take_over_from(&mut self, input: &ControlInput<'_>, found: &Handover) {
        for (i, leg) in input.creature.legs.iter().enumerate().take(4) {
            self.hip_target[i] = [input.data.q[leg.hip[0]], input.data.q[leg.hip[1]]];
        }
        if let Some(t) = found.stance_s {
            for pair in &mut self.pairs {
                pair.stance_s = t;
            }
        }
        let trunk = input.creature.trunk;
        let landing = self.params.landing_rest_m * self.plan.scale.length();
        let lands_in = |k: usize| {
            PAIRS[k]
                .iter()
                .map(|&i| {
                    let at = input.creature.legs[i].hip_in_trunk;
                    let hip = input.data.point_world(trunk, at).y;
                    let vy = input.data.point_velocity_world(trunk, at).y;
                    time_to_fall(hip, vy, self.plan.leg_m[i] + landing)
                })
                .fold(f64::INFINITY, f64::min)
        };
        let first = if lands_in(FRONT) < lands_in(REAR) {
            FRONT
        } else {
            REAR
        };
        self.pairs[first].armed = true;
        self.pairs[1 - first].armed = false;
    }
}
