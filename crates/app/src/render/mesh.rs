//! The unit capsule mesh every bone and sphere is instanced from.
//!
//! Each vertex is `[nx, ny, nz, end]`: a unit normal in a local frame whose +z
//! runs along the capsule's axis, and which end the vertex belongs to (0: the
//! start `a`, 1: the end `b`). The vertex shader places it at
//! `mix(a, b, end) + radius · (frame · n)`, so one mesh draws capsules of any
//! length and radius, and spheres when `a == b`: the −z hemisphere caps `a`,
//! the +z hemisphere caps `b`, and the band joining their equators is the
//! cylinder between them.

/// Points around each ring of the capsule mesh.
pub const SEGMENTS: usize = 20;
/// Rings per hemisphere, pole and equator included.
pub const HEMISPHERE_RINGS: usize = 6;

/// Vertices (`[nx, ny, nz, end]`) and triangle-list indices of the unit capsule
/// with `segments` points per ring and `rings` rings per hemisphere (both ≥ 2).
///
/// Triangles are counter-clockwise seen from outside.
#[must_use]
pub fn capsule_mesh(segments: usize, rings: usize) -> (Vec<[f32; 4]>, Vec<u16>) {
    let segments = segments.max(3);
    let rings = rings.max(2);
    let mut vertices = Vec::with_capacity(2 * rings * segments);
    // Polar angle from +z: end 0 runs from the −z pole (π) to its equator
    // (π/2), end 1 from its equator to the +z pole (0).
    for end in 0..2 {
        for ring in 0..rings {
            let along = ring as f32 / (rings - 1) as f32;
            let polar = if end == 0 {
                std::f32::consts::PI - std::f32::consts::FRAC_PI_2 * along
            } else {
                std::f32::consts::FRAC_PI_2 * (1.0 - along)
            };
            let (sin_polar, cos_polar) = polar.sin_cos();
            for segment in 0..segments {
                let azimuth = std::f32::consts::TAU * segment as f32 / segments as f32;
                let (sin_az, cos_az) = azimuth.sin_cos();
                vertices.push([
                    sin_polar * cos_az,
                    sin_polar * sin_az,
                    cos_polar,
                    end as f32,
                ]);
            }
        }
    }
    let ring_count = 2 * rings;
    let mut indices = Vec::with_capacity((ring_count - 1) * segments * 6);
    let index = |ring: usize, segment: usize| {
        u16::try_from(ring * segments + segment % segments).unwrap_or(u16::MAX)
    };
    for ring in 0..ring_count - 1 {
        for segment in 0..segments {
            // Ring `ring` is nearer −z than ring `ring + 1`; azimuth grows
            // counter-clockwise about +z, so (low, low+1, high) faces outward.
            let (a, b) = (index(ring, segment), index(ring, segment + 1));
            let (c, d) = (index(ring + 1, segment), index(ring + 1, segment + 1));
            indices.extend_from_slice(&[a, b, d, a, d, c]);
        }
    }
    (vertices, indices)
}

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;

    #[test]
    fn normals_are_unit_and_ends_cap_their_hemispheres() {
        let (vertices, indices) = capsule_mesh(SEGMENTS, HEMISPHERE_RINGS);
        assert_eq!(vertices.len(), 2 * HEMISPHERE_RINGS * SEGMENTS);
        assert_eq!(indices.len(), (2 * HEMISPHERE_RINGS - 1) * SEGMENTS * 6);
        for v in &vertices {
            let n = Vec3::new(v[0], v[1], v[2]);
            assert!((n.length() - 1.0).abs() < 1e-5);
            if v[3] == 0.0 {
                assert!(n.z <= 1e-6, "end 0 is the −z hemisphere");
            } else {
                assert_eq!(v[3], 1.0);
                assert!(n.z >= -1e-6, "end 1 is the +z hemisphere");
            }
        }
        assert!(indices.iter().all(|&i| usize::from(i) < vertices.len()));
    }

    #[test]
    fn triangles_face_outward() {
        // Place the mesh as a capsule from (0,0,0) to (0,0,1), radius 0.5, and
        // check every non-degenerate triangle's normal points away from the axis.
        let (vertices, indices) = capsule_mesh(SEGMENTS, HEMISPHERE_RINGS);
        let place = |v: [f32; 4]| Vec3::new(v[0], v[1], v[2]) * 0.5 + Vec3::Z * v[3];
        let mut checked = 0;
        for tri in indices.chunks_exact(3) {
            let [a, b, c] = [tri[0], tri[1], tri[2]].map(|i| place(vertices[usize::from(i)]));
            let normal = (b - a).cross(c - a);
            if normal.length() < 1e-7 {
                continue; // a sliver at a pole
            }
            let centre = (a + b + c) / 3.0;
            let axis_point = Vec3::Z * centre.z.clamp(0.0, 1.0);
            assert!(
                normal.dot(centre - axis_point) > 0.0,
                "inward triangle at {centre}"
            );
            checked += 1;
        }
        assert!(checked > indices.len() / 3 / 2);
    }
}
