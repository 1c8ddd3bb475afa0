//! The terrain model (issue 45 item 1): each kind's height and normal, the
//! normal against a finite-difference gradient of the height, the height
//! field's triangles against an independent reading of MuJoCo's hfield
//! triangle strip (rows reversed and turned onto −z, as an export lays the
//! field), and bad values named by their field.

use gaitlab_core::terrain::{HeightField, Plane, Stairs, Terrain};
use glam::DVec3;

/// xorshift in [0, 1).
fn next(state: &mut u64) -> f64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

/// The normal from central differences of the height, `h` apart.
fn numeric_normal(terrain: &Terrain, x: f64, z: f64, h: f64) -> DVec3 {
    let gx = (terrain.height_m(x + h, z) - terrain.height_m(x - h, z)) / (2.0 * h);
    let gz = (terrain.height_m(x, z + h) - terrain.height_m(x, z - h)) / (2.0 * h);
    DVec3::new(-gx, 1.0, -gz).normalize()
}

#[test]
fn flat_and_plane_heights_and_normals() {
    let flat = Terrain::Flat;
    assert_eq!(flat.height_m(3.0, -2.0), 0.0);
    assert_eq!(flat.normal(3.0, -2.0), DVec3::Y);
    let tan10 = libm::tan(10f64.to_radians());
    for (direction_deg, along) in [(0.0, DVec3::X), (90.0, DVec3::Z), (180.0, -DVec3::X)] {
        let plane = Terrain::Plane(Plane {
            slope_deg: 10.0,
            direction_deg,
        });
        let up = plane.height_m(along.x, along.z);
        assert!((up - tan10).abs() < 1e-12, "{direction_deg}: {up}");
        assert!(plane.height_m(-along.x, -along.z) + tan10 < 1e-12);
        let n = plane.normal(0.3, 0.7);
        assert!((n.length() - 1.0).abs() < 1e-12);
        assert!(n.dot(along) < 0.0, "the normal leans downhill");
        assert!((n.y - libm::cos(10f64.to_radians())).abs() < 1e-12);
        assert!(n.distance(numeric_normal(&plane, 0.3, 0.7, 1e-4)) < 1e-9);
    }
}

#[test]
fn stairs_have_level_treads_and_risers_where_they_should() {
    let stairs = Stairs {
        rise_m: 0.05,
        run_m: 0.3,
        count: 5,
        direction_deg: 0.0,
        start_m: 1.0,
    };
    let t = Terrain::Stairs(stairs.clone());
    for (x, h) in [
        (-5.0, 0.0),
        (0.99, 0.0),
        (1.0, 0.05),
        (1.15, 0.05),
        (1.35, 0.10),
        (2.19, 0.2),
        (2.21, 0.25),
        (40.0, 0.25),
    ] {
        assert!(
            (t.height_m(x, 7.0) - h).abs() < 1e-12,
            "x {x}: {}",
            t.height_m(x, 7.0)
        );
    }
    assert_eq!(t.normal(1.1, 0.0), DVec3::Y);
    assert!(stairs.riser_between([0.9, 0.0], [1.1, 0.0]));
    assert!(!stairs.riser_between([1.05, 0.0], [1.25, 0.0]));
    assert!(
        !stairs.riser_between([3.0, 0.0], [9.0, 0.0]),
        "past the top"
    );
    // Climbing toward +z instead.
    let north = Terrain::Stairs(Stairs {
        direction_deg: 90.0,
        ..stairs
    });
    assert!((north.height_m(0.0, 1.35) - 0.10).abs() < 1e-12);
    assert_eq!(north.height_m(1.35, 0.0), 0.0);
}

fn field(state: &mut u64, rows: usize, cols: usize) -> HeightField {
    HeightField {
        cell_m: 0.25,
        cols,
        rows,
        origin_m: Some([-0.4, 0.3]),
        heights_m: (0..rows * cols).map(|_| 0.2 * next(state)).collect(),
        friction: Some(
            (0..(rows - 1) * (cols - 1))
                .map(|i| i as f64 * 0.1)
                .collect(),
        ),
    }
}

/// MuJoCo's reading of the same field, written independently: the data
/// rows reversed (its local y is gaitlab's −z), local coordinates about the
/// grid's centre, and each cell the strip's two triangles {(c, r+1), (c, r),
/// (c+1, r+1)} and {(c, r), (c+1, r+1), (c+1, r)}; the height is the plane
/// through the triangle holding the point.
fn mujoco_height(f: &HeightField, x: f64, z: f64) -> f64 {
    let (nrow, ncol) = (f.rows, f.cols);
    let data = |r: usize, c: usize| f.heights_m[(nrow - 1 - r) * ncol + c];
    let [x0, z0] = f.origin();
    let size0 = 0.5 * f.cell_m * (ncol - 1) as f64;
    let size1 = 0.5 * f.cell_m * (nrow - 1) as f64;
    let (cx, cz) = (x0 + size0, z0 + size1);
    let (lx, ly) = (x - cx, -(z - cz));
    let (dx, dy) = (
        2.0 * size0 / (ncol - 1) as f64,
        2.0 * size1 / (nrow - 1) as f64,
    );
    let c = (((lx + size0) / dx).floor() as usize).min(ncol - 2);
    let r = (((ly + size1) / dy).floor() as usize).min(nrow - 2);
    let vertex =
        |c: usize, r: usize| DVec3::new(dx * c as f64 - size0, dy * r as f64 - size1, data(r, c));
    let (a, b, cc, d) = (
        vertex(c, r + 1),
        vertex(c, r),
        vertex(c + 1, r + 1),
        vertex(c + 1, r),
    );
    let inside = |p: DVec3, q: DVec3, s: DVec3| {
        let sign = |u: DVec3, v: DVec3| (lx - v.x) * (u.y - v.y) - (u.x - v.x) * (ly - v.y);
        let (d1, d2, d3) = (sign(p, q), sign(q, s), sign(s, p));
        !((d1 < -1e-12 || d2 < -1e-12 || d3 < -1e-12) && (d1 > 1e-12 || d2 > 1e-12 || d3 > 1e-12))
    };
    let (p, q, s) = if inside(a, b, cc) {
        (a, b, cc)
    } else {
        (b, cc, d)
    };
    let n = (q - p).cross(s - p);
    // Plane through p with normal n, solved for the height at (lx, ly).
    p.z - (n.x * (lx - p.x) + n.y * (ly - p.y)) / n.z
}

#[test]
fn a_height_field_splits_its_cells_as_mujoco_does() {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let f = field(&mut state, 5, 7);
    let t = Terrain::HeightField(f.clone());
    let [x0, z0] = f.origin();
    // At the samples, the data.
    for r in 0..f.rows {
        for c in 0..f.cols {
            let (x, z) = (x0 + c as f64 * f.cell_m, z0 + r as f64 * f.cell_m);
            assert!((t.height_m(x, z) - f.heights_m[r * f.cols + c]).abs() < 1e-12);
        }
    }
    // A cell's centre lies on the diagonal u + w = 1: the mean of the
    // samples (1, 0) and (0, 1), not of (0, 0) and (1, 1).
    let (x, z) = (x0 + 1.5 * f.cell_m, z0 + 2.5 * f.cell_m);
    let h = |r: usize, c: usize| f.heights_m[r * f.cols + c];
    assert!((t.height_m(x, z) - 0.5 * (h(2, 2) + h(3, 1))).abs() < 1e-12);
    assert!((0.5 * (h(2, 1) + h(3, 2)) - 0.5 * (h(2, 2) + h(3, 1))).abs() > 1e-3);
    // Anywhere on the grid: MuJoCo's triangles give the same height, and
    // the normal is the height's gradient.
    let mut worst = 0.0_f64;
    let mut normals = 0;
    for _ in 0..2000 {
        let x = x0 + next(&mut state) * (f.cols - 1) as f64 * f.cell_m;
        let z = z0 + next(&mut state) * (f.rows - 1) as f64 * f.cell_m;
        worst = worst.max((t.height_m(x, z) - mujoco_height(&f, x, z)).abs());
        // Away from the cell's edges and diagonal, one triangle's plane.
        let (u, w) = (((x - x0) / f.cell_m).fract(), ((z - z0) / f.cell_m).fract());
        if u.min(w).min(1.0 - u).min(1.0 - w) > 0.01 && (u + w - 1.0).abs() > 0.01 {
            let n = numeric_normal(&t, x, z, 1e-5);
            assert!(t.normal(x, z).distance(n) < 1e-6, "normal at ({x}, {z})");
            normals += 1;
        }
    }
    assert!(worst < 1e-12, "MuJoCo's split differs by {worst} m");
    assert!(normals > 1000);
    // Off the grid: the floor.
    assert_eq!(t.height_m(x0 - 0.01, z0), 0.0);
    assert_eq!(t.normal(x0 - 0.01, z0), DVec3::Y);
    // Friction per cell: cell (row 1, column 2) is index 1 × 6 + 2.
    let mu = t.friction(x0 + 2.5 * f.cell_m, z0 + 1.5 * f.cell_m);
    assert!(mu.is_some_and(|m| (m - 0.8).abs() < 1e-12), "{mu:?}");
    assert_eq!(Terrain::Flat.friction(0.0, 0.0), None);
}

#[test]
fn bad_terrains_name_their_field() {
    let mut state = 7_u64;
    let good = field(&mut state, 3, 4);
    assert_eq!(Terrain::HeightField(good.clone()).check(), Ok(()));
    let bad = |f: HeightField| Terrain::HeightField(f).check().err().map(|e| e.field);
    let mut nan = good.clone();
    nan.heights_m[5] = f64::NAN;
    assert_eq!(bad(nan).as_deref(), Some("heights_m[5]"));
    let mut below = good.clone();
    below.heights_m[2] = -0.1;
    assert_eq!(bad(below).as_deref(), Some("heights_m[2]"));
    let empty = HeightField {
        rows: 0,
        heights_m: vec![],
        ..good.clone()
    };
    assert_eq!(bad(empty).as_deref(), Some("rows"));
    let huge = HeightField {
        rows: 31_623,
        cols: 31_623,
        heights_m: vec![],
        friction: None,
        ..good.clone()
    };
    let error = Terrain::HeightField(huge).check().err();
    assert!(
        error
            .as_ref()
            .is_some_and(|e| e.field == "rows" && e.reason.contains("at most")),
        "{error:?}"
    );
    let short = HeightField {
        heights_m: vec![0.0; 11],
        ..good.clone()
    };
    assert_eq!(bad(short).as_deref(), Some("heights_m"));
    let friction = HeightField {
        friction: Some(vec![0.5; 2]),
        ..good.clone()
    };
    assert_eq!(bad(friction).as_deref(), Some("friction"));
    let zero_cell = HeightField {
        cell_m: 0.0,
        ..good
    };
    assert_eq!(bad(zero_cell).as_deref(), Some("cell_m"));
    let steep = Terrain::Plane(Plane {
        slope_deg: 80.0,
        direction_deg: 0.0,
    });
    assert_eq!(
        steep.check().err().map(|e| e.field).as_deref(),
        Some("slope_deg")
    );
    let stairs = Stairs {
        rise_m: 0.05,
        run_m: 0.3,
        count: 0,
        direction_deg: 0.0,
        start_m: 1.0,
    };
    assert_eq!(
        Terrain::Stairs(stairs.clone())
            .check()
            .err()
            .map(|e| e.field)
            .as_deref(),
        Some("count")
    );
    let flat_tread = Stairs {
        count: 3,
        run_m: 0.0,
        ..stairs
    };
    let error = Terrain::Stairs(flat_tread).check().err();
    assert_eq!(
        error
            .as_ref()
            .map(|e| e.path("scenario.terrain"))
            .as_deref(),
        Some("scenario.terrain.run_m")
    );
}

#[test]
fn terrain_json_is_tagged_by_kind() {
    let stairs: Terrain =
        serde_json::from_str(r#"{"kind": "stairs", "rise_m": 0.05, "run_m": 0.3, "count": 5}"#)
            .unwrap_or_else(|e| panic!("{e}"));
    assert!(matches!(&stairs, Terrain::Stairs(s) if s.start_m == 1.0 && s.direction_deg == 0.0));
    let text = serde_json::to_string(&stairs).unwrap_or_default();
    assert_eq!(serde_json::from_str::<Terrain>(&text).ok(), Some(stairs));
    let flat: Terrain =
        serde_json::from_str(r#"{"kind": "flat"}"#).unwrap_or_else(|e| panic!("{e}"));
    assert!(flat.is_flat());
    for bad in [
        r#"{"kind": "lava"}"#,
        r#"{"kind": "plane", "slope_deg": 5, "tilt": 1}"#,
        r#"{"rise_m": 0.05}"#,
    ] {
        assert!(serde_json::from_str::<Terrain>(bad).is_err(), "{bad}");
    }
}

#[test]
fn rough_ground_is_the_same_from_the_same_seed_and_scales_with_difficulty() {
    let parse = |json: &str| -> Terrain { serde_json::from_str(json).expect(json) };
    let a = parse(r#"{"kind": "rough", "seed": 7, "difficulty": 0.5}"#);
    let b = parse(r#"{"kind": "rough", "seed": 7, "difficulty": 0.5}"#);
    let other = parse(r#"{"kind": "rough", "seed": 8, "difficulty": 0.5}"#);
    let flat = parse(r#"{"kind": "rough", "seed": 7, "difficulty": 0}"#);
    let full = parse(r#"{"kind": "rough", "seed": 7, "difficulty": 1}"#);
    for t in [&a, &other, &flat, &full] {
        t.check().expect("valid rough ground");
    }
    assert_eq!(a, b);
    let Terrain::Rough(rough) = &a else {
        panic!("a rough terrain");
    };
    let field = rough.field();
    assert_eq!(
        (field.cols, field.rows),
        (121, 481),
        "6 × 24 m in 0.05 m cells"
    );
    let mut state = 21_u64;
    let (mut differ, mut highest) = (0_u32, 0.0_f64);
    for _ in 0..2000 {
        let (x, z) = (
            -3.0 + 6.0 * next(&mut state),
            -2.0 + 24.0 * next(&mut state),
        );
        let h = a.height_m(x, z);
        assert_eq!(
            h.to_bits(),
            b.height_m(x, z).to_bits(),
            "the same seed, the same ground"
        );
        assert!(
            (0.0..=0.5 * 0.08 + 1e-12).contains(&h),
            "height {h} at difficulty 0.5"
        );
        assert!(
            (full.height_m(x, z) - 2.0 * h).abs() < 1e-12,
            "difficulty scales the heights"
        );
        assert_eq!(flat.height_m(x, z), 0.0, "difficulty 0 is flat");
        differ += u32::from((other.height_m(x, z) - h).abs() > 1e-3);
        highest = highest.max(h);
    }
    assert!(
        differ > 1000,
        "another seed, another ground: {differ} of 2000 points differ"
    );
    assert!(highest > 0.03, "bumps near their height: {highest} m");
    // Faded to the floor at the border: no step walking off the patch.
    for x in [-3.0, 0.0, 2.99] {
        assert!(a.height_m(x, -2.0).abs() < 1e-12 && a.height_m(x, 22.0).abs() < 1e-12);
    }
    // JSON keeps the parameters, not the heights.
    let written = serde_json::to_string(&a).expect("serialises");
    assert!(
        written.len() < 300 && !written.contains("heights"),
        "{written}"
    );
    assert_eq!(parse(&written), a);
}

#[test]
fn bad_rough_ground_names_its_field() {
    for (json, field) in [
        (r#"{"kind": "rough", "difficulty": 1.5}"#, "difficulty"),
        (r#"{"kind": "rough", "difficulty": -0.1}"#, "difficulty"),
        (
            r#"{"kind": "rough", "difficulty": 0.5, "cell_m": 0}"#,
            "cell_m",
        ),
        (
            r#"{"kind": "rough", "difficulty": 0.5, "cell_m": 0.001}"#,
            "cell_m",
        ),
        (
            r#"{"kind": "rough", "difficulty": 0.5, "size_m": [1e9, 1]}"#,
            "size_m[0]",
        ),
        (
            r#"{"kind": "rough", "difficulty": 0.5, "max_height_m": 1000}"#,
            "max_height_m",
        ),
    ] {
        let terrain: Terrain = serde_json::from_str(json).expect(json);
        let error = terrain.check().expect_err(json);
        assert_eq!(error.field, field, "{json}: {error}");
    }
    let nan: Result<Terrain, _> = serde_json::from_str(r#"{"kind": "rough", "difficulty": NaN}"#);
    assert!(nan.is_err(), "NaN is not JSON");
}
