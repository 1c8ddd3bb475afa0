//! The terrain's MJCF (issue 45 item 5) read back by an independent XML
//! reader: a ray straight down through the written boxes meets each plane
//! and flight of stairs at `Terrain::height_m` to 1e-9 m at 100 points; a
//! height field's elevations are 0–1, and MuJoCo's reading of them (its
//! XML's first row at the geom's local +y, turned onto −z) puts every
//! sample at its gaitlab height; the floor is the physics export's own line.
//! (`tools/terrain_mujoco_check.py` loads the same files in MuJoCo itself.)

use gaitlab_core::terrain::{HeightField, Plane, Stairs, Terrain, to_mjcf};
use glam::{DQuat, DVec3};

fn next(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

fn numbers(text: &str) -> Vec<f64> {
    text.split_whitespace()
        .map(|v| v.parse().expect("a number"))
        .collect()
}

fn v3(text: &str) -> DVec3 {
    let v = numbers(text);
    DVec3::new(v[0], v[1], v[2])
}

/// The written `<asset>` children and worldbody geoms.
fn geoms(terrain: &Terrain) -> (String, String) {
    let m = to_mjcf(terrain);
    (m.asset, m.geoms)
}

/// Where a ray down from high above (x, z) first meets a box (the slab
/// test in the box's frame), or `None`.
fn ray_down_on_box(centre: DVec3, half: DVec3, rotation: DQuat, x: f64, z: f64) -> Option<f64> {
    let top = 1000.0;
    let inverse = rotation.inverse();
    let origin = inverse * (DVec3::new(x, top, z) - centre);
    let direction = inverse * DVec3::NEG_Y;
    let (mut near, mut far) = (f64::NEG_INFINITY, f64::INFINITY);
    for axis in 0..3 {
        let (o, d, h) = (origin[axis], direction[axis], half[axis]);
        if d.abs() < 1e-15 {
            if o.abs() > h {
                return None;
            }
            continue;
        }
        let (a, b) = ((-h - o) / d, (h - o) / d);
        near = near.max(a.min(b));
        far = far.min(a.max(b));
    }
    (near <= far && near >= 0.0).then_some(top - near)
}

fn ground_of_boxes(xml: &str, x: f64, z: f64) -> f64 {
    let text = format!("<w>{xml}</w>");
    let doc = roxmltree::Document::parse(&text).expect("well-formed geoms");
    doc.descendants()
        .filter(|n| n.has_tag_name("geom"))
        .filter_map(|g| {
            assert_eq!(g.attribute("type"), Some("box"));
            let q = numbers(g.attribute("quat").expect("quat"));
            let rotation = DQuat::from_xyzw(q[1], q[2], q[3], q[0]);
            assert!((rotation.length() - 1.0).abs() < 1e-12, "a unit quaternion");
            ray_down_on_box(
                v3(g.attribute("pos").expect("pos")),
                v3(g.attribute("size").expect("size")),
                rotation,
                x,
                z,
            )
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

#[test]
fn planes_and_stairs_are_boxes_whose_tops_are_the_ground() {
    let terrains = [
        Terrain::Plane(Plane {
            slope_deg: 10.0,
            direction_deg: 0.0,
        }),
        Terrain::Plane(Plane {
            slope_deg: -10.0,
            direction_deg: 200.0,
        }),
        Terrain::Plane(Plane {
            slope_deg: 35.0,
            direction_deg: 300.0,
        }),
        Terrain::Stairs(Stairs {
            rise_m: 0.05,
            run_m: 0.3,
            count: 5,
            direction_deg: 0.0,
            start_m: 0.5,
        }),
        Terrain::Stairs(Stairs {
            rise_m: -0.03,
            run_m: 0.2,
            count: 8,
            direction_deg: 135.0,
            start_m: -0.6,
        }),
    ];
    let mut state = 3_u64;
    for terrain in &terrains {
        let (asset, xml) = geoms(terrain);
        assert!(asset.is_empty());
        let mut worst = 0.0_f64;
        for _ in 0..100 {
            let (x, z) = (-3.0 + 6.0 * next(&mut state), -3.0 + 6.0 * next(&mut state));
            worst = worst.max((ground_of_boxes(&xml, x, z) - terrain.height_m(x, z)).abs());
        }
        assert!(worst < 1e-9, "{terrain:?}: the boxes' top is {worst} m off");
    }
}

#[test]
fn a_height_field_is_normalised_and_lies_where_mujoco_reads_it() {
    let mut state = 5_u64;
    let (rows, cols) = (7, 11);
    let field = HeightField {
        cell_m: 0.2,
        cols,
        rows,
        origin_m: Some([-0.7, 0.4]),
        heights_m: (0..rows * cols)
            .map(|_| 0.05 + 0.3 * next(&mut state))
            .collect(),
        friction: None,
    };
    let (asset, xml) = geoms(&Terrain::HeightField(field.clone()));
    let text = format!("<w>{asset}{xml}</w>");
    let doc = roxmltree::Document::parse(&text).expect("well-formed");
    let hfield = doc
        .descendants()
        .find(|n| n.has_tag_name("hfield"))
        .expect("an hfield asset");
    assert_eq!(hfield.attribute("nrow"), Some("7"));
    assert_eq!(hfield.attribute("ncol"), Some("11"));
    let size = numbers(hfield.attribute("size").expect("size"));
    let elevation = numbers(hfield.attribute("elevation").expect("elevation"));
    assert_eq!(elevation.len(), rows * cols);
    let (lo, hi) = elevation
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &e| {
            (a.min(e), b.max(e))
        });
    assert_eq!((lo, hi), (0.0, 1.0), "normalised as MuJoCo requires");
    let geom = doc
        .descendants()
        .find(|n| n.attribute("type") == Some("hfield"))
        .expect("the hfield geom");
    assert_eq!(geom.attribute("zaxis"), Some("0 1 0"));
    let pos = v3(geom.attribute("pos").expect("pos"));
    // MuJoCo's reading: XML row k, column c lies at local
    // (−size₀ + c·dx, size₁ − k·dy), height pos.y + size₂·e; local +y is world −z.
    let (dx, dy) = (
        2.0 * size[0] / (cols - 1) as f64,
        2.0 * size[1] / (rows - 1) as f64,
    );
    let mut worst = 0.0_f64;
    for k in 0..rows {
        for c in 0..cols {
            let (lx, ly) = (-size[0] + dx * c as f64, size[1] - dy * k as f64);
            // A hair inside, so the grid's last line is not read as off the grid.
            let inside = 1.0 - 1e-12;
            let (x, z) = (pos.x + lx * inside, pos.z - ly * inside);
            let height = pos.y + size[2] * elevation[k * cols + c];
            worst = worst.max((height - field.height_m(x, z)).abs());
        }
    }
    assert!(worst < 1e-9, "samples {worst} m off");
    // The floor stays under and around it.
    assert!(xml.contains("name=\"floor\""));
}

#[test]
fn the_floor_is_the_physics_exports_line() {
    let (asset, xml) = geoms(&Terrain::Flat);
    assert!(asset.is_empty());
    assert_eq!(
        xml,
        "    <geom name=\"floor\" type=\"plane\" size=\"50 50 0.1\" zaxis=\"0 1 0\" contype=\"1\" conaffinity=\"1\" rgba=\"0.3 0.33 0.36 1\"/>\n"
    );
}

#[test]
fn a_field_of_one_height_is_a_box() {
    let field = HeightField {
        cell_m: 0.5,
        cols: 3,
        rows: 3,
        origin_m: None,
        heights_m: vec![0.12; 9],
        friction: None,
    };
    let (asset, xml) = geoms(&Terrain::HeightField(field.clone()));
    assert!(asset.is_empty(), "no hfield of zero elevation");
    let top = ground_of_boxes(
        &xml.lines()
            .filter(|l| l.contains("type=\"box\""))
            .collect::<String>(),
        0.1,
        -0.2,
    );
    assert!((top - 0.12).abs() < 1e-12, "the box's top {top}");
}
