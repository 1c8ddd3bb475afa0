//! Foot placement for speed control (Raibert & Hodgins 1991, eq. 3):
//! `x_fh,d = ẋ·T_s/2 + k_ẋ·(ẋ − ẋ_d)` — the neutral point plus a correction
//! for the speed error — and the hip angles that point a leg at that foot
//! position.

use gaitlab_core::portable::Portable;
use glam::{DMat3, DVec3};

use crate::world::ground_view::GroundView;

/// Eq. 3 on the ground plane: the desired foot displacement from the
/// projection of the centre of mass (world, m, y = 0) for horizontal velocity
/// `velocity`, desired velocity `desired`, predicted stance time `stance_s`
/// and gain `gain_s` (s).
#[must_use]
pub fn foot_displacement(velocity: DVec3, desired: DVec3, stance_s: f64, gain_s: f64) -> DVec3 {
    let v = DVec3::new(velocity.x, 0.0, velocity.z);
    let vd = DVec3::new(desired.x, 0.0, desired.z);
    v * (stance_s / 2.0) + (v - vd) * gain_s
}

/// The gimbal angles `(roll, pitch)` (rad) that point a leg hanging along
/// the hip's −y at `direction` (trunk coordinates): the roll joint turns
/// about the trunk's z, the pitch joint then about x.
#[must_use]
pub fn gimbal_angles(direction: DVec3) -> (f64, f64) {
    let u = direction.normalize_or(DVec3::NEG_Y);
    let pitch = (-u.z).clamp(-1.0, 1.0).pasin();
    let roll = u.x.patan2(-u.y);
    (roll, pitch)
}

/// The leg direction (trunk coordinates) that puts a foot `reach` metres from
/// the hip at the horizontal world displacement `offset` from the hip.
#[must_use]
pub fn leg_direction(trunk_rot: DMat3, offset: DVec3, reach: f64) -> DVec3 {
    let horizontal = DVec3::new(offset.x, 0.0, offset.z);
    let h = horizontal.length().min(0.95 * reach);
    let horizontal = horizontal.normalize_or_zero() * h;
    let world = DVec3::new(horizontal.x, -(reach * reach - h * h).sqrt(), horizontal.z);
    trunk_rot.transpose() * world
}

/// The frame a positioning leg is aimed in: the trunk's rotation `trunk_rot`
/// (columns: side, up, forward) with the share `roll_follow` (0–1) of its
/// roll about its forward axis kept. At 1 (or above) it is `trunk_rot`
/// itself, to the bit: the leg is aimed at its ground point through the
/// trunk's measured attitude. At 0 the trunk's roll is left out, and the
/// leg is aimed in the trunk's sagittal plane. With every foot off the
/// ground a leg held at a world angle sends the body's roll momentum into
/// the trunk alone; one held in the trunk's frame rolls with the trunk.
/// The paper says only that "a kinematic transformation determines the
/// joint angles" (docs/physics.md, "Aiming the legs through the trunk's
/// roll"); the bound's and the trot's `swing_roll_follow` choose the share.
#[must_use]
pub fn aim_frame(trunk_rot: DMat3, roll_follow: f64) -> DMat3 {
    if roll_follow >= 1.0 {
        return trunk_rot;
    }
    let forward = trunk_rot.z_axis;
    let side = DVec3::Y.cross(forward).normalize_or(trunk_rot.x_axis);
    let up = forward.cross(side);
    let level = DMat3::from_cols(side, up, forward);
    // Not above 1 here; NaN or below 0 reads as 0.
    let share = if roll_follow > 0.0 { roll_follow } else { 0.0 };
    if share == 0.0 {
        return level;
    }
    let roll = trunk_rot.x_axis.dot(up).patan2(trunk_rot.x_axis.dot(side));
    let (sin, cos) = (share * roll).psin_cos();
    level
        * DMat3::from_cols(
            DVec3::new(cos, sin, 0.0),
            DVec3::new(-sin, cos, 0.0),
            DVec3::Z,
        )
}

/// The hip's gimbal angles `[roll, pitch]` (rad) that aim a leg of length
/// `reach` (m) from the hip at `hip_world` toward the ground point `foot`
/// (world): eq. 3's foot place as hip targets.
#[must_use]
pub fn hip_angles(trunk_rot: DMat3, hip_world: DVec3, foot: DVec3, reach: f64) -> [f64; 2] {
    let (roll, pitch) = gimbal_angles(leg_direction(trunk_rot, foot - hip_world, reach));
    [roll, pitch]
}

/// Where on the ground (world, y = 0) the hip will be at touchdown, looking
/// at most `lookahead_s` ahead: the hip at `hip_world` moving at `hip_v`,
/// falling under gravity until a leg of length `reach` pointed `displacement`
/// ahead of it reaches the ground. Eq. 3's foot position is taken about this
/// point, so the target stays put on the ground while the body travels and
/// the leg sweeps back before landing (ground speed matching).
#[must_use]
pub fn hip_at_touchdown(
    hip_world: DVec3,
    hip_v: DVec3,
    reach: f64,
    displacement: DVec3,
    lookahead_s: f64,
) -> DVec3 {
    let drop = hip_world.y
        - (reach * reach - displacement.length_squared())
            .max(0.0)
            .sqrt();
    let t_rem = if drop > 0.0 {
        fall_time_s(drop, hip_v.y)
    } else {
        0.0
    }
    .min(lookahead_s);
    let ahead = DVec3::new(hip_v.x, 0.0, hip_v.z) * t_rem;
    DVec3::new(hip_world.x, 0.0, hip_world.z) + ahead
}

/// [`hip_at_touchdown`] over the ground plane `ground` instead of the floor
/// (the lab's `ground_ahead`, issue 45): the hip's fall is measured to the
/// ground's height where the foot will land (found by two passes), and the
/// point returned lies on that ground. On [`GroundView::FLAT`] it is
/// [`hip_at_touchdown`] to the bit.
#[must_use]
pub fn hip_at_touchdown_over(
    ground: &GroundView,
    hip_world: DVec3,
    hip_v: DVec3,
    reach: f64,
    displacement: DVec3,
    lookahead_s: f64,
) -> DVec3 {
    let land = |at: DVec3| ground.height_at(at.x + displacement.x, at.z + displacement.z);
    let mut ground_y = land(hip_world);
    for _ in 0..2 {
        let at = hip_at_touchdown(
            hip_world - DVec3::Y * ground_y,
            hip_v,
            reach,
            displacement,
            lookahead_s,
        );
        ground_y = land(at);
    }
    let lifted = hip_world - DVec3::Y * ground_y;
    hip_at_touchdown(lifted, hip_v, reach, displacement, lookahead_s) + DVec3::Y * ground_y
}

/// How long a point moving up at `vy_mps` takes to fall `drop_m` (m,
/// ≥ 0) below where it is, under gravity alone (s): the flight ahead.
#[must_use]
pub fn fall_time_s(drop_m: f64, vy_mps: f64) -> f64 {
    let g = crate::dynamics::model::GRAVITY_MPS2;
    (vy_mps + (vy_mps * vy_mps + 2.0 * g * drop_m).sqrt()) / g
}

/// How long a point `height_m` above the ground, moving up at `vy_mps`,
/// takes to fall to `land_m` (s; 0 once it is there or below, falling).
#[must_use]
pub fn time_to_fall(height_m: f64, vy_mps: f64, land_m: f64) -> f64 {
    fall_time_s((height_m - land_m).max(0.0), vy_mps).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    #[test]
    fn gimbal_angles_reproduce_the_direction() {
        for dir in [
            DVec3::new(0.2, -0.9, 0.3),
            DVec3::new(-0.1, -1.0, -0.4),
            DVec3::NEG_Y,
        ] {
            let (roll, pitch) = gimbal_angles(dir);
            let back = DQuat::from_rotation_z(roll) * DQuat::from_rotation_x(pitch) * DVec3::NEG_Y;
            assert!((back - dir.normalize()).length() < 1e-12, "{dir} → {back}");
        }
    }

    #[test]
    fn the_hip_at_touchdown_is_where_it_falls_to_leg_length() {
        // A hip 1.0 m up, level, moving 2 m/s forward, over a 0.8 m leg
        // pointed straight down: it falls 0.2 m in √(2·0.2/g) s.
        let g = crate::dynamics::model::GRAVITY_MPS2;
        let hip = DVec3::new(0.0, 1.0, 0.0);
        let v = DVec3::new(0.0, 0.0, 2.0);
        let at = hip_at_touchdown(hip, v, 0.8, DVec3::ZERO, 1.0);
        let t = (2.0 * 0.2 / g).sqrt();
        assert!((at - DVec3::new(0.0, 0.0, 2.0 * t)).length() < 1e-12);
        // The look-ahead caps it; a hip already low looks nowhere ahead.
        assert!((hip_at_touchdown(hip, v, 0.8, DVec3::ZERO, 0.05).z - 0.1).abs() < 1e-12);
        assert_eq!(hip_at_touchdown(hip, v, 1.2, DVec3::ZERO, 1.0), DVec3::ZERO);
    }

    /// A trunk yawed, pitched nose down and rolled by the given angles (rad).
    fn trunk(yaw: f64, pitch: f64, roll: f64) -> DMat3 {
        DMat3::from_quat(
            DQuat::from_rotation_y(yaw)
                * DQuat::from_rotation_x(pitch)
                * DQuat::from_rotation_z(roll),
        )
    }

    #[test]
    fn the_aim_frame_keeps_the_share_of_roll_asked_for() {
        let rolled = trunk(0.3, 0.4, 0.25);
        // 1: the trunk's own rotation, to the bit.
        assert_eq!(aim_frame(rolled, 1.0), rolled);
        // 0: the same trunk without its roll; the share: that much roll.
        let level = trunk(0.3, 0.4, 0.0);
        for (share, want) in [(0.0, level), (0.5, trunk(0.3, 0.4, 0.125))] {
            let got = aim_frame(rolled, share);
            assert!(
                (got - want).to_cols_array().iter().all(|e| e.abs() < 1e-12),
                "{share}: {got} against {want}"
            );
        }
        // A level trunk is left as it is; NaN and negative shares read as 0.
        assert!(
            (aim_frame(level, 0.0) - level)
                .to_cols_array()
                .iter()
                .all(|e| e.abs() < 1e-12)
        );
        assert_eq!(aim_frame(rolled, f64::NAN), aim_frame(rolled, 0.0));
        assert_eq!(aim_frame(rolled, -2.0), aim_frame(rolled, 0.0));
    }

    #[test]
    fn a_leg_aimed_without_the_roll_hangs_in_the_trunks_plane() {
        // A trunk rolled 0.3 rad, the foot place straight below the hip: aimed
        // through the roll the leg turns 0.3 rad back at its roll joint to hang
        // plumb; aimed in the trunk's plane it hangs along the trunk's −y.
        let rolled = trunk(0.0, 0.0, 0.3);
        let hip = DVec3::new(0.0, 1.0, 0.0);
        let foot = DVec3::ZERO;
        let through = hip_angles(aim_frame(rolled, 1.0), hip, foot, 0.8);
        assert!(
            (through[0] + 0.3).abs() < 1e-12 && through[1].abs() < 1e-12,
            "{through:?}"
        );
        let plane = hip_angles(aim_frame(rolled, 0.0), hip, foot, 0.8);
        assert!(
            plane[0].abs() < 1e-12 && plane[1].abs() < 1e-12,
            "{plane:?}"
        );
    }

    #[test]
    fn neutral_point_is_half_the_stance_travel() {
        let v = DVec3::new(0.0, 0.3, 2.0);
        let d = foot_displacement(v, v, 0.2, 0.1);
        assert!((d - DVec3::new(0.0, 0.0, 0.2)).length() < 1e-12);
        // Too slow: the foot lands closer, so the body accelerates.
        let slow = foot_displacement(v, v * 1.5, 0.2, 0.1);
        assert!(slow.z < d.z);
    }
}
