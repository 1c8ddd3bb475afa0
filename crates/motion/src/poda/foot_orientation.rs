//! The foot's orientation (Girard & Maciejewski 1985 eq. 2, the last three
//! components of the end-effector vector): the orientation a foot touches
//! down with (its rest orientation carried by the body's ground yaw: level,
//! facing the heading), the turn between lift-off and touchdown (a slerp
//! along the transfer), and the orientation error the leg IK's angular rows
//! solve for (the rotation vector of `R_target · R_currentᵀ`, radians).
//!
//! Conventions: orientations are unit quaternions from the foot's frame to
//! the world; a rotation vector is the rotation's axis times its angle in
//! radians, the angle in [0, π] (the shorter way round). Transcendental
//! functions go through [`Portable`], so every platform gets the same bits.

use gaitlab_core::portable::Portable;
use glam::{DMat3, DQuat, DVec3};

/// Below this half-angle sine a rotation vector is taken to first order
/// (`2·v`, the error of the first order is below 1e-24 rad).
const SMALL_HALF_SINE: f64 = 1e-12;

/// The rotation by `yaw_rad` about the world's vertical (+y), the ground
/// pose's heading convention (0 faces +z, positive turns toward +x).
#[must_use]
pub fn yaw_rotation(yaw_rad: f64) -> DQuat {
    let (sine, cosine) = (0.5 * yaw_rad).psin_cos();
    DQuat::from_xyzw(0.0, sine, 0.0, cosine)
}

/// The heading of `rotation` on the ground, radians: the yaw that turns +z
/// toward where `rotation` carries +z, seen from above (0 when it points
/// straight up or down).
#[must_use]
pub fn heading_rad(rotation: DMat3) -> f64 {
    let forward = rotation * DVec3::Z;
    if forward.x == 0.0 && forward.z == 0.0 {
        0.0
    } else {
        forward.x.patan2(forward.z)
    }
}

/// The rotation vector of `rotation`, radians: its axis times its angle,
/// the angle in [0, π].
#[must_use]
pub fn rotation_vector_rad(rotation: DQuat) -> DVec3 {
    // q and −q are the same rotation; w ≥ 0 takes the shorter way round.
    let q = if rotation.w < 0.0 {
        -rotation
    } else {
        rotation
    };
    let half = DVec3::new(q.x, q.y, q.z);
    let half_sine = half.length();
    if half_sine < SMALL_HALF_SINE {
        return 2.0 * half;
    }
    half * (2.0 * half_sine.patan2(q.w) / half_sine)
}

/// The rotation of the rotation vector `turn_rad` (axis times angle, radians).
#[must_use]
pub fn from_rotation_vector(turn_rad: DVec3) -> DQuat {
    let angle_rad = turn_rad.length();
    if angle_rad < 2.0 * SMALL_HALF_SINE {
        let half = 0.5 * turn_rad;
        return DQuat::from_xyzw(half.x, half.y, half.z, 1.0).normalize();
    }
    let (sine, cosine) = (0.5 * angle_rad).psin_cos();
    let half = turn_rad * (sine / angle_rad);
    DQuat::from_xyzw(half.x, half.y, half.z, cosine)
}

/// Spherical linear interpolation from `from` (`u` = 0) to `to` (`u` = 1)
/// the shorter way round, at a constant angular speed in `u`.
#[must_use]
pub fn slerp(from: DQuat, to: DQuat, u: f64) -> DQuat {
    let turn_rad = rotation_vector_rad(to * from.conjugate());
    (from_rotation_vector(turn_rad * u) * from).normalize()
}

/// The orientation error the IK's angular rows solve for: the rotation
/// vector, world radians, of the turn `target · currentᵀ` that brings the
/// foot's `current` orientation (a rotation matrix from its frame to the
/// world) to `target`.
#[must_use]
pub fn orientation_error_rad(target: DQuat, current: DMat3) -> DVec3 {
    rotation_vector_rad(target * DQuat::from_mat3(&current).conjugate())
}

/// The angle between two orientations, radians in [0, π].
#[must_use]
pub fn angle_between_rad(a: DQuat, b: DQuat) -> f64 {
    rotation_vector_rad(b * a.conjugate()).length()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DQuat, b: DQuat) -> f64 {
        angle_between_rad(a, b)
    }

    #[test]
    fn a_rotation_vector_goes_there_and_back() {
        for turn in [
            DVec3::new(0.3, -0.2, 0.9),
            DVec3::new(0.0, 3.0, 0.0),
            DVec3::new(1e-14, 0.0, -2e-14),
            DVec3::ZERO,
        ] {
            let q = from_rotation_vector(turn);
            let back = rotation_vector_rad(q);
            assert!((back - turn).length() < 1e-12, "{turn} → {back}");
            // The same rotation as glam's axis-angle constructor.
            if turn.length() > 1e-6 {
                let glam = DQuat::from_axis_angle(turn.normalize(), turn.length());
                assert!(close(q, glam) < 1e-12);
            }
        }
        // −q is the same rotation: the shorter way round.
        let q = from_rotation_vector(DVec3::new(0.0, 0.0, 1.0));
        assert!((rotation_vector_rad(-q) - DVec3::Z).length() < 1e-12);
    }

    #[test]
    fn yaw_matches_the_ground_poses_rotation_and_its_heading() {
        let yaw = 0.7;
        let q = yaw_rotation(yaw);
        let m = DMat3::from_rotation_y(yaw);
        assert!(close(q, DQuat::from_mat3(&m)) < 1e-12);
        assert!((heading_rad(m) - yaw).abs() < 1e-12);
        assert!((heading_rad(m * DMat3::from_rotation_x(0.4)) - yaw).abs() < 1e-12);
    }

    #[test]
    fn slerp_turns_evenly_from_one_end_to_the_other() {
        let a = from_rotation_vector(DVec3::new(0.1, 0.2, 0.0));
        let b = from_rotation_vector(DVec3::new(-0.3, 1.1, 0.4));
        assert!(close(slerp(a, b, 0.0), a) < 1e-12);
        assert!(close(slerp(a, b, 1.0), b) < 1e-12);
        let whole = angle_between_rad(a, b);
        for u in [0.25, 0.5, 0.8] {
            let q = slerp(a, b, u);
            assert!((angle_between_rad(a, q) - u * whole).abs() < 1e-12);
            assert!((angle_between_rad(q, b) - (1.0 - u) * whole).abs() < 1e-12);
        }
    }

    #[test]
    fn the_error_is_the_turn_from_the_current_orientation_to_the_target() {
        let current = DMat3::from_axis_angle(DVec3::new(1.0, 2.0, -1.0).normalize(), 0.8);
        let turn = DVec3::new(0.05, -0.3, 0.2);
        let target = from_rotation_vector(turn) * DQuat::from_mat3(&current);
        let error = orientation_error_rad(target, current);
        assert!((error - turn).length() < 1e-12, "{error}");
    }
}
