//! The kangaroo's controller for a start on its hopping cycle
//! (`scenario.physics.start: "on_cycle"`, docs/physics.md "The start on the
//! cycle"): the copy that brings the hop up to speed before t = 0, and the
//! hand-over of what that copy learned to the controller the run starts
//! with. The paper leaves the start to the animator (Figure 2's text).

use glam::DVec3;

use super::{JumpStage, KangarooHop};

impl KangarooHop {
    /// A copy of this controller for bringing the hop up to speed out of
    /// sight: the lab's speed ramp on (from the start at no more than
    /// [`crate::control::gaits::kangaroo_hop::start::KANGAROO_START_MPS`]), no jump.
    #[must_use]
    pub fn for_settling(&self) -> Self {
        let mut params = self.params;
        params.speed_ramp = true;
        let mut copy = Self::new(params);
        copy.clear_jumps();
        copy
    }

    /// Continue from `settled`'s state of the hop cycle, with this
    /// controller's parameters and jump: its measured stance time, thrust
    /// rest angle, learned apex correction, commanded speed, phase and
    /// stride marks, moved to a clock `elapsed_s` (s) later and a world
    /// moved back by `advanced_m` (m) along +z.
    pub fn resume_from(&mut self, settled: &Self, elapsed_s: f64, advanced_m: f64) {
        let moved = DVec3::new(0.0, 0.0, advanced_m);
        self.phase = settled.phase;
        self.jump = JumpStage::None;
        self.stance_s = settled.stance_s;
        self.ankle_rest = settled.ankle_rest;
        self.apex_correction_m = settled.apex_correction_m;
        self.speed_command_mps = settled.speed_command_mps;
        self.trim = settled.trim;
        self.trim.move_origin(elapsed_s, moved);
        self.started = settled.started;
        self.touchdown_time = settled.touchdown_time - elapsed_s;
        // 0 marks "no touchdown yet" (stride.rs).
        self.touchdown_toe = if settled.touchdown_toe == 0.0 {
            0.0
        } else {
            settled.touchdown_toe - advanced_m
        };
        self.liftoff_com_y = settled.liftoff_com_y;
        self.liftoff_ground_y = settled.liftoff_ground_y;
        self.apex_com_y = settled.apex_com_y;
        self.target_apex_y = settled.target_apex_y;
        self.flight_start = settled.flight_start - elapsed_s;
        self.stride_m = settled.stride_m;
        self.knee_servo = settled.knee_servo;
    }
}
