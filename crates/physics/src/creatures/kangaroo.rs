//! The planar kangaroo of Table 3 and Figure 5: trunk, one leg (thigh, shin,
//! foot; the toe joint removed), a three-link tail and a head, moving in the
//! sagittal plane on a 3-DOF planar base (Raibert & Hodgins 1991, "Kangaroo
//! control"). Every joint turns about the lateral axis (gaitlab x).
//!
//! Table 3's location rows lost their signs in the source text; the hip and
//! tail are read as behind the trunk's centre of mass (−0.11 m and −0.2 m
//! forward) and the head in front (+0.21 m), as Figure 5 draws them. Link
//! inertias are given about the lateral axis only; the planar model needs no
//! other, so the other two axes repeat that value.

use glam::{DMat3, DVec3};

use super::build::{Builder, paper};
use super::physical_creature::{Leg, PhysicalCreature, Species};
use crate::dynamics::model::{Joint, Model, ModelError};

/// One link of Table 3: length, mass centre from the proximal joint (m),
/// mass (kg), moment of inertia about the lateral axis (kg·m²).
struct Link {
    length: f64,
    com: f64,
    mass: f64,
    inertia: f64,
}

const TRUNK_MASS_KG: f64 = 3.67;
const TRUNK_INERTIA: f64 = 0.034;
const THIGH: Link = Link {
    length: 0.13,
    com: 0.064,
    mass: 1.62,
    inertia: 0.0039,
};
const SHIN: Link = Link {
    length: 0.26,
    com: 0.105,
    mass: 0.60,
    inertia: 0.0033,
};
const FOOT: Link = Link {
    length: 0.174,
    com: 0.082,
    mass: 0.14,
    inertia: 0.00038,
};
const TAIL: [Link; 3] = [
    Link {
        length: 0.166,
        com: 0.079,
        mass: 0.24,
        inertia: 0.00058,
    },
    Link {
        length: 0.166,
        com: 0.071,
        mass: 0.14,
        inertia: 0.00033,
    },
    Link {
        length: 0.166,
        com: 0.076,
        mass: 0.069,
        inertia: 0.00016,
    },
];
const HEAD_MASS_KG: f64 = 0.33;
const HEAD_INERTIA: f64 = 0.00046;
/// Head mass centre from the neck: forward, up (m).
const HEAD_COM_M: [f64; 2] = [0.04, 0.04];
/// Joint locations from the trunk's centre of mass, forward (m).
const HIP_FORWARD_M: f64 = -0.11;
const HEAD_FORWARD_M: f64 = 0.21;
const TAIL_FORWARD_M: f64 = -0.2;

fn planar_inertia(i: f64) -> DMat3 {
    DMat3::from_diagonal(DVec3::splat(i))
}

/// The kangaroo at dynamic scale `l`. Leg links hang down (−y) at zero
/// angle, tail links point back (−z).
///
/// # Errors
/// The model check's error for a non-positive or non-finite `l`.
pub fn kangaroo(l: f64) -> Result<PhysicalCreature, ModelError> {
    let mut b = Builder::new(l);
    let forward = b.link(
        "base-forward",
        None,
        Joint::Prismatic(DVec3::Z),
        DVec3::ZERO,
    );
    let up = b.link(
        "base-up",
        Some(forward),
        Joint::Prismatic(DVec3::Y),
        DVec3::ZERO,
    );
    let trunk = b.body(
        "trunk",
        Some(up),
        Joint::Revolute(DVec3::X),
        DVec3::ZERO,
        TRUNK_MASS_KG,
        DVec3::ZERO,
        planar_inertia(TRUNK_INERTIA),
    );
    let down = |x: f64| paper(0.0, 0.0, -x);
    let hip_at = paper(HIP_FORWARD_M, 0.0, 0.0);
    let thigh = b.body(
        "thigh",
        Some(trunk),
        Joint::Revolute(DVec3::X),
        hip_at,
        THIGH.mass,
        down(THIGH.com),
        planar_inertia(THIGH.inertia),
    );
    let shin = b.body(
        "shin",
        Some(thigh),
        Joint::Revolute(DVec3::X),
        down(THIGH.length),
        SHIN.mass,
        down(SHIN.com),
        planar_inertia(SHIN.inertia),
    );
    let foot = b.body(
        "foot",
        Some(shin),
        Joint::Revolute(DVec3::X),
        down(SHIN.length),
        FOOT.mass,
        down(FOOT.com),
        planar_inertia(FOOT.inertia),
    );
    let mut parent = trunk;
    let mut at = paper(TAIL_FORWARD_M, 0.0, 0.0);
    for (k, link) in TAIL.iter().enumerate() {
        let back = |x: f64| paper(-x, 0.0, 0.0);
        parent = b.body(
            &format!("tail{}", k + 1),
            Some(parent),
            Joint::Revolute(DVec3::X),
            at,
            link.mass,
            back(link.com),
            planar_inertia(link.inertia),
        );
        at = back(link.length);
    }
    let _neck_body = b.body(
        "head",
        Some(trunk),
        Joint::Revolute(DVec3::X),
        paper(HEAD_FORWARD_M, 0.0, 0.0),
        HEAD_MASS_KG,
        paper(HEAD_COM_M[0], 0.0, HEAD_COM_M[1]),
        planar_inertia(HEAD_INERTIA),
    );
    // Coordinates: 0 forward, 1 up, 2 trunk pitch, 3 hip, 4 knee, 5 ankle,
    // 6–8 tail, 9 neck.
    let legs = vec![Leg {
        name: "leg".to_owned(),
        hip: vec![3],
        spring: 5,
        knee: Some(4),
        foot_body: foot,
        foot_point: down(FOOT.length) * l,
        hip_in_trunk: hip_at * l,
        length_m: 0.0,
    }];
    Ok(PhysicalCreature::new(
        Species::Kangaroo,
        l,
        Model::new(b.bodies)?,
        trunk,
        legs,
        vec![6, 7, 8],
        Some(9),
    ))
}
