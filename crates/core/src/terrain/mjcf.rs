//! The terrain as MuJoCo geoms (issue 45 item 5), in gaitlab's axes (y up,
//! as the MJCF export keeps them): the floor as MuJoCo's `plane`; a sloped
//! plane and each stair tread as a `box` whose top face is the ground; a
//! height field as an `hfield` asset with its heights normalised to 0–1
//! (MuJoCo scales them by the size's elevation and lifts them by the geom's
//! position) and its geom turned z → +y (`zaxis="0 1 0"`), which turns the
//! field's local +y onto −z. The XML's first row of elevations lies at local
//! +y (MuJoCo's compiler stores the rows in reverse, its row 0 at −y), so the
//! rows are written in gaitlab's own order: row 0 at the lowest z. MuJoCo's
//! split of each cell is then the one [`super::HeightField`] uses (checked in
//! MuJoCo itself by `tools/terrain_mujoco_check.py`). Numbers are written so they read back to the
//! same `f64`.
//!
//! Extent: boxes reach [`EXTENT_M`] beyond the stairs' ends and the origin
//! on every side (the floor plane's drawn size); a height field keeps the
//! floor under and around it. Per-cell friction has no MuJoCo counterpart
//! on one hfield and is not written.

use std::fmt::Write as _;

use glam::{DQuat, DVec3};

use super::direction::ground_direction;
use super::{HeightField, Plane, Stairs, Terrain};
use crate::export::text::write_round_trip;

/// How far the written ground reaches, metres (half the side of the floor
/// plane as drawn, and of a plane's or stairs' boxes across).
pub const EXTENT_M: f64 = 50.0;

/// How deep the boxes reach below the lowest ground they carry, metres.
const BOX_DEPTH_M: f64 = 1.0;

/// The hfield's base below its lowest sample, metres (MuJoCo's `size[3]`).
const HFIELD_BASE_M: f64 = 0.1;

/// The floor as the physics export has always written it.
const FLOOR: &str = "    <geom name=\"floor\" type=\"plane\" size=\"50 50 0.1\" zaxis=\"0 1 0\" contype=\"1\" conaffinity=\"1\" rgba=\"0.3 0.33 0.36 1\"/>\n";

/// The ground's colour (the floor's).
const RGBA: &str = "0.3 0.33 0.36 1";

/// A terrain's MJCF: what goes in `<asset>` (empty when nothing) and the
/// geoms that go in `<worldbody>`, each line indented for its place.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TerrainMjcf {
    /// The `<asset>` element's children (an `hfield`), or empty.
    pub asset: String,
    /// The ground's geoms.
    pub geoms: String,
}

fn num(x: f64) -> String {
    let mut s = String::new();
    let _ = write_round_trip(&mut s, if x == 0.0 { 0.0 } else { x });
    s
}

fn v3(v: DVec3) -> String {
    format!("{} {} {}", num(v.x), num(v.y), num(v.z))
}

/// MJCF's `quat` (w x y z).
fn quat(q: DQuat) -> String {
    format!("{} {} {} {}", num(q.w), num(q.x), num(q.y), num(q.z))
}

/// The turn about +y that takes +x onto the ground heading `direction_deg`.
fn heading(direction_deg: f64) -> DQuat {
    let d = ground_direction(direction_deg);
    // +x turned by φ about +y is (cos φ, 0, −sin φ): φ = atan2(−d.z, d.x).
    let (half_sin, half_cos) = half_angle(-d.z, d.x);
    DQuat::from_xyzw(0.0, half_sin, 0.0, half_cos)
}

/// sin and cos of half the angle whose sine and cosine are `s` and `c`
/// (a unit pair), without trigonometry: cos(φ/2) = √((1 + c)/2).
fn half_angle(s: f64, c: f64) -> (f64, f64) {
    let half_cos = (0.5 * (1.0 + c)).max(0.0).sqrt();
    if half_cos > 1e-9 {
        (s / (2.0 * half_cos), half_cos)
    } else {
        (1.0, 0.0)
    }
}

fn geom_box(out: &mut String, name: &str, centre: DVec3, half: DVec3, rotation: DQuat) {
    let _ = writeln!(
        out,
        "    <geom name=\"{name}\" type=\"box\" pos=\"{}\" size=\"{}\" quat=\"{}\" contype=\"1\" conaffinity=\"1\" rgba=\"{RGBA}\"/>",
        v3(centre),
        v3(half),
        quat(rotation),
    );
}

/// The MJCF of `terrain`.
#[must_use]
pub fn to_mjcf(terrain: &Terrain) -> TerrainMjcf {
    let mut m = TerrainMjcf::default();
    match terrain {
        Terrain::Flat => m.geoms.push_str(FLOOR),
        Terrain::Plane(plane) => plane_box(&mut m.geoms, plane),
        Terrain::Stairs(stairs) => stair_boxes(&mut m.geoms, stairs),
        Terrain::HeightField(field) => {
            m.geoms.push_str(FLOOR);
            height_field(&mut m, field);
        }
        Terrain::Rough(rough) => {
            m.geoms.push_str(FLOOR);
            height_field(&mut m, rough.field());
        }
    }
    m
}

/// One box whose top face is the plane through the origin: turned by the
/// slope α about +z (taking +y onto (−sin α, cos α, 0)), then onto the
/// heading, which takes +y onto the plane's normal.
fn plane_box(out: &mut String, plane: &Plane) {
    let n = plane.normal();
    let d = ground_direction(plane.direction_deg);
    let (sin_a, cos_a) = (-(n.x * d.x + n.z * d.z), n.y);
    let (half_sin, half_cos) = half_angle(sin_a, cos_a);
    let tilt = DQuat::from_xyzw(0.0, 0.0, half_sin, half_cos);
    let rotation = heading(plane.direction_deg) * tilt;
    let half = DVec3::new(EXTENT_M, 0.5 * BOX_DEPTH_M, EXTENT_M);
    geom_box(out, "ground", -0.5 * BOX_DEPTH_M * n, half, rotation);
}

/// One box per level of the flight: before the first riser, each tread,
/// and the top, laid along the heading.
fn stair_boxes(out: &mut String, stairs: &Stairs) {
    let d = ground_direction(stairs.direction_deg);
    let rotation = heading(stairs.direction_deg);
    let count = stairs.count;
    let top = stairs.rise_m * f64::from(count);
    let bottom = 0.0_f64.min(top) - BOX_DEPTH_M;
    let riser = |k: u32| stairs.start_m + stairs.run_m * f64::from(k);
    for level in 0..=count {
        // Level k spans from riser k (k − 1 treads past the first riser) to riser k + 1.
        let from = if level == 0 {
            stairs.start_m.min(0.0) - EXTENT_M
        } else {
            riser(level - 1)
        };
        let to = if level == count {
            riser(count - 1) + EXTENT_M
        } else {
            riser(level)
        };
        let height = stairs.rise_m * f64::from(level);
        let mid = 0.5 * (from + to);
        let centre = DVec3::new(d.x * mid, 0.5 * (height + bottom), d.z * mid);
        let half = DVec3::new(0.5 * (to - from), 0.5 * (height - bottom), EXTENT_M);
        geom_box(out, &format!("stair{level}"), centre, half, rotation);
    }
}

/// The `hfield` asset and its geom; a field of one height is a box.
fn height_field(m: &mut TerrainMjcf, field: &HeightField) {
    let (low, high) = field
        .heights_m
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &h| {
            (lo.min(h), hi.max(h))
        });
    let [x0, z0] = field.origin();
    let size_x = 0.5 * field.cell_m * (field.cols.saturating_sub(1)) as f64;
    let size_z = 0.5 * field.cell_m * (field.rows.saturating_sub(1)) as f64;
    let centre = DVec3::new(x0 + size_x, low, z0 + size_z);
    let span = high - low;
    if !span.is_finite() || span <= 0.0 {
        let half = DVec3::new(size_x, 0.5 * (low.max(0.0) + HFIELD_BASE_M), size_z);
        let at = DVec3::new(centre.x, 0.5 * (low.max(0.0) - HFIELD_BASE_M), centre.z);
        geom_box(&mut m.geoms, "terrain", at, half, DQuat::IDENTITY);
        return;
    }
    let mut elevation = String::new();
    for row in 0..field.rows {
        for col in 0..field.cols {
            let h = field.heights_m[row * field.cols + col];
            if !elevation.is_empty() {
                elevation.push(' ');
            }
            elevation.push_str(&num((h - low) / span));
        }
    }
    let _ = writeln!(
        m.asset,
        "    <hfield name=\"terrain\" nrow=\"{}\" ncol=\"{}\" size=\"{} {} {} {}\" elevation=\"{elevation}\"/>",
        field.rows,
        field.cols,
        num(size_x),
        num(size_z),
        num(span),
        num(HFIELD_BASE_M),
    );
    let _ = writeln!(
        m.geoms,
        "    <geom name=\"terrain\" type=\"hfield\" hfield=\"terrain\" pos=\"{}\" zaxis=\"0 1 0\" contype=\"1\" conaffinity=\"1\" rgba=\"{RGBA}\"/>",
        v3(centre),
    );
}
