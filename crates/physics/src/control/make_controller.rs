//! Building a gait's controller from a preset's physics section (Raibert &
//! Hodgins 1991, "Gaits": which state machine drives each gait of each
//! model): the preset's speed, hop height and obstacles, its controller
//! parameters by name, and the lab's additions resolved against what each
//! controller offers.

use gaitlab_core::preset::{PhysicsParams, PresetError};

use crate::control::additions::Additions;
use crate::control::biped_gallop::BipedGallop;
use crate::control::biped_gallop_params::{BipedGallopParams, GallopStyle};
use crate::control::biped_run::BipedRun;
use crate::control::biped_run_params::BipedRunParams;
use crate::control::gait_controller::{GaitController, gait_names};
use crate::control::hop_height::flight_for_height;
use crate::control::kangaroo_hop::KangarooHop;
use crate::control::kangaroo_hop_params::KangarooHopParams;
use crate::control::parameters::NamedParameters;
use crate::control::quadruped_bound::QuadrupedBound;
use crate::control::quadruped_bound_params::{BoundStyle, QuadrupedBoundParams};
use crate::control::quadruped_run::QuadrupedRun;
use crate::control::quadruped_run_params::QuadrupedRunParams;
use crate::creatures::{PhysicalCreature, Species};
use crate::world::sim::Controller;

/// `p` with the preset's controller parameters (`scenario.physics.controller`)
/// set by name.
///
/// # Errors
/// `scenario.physics.controller.NAME` for a name the gait's controller lacks.
fn with_parameters<P: NamedParameters>(
    mut p: P,
    params: &PhysicsParams,
    gait: &str,
) -> Result<P, PresetError> {
    for (name, &value) in &params.controller {
        if !p.set_parameter(name, value) {
            return Err(PresetError::new(
                format!("scenario.physics.controller.{name}"),
                format!(
                    "the {gait} controller has no such parameter (it has: {})",
                    P::NAMES.join(", ")
                ),
            ));
        }
    }
    Ok(p)
}

/// The controller of `gait` for `creature`, with `params`' speed, hop height,
/// obstacles, controller parameters and the lab's additions (which win over
/// a controller parameter they zero).
///
/// # Errors
/// `scenario.physics.gait` for a gait the model lacks; `scenario.physics.legs`
/// when the legs do not fit the gait's controller; `scenario.physics.controller.NAME`
/// for a parameter it does not have.
pub fn make_controller(
    creature: &PhysicalCreature,
    gait: &str,
    params: &PhysicsParams,
) -> Result<GaitController, PresetError> {
    let bad = || {
        let names = gait_names(creature.species);
        PresetError::new(
            "scenario.physics.gait",
            format!(
                "unknown gait \"{gait}\" (this model has: {})",
                names.join(", ")
            ),
        )
    };
    let additions = |offered| Additions::resolve(params.lab_additions.as_ref(), offered);
    let two_ball_legs =
        creature.legs.len() == 2 && creature.legs.iter().all(|leg| leg.hip.len() == 3);
    let biped_needs = || {
        PresetError::new(
            "scenario.physics.legs",
            "the biped gaits need two legs with three hip joints each",
        )
    };
    match (creature.species, gait) {
        (Species::Biped, "run") => {
            if !two_ball_legs {
                return Err(biped_needs());
            }
            let additions = additions(BipedRunParams::LAB_ADDITIONS);
            let d = if additions.legacy {
                BipedRunParams::before_lab_additions()
            } else {
                BipedRunParams::default()
            };
            let p = BipedRunParams {
                speed_mps: params.speed_mps,
                hop_height_m: params.hop_height_m.unwrap_or(d.hop_height_m),
                ..d
            };
            let mut p = with_parameters(p, params, gait)?;
            p.unloading_posture = additions.unloading_posture;
            p.speed_trim = additions.speed_trim;
            Ok(GaitController::BipedRun(Box::new(BipedRun::new(
                p, creature,
            ))))
        }
        (Species::Biped, "gallop" | "gallop_alternate") => {
            if !two_ball_legs {
                return Err(biped_needs());
            }
            let d = BipedGallopParams::default();
            let style = if gait == "gallop" {
                GallopStyle::TogetherSwing
            } else {
                GallopStyle::AlternateSwing
            };
            let p = BipedGallopParams {
                speed_mps: params.speed_mps,
                hop_height_m: params.hop_height_m.unwrap_or(d.hop_height_m),
                style,
                ..d
            };
            let mut p = with_parameters(p, params, gait)?;
            p.speed_trim = additions(BipedGallopParams::LAB_ADDITIONS).speed_trim;
            Ok(GaitController::BipedGallop(Box::new(BipedGallop::new(
                p, creature,
            ))))
        }
        (Species::Quadruped, "trot" | "bound" | "gallop") => {
            if creature.legs.len() != 4 || creature.legs.iter().any(|leg| leg.hip.len() != 2) {
                return Err(PresetError::new(
                    "scenario.physics.legs",
                    "the quadruped gaits need four legs with two hip joints each",
                ));
            }
            if gait == "trot" {
                let p = QuadrupedRunParams {
                    speed_mps: params.speed_mps,
                    ..QuadrupedRunParams::default()
                };
                let p = with_parameters(p, params, gait)?;
                let mut c = QuadrupedRun::new(p, creature);
                if let Some(h) = params.hop_height_m {
                    c.set_hop_height(h);
                }
                return Ok(GaitController::Quadruped(Box::new(c)));
            }
            let style = if gait == "bound" {
                BoundStyle::Bound
            } else {
                BoundStyle::Gallop
            };
            let p = QuadrupedBoundParams {
                speed_mps: params.speed_mps,
                style,
                ..QuadrupedBoundParams::default()
            };
            let mut p = with_parameters(p, params, gait)?;
            p.speed_trim = additions(QuadrupedBoundParams::LAB_ADDITIONS).speed_trim;
            if let Some(h) = params.hop_height_m {
                p.stride_flight_s = flight_for_height(h);
            }
            Ok(GaitController::QuadrupedBound(Box::new(
                QuadrupedBound::new(p, creature),
            )))
        }
        (Species::Kangaroo, "hop") => {
            let ok = creature.legs.len() == 1
                && creature.legs[0].knee.is_some()
                && creature.legs[0].hip.len() == 1
                && creature.tail.len() == 3
                && creature.neck.is_some()
                && creature.model.joint_count() >= 10;
            if !ok {
                return Err(PresetError::new(
                    "scenario.physics.legs",
                    "the kangaroo hop needs a planar base, one leg with hip, knee and ankle, a three-joint tail and a neck",
                ));
            }
            let d = KangarooHopParams::default();
            let obstacle = params.obstacles.first();
            let p = KangarooHopParams {
                speed_mps: params.speed_mps,
                hop_rise_m: params.hop_height_m.unwrap_or(d.hop_rise_m),
                jump_at_m: obstacle.map(|o| o.at_m),
                obstacle_height_m: obstacle.map_or(d.obstacle_height_m, |o| o.height_m),
                obstacle_depth_m: obstacle.map_or(d.obstacle_depth_m, |o| o.depth_m),
                ..d
            };
            let mut p = with_parameters(p, params, gait)?;
            let additions = additions(KangarooHopParams::LAB_ADDITIONS);
            p.speed_trim = additions.speed_trim;
            p.speed_ramp = additions.speed_ramp;
            p.tail_feedback = additions.tail_feedback;
            Ok(GaitController::Kangaroo(Box::new(KangarooHop::new(p))))
        }
        _ => Err(bad()),
    }
}
