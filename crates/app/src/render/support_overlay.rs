//! The static stability of a PODA walk, drawn on the ground (issue 21 item
//! 3): the support polygon of the feet down and the body's centre projected
//! on the ground, green while the centre is inside, orange when it is not
//! (the PODA driver's stability report, through the engine layer).

use glam::{DVec2, Vec3};

use super::gait_overlay::on_ground;
use super::scene::{Scene, Segment};

/// The support polygon and centre while statically stable (sRGB with alpha).
pub const SUPPORT_COLOR: [f32; 4] = [0.15, 0.70, 0.35, 0.95];
/// The same while the centre is outside the polygon.
pub const UNSUPPORTED_COLOR: [f32; 4] = [0.95, 0.45, 0.10, 0.95];
/// Lift above the ground, above the footprints (metres).
const LIFT_M: f32 = 0.003;
/// Half the size of the centre's cross (metres).
const CENTRE_HALF_M: f32 = 0.04;

impl Scene {
    /// Adds the support polygon (ground x, z corners, in order; two corners
    /// make a line, one a point) and the body's centre as a cross; `stable`
    /// picks the colour. Non-finite points draw nothing.
    pub fn add_support_overlay(&mut self, polygon: &[DVec2], centre: DVec2, stable: bool) {
        if !(centre.is_finite() && polygon.iter().all(|p| p.is_finite())) {
            return;
        }
        let colour = if stable {
            SUPPORT_COLOR
        } else {
            UNSUPPORTED_COLOR
        };
        let terrain = self.frame().terrain.clone();
        let ground = |p: DVec2| on_ground(terrain.as_deref(), p.x, p.y, LIFT_M);
        let frame = self.frame_mut();
        let n = polygon.len();
        if n >= 2 {
            // A closed outline; a line of two feet once.
            let edges = if n == 2 { 1 } else { n };
            for i in 0..edges {
                let (a, b) = (polygon[i], polygon[(i + 1) % n]);
                frame
                    .segments
                    .push(Segment::new(ground(a), ground(b), 2.5, colour));
            }
        }
        let c = ground(centre);
        for d in [Vec3::X, Vec3::Z] {
            let d = d * CENTRE_HALF_M;
            frame.segments.push(Segment::new(c - d, c + d, 3.0, colour));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_triangle_gets_three_edges_and_a_cross_in_the_stable_colour() {
        let mut scene = Scene::new();
        let triangle = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(0.0, 1.0),
        ];
        scene.add_support_overlay(&triangle, DVec2::new(0.2, 0.2), true);
        let segments = &scene.frame().segments;
        assert_eq!(segments.len(), 5);
        assert!(segments.iter().all(|s| s.color == SUPPORT_COLOR));
        let mut scene = Scene::new();
        scene.add_support_overlay(&triangle[..2], DVec2::new(0.5, 0.5), false);
        let segments = &scene.frame().segments;
        assert_eq!(segments.len(), 3, "one edge for two feet, and the cross");
        assert!(segments.iter().all(|s| s.color == UNSUPPORTED_COLOR));
        let mut scene = Scene::new();
        scene.add_support_overlay(&triangle, DVec2::splat(f64::NAN), true);
        assert!(scene.frame().segments.is_empty());
    }
}
