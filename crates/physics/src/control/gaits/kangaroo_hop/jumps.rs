//! The boxes the kangaroo is still to jump, nearest first (Raibert &
//! Hodgins 1991, Figure 2: the animator's "event information, such as when
//! and how high to jump", given once per obstacle). The jump's states
//! (stride.rs) work on one box at a time, the one in `jump_at_m`,
//! `obstacle_depth_m` and `obstacle_height_m` of the parameters; the others
//! wait here and the nearest one ahead becomes the next once a jump has
//! landed. Positions are metres at scale 1, as `scenario.physics.obstacles`
//! gives them; the world's are × L.

use super::{JumpStage, KangarooHop};

/// A box still to jump (m at scale 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QueuedJump {
    /// Its near face along the way.
    pub at_m: f64,
    /// Its depth along the way.
    pub depth_m: f64,
    /// Its height.
    pub height_m: f64,
}

impl KangarooHop {
    /// Ask for a jump over a box whose near face is at `at_m` (m at scale
    /// 1), `depth_m` deep and `height_m` high. With no jump under way it is
    /// the next; otherwise it waits its turn (nearest first), so boxes
    /// placed one after another are each jumped.
    pub fn jump_over(&mut self, jump: QueuedJump) {
        let busy = self.jump_under_way();
        let current = self.params.jump_at_m.map(|at_m| QueuedJump {
            at_m,
            depth_m: self.params.obstacle_depth_m,
            height_m: self.params.obstacle_height_m,
        });
        match current {
            // A box nearer than the one pending goes first.
            Some(c) if self.jump_pending && jump.at_m < c.at_m => {
                self.make_next(jump);
                self.queue(c);
            }
            _ if busy => self.queue(jump),
            _ => self.make_next(jump),
        }
    }

    /// The boxes waiting after the one under way, nearest first.
    #[must_use]
    pub fn queued_jumps(&self) -> &[QueuedJump] {
        &self.queued
    }

    /// A jump pending, or its take-off or flight under way.
    fn jump_under_way(&self) -> bool {
        self.jump_pending || matches!(self.jump, JumpStage::Takeoff | JumpStage::Airborne)
    }

    fn queue(&mut self, jump: QueuedJump) {
        let at = self.queued.partition_point(|q| q.at_m <= jump.at_m);
        self.queued.insert(at, jump);
    }

    fn make_next(&mut self, jump: QueuedJump) {
        self.params.jump_at_m = Some(jump.at_m);
        self.params.obstacle_depth_m = jump.depth_m;
        self.params.obstacle_height_m = jump.height_m;
        self.jump_pending = true;
    }

    /// At a touchdown `toe_z` (world m) with no jump pending or in the
    /// air: the nearest waiting box whose near face is still ahead becomes
    /// the next; boxes already reached are dropped.
    pub(super) fn next_jump(&mut self, toe_z: f64, l: f64) {
        if self.jump_under_way() {
            return;
        }
        let passed = self.queued.partition_point(|q| q.at_m * l <= toe_z);
        self.queued.drain(..passed);
        if !self.queued.is_empty() {
            let next = self.queued.remove(0);
            self.make_next(next);
        }
    }

    /// Forget every box still to jump (the copy that settles the start).
    pub(super) fn clear_jumps(&mut self) {
        self.queued.clear();
        self.params.jump_at_m = None;
        self.jump_pending = false;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::gaits::kangaroo_hop::KangarooHopParams;

    fn jump(at_m: f64) -> QueuedJump {
        QueuedJump {
            at_m,
            depth_m: 0.3,
            height_m: 0.2,
        }
    }

    #[test]
    fn boxes_are_jumped_nearest_first_and_those_reached_are_dropped() {
        let mut k = KangarooHop::new(KangarooHopParams::default());
        k.jump_over(jump(9.0));
        assert_eq!(k.params.jump_at_m, Some(9.0));
        // A farther box waits; a nearer one goes first.
        k.jump_over(jump(15.0));
        k.jump_over(jump(6.0));
        assert_eq!(k.params.jump_at_m, Some(6.0));
        let waiting: Vec<f64> = k.queued_jumps().iter().map(|q| q.at_m).collect();
        assert_eq!(waiting, [9.0, 15.0]);
        // While one is pending, nothing moves up.
        k.next_jump(7.0, 1.0);
        assert_eq!(k.params.jump_at_m, Some(6.0));
        // Once it is done, the nearest box still ahead is next (at L = 2
        // the box at 9 m of scale 1 sits at 18 m: ahead of a toe at 17 m).
        k.jump_pending = false;
        k.next_jump(17.0, 2.0);
        assert_eq!(k.params.jump_at_m, Some(9.0));
        k.jump_pending = false;
        // The box at 15 m (30 m in the world) was reached without a jump: dropped.
        k.next_jump(31.0, 2.0);
        assert!(!k.jump_pending);
        assert!(k.queued_jumps().is_empty());
    }
}
