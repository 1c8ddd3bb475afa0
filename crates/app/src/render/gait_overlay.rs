//! What PODA plans, drawn on the ground (Girard & Maciejewski 1985,
//! "Foothold and Transfer Trajectory Planning", "Horizontal Control"): the
//! footprints of recent supports, the footholds planned for the feet in
//! transfer (eq. 11), and the body path ahead.

use glam::{DVec2, DVec3, Vec3};

use super::scene::{GROUND_Y, Scene, Segment};

/// Footprint rings, sRGB with alpha.
pub const FOOTPRINT_COLOR: [f32; 4] = [0.30, 0.32, 0.38, 0.55];
/// Planned-foothold crosses.
pub const FOOTHOLD_COLOR: [f32; 4] = [0.98, 0.55, 0.10, 0.95];
/// The body path ahead.
pub const PATH_COLOR: [f32; 4] = [0.20, 0.55, 0.95, 0.75];
/// Lift above the ground so the marks win the depth test against the grid, metres.
const LIFT_M: f32 = 0.002;
/// Footprint ring radius, metres.
const FOOTPRINT_RADIUS_M: f32 = 0.03;
/// Segments per footprint ring.
const RING_SEGMENTS: usize = 8;

fn ground(p: DVec3) -> Vec3 {
    Vec3::new(p.x as f32, GROUND_Y + LIFT_M, p.z as f32)
}

impl Scene {
    /// Adds the gait overlay after [`Scene::fill`]: a ring per footprint, a
    /// cross per planned foothold, and a polyline through `path` (ground
    /// points `(x, z)`). Non-finite points are skipped.
    pub fn add_gait_overlay(
        &mut self,
        footprints: impl Iterator<Item = DVec3>,
        footholds: impl Iterator<Item = DVec3>,
        path: impl Iterator<Item = DVec2>,
    ) {
        let frame = self.frame_mut();
        for print in footprints.filter(|p| p.is_finite()) {
            let centre = ground(print);
            for k in 0..RING_SEGMENTS {
                let angle = |k: usize| k as f32 / RING_SEGMENTS as f32 * std::f32::consts::TAU;
                let at = |a: f32| centre + Vec3::new(a.cos(), 0.0, a.sin()) * FOOTPRINT_RADIUS_M;
                frame.segments.push(Segment::new(
                    at(angle(k)),
                    at(angle(k + 1)),
                    1.5,
                    FOOTPRINT_COLOR,
                ));
            }
        }
        for hold in footholds.filter(|p| p.is_finite()) {
            let centre = ground(hold);
            let half = FOOTPRINT_RADIUS_M;
            for (dx, dz) in [(half, half), (half, -half)] {
                let d = Vec3::new(dx, 0.0, dz);
                frame
                    .segments
                    .push(Segment::new(centre - d, centre + d, 2.0, FOOTHOLD_COLOR));
            }
        }
        let mut previous: Option<Vec3> = None;
        for point in path.filter(|p| p.is_finite()) {
            let at = ground(DVec3::new(point.x, 0.0, point.y));
            if let Some(from) = previous {
                frame.segments.push(Segment::new(from, at, 2.0, PATH_COLOR));
            }
            previous = Some(at);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overlay_adds_rings_crosses_and_a_polyline() {
        let mut scene = Scene::new();
        scene.add_gait_overlay(
            [DVec3::new(0.1, 0.0, 0.2), DVec3::splat(f64::NAN)].into_iter(),
            std::iter::once(DVec3::new(0.3, 0.0, 0.5)),
            (0..5).map(|k| DVec2::new(0.0, f64::from(k) * 0.5)),
        );
        let segments = scene.segments();
        // One ring (8), one cross (2), four path pieces.
        assert_eq!(segments.len(), RING_SEGMENTS + 2 + 4);
        let ring = &segments[..RING_SEGMENTS];
        for segment in ring {
            let centre = Vec3::new(0.1, GROUND_Y + LIFT_M, 0.2);
            let r = (Vec3::from(segment.a) - centre).length();
            assert!((r - FOOTPRINT_RADIUS_M).abs() < 1e-6, "ring radius {r}");
        }
        let last = segments[segments.len() - 1];
        assert!((last.b[2] - 2.0).abs() < 1e-6, "path reaches z = 2 m");
    }
}
