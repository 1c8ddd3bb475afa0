//! Whether a physics preset's parts agree before it runs (issue 41 item 6):
//! `gaitlab validate` builds the driver, so a preset it accepts starts without
//! a blow-up from these causes, and one it refuses names the field.
//!
//! - the contact point is the foot's effector (`legs[i].foot_point_m` against
//!   the skeleton's effector on the foot joint: one edited without the other
//!   puts the simulated foot where none is drawn);
//! - the foot is carried by the leg's spring (the foot joint is the spring
//!   joint or below it), as Raibert & Hodgins' legs are;
//! - every body at the end of a chain has mass and inertia (a massless leaf
//!   makes the articulated inertia singular), and a free trunk has both;
//! - at the start, no foot is below the ground, and the lowest foot is within
//!   one leg length of it (a creature dropped from higher lands on its trunk).

use gaitlab_core::preset::{Creature as PresetCreature, PhysicsParams, PresetError};
use glam::DVec3;

use crate::creatures::PhysicalCreature;
use crate::dynamics::data::Data;
use crate::world::ground::Terrain;

/// How far a foot may start below the ground, metres at scale 1 (the ground
/// spring's own give under standing weight is a few millimetres).
const BELOW_GROUND_TOLERANCE_M: f64 = 0.005;

/// Effector and contact point agree within this, metres.
const SAME_POINT_M: f64 = 1e-9;

/// The structural rules: foot point against effector, foot under spring,
/// mass on every leaf body.
///
/// # Errors
/// The first rule broken, naming the field to change.
pub fn check_structure(preset: &PresetCreature, params: &PhysicsParams) -> Result<(), PresetError> {
    let skeleton = &preset.skeleton;
    for (i, leg) in params.legs.iter().enumerate() {
        let at = |f: &str| format!("scenario.physics.legs[{i}].{f}");
        let (Some(foot), Some(spring)) = (
            skeleton.joint_index(&leg.foot),
            skeleton.joint_index(&leg.spring),
        ) else {
            continue; // named joints are checked where the model is built
        };
        let point = DVec3::from_array(leg.foot_point_m);
        let effectors: Vec<(usize, DVec3)> = skeleton
            .effectors()
            .iter()
            .enumerate()
            .filter(|(_, e)| e.joint == foot)
            .map(|(k, e)| (k, e.offset))
            .collect();
        if !effectors.is_empty()
            && !effectors
                .iter()
                .any(|(_, offset)| (*offset - point).length() <= SAME_POINT_M)
        {
            let (k, offset) = effectors[0];
            return Err(PresetError::new(
                at("foot_point_m"),
                format!(
                    "the contact point [{}, {}, {}] is not the foot's effector ({} at [{}, {}, {}] on joint \"{}\"): change both together",
                    point.x,
                    point.y,
                    point.z,
                    skeleton.effectors()[k].name,
                    offset.x,
                    offset.y,
                    offset.z,
                    leg.foot
                ),
            ));
        }
        let mut carried = Some(foot);
        while let Some(j) = carried {
            if j == spring {
                break;
            }
            carried = skeleton.joints()[j].parent;
        }
        if carried.is_none() {
            return Err(PresetError::new(
                at("foot"),
                format!(
                    "the foot's joint \"{}\" is not the spring \"{}\" or below it: the leg's spring must carry the foot",
                    leg.foot, leg.spring
                ),
            ));
        }
    }
    let joints = skeleton.joints();
    for (j, joint) in joints.iter().enumerate() {
        let leaf = !joints.iter().any(|k| k.parent == Some(j));
        if !leaf {
            continue;
        }
        let body = params.bodies.iter().position(|b| b.joint == joint.name);
        let massive = body.is_some_and(|b| {
            let m = &params.bodies[b].mass;
            m.mass_kg > 0.0 && m.inertia_kgm2.iter().any(|&i| i > 0.0)
        });
        if !massive {
            let path = body.map_or_else(
                || "scenario.physics.bodies".to_owned(),
                |b| format!("scenario.physics.bodies[{b}]"),
            );
            return Err(PresetError::new(
                path,
                format!(
                    "joint \"{}\" ends a chain and moves a body without mass or inertia: list it with mass_kg and inertia_kgm2 above 0",
                    joint.name
                ),
            ));
        }
    }
    if let Some(trunk) = &params.trunk
        && !(trunk.mass_kg > 0.0 && trunk.inertia_kgm2.iter().all(|&i| i > 0.0))
    {
        return Err(PresetError::new(
            "scenario.physics.trunk",
            "a free trunk needs mass_kg and all three inertia_kgm2 above 0",
        ));
    }
    Ok(())
}

/// The start rule: every foot at or above the ground, the lowest within one
/// leg length of it, with the creature in its start state (`data` after
/// kinematics).
///
/// # Errors
/// Naming the foot's contact point, with how far below or above it starts.
pub fn check_start(
    creature: &PhysicalCreature,
    data: &Data,
    terrain: &Terrain,
) -> Result<(), PresetError> {
    let l = creature.scale;
    let mut lowest: Option<(usize, f64)> = None;
    for (i, leg) in creature.legs.iter().enumerate() {
        let p = data.point_world(leg.foot_body, leg.foot_point);
        let height = p.y - terrain.height(p.x, p.z);
        if height < -BELOW_GROUND_TOLERANCE_M * l {
            return Err(PresetError::new(
                format!("scenario.physics.legs[{i}].foot_point_m"),
                format!(
                    "the foot starts {:.3} m below the ground (raise skeleton.root.position or shorten the leg)",
                    -height / l
                ),
            ));
        }
        if lowest.is_none_or(|(_, h)| height < h) {
            lowest = Some((i, height));
        }
    }
    if let Some((i, height)) = lowest {
        let reach = creature.legs[i].length_m;
        if height > reach {
            return Err(PresetError::new(
                "skeleton.root.position",
                format!(
                    "the lowest foot starts {:.3} m above the ground, more than its leg's length ({:.3} m): the creature would drop onto its trunk",
                    height / l,
                    reach / l
                ),
            ));
        }
    }
    Ok(())
}
