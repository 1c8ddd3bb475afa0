//! The lab's `ground_ahead` (issue 45 item 3; not in Raibert & Hodgins
//! 1991, whose laws are written for a level floor): eq. 2's apex target
//! measured from the ground plane the controller is handed
//! ([`GroundView`]), so a hop up a slope rises as far above the ground
//! ahead as it would above the floor. Off, the target is the paper's: the
//! hop height above the last lift-off.
//!
//! The gaits' other uses of the ground plane under this addition (eq. 3's
//! touchdown point, the trot's pair landing together and its trunk pitched
//! with the slope) sit where those laws are applied, each behind the same
//! switch.

use glam::DVec3;

use crate::dynamics::model::GRAVITY_MPS2;
use crate::world::ground_view::GroundView;

/// Where the centre of mass took off: its height and the ground plane's
/// height under it then (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Liftoff {
    /// The centre of mass's height at lift-off (m).
    pub com_y: f64,
    /// The ground's height under it then (m; 0 on the floor).
    pub ground_y: f64,
}

impl Liftoff {
    /// Not yet measured.
    pub const UNKNOWN: Self = Self {
        com_y: f64::NAN,
        ground_y: 0.0,
    };

    /// The lift-off of a centre of mass at `com` over `ground`.
    #[must_use]
    pub fn at(com: DVec3, ground: &GroundView) -> Self {
        Self {
            com_y: com.y,
            ground_y: ground.height_at(com.x, com.z),
        }
    }
}

/// Eq. 2's apex target (m, world height): the paper's `liftoff.com_y +
/// rise_m` when `on` is false; on, the same height above the ground plane
/// under the next apex — the centre of mass at `com` moving at `v` (m/s)
/// reaches it `stance_left_s` (s) of stance plus the rise under gravity
/// from now.
#[must_use]
pub fn apex_target_m(
    on: bool,
    ground: &GroundView,
    liftoff: Liftoff,
    (com, v): (DVec3, DVec3),
    stance_left_s: f64,
    rise_m: f64,
) -> f64 {
    if !on {
        return liftoff.com_y + rise_m;
    }
    let rising_s = (2.0 * rise_m.max(0.0) / GRAVITY_MPS2).sqrt();
    let apex = com + DVec3::new(v.x, 0.0, v.z) * (stance_left_s.max(0.0) + rising_s);
    let ground_rise = ground.height_at(apex.x, apex.z) - liftoff.ground_y;
    liftoff.com_y + rise_m + ground_rise
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::{Liftoff, apex_target_m};
    use crate::world::ground_view::GroundView;

    #[test]
    fn off_it_is_the_papers_target_and_on_it_climbs_with_the_ground() {
        // A 10 % grade along +z; lift-off at z = 0, now at z = 0.5 moving
        // 2 m/s, 0.05 s of stance left, a 0.1 m rise (0.143 s rising).
        let ground = GroundView {
            grade_z: 0.1,
            ..GroundView::FLAT
        };
        let liftoff = Liftoff::at(DVec3::new(0.0, 0.7, 0.0), &ground);
        let now = (DVec3::new(0.0, 0.66, 0.5), DVec3::new(0.0, 0.0, 2.0));
        let paper = apex_target_m(false, &ground, liftoff, now, 0.05, 0.1);
        assert!((paper - 0.8).abs() < 1e-12, "{paper}");
        let on = apex_target_m(true, &ground, liftoff, now, 0.05, 0.1);
        let ahead = 0.5 + 2.0 * (0.05 + (0.2 / 9.81_f64).sqrt());
        assert!((on - (0.8 + 0.1 * ahead)).abs() < 1e-3, "{on}");
        // On the floor the addition changes nothing.
        let flat = GroundView::FLAT;
        let floor = Liftoff::at(DVec3::new(0.0, 0.7, 0.0), &flat);
        let paper = apex_target_m(false, &flat, floor, now, 0.05, 0.1);
        assert_eq!(apex_target_m(true, &flat, floor, now, 0.05, 0.1), paper);
    }
}
