//! What PODA plans, drawn on the ground (Girard & Maciejewski 1985,
//! "Foothold and Transfer Trajectory Planning", "Horizontal Control"): the
//! footprints of recent supports, the footholds planned for the feet in
//! transfer (eq. 11), where uneven ground moved one (issue 45 item 2: eq.
//! 11's own spot, a line to the one chosen), and the body path ahead — all
//! on the ground drawn, flat or not.

use glam::{DVec2, DVec3, Vec3};

use super::scene::{GROUND_Y, Scene, Segment, TerrainMesh};

/// Footprint rings, sRGB with alpha.
pub const FOOTPRINT_COLOR: [f32; 4] = [0.30, 0.32, 0.38, 0.55];
/// Planned-foothold crosses.
pub const FOOTHOLD_COLOR: [f32; 4] = [0.98, 0.55, 0.10, 0.95];
/// Eq. 11's own spot where uneven ground moved the foothold, and the line to it.
pub const MOVED_FROM_COLOR: [f32; 4] = [0.62, 0.62, 0.66, 0.9];
/// The body path ahead.
pub const PATH_COLOR: [f32; 4] = [0.20, 0.55, 0.95, 0.75];
/// Lift above the ground so the marks win the depth test against the grid, metres.
const LIFT_M: f32 = 0.002;
/// Footprint ring radius, metres.
const FOOTPRINT_RADIUS_M: f32 = 0.03;
/// Segments per footprint ring.
const RING_SEGMENTS: usize = 8;

/// The ground point under `p` (x, z), just above the ground drawn.
pub(super) fn on_ground(terrain: Option<&TerrainMesh>, x: f64, z: f64, lift_m: f32) -> Vec3 {
    let height = terrain.map_or(GROUND_Y, |mesh| mesh.height_m(x, z) as f32);
    Vec3::new(x as f32, height + lift_m, z as f32)
}

impl Scene {
    /// Adds the gait overlay after [`Scene::fill`]: a ring per footprint, a
    /// cross per planned foothold, a grey cross on each `moved` foothold's
    /// eq. 11 spot with a line to the foothold chosen, and a polyline through
    /// `path` (ground points `(x, z)`), all on the ground drawn. Non-finite
    /// points are skipped.
    pub fn add_gait_overlay(
        &mut self,
        footprints: impl Iterator<Item = DVec3>,
        footholds: impl Iterator<Item = DVec3>,
        moved: impl Iterator<Item = (DVec3, DVec3)>,
        path: impl Iterator<Item = DVec2>,
    ) {
        let terrain = self.frame().terrain.clone();
        let ground = |p: DVec3| on_ground(terrain.as_deref(), p.x, p.z, LIFT_M);
        // Every end on the ground under it, so a mark on a slope or a
        // tread's edge never dips into the ground.
        let on = |x: f64, z: f64| on_ground(terrain.as_deref(), x, z, LIFT_M);
        let radius = f64::from(FOOTPRINT_RADIUS_M);
        let frame = self.frame_mut();
        for print in footprints.filter(|p| p.is_finite()) {
            let at = |k: usize| {
                let angle = k as f64 / RING_SEGMENTS as f64 * std::f64::consts::TAU;
                let (sin, cos) = gaitlab_core::trig::sin_cos(angle);
                on(print.x + radius * cos, print.z + radius * sin)
            };
            for k in 0..RING_SEGMENTS {
                frame
                    .segments
                    .push(Segment::new(at(k), at(k + 1), 1.5, FOOTPRINT_COLOR));
            }
        }
        let cross = |centre: DVec3, half: f64| {
            [(half, half), (half, -half)].map(|(dx, dz)| {
                (
                    on(centre.x - dx, centre.z - dz),
                    on(centre.x + dx, centre.z + dz),
                )
            })
        };
        for hold in footholds.filter(|p| p.is_finite()) {
            for (a, b) in cross(hold, radius) {
                frame.segments.push(Segment::new(a, b, 2.0, FOOTHOLD_COLOR));
            }
        }
        for (nominal, chosen) in moved.filter(|(a, b)| a.is_finite() && b.is_finite()) {
            for (a, b) in cross(nominal, 0.6 * radius) {
                frame
                    .segments
                    .push(Segment::new(a, b, 1.5, MOVED_FROM_COLOR));
            }
            frame.segments.push(Segment::new(
                ground(nominal),
                ground(chosen),
                1.0,
                MOVED_FROM_COLOR,
            ));
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
            std::iter::empty(),
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
