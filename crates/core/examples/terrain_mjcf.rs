//! Writes sample terrains as MuJoCo models, with gaitlab's heights at 100
//! points on each, for `tools/terrain_mujoco_check.py` to ray-cast in MuJoCo
//! (issue 45 item 5): `cargo run --release -p gaitlab-core --example
//! terrain_mjcf -- OUT_DIR` writes `OUT_DIR/NAME.xml` per terrain and prints
//! one JSON object: name → `[[x, z, height_m], …]`.

use std::fmt::Write as _;

use gaitlab_core::terrain::{HeightField, Plane, Stairs, Terrain, to_mjcf};

/// Uniform in [0, 1), from a fixed sequence (the same points every run).
fn next(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

fn terrains() -> Vec<(&'static str, Terrain)> {
    let mut state = 7_u64;
    let mut field = |rows: usize, cols: usize, origin: Option<[f64; 2]>| HeightField {
        cell_m: 0.25,
        cols,
        rows,
        origin_m: origin,
        heights_m: (0..rows * cols).map(|_| 0.2 * next(&mut state)).collect(),
        friction: None,
    };
    let field_a = field(17, 21, None);
    let field_b = field(13, 9, Some([-0.4, 0.3]));
    vec![
        ("flat", Terrain::Flat),
        (
            "slope-up-10",
            Terrain::Plane(Plane {
                slope_deg: 10.0,
                direction_deg: 0.0,
            }),
        ),
        (
            "slope-down-10-at-200",
            Terrain::Plane(Plane {
                slope_deg: -10.0,
                direction_deg: 200.0,
            }),
        ),
        (
            "stairs-5cm",
            Terrain::Stairs(Stairs {
                rise_m: 0.05,
                run_m: 0.3,
                count: 5,
                direction_deg: 0.0,
                start_m: 0.5,
            }),
        ),
        (
            "stairs-3cm-at-90",
            Terrain::Stairs(Stairs {
                rise_m: 0.03,
                run_m: 0.2,
                count: 8,
                direction_deg: 90.0,
                start_m: -0.6,
            }),
        ),
        (
            "stairs-down-at-135",
            Terrain::Stairs(Stairs {
                rise_m: -0.05,
                run_m: 0.25,
                count: 6,
                direction_deg: 135.0,
                start_m: 0.2,
            }),
        ),
        ("field-21x17", Terrain::HeightField(field_a)),
        ("field-9x13-offset", Terrain::HeightField(field_b)),
    ]
}

fn main() -> Result<(), String> {
    let out = std::env::args()
        .nth(1)
        .ok_or("usage: terrain_mjcf OUT_DIR")?;
    let mut json = String::from("{");
    let mut state = 11_u64;
    for (i, (name, terrain)) in terrains().into_iter().enumerate() {
        terrain.check().map_err(|e| format!("{name}: {e}"))?;
        let mjcf = to_mjcf(&terrain);
        let mut xml = format!("<mujoco model=\"{name}\">\n");
        if !mjcf.asset.is_empty() {
            let _ = write!(xml, "  <asset>\n{}  </asset>\n", mjcf.asset);
        }
        let _ = write!(
            xml,
            "  <worldbody>\n{}  </worldbody>\n</mujoco>\n",
            mjcf.geoms
        );
        let path = format!("{out}/{name}.xml");
        std::fs::write(&path, xml).map_err(|e| format!("{path}: {e}"))?;
        let points: Vec<String> = (0..100)
            .map(|_| {
                let x = -3.0 + 6.0 * next(&mut state);
                let z = -3.0 + 6.0 * next(&mut state);
                format!("[{x},{z},{}]", terrain.height_m(x, z))
            })
            .collect();
        if i > 0 {
            json.push(',');
        }
        let _ = write!(json, "\"{name}\":[{}]", points.join(","));
    }
    json.push('}');
    println!("{json}");
    Ok(())
}
