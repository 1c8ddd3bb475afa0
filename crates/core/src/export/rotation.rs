//! Rotation parameterisations used by the export formats: ZXY Euler angles (the
//! BVH channel order `Zrotation Xrotation Yrotation`) and rotation vectors (the
//! root orientation columns of the pose CSV).
//!
//! The Euler decomposition follows the two-step method of Day ("Extracting Euler
//! angles from a rotation matrix", Insomniac Games, 2012): the middle angle and
//! the first angle come from the matrix, and the last angle from the matrix with
//! the first rotation removed. The last step never divides by `cos x`, so the
//! angles reproduce the matrix to rounding error even at gimbal lock (x = ±90°),
//! where only `z ± y` is determined and the split between them is arbitrary.

use crate::portable::Portable;
use glam::{DMat3, DQuat, DVec3};

/// ZXY Euler angles of `rotation`, radians: the returned `DVec3 { x, y, z }`
/// satisfies `rotation = Rz(z) · Rx(x) · Ry(y)` (column vectors), which is what the
/// BVH channel list `Zrotation Xrotation Yrotation` means.
///
/// `x ∈ [-π/2, π/2]`, `y, z ∈ [-π, π]`. `rotation` must be a rotation matrix
/// (orthonormal, determinant +1); anything else gives angles of its nearest
/// meaning, never a panic.
#[must_use]
pub fn euler_zxy(rotation: DMat3) -> DVec3 {
    // R = Rz·Rx·Ry =
    // [ cz·cy − sz·sx·sy   −sz·cx   cz·sy + sz·sx·cy ]
    // [ sz·cy + cz·sx·sy    cz·cx   sz·sy − cz·sx·cy ]
    // [ −cx·sy              sx      cx·cy            ]
    let m01 = rotation.y_axis.x;
    let m11 = rotation.y_axis.y;
    let m21 = rotation.y_axis.z;
    let x = m21.patan2(m01.phypot(m11));
    let z = (-m01).patan2(m11);
    let (sin_z, cos_z) = z.psin_cos();
    // Row 0 of Rz(z)ᵀ·R = Rx(x)·Ry(y) is (cos y, 0, sin y): free of cos x, so
    // y stays exact (and consistent with whatever z was) near gimbal lock.
    let cos_y = cos_z * rotation.x_axis.x + sin_z * rotation.x_axis.y;
    let sin_y = cos_z * rotation.z_axis.x + sin_z * rotation.z_axis.y;
    let y = sin_y.patan2(cos_y);
    DVec3::new(x, y, z)
}

/// The rotation `Rz(z) · Rx(x) · Ry(y)` for ZXY Euler angles in radians (inverse of [`euler_zxy`]).
#[must_use]
pub fn from_euler_zxy(angles: DVec3) -> DMat3 {
    DMat3::from_rotation_z(angles.z)
        * DMat3::from_rotation_x(angles.x)
        * DMat3::from_rotation_y(angles.y)
}

/// Rotation vector of `rotation`: unit axis times angle in radians, angle in `[0, π]`.
///
/// Computed through a unit quaternion with `w ≥ 0`, as `2·atan2(|v|, w) · v/|v|`,
/// which keeps full precision for tiny angles.
#[must_use]
pub fn rotation_vector(rotation: DMat3) -> DVec3 {
    let mut q = DQuat::from_mat3(&rotation);
    if q.w < 0.0 {
        q = -q;
    }
    let v = DVec3::new(q.x, q.y, q.z);
    let sin_half = v.length();
    if sin_half <= 0.0 || !sin_half.is_finite() {
        return DVec3::ZERO;
    }
    let angle = 2.0 * sin_half.patan2(q.w);
    v * (angle / sin_half)
}

/// The rotation whose rotation vector is `vector` (axis times angle, radians).
#[must_use]
pub fn from_rotation_vector(vector: DVec3) -> DMat3 {
    let angle = vector.length();
    if angle <= 0.0 || !angle.is_finite() {
        return DMat3::IDENTITY;
    }
    DMat3::from_axis_angle(vector / angle, angle)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn max_diff(a: DMat3, b: DMat3) -> f64 {
        (a - b)
            .to_cols_array()
            .iter()
            .fold(0.0_f64, |m, v| m.max(v.abs()))
    }

    #[test]
    fn euler_zxy_recomposes_over_a_grid_including_gimbal_lock() {
        let steps = [
            -180.0,
            -135.0,
            -90.0,
            -45.0,
            -1e-9,
            0.0,
            30.0,
            89.999_999_9,
            90.0,
            120.0,
            179.0,
        ];
        let xs = [-90.0, -89.999_999, -60.0, 0.0, 45.0, 89.999_999_999, 90.0];
        let mut worst = 0.0_f64;
        for &z in &steps {
            for &x in &xs {
                for &y in &steps {
                    let angles =
                        DVec3::new(f64::to_radians(x), f64::to_radians(y), f64::to_radians(z));
                    let rotation = from_euler_zxy(angles);
                    let back = from_euler_zxy(euler_zxy(rotation));
                    worst = worst.max(max_diff(rotation, back));
                }
            }
        }
        assert!(worst < 1e-14, "worst recomposition error {worst}");
    }

    #[test]
    fn euler_zxy_returns_the_angles_away_from_gimbal_lock() {
        let angles = DVec3::new(0.3, -1.2, 2.5);
        let found = euler_zxy(from_euler_zxy(angles));
        assert!((found - angles).abs().max_element() < 1e-14, "{found:?}");
    }

    #[test]
    fn euler_zxy_at_exact_gimbal_lock_keeps_x_and_the_sum() {
        // x = +90°: R depends on z + y only.
        let rotation = from_euler_zxy(DVec3::new(std::f64::consts::FRAC_PI_2, 0.4, 0.7));
        let found = euler_zxy(rotation);
        assert!((found.x - std::f64::consts::FRAC_PI_2).abs() < 1e-7);
        assert!(max_diff(from_euler_zxy(found), rotation) < 1e-15);
    }

    #[test]
    fn rotation_vector_round_trips_small_and_large_angles() {
        for (axis, angle) in [
            (DVec3::X, 1e-12),
            (DVec3::new(1.0, 2.0, -2.0).normalize(), 0.5),
            (DVec3::new(-3.0, 0.0, 4.0).normalize(), 3.0),
            (DVec3::Y, std::f64::consts::PI - 1e-9),
        ] {
            let rotation = DMat3::from_axis_angle(axis, angle);
            let vector = rotation_vector(rotation);
            assert!(
                (vector.length() - angle).abs() <= 1e-9 * angle,
                "{vector:?} for {angle}"
            );
            assert!(max_diff(from_rotation_vector(vector), rotation) < 1e-14);
        }
        assert_eq!(rotation_vector(DMat3::IDENTITY), DVec3::ZERO);
    }
}
