//! The ground that is not flat as triangles for the 3-D view (issue 45 item
//! 4): a plane, a flight of stairs with its risers, or a height field split
//! into triangles the way the terrain model (and MuJoCo) splits it, each
//! inside a flat surround out to [`REACH_M`]. Built once per terrain, not per
//! frame; the renderer uploads it once per [`TerrainMesh::id`].

use std::sync::atomic::{AtomicU64, Ordering};

use gaitlab_core::terrain::{HeightField, Plane, Stairs, Terrain, ground_direction};
use glam::DVec3;

use super::primitives::Segment;

/// How far the drawn ground reaches from the origin, metres (the view's
/// fog hides it long before).
pub const REACH_M: f64 = 400.0;

/// How far a step's edge lines reach to each side of the walk, metres.
pub const EDGE_REACH_M: f64 = 30.0;

/// A step's edge lines, sRGB with alpha: a mid grey that reads on the dark
/// and the light ground alike.
pub const EDGE_COLOR: [f32; 4] = [0.50, 0.52, 0.56, 0.9];

/// Edge lines sit this far out of the solid corner they mark, metres, so
/// the ground's own faces never hide them.
const EDGE_LIFT_M: f64 = 0.002;

/// The most height-field samples drawn one to one; a larger field is
/// drawn every `stride`-th sample (the model keeps every one).
pub const DRAWN_SAMPLES: usize = 1 << 18;

/// The ground's triangles, world metres.
#[derive(Clone, Debug, PartialEq)]
pub struct TerrainMesh {
    /// The terrain drawn (the overlays and the camera ask it for heights).
    pub terrain: Terrain,
    /// Vertex positions, world metres (w = 1).
    pub positions: Vec<[f32; 4]>,
    /// Three indices into [`Self::positions`] per triangle.
    pub indices: Vec<u32>,
    /// Samples of a height field per drawn cell side (1: every sample).
    pub stride: usize,
    /// Lines along the edges of steps (each riser's top and foot), so a
    /// step shows from above too; drawn with the figure's segments.
    pub edges: Vec<Segment>,
    /// Different for every mesh built: the renderer uploads each id once.
    pub id: u64,
}

static NEXT_ID: AtomicU64 = AtomicU64::new(1);

impl TerrainMesh {
    /// The mesh of `terrain`; `None` for the floor (the view's own ground
    /// plane draws it).
    #[must_use]
    pub fn of(terrain: &Terrain) -> Option<Self> {
        let mut mesh = Self {
            terrain: terrain.clone(),
            positions: Vec::new(),
            indices: Vec::new(),
            stride: 1,
            edges: Vec::new(),
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
        };
        match terrain {
            Terrain::Flat => return None,
            Terrain::Plane(plane) => mesh.plane(plane),
            Terrain::Stairs(stairs) => mesh.stairs(stairs),
            Terrain::HeightField(field) => mesh.field(field),
            Terrain::Rough(rough) => mesh.field(rough.field()),
        }
        Some(mesh)
    }

    /// Triangles drawn.
    #[must_use]
    pub fn triangles(&self) -> usize {
        self.indices.len() / 3
    }

    /// Ground height under (x, z), metres.
    #[must_use]
    pub fn height_m(&self, x: f64, z: f64) -> f64 {
        self.terrain.height_m(x, z)
    }

    fn vertex(&mut self, p: DVec3) -> u32 {
        let index = u32::try_from(self.positions.len()).unwrap_or(u32::MAX);
        self.positions
            .push([p.x as f32, p.y as f32, p.z as f32, 1.0]);
        index
    }

    /// A quad a–b–c–d (in order round its edge) as two triangles.
    fn quad(&mut self, corners: [DVec3; 4]) {
        let [a, b, c, d] = corners.map(|p| self.vertex(p));
        self.indices.extend_from_slice(&[a, b, c, a, c, d]);
    }

    fn plane(&mut self, plane: &Plane) {
        let r = REACH_M;
        let at = |x: f64, z: f64| DVec3::new(x, plane.height_m(x, z), z);
        self.quad([at(-r, -r), at(r, -r), at(r, r), at(-r, r)]);
    }

    /// The floor before the flight, each tread (the last one out to the
    /// reach) and each riser, in the stairs' own heading.
    fn stairs(&mut self, stairs: &Stairs) {
        let along = ground_direction(stairs.direction_deg);
        let across = DVec3::new(-along.z, 0.0, along.x);
        let r = REACH_M;
        let at = |s: f64, y: f64, t: f64| along * s + across * t + DVec3::Y * y;
        let strip =
            |s0: f64, s1: f64, y: f64| [at(s0, y, -r), at(s1, y, -r), at(s1, y, r), at(s0, y, r)];
        let first = stairs.start_m;
        self.quad(strip(-r, first, 0.0));
        let count = stairs.count;
        for k in 0..count {
            let s0 = first + f64::from(k) * stairs.run_m;
            let (low, high) = (
                stairs.rise_m * f64::from(k),
                stairs.rise_m * f64::from(k + 1),
            );
            self.quad([
                at(s0, low, -r),
                at(s0, high, -r),
                at(s0, high, r),
                at(s0, low, r),
            ]);
            // The riser's top and foot, just out of the corner toward the walker.
            let (e, out) = (EDGE_REACH_M, s0 - EDGE_LIFT_M * stairs.rise_m.signum());
            for y in [low, high] {
                let y = y + EDGE_LIFT_M;
                self.edges.push(Segment::new(
                    at(out, y, -e).as_vec3(),
                    at(out, y, e).as_vec3(),
                    1.5,
                    EDGE_COLOR,
                ));
            }
            let s1 = if k + 1 == count {
                (s0 + stairs.run_m).max(r)
            } else {
                s0 + stairs.run_m
            };
            self.quad(strip(s0, s1, high));
        }
    }

    /// The grid's triangles (every `stride`-th sample), walls down to the
    /// floor at its edges, and the floor around it.
    fn field(&mut self, field: &HeightField) {
        let (cols, rows) = (field.cols, field.rows);
        if cols < 2 || rows < 2 {
            return;
        }
        let samples = cols.saturating_mul(rows);
        let stride = if samples <= DRAWN_SAMPLES {
            1
        } else {
            let ratio = samples as f64 / DRAWN_SAMPLES as f64;
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "a small positive ratio's square root"
            )]
            let s = ratio.sqrt().ceil() as usize;
            s.max(2)
        };
        self.stride = stride;
        // Drawn sample indices along each side: every stride-th, and the last.
        let picks = |n: usize| -> Vec<usize> {
            let mut v: Vec<usize> = (0..n).step_by(stride).collect();
            if v.last() != Some(&(n - 1)) {
                v.push(n - 1);
            }
            v
        };
        let (pick_cols, pick_rows) = (picks(cols), picks(rows));
        let [x0, z0] = field.origin();
        let cell = field.cell_m;
        let sample = |row: usize, col: usize| {
            let h = field
                .heights_m
                .get(row * cols + col)
                .copied()
                .unwrap_or(0.0);
            DVec3::new(x0 + col as f64 * cell, h, z0 + row as f64 * cell)
        };
        let base = self.positions.len();
        for &row in &pick_rows {
            for &col in &pick_cols {
                let p = sample(row, col);
                self.vertex(p);
            }
        }
        let width = pick_cols.len();
        let index = |i: usize, j: usize| u32::try_from(base + i * width + j).unwrap_or(u32::MAX);
        for i in 0..pick_rows.len() - 1 {
            for j in 0..width - 1 {
                let (h00, h10, h01, h11) = (
                    index(i, j),
                    index(i, j + 1),
                    index(i + 1, j),
                    index(i + 1, j + 1),
                );
                // The model's split: (0,0)–(1,0)–(0,1) and (1,1)–(0,1)–(1,0).
                self.indices
                    .extend_from_slice(&[h00, h10, h01, h11, h01, h10]);
            }
        }
        // Walls from the edge down (or up) to the floor.
        let edge = |this: &mut Self, points: &[DVec3]| {
            for pair in points.windows(2) {
                let (a, b) = (pair[0], pair[1]);
                let floor = |p: DVec3| DVec3::new(p.x, 0.0, p.z);
                this.quad([a, b, floor(b), floor(a)]);
            }
        };
        let first_row: Vec<DVec3> = pick_cols.iter().map(|&c| sample(0, c)).collect();
        let last_row: Vec<DVec3> = pick_cols.iter().map(|&c| sample(rows - 1, c)).collect();
        let first_col: Vec<DVec3> = pick_rows.iter().map(|&r| sample(r, 0)).collect();
        let last_col: Vec<DVec3> = pick_rows.iter().map(|&r| sample(r, cols - 1)).collect();
        for side in [first_row, last_row, first_col, last_col] {
            edge(self, &side);
        }
        // The floor around the grid: four strips.
        let (x1, z1) = (x0 + (cols - 1) as f64 * cell, z0 + (rows - 1) as f64 * cell);
        let r = REACH_M
            .max(x1.abs())
            .max(z1.abs())
            .max(x0.abs())
            .max(z0.abs())
            + 1.0;
        let at = |x: f64, z: f64| DVec3::new(x, 0.0, z);
        self.quad([at(-r, -r), at(r, -r), at(r, z0), at(-r, z0)]);
        self.quad([at(-r, z1), at(r, z1), at(r, r), at(-r, r)]);
        self.quad([at(-r, z0), at(x0, z0), at(x0, z1), at(-r, z1)]);
        self.quad([at(x1, z0), at(r, z0), at(r, z1), at(x1, z1)]);
    }
}

#[cfg(test)]
mod tests {
    use gaitlab_core::terrain::Rough;

    use super::*;

    /// The height of the drawn triangle under (x, z), by barycentric
    /// interpolation of its vertices (`None` when no upward triangle covers it).
    fn drawn_height(mesh: &TerrainMesh, x: f64, z: f64) -> Option<f64> {
        let mut best: Option<f64> = None;
        for tri in mesh.indices.chunks_exact(3) {
            let [a, b, c] =
                [tri[0], tri[1], tri[2]].map(|i| mesh.positions[i as usize].map(f64::from));
            let (ax, az, bx, bz, cx, cz) = (a[0], a[2], b[0], b[2], c[0], c[2]);
            let det = (bz - cz) * (ax - cx) + (cx - bx) * (az - cz);
            if det.abs() < 1e-12 {
                continue; // a wall
            }
            let l1 = ((bz - cz) * (x - cx) + (cx - bx) * (z - cz)) / det;
            let l2 = ((cz - az) * (x - cx) + (ax - cx) * (z - cz)) / det;
            let l3 = 1.0 - l1 - l2;
            let tol = 1e-9;
            if l1 >= -tol && l2 >= -tol && l3 >= -tol {
                let h = l1 * a[1] + l2 * b[1] + l3 * c[1];
                best = Some(best.map_or(h, |old: f64| old.max(h)));
            }
        }
        best
    }

    fn check_agrees(terrain: &Terrain, points: &[(f64, f64)], tolerance_m: f64) {
        let mesh = TerrainMesh::of(terrain).expect("a mesh");
        for &(x, z) in points {
            let drawn = drawn_height(&mesh, x, z).expect("covered");
            let model = terrain.height_m(x, z);
            assert!(
                (drawn - model).abs() <= tolerance_m,
                "{}: at ({x}, {z}) drawn {drawn} m, model {model} m",
                terrain.kind_name()
            );
        }
    }

    fn grid_points() -> Vec<(f64, f64)> {
        // Off the exact edges, where treads and risers meet.
        (0..13)
            .flat_map(|i| {
                (0..9).map(move |j| {
                    (
                        -2.937 + 0.4931 * f64::from(i),
                        -1.913 + 0.4717 * f64::from(j),
                    )
                })
            })
            .collect()
    }

    #[test]
    fn the_floor_has_no_mesh() {
        assert!(TerrainMesh::of(&Terrain::Flat).is_none());
    }

    #[test]
    fn a_plane_is_drawn_at_its_height() {
        let plane = Terrain::Plane(Plane {
            slope_deg: 10.0,
            direction_deg: 30.0,
        });
        check_agrees(&plane, &grid_points(), 1e-4);
    }

    #[test]
    fn stairs_treads_are_drawn_at_their_height_with_a_riser_each() {
        let stairs = Terrain::Stairs(Stairs {
            rise_m: 0.05,
            run_m: 0.3,
            count: 5,
            direction_deg: 90.0,
            start_m: -1.0,
        });
        check_agrees(&stairs, &grid_points(), 1e-6);
        let mesh = TerrainMesh::of(&stairs).expect("a mesh");
        // Floor, then per step a riser and a tread.
        assert_eq!(mesh.triangles(), 2 * (1 + 2 * 5));
        // A line at each riser's top and foot, 2 mm out of the corner.
        assert_eq!(mesh.edges.len(), 2 * 5);
        let first = mesh.edges[1];
        assert!((first.a[1] - 0.052).abs() < 1e-6, "{first:?}");
        assert!((first.a[2] - (-1.002)).abs() < 1e-6, "{first:?}");
    }

    #[test]
    fn rough_ground_is_drawn_as_the_model_splits_its_cells() {
        let rough = Terrain::Rough(Rough::new(7, 1.0));
        check_agrees(&rough, &grid_points(), 1e-5);
        let mesh = TerrainMesh::of(&rough).expect("a mesh");
        assert_eq!(mesh.stride, 1);
    }

    #[test]
    fn a_huge_field_is_drawn_thinned() {
        let (cols, rows) = (1024, 1024);
        let field = HeightField {
            cell_m: 0.01,
            cols,
            rows,
            origin_m: None,
            heights_m: vec![0.02; cols * rows],
            friction: None,
        };
        let mesh = TerrainMesh::of(&Terrain::HeightField(field)).expect("a mesh");
        assert_eq!(mesh.stride, 2);
        // Every other sample and the last (513 a side), a wall of 512 quads
        // a side, four quads of floor around.
        assert_eq!(mesh.positions.len(), 513 * 513 + 4 * 512 * 4 + 4 * 4);
    }

    #[test]
    fn every_mesh_has_its_own_id() {
        let plane = Terrain::Plane(Plane {
            slope_deg: 5.0,
            direction_deg: 0.0,
        });
        let (a, b) = (TerrainMesh::of(&plane), TerrainMesh::of(&plane));
        assert_ne!(a.map(|m| m.id), b.map(|m| m.id));
    }
}
