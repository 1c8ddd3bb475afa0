//! The gait controllers a physics driver runs: which of Raibert & Hodgins
//! 1991's state machines drives each gait of each model ("Gaits"), how each
//! is built from a preset's physics section, and the state it starts from.

use gaitlab_core::preset::{PhysicsParams, PresetError};

use crate::control::additions::Additions;
use crate::control::biped_gallop::BipedGallop;
use crate::control::biped_gallop_params::{BipedGallopParams, GallopStyle};
use crate::control::biped_run::BipedRun;
use crate::control::biped_run_params::BipedRunParams;
use crate::control::hop_height::flight_for_height;
use crate::control::kangaroo_hop::{KangarooHop, kangaroo_start};
use crate::control::kangaroo_hop_params::KangarooHopParams;
use crate::control::parameters::NamedParameters;
use crate::control::quadruped_bound::{QuadrupedBound, bound_start};
use crate::control::quadruped_bound_params::{BoundStyle, QuadrupedBoundParams};
use crate::control::quadruped_run::{QuadrupedRun, quadruped_start};
use crate::control::quadruped_run_params::QuadrupedRunParams;
use crate::creatures::{PhysicalCreature, Species};
use crate::world::sim::{Controller, Sim};

/// The gaits of each model, the default first.
#[must_use]
pub fn gait_names(species: Species) -> &'static [&'static str] {
    match species {
        Species::Biped => &["run", "gallop", "gallop_alternate"],
        Species::Quadruped => &["trot", "bound", "gallop"],
        Species::Kangaroo => &["hop"],
    }
}

/// With the lab's speed ramp, the kangaroo starts no faster than this (m/s
/// at scale 1) and its controller ramps to the desired speed: started at
/// 5 m/s it tumbles.
pub const KANGAROO_START_MPS: f64 = 2.0;

/// The controller of the gait running: one of the paper's state machines.
/// (One lives per driver, so the variants' differing sizes do not matter.)
#[derive(Clone, Debug)]
pub enum GaitController {
    /// Biped running (Figure 4).
    BipedRun(Box<BipedRun>),
    /// Biped galloping, either style.
    BipedGallop(Box<BipedGallop>),
    /// Quadruped trot on virtual legs.
    Quadruped(Box<QuadrupedRun>),
    /// Quadruped bound or gallop: front and rear pairs as a planar biped.
    QuadrupedBound(Box<QuadrupedBound>),
    /// The kangaroo's hop.
    Kangaroo(Box<KangarooHop>),
}

impl GaitController {
    /// The lab's additions this controller runs with (its parameters'
    /// flags, resolved when it was made).
    #[must_use]
    pub fn additions(&self) -> Additions {
        let none = Additions::resolve(
            Some(&gaitlab_core::preset::physics::LabAdditions::default()),
            crate::control::additions::Offered::NONE,
        );
        match self {
            GaitController::BipedRun(c) => Additions {
                speed_trim: c.params.speed_trim,
                unloading_posture: c.params.unloading_posture,
                ..none
            },
            GaitController::BipedGallop(c) => Additions {
                speed_trim: c.params.speed_trim,
                ..none
            },
            GaitController::Quadruped(_) => none,
            GaitController::QuadrupedBound(c) => Additions {
                speed_trim: c.params.speed_trim,
                ..none
            },
            GaitController::Kangaroo(c) => Additions {
                speed_trim: c.params.speed_trim,
                speed_ramp: c.params.speed_ramp,
                tail_feedback: c.params.tail_feedback,
                ..none
            },
        }
    }

    fn inner(&self) -> &dyn Controller {
        match self {
            GaitController::BipedRun(c) => c.as_ref(),
            GaitController::BipedGallop(c) => c.as_ref(),
            GaitController::Quadruped(c) => c.as_ref(),
            GaitController::QuadrupedBound(c) => c.as_ref(),
            GaitController::Kangaroo(c) => c.as_ref(),
        }
    }

    fn inner_mut(&mut self) -> &mut dyn Controller {
        match self {
            GaitController::BipedRun(c) => c.as_mut(),
            GaitController::BipedGallop(c) => c.as_mut(),
            GaitController::Quadruped(c) => c.as_mut(),
            GaitController::QuadrupedBound(c) => c.as_mut(),
            GaitController::Kangaroo(c) => c.as_mut(),
        }
    }
}

impl Controller for GaitController {
    fn control(
        &mut self,
        input: &crate::world::sim::ControlInput<'_>,
        drives: &mut [crate::world::sim::Drive],
    ) {
        self.inner_mut().control(input, drives);
    }

    fn servo(
        &mut self,
        input: &crate::world::sim::ControlInput<'_>,
        drives: &mut [crate::world::sim::Drive],
    ) {
        self.inner_mut().servo(input, drives);
    }

    fn phase_name(&self) -> &'static str {
        self.inner().phase_name()
    }

    fn leg_phase_name(&self, leg: usize) -> Option<&'static str> {
        self.inner().leg_phase_name(leg)
    }

    fn set_speed(&mut self, speed_mps: f64) {
        self.inner_mut().set_speed(speed_mps);
    }

    fn set_heading(&mut self, heading: f64) {
        self.inner_mut().set_heading(heading);
    }

    fn set_hop_height(&mut self, height_m: f64) {
        self.inner_mut().set_hop_height(height_m);
    }

    fn hop_height_m(&self) -> Option<f64> {
        self.inner().hop_height_m()
    }

    fn gains(&self) -> Vec<crate::world::sim::Gain> {
        self.inner().gains()
    }

    fn set_gain(&mut self, name: &str, value: f64) -> bool {
        self.inner_mut().set_gain(name, value)
    }
}

/// Put `sim` in the starting state of `controller` where it has its own:
/// the quadruped just above standing height, the kangaroo just before a
/// landing at no more than [`KANGAROO_START_MPS`] (its controller ramps to
/// the rest); other creatures keep the preset's rest pose.
pub fn start_state(sim: &mut Sim, controller: &GaitController, speed_mps: f64) {
    match controller {
        GaitController::Quadruped(_) => quadruped_start(sim, speed_mps),
        GaitController::QuadrupedBound(_) => bound_start(sim, speed_mps),
        GaitController::Kangaroo(c) if c.params.speed_ramp => {
            kangaroo_start(sim, speed_mps.clamp(0.0, KANGAROO_START_MPS));
        }
        GaitController::Kangaroo(_) => kangaroo_start(sim, speed_mps),
        GaitController::BipedRun(_) | GaitController::BipedGallop(_) => {}
    }
}

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
