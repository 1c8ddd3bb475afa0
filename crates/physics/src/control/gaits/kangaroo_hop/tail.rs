//! The kangaroo's tail and head (Raibert & Hodgins 1991, "Kangaroo
//! control"): the tail-base spring's rest steps down in stance and up in
//! flight, its stiffness tuned so the tail counter-oscillates with the leg;
//! the distal tail joints are spring-dampers at a fixed rest; the neck keeps
//! the head level.

use super::KangarooHop;
use crate::control::laws::scale::Scale;
use crate::creatures::PhysicalCreature;
use crate::world::sim::Drive;

impl KangarooHop {
    /// Drive the tail and the neck for a trunk at `pitch` (rad) turning at
    /// `pitch_rate` (rad/s), in stance or in flight.
    pub(super) fn tail_and_neck(
        &self,
        creature: &PhysicalCreature,
        pitch: f64,
        pitch_rate: f64,
        stance: bool,
        drives: &mut [Drive],
    ) {
        let p = &self.params;
        let l = creature.scale;
        let s = Scale::new(l);
        let (t4, t45) = (s.torsional_stiffness(), s.torsional_damping());
        // Tail: a step of the base spring's rest, down in stance, up in flight.
        let mut tail = creature.tail.iter().copied();
        if let Some(base) = tail.next() {
            let step = if stance {
                p.tail_mean_rad - 0.5 * p.tail_step_rad
            } else {
                p.tail_mean_rad + 0.5 * p.tail_step_rad
            };
            // The lab's tail feedback: the rest also follows the trunk's
            // pitch error and rate (the paper only steps it).
            let assist = if p.tail_feedback {
                p.tail_pitch_gain * (pitch - p.pitch_rad)
                    + p.tail_rate_gain_s * Scale::new(l).time() * pitch_rate
            } else {
                0.0
            };
            let rest = step + assist.clamp(-1.0, 1.0);
            drives[base].servo(p.tail_stiffness * t4, p.tail_damping * t45, rest);
        }
        for j in tail {
            drives[j].servo(p.tail_tip_stiffness * t4, p.tail_tip_damping * t45, 0.0);
        }
        // Head level.
        if let Some(neck) = creature.neck {
            drives[neck].servo(p.neck_kp * t4, p.neck_kv * t45, -pitch);
        }
    }
}
