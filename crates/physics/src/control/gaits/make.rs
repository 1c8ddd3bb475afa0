//! Building a gait's controller from a preset's physics section (Raibert &
//! Hodgins 1991, "Gaits": which state machine drives each gait of each
//! model): the preset's speed, hop height and obstacles, its controller
//! parameters by name, and the lab's additions resolved against what each
//! controller offers.

use std::collections::BTreeMap;

use gaitlab_core::preset::{PhysicsParams, PresetError};

use crate::control::additions::{Additions, Offered};
use crate::control::gaits::biped_gallop::BipedGallop;
use crate::control::gaits::biped_gallop::params::{BipedGallopParams, GallopStyle};
use crate::control::gaits::biped_run::BipedRun;
use crate::control::gaits::biped_run::params::BipedRunParams;
use crate::control::gaits::bound::QuadrupedBound;
use crate::control::gaits::bound::params::{BoundStyle, QuadrupedBoundParams};
use crate::control::gaits::controller::{GaitController, gait_names};
use crate::control::gaits::kangaroo_hop::KangarooHop;
use crate::control::gaits::kangaroo_hop::params::KangarooHopParams;
use crate::control::gaits::parameters::NamedParameters;
use crate::control::gaits::trot::QuadrupedRun;
use crate::control::gaits::trot::params::QuadrupedRunParams;
use crate::control::laws::hop_height::flight_for_height;
use crate::creatures::{PhysicalCreature, Species};
use crate::world::sim::Controller;

/// `p` with the preset's controller parameters set by name: those of
/// every gait (`scenario.physics.controller`), then this gait's own
/// (`scenario.physics.controller_by_gait.GAIT`).
///
/// # Errors
/// The path of a name the gait's controller lacks.
fn with_parameters<P: NamedParameters>(
    mut p: P,
    params: &PhysicsParams,
    gait: &str,
) -> Result<P, PresetError> {
    let mut set = |values: &BTreeMap<String, f64>, at: &dyn Fn() -> String| {
        for (name, &value) in values {
            if !p.set_parameter(name, value) {
                return Err(PresetError::new(
                    format!("scenario.physics.{}.{name}", at()),
                    format!(
                        "the {gait} controller has no such parameter (it has: {})",
                        P::NAMES.join(", ")
                    ),
                ));
            }
        }
        Ok(())
    };
    set(&params.controller, &|| "controller".to_owned())?;
    if let Some(own) = params.controller_by_gait.get(gait) {
        set(own, &|| format!("controller_by_gait.{gait}"))?;
    }
    Ok(p)
}

/// Whether every gait `controller_by_gait` and `switch_to_start` name is
/// one of the model's.
///
/// # Errors
/// `scenario.physics.controller_by_gait.NAME` or
/// `scenario.physics.switch_to_start[I]` for a gait the model lacks.
fn known_gaits(creature: &PhysicalCreature, params: &PhysicsParams) -> Result<(), PresetError> {
    let names = gait_names(creature.species);
    let unknown = |g: &String| !names.contains(&g.as_str());
    let by_gait = params
        .controller_by_gait
        .keys()
        .find(|g| unknown(g))
        .map(|g| format!("scenario.physics.controller_by_gait.{g}"));
    let to_start = || {
        params
            .switch_to_start
            .iter()
            .position(unknown)
            .map(|i| format!("scenario.physics.switch_to_start[{i}]"))
    };
    match by_gait.or_else(to_start) {
        Some(path) => Err(PresetError::new(
            path,
            format!("this model has no such gait (it has: {})", names.join(", ")),
        )),
        None => Ok(()),
    }
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
    known_gaits(creature, params)?;
    let made = match (creature.species, gait) {
        (Species::Biped, "run") => biped_run(creature, params),
        (Species::Biped, "gallop") => biped_gallop(creature, params, GallopStyle::TogetherSwing),
        (Species::Biped, "gallop_alternate") => {
            biped_gallop(creature, params, GallopStyle::AlternateSwing)
        }
        (Species::Quadruped, "trot") => trot(creature, params),
        (Species::Quadruped, "bound") => bound(creature, params, BoundStyle::Bound),
        (Species::Quadruped, "gallop") => bound(creature, params, BoundStyle::Gallop),
        (Species::Kangaroo, "hop") => kangaroo_hop(creature, params),
        _ => {
            let names = gait_names(creature.species);
            return Err(PresetError::new(
                "scenario.physics.gait",
                format!(
                    "unknown gait \"{gait}\" (this model has: {})",
                    names.join(", ")
                ),
            ));
        }
    };
    made.map_err(|e| match e {
        Misfit::Legs(needs) => PresetError::new("scenario.physics.legs", needs),
        Misfit::Preset(e) => e,
    })
}

/// Why a gait's controller cannot be built: legs that do not fit it (what
/// it needs), or a preset field.
enum Misfit {
    Legs(&'static str),
    Preset(PresetError),
}

impl From<PresetError> for Misfit {
    fn from(e: PresetError) -> Self {
        Misfit::Preset(e)
    }
}

/// The lab's additions the preset asks of a controller offering `offered`.
fn additions(params: &PhysicsParams, offered: Offered) -> Additions {
    Additions::resolve(params.lab_additions.as_ref(), offered)
}

/// Whether `creature` has `count` legs with `hip_joints` hip joints each;
/// else what the gait `needs`.
fn legs(
    creature: &PhysicalCreature,
    count: usize,
    hip_joints: usize,
    needs: &'static str,
) -> Result<(), Misfit> {
    let fits =
        creature.legs.len() == count && creature.legs.iter().all(|leg| leg.hip.len() == hip_joints);
    if fits {
        Ok(())
    } else {
        Err(Misfit::Legs(needs))
    }
}

/// The biped's two legs with ball hips.
fn biped_legs(creature: &PhysicalCreature) -> Result<(), Misfit> {
    legs(
        creature,
        2,
        3,
        "the biped gaits need two legs with three hip joints each",
    )
}

/// The quadruped's four legs with two hip joints each.
fn quadruped_legs(creature: &PhysicalCreature) -> Result<(), Misfit> {
    legs(
        creature,
        4,
        2,
        "the quadruped gaits need four legs with two hip joints each",
    )
}

fn biped_run(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
) -> Result<GaitController, Misfit> {
    biped_legs(creature)?;
    let additions = additions(params, Offered::BIPED_RUN);
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
    let mut p = with_parameters(p, params, "run")?;
    p.unloading_posture = additions.unloading_posture;
    p.speed_trim = additions.speed_trim;
    Ok(GaitController::BipedRun(Box::new(BipedRun::new(
        p, creature,
    ))))
}

fn biped_gallop(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    style: GallopStyle,
) -> Result<GaitController, Misfit> {
    biped_legs(creature)?;
    let d = BipedGallopParams::default();
    let p = BipedGallopParams {
        speed_mps: params.speed_mps,
        hop_height_m: params.hop_height_m.unwrap_or(d.hop_height_m),
        style,
        ..d
    };
    let gait = match style {
        GallopStyle::TogetherSwing => "gallop",
        GallopStyle::AlternateSwing => "gallop_alternate",
    };
    let mut p = with_parameters(p, params, gait)?;
    p.speed_trim = additions(params, Offered::BIPED_GALLOP).speed_trim;
    Ok(GaitController::BipedGallop(Box::new(BipedGallop::new(
        p, creature,
    ))))
}

fn trot(creature: &PhysicalCreature, params: &PhysicsParams) -> Result<GaitController, Misfit> {
    quadruped_legs(creature)?;
    let p = QuadrupedRunParams {
        speed_mps: params.speed_mps,
        ..QuadrupedRunParams::default()
    };
    let mut c = QuadrupedRun::new(with_parameters(p, params, "trot")?, creature);
    if let Some(h) = params.hop_height_m {
        c.set_hop_height(h);
    }
    Ok(GaitController::Quadruped(Box::new(c)))
}

fn bound(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
    style: BoundStyle,
) -> Result<GaitController, Misfit> {
    quadruped_legs(creature)?;
    let p = QuadrupedBoundParams {
        speed_mps: params.speed_mps,
        style,
        ..QuadrupedBoundParams::default()
    };
    let mut p = with_parameters(p, params, style.name())?;
    p.speed_trim = additions(params, Offered::BOUND).speed_trim;
    if let Some(h) = params.hop_height_m {
        p.stride_flight_s = flight_for_height(h);
    }
    Ok(GaitController::QuadrupedBound(Box::new(
        QuadrupedBound::new(p, creature),
    )))
}

fn kangaroo_hop(
    creature: &PhysicalCreature,
    params: &PhysicsParams,
) -> Result<GaitController, Misfit> {
    let fits = creature.legs.len() == 1
        && creature.legs[0].knee.is_some()
        && creature.legs[0].hip.len() == 1
        && creature.tail.len() == 3
        && creature.neck.is_some()
        && creature.model.joint_count() >= 10;
    if !fits {
        return Err(Misfit::Legs(
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
    let mut p = with_parameters(p, params, "hop")?;
    let additions = additions(params, Offered::KANGAROO_HOP);
    p.speed_trim = additions.speed_trim;
    p.speed_ramp = additions.speed_ramp;
    p.tail_feedback = additions.tail_feedback;
    Ok(GaitController::Kangaroo(Box::new(KangarooHop::new(p))))
}
