//! PODA's feet on ground that is not flat (issue 45 item 2 — the lab's
//! addition: Girard & Maciejewski 1985's creatures walk on a floor, and on
//! flat ground every rule here gives the paper's figures bit for bit):
//!
//! - **Footholds** (eq. 11's spot, lifted onto the surface): a spot is
//!   acceptable when the ground within [`EDGE_MARGIN_M`] of it is no steeper
//!   than [`MAX_FOOTHOLD_SLOPE_DEG`] (eight samples on a circle): a stair's
//!   riser nearby, a slope too steep or a bump under the foot fails it. An
//!   unacceptable spot moves to the nearest acceptable one found on rings
//!   [`SEARCH_STEP_M`] apart, eight directions each, up to
//!   [`SEARCH_RINGS`] rings out — the search kinematic foothold planners make
//!   around their nominal foothold; none found, the foot lands on the spot.
//! - **Transfers**: the foot's height is the lift-off's and the foothold's
//!   blended along the transfer, plus the spline's height fraction of the
//!   step height raised by how far the highest ground between them rises
//!   above that blend — so the apex clears the highest ground between them
//!   by the step height — and never below the highest ground still between
//!   the foot and its foothold: stepping up, the foot rises above the next
//!   tread before it reaches the riser, so no frame, nor the straight line
//!   between two frames, passes through it.
//! - **The ground under the body**: each leg's ground point — its planted
//!   foot in support, blended from its lift-off point to its foothold along
//!   the transfer — gives the least-squares line of ground height against
//!   fore-aft position in the body's ground frame; its height at the root
//!   and its slope are added to eq. 12–13's height and pitch.
//! - **The gait's motion within the legs' reach** (the IK stage,
//!   `stages/ik.rs`): where the legs cannot follow the body at the planned
//!   height and pitch — a planted foot not held, or a transferring foot left
//!   below the ground, because a leg folds to its joints' limits — the frame
//!   is solved again with eq. 12–13's bob and Figure 2's pitch eased toward
//!   the body standing on the ground under the legs (the stand height above
//!   the line at the root, the line's pitch), keeping the largest fraction
//!   of them at which every foot holds (bisection, 1/64). The bound on the
//!   floor pitches the body ±16° and moves the root between 0.35 and 0.64 m
//!   about its 0.5 m stand, a front elbow already at its limit; a 10° slope
//!   or a tread adds what the leg cannot fold. On the floor the rule does
//!   not act.

use gaitlab_core::terrain::Terrain;
use glam::{DVec2, DVec3};

/// How far around a foothold the ground must be even, metres.
pub const EDGE_MARGIN_M: f64 = 0.03;
/// The steepest ground a foot lands on, degrees.
pub const MAX_FOOTHOLD_SLOPE_DEG: f64 = 30.0;
/// The distance between the foothold search's rings, metres.
pub const SEARCH_STEP_M: f64 = 0.01;
/// The foothold search's rings (so it looks up to 0.12 m from the spot).
pub const SEARCH_RINGS: u32 = 12;
/// Samples of the ground between lift-off and foothold for the clearance.
const CLEARANCE_SAMPLES: u32 = 24;
/// tan(30°): the rise per metre of [`MAX_FOOTHOLD_SLOPE_DEG`].
const MAX_RISE_PER_M: f64 = 0.577_350_269_189_625_8;
/// Slack on the evenness test for rounding, metres.
const EVEN_SLACK_M: f64 = 1e-4;

/// Eight unit directions on the ground plane, 45° apart.
const DIRECTIONS: [DVec2; 8] = {
    let s = std::f64::consts::FRAC_1_SQRT_2;
    [
        DVec2::new(1.0, 0.0),
        DVec2::new(s, s),
        DVec2::new(0.0, 1.0),
        DVec2::new(-s, s),
        DVec2::new(-1.0, 0.0),
        DVec2::new(-s, -s),
        DVec2::new(0.0, -1.0),
        DVec2::new(s, -s),
    ]
};

/// Where a foot lands: the spot eq. 11 planned and the one it takes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Foothold {
    /// Eq. 11's spot on the surface, world metres.
    pub nominal: DVec3,
    /// The spot the foot takes, world metres (the nominal one where it is
    /// acceptable).
    pub chosen: DVec3,
    /// Whether the nominal spot was unacceptable and the foot moved.
    pub moved: bool,
}

/// Whether a foot may land at `(x, z)`: the ground within
/// [`EDGE_MARGIN_M`] is no steeper than [`MAX_FOOTHOLD_SLOPE_DEG`].
#[must_use]
pub fn acceptable(terrain: &Terrain, x: f64, z: f64) -> bool {
    let h = terrain.height_m(x, z);
    let limit = MAX_RISE_PER_M * EDGE_MARGIN_M + EVEN_SLACK_M;
    DIRECTIONS.iter().all(|d| {
        let at = DVec2::new(x, z) + EDGE_MARGIN_M * *d;
        (terrain.height_m(at.x, at.y) - h).abs() <= limit
    })
}

/// The foothold for eq. 11's spot `(x, z)`: on the surface, moved to the
/// nearest acceptable spot where it is not acceptable (module docs).
#[must_use]
pub fn foothold(terrain: &Terrain, x: f64, z: f64) -> Foothold {
    let on = |x: f64, z: f64| DVec3::new(x, terrain.height_m(x, z), z);
    let nominal = on(x, z);
    if terrain.is_flat() || acceptable(terrain, x, z) {
        return Foothold {
            nominal,
            chosen: nominal,
            moved: false,
        };
    }
    for ring in 1..=SEARCH_RINGS {
        let r = SEARCH_STEP_M * f64::from(ring);
        for d in DIRECTIONS {
            let at = DVec2::new(x, z) + r * d;
            if acceptable(terrain, at.x, at.y) {
                return Foothold {
                    nominal,
                    chosen: on(at.x, at.y),
                    moved: true,
                };
            }
        }
    }
    Foothold {
        nominal,
        chosen: nominal,
        moved: false,
    }
}

/// The highest ground on the straight line from `a` to `b` (world, its
/// ends included), metres.
#[must_use]
pub fn highest_between(terrain: &Terrain, a: DVec3, b: DVec3) -> f64 {
    if terrain.is_flat() {
        return 0.0;
    }
    (0..=CLEARANCE_SAMPLES)
        .map(|k| {
            let p = a.lerp(b, f64::from(k) / f64::from(CLEARANCE_SAMPLES));
            terrain.height_m(p.x, p.z)
        })
        .fold(a.y.max(b.y), f64::max)
}

/// A transferring foot's height: `along` and `height` are the transfer
/// spline's fractions, `liftoff_m` and `foothold_m` the ground heights at
/// its ends, `highest_m` the highest ground between them. The base height
/// runs from the lift-off's to the foothold's along the transfer; the
/// spline's height fraction lifts the foot above it by the step height plus
/// what the highest ground rises above the base, so the apex (height
/// fraction 1) is the step height above the highest ground. On flat ground
/// `height · step_m`, exactly.
#[must_use]
pub fn transfer_height_m(
    along: f64,
    height: f64,
    step_m: f64,
    liftoff_m: f64,
    foothold_m: f64,
    highest_m: f64,
) -> f64 {
    let base = liftoff_m + along * (foothold_m - liftoff_m);
    base + height * (step_m + (highest_m - base).max(0.0))
}

/// The ground under the legs from each leg's `(z, h)`: its fore-aft
/// position in the body's ground frame and its ground height, metres. The
/// least-squares line `h = a + slope · z` through them, as its height at the
/// root (`z = 0`) and its slope; legs all at one `z` give their mean height
/// and no slope.
#[must_use]
pub fn ground_under(legs: impl Iterator<Item = (f64, f64)> + Clone) -> (f64, f64) {
    let (mut n, mut z_sum, mut h_sum) = (0.0, 0.0, 0.0);
    for (z, h) in legs.clone() {
        n += 1.0;
        z_sum += z;
        h_sum += h;
    }
    if n == 0.0 {
        return (0.0, 0.0);
    }
    let (z_mean, h_mean) = (z_sum / n, h_sum / n);
    let (mut zz, mut zh) = (0.0, 0.0);
    for (z, h) in legs {
        zz += (z - z_mean) * (z - z_mean);
        zh += (z - z_mean) * (h - h_mean);
    }
    let slope = if zz > 1e-12 { zh / zz } else { 0.0 };
    (h_mean - slope * z_mean, slope)
}
