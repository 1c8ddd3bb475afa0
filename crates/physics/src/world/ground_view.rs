//! What a controller may know of the ground it runs on (issue 45 item 3):
//! the local ground plane under the trunk — its height and its grade — that
//! the simulation fills from its terrain every control interval and hands to
//! the controller in [`crate::world::sim::ControlInput`]. It is the one way
//! a controller learns of the terrain: no controller reads
//! [`crate::world::ground::Terrain`] itself. Raibert & Hodgins 1991's laws
//! (eq. 2's hop height, eq. 3's foot placement) are written for a level
//! floor; the lab's `ground_ahead` addition measures them from this plane.
//!
//! The plane is fitted by central differences over ±[`GroundView::SPAN_M`]
//! (m at scale 1) about the trunk's ground point, so on a plane it is exact
//! and on rough ground it is the ground's mean tilt under the body, not one
//! cell's.

use glam::DVec3;

use crate::world::ground::Terrain;

/// The ground plane under the trunk (world frame, m, y up).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GroundView {
    /// The ground point under the trunk: its x and z, and the ground's
    /// height there (m).
    pub at: DVec3,
    /// The ground's rise per metre along +x (m/m).
    pub grade_x: f64,
    /// The ground's rise per metre along +z (m/m).
    pub grade_z: f64,
}

impl Default for GroundView {
    fn default() -> Self {
        Self::FLAT
    }
}

impl GroundView {
    /// The floor: height 0, level.
    pub const FLAT: Self = Self {
        at: DVec3::ZERO,
        grade_x: 0.0,
        grade_z: 0.0,
    };

    /// Half the span the grade is measured over, m at scale 1.
    pub const SPAN_M: f64 = 0.25;

    /// The ground plane of `terrain` under the point `trunk` (world, m) for
    /// a creature at dynamic scale `scale`: the floor's own where the
    /// terrain is the floor with no boxes.
    #[must_use]
    pub fn of(terrain: &Terrain, trunk: DVec3, scale: f64) -> Self {
        if terrain.surface.is_flat() && terrain.obstacles.is_empty() {
            return Self::FLAT;
        }
        let (x, z) = (trunk.x, trunk.z);
        let span = Self::SPAN_M * scale;
        let h = |x: f64, z: f64| terrain.height(x, z);
        Self {
            at: DVec3::new(x, h(x, z), z),
            grade_x: (h(x + span, z) - h(x - span, z)) / (2.0 * span),
            grade_z: (h(x, z + span) - h(x, z - span)) / (2.0 * span),
        }
    }

    /// The plane's height at (x, z) (m).
    #[must_use]
    pub fn height_at(&self, x: f64, z: f64) -> f64 {
        self.at.y + self.grade_x * (x - self.at.x) + self.grade_z * (z - self.at.z)
    }

    /// The plane's rise per metre along the horizontal direction `dir`
    /// (normalised here; 0 for a vertical or zero `dir`).
    #[must_use]
    pub fn grade_along(&self, dir: DVec3) -> f64 {
        let d = DVec3::new(dir.x, 0.0, dir.z).normalize_or_zero();
        self.grade_x * d.x + self.grade_z * d.z
    }
}

#[cfg(test)]
mod tests {
    use gaitlab_core::terrain::{Plane, Terrain as Surface};
    use glam::DVec3;

    use super::GroundView;
    use crate::world::ground::Terrain;

    #[test]
    fn on_a_plane_the_view_is_the_plane() {
        let terrain = Terrain {
            surface: Surface::Plane(Plane {
                slope_deg: 5.0,
                direction_deg: 90.0,
            }),
            obstacles: Vec::new(),
        };
        let view = GroundView::of(&terrain, DVec3::new(0.3, 2.0, 4.0), 1.0);
        let (sin, cos) = gaitlab_core::trig::sin_cos(5f64.to_radians());
        let rise = sin / cos;
        assert!((view.grade_z - rise).abs() < 1e-12, "{view:?}");
        assert!(view.grade_x.abs() < 1e-12, "{view:?}");
        assert!((view.at.y - 4.0 * rise).abs() < 1e-12, "{view:?}");
        assert!((view.height_at(1.0, 7.0) - 7.0 * rise).abs() < 1e-12);
        assert!((view.grade_along(DVec3::new(0.0, 0.0, -2.0)) + rise).abs() < 1e-12);
    }

    #[test]
    fn on_the_floor_it_is_the_floor() {
        let view = GroundView::of(&Terrain::default(), DVec3::new(3.0, 1.0, 9.0), 1.0);
        assert_eq!(view, GroundView::FLAT);
        assert_eq!(view.height_at(3.0, 9.0), 0.0);
    }
}
